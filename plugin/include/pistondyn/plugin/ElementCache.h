#pragma once
/// \file
/// Per-state results of one force element, kept in the Simbody State cache (so two
/// states never share results and nothing global is touched). Allocate in
/// ForceElement::realizeTopology(); fill lazily from calcForces() or an output getter:
///
///   const Results& r = cache_.getOrCalc(s, [&](Results& out) { ...compute... });
///
/// `dependsOn` is the stage whose invalidation must discard the results. The default,
/// Stage::Dynamics, is the safe choice for anything computed in calcForces(): it is
/// invalidated by changes of q, u AND of auxiliary state variables z (Simbody's updZ()
/// only backs the state up to Dynamics-1), which is where film fill fraction or wear
/// will live. Use an earlier stage only for results that depend on nothing else (e.g.
/// Stage::Position for a function of the crank angle alone).
///
/// Inside calcForces() the state is still at Stage::Velocity, so a Dynamics-dependent
/// entry is computed on each call there (once per force evaluation) and reads as valid
/// from the moment the state reaches Stage::Dynamics (reports, other elements).

#include "pistondyn/mbd_models/SimbodyBuildCheck.h"
// clang-format off (the NDEBUG guard must come before Simbody)
#include <Simbody.h>
// clang-format on

#include <stdexcept>

#include "pistondyn/plugin/ElementState.h"

namespace pistondyn::plugin {

/// Per-state results of an element in a lazy cache entry of the State (this file's
/// documentation).
///
/// Why a stamp besides Simbody's own validity: Simbody 3.7 copies a State's cache entries
/// with it, and a lazy entry copied from a state realized beyond its stage can read as valid
/// in the copy after the copy's time and q have changed (a stepper that copies an accepted,
/// realized state and moves the copy to the next step would see the previous step's forces).
/// Each value therefore carries the time and Simbody's value versions of q, u and z it was
/// computed at, and is recomputed when they differ.
template <class T>
class ElementCache {
 public:
  /// resultsDependOnZ = false: the results are a function of t, q, u (and the element's
  /// discrete variables) alone, not of the auxiliary states z, e.g. an element whose z are
  /// only integrals of its own outputs (friction work, wear volume). The entry then depends
  /// on Stage::Velocity at most and ignores z in its stamp, so that an integrator which
  /// corrects z after a force evaluation (LinearlyImplicitStepper: the implicit quadrature
  /// of the z with the accepted state's rates) does not make the next realization of that
  /// state solve everything again.
  void allocate(ElementStateAllocator& a, SimTK::Stage dependsOn = SimTK::Stage::Dynamics,
                bool resultsDependOnZ = true) const {
    subsystem_ = &a.getSubsystem();
    dependsOnZ_ = resultsDependOnZ;
    if (!resultsDependOnZ && dependsOn > SimTK::Stage::Velocity)
      dependsOn = SimTK::Stage::Velocity;
    index_ =
        subsystem_->allocateLazyCacheEntry(a.updState(), dependsOn, new SimTK::Value<Stamped>());
  }

  /// The results for state `s`: computed by calc(T&) unless the entry already holds them
  /// for this state (stamp and Simbody's validity).
  template <class Calc>
  const T& getOrCalc(const SimTK::State& s, Calc&& calc) const {
    if (subsystem_ == nullptr) {
      throw std::logic_error("ElementCache: used before realizeTopology() allocated it");
    }
    // updCacheEntry: readable below the entry's stage (inside calcForces), unlike
    // getCacheEntry which checks the stage.
    Stamped& entry = SimTK::Value<Stamped>::updDowncast(subsystem_->updCacheEntry(s, index_)).upd();
    const Stamp now{s.getTime(), s.getQValueVersion(), s.getUValueVersion(),
                    dependsOnZ_ ? s.getZValueVersion() : SimTK::ValueVersion(-1)};
    if (!subsystem_->isCacheValueRealized(s, index_) || !(entry.stamp == now)) {
      calc(entry.value);
      entry.stamp = now;
      subsystem_->markCacheValueRealized(s, index_);
    }
    return entry.value;
  }

 private:
  struct Stamp {
    double time = -1.0;
    SimTK::ValueVersion q = -1, u = -1, z = -1;
    bool operator==(const Stamp& o) const {
      return time == o.time && q == o.q && u == o.u && z == o.z;
    }
  };
  struct Stamped {
    T value;
    Stamp stamp;
  };

  /// Set once per realizeTopology (Simbody's own pattern for topology indices).
  mutable const SimTK::Subsystem* subsystem_ = nullptr;
  mutable SimTK::CacheEntryIndex index_;
  mutable bool dependsOnZ_ = true;
};

}  // namespace pistondyn::plugin
