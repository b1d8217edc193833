#pragma once
// Argument checks shared by the mapping sources, on top of pistondyn::common (one message
// shape and number format for every module). Every failure throws std::invalid_argument
// whose message names the function and the argument.

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Core>

#include "pistondyn/common/Validation.h"
#include "pistondyn/mapping/CylinderGrid.h"

namespace pistondyn::mapping::detail {

inline void requireFiniteScalar(const char* function, const char* argument, double v) {
  common::requireFinite(v, function, argument, "");
}

// An angle: finite and within +-kMaxAbsAngle_rad (CylinderGrid.h).
inline void requireAngle(const char* function, const char* argument, double v) {
  if (!(std::abs(v) <= kMaxAbsAngle_rad))
    common::throwInvalidValue(function, argument, v, "rad",
                              "finite and within +-1e6 rad (kMaxAbsAngle_rad)");
}

// Size check, then every entry finite (the first offending index is named).
inline void requireFiniteVector(const char* function, const char* argument,
                                const Eigen::Ref<const Eigen::VectorXd>& v,
                                Eigen::Index expectedSize) {
  if (v.size() != expectedSize)
    common::throwInvalidArgument(function, common::message(argument, " has ", v.size(),
                                                           " entries, expected ", expectedSize));
  // Fast path: v * 0 is 0 for every finite entry and NaN otherwise, and a plain sum
  // vectorises (allFinite() does not, and cost 3 us per call on a 64 x 48 field x 3).
  if ((v.array() * 0.0).sum() == 0.0)
    return;
  for (Eigen::Index k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k]))
      common::throwNotFinite(v[k], function, common::message(argument, "[", k, "]"), "");
}

// Node coordinates: at least minCount entries, finite, strictly increasing.
inline void requireIncreasingNodes(const char* function, const char* argument,
                                   const Eigen::Ref<const Eigen::VectorXd>& x, int minCount) {
  if (x.size() < minCount)
    common::throwInvalidArgument(
        function,
        common::message(argument, " has ", x.size(), " nodes, at least ", minCount, " needed"));
  requireFiniteVector(function, argument, x, x.size());
  for (Eigen::Index k = 1; k < x.size(); ++k)
    if (!(x[k] > x[k - 1]))
      common::throwInvalidArgument(
          function,
          common::message(argument, "[", k, "] = ", x[k], " must be greater than ", argument, "[",
                          k - 1, "] = ", x[k - 1], " (strictly increasing)"));
}

// The closing cell of a ring, x[0] + period - x[last], must be at least this fraction of
// the smallest other cell. A legitimately graded ring stays far above it (adjacent cells
// differ by a few times at most); a first node repeated at the end with rounding
// (2*pi - 1e-13) gives ~1e-13 of a cell and a closing cell that the periodic spline and
// the force map treat as a real cell (dPhi ~ 1e13 there).
inline constexpr double kMinClosingCellFraction = 0.01;

inline void requireReasonableClosingCell(const char* function, const char* argument,
                                         const Eigen::Ref<const Eigen::VectorXd>& x,
                                         double period) {
  const Eigen::Index n = x.size();
  const double closing = x[0] + period - x[n - 1];
  double smallestOther = x[1] - x[0];
  for (Eigen::Index k = 2; k < n; ++k)
    smallestOther = std::min(smallestOther, x[k] - x[k - 1]);
  if (!(closing >= kMinClosingCellFraction * smallestOther))
    common::throwInvalidArgument(
        function, common::message("the closing cell ", argument, "[0] + ", period, " - ", argument,
                                  "[", n - 1, "] = ", closing,
                                  " is less than 1 % of the smallest other cell (", smallestOther,
                                  "); is the first node repeated at the end? Drop it (the ring "
                                  "closes itself)"));
}

}  // namespace pistondyn::mapping::detail
