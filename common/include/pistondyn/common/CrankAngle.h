#pragma once
/// \file
/// The crank angle of the engine cycle: rows, tables and messages carry it in [0, 720) deg
/// (0 = firing TDC), while the simulation's angle grows without bound (4 pi per cycle).

#include <cmath>

namespace pistondyn::common {

/// Inputs: any finite crank angle [deg]. Output: the same angle of the cycle, in [0, 720) deg
/// (an input just below a multiple of 720 whose remainder rounds up to 720 gives 0).
inline double wrapCrankAngle_deg(double angle_deg) {
  double a = std::fmod(angle_deg, 720.0);
  if (a < 0.0)
    a += 720.0;
  return a < 720.0 ? a : 0.0;
}

}  // namespace pistondyn::common
