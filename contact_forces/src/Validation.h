#pragma once
// Argument checks shared by the contact_forces sources (private header). Every message
// names the function, the argument and what was expected (docs/CONVENTIONS.md).

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace pistondyn::contact::detail {

inline std::string formatNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

[[noreturn]] inline void throwInvalid(const std::string& where, const std::string& argument,
                                      double value, const std::string& unit,
                                      const std::string& expected) {
  throw std::invalid_argument(where + ": " + argument + " = " + formatNumber(value) +
                              (unit.empty() ? "" : " " + unit) + " must be " + expected);
}

inline void requirePositiveFinite(double value, const char* where, const char* argument,
                                  const char* unit) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throwInvalid(where, argument, value, unit, "positive and finite");
  }
}

inline void requireNonNegativeFinite(double value, const char* where, const char* argument,
                                     const char* unit) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throwInvalid(where, argument, value, unit, "non-negative and finite");
  }
}

inline void requireFinite(double value, const char* where, const char* argument, const char* unit) {
  if (!std::isfinite(value)) {
    throwInvalid(where, argument, value, unit, "finite");
  }
}

}  // namespace pistondyn::contact::detail
