// InterpolatedTable: the PCHIP and linear readings of a 1-D table.
// References: the data themselves (rows reproduced exactly), closed-form linear data, the
// monotonicity / no-overshoot property of Fritsch & Carlson (checked pointwise), the third-order
// convergence of PCHIP on smooth strictly monotone data (O(h^2) slopes in a cubic Hermite
// interpolant), and central finite differences of the value for the derivative.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "pistondyn/skirt/InterpolatedTable.h"

namespace ps = pistondyn::skirt;

namespace {

ps::InterpolatedTable table(const Eigen::VectorXd& x, const Eigen::VectorXd& f,
                            ps::Interpolation m = ps::Interpolation::Pchip) {
  return ps::InterpolatedTable(x, f, m, "test", "x", "m", "f", "m");
}

Eigen::VectorXd graded(int n, double a, double b) {  // spacing grows 1:3 across the range
  Eigen::VectorXd x(n);
  for (int k = 0; k < n; ++k) {
    const double s = static_cast<double>(k) / (n - 1);
    x[k] = a + (b - a) * (s + s * s) / 2.0;
  }
  return x;
}

TEST(InterpolatedTable, PchipPassesThroughEveryRowExactly) {
  const Eigen::VectorXd x = graded(9, -0.02, 0.03);
  Eigen::VectorXd f(9);
  f << 3e-5, 1e-5, 2e-6, 0.0, 1e-6, 8e-6, 7e-6, 2e-5, 4e-5;
  const ps::InterpolatedTable t = table(x, f);
  for (int k = 0; k < 9; ++k)
    EXPECT_EQ(t.value(x[k]), f[k]) << k;  // t = 0 in the Hermite basis: bit exact
}

TEST(InterpolatedTable, PchipReproducesLinearDataExactly) {
  const Eigen::VectorXd x = graded(7, 0.0, 0.1);
  const Eigen::VectorXd f = (2.0 + 3.0 * x.array()).matrix();
  const ps::InterpolatedTable t = table(x, f);
  for (int s = 0; s <= 200; ++s) {
    const double xx = 0.1 * s / 200.0;
    const ps::TableSample v = t.evaluate(xx);
    // Harmonic means and the end formula of equal secants are the secant: exact up to a few
    // rounding errors of values O(2).
    EXPECT_NEAR(v.value, 2.0 + 3.0 * xx, 1e-14) << xx;
    EXPECT_NEAR(v.derivative, 3.0, 1e-12) << xx;
  }
}

TEST(InterpolatedTable, PchipDoesNotOvershoot) {
  // A step, a spike and a plateau: between two rows the interpolant must stay between them
  // (Fritsch-Carlson monotonicity on every interval).
  Eigen::VectorXd x(10), f(10);
  x << 0, 1, 2, 3, 3.2, 3.4, 5, 6, 7, 9;
  f << 0, 0, 0, 1, 1, 5, 1, 1, 0.5, 0.5;
  const ps::InterpolatedTable t = table(x, f);
  for (int k = 0; k + 1 < 10; ++k) {
    const double lo = std::min(f[k], f[k + 1]), hi = std::max(f[k], f[k + 1]);
    double previous = f[k];
    for (int s = 1; s < 100; ++s) {
      const double v = t.value(x[k] + (x[k + 1] - x[k]) * s / 100.0);
      EXPECT_GE(v, lo - 1e-15) << "interval " << k;
      EXPECT_LE(v, hi + 1e-15) << "interval " << k;
      // monotone within the interval, in the direction of its rows
      if (f[k + 1] >= f[k])
        EXPECT_GE(v, previous - 1e-15) << "interval " << k;
      else
        EXPECT_LE(v, previous + 1e-15) << "interval " << k;
      previous = v;
    }
  }
}

TEST(InterpolatedTable, PchipConvergesAtThirdOrderOnSmoothMonotoneData) {
  // f = sin on [0, 1.2] (strictly increasing): PCHIP's slopes are O(h^2), so the value error
  // between rows is O(h^3).
  std::vector<double> err;
  for (int n : {11, 21, 41, 81}) {
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, 0.0, 1.2);
    const Eigen::VectorXd f = x.array().sin().matrix();
    const ps::InterpolatedTable t = table(x, f);
    double e = 0.0;
    for (int s = 0; s <= 4000; ++s) {
      const double xx = 1.2 * s / 4000.0;
      e = std::max(e, std::abs(t.value(xx) - std::sin(xx)));
    }
    err.push_back(e);
  }
  for (std::size_t k = 1; k < err.size(); ++k) {
    const double order = std::log2(err[k - 1] / err[k]);
    EXPECT_GT(order, 2.7) << "refinement " << k << ": errors " << err[k - 1] << " -> " << err[k];
    EXPECT_LT(order, 3.3) << "refinement " << k;
  }
  EXPECT_LT(err.back(), 1e-6);
  std::printf("[ pchip    ] sin on 10, 20, 40, 80 intervals: max errors %.2e %.2e %.2e %.2e\n",
              err[0], err[1], err[2], err[3]);
}

TEST(InterpolatedTable, DerivativeIsTheSlopeOfTheValueAndContinuous) {
  const Eigen::VectorXd x = graded(8, 0.0, 0.05);
  Eigen::VectorXd f(8);
  f << 0.0, 1e-6, 3e-6, 4e-6, 4.5e-6, 7e-6, 1.2e-5, 1.3e-5;
  const ps::InterpolatedTable t = table(x, f);
  for (int k = 0; k + 1 < 8; ++k) {
    const double h = x[k + 1] - x[k];
    for (double s : {0.2, 0.5, 0.8}) {
      const double xx = x[k] + s * h, d = 1e-4 * h;
      // central difference of a cubic: exact up to d^2 f'''/6 (~1e-8 of the slope) and
      // rounding (~1e-16 f / d)
      const double fd = (t.value(xx + d) - t.value(xx - d)) / (2.0 * d);
      EXPECT_NEAR(t.evaluate(xx).derivative, fd, 1e-7 * std::abs(fd) + 1e-9) << k << " " << s;
    }
  }
  for (int k = 1; k + 1 < 8; ++k) {  // C1 at the interior rows
    const double h = 1e-9 * (x[k + 1] - x[k - 1]);
    const double left = t.evaluate(x[k] - h).derivative, right = t.evaluate(x[k] + h).derivative;
    EXPECT_NEAR(left, right, 1e-6 * (std::abs(left) + 1e-12)) << k;
  }
}

TEST(InterpolatedTable, ExtendsTheEndValuesAsConstants) {
  Eigen::VectorXd x(3), f(3);
  x << 0.0, 1.0, 2.0;
  f << 5.0, 7.0, 6.0;
  for (ps::Interpolation m : {ps::Interpolation::Pchip, ps::Interpolation::Linear}) {
    const ps::InterpolatedTable t = table(x, f, m);
    EXPECT_EQ(t.evaluate(-3.0).value, 5.0);
    EXPECT_EQ(t.evaluate(-3.0).derivative, 0.0);
    EXPECT_EQ(t.evaluate(2.5).value, 6.0);
    EXPECT_EQ(t.evaluate(2.5).derivative, 0.0);
  }
}

TEST(InterpolatedTable, LinearIsPiecewiseLinear) {
  Eigen::VectorXd x(3), f(3);
  x << 0.0, 1.0, 3.0;
  f << 5.0, 7.0, 6.0;
  const ps::InterpolatedTable t = table(x, f, ps::Interpolation::Linear);
  EXPECT_DOUBLE_EQ(t.value(0.25), 5.5);
  EXPECT_DOUBLE_EQ(t.evaluate(0.25).derivative, 2.0);
  EXPECT_DOUBLE_EQ(t.value(2.0), 6.5);
  EXPECT_DOUBLE_EQ(t.evaluate(2.0).derivative, -0.5);
  EXPECT_DOUBLE_EQ(t.evaluate(1.0).derivative, -0.5);  // at a row: the interval to its right
}

TEST(InterpolatedTable, OneAndTwoRows) {
  Eigen::VectorXd x1(1), f1(1), x2(2), f2(2);
  x1 << 0.3;
  f1 << 2.0;
  x2 << 0.0, 2.0;
  f2 << 1.0, 5.0;
  const ps::InterpolatedTable one = table(x1, f1), two = table(x2, f2);
  EXPECT_EQ(one.value(-1.0), 2.0);
  EXPECT_EQ(one.value(0.3), 2.0);
  EXPECT_EQ(one.evaluate(7.0).derivative, 0.0);
  EXPECT_DOUBLE_EQ(two.value(0.5), 2.0);  // the straight line
  EXPECT_DOUBLE_EQ(two.evaluate(1.5).derivative, 2.0);
  const ps::InterpolatedTable empty;
  EXPECT_EQ(empty.value(1.0), 0.0);
}

}  // namespace
