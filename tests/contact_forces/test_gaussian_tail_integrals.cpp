// F_n(λ) against an independent reference: adaptive Gauss–Legendre quadrature in long
// double (ReferenceTailQuadrature.h, written here) and the closed forms of the integer
// orders. The library evaluates Chebyshev tables of log F_n generated from the
// parabolic-cylinder-function form, so none of the three shares code or method.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "ReferenceTailQuadrature.h"
#include "pistondyn/contact_forces/GaussianTailIntegrals.h"

namespace pc = pistondyn::contact_forces;
using pc::TailOrder;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
const std::vector<double> kIssuePoints = {0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0};
const std::vector<TailOrder> kAllOrders = {TailOrder::F0,   TailOrder::F1_2, TailOrder::F1,
                                           TailOrder::F3_2, TailOrder::F2,   TailOrder::F5_2};

// Tolerance of the tables: exp() turns an absolute error in log F_n into the same relative
// error in F_n, and log F_n is summed in double from 16 Chebyshev terms whose rounding is
// a few ε·|log F_n|; 32ε·max(1, |log F_n|) covers that with margin (3e-14 at |λ| = 8,
// 5e-12 at λ = 37, where F_n ≈ 1e-299).
double tableTolerance(double value) {
  return 32.0 * kEps * std::max(1.0, std::fabs(std::log(value)));
}

double relativeError(double value, long double reference) {
  return static_cast<double>(std::fabs(static_cast<long double>(value) / reference - 1.0L));
}

}  // namespace

// The issue's points for F_{5/2} and F_2 against long-double quadrature (independent).
TEST(GaussianTail, F52AndF2MatchQuadratureAtIssuePoints) {
  const pc::test::ReferenceTailQuadrature quadrature;
  double worst52 = 0.0;
  double worst2 = 0.0;
  for (double lambda : kIssuePoints) {
    const double f52 = pc::greenwoodTrippF52(lambda);
    const double f2 = pc::greenwoodTrippF2(lambda);
    const double e52 = relativeError(f52, quadrature.tail(2.5L, lambda));
    const double e2 = relativeError(f2, quadrature.tail(2.0L, lambda));
    worst52 = std::max(worst52, e52);
    worst2 = std::max(worst2, e2);
    EXPECT_LE(e52, tableTolerance(f52)) << "lambda = " << lambda;
    EXPECT_LE(e2, tableTolerance(f2)) << "lambda = " << lambda;
  }
  std::printf("max rel. error on {0,0.5,1,1.5,2,3,4}: F_5/2 %.2e, F_2 %.2e\n", worst52, worst2);
  // The issue's target is 1e-6 (1e-8 aimed for); the tables do far better.
  EXPECT_LE(worst52, 1e-14);
  EXPECT_LE(worst2, 1e-14);
}

// All six orders over the whole tabulated range and the overlap expansion below it,
// against long-double quadrature at 400 random points per order (independent).
TEST(GaussianTail, AllOrdersMatchQuadratureFromDeepOverlapToUnderflow) {
  const pc::test::ReferenceTailQuadrature quadrature;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> uniform(-45.0, 36.999);
  for (TailOrder order : kAllOrders) {
    double worstInner = 0.0;
    double worstOuter = 0.0;
    for (int k = 0; k < 400; ++k) {
      const double lambda = uniform(rng);
      const double value = pc::gaussianTailIntegral(order, lambda);
      const double error = relativeError(value, quadrature.tail(pc::tailOrderValue(order), lambda));
      ASSERT_LE(error, tableTolerance(value))
          << "n = " << pc::tailOrderValue(order) << ", lambda = " << lambda;
      (std::fabs(lambda) <= 8.0 ? worstInner : worstOuter) =
          std::max(std::fabs(lambda) <= 8.0 ? worstInner : worstOuter, error);
    }
    std::printf("n = %.1f: max rel. error |lambda| <= 8: %.2e, elsewhere: %.2e\n",
                pc::tailOrderValue(order), worstInner, worstOuter);
  }
}

// Closed forms that need no quadrature (independent): F_0 = ½erfc(λ/√2),
// F_1 = φ(λ) − λF_0, F_2 = (1+λ²)F_0 − λφ(λ), in long double. For λ > 0 the last two
// cancel (F_2 loses ~λ⁴ ulps of long double: 1e-14 at λ = 8), so they are used up to 8.
TEST(GaussianTail, IntegerOrdersMatchClosedForms) {
  const long double sqrt2pi = 2.506628274631000502415765284811045253L;
  double worst = 0.0;
  for (double lambda = -30.0; lambda <= 8.0; lambda += 0.01) {
    const long double l = lambda;
    const long double f0 = 0.5L * std::erfc(l / std::sqrt(2.0L));
    const long double phi = std::exp(-0.5L * l * l) / sqrt2pi;
    const long double f1 = phi - l * f0;
    const long double f2 = (1.0L + l * l) * f0 - l * phi;
    const double v0 = pc::gaussianTailIntegral(TailOrder::F0, lambda);
    const double v1 = pc::gaussianTailIntegral(TailOrder::F1, lambda);
    const double v2 = pc::gaussianTailIntegral(TailOrder::F2, lambda);
    // Table tolerance plus the closed form's own cancellation error (λ⁴·ε_long double).
    const double closedFormError = 1e-19 * std::pow(std::max(1.0, lambda), 4.0);
    ASSERT_LE(relativeError(v0, f0), tableTolerance(v0) + closedFormError) << lambda;
    ASSERT_LE(relativeError(v1, f1), tableTolerance(v1) + closedFormError) << lambda;
    ASSERT_LE(relativeError(v2, f2), tableTolerance(v2) + closedFormError) << lambda;
    worst = std::max({worst, relativeError(v0, f0), relativeError(v1, f1), relativeError(v2, f2)});
  }
  std::printf("closed forms F_0, F_1, F_2 on [-30, 8]: max rel. error %.2e\n", worst);
}

// Positive and strictly decreasing on a fine grid through every table piece and both table
// ends (property of the exact integral: dF_n/dλ = −n F_{n−1} < 0 for n > 0, −φ for n = 0).
TEST(GaussianTail, PositiveAndStrictlyDecreasing) {
  for (TailOrder order : kAllOrders) {
    double previous = pc::gaussianTailIntegral(order, -40.0);
    for (double lambda = -40.0 + 1e-3; lambda < 36.99; lambda += 1e-3) {
      const double value = pc::gaussianTailIntegral(order, lambda);
      ASSERT_GT(value, 0.0) << "n = " << pc::tailOrderValue(order) << ", lambda = " << lambda;
      // F_0 → 1 for λ → −∞: below λ = −7 a step of 1e-3 changes it by φ(λ)·1e-3 < 1 ulp
      // of 1, so there it can only be non-increasing in double precision.
      if (order == TailOrder::F0 && lambda < -7.0) {
        ASSERT_LE(value, previous);
      } else {
        ASSERT_LT(value, previous)
            << "n = " << pc::tailOrderValue(order) << ", lambda = " << lambda;
      }
      previous = value;
    }
    // Beyond 37 every F_n is below 1e-299 and returned as 0.
    EXPECT_LT(pc::gaussianTailIntegral(order, 36.999), 1e-298);
    EXPECT_EQ(pc::gaussianTailIntegral(order, 37.0), 0.0);
    EXPECT_EQ(pc::gaussianTailIntegral(order, std::numeric_limits<double>::infinity()), 0.0);
  }
  for (double lambda : kIssuePoints) {
    EXPECT_GT(pc::greenwoodTrippF52(lambda), 0.0);
  }
}

// dF_{5/2}/dλ = −(5/2)F_{3/2} against a central difference of F_{5/2} (independent of the
// identity): step 1e-4 gives truncation ~1e-9 and rounding ~1e-12, so 1e-6 is the issue's
// bound with room.
TEST(GaussianTail, SlopeMatchesCentralDifference) {
  double worst = 0.0;
  for (double lambda = -8.0; lambda <= 8.0; lambda += 0.05) {
    const double h = 1e-4;
    const double difference =
        (pc::greenwoodTrippF52(lambda + h) - pc::greenwoodTrippF52(lambda - h)) / (2.0 * h);
    const pc::TailValueAndSlope both = pc::greenwoodTrippF52WithSlope(lambda);
    EXPECT_DOUBLE_EQ(both.value, pc::greenwoodTrippF52(lambda));
    const double error = std::fabs(both.slope / difference - 1.0);
    worst = std::max(worst, error);
    ASSERT_LE(error, 1e-6) << "lambda = " << lambda;
  }
  std::printf("dF_5/2/dlambda vs central difference on [-8, 8]: max rel. error %.2e\n", worst);
}

// The fits of other codes against the exact integrals (reference values from the
// long-double quadrature). Prints the table that README.md quotes and pins each
// documented figure so the documentation cannot drift.
TEST(GaussianTail, FitErrorsAtIssuePoints) {
  const pc::test::ReferenceTailQuadrature quadrature;
  std::printf("%6s %13s %10s %10s %13s %10s %10s\n", "lambda", "F_5/2", "power", "poly", "F_2",
              "power(q)", "poly");
  struct Row {
    double lambda, powerF52, polyF52, powerF2, polyF2;
  };
  std::vector<Row> rows;
  for (double lambda : {0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0}) {
    const double f52 = static_cast<double>(quadrature.tail(2.5L, lambda));
    const double f2 = static_cast<double>(quadrature.tail(2.0L, lambda));
    const Row row{lambda, pc::kPowerLawFitF52.value(lambda) / f52 - 1.0,
                  pc::kPolynomialFitF52.value(lambda) / f52 - 1.0,
                  pc::kPowerLawQuotedF2.value(lambda) / f2 - 1.0,
                  pc::kPolynomialFitF2.value(lambda) / f2 - 1.0};
    rows.push_back(row);
    std::printf("%6.1f %13.6e %+9.1f%% %+9.1f%% %13.6e %+9.1f%% %+9.1f%%\n", lambda, f52,
                100 * row.powerF52, 100 * row.polyF52, f2, 100 * row.powerF2, 100 * row.polyF2);
  }
  auto at = [&rows](double lambda) {
    return *std::find_if(rows.begin(), rows.end(),
                         [lambda](const Row& r) { return r.lambda == lambda; });
  };
  // Power law 4.4068e-5 (4 − λ)^6.804: −10.8 % at 0, −9.2 % at 2, −74 % (×3.9) at 3,
  // −98 % at 3.5 (docs/DESIGN.md §4: "~10 % at λ = 0 and ×4 at λ = 3").
  EXPECT_NEAR(at(0.0).powerF52, -0.108, 0.001);
  EXPECT_NEAR(at(2.0).powerF52, -0.092, 0.001);
  EXPECT_NEAR(at(3.0).powerF52, -0.742, 0.001);
  EXPECT_NEAR(at(3.5).powerF52, -0.982, 0.001);
  // Quoted F_2 power law 1.7011e-5 (4 − λ)^6.832 is no fit of F_2: −56 %, −66 %, −92 %.
  EXPECT_NEAR(at(0.0).powerF2, -0.558, 0.001);
  EXPECT_NEAR(at(2.0).powerF2, -0.664, 0.001);
  EXPECT_NEAR(at(3.0).powerF2, -0.916, 0.001);
  // Published quintics: F_{5/2} within 1.5 % and F_2 within 2.5 % up to λ = 1.5; both 0
  // from their cut points (1.91 and 2.29) on, i.e. −100 % at λ ≥ 2.5.
  for (double lambda : {0.0, 0.5, 1.0, 1.5}) {
    EXPECT_LE(std::fabs(at(lambda).polyF52), 0.015) << lambda;
    EXPECT_LE(std::fabs(at(lambda).polyF2), 0.025) << lambda;
  }
  EXPECT_EQ(at(2.0).polyF52, -1.0);
  EXPECT_NEAR(at(2.0).polyF2, -0.220, 0.001);
  EXPECT_EQ(at(2.5).polyF2, -1.0);
}

// The fits in overlap (λ < 0, mean planes crossed), where no fit was made (they were fitted
// for 0 ≤ λ ≲ 4) but a solver can still take them: against long-double quadrature
// (independent). The power law grows like (4 − λ)^6.8 instead of |λ|^2.5: ratio to the
// exact F_{5/2} 0.91 at λ = −1, 1.32 at −3, 8.6 at −10; the quintics 1.03, 1.30, 4.2;
// the quoted F_2 power law 0.53, 1.01, 11.4. Pinned to 0.5 % (figures in README).
TEST(GaussianTail, FitRatiosInOverlap) {
  const pc::test::ReferenceTailQuadrature quadrature;
  struct Row {
    double lambda, power52, poly52, power2, poly2;
  };
  const Row expected[] = {{-1.0, 0.9114, 1.0292, 0.5269, 1.0563},
                          {-3.0, 1.3175, 1.3018, 1.0103, 1.5025},
                          {-10.0, 8.5964, 4.2085, 11.3961, 6.8804}};
  for (const Row& r : expected) {
    const double f52 = static_cast<double>(quadrature.tail(2.5L, r.lambda));
    const double f2 = static_cast<double>(quadrature.tail(2.0L, r.lambda));
    EXPECT_NEAR(pc::kPowerLawFitF52.value(r.lambda) / f52 / r.power52, 1.0, 5e-3) << r.lambda;
    EXPECT_NEAR(pc::kPolynomialFitF52.value(r.lambda) / f52 / r.poly52, 1.0, 5e-3) << r.lambda;
    EXPECT_NEAR(pc::kPowerLawQuotedF2.value(r.lambda) / f2 / r.power2, 1.0, 5e-3) << r.lambda;
    EXPECT_NEAR(pc::kPolynomialFitF2.value(r.lambda) / f2 / r.poly2, 1.0, 5e-3) << r.lambda;
  }
}

// The cut points recorded with the published quintics: where the F_{5/2} fit stops
// decreasing (slope 0) and where the F_2 fit crosses zero; and the jump left at the first.
TEST(GaussianTail, PolynomialFitCutPoints) {
  const double end52 = pc::kPolynomialFitF52.lambdaEnd;
  const double end2 = pc::kPolynomialFitF2.lambdaEnd;
  EXPECT_NEAR(pc::kPolynomialFitF52.slope(std::nextafter(end52, 0.0)), 0.0, 1e-12);
  EXPECT_NEAR(pc::kPolynomialFitF2.value(std::nextafter(end2, 0.0)), 0.0, 1e-12);
  // The F_{5/2} quintic is 0.01256 at its cut: 1.77 × the exact value there.
  const double justBefore = pc::kPolynomialFitF52.value(std::nextafter(end52, 0.0));
  EXPECT_NEAR(justBefore, 0.01256, 5e-5);
  EXPECT_NEAR(justBefore / pc::greenwoodTrippF52(end52), 1.77, 0.005);
  EXPECT_EQ(pc::kPolynomialFitF52.value(end52), 0.0);
}

TEST(GaussianTail, NanPropagates) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (TailOrder order : kAllOrders) {
    EXPECT_TRUE(std::isnan(pc::gaussianTailIntegral(order, nan)));
  }
  EXPECT_TRUE(std::isnan(pc::greenwoodTrippF52WithSlope(nan).slope));
  EXPECT_TRUE(std::isnan(pc::kPowerLawFitF52.value(nan)));
  EXPECT_TRUE(std::isnan(pc::kPolynomialFitF2.value(nan)));
}
