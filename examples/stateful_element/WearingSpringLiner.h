#pragma once
// Example of a force element WITH HISTORY, written against the public element layer
// (pistondyn/plugin/ForceElement.h, ElementState.h) the way a user writes one.
//
// WearingSpringLiner holds the piston in the bore with penalty springs and dampers: a
// lateral spring that acts only outside a clearance band |u_lat| <= c + w, a tilt spring
// and a spring along the pin axis. The band widens as the liner wears: the wear depth w
// grows by Archard's law, dw = k * F_n * |v_y| * dt, once per ACCEPTED integration step,
// so it lives in an auto-update discrete variable. The energy the dampers dissipate is
// integrated exactly, with the motion, as a continuous state z. A counter of accepted
// updates (a second auto-update variable) shows that trial and rejected steps never
// advance the history.
//
// What it demonstrates (tests/plugin/test_stateful_element.cpp checks each):
//   - history survives integrator step rejections (only accepted steps update it);
//   - rewinding is copying a State: a run restarted from a copy repeats itself exactly;
//   - two copies of a State give identical forces;
//   - z states integrate a quantity exactly (here: mechanical energy + dissipated energy
//     is conserved).

#include <cmath>
#include <string>

#include "pistondyn/plugin/ElementCache.h"
#include "pistondyn/plugin/ElementState.h"
#include "pistondyn/plugin/LinerElement.h"

namespace pistondyn::examples {

class WearingSpringLiner final : public plugin::LinerElement {
 public:
  struct Parameters {
    double clearance_m = 20e-6;           // half-width of the band without lateral force [m]
    double lateralStiffness_Npm = 2e7;    // outside the band [N/m]
    double lateralDamping_Nspm = 500.0;   // on the lateral velocity, everywhere [N s/m]
    double tiltStiffness_Nmprad = 2e4;    // [N m/rad]
    double tiltDamping_Nmsprad = 0.5;     // [N m s/rad]
    double axialStiffness_Npm = 2e7;      // along the pin axis [N/m]
    double axialDamping_Nspm = 500.0;     // [N s/m]
    double wearCoefficient_m2pN = 1e-13;  // Archard k / hardness, depth per (N m) slid [m^2/N]
  };
  explicit WearingSpringLiner(const Parameters& p) : p_(p) {}

  std::string getName() const override { return "wearing_spring_liner"; }
  void addToModel(const plugin::ModelBuildContext& context) override {
    crankTrain_ = &context.crankTrain;
  }

  void realizeTopology(SimTK::State&, plugin::ElementStateAllocator& alloc) const override {
    wear_.allocate(alloc, 0.0);
    acceptedUpdates_.allocate(alloc, 0L);
    dissipated_.allocate(alloc, SimTK::Vector(1, 0.0));
    cache_.allocate(alloc);
  }

  void calcForces(const SimTK::State& s, plugin::AppliedForces& forces) const override {
    const Results& r = getResults(s);
    const SimTK::MobilizedBody& piston = crankTrain_->getPiston();
    forces.addForceAtStation(s, piston, SimTK::Vec3(0), SimTK::Vec3(r.lateral_N, 0, r.axial_N));
    forces.addTorque(s, piston, SimTK::Vec3(0, 0, r.tiltMoment_Nm));
    // History: the wear depth and the counter this step leads to, if it is accepted.
    const double dt = wear_.calcTimeSinceLastUpdate(s);
    const double vy = piston.getBodyOriginVelocity(s)[1];
    wear_.setUpdateValue(s, wear_.getValue(s) + p_.wearCoefficient_m2pN * std::abs(r.lateral_N) *
                                                    std::abs(vy) * std::max(dt, 0.0));
    acceptedUpdates_.setUpdateValue(s, acceptedUpdates_.getValue(s) + 1);
  }

  void realizeAcceleration(const SimTK::State& s) const override {
    dissipated_.setDerivative(s, 0, getResults(s).dampingPower_W);
  }

  double calcPotentialEnergy(const SimTK::State& s) const override {
    const Results& r = getResults(s);
    return 0.5 * p_.lateralStiffness_Npm * r.penetration_m * r.penetration_m +
           0.5 * p_.tiltStiffness_Nmprad * r.tilt_rad * r.tilt_rad +
           0.5 * p_.axialStiffness_Npm * r.transverse_m * r.transverse_m;
  }

  double getSideForce_N(const SimTK::State& s) const override { return -getResults(s).lateral_N; }

  plugin::ElementOutputs getOutputs() const override {
    return {{"side_force", "N", "lateral force of the piston on the liner, + towards thrust",
             [this](const SimTK::State& s) { return getSideForce_N(s); }},
            {"wear_depth", "um", "accepted wear depth of the liner",
             [this](const SimTK::State& s) { return 1e6 * wear_.getValue(s); }},
            {"dissipated_energy", "J", "energy dissipated by the dampers since the start",
             [this](const SimTK::State& s) { return *getDissipatedEnergy_J(s); }}};
  }

  double getWearDepth_m(const SimTK::State& s) const { return wear_.getValue(s); }
  long getAcceptedUpdates(const SimTK::State& s) const { return acceptedUpdates_.getValue(s); }
  // The liner role's dissipated energy (LinerElement.h): the dampers' [J].
  std::optional<double> getDissipatedEnergy_J(const SimTK::State& s) const override {
    return dissipated_.getValue(s, 0);
  }

 private:
  struct Results {
    double penetration_m = 0, tilt_rad = 0, transverse_m = 0;
    double lateral_N = 0, tiltMoment_Nm = 0, axial_N = 0;  // on the piston, in ground
    double dampingPower_W = 0;                             // >= 0
  };

  const Results& getResults(const SimTK::State& s) const {
    return cache_.getOrCalc(s, [&](Results& r) {
      const SimTK::MobilizedBody& piston = crankTrain_->getPiston();
      const double u = crankTrain_->getLateralDisplacement_m(s);
      const double band = p_.clearance_m + wear_.getValue(s);
      r.penetration_m = std::abs(u) > band ? u - std::copysign(band, u) : 0.0;
      r.tilt_rad = crankTrain_->getTilt_rad(s);
      r.transverse_m = crankTrain_->getTransverseDisplacement_m(s);
      const SimTK::Vec3 v = piston.getBodyOriginVelocity(s);
      const double tiltRate = -piston.getBodyAngularVelocity(s)[2];
      r.lateral_N = -p_.lateralStiffness_Npm * r.penetration_m - p_.lateralDamping_Nspm * v[0];
      r.axial_N = -p_.axialStiffness_Npm * r.transverse_m - p_.axialDamping_Nspm * v[2];
      // Tilt is a rotation about -z: the restoring moment about +z is +k * tilt.
      r.tiltMoment_Nm = p_.tiltStiffness_Nmprad * r.tilt_rad + p_.tiltDamping_Nmsprad * tiltRate;
      r.dampingPower_W = p_.lateralDamping_Nspm * v[0] * v[0] + p_.axialDamping_Nspm * v[2] * v[2] +
                         p_.tiltDamping_Nmsprad * tiltRate * tiltRate;
    });
  }

  Parameters p_;
  const mbd::CrankTrain* crankTrain_ = nullptr;  // non-owning; the model owns both
  plugin::ElementAutoUpdateVariable<double> wear_;
  plugin::ElementAutoUpdateVariable<long> acceptedUpdates_;
  plugin::ElementZ dissipated_;
  plugin::ElementCache<Results> cache_;
};

}  // namespace pistondyn::examples
