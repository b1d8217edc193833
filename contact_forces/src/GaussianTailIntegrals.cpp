#include "pistondyn/contact_forces/GaussianTailIntegrals.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "GreenwoodTrippTails.h"

namespace pistondyn::contact_forces {
namespace {

// kTailOrders, kTableLambdaMin, kTableLambdaZero, kTablePieces, kChebCoeffs,
// kOverlapTerms, kLogTailCheb, kOverlapExpansion.
#include "GaussianTailTables.inc"

// Σ_j c_j T_j(t) by Clenshaw's recurrence, t ∈ [−1, 1].
inline double chebyshevSum(const double* c, double t) {
  const double twoT = 2.0 * t;
  double b1 = 0.0;
  double b2 = 0.0;
  for (int j = kChebCoeffs - 1; j >= 1; --j) {
    const double b0 = twoT * b1 - b2 + c[j];
    b2 = b1;
    b1 = b0;
  }
  return t * b1 - b2 + c[0];
}

// F_n(λ) for λ < kTableLambdaMin: Σ_k e_k a^(n−2k), a = −λ (Gaussian moments).
double overlapExpansion(int order, double lambda) {
  const double a = -lambda;
  const double inverseSquare = 1.0 / (a * a);
  const double* e = kOverlapExpansion[order];
  double sum = e[kOverlapTerms - 1];
  for (int k = kOverlapTerms - 2; k >= 0; --k) {
    sum = sum * inverseSquare + e[k];
  }
  return std::pow(a, 0.5 * order) * sum;
}

// Table piece and local coordinate t for kTableLambdaMin ≤ λ < kTableLambdaZero.
struct PieceLocation {
  int piece;
  double t;
};
inline PieceLocation locate(double lambda) {
  const double x = lambda - kTableLambdaMin;
  int piece = static_cast<int>(x);  // x ≥ 0, so truncation is floor
  if (piece > kTablePieces - 1) {
    piece = kTablePieces - 1;  // guards rounding just below kTableLambdaZero
  }
  return {piece, 2.0 * (x - piece) - 1.0};
}

int checkedOrder(TailOrder order) {
  const int k = static_cast<int>(order);
  if (k < 0 || k >= kTailOrders) {
    throw std::invalid_argument("gaussianTailIntegral: order = " + std::to_string(k) +
                                " must be one of the TailOrder values");
  }
  return k;
}

// The one place where the range of λ is decided and the table piece located. `set` names
// the integrals wanted: set.uniform(v) gives all of them equal to v (NaN for a NaN λ, 0 for
// λ ≥ kTableLambdaZero) and set.from(F) builds them from F(k) = F_k(λ), the overlap
// expansion for λ < kTableLambdaMin and otherwise the piece located once for every k.
template <class TailSet>
inline auto evalTails(const TailSet& set, double lambda) {
  if (std::isnan(lambda)) {
    return set.uniform(lambda);
  }
  if (lambda >= kTableLambdaZero) {
    return set.uniform(0.0);
  }
  if (lambda < kTableLambdaMin) {
    return set.from([lambda](int k) { return overlapExpansion(k, lambda); });
  }
  const PieceLocation at = locate(lambda);
  return set.from([&at](int k) { return std::exp(chebyshevSum(kLogTailCheb[k][at.piece], at.t)); });
}

constexpr int k52 = static_cast<int>(TailOrder::F5_2);
constexpr int k32 = static_cast<int>(TailOrder::F3_2);
constexpr int k2 = static_cast<int>(TailOrder::F2);

// F_k alone.
struct OneOrder {
  int k;
  double uniform(double v) const { return v; }
  template <class F>
  double from(const F& tail) const {
    return tail(k);
  }
};

// F_{5/2} and dF_{5/2}/dλ = −(5/2)·F_{3/2}.
struct F52AndSlope {
  TailValueAndSlope uniform(double v) const { return {v, v}; }
  template <class F>
  TailValueAndSlope from(const F& tail) const {
    return {tail(k52), -2.5 * tail(k32)};
  }
};

// F_{5/2}, its slope and F_2.
struct F52SlopeAndF2 {
  detail::GreenwoodTrippTails uniform(double v) const { return {v, v, v}; }
  template <class F>
  detail::GreenwoodTrippTails from(const F& tail) const {
    return {tail(k52), -2.5 * tail(k32), tail(k2)};
  }
};

}  // namespace

double gaussianTailIntegral(TailOrder order, double lambda) {
  return evalTails(OneOrder{checkedOrder(order)}, lambda);
}

TailValueAndSlope greenwoodTrippF52WithSlope(double lambda) {
  return evalTails(F52AndSlope{}, lambda);
}

detail::GreenwoodTrippTails detail::greenwoodTrippTails(double lambda) {
  return evalTails(F52SlopeAndF2{}, lambda);
}

double PowerLawTailFit::value(double lambda) const {
  if (!(lambda < lambdaMax)) {
    return std::isnan(lambda) ? lambda : 0.0;
  }
  return coefficient * std::pow(lambdaMax - lambda, exponent);
}

double PowerLawTailFit::slope(double lambda) const {
  if (!(lambda < lambdaMax)) {
    return std::isnan(lambda) ? lambda : 0.0;
  }
  return -coefficient * exponent * std::pow(lambdaMax - lambda, exponent - 1.0);
}

double PolynomialTailFit::value(double lambda) const {
  if (!(lambda < lambdaEnd)) {
    return std::isnan(lambda) ? lambda : 0.0;
  }
  double sum = coefficients[0];
  for (std::size_t k = 1; k < coefficients.size(); ++k) {
    sum = sum * lambda + coefficients[k];
  }
  return sum;
}

double PolynomialTailFit::slope(double lambda) const {
  if (!(lambda < lambdaEnd)) {
    return std::isnan(lambda) ? lambda : 0.0;
  }
  const std::size_t degree = coefficients.size() - 1;
  double sum = static_cast<double>(degree) * coefficients[0];
  for (std::size_t k = 1; k < degree; ++k) {
    sum = sum * lambda + static_cast<double>(degree - k) * coefficients[k];
  }
  return sum;
}

}  // namespace pistondyn::contact_forces
