#pragma once
/// @file
/// Role interface of the element that holds the piston in the bore (the ideal liner
/// guide, the lubricated skirt, a user's own liner model). Summaries, convergence checks
/// and plots ask the model's liner element for these physics figures through this interface,
/// so they work with whatever liner a deck selects and never look up columns by name or cast
/// to a concrete element. Solver counters are not figures: ForceElement::getSolverCounters().
///
/// Every getter needs a state realized through Stage::Acceleration.

#include <optional>

#include "pistondyn/plugin/ForceElement.h"
#include "pistondyn/plugin/LinerOilSource.h"
#include "pistondyn/plugin/NodalFields.h"

namespace pistondyn::plugin {

/// A side of the skirt: Thrust (+x, the side the piston presses on in the expansion stroke)
/// or AntiThrust (-x).
enum class SkirtSide { Thrust, AntiThrust };

/// The element that holds the piston in the bore, seen through the physics figures that
/// summaries, convergence checks and plots read (this file's comment). A user's liner derives
/// from it, implements getSideForce_N() and overrides the optional getters it can answer; the
/// defaults say "not provided" (0 or nullopt). Every getter needs a state realized through
/// Stage::Acceleration.
class LinerElement : public ForceElement {
 public:
  /// Lateral force the piston exerts on the liner, + towards the thrust side [N].
  virtual double getSideForce_N(const SimTK::State& s) const = 0;
  /// Axial friction force the liner exerts on the piston, + along +y (towards the head) [N].
  virtual double getFrictionForce_N(const SimTK::State& /*s*/) const { return 0.0; }
  /// Power the axial friction force takes from the piston's primary motion, -F_y v_y [W] (with
  /// the pressure terms of a film: what it dissipates along the stroke; >= 0 typical).
  virtual double getFrictionPower_W(const SimTK::State& /*s*/) const { return 0.0; }
  /// The integral of getFrictionPower_W since the start of the run [J], if the element
  /// integrates it (a continuous state); nullopt otherwise.
  virtual std::optional<double> getFrictionWork_J(const SimTK::State& /*s*/) const {
    return std::nullopt;
  }
  /// Minimum film thickness on one side of the skirt [m]; nullopt for a liner without a
  /// film (the ideal guide).
  virtual std::optional<double> getMinFilmThickness_m(const SimTK::State& /*s*/,
                                                      SkirtSide /*side*/) const {
    return std::nullopt;
  }
  /// Smallest ratio of the nominal gap to the composite roughness on one side [-].
  virtual std::optional<double> getMinGapOverSigma(const SimTK::State& /*s*/,
                                                   SkirtSide /*side*/) const {
    return std::nullopt;
  }
  /// Impact kinetic energy of the last completed slap event [J] (the element's definition).
  virtual std::optional<double> getLastSlapEnergy_J(const SimTK::State& /*s*/) const {
    return std::nullopt;
  }
  /// Radial clearance between skirt and liner at operating temperature [m].
  virtual std::optional<double> getHotRunningClearance_m() const { return std::nullopt; }
  /// The part of getFrictionWork_J dissipated by asperity (boundary) friction [J], if the
  /// element integrates it.
  virtual std::optional<double> getAsperityFrictionWork_J(const SimTK::State& /*s*/) const {
    return std::nullopt;
  }
  /// The energy the liner's friction and film dissipated since the start of the run [J], if
  /// the element integrates it: over a periodic cycle getFrictionWork_J() +
  /// getSecondaryMotionWork_J() = this.
  virtual std::optional<double> getDissipatedEnergy_J(const SimTK::State& /*s*/) const {
    return std::nullopt;
  }
  /// The work the liner's forces took from the piston's secondary motion since the start of
  /// the run [J], if the element integrates it (see getDissipatedEnergy_J()).
  virtual std::optional<double> getSecondaryMotionWork_J(const SimTK::State& /*s*/) const {
    return std::nullopt;
  }
  /// Nodal fields over the liner's contact regions (NodalFields.h), for field dumps and maps;
  /// null for a liner without them.
  virtual const NodalFieldSource* getNodalFields() const { return nullptr; }
  /// The oil film it carries on the liner along the bore (LinerOilSource.h); null for a liner
  /// without one.
  virtual const LinerOilSource* getLinerOil() const { return nullptr; }
};

/// The outputs the summary, the figures and the report know, computed from the liner role's
/// getters (and the crank train's kinematics): a liner declares in its getOutputs() those it
/// provides, so that every liner, built in or a user's, gets the same columns and figures for
/// the same figures. The optional getters of a declared output must have values.
enum class LinerOutput {
  SideForce,                ///< side_force [N]
  LateralAtSkirtTop,        ///< u_lat_skirt_top [um] (kinematic: lateral displacement and tilt)
  LateralAtSkirtBottom,     ///< u_lat_skirt_bottom [um]
  FrictionForce,            ///< friction_force [N]
  FrictionPower,            ///< friction_power [W]
  FrictionWork,             ///< friction_work [J]
  MinFilmThrust,            ///< min_film_thickness_thrust [um]
  MinFilmAntiThrust,        ///< min_film_thickness_antithrust [um]
  MinGapOverSigmaThrust,    ///< min_h_over_sigma_thrust [1]
  MinGapOverSigmaAntiThrust,  ///< min_h_over_sigma_antithrust [1]
};
/// The output `which` of `liner` (which must outlive it) in a model of `crankTrain`.
ElementOutput makeLinerOutput(LinerOutput which, const LinerElement& liner,
                              const mbd::CrankTrain& crankTrain);

}  // namespace pistondyn::plugin
