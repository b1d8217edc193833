// h_rigid: the gap of the posed rigid round skirt in the round bore.
// References: hand-computed gaps of a pure lateral shift, a pure tilt and a pure tertiary shift
// at chosen nodes; the exact distance of the rotated and shifted skirt point from the cylinder
// axis (rotation matrix, no linearisation), which must differ from the linear form by no more
// than the neglected terms stated in RigidGap.h; central finite differences of the gap for the
// pose derivatives and of the gap along the motion for the rate.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "ExpectInvalidArgument.h"
#include "SkirtTestSupport.h"
#include "pistondyn/skirt/RigidGap.h"

namespace ps = pistondyn::skirt;

namespace {

struct RigidFields {
  Eigen::ArrayXd h, rate;
  Eigen::MatrixXd dh, basis;
  explicit RigidFields(int n) : h(n), rate(n), dh(n, 3), basis(n, 3) {}
};

RigidFields rigid(const ps::SkirtSideGrid& g, double c0, const ps::PistonPose& pose,
                  const ps::PistonPoseRate& rate = {}) {
  RigidFields f(g.nodeCount());
  ps::calcRigidGap(g, c0, pose, rate, f.h, f.rate, f.dh, f.basis);
  return f;
}

constexpr double kC0 = 30e-6;  // cold radial clearance [m]

TEST(RigidGap, PureLateralShiftAtChosenNodes) {
  for (ps::SkirtSide side : {ps::SkirtSide::Thrust, ps::SkirtSide::AntiThrust}) {
    ps::SkirtSideGridParameters p = ps::test::thrustSide(7, 5);
    p.side = side;
    const ps::SkirtSideGrid g(p);
    const double e = 20e-6;
    const RigidFields f = rigid(g, kC0, {e, 0.0, 0.0});
    const double c = side == ps::SkirtSide::Thrust ? 0.0 : ps::test::kPi;
    // centre line: the piston moved towards thrust by e, so the thrust gap closes by e and
    // the anti-thrust gap opens by e
    const double centre = side == ps::SkirtSide::Thrust ? kC0 - e : kC0 + e;
    EXPECT_NEAR(f.h[g.nodeIndex(3, 0)], centre, 1e-20);
    EXPECT_NEAR(f.h[g.nodeIndex(3, 4)], centre, 1e-20);
    // edges of the 60 deg side: cos(c -+ 30 deg) = +-cos 30 deg
    const double edge = kC0 - e * std::cos(c + ps::test::kPi / 6);
    EXPECT_NEAR(f.h[g.nodeIndex(0, 2)], edge, 1e-20);
    EXPECT_NEAR(f.h[g.nodeIndex(6, 2)], edge, 1e-20);
  }
}

TEST(RigidGap, PureTiltAtChosenNodes) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(7, 5));  // y from -25 mm to +15 mm
  const double a = 0.8e-3;                                // crown towards thrust
  const RigidFields f = rigid(g, kC0, {0.0, a, 0.0});
  // top row (y = +15 mm) on the thrust axis: the crown leans into the thrust side -> closes
  EXPECT_NEAR(f.h[g.nodeIndex(3, 4)], kC0 - 0.015 * std::sin(a), 1e-20);
  // bottom row (y = -25 mm): the skirt end swings away -> opens
  EXPECT_NEAR(f.h[g.nodeIndex(3, 0)], kC0 + 0.025 * std::sin(a), 1e-20);
  // middle row (y = -5 mm) at the edge phi = 30 deg
  EXPECT_NEAR(f.h[g.nodeIndex(6, 2)], kC0 + 0.005 * std::sin(a) * std::cos(ps::test::kPi / 6),
              1e-20);
}

TEST(RigidGap, PureTertiaryShiftAtChosenNodes) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(7, 5));
  const double z = 15e-6;
  const RigidFields f = rigid(g, kC0, {0.0, 0.0, z});
  EXPECT_NEAR(f.h[g.nodeIndex(3, 1)], kC0, 1e-20);                                    // phi = 0
  EXPECT_NEAR(f.h[g.nodeIndex(6, 1)], kC0 - z * std::sin(ps::test::kPi / 6), 1e-20);  // +30 deg
  EXPECT_NEAR(f.h[g.nodeIndex(0, 1)], kC0 + z * std::sin(ps::test::kPi / 6), 1e-20);  // -30 deg
}

TEST(RigidGap, LinearFormIsWithinTheStatedNeglectedTermsOfTheExactGap) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(21, 11));
  const double R = g.getRadius_m();
  const ps::PistonPose pose{50e-6, 1e-3, 10e-6};  // the header's typical values
  const RigidFields f = rigid(g, kC0, pose);
  // Exact: rotate the skirt point about -z by alpha, shift by (e, 0, z_t), distance from the
  // cylinder axis; the bore radius is R + c0.
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(-pose.tilt_rad, Eigen::Vector3d::UnitZ()).matrix();
  double worst = 0.0, worstBound = 0.0;
  for (int k = 0; k < g.nodeCount(); ++k) {
    const double ph = g.getNodePhi_rad()[k], y = g.getNodeY_m()[k];
    const Eigen::Vector3d r = rot * Eigen::Vector3d(R * std::cos(ph), y, R * std::sin(ph)) +
                              Eigen::Vector3d(pose.lateral_m, 0.0, pose.tertiary_m);
    const double exact = (R + kC0) - std::hypot(r.x(), r.z());
    const double u = pose.lateral_m + y * std::sin(pose.tilt_rad);
    const double s = u * std::sin(ph) - pose.tertiary_m * std::cos(ph);
    const double bound = s * s / (2 * R) +
                         R * (1 - std::cos(pose.tilt_rad)) * std::cos(ph) * std::cos(ph) +
                         std::abs(u * std::cos(ph)) * (1 - std::cos(pose.tilt_rad));
    // the neglected terms are the leading terms of the difference; 2 % covers the higher orders
    EXPECT_LE(std::abs(f.h[k] - exact), 1.02 * bound + 1e-15) << "node " << k;
    worst = std::max(worst, std::abs(f.h[k] - exact));
    worstBound = std::max(worstBound, bound);
  }
  EXPECT_LT(worstBound, 0.05e-6);  // the header's figures: 0.034 um + 0.019 um at most
  std::printf("[ rigid    ] linear vs exact gap: worst %.3e m (bound %.3e m)\n", worst, worstBound);
}

TEST(RigidGap, DerivativesAndRateMatchFiniteDifferences) {
  ps::SkirtSideGridParameters p = ps::test::thrustSide(9, 7);
  p.side = ps::SkirtSide::AntiThrust;
  const ps::SkirtSideGrid g(p);
  const ps::PistonPose pose{-12e-6, 0.6e-3, 4e-6};
  const ps::PistonPoseRate rate{0.01, 2.0, -0.003};
  const RigidFields f = rigid(g, kC0, pose, rate);
  const double steps[3] = {1e-7, 1e-5, 1e-7};
  for (int q = 0; q < 3; ++q) {
    ps::PistonPose plus = pose, minus = pose;
    double* pp[3] = {&plus.lateral_m, &plus.tilt_rad, &plus.tertiary_m};
    double* pm[3] = {&minus.lateral_m, &minus.tilt_rad, &minus.tertiary_m};
    *pp[q] += steps[q];
    *pm[q] -= steps[q];
    const Eigen::ArrayXd fd = (rigid(g, kC0, plus).h - rigid(g, kC0, minus).h) / (2 * steps[q]);
    // linear in e and z_t (exact up to rounding 1e-16 * c0 / step); in alpha the central
    // difference of sin is off by step^2/6 relative (~1e-11)
    for (int k = 0; k < g.nodeCount(); ++k)
      EXPECT_NEAR(f.dh(k, q), fd[k], 1e-9 * std::abs(fd[k]) + 1e-9) << "column " << q;
  }
  EXPECT_EQ((f.basis - f.dh).cwiseAbs().maxCoeff(), 0.0);
  // rate: d/dt along the motion pose(t) = pose + rate t, central difference in t
  const double dt = 1e-6;
  const auto at = [&](double t) {
    return rigid(g, kC0,
                 {pose.lateral_m + rate.lateral_mps * t, pose.tilt_rad + rate.tilt_radps * t,
                  pose.tertiary_m + rate.tertiary_mps * t})
        .h;
  };
  const Eigen::ArrayXd fdRate = (at(dt) - at(-dt)) / (2 * dt);
  for (int k = 0; k < g.nodeCount(); ++k)
    EXPECT_NEAR(f.rate[k], fdRate[k], 1e-8 * std::abs(fdRate[k]) + 1e-12) << k;
  // and the rate is the squeeze basis times the pose rates
  const Eigen::ArrayXd viaBasis =
      (f.basis * Eigen::Vector3d(rate.lateral_mps, rate.tilt_radps, rate.tertiary_mps)).array();
  EXPECT_LT((viaBasis - f.rate).abs().maxCoeff(), 1e-18);
}

TEST(RigidGap, RejectsWrongSizesAndNonFiniteInput) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(5, 4));
  RigidFields f(g.nodeCount());
  Eigen::ArrayXd small(3);
  Eigen::MatrixXd wrong(g.nodeCount(), 2);
  using pistondyn::test::expectInvalidArgument;
  expectInvalidArgument([&] { ps::calcRigidGap(g, kC0, {}, {}, small, f.rate, f.dh, f.basis); },
                        {"calcRigidGap", "gap_m", "expected 20"});
  expectInvalidArgument([&] { ps::calcRigidGap(g, kC0, {}, {}, f.h, f.rate, wrong, f.basis); },
                        {"dGap_dPose", "x 3"});
  expectInvalidArgument([&] { ps::calcRigidGap(g, NAN, {}, {}, f.h, f.rate, f.dh, f.basis); },
                        {"coldRadialClearance_m", "finite"});
  expectInvalidArgument(
      [&] {
        ps::calcRigidGap(g, kC0, {0, INFINITY, 0}, {}, f.h, f.rate, f.dh, f.basis);
      },
      {"pose.tilt_rad", "finite"});
  expectInvalidArgument(
      [&] {
        ps::calcRigidGap(g, kC0, {}, {0, 0, NAN}, f.h, f.rate, f.dh, f.basis);
      },
      {"rate.tertiary_mps", "finite"});
}

}  // namespace
