#pragma once
// A user's own asperity contact law: the power-law form many ring-pack and skirt codes use
// instead of the exact Greenwood-Tripp integrals (Hu, Cheng, Arai, Kobayashi & Aoyama,
// "Numerical simulation of piston ring in mixed lubrication", ASME J. Tribol. 116 (1994)):
//
//   p_c(h)  = K E' A (4 - h/sigma)^z       for h/sigma < 4, else 0
//   dp_c/dh = -z K E' A (4 - h/sigma)^(z - 1) / sigma
//   A_c/A   = pi^2 (eta beta sigma)^2 A2 (4 - h/sigma)^z2
//
// with K = (8 sqrt 2 / 15) pi (eta beta sigma)^2 sqrt(sigma/beta), E' = 2 / [(1 - nu1^2)/E1 +
// (1 - nu2^2)/E2], A = 4.4068e-5, z = 6.804 (the F_5/2 fit) and A2 = 1.7011e-5, z2 = 6.832
// (the F_2 pair as it is usually quoted). Written here from those formulas alone, as a user
// would, to show how a law is made and swapped in; the fits' errors against the exact
// integrals (about 10 % at h/sigma = 0, x4 at 3; contact_forces/README.md) are why the
// element's default is the exact law.
//
// A law implements the hooks of contact_forces::AsperityContactLaw: evalPressure,
// evalPressureAndSlope, evalAreaFraction and compositeSigma_m (the interface checks the
// inputs and outputs around them). It is immutable and so safe on every thread.

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pistondyn/contact_forces/AsperityContactLaw.h"

namespace examples {

struct PowerLawContactParameters {
  double compositeSigma_m = 0.0;       // sqrt(Rq_liner^2 + Rq_skirt^2) [m], > 0
  double effectiveModulus_Pa = 0.0;    // E' [Pa], > 0
  double roughnessParameter = 0.04;    // eta beta sigma [-]
  double sigmaOverBeta = 0.001;        // sigma / beta [-]
  double coefficient = 4.4068e-5;      // A [-]
  double exponent = 6.804;             // z [-]
  double areaCoefficient = 1.7011e-5;  // A2 [-]
  double areaExponent = 6.832;         // z2 [-]
  double lambdaMax = 4.0;              // h/sigma beyond which there is no contact [-]
};

class PowerLawContactLaw final : public pistondyn::contact_forces::AsperityContactLaw {
 public:
  explicit PowerLawContactLaw(const PowerLawContactParameters& p) : p_(p) {
    if (!(p.compositeSigma_m > 0.0) || !(p.effectiveModulus_Pa > 0.0) ||
        !(p.roughnessParameter > 0.0) || !(p.sigmaOverBeta > 0.0))
      throw std::invalid_argument(
          "PowerLawContactLaw: sigma, E', eta beta sigma and sigma/beta "
          "must be positive");
    const double ebs = p.roughnessParameter;
    // The terms grouped as the formulas read: (K E') (A (4 - lambda)^z).
    const double k = 8.0 * std::sqrt(2.0) / 15.0 * M_PI * ebs * ebs * std::sqrt(p.sigmaOverBeta);
    pressureScale_Pa_ = k * p.effectiveModulus_Pa;
    areaScale_ = M_PI * M_PI * ebs * ebs;
  }

  const char* name() const override { return "PowerLaw (user example)"; }
  double compositeSigma_m() const override { return p_.compositeSigma_m; }

 protected:
  double evalPressure(double gap_m) const override {
    return evalPressureAndSlope(gap_m).pressure_Pa;
  }

  pistondyn::contact_forces::PressureAndSlope evalPressureAndSlope(double gap_m) const override {
    const double lambda = gap_m / p_.compositeSigma_m;
    if (!(lambda < p_.lambdaMax))
      return {};  // far apart (gap = +inf included)
    const double d = p_.lambdaMax - lambda;
    return {pressureScale_Pa_ * (p_.coefficient * std::pow(d, p_.exponent)),
            pressureScale_Pa_ * (-p_.coefficient * p_.exponent * std::pow(d, p_.exponent - 1.0)) /
                p_.compositeSigma_m};
  }

  double evalAreaFraction(double gap_m) const override {
    const double lambda = gap_m / p_.compositeSigma_m;
    if (!(lambda < p_.lambdaMax))
      return 0.0;
    // The statistical area exceeds 1 only for overlaps of many sigma: capped.
    return std::min(
        1.0, areaScale_ * (p_.areaCoefficient * std::pow(p_.lambdaMax - lambda, p_.areaExponent)));
  }

 private:
  PowerLawContactParameters p_;
  double pressureScale_Pa_ = 0.0;  // K E' [Pa]
  double areaScale_ = 0.0;         // pi^2 (eta beta sigma)^2 [-]
};

}  // namespace examples
