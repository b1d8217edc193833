#pragma once
// Helpers for the skirt tests that do not use the library under test: Gauss-Legendre rules
// (Newton iteration on the Legendre recurrence), the 1-D hat function of a node, and a default
// skirt side.

#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "GaussLegendre.h"

#include "pistondyn/skirt/SkirtSideGrid.h"

namespace pistondyn::skirt::test {

constexpr double kPi = 3.14159265358979323846264338327950;

// n-point Gauss-Legendre nodes and weights on [-1, 1] (tests/support/GaussLegendre.h).
using pistondyn::test::gaussLegendre;

// Hat function of node i of the increasing nodes x, at t.
inline double hat(const Eigen::VectorXd& x, int i, double t) {
  if (i > 0 && t >= x[i - 1] && t <= x[i])
    return (t - x[i - 1]) / (x[i] - x[i - 1]);
  if (i + 1 < x.size() && t >= x[i] && t <= x[i + 1])
    return (x[i + 1] - t) / (x[i + 1] - x[i]);
  return 0.0;
}

// A thrust-side skirt of a 74 mm bore: 60 deg wide, 40 mm long from 15 mm above the pin axis.
inline SkirtSideGridParameters thrustSide(int nPhi = 24, int nY = 18) {
  SkirtSideGridParameters p;
  p.side = SkirtSide::Thrust;
  p.radius_m = 0.037;
  p.arcWidth_rad = kPi / 3.0;
  p.nPhi = nPhi;
  p.nY = nY;
  p.skirtTopHeight_m = 0.015;
  p.skirtLength_m = 0.040;
  return p;
}

}  // namespace pistondyn::skirt::test
