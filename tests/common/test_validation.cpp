// pistondyn::common's number format and argument checks (common/include/pistondyn/common/
// Validation.h).
//
// Independent references: the C library's strtod (reading the text back) and printf's
// correctly rounded %.*e (the fewest significant digits that read back), and the message
// shape written out by hand from docs/CONVENTIONS.md ("Errors").

#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "pistondyn/common/Validation.h"

namespace pc = pistondyn::common;

namespace {

std::uint64_t bitsOf(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

double fromBits(std::uint64_t b) {
  double v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

// strtod of the whole text; fails the test if any character is left over.
double readBack(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  EXPECT_EQ(*end, '\0') << "'" << text << "' is not read completely";
  return v;
}

// Significant digits of a decimal text: digits of the mantissa without leading zeros and
// without the trailing zeros of an integer written in full ("100" has one).
int significantDigits(const std::string& text) {
  std::string digits;
  for (char c : text) {
    if (c == 'e')
      break;
    if (c >= '0' && c <= '9')
      digits.push_back(c);
  }
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos)
    return 1;  // zero
  digits.erase(0, first);
  digits.erase(digits.find_last_not_of('0') + 1);
  return static_cast<int>(digits.size());
}

// printf's correctly rounded %.(p-1)e with the fewest significant digits p that reads back
// to v.
std::string shortestPrintfScientific(double v) {
  char buffer[64];
  for (int p = 1; p <= 17; ++p) {
    std::snprintf(buffer, sizeof buffer, "%.*e", p - 1, v);
    if (bitsOf(std::strtod(buffer, nullptr)) == bitsOf(v))
      break;
  }
  return buffer;
}

std::string printfInteger(double v) {
  char buffer[400];
  std::snprintf(buffer, sizeof buffer, "%.0f", v);
  return buffer;
}

// A few thousand finite doubles over the whole range: random bit patterns (every binade
// equally likely), subnormals, values near 1e+300 and 1e-300, and ordinary magnitudes.
std::vector<double> sampleDoubles() {
  std::mt19937_64 rng(20261124);
  std::vector<double> v;
  std::uniform_real_distribution<double> unit(1.0, 10.0);
  while (v.size() < 2500) {
    const double x = fromBits(rng());
    if (std::isfinite(x))
      v.push_back(x);
  }
  for (int k = 0; k < 500; ++k) {  // subnormals: exponent field 0, random mantissa
    const std::uint64_t mantissa = rng() & ((std::uint64_t{1} << 52) - 1);
    v.push_back(fromBits(mantissa | (k % 2 ? std::uint64_t{1} << 63 : 0)));
  }
  for (int k = 0; k < 500; ++k) {
    v.push_back(1e300 * unit(rng));
    v.push_back(-1e-300 * unit(rng));
  }
  for (int k = 0; k < 1000; ++k)
    v.push_back(std::ldexp(unit(rng), static_cast<int>(rng() % 80) - 40));
  const double specials[] = {0.0,
                             -0.0,
                             1.0,
                             0.1,
                             2e-6,
                             2e-9,
                             1e300,
                             -1e-300,
                             std::numeric_limits<double>::min(),
                             std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::lowest(),
                             std::numeric_limits<double>::epsilon(),
                             std::nextafter(1.0, 2.0),
                             12345678901234567.0};
  v.insert(v.end(), std::begin(specials), std::end(specials));
  return v;
}

}  // namespace

// The examples of docs/CONVENTIONS.md, and what std::to_string and %.6g got wrong.
TEST(CommonNumberFormat, ShortestTextOfTypicalValues) {
  EXPECT_EQ(pc::formatNumber(2e-6), "2e-06");
  EXPECT_EQ(pc::formatNumber(0.1), "0.1");
  EXPECT_EQ(pc::formatNumber(1e300), "1e+300");
  EXPECT_EQ(pc::formatNumber(-1e-300), "-1e-300");
  EXPECT_EQ(pc::formatNumber(2e-9), "2e-09");           // std::to_string: "0.000000"
  EXPECT_EQ(pc::formatNumber(1.0000001), "1.0000001");  // %.6g: "1"
  EXPECT_EQ(pc::formatNumber(250.0), "250");
  EXPECT_EQ(pc::formatNumber(-2.5), "-2.5");
  EXPECT_EQ(pc::formatNumber(0.0), "0");
  EXPECT_EQ(pc::formatNumber(-0.0), "-0");
  EXPECT_EQ(pc::formatNumber(std::numeric_limits<double>::denorm_min()), "5e-324");
  EXPECT_EQ(pc::formatNumber(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(pc::formatNumber(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(pc::formatNumber(std::numeric_limits<double>::quiet_NaN()), "nan");
}

// Every printed value reads back bit for bit (strtod, the C library's own parser) and is
// never longer than printf's shortest scientific form that reads back. Its digits are
// never more than that form's, except for an integer written out in full (chosen when that
// is the shorter text), which is then exactly printf's %.0f. (It may have fewer digits:
// next to a power of two the rounding interval is lopsided and a shortest form can lie on
// its wide side, where the nearest decimal of that many digits does not.)
TEST(CommonNumberFormat, RoundTripsBitForBitAndIsShortest) {
  ASSERT_NE(std::setlocale(LC_NUMERIC, "C"), nullptr);
  const std::vector<double> values = sampleDoubles();
  ASSERT_GE(values.size(), 5000u);
  int subnormals = 0;
  int integersInFull = 0;
  for (double v : values) {
    const std::string text = pc::formatNumber(v);
    ASSERT_EQ(bitsOf(readBack(text)), bitsOf(v)) << text << " does not read back";
    const std::string scientific = shortestPrintfScientific(v);
    ASSERT_LE(text.size(), scientific.size()) << text << " vs " << scientific;
    if (text.find_first_of(".e") == std::string::npos) {
      ASSERT_EQ(text, printfInteger(v));
      ++integersInFull;
    } else {
      ASSERT_LE(significantDigits(text), significantDigits(scientific)) << text;
    }
    subnormals += std::fpclassify(v) == FP_SUBNORMAL;
  }
  std::printf("  %zu values read back bit for bit (%d subnormal, %d integers in full)\n",
              values.size(), subnormals, integersInFull);
  EXPECT_GE(subnormals, 500);
  EXPECT_GT(integersInFull, 0);
}

// appendNumber and message() put the same text into a longer string.
TEST(CommonMessage, JoinsTextNumbersAndIntegers) {
  std::string s = "h = ";
  pc::appendNumber(s, 3e-7);
  EXPECT_EQ(s, "h = 3e-07");
  const std::string name = "gap_m";
  const long index = 17;
  EXPECT_EQ(pc::message("f: ", name, "[", index, "] = ", -2e-6, ' ', std::string_view("m"), " (", 3,
                        " of ", std::size_t{4}, ")"),
            "f: gap_m[17] = -2e-06 m (3 of 4)");
  EXPECT_EQ(pc::message(0.1f), "0.10000000149011612");  // a float is printed as its double
}

// The message shape of docs/CONVENTIONS.md: function, argument, value with unit, expectation.
TEST(CommonChecks, MessagesNameFunctionArgumentValueUnitAndExpectation) {
  auto what = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_EQ(
      what([] { pc::requirePositiveFinite(-2e-6, "ReynoldsSolver::solve", "gap h[17]", "m"); }),
      "ReynoldsSolver::solve: gap h[17] = -2e-06 m must be positive and finite");
  EXPECT_EQ(what([] { pc::requireNonNegativeFinite(-0.5, "Law", "frictionCoefficient", ""); }),
            "Law: frictionCoefficient = -0.5 must be non-negative and finite");
  EXPECT_EQ(what([] { pc::requireFinite(std::nan(""), "f", "x", "Pa"); }),
            "f: x = nan Pa must be finite");
  EXPECT_EQ(what([] { pc::throwInvalidValue("g", "y_m", 2e-9, "m", "at least 1e-06 m"); }),
            "g: y_m = 2e-09 m must be at least 1e-06 m");
  EXPECT_EQ(what([] { pc::throwInvalidArgument("h", "grid has 2 x 5 nodes"); }),
            "h: grid has 2 x 5 nodes");
}

// Which values pass each requirement.
TEST(CommonChecks, RequirementsAcceptExactlyTheirDomain) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double tiny = std::numeric_limits<double>::denorm_min();
  for (double v : {tiny, 1.0, 1e300})
    EXPECT_NO_THROW(pc::requirePositiveFinite(v, "f", "v", ""));
  for (double v : {0.0, -0.0, -tiny, -1.0, inf, -inf, nan})
    EXPECT_THROW(pc::requirePositiveFinite(v, "f", "v", ""), std::invalid_argument) << v;
  for (double v : {0.0, -0.0, tiny, 1e300})
    EXPECT_NO_THROW(pc::requireNonNegativeFinite(v, "f", "v", ""));
  for (double v : {-tiny, -1.0, inf, -inf, nan})
    EXPECT_THROW(pc::requireNonNegativeFinite(v, "f", "v", ""), std::invalid_argument) << v;
  for (double v : {0.0, -1e300, tiny})
    EXPECT_NO_THROW(pc::requireFinite(v, "f", "v", ""));
  for (double v : {inf, -inf, nan})
    EXPECT_THROW(pc::requireFinite(v, "f", "v", ""), std::invalid_argument) << v;
  EXPECT_TRUE(pc::notPositiveFinite(0.0));
  EXPECT_FALSE(pc::notPositiveFinite(tiny));
  EXPECT_TRUE(pc::notNonNegativeFinite(nan));
  EXPECT_FALSE(pc::notNonNegativeFinite(-0.0));
}
