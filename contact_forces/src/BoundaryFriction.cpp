#include "pistondyn/contact_forces/BoundaryFriction.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "Validation.h"

namespace pistondyn::contact {
namespace {

constexpr const char* kWhere = "BoundaryFriction";

void requireFiniteVelocity(const Eigen::Vector2d& v, const char* function) {
  if (!std::isfinite(v.x()) || !std::isfinite(v.y())) {
    const double bad = std::isfinite(v.x()) ? v.y() : v.x();
    detail::throwInvalid(std::string(kWhere) + "::" + function, "slidingVelocity_mps component",
                         bad, "m/s", "finite");
  }
}

void requirePressure(double p, const char* function) {
  if (!(p >= 0.0) || !std::isfinite(p)) {
    detail::throwInvalid(std::string(kWhere) + "::" + function, "contactPressure_Pa", p, "Pa",
                         "non-negative and finite");
  }
}

}  // namespace

BoundaryFriction::BoundaryFriction(const BoundaryFrictionParameters& parameters)
    : parameters_(parameters) {
  detail::requireNonNegativeFinite(parameters_.frictionCoefficient, kWhere, "frictionCoefficient",
                                   "");
  detail::requirePositiveFinite(parameters_.regularisationSpeed_mps, kWhere,
                                "regularisationSpeed_mps", "m/s");
  if (parameters_.regularisation != FrictionRegularisation::Algebraic &&
      parameters_.regularisation != FrictionRegularisation::Tanh) {
    throw std::invalid_argument(
        "BoundaryFriction: regularisation is not a FrictionRegularisation value");
  }
}

double BoundaryFriction::weightPerVelocity(double speed) const {
  const double vEps = parameters_.regularisationSpeed_mps;
  if (parameters_.regularisation == FrictionRegularisation::Algebraic) {
    return 1.0 / std::sqrt(speed * speed + vEps * vEps);
  }
  const double x = speed / vEps;
  if (x < 1e-3) {  // tanh(x)/x = 1 − x²/3 + 2x⁴/15 − …; truncation error < 1e-18
    const double x2 = x * x;
    return (1.0 - x2 / 3.0 + 2.0 * x2 * x2 / 15.0) / vEps;
  }
  return std::tanh(x) / speed;
}

double BoundaryFriction::calcEffectiveCoefficient(double slidingSpeed_mps) const {
  if (!(slidingSpeed_mps >= 0.0) || !std::isfinite(slidingSpeed_mps)) {
    detail::throwInvalid("BoundaryFriction::calcEffectiveCoefficient", "slidingSpeed_mps",
                         slidingSpeed_mps, "m/s", "non-negative and finite");
  }
  return parameters_.frictionCoefficient * weightPerVelocity(slidingSpeed_mps) * slidingSpeed_mps;
}

Eigen::Vector2d BoundaryFriction::calcShearStress_Pa(
    double contactPressure_Pa, const Eigen::Vector2d& slidingVelocity_mps) const {
  requirePressure(contactPressure_Pa, "calcShearStress_Pa");
  requireFiniteVelocity(slidingVelocity_mps, "calcShearStress_Pa");
  const double w = weightPerVelocity(slidingVelocity_mps.norm());
  return (-parameters_.frictionCoefficient * contactPressure_Pa * w) * slidingVelocity_mps;
}

Eigen::Matrix2d BoundaryFriction::calcShearStressVelocityJacobian(
    double contactPressure_Pa, const Eigen::Vector2d& slidingVelocity_mps) const {
  requirePressure(contactPressure_Pa, "calcShearStressVelocityJacobian");
  requireFiniteVelocity(slidingVelocity_mps, "calcShearStressVelocityJacobian");
  // τ = −f p w(s) v, s = |v|  ⇒  ∂τ/∂v = −f p [ w I + (w'(s)/s) v vᵀ ].
  const Eigen::Vector2d& v = slidingVelocity_mps;
  const double speed = v.norm();
  const double vEps = parameters_.regularisationSpeed_mps;
  const double w = weightPerVelocity(speed);
  double dwOverS = 0.0;  // w'(s)/s
  if (parameters_.regularisation == FrictionRegularisation::Algebraic) {
    dwOverS = -w * w * w;  // w = (s² + ε²)^(−1/2)
  } else {
    // w = h(x)/ε, x = s/ε, h = tanh(x)/x  ⇒  w'(s)/s = (h'(x)/x)/ε³,
    // h'(x)/x = (sech²x − h(x))/x², by its series below x = 0.01 to avoid cancellation.
    const double x = speed / vEps;
    double hPrimeOverX;
    if (x < 1e-2) {
      const double x2 = x * x;
      hPrimeOverX = -2.0 / 3.0 + 8.0 / 15.0 * x2 - 34.0 / 105.0 * x2 * x2;
    } else {
      const double sech = 1.0 / std::cosh(x);
      hPrimeOverX = (sech * sech - std::tanh(x) / x) / (x * x);
    }
    dwOverS = hPrimeOverX / (vEps * vEps * vEps);
  }
  const double scale = -parameters_.frictionCoefficient * contactPressure_Pa;
  return scale * (w * Eigen::Matrix2d::Identity() + dwOverS * v * v.transpose());
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
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      const double p = contactPressure_Pa(i, j);
      const double vx = slidingVelocityX_mps(i, j);
      const double vy = slidingVelocityY_mps(i, j);
      if (!(p >= 0.0) || !std::isfinite(p) || !std::isfinite(vx) || !std::isfinite(vy)) {
        const std::string at = "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
        if (!(p >= 0.0) || !std::isfinite(p)) {
          detail::throwInvalid("BoundaryFriction::calcShearStressField", "contactPressure_Pa" + at,
                               p, "Pa", "non-negative and finite");
        }
        detail::throwInvalid(
            "BoundaryFriction::calcShearStressField",
            (std::isfinite(vx) ? "slidingVelocityY_mps" : "slidingVelocityX_mps") + at,
            std::isfinite(vx) ? vy : vx, "m/s", "finite");
      }
    }
  }
  shearStressX_Pa.resize(rows, cols);
  shearStressY_Pa.resize(rows, cols);
  const double f = parameters_.frictionCoefficient;
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      const double vx = slidingVelocityX_mps(i, j);
      const double vy = slidingVelocityY_mps(i, j);
      const double scale = -f * contactPressure_Pa(i, j) * weightPerVelocity(std::hypot(vx, vy));
      shearStressX_Pa(i, j) = scale * vx;
      shearStressY_Pa(i, j) = scale * vy;
    }
  }
}

}  // namespace pistondyn::contact
