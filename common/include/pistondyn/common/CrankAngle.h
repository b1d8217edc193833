#pragma once
/// \file
/// The crank angle of the engine cycle: rows, tables and messages carry it in [0, 720) deg
/// (0 = firing TDC), while the simulation's angle grows without bound (4 pi per cycle).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace pistondyn::common {

/// Inputs: any finite crank angle [deg]. Output: the same angle of the cycle, in [0, 720) deg
/// (an input just below a multiple of 720 whose remainder rounds up to 720 gives 0).
inline double wrapCrankAngle_deg(double angle_deg) {
  double a = std::fmod(angle_deg, 720.0);
  if (a < 0.0)
    a += 720.0;
  return a < 720.0 ? a : 0.0;
}

/// A table over the 720 deg cycle read at a crank angle: linear between its points, the
/// segment after the last point wrapping to the first. Inputs: angle_deg strictly increasing
/// within [0, 720), value of the same size, at least 2 points (the caller checks); angle: any
/// finite crank angle [deg].
inline double interpolateOverCycle(const std::vector<double>& angle_deg,
                                   const std::vector<double>& value, double angle) {
  const std::size_t n = angle_deg.size();
  double a = wrapCrankAngle_deg(angle);
  const auto it = std::upper_bound(angle_deg.begin(), angle_deg.end(), a);
  const std::size_t hi = static_cast<std::size_t>(it - angle_deg.begin()) % n;
  const std::size_t lo = (hi + n - 1) % n;
  const double a0 = angle_deg[lo];
  double a1 = angle_deg[hi];
  if (a1 <= a0)
    a1 += 720.0;
  if (a < a0)
    a += 720.0;
  const double w = (a - a0) / (a1 - a0);
  return (1.0 - w) * value[lo] + w * value[hi];
}

}  // namespace pistondyn::common
