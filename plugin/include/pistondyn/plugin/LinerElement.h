#pragma once
// Role interface of the element that holds the piston in the bore (the ideal liner
// guide, the lubricated skirt, a user's own liner model). Summaries, convergence checks
// and plots ask the model's liner element for these figures through this interface, so
// they work with whatever liner a deck selects and never look up columns by name.
//
// Every getter needs a state realized through Stage::Acceleration.

#include <optional>

#include "pistondyn/plugin/ForceElement.h"

namespace pistondyn::plugin {

enum class SkirtSide { Thrust, AntiThrust };

class LinerElement : public ForceElement {
 public:
  // Lateral force the piston exerts on the liner, + towards the thrust side [N].
  virtual double getSideForce_N(const SimTK::State& s) const = 0;
  // Axial friction force the liner exerts on the piston, + along +y (towards the head) [N].
  virtual double getFrictionForce_N(const SimTK::State& /*s*/) const { return 0.0; }
  // Power dissipated by friction between skirt and liner, >= 0 [W].
  virtual double getFrictionPower_W(const SimTK::State& /*s*/) const { return 0.0; }
  // Friction work dissipated since the start of the run, >= 0 [J], if the element
  // integrates it (a continuous state); nullopt otherwise.
  virtual std::optional<double> getFrictionWork_J(const SimTK::State& /*s*/) const {
    return std::nullopt;
  }
  // Minimum film thickness on one side of the skirt [m]; nullopt for a liner without a
  // film (the ideal guide).
  virtual std::optional<double> getMinFilmThickness_m(const SimTK::State& /*s*/,
                                                      SkirtSide /*side*/) const {
    return std::nullopt;
  }
  // Smallest ratio of the nominal gap to the composite roughness on one side [-].
  virtual std::optional<double> getMinGapOverSigma(const SimTK::State& /*s*/,
                                                   SkirtSide /*side*/) const {
    return std::nullopt;
  }
  // Impact kinetic energy of the last completed slap event [J] (the element's definition).
  virtual std::optional<double> getLastSlapEnergy_J(const SimTK::State& /*s*/) const {
    return std::nullopt;
  }
  // Radial clearance between skirt and liner at operating temperature [m].
  virtual std::optional<double> getHotRunningClearance_m() const { return std::nullopt; }
  // Film solves done by the element so far, how many of them needed the film solver's
  // fallback to the reference solver, and how many returned no squeeze derivatives (their
  // linear solve failed; FilmResult::derivativesFailed) (diagnostics; counted over the
  // element's life).
  virtual std::optional<long> getFilmSolveCount() const { return std::nullopt; }
  virtual std::optional<long> getFilmFallbackCount() const { return std::nullopt; }
  virtual std::optional<long> getFilmDerivativeFailureCount() const { return std::nullopt; }
};

}  // namespace pistondyn::plugin
