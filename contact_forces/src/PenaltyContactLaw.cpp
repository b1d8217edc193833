#include "pistondyn/contact_forces/PenaltyContactLaw.h"

#include <cmath>

#include "pistondyn/common/Validation.h"

namespace pistondyn::contact_forces {
namespace {

constexpr const char* kWhere = "PenaltyContactLaw";

// Cubic step S(x) and its derivative.
struct Step {
  double value;
  double slope;
};
inline Step cubicStep(double x) {
  if (x <= 0.0) {
    return {0.0, 0.0};
  }
  if (x >= 1.0) {
    return {1.0, 0.0};
  }
  return {x * x * (3.0 - 2.0 * x), 6.0 * x * (1.0 - x)};
}

}  // namespace

PenaltyContactLaw::PenaltyContactLaw(const PenaltyContactParameters& parameters)
    : parameters_(parameters) {
  const PenaltyContactParameters& p = parameters_;
  common::requirePositiveFinite(p.referencePressure_Pa, kWhere, "referencePressure_Pa", "Pa");
  common::requirePositiveFinite(p.referencePenetration_m, kWhere, "referencePenetration_m", "m");
  if (!(p.exponent >= 1.0) || !std::isfinite(p.exponent)) {
    common::throwInvalidValue(kWhere, "exponent", p.exponent, "",
                              ">= 1 and finite (pressure and slope continuous at the onset)");
  }
  common::requireFinite(p.onsetGap_m, kWhere, "onsetGap_m", "m");
  common::requirePositiveFinite(p.transitionDepth_m, kWhere, "transitionDepth_m", "m");
  common::requirePositiveFinite(p.compositeRoughness_m, kWhere, "compositeRoughness_m", "m");
}

double PenaltyContactLaw::evalPressure(double gap_m) const {
  return evalPressureAndSlope(gap_m).pressure_Pa;
}

PressureAndSlope PenaltyContactLaw::evalPressureAndSlope(double gap_m) const {
  const PenaltyContactParameters& p = parameters_;
  const double penetration = p.onsetGap_m - gap_m;  // δ
  if (!(penetration > 0.0)) {
    return {0.0, 0.0};
  }
  const Step s = cubicStep(penetration / p.transitionDepth_m);
  const double relative = penetration / p.referencePenetration_m;
  const double power = std::pow(relative, p.exponent);  // (δ/δ_ref)^e
  const double powerSlope =                             // d/dδ (δ/δ_ref)^e
      p.exponent * std::pow(relative, p.exponent - 1.0) / p.referencePenetration_m;
  const double pressure = p.referencePressure_Pa * power * s.value;
  // Past the onset ramp S = 1 and S' = 0: the product power·S' is left out there, so that
  // a power that overflowed gives p = inf (reported by the base class), never inf·0 = NaN.
  double slopeSum = powerSlope * s.value;
  if (s.slope != 0.0) {
    slopeSum += power * s.slope / p.transitionDepth_m;
  }
  const double dPressure_dPenetration = p.referencePressure_Pa * slopeSum;
  return {pressure, -dPressure_dPenetration};  // dδ/dh = −1
}

double PenaltyContactLaw::evalAreaFraction(double gap_m) const {
  return cubicStep((parameters_.onsetGap_m - gap_m) / parameters_.transitionDepth_m).value;
}

}  // namespace pistondyn::contact_forces
