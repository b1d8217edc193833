#pragma once
// Argument checks shared by the mapping sources. Every failure throws
// std::invalid_argument whose message names the function and the argument.

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "pistondyn/mapping/CylinderGrid.h"

namespace pistondyn::mapping::detail {

[[noreturn]] inline void fail(const char* function, const std::string& what) {
  throw std::invalid_argument(std::string(function) + ": " + what);
}

inline std::string str(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

inline void requireFiniteScalar(const char* function, const char* argument, double v) {
  if (!std::isfinite(v))
    fail(function, std::string(argument) + " = " + str(v) + " must be finite");
}

// An angle: finite and within +-kMaxAbsAngle_rad (CylinderGrid.h).
inline void requireAngle(const char* function, const char* argument, double v) {
  if (!(std::abs(v) <= kMaxAbsAngle_rad))
    fail(function, std::string(argument) + " = " + str(v) +
                       " rad must be finite and within +-1e6 rad (kMaxAbsAngle_rad)");
}

// Size check, then every entry finite (the first offending index is named).
inline void requireFiniteVector(const char* function, const char* argument,
                                const Eigen::Ref<const Eigen::VectorXd>& v,
                                Eigen::Index expectedSize) {
  if (v.size() != expectedSize)
    fail(function, std::string(argument) + " has " + std::to_string(v.size()) +
                       " entries, expected " + std::to_string(expectedSize));
  // Fast path: v * 0 is 0 for every finite entry and NaN otherwise, and a plain sum
  // vectorises (allFinite() does not, and cost 3 us per call on a 64 x 48 field x 3).
  if ((v.array() * 0.0).sum() == 0.0)
    return;
  for (Eigen::Index k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k]))
      fail(function, std::string(argument) + "[" + std::to_string(k) + "] = " + str(v[k]) +
                         " must be finite");
}

// Node coordinates: at least minCount entries, finite, strictly increasing.
inline void requireIncreasingNodes(const char* function, const char* argument,
                                   const Eigen::Ref<const Eigen::VectorXd>& x, int minCount) {
  if (x.size() < minCount)
    fail(function, std::string(argument) + " has " + std::to_string(x.size()) +
                       " nodes, at least " + std::to_string(minCount) + " needed");
  requireFiniteVector(function, argument, x, x.size());
  for (Eigen::Index k = 1; k < x.size(); ++k)
    if (!(x[k] > x[k - 1]))
      fail(function, std::string(argument) + "[" + std::to_string(k) + "] = " + str(x[k]) +
                         " must be greater than " + argument + "[" + std::to_string(k - 1) +
                         "] = " + str(x[k - 1]) + " (strictly increasing)");
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
    fail(function, std::string("the closing cell ") + argument + "[0] + " + str(period) + " - " +
                       argument + "[" + std::to_string(n - 1) + "] = " + str(closing) +
                       " is less than 1 % of the smallest other cell (" + str(smallestOther) +
                       "); is the first node repeated at the end? Drop it (the ring closes "
                       "itself)");
}

}  // namespace pistondyn::mapping::detail
