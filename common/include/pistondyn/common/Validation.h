#pragma once
/// \file
/// Argument checks and error-message text shared by every pistondyn module: one number format
/// and one message shape (docs/CONVENTIONS.md, "Errors").
///
/// A message names the function, the argument, its value with unit and what was expected:
///   "ReynoldsSolver::solve: gap h[17] = -2e-06 m must be positive and finite"
/// Numbers are printed as the shortest text that reads back to the same double
/// (std::to_chars without a format): "2e-06", "0.1", "1e+300", "5e-324", "-0", "inf", "nan".
/// Unlike std::to_string (six fixed decimals: 2e-09 -> "0.000000") or a 6-digit %g
/// (1.0000001 -> "1"), it never hides the value that was rejected.
///
/// Header-only (target pistondyn::common), no allocation unless a check fails: names are
/// taken as std::string_view, so literals cost nothing on the passing path. A caller that
/// would build a name per value (per node, per call) tests with a not*() predicate first and
/// builds the name only to throw.

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace pistondyn::common {

/// Appends the shortest text that reads back (std::from_chars, strtod) to exactly value.
inline void appendNumber(std::string& out, double value) {
  // Longest shortest form: "-2.2250738585072014e-308", 24 characters.
  char buffer[32];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, r.ptr);
}

/// The shortest text that reads back to exactly value (see appendNumber).
inline std::string formatNumber(double value) {
  std::string text;
  appendNumber(text, value);
  return text;
}

/// Implementation details of the message helpers (not API).
namespace detail {

/// Appends one part of a message (see message()).
template <class Part>
void appendPart(std::string& out, const Part& part) {
  if constexpr (std::is_same_v<Part, bool>) {
    out.append(part ? "true" : "false");
  } else if constexpr (std::is_same_v<Part, char>) {
    out.push_back(part);
  } else if constexpr (std::is_floating_point_v<Part>) {
    static_assert(!std::is_same_v<Part, long double>, "messages print doubles");
    appendNumber(out, static_cast<double>(part));
  } else if constexpr (std::is_integral_v<Part> || std::is_enum_v<Part>) {
    // Integers (indices, counts, enum values) in decimal.
    using Integer = std::conditional_t<std::is_enum_v<Part>, std::underlying_type<Part>,
                                       std::common_type<Part>>;
    char buffer[24];
    const std::to_chars_result r =
        std::to_chars(buffer, buffer + sizeof buffer, static_cast<typename Integer::type>(part));
    out.append(buffer, r.ptr);
  } else {
    out.append(std::string_view(part));
  }
}

}  // namespace detail

/// Concatenates the parts of a message: text (string literals, std::string, string_view) as it
/// is, floating-point numbers in the format of appendNumber, integers in decimal. E.g.
///   message("Oil: ", name, " = ", value, " degC is outside [", lo, ", ", hi, "] degC")
template <class... Parts>
std::string message(const Parts&... parts) {
  std::string text;
  (detail::appendPart(text, parts), ...);
  return text;
}

/// Throws std::invalid_argument("where: what").
[[noreturn]] inline void throwInvalidArgument(std::string_view where, std::string_view what) {
  throw std::invalid_argument(message(where, ": ", what));
}

/// Throws std::invalid_argument("where: argument = value unit must be expected"); the unit and
/// its space are left out when unit is empty (dimensionless values).
[[noreturn]] inline void throwInvalidValue(std::string_view where, std::string_view argument,
                                           double value, std::string_view unit,
                                           std::string_view expected) {
  throw std::invalid_argument(message(where, ": ", argument, " = ", value, unit.empty() ? "" : " ",
                                      unit, " must be ", expected));
}

/// The common requirements. Each is a test that is true for a bad value (not*), a throw with
/// its message (throwNot*, [[noreturn]]) and both in one call (require*).
/// This one: true for a value that is not positive, or NaN or infinite.
inline bool notPositiveFinite(double value) {
  return !(value > 0.0) || !std::isfinite(value);
}

/// True for a value that is negative, NaN or infinite.
inline bool notNonNegativeFinite(double value) {
  return !(value >= 0.0) || !std::isfinite(value);
}

/// Throws std::invalid_argument("where: argument = value unit must be positive and finite").
[[noreturn]] inline void throwNotPositiveFinite(double value, std::string_view where,
                                                std::string_view argument, std::string_view unit) {
  throwInvalidValue(where, argument, value, unit, "positive and finite");
}

/// Throws std::invalid_argument("where: argument = value unit must be non-negative and
/// finite").
[[noreturn]] inline void throwNotNonNegativeFinite(double value, std::string_view where,
                                                   std::string_view argument,
                                                   std::string_view unit) {
  throwInvalidValue(where, argument, value, unit, "non-negative and finite");
}

/// Throws std::invalid_argument("where: argument = value unit must be finite").
[[noreturn]] inline void throwNotFinite(double value, std::string_view where,
                                        std::string_view argument, std::string_view unit) {
  throwInvalidValue(where, argument, value, unit, "finite");
}

/// Throw std::invalid_argument ("where: argument = value unit must be positive and finite",
/// and so on) unless the requirement holds.
inline void requirePositiveFinite(double value, std::string_view where, std::string_view argument,
                                  std::string_view unit) {
  if (notPositiveFinite(value)) {
    throwNotPositiveFinite(value, where, argument, unit);
  }
}

/// Throws as throwNotNonNegativeFinite() unless value is >= 0 and finite.
inline void requireNonNegativeFinite(double value, std::string_view where,
                                     std::string_view argument, std::string_view unit) {
  if (notNonNegativeFinite(value)) {
    throwNotNonNegativeFinite(value, where, argument, unit);
  }
}

/// Throws as throwNotFinite() unless value is finite.
inline void requireFinite(double value, std::string_view where, std::string_view argument,
                          std::string_view unit) {
  if (!std::isfinite(value)) {
    throwNotFinite(value, where, argument, unit);
  }
}

}  // namespace pistondyn::common
