#pragma once
/// \file
/// The film gap under a floor: where rough surfaces touch, their mean planes may overlap (a
/// nominal gap h <= 0) while oil stays in the roughness valleys, so the film solve takes the
/// smooth maximum of the nominal gap and a floor h_c > 0,
///   h_f = (h + h_c + sqrt((h - h_c)^2 + h_c^2)) / 2,   h_c < h_f,   dh_f/dh in (0, 1),
/// h_f -> h where h >> h_c (h_f - h = h_c^2 / (4 h) + ...) and h_f -> h_c + h_c^2 / (4 |h|) where
/// h << -h_c. Inverse: h = h_f - h_c^2 / (4 (h_f - h_c)).
///
/// FilmProblem::gapFloor_m names the floor of a problem whose gap_m are such film gaps; the
/// solver then integrates the face values along the nominal gap (FilmProblem.h). Callers that
/// floor their gaps use these two functions, so both sides share one formula.

#include <algorithm>
#include <cmath>
#include <limits>

namespace pistondyn::lubrication {

/// The film gap over its floor and its first two derivatives with respect to the nominal gap.
struct FlooredGap {
  double film_m = 0.0;  ///< h_f [m]
  double slope = 0.0;   ///< dh_f/dh [-]
  /// d^2h_f/dh^2 = h_c^2 / (2 ((h - h_c)^2 + h_c^2)^(3/2)) [1/m] (> 0): a film rate
  /// slope * dh/dt changes with the gap through it.
  double curvature_per_m = 0.0;
};

/// Inputs: nominal gap h [m] (finite), floor h_c [m] (> 0).
inline FlooredGap calcFlooredGap(double nominal_m, double floor_m) {
  const double d = nominal_m - floor_m;
  const double root = std::sqrt(d * d + floor_m * floor_m);
  return {0.5 * (nominal_m + floor_m + root), 0.5 * (1.0 + d / root),
          0.5 * floor_m * floor_m / (root * root * root)};
}

/// Inputs: film gap h_f [m] (> h_c), floor h_c [m] (> 0). Returns the nominal gap [m]; a film
/// gap at the floor itself (rounding) maps to the lowest finite value.
inline double calcNominalGap(double film_m, double floor_m) {
  const double excess = film_m - floor_m;
  if (!(excess > 0.0))
    return std::numeric_limits<double>::lowest();
  return film_m - floor_m * floor_m / (4.0 * excess);
}

}  // namespace pistondyn::lubrication
