#pragma once
/// @file
/// The oil film on the liner that a liner element carries along the bore (the lubricated
/// skirt's liner oil transport, skirt/LinerOilFilm.h), as a role the edge (io/, app/) reads
/// without knowing the element's type, like NodalFieldSource.

#include <Eigen/Core>

#include "pistondyn/skirt/LinerOilFilm.h"

namespace SimTK {
class State;
}

namespace pistondyn::plugin {

enum class SkirtSide;

/// The liner's oil since the start of the run, both sides summed: stored - initial =
/// flows.netSource_m3(), to round-off (skirt::LinerOilFlows).
struct LinerOilBalance {
  double stored_m3 = 0.0;       ///< on the liner now [m^3]
  double initial_m3 = 0.0;      ///< on the liner at the start [m^3]
  skirt::LinerOilFlows flows;   ///< what came and went
};

/// The liner film of an element (LinerElement::getLinerOil()).
class LinerOilSource {
 public:
  virtual ~LinerOilSource() = default;
  /// Bore heights of the film's rows above the crank axis [m], increasing.
  virtual Eigen::VectorXd getLinerOilRowHeights_m() const = 0;
  /// The film along the bore on one side at the last accepted step before state s [m] (per
  /// row: mean over the side's arc; 0 where the skirt covers the liner).
  virtual void calcLinerOilFilm(const SimTK::State& s, SkirtSide side,
                                Eigen::VectorXd& film_m) const = 0;
  /// The balance since the start, both sides, at the last accepted step before state s.
  virtual LinerOilBalance calcLinerOilBalance(const SimTK::State& s) const = 0;
};

}  // namespace pistondyn::plugin
