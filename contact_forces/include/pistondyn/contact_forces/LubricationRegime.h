#pragma once
/// \file
/// Lubrication regime from the film ratio h/σ (nominal gap over composite RMS roughness),
/// with the bounds used by the thesis (after Patir & Cheng):
///   hydrodynamic  h/σ > 3       surfaces separated by the film, asperities do not touch
///   mixed         1 < h/σ ≤ 3   film and asperities share the load
///   boundary      h/σ ≤ 1       asperity contact dominates (Coulomb friction)

#include <cstdint>

namespace pistondyn::contact_forces {

/// Lubrication regime of a node (bounds above).
enum class LubricationRegime : std::uint8_t {
  Hydrodynamic = 0,  ///< h/σ > 3
  Mixed = 1,         ///< 1 < h/σ ≤ 3
  Boundary = 2,      ///< h/σ ≤ 1
};

/// Film-ratio bounds between the regimes [-].
inline constexpr double kMixedRegimeUpperFilmRatio = 3.0;  ///< h/σ ≤ 3 is no longer hydrodynamic
inline constexpr double kBoundaryRegimeUpperFilmRatio = 1.0;  ///< h/σ ≤ 1 is boundary

/// Regime of one node.
/// Inputs:  filmRatio  h/σ [-], not NaN (+inf is hydrodynamic, −inf boundary)
/// Outputs: the regime; throws std::invalid_argument for NaN.
LubricationRegime classifyRegime(double filmRatio);

/// "hydrodynamic", "mixed" or "boundary".
const char* toString(LubricationRegime regime);

}  // namespace pistondyn::contact_forces
