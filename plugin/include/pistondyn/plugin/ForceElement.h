#pragma once
// The force-element interface: pistondyn's open equivalent of Adams user-written
// subroutines. Every time Simbody realizes forces (Stage::Dynamics), the model calls
// calcForces() of every registered element with the current state; the element reads
// the kinematics it needs, calls the numerics (film, contact, mapping), and applies
// body forces. A user writes one class deriving from ForceElement, registers it with
// PistonAssemblyModel::addElement() (or swaps it for an existing one with
// replaceElement()), and touches nothing else.
//
// Life cycle (Simbody verbs):
//   addToModel()      once, when the model builds its Simbody system: keep handles,
//                     add Simbody constraints if the element is kinematic (ideal guide)
//   realizeTopology() once per new default state: allocate per-state cache entries and
//                     state variables (film fill fraction, warm starts) - see ElementCache
//   calcForces()      every force evaluation; must be a pure function of the state
//   calcPotentialEnergy() for conservative elements (default 0)
//   getReportColumns()/calcReport()  output columns (names carry units) evaluated on a
//                     state realized through Stage::Acceleration

#include "pistondyn/mbd_models/CrankTrain.h"

#include <string>
#include <vector>

namespace pistondyn::plugin {

// What an element gets while the model is being built.
struct ModelBuildContext {
  SimTK::SimbodyMatterSubsystem& matter;
  SimTK::GeneralForceSubsystem& forces;
  const mbd::CrankTrain& crankTrain;
};

// Where an element puts its forces during calcForces(). Thin wrapper over Simbody's
// force arrays so elements never index them by hand.
class AppliedForces {
 public:
  AppliedForces(SimTK::Vector_<SimTK::SpatialVec>& bodyForces, SimTK::Vector& mobilityForces)
      : bodyForces_(bodyForces), mobilityForces_(mobilityForces) {}

  // Force [N] expressed in ground acting at a station (point fixed in the body,
  // coordinates in the body frame [m]).
  void addForceAtStation(const SimTK::State& s, const SimTK::MobilizedBody& body,
                         const SimTK::Vec3& stationInBody_m, const SimTK::Vec3& forceInGround_N) {
    body.applyForceToBodyPoint(s, stationInBody_m, forceInGround_N, bodyForces_);
  }
  // Pure torque [N m] expressed in ground.
  void addTorque(const SimTK::State& s, const SimTK::MobilizedBody& body,
                 const SimTK::Vec3& torqueInGround_Nm) {
    body.applyBodyTorque(s, torqueInGround_Nm, bodyForces_);
  }
  // Generalised force on one mobility of a mobilizer [N or N m].
  void addMobilityForce(const SimTK::State& s, const SimTK::MobilizedBody& body, int which,
                        double force) {
    body.applyOneMobilityForce(s, SimTK::MobilizerUIndex(which), force, mobilityForces_);
  }

 private:
  SimTK::Vector_<SimTK::SpatialVec>& bodyForces_;
  SimTK::Vector& mobilityForces_;
};

class ForceElement {
 public:
  virtual ~ForceElement() = default;

  // Unique name within a model; used to find, replace and label the element.
  virtual std::string getName() const = 0;

  virtual void addToModel(const ModelBuildContext& context) = 0;
  virtual void realizeTopology(SimTK::State& /*state*/,
                               const SimTK::Subsystem& /*forceSubsystem*/) const {}
  virtual void calcForces(const SimTK::State& state, AppliedForces& forces) const = 0;
  virtual double calcPotentialEnergy(const SimTK::State& /*state*/) const { return 0.0; }
  // True if calcForces() reads only positions (lets Simbody cache forces at Position).
  virtual bool dependsOnlyOnPositions() const { return false; }

  virtual std::vector<std::string> getReportColumns() const { return {}; }
  // Appends one value per column of getReportColumns(), in that order.
  virtual void calcReport(const SimTK::State& /*state*/, std::vector<double>& /*values*/) const {}
};

}  // namespace pistondyn::plugin
