#pragma once
// Internal to pistondyn::mapping: 2*pi and the cells of a line of nodes, open or closed
// into a ring, shared by the grid, the spline slopes, the Hermite surface and the hat
// overlaps.

#include <Eigen/Core>

namespace pistondyn::mapping::detail {

inline constexpr double kTwoPi = 6.283185307179586476925286766559;

// Node i of the strictly increasing nodes x, where i == x.size() is the closing node
// x[0] + period of a ring (as CylinderGrid::phiNode_rad for a full circle).
inline double ringNode(const Eigen::VectorXd& x, double period, Eigen::Index i) {
  return i < x.size() ? x[i] : x[0] + period;
}

// Widths of the cells of x: x.size() - 1 for an open line; x.size() for a ring (closed),
// whose last cell closes it from x[last] to x[0] + period.
inline Eigen::VectorXd cellWidths(const Eigen::VectorXd& x, bool closed, double period) {
  const Eigen::Index cells = closed ? x.size() : x.size() - 1;
  Eigen::VectorXd h(cells);
  for (Eigen::Index c = 0; c < cells; ++c)
    h[c] = ringNode(x, period, c + 1) - x[c];
  return h;
}

}  // namespace pistondyn::mapping::detail
