#include "pistondyn/lubrication/Oil.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "OilUnits.h"
#include "pistondyn/common/Validation.h"

namespace pistondyn::lubrication {

namespace {

constexpr double kZeroCelsius_K = 273.15;
constexpr double kWaltherShift_cSt = 0.7;         // ASTM D341, nu >= 2 cSt
constexpr double kWaltherMinViscosity_cSt = 2.0;  // lower limit of the simple form
using detail::kM2psPerCSt;
constexpr double kMaxThermalExpansion_perK = 2e-3;

// "Oil: " followed by the parts of the message (common::message).
template <class... Parts>
[[noreturn]] void fail(const Parts&... parts) {
  common::throwInvalidArgument("Oil", common::message(parts...));
}

// Plausibility bounds of the data (unit mistakes, not physics):
//  - kinematic viscosity at a data point <= 1e-2 m^2/s (10000 mm^2/s): above any engine
//    oil at its data temperatures; a value given in mm^2/s (cSt) is 1e6 times too large
//    and lands far above (the lower end, 2e-6 m^2/s, is the Walther form's own limit);
//  - density in (500, 2000) kg/m^3: oils are 800..1000; g/ml gives ~0.85;
//  - data temperatures in (-60, 250) degC: oil data are measured between the pour point
//    (>= -60 C for engine oils) and below the flash point (about 200..250 C); kelvin
//    values of the usual 15 / 40 / 100 C points (288.15, 313.15, 373.15) land above 250.
constexpr double kMaxDataViscosity_m2ps = 1e-2;
constexpr double kMinDensity_kgpm3 = 500.0;
constexpr double kMaxDensity_kgpm3 = 2000.0;
constexpr double kMinDataTemperature_degC = -60.0;
constexpr double kMaxDataTemperature_degC = 250.0;

void checkDataTemperature(const char* name, double temperature_degC) {
  if (!(temperature_degC > kMinDataTemperature_degC &&
        temperature_degC < kMaxDataTemperature_degC)) {
    fail(name, " = ", temperature_degC, " degC is implausible for oil data (expected ",
         kMinDataTemperature_degC, " .. ", kMaxDataTemperature_degC,
         " degC); was it given in kelvin? Subtract 273.15");
  }
}

void checkDataViscosity(const char* name, double nu_m2ps) {
  if (!(nu_m2ps <= kMaxDataViscosity_m2ps)) {
    fail(name, " = ", nu_m2ps, " m^2/s is implausible for an oil (expected at most ",
         kMaxDataViscosity_m2ps,
         " m^2/s = 10000 mm^2/s); was it given in mm^2/s (cSt)? Multiply by 1e-6");
  }
}

void checkFinite(const char* name, double value) {
  common::requireFinite(value, "Oil", name, "");
}

void checkPositive(const char* name, double value) {
  if (!(value > 0.0)) {
    fail(name, " = ", value, " must be > 0");
  }
}

void checkAboveAbsoluteZero(const char* name, double temperature_degC) {
  if (!(temperature_degC > -kZeroCelsius_K)) {
    fail(name, " = ", temperature_degC, " degC is not above absolute zero");
  }
}

double loglog(double nu_cSt) {
  return std::log10(std::log10(nu_cSt + kWaltherShift_cSt));
}

}  // namespace

Oil::Oil(const OilSpec& spec) : spec_(spec) {
  checkFinite("temperature1_degC", spec.temperature1_degC);
  checkFinite("temperature2_degC", spec.temperature2_degC);
  checkFinite("kinematicViscosity1_m2ps", spec.kinematicViscosity1_m2ps);
  checkFinite("kinematicViscosity2_m2ps", spec.kinematicViscosity2_m2ps);
  checkFinite("density_kgpm3", spec.density_kgpm3);
  checkFinite("densityReferenceTemperature_degC", spec.densityReferenceTemperature_degC);
  checkFinite("thermalExpansion_perK", spec.thermalExpansion_perK);
  checkFinite("minTemperature_degC", spec.minTemperature_degC);
  checkFinite("maxTemperature_degC", spec.maxTemperature_degC);
  checkAboveAbsoluteZero("temperature1_degC", spec.temperature1_degC);
  checkAboveAbsoluteZero("densityReferenceTemperature_degC", spec.densityReferenceTemperature_degC);
  checkAboveAbsoluteZero("minTemperature_degC", spec.minTemperature_degC);
  checkDataTemperature("temperature1_degC", spec.temperature1_degC);
  checkDataTemperature("temperature2_degC", spec.temperature2_degC);
  checkDataTemperature("densityReferenceTemperature_degC", spec.densityReferenceTemperature_degC);

  if (!(spec.temperature2_degC > spec.temperature1_degC)) {
    fail("temperature2_degC = ", spec.temperature2_degC,
         " must be greater than temperature1_degC = ", spec.temperature1_degC,
         " (give the (T, nu) points in order of increasing temperature)");
  }
  const double nu1_cSt = spec.kinematicViscosity1_m2ps / kM2psPerCSt;
  const double nu2_cSt = spec.kinematicViscosity2_m2ps / kM2psPerCSt;
  checkPositive("kinematicViscosity1_m2ps", spec.kinematicViscosity1_m2ps);
  checkPositive("kinematicViscosity2_m2ps", spec.kinematicViscosity2_m2ps);
  checkDataViscosity("kinematicViscosity1_m2ps", spec.kinematicViscosity1_m2ps);
  checkDataViscosity("kinematicViscosity2_m2ps", spec.kinematicViscosity2_m2ps);
  if (!(nu2_cSt < nu1_cSt)) {
    fail("kinematicViscosity2_m2ps = ", spec.kinematicViscosity2_m2ps,
         " at the higher temperature must be below kinematicViscosity1_m2ps = ",
         spec.kinematicViscosity1_m2ps, " (viscosity must decrease with temperature)");
  }
  if (nu2_cSt < kWaltherMinViscosity_cSt) {
    fail("kinematicViscosity2_m2ps = ", spec.kinematicViscosity2_m2ps,
         " is below 2e-6 m^2/s, the lower limit of the ASTM D341 Walther form");
  }
  checkPositive("density_kgpm3", spec.density_kgpm3);
  if (!(spec.density_kgpm3 > kMinDensity_kgpm3 && spec.density_kgpm3 < kMaxDensity_kgpm3)) {
    fail("density_kgpm3 = ", spec.density_kgpm3, " kg/m^3 is implausible for an oil (expected ",
         kMinDensity_kgpm3, " .. ", kMaxDensity_kgpm3,
         " kg/m^3); was it given in g/ml? Multiply by 1000");
  }
  if (!(spec.thermalExpansion_perK >= 0.0 &&
        spec.thermalExpansion_perK < kMaxThermalExpansion_perK)) {
    fail("thermalExpansion_perK = ", spec.thermalExpansion_perK, " must be in [0, ",
         kMaxThermalExpansion_perK, ")");
  }
  if (!(spec.maxTemperature_degC > spec.minTemperature_degC)) {
    fail("maxTemperature_degC = ", spec.maxTemperature_degC,
         " must be greater than minTemperature_degC = ", spec.minTemperature_degC);
  }

  // Walther line through both points.
  const double logT1 = std::log10(spec.temperature1_degC + kZeroCelsius_K);
  const double logT2 = std::log10(spec.temperature2_degC + kZeroCelsius_K);
  const double y1 = loglog(nu1_cSt);
  const double y2 = loglog(nu2_cSt);
  waltherB_ = (y1 - y2) / (logT2 - logT1);
  waltherA_ = y1 + waltherB_ * logT1;

  // The density must stay positive over the range (1 + alpha dT > 0).
  if (spec.thermalExpansion_perK > 0.0) {
    const double lowest = spec.densityReferenceTemperature_degC - 1.0 / spec.thermalExpansion_perK;
    if (!(spec.minTemperature_degC > lowest)) {
      fail("minTemperature_degC = ", spec.minTemperature_degC,
           " is outside the range of the linear specific-volume density model");
    }
  }

  // Upper end: where nu reaches 2 cSt, if that comes before the requested maximum.
  minTemperature_degC_ = spec.minTemperature_degC;
  maxTemperature_degC_ = spec.maxTemperature_degC;
  const double logTAtLimit = (waltherA_ - loglog(kWaltherMinViscosity_cSt)) / waltherB_;
  const double tAtLimit_degC = std::pow(10.0, logTAtLimit) - kZeroCelsius_K;
  maxTemperature_degC_ = std::min(maxTemperature_degC_, tAtLimit_degC);
  if (!(maxTemperature_degC_ > minTemperature_degC_)) {
    fail("minTemperature_degC = ", spec.minTemperature_degC, " is not below the temperature ",
         tAtLimit_degC, " degC where the oil thins to 2e-6 m^2/s");
  }
}

void Oil::checkTemperature(const char* function, double temperature_degC,
                           Eigen::Index index) const {
  if (!(temperature_degC >= minTemperature_degC_ && temperature_degC <= maxTemperature_degC_)) {
    const std::string value =
        index >= 0 ? common::message("temperature_degC[", index, "] = ", temperature_degC)
                   : common::message("temperature ", temperature_degC);
    throw std::invalid_argument(common::message(
        "Oil::", function, ": ", value, " degC is outside the valid range [", minTemperature_degC_,
        ", ", maxTemperature_degC_, "] degC of oil '", spec_.name, "'"));
  }
}

double Oil::kinematicViscosity_cSt(double temperature_K) const {
  const double y = waltherA_ - waltherB_ * std::log10(temperature_K);
  return std::pow(10.0, std::pow(10.0, y)) - kWaltherShift_cSt;
}

double Oil::calcKinematicViscosity_m2ps(double temperature_degC) const {
  checkTemperature("calcKinematicViscosity_m2ps", temperature_degC);
  return kinematicViscosity_cSt(temperature_degC + kZeroCelsius_K) * kM2psPerCSt;
}

double Oil::density_kgpm3(double temperature_degC) const {
  return spec_.density_kgpm3 /
         (1.0 + spec_.thermalExpansion_perK *
                    (temperature_degC - spec_.densityReferenceTemperature_degC));
}

double Oil::calcDensity_kgpm3(double temperature_degC) const {
  checkTemperature("calcDensity_kgpm3", temperature_degC);
  return density_kgpm3(temperature_degC);
}

double Oil::dynamicViscosity_Pas(double temperature_degC) const {
  return density_kgpm3(temperature_degC) *
         kinematicViscosity_cSt(temperature_degC + kZeroCelsius_K) * kM2psPerCSt;
}

double Oil::calcDynamicViscosity_Pas(double temperature_degC) const {
  checkTemperature("calcDynamicViscosity_Pas", temperature_degC);
  return dynamicViscosity_Pas(temperature_degC);
}

void Oil::calcDynamicViscosity_Pas(const Eigen::Ref<const Eigen::ArrayXd>& temperature_degC,
                                   Eigen::Ref<Eigen::ArrayXd> viscosity_Pas) const {
  if (viscosity_Pas.size() != temperature_degC.size()) {
    throw std::invalid_argument(common::message(
        "Oil::calcDynamicViscosity_Pas: viscosity_Pas has ", viscosity_Pas.size(),
        " entries, expected ", temperature_degC.size(), " (temperature_degC.size())"));
  }
  // Check everything first, so that a bad entry leaves the output untouched.
  for (Eigen::Index k = 0; k < temperature_degC.size(); ++k)
    checkTemperature("calcDynamicViscosity_Pas", temperature_degC[k], k);
  for (Eigen::Index k = 0; k < temperature_degC.size(); ++k)
    viscosity_Pas[k] = dynamicViscosity_Pas(temperature_degC[k]);
}

double Oil::calcDynamicViscosityAtKelvin_Pas(double temperature_K) const {
  common::requireFinite(temperature_K, "Oil::calcDynamicViscosityAtKelvin_Pas", "temperature_K",
                        "K");
  return calcDynamicViscosity_Pas(temperature_K - kZeroCelsius_K);
}

}  // namespace pistondyn::lubrication
