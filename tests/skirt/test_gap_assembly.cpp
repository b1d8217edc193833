// GapAssembly: the seven terms summed for a pose.
// References: the closed forms of every term at every node (rigid shift and tilt, parabolic
// barrel within its PCHIP bound, elliptic ovality, one bore-distortion order linear in depth,
// uniform thermal growths, the caller's elastic fields), the switches, and a central
// difference in time of the whole gap along a motion (pose, pose rates and the axial motion
// together) for the total rate.
#include <gtest/gtest.h>

#include <cmath>

#include "ExpectInvalidArgument.h"
#include "SkirtTestSupport.h"
#include "pistondyn/skirt/GapAssembly.h"

namespace ps = pistondyn::skirt;
using ps::test::kPi;

namespace {

constexpr double kC0 = 60e-6, kAlphaP = 21e-6, kAlphaL = 11e-6;
constexpr double kBarrel = 0.04, kVertex = -0.004;  // drop = c (y - y0)^2
constexpr double kOvality = 40e-6;
// bore distortion order 2: a_2 = 3e-6 + 2e-5 depth, b_2 = 1e-6 [m]
double a2(double depth) {
  return 3e-6 + 2e-5 * depth;
}
constexpr double kB2 = 1e-6;

ps::GapAssemblyParameters allTerms() {
  ps::GapAssemblyParameters p;
  p.coldRadialClearance_m = kC0;
  p.linerTopHeight_m = 0.25;
  p.travel = {0.12, 0.20};
  p.skirtProfile.axial.height_m = Eigen::VectorXd::LinSpaced(13, -0.03, 0.03);
  p.skirtProfile.axial.radialDrop_m = p.skirtProfile.axial.height_m.unaryExpr(
      [](double y) { return kBarrel * (y - kVertex) * (y - kVertex); });
  p.skirtProfile.ovality.diametralOvality_m = kOvality;
  ps::BoreDistortionOrder o;
  o.order = 2;
  o.depth_m = Eigen::Vector3d(0.0, 0.1, 0.3);
  o.amplitude_m.resize(3);
  o.phase_rad.resize(3);
  for (int r = 0; r < 3; ++r) {
    o.amplitude_m[r] = std::hypot(a2(o.depth_m[r]), kB2);
    o.phase_rad[r] = std::atan2(kB2, a2(o.depth_m[r])) / 2;
  }
  p.linerShape.orders.push_back(o);
  p.pistonThermal.expansionCoefficient_perK = kAlphaP;
  p.pistonThermal.height_m = Eigen::VectorXd::Constant(1, 0.0);
  p.pistonThermal.temperature_degC = Eigen::VectorXd::Constant(1, 60.0);
  p.linerThermal.expansionCoefficient_perK = kAlphaL;
  p.linerThermal.depth_m = Eigen::Vector2d(0.0, 0.3);
  p.linerThermal.temperature_degC = Eigen::Vector2d(100.0, 40.0);  // -200 K/m with depth
  return p;
}

// Closed forms of the terms at node k.
struct Expected {
  double rigid, profile, liner, pistonT, linerT;
  double linerRate, linerTRate, rigidRate;
};
Expected expected(const ps::SkirtSideGrid& g, int k, const ps::PistonPose& q,
                  const ps::PistonPoseRate& r, double pin, double vy) {
  const double ph = g.getNodePhi_rad()[k], y = g.getNodeY_m()[k], R = g.getRadius_m();
  const double depth = 0.25 - (pin + y);
  Expected e;
  e.rigid =
      kC0 - (q.lateral_m + y * std::sin(q.tilt_rad)) * std::cos(ph) - q.tertiary_m * std::sin(ph);
  e.rigidRate = -(r.lateral_mps + y * std::cos(q.tilt_rad) * r.tilt_radps) * std::cos(ph) -
                r.tertiary_mps * std::sin(ph);
  e.profile = kBarrel * (y - kVertex) * (y - kVertex) + kOvality / 4 * (1 - std::cos(2 * ph));
  e.liner = a2(depth) * std::cos(2 * ph) + kB2 * std::sin(2 * ph);
  e.linerRate = -2e-5 * std::cos(2 * ph) * vy;
  e.pistonT = -R * kAlphaP * 40.0;
  e.linerT = R * kAlphaL * (100.0 - 200.0 * depth - 20.0);
  e.linerTRate = R * kAlphaL * 200.0 * vy;
  return e;
}

TEST(GapAssembly, SumsTheSevenTermsAtEveryNode) {
  for (ps::SkirtSide side : {ps::SkirtSide::Thrust, ps::SkirtSide::AntiThrust}) {
    ps::SkirtSideGridParameters gp = ps::test::thrustSide(15, 13);
    gp.side = side;
    const ps::SkirtSideGrid g(gp);
    const ps::GapAssembly gap(g, allTerms());
    ps::GapFields f = gap.makeFields();
    // the caller's elastic fields
    for (int k = 0; k < g.nodeCount(); ++k) {
      f.pistonElastic_m[k] = 1e-6 * std::cos(g.getNodePhi_rad()[k]);
      f.linerElastic_m[k] = 0.5e-6 * g.getNodeY_m()[k] / 0.04;
      f.pistonElasticRate_mps[k] = 1e-4;
      f.linerElasticRate_mps[k] = -3e-4;
    }
    const ps::PistonPose q{15e-6, 0.5e-3, -5e-6};
    const ps::PistonPoseRate r{0.02, 1.5, 0.004};
    const double pin = 0.17, vy = -8.0;
    gap.calc(q, r, pin, vy, f);
    const double pchip = 2 * kBarrel * 0.005 * 0.005 / 4;  // PCHIP bound of the barrel table
    for (int k = 0; k < g.nodeCount(); ++k) {
      const Expected e = expected(g, k, q, r, pin, vy);
      EXPECT_NEAR(f.rigid_m[k], e.rigid, 1e-19);
      EXPECT_NEAR(f.skirtProfile_m[k], e.profile, pchip);
      EXPECT_NEAR(f.linerShape_m[k], e.liner, 1e-19);
      EXPECT_NEAR(f.pistonThermal_m[k], e.pistonT, 1e-19);
      EXPECT_NEAR(f.linerThermal_m[k], e.linerT, 1e-19);
      const double total = e.rigid + e.profile + e.liner + e.pistonT + e.linerT +
                           f.pistonElastic_m[k] + f.linerElastic_m[k];
      EXPECT_NEAR(f.gap_m[k], total, pchip + 1e-18);
      EXPECT_NEAR(f.rigidRate_mps[k], e.rigidRate, 1e-17);
      EXPECT_NEAR(f.linerShapeRate_mps[k], e.linerRate, 1e-17);
      EXPECT_NEAR(f.linerThermalRate_mps[k], e.linerTRate, 1e-17);
      EXPECT_NEAR(f.gapRate_mps[k], e.rigidRate + e.linerRate + e.linerTRate + 1e-4 - 3e-4, 1e-16);
      // the elastic inputs are left as written
      EXPECT_EQ(f.pistonElasticRate_mps[k], 1e-4);
    }
    EXPECT_EQ((f.squeezeBasis - f.dGap_dPose).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_NEAR(f.dGap_dPose(g.nodeIndex(7, 12), ps::kTilt),
                -0.015 * std::cos(q.tilt_rad) * std::cos(g.getCentreAngle_rad()), 1e-18);
  }
}

TEST(GapAssembly, TotalRateIsTheTimeDerivativeOfTheGapAlongTheMotion) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(11, 9));
  ps::GapAssemblyParameters p = allTerms();
  p.linerThermal.interpolation = ps::Interpolation::Pchip;  // smooth along the bore
  const ps::GapAssembly gap(g, p);
  const ps::PistonPose q{-10e-6, -0.4e-3, 3e-6};
  const ps::PistonPoseRate r{0.015, -2.0, 0.002};
  const double pin = 0.16, vy = 11.0;
  ps::GapFields f = gap.makeFields();
  gap.calc(q, r, pin, vy, f);
  const Eigen::ArrayXd rate = f.gapRate_mps;
  const auto gapAt = [&](double t) {
    ps::GapFields ft = gap.makeFields();
    gap.calc({q.lateral_m + r.lateral_mps * t, q.tilt_rad + r.tilt_radps * t,
              q.tertiary_m + r.tertiary_mps * t},
             r, pin + vy * t, vy, ft);
    return Eigen::ArrayXd(ft.gap_m);
  };
  // dt = 1 us moves the piston 11 um along the bore: the O(dt^2) error of the central
  // difference is ~1e-10 of the rate; rounding ~1e-16 * 1e-4 m / 1e-6 s = 1e-14 m/s
  const double dt = 1e-6;
  const Eigen::ArrayXd fd = (gapAt(dt) - gapAt(-dt)) / (2 * dt);
  for (int k = 0; k < g.nodeCount(); ++k)
    EXPECT_NEAR(rate[k], fd[k], 1e-7 * rate.abs().maxCoeff()) << k;
}

TEST(GapAssembly, SwitchedOffTermsReadZeroAndAddNothing) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(9, 7));
  ps::GapAssemblyParameters p = allTerms();
  p.terms.skirtProfile = false;
  p.terms.linerShape = false;
  p.terms.pistonElastic = false;
  const ps::GapAssembly gap(g, p);
  ps::GapFields f = gap.makeFields();
  f.pistonElastic_m.setConstant(2e-6);
  f.linerElastic_m.setConstant(1e-6);
  gap.calc({}, {}, 0.15, 3.0, f);
  EXPECT_EQ(f.skirtProfile_m.abs().maxCoeff(), 0.0);
  EXPECT_EQ(f.linerShape_m.abs().maxCoeff(), 0.0);
  EXPECT_EQ(f.linerShapeRate_mps.abs().maxCoeff(), 0.0);
  EXPECT_EQ(f.pistonElastic_m.minCoeff(), 2e-6);  // left as written, but not added
  const Eigen::ArrayXd sum = f.rigid_m + f.pistonThermal_m + f.linerThermal_m + 1e-6;
  EXPECT_LT((f.gap_m - sum).abs().maxCoeff(), 1e-20);
  // the pose-independent terms are still available for inspection
  EXPECT_GT(gap.getSkirtProfile_m().maxCoeff(), 0.0);
  // rigid off: no clearance and no pose derivatives
  p.terms.rigid = false;
  const ps::GapAssembly noRigid(g, p);
  noRigid.calc({10e-6, 0, 0}, {1, 0, 0}, 0.15, 0.0, f);
  EXPECT_EQ(f.rigid_m.abs().maxCoeff(), 0.0);
  EXPECT_EQ(f.dGap_dPose.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(f.squeezeBasis.cwiseAbs().maxCoeff(), 0.0);
}

TEST(GapAssembly, RejectsBadCallInputsNamingThem) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(9, 7));
  const ps::GapAssembly gap(g, allTerms());
  ps::GapFields f = gap.makeFields();
  using pistondyn::test::expectInvalidArgument;
  expectInvalidArgument([&] { gap.calc({}, {}, NAN, 0.0, f); },
                        {"GapAssembly::calc", "pinHeight_m"});
  expectInvalidArgument([&] { gap.calc({}, {}, 0.15, INFINITY, f); }, {"axialVelocity_mps"});
  expectInvalidArgument([&] { gap.calc({NAN, 0, 0}, {}, 0.15, 0.0, f); }, {"pose.lateral_m"});
  f.linerElastic_m.resize(5);
  expectInvalidArgument([&] { gap.calc({}, {}, 0.15, 0.0, f); },
                        {"out.linerElastic_m", "5 entries", "expected 63"});
  f = gap.makeFields();
  f.squeezeBasis.resize(63, 2);
  expectInvalidArgument([&] { gap.calc({}, {}, 0.15, 0.0, f); }, {"out.squeezeBasis", "63 x 2"});
}

}  // namespace
