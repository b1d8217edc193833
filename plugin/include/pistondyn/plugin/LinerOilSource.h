#pragma once
/// @file
/// The oil film on the liner that a liner element carries along the bore (the lubricated
/// skirt's liner oil transport, skirt/LinerOilFilm.h), as a role the edge (io/, app/) reads
/// without knowing the element's type, like NodalFieldSource.

#include <Eigen/Core>

namespace SimTK {
class State;
}

namespace pistondyn::plugin {

enum class SkirtSide;

/// Where the liner's oil came from and went since the start of the run, both sides summed
/// [m^3]. stored - initial = ring + splash + deficit - drain - filmIntake - sideLeakage -
/// skirtShare, to round-off (skirt::LinerOilState).
struct LinerOilBalance {
  double stored_m3 = 0.0;          ///< on the liner now
  double initial_m3 = 0.0;         ///< on the liner at the start
  double ringSource_m3 = 0.0;      ///< net film the oil-control ring left
  double splashSource_m3 = 0.0;    ///< crankcase splash
  double deficitSource_m3 = 0.0;   ///< oil the skirt's film drew that the liner did not hold
  double drainLoss_m3 = 0.0;       ///< drained above the largest film
  double filmIntake_m3 = 0.0;      ///< the skirt films' net gain across all their edges
  double sideLeakage_m3 = 0.0;     ///< lost across the films' circumferential edges
  double skirtShareLoss_m3 = 0.0;  ///< left on the skirt at the trailing edge
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
