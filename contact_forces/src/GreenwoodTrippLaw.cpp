#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "GreenwoodTrippTails.h"
#include "pistondyn/common/Validation.h"

namespace pistondyn::contact_forces {
namespace {

constexpr const char* kWhere = "GreenwoodTrippLaw";
constexpr double kPi = 3.14159265358979323846;

void validatePowerLaw(const PowerLawTailFit& fit, const char* name) {
  const std::string n(name);
  common::requirePositiveFinite(fit.coefficient, kWhere, n + ".coefficient", "");
  common::requirePositiveFinite(fit.exponent, kWhere, n + ".exponent", "");
  common::requireFinite(fit.lambdaMax, kWhere, n + ".lambdaMax", "");
}

void validatePolynomial(const PolynomialTailFit& fit, const char* name) {
  const std::string n(name);
  for (std::size_t k = 0; k < fit.coefficients.size(); ++k) {
    common::requireFinite(fit.coefficients[k], kWhere,
                          n + ".coefficients[" + std::to_string(k) + "]", "");
  }
  common::requireFinite(fit.lambdaEnd, kWhere, n + ".lambdaEnd", "");
}

}  // namespace

double greenwoodTrippCoefficient(double roughnessParameter, double sigmaOverBeta) {
  common::requirePositiveFinite(roughnessParameter, "greenwoodTrippCoefficient",
                                "roughnessParameter (eta*beta*sigma)", "");
  common::requirePositiveFinite(sigmaOverBeta, "greenwoodTrippCoefficient",
                                "sigmaOverBeta (sigma/beta)", "");
  return 8.0 * std::sqrt(2.0) / 15.0 * kPi * roughnessParameter * roughnessParameter *
         std::sqrt(sigmaOverBeta);
}

GreenwoodTrippLaw::GreenwoodTrippLaw(const GreenwoodTrippParameters& parameters)
    : parameters_(parameters) {
  const GreenwoodTrippParameters& p = parameters_;
  common::requireNonNegativeFinite(p.roughnessSurface1_m, kWhere, "roughnessSurface1_m", "m");
  common::requireNonNegativeFinite(p.roughnessSurface2_m, kWhere, "roughnessSurface2_m", "m");
  validateMaterial(p.surface1, kWhere, "surface1");
  validateMaterial(p.surface2, kWhere, "surface2");
  common::requirePositiveFinite(p.roughnessParameter, kWhere, "roughnessParameter (eta*beta*sigma)",
                                "");
  common::requirePositiveFinite(p.sigmaOverBeta, kWhere, "sigmaOverBeta (sigma/beta)", "");
  switch (p.tailModel) {
    case TailIntegralModel::Exact:
      break;
    case TailIntegralModel::PowerLawFit:
      validatePowerLaw(p.powerLawF52, "powerLawF52");
      validatePowerLaw(p.powerLawF2, "powerLawF2");
      break;
    case TailIntegralModel::PolynomialFit:
      validatePolynomial(p.polynomialF52, "polynomialF52");
      validatePolynomial(p.polynomialF2, "polynomialF2");
      break;
    default:
      throw std::invalid_argument("GreenwoodTrippLaw: tailModel is not a TailIntegralModel value");
  }
  sigma_m_ = compositeRoughness_m(p.roughnessSurface1_m, p.roughnessSurface2_m);
  if (!(sigma_m_ >= kMinCompositeRoughness_m)) {
    common::throwInvalidValue(kWhere, "sqrt(roughnessSurface1_m^2 + roughnessSurface2_m^2)",
                              sigma_m_, "m",
                              "at least 1e-12 m (no engineering surface is smoother than a "
                              "picometre; a length converted to metres twice?)");
  }
  effectiveModulus_Pa_ = contact_forces::effectiveModulus_Pa(p.surface1, p.surface2);
  coefficientK_ = greenwoodTrippCoefficient(p.roughnessParameter, p.sigmaOverBeta);
  pressureScale_Pa_ = coefficientK_ * effectiveModulus_Pa_;
  areaScale_ = kPi * kPi * p.roughnessParameter * p.roughnessParameter;
}

TailValueAndSlope GreenwoodTrippLaw::evalF52(double lambda) const {
  switch (parameters_.tailModel) {
    case TailIntegralModel::PowerLawFit:
      return {parameters_.powerLawF52.value(lambda), parameters_.powerLawF52.slope(lambda)};
    case TailIntegralModel::PolynomialFit:
      return {parameters_.polynomialF52.value(lambda), parameters_.polynomialF52.slope(lambda)};
    case TailIntegralModel::Exact:
    default:
      return greenwoodTrippF52WithSlope(lambda);
  }
}

double GreenwoodTrippLaw::evalF2(double lambda) const {
  switch (parameters_.tailModel) {
    case TailIntegralModel::PowerLawFit:
      return parameters_.powerLawF2.value(lambda);
    case TailIntegralModel::PolynomialFit:
      return parameters_.polynomialF2.value(lambda);
    case TailIntegralModel::Exact:
    default:
      return greenwoodTrippF2(lambda);
  }
}

double GreenwoodTrippLaw::evalPressure(double gap_m) const {
  const double lambda = gap_m / sigma_m_;
  switch (parameters_.tailModel) {
    case TailIntegralModel::PowerLawFit:
      return pressureScale_Pa_ * parameters_.powerLawF52.value(lambda);
    case TailIntegralModel::PolynomialFit:
      return pressureScale_Pa_ * parameters_.polynomialF52.value(lambda);
    case TailIntegralModel::Exact:
    default:
      return pressureScale_Pa_ * greenwoodTrippF52(lambda);
  }
}

PressureAndSlope GreenwoodTrippLaw::evalPressureAndSlope(double gap_m) const {
  const TailValueAndSlope f = evalF52(gap_m / sigma_m_);
  return {pressureScale_Pa_ * f.value, pressureScale_Pa_ * f.slope / sigma_m_};
}

double GreenwoodTrippLaw::evalAreaFraction(double gap_m) const {
  // The statistical model gives A_c/A > 1 only for overlaps of many σ, where it no longer
  // describes anything physical; the fraction is capped at 1.
  return std::min(1.0, areaScale_ * evalF2(gap_m / sigma_m_));
}

// λ once per node; for the exact model F_{5/2}, its slope and F_2 from one table lookup, for
// the fits evalF52 and evalF2 as in evalPressureAndSlope and evalAreaFraction. Same
// expressions as those two and the default evalNode, so the same values to the last bit.
ContactNodeState GreenwoodTrippLaw::evalNode(double gap_m) const {
  const double lambda = gap_m / sigma_m_;
  TailValueAndSlope f52;
  double f2 = 0.0;
  if (parameters_.tailModel == TailIntegralModel::Exact) {
    const detail::GreenwoodTrippTails f = detail::greenwoodTrippTails(lambda);
    f52 = {f.f52, f.f52Slope};
    f2 = f.f2;
  } else {
    f52 = evalF52(lambda);
    f2 = evalF2(lambda);
  }
  ContactNodeState node;
  node.pressure_Pa = pressureScale_Pa_ * f52.value;
  node.dPressure_dGap_PaPerM = pressureScale_Pa_ * f52.slope / sigma_m_;
  node.realAreaFraction = std::min(1.0, areaScale_ * f2);
  node.filmRatio = lambda;
  node.regime = classifyRegime(lambda);
  return node;
}

}  // namespace pistondyn::contact_forces
