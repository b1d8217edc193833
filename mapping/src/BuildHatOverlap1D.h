#pragma once
// Internal to pistondyn::mapping: calcHatOverlap1D without its argument checks, for
// callers whose nodes were already checked (TensorForceMap::setAxialOffset rebuilds the
// axial factor every step from the CylinderGrid's y nodes, checked when the grid was made).

#include <Eigen/Core>

#include "pistondyn/mapping/HatOverlap1D.h"

namespace pistondyn::mapping::detail {

// Same inputs and result as calcHatOverlap1D (HatOverlap1D.h); the caller guarantees what
// it would check: finite offset and period, nodes finite and strictly increasing (>= 2,
// >= 3 when closed), period > 0 for a closed grid, spans below a period, offset within
// kMaxAbsAngle_rad's number of turns, reasonable closing cells. Nothing is checked here.
void buildHatOverlap1D(const Eigen::VectorXd& sourceNodes, bool sourceClosed,
                       const Eigen::VectorXd& targetNodes, bool targetClosed, double period,
                       double offset, LoadRule rule, bool withTrig, HatOverlap1D& out);

}  // namespace pistondyn::mapping::detail
