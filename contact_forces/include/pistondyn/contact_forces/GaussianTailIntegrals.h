#pragma once
/// \file
/// Statistical integrals of the Greenwood–Tripp asperity-contact model.
///
///   F_n(λ) = 1/√(2π) ∫_λ^∞ (s − λ)^n e^(−s²/2) ds,       λ = h/σ (film ratio)
///
/// is the n-th moment of the part of a unit Gaussian height distribution that lies above
/// λ. The asperity pressure of Greenwood & Tripp goes with F_{5/2}, the real contact area
/// with F_2, and dF_n/dλ = −n F_{n−1}, so the pressure's slope goes with F_{3/2}.
///
/// Exact evaluation (gaussianTailIntegral): F_n for n = 0, ½, 1, 3/2, 2, 5/2 from tables of
/// log F_n generated once (tools/gen_gaussian_tail_tables.py, 40-digit arithmetic) from the
/// special-function form F_n(λ) = Γ(n+1)/√(2π) · e^(−λ²/4) · U(n+½, λ), U = parabolic
/// cylinder function (DLMF 12.5.1), cross-checked there against direct quadrature:
///   - −32 ≤ λ < 37: piecewise Chebyshev series of degree 15 on unit intervals; relative
///     error below 32·ε·max(1, |log F_n|) (ε = 2.2e-16): measured ≤ 5e-15 for |λ| ≤ 8 and
///     ≤ 1.1e-13 up to λ = 37 against long-double quadrature. The bound grows with |log F_n|
///     because exp() turns the rounding of log F_n into a relative error of F_n;
///   - λ < −32 (surfaces deep in overlap): the Gaussian-moment expansion
///     F_n(−a) = Σ_k C(n,2k)(2k−1)!! a^(n−2k) with 8 terms (exact for integer n; the
///     neglected part is O(e^(−a²/2)) < 1e-220);
///   - λ ≥ 37: 0. Every F_n is below 1e-299 there, so the step to 0 is invisible to any
///     integrator (the smallest normal double is 2.2e-308).
/// The result is positive, smooth and strictly decreasing in λ on (−∞, 37), and grows like
/// |λ|^n for λ → −∞ (overlap), which is what the statistical model gives when the mean
/// planes cross. Cost: one table lookup, a 16-term Clenshaw sum and one exp().
///
/// Fits used by other codes (PowerLawTailFit, PolynomialTailFit) are provided for
/// comparison only; their errors are tabulated in contact_forces/README.md and pinned by
/// tests/contact_forces/test_gaussian_tail_integrals.cpp.

#include <array>

namespace pistondyn::contact_forces {

/// The orders that have exact tables. The value of n is 0.5 * (enumerator).
enum class TailOrder : int { F0 = 0, F1_2 = 1, F1 = 2, F3_2 = 3, F2 = 4, F5_2 = 5 };

/// n as a number: 0, 0.5, 1, 1.5, 2, 2.5.
constexpr double tailOrderValue(TailOrder order) {
  return 0.5 * static_cast<int>(order);
}

/// F_n(λ) for one of the tabulated orders.
/// Inputs:  order   n ∈ {0, ½, 1, 3/2, 2, 5/2}
///          lambda  film ratio λ = h/σ [-], any value (NaN gives NaN, +inf gives 0)
/// Outputs: F_n(λ) [-]
double gaussianTailIntegral(TailOrder order, double lambda);

/// F_{5/2}(λ): Greenwood–Tripp pressure integral.
inline double greenwoodTrippF52(double lambda) {
  return gaussianTailIntegral(TailOrder::F5_2, lambda);
}
/// F_2(λ): Greenwood–Tripp real-contact-area integral.
inline double greenwoodTrippF2(double lambda) {
  return gaussianTailIntegral(TailOrder::F2, lambda);
}

/// A tail integral and its slope d/dλ, [-].
struct TailValueAndSlope {
  double value = 0.0;  ///< F(λ) [-]
  double slope = 0.0;  ///< dF/dλ [-]
};

/// F_{5/2}(λ) and dF_{5/2}/dλ = −(5/2)·F_{3/2}(λ) in one call (one table lookup).
TailValueAndSlope greenwoodTrippF52WithSlope(double lambda);

// ---------------------------------------------------------------------------------------
/// Fits of the form  F(λ) ≈ coefficient · (lambdaMax − λ)^exponent  for λ < lambdaMax,
/// 0 beyond (continuous, with exponent − 1 continuous derivatives, at lambdaMax).
struct PowerLawTailFit {
  double coefficient = 0.0;  ///< A [-], no default (see the named fits below)
  double exponent = 0.0;     ///< p [-], no default
  double lambdaMax = 4.0;    ///< λ beyond which the fit is 0 [-], default 4

  double value(double lambda) const;  ///< F(λ) of the fit [-]
  double slope(double lambda) const;  ///< d/dλ
};

/// The power-law fit of F_{5/2} quoted throughout the ring-pack and skirt literature
/// (Hu, Cheng, Arai, Kobayashi & Aoyama 1994; Arcoumanis et al. 1997; many later papers,
/// some printing 4.4086e-5 instead — 0.04 % apart). Error against the exact F_{5/2}:
/// −10.8 % at λ = 0, −9.2 % at λ = 2, −74 % (a factor 3.9) at λ = 3, −98 % at λ = 3.5.
inline constexpr PowerLawTailFit kPowerLawFitF52{4.4068e-5, 6.804, 4.0};

/// The F_2 "counterpart" 1.7011e-5·(4 − λ)^6.832 found in circulation. It does NOT
/// approximate F_2: −56 % at λ = 0, −66 % at λ = 2, −92 % at λ = 3 (see README). Kept only
/// so that a code that uses it can be reproduced; the default GreenwoodTrippLaw uses exact
/// integrals.
inline constexpr PowerLawTailFit kPowerLawQuotedF2{1.7011e-5, 6.832, 4.0};

// ---------------------------------------------------------------------------------------
/// Fifth-degree polynomial fits  F(λ) ≈ Σ_k c_k λ^(5−k)  for λ < lambdaEnd, 0 beyond.
/// A quintic cannot follow the Gaussian tail, so each published fit is cut where it stops
/// decreasing (stationary point) or crosses zero; lambdaEnd records that point.
struct PolynomialTailFit {
  std::array<double, 6> coefficients{};  ///< c_0 … c_5, highest power first [-]
  double lambdaEnd = 0.0;                ///< λ from which the fit is 0 [-]

  double value(double lambda) const;  ///< F(λ) of the fit [-]
  double slope(double lambda) const;  ///< d/dλ
};

/// The quintic fits quoted in the Loughborough ring-pack papers (e.g. Morris, Rahmani,
/// Rahnejat, King & Fitzsimons 2013, Tribol. Int. 59): coefficients as printed there.
/// F_{5/2}: within 1.4 % for λ ≤ 1.5, then it turns up; it has a minimum at λ = 1.9112
/// (value 0.01256, 1.77 × the exact F_{5/2} there) and is cut to 0 from that point — a jump.
inline constexpr PolynomialTailFit kPolynomialFitF52{{-0.004, 0.057, -0.296, 0.784, -1.078, 0.617},
                                                     1.9111512521208642};
/// F_2: within 2.5 % for λ ≤ 1.5, −22 % at λ = 2; crosses zero at λ = 2.2946 and is cut
/// to 0 there (continuous).
inline constexpr PolynomialTailFit kPolynomialFitF2{
    {-0.0018, 0.0281, -0.1728, 0.5258, -0.8043, 0.5003}, 2.2945781132122444};

}  // namespace pistondyn::contact_forces
