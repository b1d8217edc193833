#pragma once
/// \file
/// The force-element interface: pistondyn's open equivalent of Adams user-written
/// subroutines. Every time Simbody realizes forces (Stage::Dynamics), the model calls
/// calcForces() of every registered element with the current state; the element reads
/// the kinematics it needs, calls the numerics (film, contact, mapping), and applies
/// body forces. A user writes one class deriving from ForceElement, registers it with
/// PistonAssemblyModel::addElement() (or swaps it for an existing one with
/// replaceElement()), and touches nothing else.
///
/// Life cycle (Simbody verbs; every hook has a do-nothing default):
///   addToModel()        once, when the model builds its Simbody system: keep handles,
///                       add Simbody constraints if the element is kinematic (ideal guide)
///   realizeTopology()   once per new default state: allocate state variables
///                       (ElementState.h: continuous z, discrete and auto-update discrete
///                       variables) and cache entries (ElementCache.h)
///   realizeModel() .. realizeReport()   Simbody's realize stages, forwarded unchanged
///   calcForces()        every force evaluation, state realized through Stage::Velocity;
///                       may compute the update values of auto-update variables
///   realizeAcceleration() set the derivatives of the element's z (ElementZ)
///   getOutputs()        typed outputs (ElementOutput.h), read on a state realized through
///                       Stage::Acceleration
///
/// Where an element keeps what (docs/DESIGN.md §2). Everything the trajectory depends on is a
/// function of the State: q, u, z, discrete variables, time. History (fill fraction,
/// inlet film, wear depth) lives in auto-update discrete variables, integrals in z. Per-
/// state results go into the State's cache (ElementCache). Mutable members are allowed
/// ONLY for solver workspaces and warm starts (factorisations, multigrid levels, the last
/// film solution as a starting guess) and only when results depend on them no more than
/// the solver tolerance does: a State evaluated twice, or two copies of a State evaluated
/// in any order, give the same forces to that tolerance. Such workspaces make an element
/// single-threaded: use one model per thread (models are cheap to build), never share an
/// element, a model or a State's realization between threads.

#include "pistondyn/mbd_models/CrankTrain.h"
#include "pistondyn/plugin/ElementOutput.h"
#include "pistondyn/plugin/ElementState.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace pistondyn::plugin {

/// What an element gets while the model is being built.
struct ModelBuildContext {
  SimTK::SimbodyMatterSubsystem& matter;  ///< the model's matter subsystem
  SimTK::GeneralForceSubsystem& forces;   ///< the model's force subsystem
  const mbd::CrankTrain& crankTrain;      ///< the crank train (bodies, engine description)
};

/// Where an element puts its forces during calcForces(). Thin wrapper over Simbody's
/// force arrays so elements never index them by hand.
class AppliedForces {
 public:
  /// Wraps the force arrays Simbody hands to a Force::Custom.
  AppliedForces(SimTK::Vector_<SimTK::SpatialVec>& bodyForces, SimTK::Vector& mobilityForces)
      : bodyForces_(bodyForces), mobilityForces_(mobilityForces) {}

  /// Force [N] expressed in ground acting at a station (point fixed in the body,
  /// coordinates in the body frame [m]).
  void addForceAtStation(const SimTK::State& s, const SimTK::MobilizedBody& body,
                         const SimTK::Vec3& stationInBody_m, const SimTK::Vec3& forceInGround_N) {
    body.applyForceToBodyPoint(s, stationInBody_m, forceInGround_N, bodyForces_);
  }
  /// Pure torque [N m] expressed in ground.
  void addTorque(const SimTK::State& s, const SimTK::MobilizedBody& body,
                 const SimTK::Vec3& torqueInGround_Nm) {
    body.applyBodyTorque(s, torqueInGround_Nm, bodyForces_);
  }
  /// Generalised force on one mobility of a mobilizer [N or N m].
  void addMobilityForce(const SimTK::State& s, const SimTK::MobilizedBody& body, int which,
                        double force) {
    body.applyOneMobilityForce(s, SimTK::MobilizerUIndex(which), force, mobilityForces_);
  }

 private:
  SimTK::Vector_<SimTK::SpatialVec>& bodyForces_;
  SimTK::Vector& mobilityForces_;
};

/// Linearisation of an element's generalised (mobility) forces f(q, u) about the state
/// of the last calcForces(), for implicit steppers: dfdq(i, j) = d f_i / d q_j,
/// dfdu(i, j) = d f_i / d u_j (nu x nq and nu x nu, Simbody's mobility order). An element
/// adds the parts it knows (a stiff squeeze-film damping, a contact stiffness); what it
/// leaves out is treated explicitly by the stepper, so leave out only what is not stiff.
struct ForceJacobian {
  SimTK::Matrix dfdq;  ///< d f / d q, nu x nq [N/m, N m/rad]
  SimTK::Matrix dfdu;  ///< d f / d u, nu x nu [N s/m, N m s/rad]
};

/// Work and time of an element's numerical solvers since its construction (diagnostics for
/// summaries and benchmarks; results never depend on them), apart from the physics figures an
/// element's role interface (LinerElement.h) gives.
struct SolverCounters {
  long filmSolves = 0;  ///< film solves (an elastic coupling does several per evaluation)
  long filmFallbacks = 0;       ///< of them finished by the film solver's reference fallback
  long derivativeFailures = 0;  ///< of them that returned no derivatives
  long evaluations = 0;         ///< force evaluations that returned
  /// Wall time [s] of the phases: gap, film, contact and loads include every film solve (each
  /// coupling iteration, and the evaluations that threw).
  double gap_s = 0.0;
  double film_s = 0.0;      ///< see gap_s
  double contact_s = 0.0;   ///< see gap_s
  double loads_s = 0.0;     ///< see gap_s
  double coupling_s = 0.0;  ///< the elastic coupling's own work [s]
  double total_s = 0.0;     ///< the evaluations that returned [s]
};

/// A force element: the interface a user implements (the documentation of ForceElement.h gives the
/// life cycle and where an element keeps what).
class ForceElement {
 public:
  virtual ~ForceElement() = default;

  /// Unique name within a model; used to find, replace and label the element.
  virtual std::string getName() const = 0;

  /// Once, when the model builds its Simbody system: keep handles (crank train, bodies), add
  /// Simbody constraints if the element is kinematic, check parameters against the engine.
  virtual void addToModel(const ModelBuildContext& context) = 0;

  // ---- Simbody realize stages (forwarded by the model's Force::Custom adapter) -----
  /// Once per new default state: allocate state variables and cache entries
  /// (ElementState.h, ElementCache.h).
  virtual void realizeTopology(SimTK::State& /*state*/, ElementStateAllocator& /*alloc*/) const {}
  virtual void realizeModel(SimTK::State& /*state*/) const {}           ///< Simbody's stage
  virtual void realizeInstance(const SimTK::State& /*state*/) const {}  ///< Simbody's stage
  virtual void realizeTime(const SimTK::State& /*state*/) const {}      ///< Simbody's stage
  virtual void realizePosition(const SimTK::State& /*state*/) const {}  ///< Simbody's stage
  virtual void realizeVelocity(const SimTK::State& /*state*/) const {}  ///< Simbody's stage
  virtual void realizeDynamics(const SimTK::State& /*state*/) const {}  ///< Simbody's stage
  /// Every realization to Stage::Acceleration: set the derivatives of the element's z
  /// (ElementZ::setDerivative, every one, every time).
  virtual void realizeAcceleration(const SimTK::State& /*state*/) const {}
  virtual void realizeReport(const SimTK::State& /*state*/) const {}  ///< Simbody's stage

  // ---- forces ------------------------------------------------------------------------
  /// Every force evaluation, state realized through Stage::Velocity: read the kinematics,
  /// call the numerics, apply forces; may compute the update values of auto-update
  /// variables.
  virtual void calcForces(const SimTK::State& state, AppliedForces& forces) const = 0;
  /// Potential energy of the element's forces [J] (Simbody's Force::Custom query); default 0.
  virtual double calcPotentialEnergy(const SimTK::State& /*state*/) const { return 0.0; }
  /// True if calcForces() reads only positions (lets Simbody cache forces at Position).
  virtual bool dependsOnlyOnPositions() const { return false; }
  /// Adds this element's part of the force Jacobian (see ForceJacobian) at a state
  /// realized through Stage::Dynamics. Returns false if the element adds nothing.
  virtual bool addForceJacobian(const SimTK::State& /*state*/, ForceJacobian& /*jacobian*/) const {
    return false;
  }
  /// Whether the next realizations will be asked for the velocity part of addForceJacobian
  /// (dfdu; default: yes). An implicit stepper that keeps its damping Jacobian over several
  /// steps says no before it realizes a state whose dfdu it will not read; an element whose
  /// dfdu is costly (the lubricated skirt: one film back-substitution per pose velocity and
  /// side) may then leave it out - NaN, so that a misuse cannot pass unnoticed - but must still
  /// add the position part (dfdq), which the stepper reads at every evaluation (contact
  /// stiffness switches within a step). Forces and outputs must not depend on it. A request,
  /// not state: read when a realization computes the element's cache entry (a state already
  /// realized keeps what it has).
  virtual void setForceJacobianWanted(bool /*wanted*/) const {}

  // ---- warm start (CycleSimulation.h, WarmStart) ------------------------------------------
  /// What of the element's own state (discrete variables beyond the bodies' q and u) a later
  /// run should start from, as numbers in a layout of the element's own, at a state realized
  /// through Stage::Acceleration; empty (the default): nothing.
  virtual std::vector<double> getWarmStartRecord(const SimTK::State& /*state*/) const {
    return {};
  }
  /// Puts a record of getWarmStartRecord() into a run's initial state (before its integrator
  /// starts). Throws std::invalid_argument when the record does not fit this element (another
  /// grid); the default accepts only an empty record.
  virtual void setWarmStartRecord(SimTK::State& /*state*/,
                                  const std::vector<double>& record) const {
    if (!record.empty())
      throw std::invalid_argument("element '" + getName() + "' keeps no warm-start record");
  }

  // ---- outputs -----------------------------------------------------------------------
  /// Declared once; the model records them when it builds the system.
  virtual ElementOutputs getOutputs() const { return {}; }
  /// The work of the element's solvers so far (SolverCounters), if it counts any.
  virtual std::optional<SolverCounters> getSolverCounters() const { return std::nullopt; }
};

}  // namespace pistondyn::plugin
