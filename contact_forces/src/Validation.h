#pragma once
// Argument checks shared by the contact_forces sources (private header). Every message
// names the function, the argument and what was expected (docs/CONVENTIONS.md).

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

namespace pistondyn::contact_forces::detail {

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

// Each requirement is a test that is true for a bad value (not*) and a throw with its
// message (throwNot*, [[noreturn]]); require* combines the two. Names may be literals or built
// strings: a caller that would build a name for every value (per node, per call) tests first and
// builds it only to throw.
inline bool notPositiveFinite(double value) {
  return !(value > 0.0) || !std::isfinite(value);
}

inline bool notNonNegativeFinite(double value) {
  return !(value >= 0.0) || !std::isfinite(value);
}

[[noreturn]] inline void throwNotPositiveFinite(double value, std::string_view where,
                                                std::string_view argument, std::string_view unit) {
  throwInvalid(std::string(where), std::string(argument), value, std::string(unit),
               "positive and finite");
}

[[noreturn]] inline void throwNotNonNegativeFinite(double value, std::string_view where,
                                                   std::string_view argument,
                                                   std::string_view unit) {
  throwInvalid(std::string(where), std::string(argument), value, std::string(unit),
               "non-negative and finite");
}

[[noreturn]] inline void throwNotFinite(double value, std::string_view where,
                                        std::string_view argument, std::string_view unit) {
  throwInvalid(std::string(where), std::string(argument), value, std::string(unit), "finite");
}

inline void requirePositiveFinite(double value, std::string_view where, std::string_view argument,
                                  std::string_view unit) {
  if (notPositiveFinite(value)) {
    throwNotPositiveFinite(value, where, argument, unit);
  }
}

inline void requireNonNegativeFinite(double value, std::string_view where,
                                     std::string_view argument, std::string_view unit) {
  if (notNonNegativeFinite(value)) {
    throwNotNonNegativeFinite(value, where, argument, unit);
  }
}

inline void requireFinite(double value, std::string_view where, std::string_view argument,
                          std::string_view unit) {
  if (!std::isfinite(value)) {
    throwNotFinite(value, where, argument, unit);
  }
}

}  // namespace pistondyn::contact_forces::detail
