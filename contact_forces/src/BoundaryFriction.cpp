#include "pistondyn/contact_forces/BoundaryFriction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "pistondyn/common/Validation.h"

namespace pistondyn::contact_forces {
namespace {

constexpr const char* kWhere = "BoundaryFriction";

void requireFiniteVelocity(const Eigen::Vector2d& v, const char* function) {
  if (!std::isfinite(v.x()) || !std::isfinite(v.y())) {
    common::throwNotFinite(std::isfinite(v.x()) ? v.y() : v.x(),
                           std::string(kWhere) + "::" + function, "slidingVelocity_mps component",
                           "m/s");
  }
}

void requirePressure(double p, const char* function) {
  if (common::notNonNegativeFinite(p)) {
    common::throwNotNonNegativeFinite(p, std::string(kWhere) + "::" + function,
                                      "contactPressure_Pa", "Pa");
  }
}

// tanh(s/v_ε)/s [s/m] for x = s/v_ε, finite at s = 0 (where it is 1/v_ε).
inline double tanhFractionOverSpeed(double x, double speed, double vEps) {
  if (x < 1e-3) {  // tanh(x)/x = 1 − x²/3 + 2x⁴/15 − …; truncation error < 1e-18
    const double x2 = x * x;
    return (1.0 - x2 / 3.0 + 2.0 * x2 * x2 / 15.0) / vEps;
  }
  return std::tanh(x) / speed;
}

// "(i, j)", appended to a field's name in messages.
std::string nodeIndex(Eigen::Index i, Eigen::Index j) {
  return "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
}

}  // namespace

BoundaryFriction::BoundaryFriction(const BoundaryFrictionParameters& parameters)
    : parameters_(parameters) {
  common::requireNonNegativeFinite(parameters_.frictionCoefficient, kWhere, "frictionCoefficient",
                                   "");
  common::requirePositiveFinite(parameters_.regularisationSpeed_mps, kWhere,
                                "regularisationSpeed_mps", "m/s");
  if (parameters_.regularisation != FrictionRegularisation::Algebraic &&
      parameters_.regularisation != FrictionRegularisation::Tanh) {
    throw std::invalid_argument(
        "BoundaryFriction: regularisation is not a FrictionRegularisation value");
  }
  // |v|² + v_ε² stays finite when both are below 1e150 (see weightedDirection).
  constexpr double kFastPathLimit_mps = 1e150;
  fastPathSpeed_mps_ =
      parameters_.regularisationSpeed_mps <= kFastPathLimit_mps ? kFastPathLimit_mps : 0.0;
}

// |v| and v/|v| without overflow or underflow: the components are scaled by the larger
// magnitude first, so the square root sees a number in [1, 2]. |v| may still be +inf for
// |v| > DBL_MAX (every formula below takes that limit correctly); unit = 0 for v = 0.
BoundaryFriction::SpeedAndDirection BoundaryFriction::splitVelocity(double vx, double vy) {
  const double m = std::max(std::fabs(vx), std::fabs(vy));
  if (m == 0.0) {
    return {0.0, 0.0, 0.0};
  }
  const double ax = vx / m;
  const double ay = vy / m;
  const double norm = std::sqrt(ax * ax + ay * ay);
  return {m * norm, ax / norm, ay / norm};
}

// g(s) = effective coefficient / f ∈ [0, 1): s/√(s² + v_ε²) or tanh(s/v_ε). The algebraic
// form is evaluated on the side of x = s/v_ε where neither x² nor (1/x)² can overflow:
// s = 1e200 gives 1 (not 0 from s² = inf), s = 1e-200 gives s/v_ε (not 0).
double BoundaryFriction::fraction(double speed) const {
  const double vEps = parameters_.regularisationSpeed_mps;
  const double x = speed / vEps;
  if (parameters_.regularisation == FrictionRegularisation::Tanh) {
    return std::tanh(x);
  }
  if (x <= 1.0) {
    return x / std::sqrt(1.0 + x * x);
  }
  const double r = vEps / speed;  // < 1
  return 1.0 / std::sqrt(1.0 + r * r);
}

// g(s)/s [s/m] (finite at s = 0, where it is 1/v_ε) and g'(s) [s/m].
void BoundaryFriction::fractionOverSpeedAndSlope(double speed, double& overSpeed,
                                                 double& slope) const {
  const double vEps = parameters_.regularisationSpeed_mps;
  const double x = speed / vEps;
  if (parameters_.regularisation == FrictionRegularisation::Tanh) {
    overSpeed = tanhFractionOverSpeed(x, speed, vEps);
    const double sech = 1.0 / std::cosh(x);  // cosh(x) = inf for large x: sech = 0
    slope = sech * sech / vEps;
    return;
  }
  if (x <= 1.0) {
    const double q = 1.0 / std::sqrt(1.0 + x * x);
    overSpeed = q / vEps;      // 1/√(s² + v_ε²)
    slope = q * q * q / vEps;  // v_ε²/(s² + v_ε²)^{3/2}
  } else {
    const double r = vEps / speed;
    const double q = 1.0 / std::sqrt(1.0 + r * r);
    overSpeed = q / speed;
    slope = r * r * r * q * q * q / vEps;
  }
}

// (tx, ty) = g(|v|)·v/|v|, so that τ = −f·p·(tx, ty). Below fastPathSpeed_mps_ (1e150 per
// component, and v_ε below that too) |v|² cannot overflow, and its underflow for tiny v
// is harmless (both forms then give v/v_ε, the correct limit), so the common case needs
// one square root and one division instead of the scaled split.
void BoundaryFriction::weightedDirection(double vx, double vy, double& tx, double& ty) const {
  const double m = std::max(std::fabs(vx), std::fabs(vy));
  if (m <= fastPathSpeed_mps_) {
    const double vEps = parameters_.regularisationSpeed_mps;
    const double s2 = vx * vx + vy * vy;
    double w;  // g(s)/s
    if (parameters_.regularisation == FrictionRegularisation::Algebraic) {
      w = 1.0 / std::sqrt(s2 + vEps * vEps);
    } else {
      const double s = std::sqrt(s2);
      w = tanhFractionOverSpeed(s / vEps, s, vEps);
    }
    tx = w * vx;
    ty = w * vy;
    return;
  }
  const SpeedAndDirection v = splitVelocity(vx, vy);
  const double g = fraction(v.speed);
  tx = g * v.unitX;
  ty = g * v.unitY;
}

double BoundaryFriction::calcEffectiveCoefficient(double slidingSpeed_mps) const {
  common::requireNonNegativeFinite(slidingSpeed_mps, "BoundaryFriction::calcEffectiveCoefficient",
                                   "slidingSpeed_mps", "m/s");
  return parameters_.frictionCoefficient * fraction(slidingSpeed_mps);
}

Eigen::Vector2d BoundaryFriction::calcShearStress_Pa(
    double contactPressure_Pa, const Eigen::Vector2d& slidingVelocity_mps) const {
  requirePressure(contactPressure_Pa, "calcShearStress_Pa");
  requireFiniteVelocity(slidingVelocity_mps, "calcShearStress_Pa");
  double tx = 0.0, ty = 0.0;
  weightedDirection(slidingVelocity_mps.x(), slidingVelocity_mps.y(), tx, ty);
  const double scale = -parameters_.frictionCoefficient * contactPressure_Pa;
  return {scale * tx, scale * ty};
}

Eigen::Matrix2d BoundaryFriction::calcShearStressVelocityJacobian(
    double contactPressure_Pa, const Eigen::Vector2d& slidingVelocity_mps) const {
  requirePressure(contactPressure_Pa, "calcShearStressVelocityJacobian");
  requireFiniteVelocity(slidingVelocity_mps, "calcShearStressVelocityJacobian");
  // τ = −f p g(s) e, s = |v|, e = v/s  ⇒  ∂τ/∂v = −f p [ g'(s) e eᵀ + (g(s)/s)(I − e eᵀ) ]
  // (along v the slope of g, across it the turning of the direction). At s = 0, e = 0 and
  // g/s = g'(0) = 1/v_ε. No term overflows or cancels for any finite v.
  const SpeedAndDirection v = splitVelocity(slidingVelocity_mps.x(), slidingVelocity_mps.y());
  double overSpeed = 0.0;
  double slope = 0.0;
  fractionOverSpeedAndSlope(v.speed, overSpeed, slope);
  const Eigen::Vector2d e(v.unitX, v.unitY);
  const Eigen::Matrix2d along = e * e.transpose();
  const double scale = -parameters_.frictionCoefficient * contactPressure_Pa;
  return scale * (slope * along + overSpeed * (Eigen::Matrix2d::Identity() - along));
}

void BoundaryFriction::calcShearStressField(
    const Eigen::Ref<const Eigen::ArrayXXd>& contactPressure_Pa,
    const Eigen::Ref<const Eigen::ArrayXXd>& slidingVelocityX_mps,
    const Eigen::Ref<const Eigen::ArrayXXd>& slidingVelocityY_mps, Eigen::ArrayXXd& shearStressX_Pa,
    Eigen::ArrayXXd& shearStressY_Pa) const {
  const Eigen::Index rows = contactPressure_Pa.rows();
  const Eigen::Index cols = contactPressure_Pa.cols();
  if (slidingVelocityX_mps.rows() != rows || slidingVelocityX_mps.cols() != cols ||
      slidingVelocityY_mps.rows() != rows || slidingVelocityY_mps.cols() != cols) {
    throw std::invalid_argument(
        "BoundaryFriction::calcShearStressField: slidingVelocityX_mps and slidingVelocityY_mps "
        "must have the shape of contactPressure_Pa (" +
        std::to_string(rows) + " x " + std::to_string(cols) + ")");
  }
  const char* fn = "BoundaryFriction::calcShearStressField";
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      const double p = contactPressure_Pa(i, j);
      const double vx = slidingVelocityX_mps(i, j);
      const double vy = slidingVelocityY_mps(i, j);
      if (common::notNonNegativeFinite(p) || !std::isfinite(vx) || !std::isfinite(vy)) {
        const std::string at = nodeIndex(i, j);
        common::requireNonNegativeFinite(p, fn, "contactPressure_Pa" + at, "Pa");
        common::requireFinite(vx, fn, "slidingVelocityX_mps" + at, "m/s");
        common::throwNotFinite(vy, fn, "slidingVelocityY_mps" + at, "m/s");
      }
    }
  }
  shearStressX_Pa.resize(rows, cols);
  shearStressY_Pa.resize(rows, cols);
  const double f = parameters_.frictionCoefficient;
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      double tx = 0.0, ty = 0.0;
      weightedDirection(slidingVelocityX_mps(i, j), slidingVelocityY_mps(i, j), tx, ty);
      const double scale = -f * contactPressure_Pa(i, j);
      shearStressX_Pa(i, j) = scale * tx;
      shearStressY_Pa(i, j) = scale * ty;
    }
  }
}

void BoundaryFriction::calcShearStressField(
    const Eigen::Ref<const Eigen::ArrayXXd>& contactPressure_Pa,
    const Eigen::Vector2d& slidingVelocity_mps, Eigen::ArrayXXd& shearStressX_Pa,
    Eigen::ArrayXXd& shearStressY_Pa) const {
  const char* fn = "BoundaryFriction::calcShearStressField";
  requireFiniteVelocity(slidingVelocity_mps, "calcShearStressField");
  const Eigen::Index rows = contactPressure_Pa.rows();
  const Eigen::Index cols = contactPressure_Pa.cols();
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      const double p = contactPressure_Pa(i, j);
      if (common::notNonNegativeFinite(p)) {
        common::throwNotNonNegativeFinite(p, fn, "contactPressure_Pa" + nodeIndex(i, j), "Pa");
      }
    }
  }
  // One speed, one coefficient, one direction for the whole field.
  const SpeedAndDirection v = splitVelocity(slidingVelocity_mps.x(), slidingVelocity_mps.y());
  const double magnitude = -parameters_.frictionCoefficient * fraction(v.speed);
  shearStressX_Pa.resize(rows, cols);
  shearStressY_Pa.resize(rows, cols);
  shearStressX_Pa = (magnitude * v.unitX) * contactPressure_Pa;
  shearStressY_Pa = (magnitude * v.unitY) * contactPressure_Pa;
}

}  // namespace pistondyn::contact_forces
