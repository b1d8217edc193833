#pragma once
/// \file
/// Expected local film thickness h_T of the average Reynolds equation (Patir & Cheng
/// 1978): the mean over the roughness of the local gap h_local = h + delta where it is
/// positive, h_T = E[max(h + delta, 0)], delta being the combined roughness height of
/// both surfaces (zero mean, RMS sigma). The squeeze and Couette terms carry h_T and the
/// squeeze term also dh_T/dh.

namespace pistondyn::lubrication {

/// Height distribution assumed for the combined roughness.
enum class ExpectedGapForm {
  /// Default. Gaussian heights N(0, sigma^2), the distribution of the surfaces P&C
  /// simulated. With H = h/sigma, Phi the standard normal CDF and phi_N its density:
  ///   h_T / sigma = H Phi(H) + phi_N(H),   dh_T/dh = Phi(H) = (1 + erf(H / sqrt 2)) / 2.
  kGaussian,
  /// The polynomial density (35/96)(1 - x^2/9)^3 on |x| <= 3 sigma that P&C 1978 use for
  /// their closed forms (and that phi_f is built on; choose it for h_T and phi_f on one
  /// density; the Gaussian h_T differs from it by at most 0.0113 sigma). With z = H/3, for |z| < 1:
  ///   h_T / sigma = (3/256)(35 + 128 z + 140 z^2 - 70 z^4 + 28 z^6 - 5 z^8),
  ///   dh_T/dh     = (1/256)(128 + 280 z - 280 z^3 + 168 z^5 - 40 z^7);
  /// h_T = h for z >= 1 (no contact) and 0 for z <= -1.
  kPatirChengPolynomial,
  /// No roughness correction: h_T = max(h, 0), dh_T/dh = 1 where h > 0 (else 0).
  kNominal,
};

/// The expected gap h_T and its slope.
struct ExpectedGap {
  double value_m = 0.0;    ///< h_T [m]
  double dValue_dh = 1.0;  ///< dh_T/dh [-]
};

/// Expected gap for nominal gap h and composite roughness sigma.
/// Inputs:
///   h_m      nominal (mean-plane) gap, finite, any sign [m]
///   sigma_m  composite RMS roughness sqrt(Rq1^2 + Rq2^2), finite and >= 0 [m]; with
///            sigma = 0 the result is max(h, 0) whatever the form
///   form     height distribution
/// Outputs:
///   h_T >= 0 and dh_T/dh in [0, 1]; h_T -> h and dh_T/dh -> 1 as h/sigma -> infinity.
/// Throws std::invalid_argument for non-finite h or negative / non-finite sigma.
ExpectedGap calcExpectedGap(double h_m, double sigma_m,
                            ExpectedGapForm form = ExpectedGapForm::kGaussian);

}  // namespace pistondyn::lubrication
