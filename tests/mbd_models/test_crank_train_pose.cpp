// CrankTrain::setPose / setRates produce exactly the requested piston pose and rates
// (read back through Simbody's own kinematics, not through the setters' formulas),
// for every pin joint and both drive modes, with pin and crank offsets; the pose
// survives integrator initialisation; the tertiary motion carries the right bodies.

#include <gtest/gtest.h>

#include <cmath>

#include "pistondyn/mbd_models/CrankTrain.h"

namespace {

using namespace pistondyn::mbd;

EngineDescription engine(PinJoint joint, CrankDrive::Mode mode) {
  EngineDescription e;
  e.geometry.crankRadius_m = 0.04;
  e.geometry.conrodLength_m = 0.14;
  e.geometry.pinOffset_m = 0.0008;
  e.geometry.crankOffset_m = -0.0015;
  e.piston = {0.08, 0.03, 0.04, 0.01};
  e.mass.crank = {2, 0, -0.01, 3e-3};
  e.mass.conrod = {0.5, 0, 0.04, 2e-3};
  e.mass.pin = {0.06, 0, 0, 5e-6};
  e.mass.piston = {0.25, 0.001, 0.005, 2e-4};
  e.pinJoint = joint;
  e.drive.mode = mode;
  e.drive.speed_radps = 300.0;
  e.drive.flywheelInertia_kgm2 = 0.05;
  return e;
}

struct Model {
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter{system};
  SimTK::GeneralForceSubsystem forces{system};
  CrankTrain ct;
  explicit Model(const EngineDescription& e) : ct(matter, forces, e) { system.realizeTopology(); }
};

class PoseRoundTrip
    : public ::testing::TestWithParam<std::tuple<PinJoint, CrankDrive::Mode>> {};

TEST_P(PoseRoundTrip, StateHasTheRequestedPoseAndRates) {
  const auto [joint, mode] = GetParam();
  Model m(engine(joint, mode));
  const double theta = 1.1, uLat = 23e-6, tilt = 4e-4, uTran = 7e-6;
  const double uLatDot = 0.013, tiltDot = -0.21, uTranDot = 0.004, omega = 300.0;
  SimTK::State s = m.system.getDefaultState();
  m.ct.setPose(s, theta, uLat, tilt, uTran);
  m.ct.setRates(s, omega, uLatDot, tiltDot, uTranDot);
  m.system.realize(s, SimTK::Stage::Velocity);
  const SimTK::MobilizedBody& piston = m.ct.getPiston();
  EXPECT_NEAR(m.ct.getCrankAngle_rad(s), theta, 1e-15);
  EXPECT_NEAR(m.ct.getLateralDisplacement_m(s), uLat, 1e-15);
  EXPECT_NEAR(m.ct.getTilt_rad(s), tilt, 1e-15);
  EXPECT_NEAR(m.ct.getTransverseDisplacement_m(s), uTran, 1e-15);
  EXPECT_NEAR(m.ct.getCrankSpeed_radps(s), omega, 1e-12);
  const SimTK::Vec3 v = piston.getBodyOriginVelocity(s);
  EXPECT_NEAR(v[0], uLatDot, 1e-13);
  EXPECT_NEAR(-piston.getBodyAngularVelocity(s)[2], tiltDot, 1e-13);
  EXPECT_NEAR(v[2], uTranDot, 1e-13);
  // The pin axis sits at the small end of the rod and at the piston's pin bosses.
  const SimTK::Vec3 smallEnd =
      m.ct.getConrod().findStationLocationInGround(s, SimTK::Vec3(0, 0.14, 0));
  const SimTK::Vec3 bosses = piston.findStationLocationInGround(s, m.ct.getPinAxisInPiston());
  EXPECT_NEAR((smallEnd - bosses).norm() - std::abs(smallEnd[2] - bosses[2]), 0.0, 1e-15);
}

// Regression: with a constant-speed drive, setPose must leave a state the integrator
// accepts as is (it prescribes theta = omega t, so the clock must match the angle).
TEST_P(PoseRoundTrip, PoseSurvivesIntegratorInitialisation) {
  const auto [joint, mode] = GetParam();
  Model m(engine(joint, mode));
  SimTK::State s = m.system.getDefaultState();
  m.ct.setPose(s, 1.0, 10e-6, 2e-4);
  m.ct.setRates(s, 300.0);
  SimTK::RungeKuttaMersonIntegrator integ(m.system);
  integ.initialize(s);
  const SimTK::State& si = integ.getState();
  EXPECT_NEAR(m.ct.getCrankAngle_rad(si), 1.0, 1e-12);
  EXPECT_NEAR(m.ct.getLateralDisplacement_m(si), 10e-6, 1e-12);
  EXPECT_NEAR(m.ct.getTilt_rad(si), 2e-4, 1e-12);
}

// Tertiary motion: a floating pin (circlips) and a pin fixed in the piston move along
// the pin axis with the piston; a pin clamped in the rod stays with the rod.
TEST_P(PoseRoundTrip, TertiaryMotionCarriesThePinUnlessItIsFixedInTheRod) {
  const auto [joint, mode] = GetParam();
  Model m(engine(joint, mode));
  SimTK::State s = m.system.getDefaultState();
  m.ct.setPose(s, 0.3, 0.0, 0.0, 5e-6);
  m.system.realize(s, SimTK::Stage::Position);
  const double pinZ = m.ct.getPin().getBodyOriginLocation(s)[2];
  EXPECT_NEAR(pinZ, joint == PinJoint::FixedInRod ? 0.0 : 5e-6, 1e-18);
}

INSTANTIATE_TEST_SUITE_P(
    AllJointsAndDrives, PoseRoundTrip,
    ::testing::Combine(::testing::Values(PinJoint::Floating, PinJoint::FixedInRod,
                                         PinJoint::FixedInPiston),
                       ::testing::Values(CrankDrive::Mode::ConstantSpeed, CrankDrive::Mode::Free)));

}  // namespace
