#pragma once
// Argument checks shared by the pistondyn::skirt sources (private header), a thin layer over
// pistondyn::common (one message shape and number format for every module). Every failure
// throws std::invalid_argument whose message names the function or parameter struct, the
// member and what was expected (docs/CONVENTIONS.md).

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "pistondyn/common/Validation.h"

namespace pistondyn::skirt::detail {

// Names and units are std::string_view so that a passing check builds no string (the per-call
// checks must not allocate); the message is built only to throw.
[[noreturn]] inline void fail(std::string_view where, const std::string& what) {
  common::throwInvalidArgument(where, what);
}

// The shortest text that reads back to the same double (common::formatNumber), so that 0.015
// prints as 0.015 and not 0.014999999999999999.
inline std::string str(double v) {
  return common::formatNumber(v);
}

// "name = value unit"
inline std::string named(std::string_view name, double value, std::string_view unit) {
  return common::message(name, " = ", value, unit.empty() ? "" : " ", unit);
}

inline std::string indexed(std::string_view name, Eigen::Index k) {
  return common::message(name, "[", k, "]");
}

inline void requireFinite(std::string_view where, std::string_view name, double v,
                          std::string_view unit) {
  common::requireFinite(v, where, name, unit);
}

inline void requirePositive(std::string_view where, std::string_view name, double v,
                            std::string_view unit) {
  common::requirePositiveFinite(v, where, name, unit);
}

inline void requireNonNegative(std::string_view where, std::string_view name, double v,
                               std::string_view unit) {
  common::requireNonNegativeFinite(v, where, name, unit);
}

// Every entry finite; the first offending row is named.
inline void requireFiniteEntries(std::string_view where, std::string_view name,
                                 const Eigen::Ref<const Eigen::VectorXd>& v,
                                 std::string_view unit) {
  for (Eigen::Index k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k]))
      fail(where, named(indexed(name, k), v[k], unit) + " must be finite");
}

inline void requireSameSize(std::string_view where, std::string_view name, Eigen::Index size,
                            std::string_view otherName, Eigen::Index otherSize) {
  if (size != otherSize)
    fail(where, std::string(name) + " has " + std::to_string(size) + " entries but " +
                    std::string(otherName) + " has " + std::to_string(otherSize) +
                    "; they must be the same length");
}

// Strictly increasing, finite abscissae of a table (at least minCount rows); the first row that
// breaks the order is named.
inline void requireIncreasing(std::string_view where, std::string_view name,
                              const Eigen::Ref<const Eigen::VectorXd>& x, std::string_view unit,
                              Eigen::Index minCount) {
  if (x.size() < minCount)
    fail(where, std::string(name) + " has " + std::to_string(x.size()) + " rows, at least " +
                    std::to_string(minCount) + " needed");
  requireFiniteEntries(where, name, x, unit);
  for (Eigen::Index k = 1; k < x.size(); ++k)
    if (!(x[k] > x[k - 1]))
      fail(where, named(indexed(name, k), x[k], unit) + " must be greater than " +
                      named(indexed(name, k - 1), x[k - 1], unit) +
                      " (the table must be strictly increasing)");
}

// Absolute zero in degrees Celsius.
inline constexpr double kAbsoluteZero_degC = -273.15;

inline void requireAboveAbsoluteZero(std::string_view where, std::string_view name, double t_degC) {
  if (!(std::isfinite(t_degC) && t_degC > kAbsoluteZero_degC))
    fail(where, named(name, t_degC, "degC") + " must be finite and above absolute zero (" +
                    str(kAbsoluteZero_degC) + " degC)");
}

}  // namespace pistondyn::skirt::detail
