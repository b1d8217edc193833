#pragma once
// Per-state results of one force element, kept in the Simbody State cache (so two
// states never share results and nothing global is touched). Allocate in
// ForceElement::realizeTopology(); fill lazily from calcForces() or calcReport():
//
//   const Results& r = cache_.getOrCalc(s, [&](Results& out) { ...compute... });
//
// The entry is invalidated by Simbody whenever the state changes at or below
// `dependsOn` (default Stage::Velocity: results depend on positions and speeds).

#include <Simbody.h>

#include <stdexcept>

namespace pistondyn::plugin {

template <class T>
class ElementCache {
 public:
  void allocate(SimTK::State& s, const SimTK::Subsystem& subsystem,
                SimTK::Stage dependsOn = SimTK::Stage::Velocity) const {
    subsystem_ = &subsystem;
    index_ = subsystem.allocateLazyCacheEntry(s, dependsOn, new SimTK::Value<T>());
  }

  template <class Calc>
  const T& getOrCalc(const SimTK::State& s, Calc&& calc) const {
    if (subsystem_ == nullptr) {
      throw std::logic_error("ElementCache: used before realizeTopology() allocated it");
    }
    if (!subsystem_->isCacheValueRealized(s, index_)) {
      calc(SimTK::Value<T>::updDowncast(subsystem_->updCacheEntry(s, index_)).upd());
      subsystem_->markCacheValueRealized(s, index_);
    }
    return SimTK::Value<T>::downcast(subsystem_->getCacheEntry(s, index_)).get();
  }

 private:
  // Set once per realizeTopology (Simbody's own pattern for topology indices).
  mutable const SimTK::Subsystem* subsystem_ = nullptr;
  mutable SimTK::CacheEntryIndex index_;
};

}  // namespace pistondyn::plugin
