#pragma once
/// \file
/// The crank train as Simbody bodies: crank, connecting rod, piston pin and piston.
///
///   Ground --Pin(z)--> crank --Pin(z)--> conrod --[small end]--> pin --> piston
///     floating pin:        conrod --Cylinder(z)--> pin --Pin(z)--> piston
///     pin fixed in piston: conrod --Cylinder(z)--> pin --Weld-->   piston
///     pin fixed in rod:    conrod --Weld-->        pin --Cylinder(z)--> piston
/// (Cylinder = rotation about and translation along the pin axis: the tertiary motion
/// sits where the piston side slides, so a floating pin moves axially with the piston.)
///
/// The piston has its own rotation (tilt) and translation along the pin axis (tertiary
/// motion) as mobilities, and the rod angle gives its lateral position: the piston is
/// held in the bore only by whatever force element the user adds (the ideal-liner guide
/// or the lubricated skirt), never by a built-in joint. With all generalised
/// coordinates zero the train is assembled at firing TDC with the piston upright.
///
/// The crank either follows a prescribed constant speed (a position-level Simbody
/// Motion, exact crank angle theta(t) = theta0 + omega t) or turns freely with a
/// flywheel inertia and a constant load torque.

#include "pistondyn/mbd_models/SimbodyBuildCheck.h"
// clang-format off (the guard must come first)
#include <Simbody.h>
// clang-format on

#include <memory>

#include "pistondyn/mbd_models/EngineDescription.h"
#include "pistondyn/mbd_models/SliderCrank.h"

namespace pistondyn::mbd {

/// The crank train of one cylinder as Simbody bodies and mobilizers (this file's
/// documentation), with closed-form pose setting and the read-outs of its loads.
class CrankTrain {
 public:
  /// Builds the bodies and mobilizers into `matter`, gravity and (free drive) the load
  /// torque into `forces`. Validates `engine` (std::invalid_argument on bad input).
  CrankTrain(SimTK::SimbodyMatterSubsystem& matter, SimTK::GeneralForceSubsystem& forces,
             const EngineDescription& engine);

  const EngineDescription& getEngine() const { return engine_; }    ///< as validated, SI
  const SliderCrank& getKinematics() const { return kinematics_; }  ///< closed-form kinematics

  const SimTK::MobilizedBody& getCrank() const { return crank_; }    ///< the crank body
  const SimTK::MobilizedBody& getConrod() const { return conrod_; }  ///< the connecting rod
  const SimTK::MobilizedBody& getPin() const { return pin_; }        ///< the piston pin
  const SimTK::MobilizedBody& getPiston() const { return piston_; }  ///< the piston
  SimTK::MobilizedBody& updPiston() { return piston_; }              ///< writable piston

  /// Piston points in the piston frame: pin axis, crown centre.
  SimTK::Vec3 getPinAxisInPiston() const;
  SimTK::Vec3 getCrownCentreInPiston() const;  ///< see getPinAxisInPiston

  // ---- state read-outs (require Stage::Position unless stated) -----------------
  /// Crank angle theta from firing TDC [rad], not wrapped (grows by 4 pi per cycle).
  double getCrankAngle_rad(const SimTK::State& s) const;
  /// Crank speed [rad/s] (Stage::Velocity).
  double getCrankSpeed_radps(const SimTK::State& s) const;
  /// Height of the piston-frame origin (piston axis at pin height) above the crank axis [m].
  double getPistonHeight_m(const SimTK::State& s) const;
  /// Secondary motion: lateral displacement of the piston axis from the cylinder axis,
  /// + towards thrust [m]; tilt [rad], + when the crown leans towards the thrust side
  /// (a rotation about -z, the thesis' sign); tertiary displacement along +z [m].
  double getLateralDisplacement_m(const SimTK::State& s) const;
  double getTilt_rad(const SimTK::State& s) const;                  ///< see above
  double getTransverseDisplacement_m(const SimTK::State& s) const;  ///< see above

  // ---- assembly ------------------------------------------------------------------
  /// Sets every q so that the crank is at theta, the piston axis is displaced by
  /// uLat_m, tilted by tilt_rad and shifted by uTran_m. With a constant-speed drive the
  /// crank angle is prescribed as theta = omega t, so setPose also sets the state's time
  /// to theta / omega (otherwise the integrator would move the crank back to omega t
  /// while the rod kept the angle computed for theta). setRates sets every u so that the crank
  /// turns at crankSpeed_radps and the piston has the given lateral, tilt and
  /// transverse rates. Closed-form; no iteration. The pin (Floating) does not spin.
  void setPose(SimTK::State& s, double crankAngle_rad, double uLat_m = 0.0, double tilt_rad = 0.0,
               double uTran_m = 0.0) const;
  /// Sets every u (see setPose); call after setPose.
  void setRates(SimTK::State& s, double crankSpeed_radps, double uLatDot_mps = 0.0,
                double tiltDot_radps = 0.0, double uTranDot_mps = 0.0) const;

  /// Torque the crank drive applies to hold the prescribed speed [N m], positive in
  /// the direction of rotation (Stage::Acceleration). For a free crank: minus the load.
  double getDriveTorque_Nm(const SimTK::State& s) const;

  /// Axial force in the connecting rod at the small end [N], + compression: the component
  /// along the rod axis of the force the rod side exerts on the piston side across the
  /// small-end interface. The pin belongs to the piston side when it floats or is fixed
  /// in the piston (force of the rod on the pin) and to the rod side when it is fixed in
  /// the rod (force of the pin on the piston bosses). Stage::Acceleration.
  double getConrodAxialForce_N(const SimTK::State& s) const;
  /// Lateral force across the small end [N], + towards thrust: the x component (ground) of
  /// the same force of the rod side on the piston side. The crank train's own side force -
  /// what an ideal guide carries, the piston held centred and upright (with the pin in the
  /// piston side, x: 0 = F_x + N); a liner that lets the piston move adds the piston side's
  /// lateral inertia to it. Stage::Acceleration.
  double getConrodLateralForce_N(const SimTK::State& s) const;
  /// Torque the connecting rod exerts on the crank about the crank axis [N m], + in the
  /// direction of rotation (the engine's indicated torque at the crank pin).
  /// Stage::Acceleration.
  double getCrankTorqueFromConrod_Nm(const SimTK::State& s) const;

 private:
  /// The Cylinder mobilizer at the small end (rod -> pin, or pin -> piston when the pin is fixed
  /// in the rod): its second coordinate is the tertiary translation, its reaction loads the rod.
  const SimTK::MobilizedBody& getSmallEndSlider() const {
    return engine_.pinJoint == PinJoint::FixedInRod ? piston_ : pin_;
  }

  EngineDescription engine_;
  SliderCrank kinematics_;
  const SimTK::SimbodyMatterSubsystem& matter_;
  SimTK::MobilizedBody crank_, conrod_, pin_, piston_;
};

}  // namespace pistondyn::mbd
