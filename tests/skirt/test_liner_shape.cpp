// h_linerShape: bore distortion as Fourier orders along the bore.
// References: the closed form A cos(n (phi - psi)) of one order at every node; order 0 as a
// uniform radius change; order 1 as a shift of the bore axis (the rigid gap of the opposite
// piston shift, and the exact distance to a shifted circle to O(A^2/R)); Cartesian
// coefficients linear in depth reproduced exactly between the rows; the convective rate against
// central differences of the gap along the bore, with their O(delta^2) trend.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "SkirtTestSupport.h"
#include "pistondyn/skirt/LinerShape.h"
#include "pistondyn/skirt/RigidGap.h"

namespace ps = pistondyn::skirt;
using ps::test::kPi;

namespace {

constexpr double kLinerTop_m = 0.25;  // liner top above the crank axis
constexpr double kPin_m = 0.18;       // a pin height: skirt nodes at depths 55..95 mm

ps::BoreDistortionOrder constantOrder(int n, double amplitude, double phase) {
  ps::BoreDistortionOrder o;
  o.order = n;
  o.depth_m = Eigen::Vector2d(0.0, 0.15);
  o.amplitude_m = Eigen::Vector2d(amplitude, amplitude);
  o.phase_rad = Eigen::Vector2d(phase, phase);
  return o;
}

struct Field {
  Eigen::ArrayXd h, rate;
};
Field field(const ps::LinerShape& s, const ps::SkirtSideGrid& g, double pin, double vy = 0.0) {
  Field f{Eigen::ArrayXd(g.nodeCount()), Eigen::ArrayXd(g.nodeCount())};
  s.calcField(pin, vy, f.h, f.rate);
  return f;
}

TEST(LinerShape, OneOrderIsReproducedAtEveryNode) {
  for (ps::SkirtSide side : {ps::SkirtSide::Thrust, ps::SkirtSide::AntiThrust}) {
    ps::SkirtSideGridParameters gp = ps::test::thrustSide(25, 6);
    gp.side = side;
    const ps::SkirtSideGrid g(gp);
    for (int n = 0; n <= ps::kMaxBoreDistortionOrder; ++n) {
      const double A = 3e-6 / (1 + n), psi = 0.3 + 0.1 * n;
      ps::BoreDistortionParameters p;
      p.orders.push_back(constantOrder(n, A, psi));
      const ps::LinerShape s(p, g, kLinerTop_m);
      const Field f = field(s, g, kPin_m, 5.0);
      for (int k = 0; k < g.nodeCount(); ++k) {
        const double ph = g.getNodePhi_rad()[k];
        // angles n phi up to 12 * 3.7 rad: rounding ~1e-14 of A
        EXPECT_NEAR(f.h[k], A * std::cos(n * (ph - psi)), 1e-13 * A) << "order " << n;
        EXPECT_EQ(f.rate[k], 0.0);  // constant along the bore: no convective rate
      }
    }
  }
}

TEST(LinerShape, OrderZeroIsAUniformRadiusChange) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(9, 5));
  ps::BoreDistortionOrder o;
  o.order = 0;
  o.depth_m = Eigen::VectorXd::Constant(1, 0.05);  // one row: constant along the bore
  o.amplitude_m = Eigen::VectorXd::Constant(1, 4e-6);
  ps::BoreDistortionParameters p;
  p.orders.push_back(o);  // phase may be left empty for order 0
  const ps::LinerShape s(p, g, kLinerTop_m);
  const Field f = field(s, g, kPin_m);
  EXPECT_EQ((f.h - 4e-6).abs().maxCoeff(), 0.0);
}

TEST(LinerShape, OrderOneIsAShiftOfTheBoreAxis) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(15, 5));
  const double A = 8e-6, psi = 0.7, R = g.getRadius_m(), c0 = 30e-6;
  ps::BoreDistortionParameters p;
  p.orders.push_back(constantOrder(1, A, psi));
  const ps::LinerShape s(p, g, kLinerTop_m);
  const Field f = field(s, g, kPin_m);
  // The bore moved by A towards psi = the piston moved by A the other way.
  const int n = g.nodeCount();
  Eigen::ArrayXd h(n), rate(n);
  Eigen::MatrixXd d(n, 3), b(n, 3);
  ps::calcRigidGap(g, c0, {-A * std::cos(psi), 0.0, -A * std::sin(psi)}, {}, h, rate, d, b);
  EXPECT_LT((f.h - (h - c0)).abs().maxCoeff(), 1e-20);
  // Exact: distance from the original axis to the shifted circle of radius Rb along phi.
  const double Rb = R + c0;
  for (int k = 0; k < n; ++k) {
    const double t = g.getNodePhi_rad()[k] - psi;
    const double exact =
        A * std::cos(t) + std::sqrt(Rb * Rb - A * A * std::sin(t) * std::sin(t)) - Rb;
    EXPECT_NEAR(f.h[k], exact, A * A / (2 * Rb)) << k;
  }
}

TEST(LinerShape, CartesianCoefficientsLinearInDepthAreReproducedBetweenRows) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(13, 9));
  // a_2(d) = 2e-6 + 3e-5 d, b_2(d) = -1e-6 + 4e-5 d given as amplitude and phase at 3 rows
  const int n = 2;
  const auto a = [](double d) { return 2e-6 + 3e-5 * d; };
  const auto b = [](double d) { return -1e-6 + 4e-5 * d; };
  ps::BoreDistortionOrder o;
  o.order = n;
  o.depth_m = Eigen::Vector3d(0.0, 0.07, 0.15);
  o.amplitude_m.resize(3);
  o.phase_rad.resize(3);
  for (int r = 0; r < 3; ++r) {
    o.amplitude_m[r] = std::hypot(a(o.depth_m[r]), b(o.depth_m[r]));
    o.phase_rad[r] = std::atan2(b(o.depth_m[r]), a(o.depth_m[r])) / n;
  }
  ps::BoreDistortionParameters p;
  p.orders.push_back(o);
  const ps::LinerShape s(p, g, kLinerTop_m);
  const double vy = 7.0;
  const Field f = field(s, g, kPin_m, vy);
  for (int k = 0; k < g.nodeCount(); ++k) {
    const double ph = g.getNodePhi_rad()[k];
    const double d = kLinerTop_m - (kPin_m + g.getNodeY_m()[k]);
    EXPECT_NEAR(f.h[k], a(d) * std::cos(n * ph) + b(d) * std::sin(n * ph), 1e-19) << k;
    // rate = -(d dr / d depth) v_y
    EXPECT_NEAR(f.rate[k], -(3e-5 * std::cos(n * ph) + 4e-5 * std::sin(n * ph)) * vy, 1e-15);
  }
  // beyond the table (piston above the liner top): the end row's values
  const Field above = field(s, g, kLinerTop_m + 0.05, vy);
  for (int k = 0; k < g.nodeCount(); ++k) {
    const double ph = g.getNodePhi_rad()[k];
    EXPECT_NEAR(above.h[k], a(0.0) * std::cos(n * ph) + b(0.0) * std::sin(n * ph), 1e-19);
    EXPECT_EQ(above.rate[k], 0.0);
  }
}

TEST(LinerShape, ConvectiveRateMatchesCentralDifferencesAlongTheBore) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(17, 9));
  // Orders 0, 2, 4 varying smoothly with depth, 9 rows over 0..160 mm.
  ps::BoreDistortionParameters p;
  const Eigen::VectorXd rows = Eigen::VectorXd::LinSpaced(9, 0.0, 0.16);
  for (int n : {0, 2, 4}) {
    ps::BoreDistortionOrder o;
    o.order = n;
    o.depth_m = rows;
    o.amplitude_m =
        rows.unaryExpr([n](double d) { return 5e-6 * (1 + 0.5 * std::sin(20 * d + n)); });
    o.phase_rad = rows.unaryExpr([n](double d) { return 0.2 * n + 3 * d; });
    p.orders.push_back(o);
  }
  const ps::LinerShape s(p, g, kLinerTop_m);
  const double vy = -9.0;  // piston moving down
  const Field f = field(s, g, kPin_m, vy);
  // Nodes whose depth stays inside one PCHIP piece over +-delta (the central difference of a
  // piecewise cubic is O(delta^2) only inside a piece).
  const double delta0 = 2e-3;
  std::vector<int> nodes;
  for (int k = 0; k < g.nodeCount(); ++k) {
    const double d = kLinerTop_m - (kPin_m + g.getNodeY_m()[k]);
    bool clear = true;
    for (Eigen::Index r = 0; r < rows.size(); ++r)
      clear = clear && std::abs(d - rows[r]) > 1.5 * delta0;
    if (clear)
      nodes.push_back(k);
  }
  ASSERT_GT(nodes.size(), 40u);
  std::vector<double> errors;
  for (double delta : {delta0, delta0 / 2, delta0 / 4}) {
    const Field up = field(s, g, kPin_m + delta), down = field(s, g, kPin_m - delta);
    double e = 0.0;
    for (int k : nodes)
      e = std::max(e, std::abs(f.rate[k] - (up.h[k] - down.h[k]) / (2 * delta) * vy));
    errors.push_back(e);
  }
  std::printf(
      "[ convect  ] |rate - central difference| at delta = 2, 1, 0.5 mm: %.3e %.3e %.3e "
      "m/s (rate scale %.3e m/s)\n",
      errors[0], errors[1], errors[2], f.rate.abs().maxCoeff());
  // O(delta^2): each halving divides the error by 4 (3.5..4.5 allows the delta^4 term)
  for (std::size_t r = 1; r < errors.size(); ++r) {
    EXPECT_GT(errors[r - 1] / errors[r], 3.5) << r;
    EXPECT_LT(errors[r - 1] / errors[r], 4.5) << r;
  }
  EXPECT_LT(errors.back(), 1e-3 * f.rate.abs().maxCoeff());
  // pointwise sample = field
  for (int k = 0; k < g.nodeCount(); ++k) {
    const ps::BoreSample b = s.calcSample(g.getNodePhi_rad()[k], kPin_m + g.getNodeY_m()[k]);
    EXPECT_NEAR(b.radialDeviation_m, f.h[k], 1e-20);
    EXPECT_NEAR(b.dRadialDeviation_dBoreHeight * vy, f.rate[k], 1e-16);
  }
}

TEST(LinerShape, WideningUpwardsOpensTheGapOfARisingPiston) {
  // Order 0 growing towards the top (smaller depth): dr/dY > 0; v_y > 0 -> rate > 0.
  const ps::SkirtSideGrid g(ps::test::thrustSide(5, 4));
  ps::BoreDistortionOrder o;
  o.order = 0;
  o.depth_m = Eigen::Vector2d(0.0, 0.2);
  o.amplitude_m = Eigen::Vector2d(10e-6, 0.0);  // 10 um wider at the top, linear
  ps::BoreDistortionParameters p;
  p.orders.push_back(o);
  const ps::LinerShape s(p, g, kLinerTop_m);
  const Field f = field(s, g, kPin_m, 10.0);
  // d dr/dY = 10 um / 0.2 m = 5e-5; times 10 m/s
  EXPECT_NEAR(f.rate.minCoeff(), 5e-4, 1e-17);
  EXPECT_NEAR(f.rate.maxCoeff(), 5e-4, 1e-17);
}

}  // namespace
