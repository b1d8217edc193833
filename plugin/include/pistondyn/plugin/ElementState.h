#pragma once
/// \file
/// State variables of a force element: what Simbody gives its own forces
/// (ExponentialSpringForce is the model), wrapped so that an element never handles raw
/// Simbody indices. Allocate them in ForceElement::realizeTopology() through the
/// ElementStateAllocator it receives; read and write them through the handles.
///
/// Which kind to use (docs/DESIGN.md §2: history lives in the State, never in mutable members):
///
///   ElementZ                  continuous states integrated with the motion, for quantities
///                             that must be integrated exactly over the cycle (friction
///                             work, impact energy, wear volume). The element sets their
///                             time derivatives in realizeAcceleration() (setDerivatives).
///   ElementDiscreteVariable   a value that only the user (or an event) changes: an input
///                             switch, a calibration factor. Changing it invalidates
///                             Stage::Dynamics of that State, nothing else.
///   ElementAutoUpdateVariable history that advances once per ACCEPTED integration step:
///                             film fill fraction of the mass-conserving model, inlet
///                             film, wear depth. During a force evaluation the element
///                             computes the value the variable should take if this step
///                             is accepted and stores it with setUpdateValue(); the
///                             integrator swaps it in after the step is accepted
///                             (SimTK::State::autoUpdateDiscreteVariables()), and a
///                             rejected or abandoned trial step leaves the variable as it
///                             was. getLastUpdateTime() gives the time of the last swap
///                             (e.g. the film's transient time step is t - that time).
///                             Simbody's integrators swap at initialize() and at the start
///                             of every step; the swap invalidates no cached result, so a
///                             force must not jump when it happens (let the history enter
///                             through increments that vanish with the step, as Archard
///                             wear dw = k F |v| dt does).
///
/// Every handle is a small value set once per realizeTopology() (Simbody's own pattern:
/// the indices are the same in every State made from that topology). Copies of a State
/// carry their own values, so rewinding a simulation is copying a State.

#include "pistondyn/mbd_models/SimbodyBuildCheck.h"
// clang-format off (the NDEBUG guard must come before Simbody)
#include <Simbody.h>
// clang-format on

#include <cmath>
#include <stdexcept>
#include <string>

namespace pistondyn::plugin {

/// Handed to ForceElement::realizeTopology(): allocates the element's state variables
/// and cache entries in the force subsystem of the model.
class ElementStateAllocator {
 public:
  /// The default state being built and the subsystem that owns the element's variables.
  ElementStateAllocator(SimTK::State& state, const SimTK::Subsystem& subsystem)
      : state_(state), subsystem_(subsystem) {}
  SimTK::State& updState() { return state_; }                          ///< the state
  const SimTK::Subsystem& getSubsystem() const { return subsystem_; }  ///< the subsystem

 private:
  SimTK::State& state_;
  const SimTK::Subsystem& subsystem_;
};

/// Implementation details (not API).
namespace detail {
/// Throws std::logic_error: `what` used before realizeTopology() allocated it.
[[noreturn]] inline void throwUnallocated(const char* what) {
  throw std::logic_error(std::string(what) +
                         ": used before ForceElement::realizeTopology() allocated it");
}
}  // namespace detail

/// A block of continuous states z (Simbody's auxiliary states), integrated by the
/// integrator together with q and u.
class ElementZ {
 public:
  /// Inputs:  initialValues  one entry per state variable (its value in the default State)
  void allocate(ElementStateAllocator& a, const SimTK::Vector& initialValues) const {
    subsystem_ = &a.getSubsystem();
    first_ = subsystem_->allocateZ(a.updState(), initialValues);
    size_ = initialValues.size();
  }
  int size() const { return size_; }  ///< number of state variables in the block
  /// Value of state variable k (any stage).
  double getValue(const SimTK::State& s, int k) const {
    check();
    return subsystem_->getZ(s)[first_ + k];
  }
  /// Sets state variable k (e.g. to reset an integral); invalidates Stage::Dynamics.
  void setValue(SimTK::State& s, int k, double value) const {
    check();
    subsystem_->updZ(s)[first_ + k] = value;
  }
  /// Time derivative of state variable k; call from realizeAcceleration() (or
  /// realizeDynamics()) of the element, for every k, on every realization.
  void setDerivative(const SimTK::State& s, int k, double zdot) const {
    check();
    subsystem_->updZDot(s)[first_ + k] = zdot;
  }

 private:
  void check() const {
    if (subsystem_ == nullptr)
      detail::throwUnallocated("ElementZ");
  }
  mutable const SimTK::Subsystem* subsystem_ = nullptr;
  mutable SimTK::ZIndex first_;
  mutable int size_ = 0;
};

/// A discrete state variable of type T changed only from outside the integration.
template <class T>
class ElementDiscreteVariable {
 public:
  /// Allocates the variable with its value in the default State (from realizeTopology()).
  void allocate(ElementStateAllocator& a, const T& initialValue) const {
    subsystem_ = &a.getSubsystem();
    index_ = subsystem_->allocateDiscreteVariable(a.updState(), SimTK::Stage::Dynamics,
                                                  new SimTK::Value<T>(initialValue));
  }
  /// The value in `s`.
  const T& getValue(const SimTK::State& s) const {
    check();
    return SimTK::Value<T>::downcast(subsystem_->getDiscreteVariable(s, index_)).get();
  }
  /// Sets the value (between steps); invalidates Stage::Dynamics.
  void setValue(SimTK::State& s, const T& value) const {
    check();
    SimTK::Value<T>::updDowncast(subsystem_->updDiscreteVariable(s, index_)).upd() = value;
  }

 private:
  void check() const {
    if (subsystem_ == nullptr)
      detail::throwUnallocated("ElementDiscreteVariable");
  }
  mutable const SimTK::Subsystem* subsystem_ = nullptr;
  mutable SimTK::DiscreteVariableIndex index_;
};

/// A discrete state variable of type T advanced once per accepted step (see top).
template <class T>
class ElementAutoUpdateVariable {
 public:
  /// Allocates the variable with its value in the default State (from realizeTopology()).
  void allocate(ElementStateAllocator& a, const T& initialValue) const {
    subsystem_ = &a.getSubsystem();
    // Changing the variable invalidates Dynamics (forces depend on it); its update value
    // is computed from a state realized through Velocity (inside calcForces()) and is
    // discarded whenever the state's time, q or u change, so a swap only ever installs a
    // value computed from the state being accepted (LinearlyImplicitStepper therefore swaps
    // in place in the evaluated iterate it accepts).
    index_ = subsystem_->allocateAutoUpdateDiscreteVariable(a.updState(), SimTK::Stage::Dynamics,
                                                            new SimTK::Value<T>(initialValue),
                                                            SimTK::Stage::Velocity);
    updateIndex_ = subsystem_->getDiscreteVarUpdateIndex(a.updState(), index_);
  }
  /// The current (accepted) value.
  const T& getValue(const SimTK::State& s) const {
    check();
    return SimTK::Value<T>::downcast(subsystem_->getDiscreteVariable(s, index_)).get();
  }
  /// Overwrites the current value (initial conditions; not during integration).
  void setValue(SimTK::State& s, const T& value) const {
    check();
    SimTK::Value<T>::updDowncast(subsystem_->updDiscreteVariable(s, index_)).upd() = value;
  }
  /// Time of the last update [s]; NaN before the first one (a State that no integrator
  /// has initialised yet).
  double getLastUpdateTime(const SimTK::State& s) const {
    check();
    return subsystem_->getDiscreteVarLastUpdateTime(s, index_);
  }
  /// s.getTime() - getLastUpdateTime(s), or 0 before the first update [s].
  double calcTimeSinceLastUpdate(const SimTK::State& s) const {
    const double last = getLastUpdateTime(s);
    return std::isfinite(last) ? s.getTime() - last : 0.0;
  }
  /// Stores the value the variable takes if the step ending at this state is accepted.
  /// Callable on a const State (it writes the State's cache, like every realize step).
  void setUpdateValue(const SimTK::State& s, const T& value) const {
    check();
    SimTK::Value<T>::updDowncast(subsystem_->updDiscreteVarUpdateValue(s, index_)).upd() = value;
    subsystem_->markDiscreteVarUpdateValueRealized(s, index_);
  }
  /// True if setUpdateValue() was called since the state last changed.
  bool hasUpdateValue(const SimTK::State& s) const {
    check();
    return subsystem_->isDiscreteVarUpdateValueRealized(s, index_);
  }
  /// The value stored by setUpdateValue() (check hasUpdateValue() first).
  const T& getUpdateValue(const SimTK::State& s) const {
    check();
    return SimTK::Value<T>::downcast(subsystem_->getDiscreteVarUpdateValue(s, index_)).get();
  }

 private:
  void check() const {
    if (subsystem_ == nullptr)
      detail::throwUnallocated("ElementAutoUpdateVariable");
  }
  mutable const SimTK::Subsystem* subsystem_ = nullptr;
  mutable SimTK::DiscreteVariableIndex index_;
  mutable SimTK::CacheEntryIndex updateIndex_;
};

}  // namespace pistondyn::plugin
