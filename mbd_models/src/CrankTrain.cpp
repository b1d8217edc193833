#include "pistondyn/mbd_models/CrankTrain.h"

#include <cmath>
#include <stdexcept>

namespace pistondyn::mbd {
namespace {

using SimTK::Inertia;
using SimTK::MassProperties;
using SimTK::MobilizedBody;
using SimTK::Rotation;
using SimTK::Transform;
using SimTK::Vec3;

// Full, valid inertia from the planar data (see PlanarMassProperties): equal principal
// moments about the COM, shifted to the body origin.
MassProperties toSimbody(const PlanarMassProperties& b, double extraAxialInertia_kgm2 = 0.0) {
  const Vec3 com(b.comX_m, b.comY_m, 0.0);
  Inertia aboutOrigin = Inertia(b.inertiaZZ_kgm2).shiftFromMassCenter(com, b.mass_kg);
  if (extraAxialInertia_kgm2 > 0.0) {
    // A thin disc on the z axis (Ixx = Iyy = Izz/2) keeps the triangle inequality.
    aboutOrigin +=
        Inertia(0.5 * extraAxialInertia_kgm2, 0.5 * extraAxialInertia_kgm2, extraAxialInertia_kgm2);
  }
  return MassProperties(b.mass_kg, com, aboutOrigin);
}

// Crank angle theta(t) = omega t prescribed at position level: exact, no drift.
// The simulation starts at t0 = theta0 / omega to start at crank angle theta0.
class ConstantSpeedMotion final : public SimTK::Motion::Custom::Implementation {
 public:
  explicit ConstantSpeedMotion(double speed_radps) : omega_(speed_radps) {}
  SimTK::Motion::Level getLevel(const SimTK::State&) const override {
    return SimTK::Motion::Position;
  }
  void calcPrescribedPosition(const SimTK::State& s, int, SimTK::Real* q) const override {
    q[0] = omega_ * s.getTime();
  }
  void calcPrescribedPositionDot(const SimTK::State&, int, SimTK::Real* qdot) const override {
    qdot[0] = omega_;
  }
  void calcPrescribedPositionDotDot(const SimTK::State&, int, SimTK::Real* qdotdot) const override {
    qdotdot[0] = 0.0;
  }

 private:
  double omega_;
};

// Planar rotation angle about +z of a body's frame in ground.
double planarAngle(const SimTK::Rotation& R) {
  return std::atan2(R[1][0], R[0][0]);
}

}  // namespace

CrankTrain::CrankTrain(SimTK::SimbodyMatterSubsystem& matter, SimTK::GeneralForceSubsystem& forces,
                       const EngineDescription& engine)
    : engine_((validate(engine), engine)), kinematics_(engine.geometry), matter_(matter) {
  const CrankTrainGeometry& g = engine_.geometry;
  const double r = g.crankRadius_m, L = g.conrodLength_m;
  // phi_TDC is baked into the crank's inboard frame: crank angle 0 is TDC.
  const double phiTdc = kinematics_.crankRotationAtTdc_rad();
  const Rotation crankFrame(phiTdc, SimTK::ZAxis);
  const Rotation uprightFrame(-phiTdc, SimTK::ZAxis);

  const double flywheel =
      engine_.drive.mode == CrankDrive::Mode::Free ? engine_.drive.flywheelInertia_kgm2 : 0.0;
  MobilizedBody::Pin crank(matter.updGround(), Transform(crankFrame, Vec3(0)),
                           SimTK::Body::Rigid(toSimbody(engine_.mass.crank, flywheel)),
                           Transform());
  crank_ = crank;

  MobilizedBody::Pin conrod(crank_, Transform(Vec3(0, r, 0)),
                            SimTK::Body::Rigid(toSimbody(engine_.mass.conrod)), Transform());
  conrod_ = conrod;

  // Tertiary motion (along the pin axis) lives in the joint that lets the piston side
  // slide: a floating pin is held axially by circlips in the piston and a pin fixed in
  // the piston moves with it, so for both the small end slides on the pin (Cylinder
  // joint rod -> pin); a pin clamped in the rod stays with the rod and the piston bosses
  // slide on it (Cylinder joint pin -> piston).
  const SimTK::Body::Rigid pinBody(toSimbody(engine_.mass.pin));
  const SimTK::Body::Rigid pistonBody(toSimbody(engine_.mass.piston));
  const Transform smallEnd(Vec3(0, L, 0));
  const Transform pistonOnPin(uprightFrame, Vec3(0));
  const Transform pinInPiston(getPinAxisInPiston());
  // Without tertiary motion the slider is a plain Pin (same rotation coordinate first).
  const bool tertiary = engine_.tertiaryMotion;
  auto slider = [tertiary](MobilizedBody& parent, const Transform& inParent,
                           const SimTK::Body::Rigid& body,
                           const Transform& inBody) -> MobilizedBody {
    if (tertiary)
      return MobilizedBody::Cylinder(parent, inParent, body, inBody);
    return MobilizedBody::Pin(parent, inParent, body, inBody);
  };
  switch (engine_.pinJoint) {
    case PinJoint::FixedInRod:
      pin_ = MobilizedBody::Weld(conrod_, smallEnd, pinBody, Transform());
      piston_ = slider(pin_, pistonOnPin, pistonBody, pinInPiston);
      break;
    case PinJoint::FixedInPiston:
      pin_ = slider(conrod_, smallEnd, pinBody, Transform());
      piston_ = MobilizedBody::Weld(pin_, pistonOnPin, pistonBody, pinInPiston);
      break;
    case PinJoint::Floating:
    default:
      pin_ = slider(conrod_, smallEnd, pinBody, Transform());
      piston_ = MobilizedBody::Pin(pin_, pistonOnPin, pistonBody, pinInPiston);
      break;
  }

  if (engine_.drive.mode == CrankDrive::Mode::ConstantSpeed) {
    SimTK::Motion::Custom(crank_, new ConstantSpeedMotion(engine_.drive.speed_radps));
  } else if (engine_.drive.loadTorque_Nm != 0.0) {
    SimTK::Force::MobilityConstantForce(forces, crank_, 0, -engine_.drive.loadTorque_Nm);
  }
  if (engine_.gravity_mps2 > 0.0) {
    SimTK::Force::Gravity(forces, matter, -SimTK::YAxis, engine_.gravity_mps2);
  }
}

SimTK::Vec3 CrankTrain::getPinAxisInPiston() const {
  return Vec3(engine_.geometry.pinOffset_m, 0, 0);
}

SimTK::Vec3 CrankTrain::getCrownCentreInPiston() const {
  return Vec3(0, engine_.piston.compressionHeight_m, 0);
}

double CrankTrain::getCrankAngle_rad(const SimTK::State& s) const {
  return crank_.getOneQ(s, SimTK::MobilizerQIndex(0));
}

double CrankTrain::getCrankSpeed_radps(const SimTK::State& s) const {
  return crank_.getOneU(s, SimTK::MobilizerUIndex(0));
}

double CrankTrain::getPistonHeight_m(const SimTK::State& s) const {
  return piston_.getBodyOriginLocation(s)[1];
}

double CrankTrain::getLateralDisplacement_m(const SimTK::State& s) const {
  return piston_.getBodyOriginLocation(s)[0] - engine_.geometry.crankOffset_m;
}

double CrankTrain::getTilt_rad(const SimTK::State& s) const {
  return -planarAngle(piston_.getBodyRotation(s));
}

double CrankTrain::getTransverseDisplacement_m(const SimTK::State& s) const {
  return piston_.getBodyOriginLocation(s)[2];
}

void CrankTrain::setPose(SimTK::State& s, double theta, double uLat, double tilt,
                         double uTran) const {
  const CrankTrainGeometry& g = engine_.geometry;
  const double r = g.crankRadius_m, L = g.conrodLength_m;
  const double phiTdc = kinematics_.crankRotationAtTdc_rad();
  const double psiCrank = theta + phiTdc;
  const double cx = -r * std::sin(psiCrank);
  const double a = -tilt;  // piston rotation about +z
  const double px = g.crankOffset_m + uLat + g.pinOffset_m * std::cos(a);
  const double dx = px - cx;
  if (!(std::abs(dx) < L)) {
    throw std::invalid_argument("CrankTrain::setPose: the rod cannot reach the displaced pin");
  }
  const double dy = std::sqrt(L * L - dx * dx);
  const double psiRod = std::atan2(-dx, dy);

  if (engine_.drive.mode == CrankDrive::Mode::ConstantSpeed) {
    // The drive prescribes theta = omega t: the crank angle is set through the clock.
    s.setTime(theta / engine_.drive.speed_radps);
  }
  crank_.setOneQ(s, SimTK::MobilizerQIndex(0), theta);
  conrod_.setOneQ(s, SimTK::MobilizerQIndex(0), psiRod - psiCrank);
  // Pin rotation: a floating pin does not spin (pin angle = rod angle), a pin fixed in
  // the piston turns with it.
  const double psiPin = engine_.pinJoint == PinJoint::FixedInPiston ? a + phiTdc : psiRod;
  const SimTK::MobilizedBody& slider = getSmallEndSlider();
  switch (engine_.pinJoint) {
    case PinJoint::FixedInRod:
      piston_.setOneQ(s, SimTK::MobilizerQIndex(0), a - psiPin + phiTdc);
      break;
    case PinJoint::FixedInPiston:
      pin_.setOneQ(s, SimTK::MobilizerQIndex(0), psiPin - psiRod);
      break;
    case PinJoint::Floating:
    default:
      pin_.setOneQ(s, SimTK::MobilizerQIndex(0), 0.0);
      piston_.setOneQ(s, SimTK::MobilizerQIndex(0), a - psiPin + phiTdc);
      break;
  }
  if (engine_.tertiaryMotion) {
    slider.setOneQ(s, SimTK::MobilizerQIndex(1), uTran);
  } else if (uTran != 0.0) {
    throw std::invalid_argument(
        "CrankTrain::setPose: a tertiary displacement needs EngineDescription::tertiaryMotion");
  }
}

void CrankTrain::setRates(SimTK::State& s, double omega, double uLatDot, double tiltDot,
                          double uTranDot) const {
  // Uses the pose already in the state's q's (call setPose first); no realization.
  const CrankTrainGeometry& g = engine_.geometry;
  const double phiTdc = kinematics_.crankRotationAtTdc_rad();
  const double psiCrank = getCrankAngle_rad(s) + phiTdc;
  const double cy = g.crankRadius_m * std::cos(psiCrank);
  const double psiRod = psiCrank + conrod_.getOneQ(s, SimTK::MobilizerQIndex(0));
  const double relY = g.conrodLength_m * std::cos(psiRod);  // (P - C)_y > 0
  // Piston rotation about +z (= -tilt) from the chain of joint angles.
  double pistonAngle = psiRod - phiTdc;
  if (engine_.pinJoint != PinJoint::FixedInRod)
    pistonAngle += pin_.getOneQ(s, SimTK::MobilizerQIndex(0));
  if (engine_.pinJoint != PinJoint::FixedInPiston) {
    pistonAngle += piston_.getOneQ(s, SimTK::MobilizerQIndex(0));
  }
  const double aDot = -tiltDot;
  // Pin centre x-velocity from the piston motion, crank pin x-velocity from the crank;
  // the rod's angular velocity closes the loop: vP = vC + omegaRod z x (P - C).
  const double vPx = uLatDot - g.pinOffset_m * std::sin(pistonAngle) * aDot;
  const double vCx = -omega * cy;
  const double omegaRod = (vCx - vPx) / relY;

  crank_.setOneU(s, SimTK::MobilizerUIndex(0), omega);
  conrod_.setOneU(s, SimTK::MobilizerUIndex(0), omegaRod - omega);
  const SimTK::MobilizedBody& slider = getSmallEndSlider();
  switch (engine_.pinJoint) {
    case PinJoint::FixedInRod:
      piston_.setOneU(s, SimTK::MobilizerUIndex(0), aDot - omegaRod);
      break;
    case PinJoint::FixedInPiston:
      pin_.setOneU(s, SimTK::MobilizerUIndex(0), aDot - omegaRod);
      break;
    case PinJoint::Floating:
    default:
      pin_.setOneU(s, SimTK::MobilizerUIndex(0), -omegaRod);  // a floating pin starts without spin
      piston_.setOneU(s, SimTK::MobilizerUIndex(0), aDot);
      break;
  }
  if (engine_.tertiaryMotion) {
    slider.setOneU(s, SimTK::MobilizerUIndex(1), uTranDot);
  } else if (uTranDot != 0.0) {
    throw std::invalid_argument(
        "CrankTrain::setRates: a tertiary velocity needs EngineDescription::tertiaryMotion");
  }
}

double CrankTrain::getDriveTorque_Nm(const SimTK::State& s) const {
  if (engine_.drive.mode == CrankDrive::Mode::Free)
    return -engine_.drive.loadTorque_Nm;
  SimTK::Vector motionForces;
  matter_.findMotionForces(s, motionForces);
  // Simbody reports Motion forces like constraint forces, with the opposite sign of an
  // applied force; negate to get the torque the drive applies to the crank.
  return -motionForces[crank_.getFirstUIndex(s)];
}

double CrankTrain::getConrodAxialForce_N(const SimTK::State& s) const {
  const SimTK::UnitVec3 rodAxis = conrod_.getBodyRotation(s).y();
  const SimTK::SpatialVec onPin =
      getSmallEndSlider().findMobilizerReactionOnBodyAtOriginInGround(s);
  return SimTK::dot(onPin[1], rodAxis);
}

double CrankTrain::getConrodLateralForce_N(const SimTK::State& s) const {
  return getSmallEndSlider().findMobilizerReactionOnBodyAtOriginInGround(s)[1][0];
}

double CrankTrain::getCrankTorqueFromConrod_Nm(const SimTK::State& s) const {
  const SimTK::SpatialVec onCrank = conrod_.findMobilizerReactionOnParentAtFInGround(s);
  const SimTK::Vec3 crankPin = conrod_.getBodyOriginLocation(s);  // rod origin = big-end centre
  return onCrank[0][2] + SimTK::cross(crankPin, onCrank[1])[2];
}

}  // namespace pistondyn::mbd
