#pragma once
// Example of a user-written liner element and of its liner model for decks.
//
// SpringLinerGuide is a compliant liner: linear springs and dampers on the piston's
// lateral displacement, tilt and transverse displacement (a crude stand-in for a skirt
// with clearance, the way a user might prototype a new force law). It implements the
// liner role pistondyn::plugin::LinerElement, so summaries find its side force without
// knowing its columns.
//
// registerSpringLinerGuide() makes it selectable from any deck as
//
//   liner:
//     model: spring_guide
//     lateral_stiffness_N_per_mm: 2.0e4     # optional, these are the defaults
//     lateral_damping_Ns_per_m: 2000
//     tilt_stiffness_Nm_per_rad: 2.0e4
//     tilt_damping_Nms_per_rad: 2.0
//     axial_stiffness_N_per_mm: 2.0e4
//     axial_damping_Ns_per_m: 2000
//
// or from the command line of a program that registered it: --set liner.model=spring_guide.

#include <memory>
#include <string>

#include "pistondyn/io/DeckSection.h"
#include "pistondyn/io/LinerRegistry.h"
#include "pistondyn/plugin/LinerElement.h"

namespace pistondyn::examples {

class SpringLinerGuide final : public plugin::LinerElement {
 public:
  struct Parameters {
    double lateralStiffness_Npm = 2e7;  // [N/m]
    double lateralDamping_Nspm = 2e3;   // [N s/m]
    double tiltStiffness_Nmprad = 2e4;  // [N m/rad]
    double tiltDamping_Nmsprad = 2.0;   // [N m s/rad]
    double axialStiffness_Npm = 2e7;    // along the pin axis [N/m]
    double axialDamping_Nspm = 2e3;     // [N s/m]
  };
  explicit SpringLinerGuide(Parameters p) : p_(p) {}

  std::string getName() const override { return "spring_liner_guide"; }
  void addToModel(const plugin::ModelBuildContext& context) override {
    crankTrain_ = &context.crankTrain;
  }
  void calcForces(const SimTK::State& s, plugin::AppliedForces& forces) const override {
    const SimTK::MobilizedBody& piston = crankTrain_->getPiston();
    const SimTK::Vec3 v = piston.getBodyOriginVelocity(s);
    const double fx = -p_.lateralStiffness_Npm * crankTrain_->getLateralDisplacement_m(s) -
                      p_.lateralDamping_Nspm * v[0];
    const double fz = -p_.axialStiffness_Npm * crankTrain_->getTransverseDisplacement_m(s) -
                      p_.axialDamping_Nspm * v[2];
    // Tilt is a rotation about -z; the restoring moment about +z is +k * tilt.
    const double tiltRate = -piston.getBodyAngularVelocity(s)[2];
    const double mz =
        p_.tiltStiffness_Nmprad * crankTrain_->getTilt_rad(s) + p_.tiltDamping_Nmsprad * tiltRate;
    forces.addForceAtStation(s, piston, SimTK::Vec3(0), SimTK::Vec3(fx, 0, fz));
    forces.addTorque(s, piston, SimTK::Vec3(0, 0, mz));
  }
  // The liner role (LinerElement.h): the force the piston puts on the liner.
  double getSideForce_N(const SimTK::State& s) const override {
    const double x = crankTrain_->getLateralDisplacement_m(s);
    const double vx = crankTrain_->getPiston().getBodyOriginVelocity(s)[0];
    return p_.lateralStiffness_Npm * x + p_.lateralDamping_Nspm * vx;
  }
  // The liner outputs the summary and the figures know (LinerElement.h) that this liner has:
  // the side force and the lateral motion at the skirt's ends (the secondary-motion figure).
  plugin::ElementOutputs getOutputs() const override {
    using plugin::LinerOutput;
    return {plugin::makeLinerOutput(LinerOutput::SideForce, *this, *crankTrain_),
            plugin::makeLinerOutput(LinerOutput::LateralAtSkirtTop, *this, *crankTrain_),
            plugin::makeLinerOutput(LinerOutput::LateralAtSkirtBottom, *this, *crankTrain_)};
  }
  const Parameters& getParameters() const { return p_; }

 private:
  Parameters p_;
  const mbd::CrankTrain* crankTrain_ = nullptr;
};

// The liner model "spring_guide": reads the keys listed above from the deck's liner
// section (units in the keys, all optional, all positive).
inline io::LinerElementMaker readSpringLinerGuide(io::DeckSection& liner) {
  using io::Bounds;
  using io::Quantity;
  SpringLinerGuide::Parameters p;
  p.lateralStiffness_Npm =
      liner.getSIOr("lateral_stiffness_N_per_mm", Quantity::Stiffness, 2e4, Bounds::positive());
  p.lateralDamping_Nspm =
      liner.getSIOr("lateral_damping_Ns_per_m", Quantity::Damping, 2e3, Bounds::nonNegative());
  p.tiltStiffness_Nmprad = liner.getSIOr("tilt_stiffness_Nm_per_rad", Quantity::RotationalStiffness,
                                         2e4, Bounds::positive());
  p.tiltDamping_Nmsprad = liner.getSIOr("tilt_damping_Nms_per_rad", Quantity::RotationalDamping,
                                        2.0, Bounds::nonNegative());
  p.axialStiffness_Npm =
      liner.getSIOr("axial_stiffness_N_per_mm", Quantity::Stiffness, 2e4, Bounds::positive());
  p.axialDamping_Nspm =
      liner.getSIOr("axial_damping_Ns_per_m", Quantity::Damping, 2e3, Bounds::nonNegative());
  return [p] { return std::make_unique<SpringLinerGuide>(p); };
}

inline void registerSpringLinerGuide(io::LinerRegistry& registry = io::LinerRegistry::getGlobal()) {
  registry.add("spring_guide", "linear springs and dampers on u_lat, tilt and u_tran (example)",
               readSpringLinerGuide);
}

}  // namespace pistondyn::examples
