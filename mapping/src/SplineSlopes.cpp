#include "pistondyn/mapping/detail/SplineSlopes.h"

#include <cmath>
#include <stdexcept>

namespace pistondyn::mapping::detail {

namespace {
// A zero pivot cannot occur for strictly increasing nodes (the closed system is strictly
// diagonally dominant; the not-a-knot elimination keeps positive pivots), so this is an
// internal error, not an argument error.
void checkPivot(double p) {
  if (!(std::abs(p) > 0.0) || !std::isfinite(p))
    throw std::logic_error("SplineSlopes: zero pivot in the spline slope system");
}
}  // namespace

SplineSlopes::SplineSlopes(const Eigen::VectorXd& x, bool closed, double period)
    : n_(static_cast<int>(x.size())), closed_(closed) {
  const int n = n_;
  const int cells = closed ? n : n - 1;
  h_.resize(cells);
  for (int c = 0; c + 1 < n; ++c)
    h_[c] = x[c + 1] - x[c];
  if (closed)
    h_[n - 1] = x[0] + period - x[n - 1];
  if (!closed && n <= 3)
    return;  // explicit formulas, no system

  // Tridiagonal coefficients: a (sub), b (diag), c (super).
  std::vector<double> a(n, 0.0), b(n, 0.0), c(n, 0.0);
  const std::vector<double>& h = h_;
  if (!closed) {
    b[0] = h[1];
    c[0] = h[0] + h[1];
    for (int i = 1; i < n - 1; ++i) {
      a[i] = h[i];
      b[i] = 2.0 * (h[i - 1] + h[i]);
      c[i] = h[i - 1];
    }
    a[n - 1] = h[n - 2] + h[n - 3];
    b[n - 1] = h[n - 3];
  } else {
    for (int i = 0; i < n; ++i) {
      const double hPrev = h[(i + n - 1) % n];
      a[i] = h[i];  // coefficient of m_{i-1}
      b[i] = 2.0 * (hPrev + h[i]);
      c[i] = hPrev;  // coefficient of m_{i+1}
    }
    // Sherman-Morrison (Numerical Recipes "cyclic"): A = T' + u v^T with
    // u = (gamma, 0, ..., alpha), v = (1, 0, ..., beta/gamma),
    // beta = A[0][n-1] = a[0], alpha = A[n-1][0] = c[n-1], gamma = -b[0].
    const double beta = a[0], alpha = c[n - 1], gamma = -b[0];
    b[0] -= gamma;
    b[n - 1] -= alpha * beta / gamma;
    smBetaOverGamma_ = beta / gamma;
    smZ_.assign(n, 0.0);
    smZ_[0] = gamma;
    smZ_[n - 1] = alpha;
  }

  lower_.assign(n, 0.0);
  pivot_.assign(n, 0.0);
  upper_ = c;
  pivot_[0] = b[0];
  checkPivot(pivot_[0]);
  for (int i = 1; i < n; ++i) {
    lower_[i] = a[i] / pivot_[i - 1];
    pivot_[i] = b[i] - lower_[i] * c[i - 1];
    checkPivot(pivot_[i]);
  }
  if (closed) {
    solveTridiagonal(smZ_.data());
    smDenominator_ = 1.0 + smZ_[0] + smBetaOverGamma_ * smZ_[n - 1];
    checkPivot(smDenominator_);
  }
}

void SplineSlopes::solveTridiagonal(double* d) const {
  const int n = n_;
  for (int i = 1; i < n; ++i)
    d[i] -= lower_[i] * d[i - 1];
  d[n - 1] /= pivot_[n - 1];
  for (int i = n - 2; i >= 0; --i)
    d[i] = (d[i] - upper_[i] * d[i + 1]) / pivot_[i];
}

// Right-hand side of the slope equations (or the slopes themselves for n <= 3 open).
void SplineSlopes::rhs(const double* f, double* b) const {
  const int n = n_;
  const std::vector<double>& h = h_;
  auto delta = [&](int c) { return (f[(c + 1) % n] - f[c]) / h[c]; };
  if (!closed_) {
    if (n == 2) {
      b[0] = b[1] = delta(0);
      return;
    }
    if (n == 3) {  // parabola through the three points
      const double d0 = delta(0), d1 = delta(1);
      const double q2 = (d1 - d0) / (h[0] + h[1]);  // second divided difference
      b[0] = d0 - q2 * h[0];
      b[1] = d0 + q2 * h[0];
      b[2] = d0 + q2 * (h[0] + 2.0 * h[1]);
      return;
    }
    const double d0 = delta(0), d1 = delta(1);
    b[0] = ((h[0] + 2.0 * (h[0] + h[1])) * h[1] * d0 + h[0] * h[0] * d1) / (h[0] + h[1]);
    double dPrev = d0;
    for (int i = 1; i < n - 1; ++i) {
      const double dNext = delta(i);
      b[i] = 3.0 * (h[i] * dPrev + h[i - 1] * dNext);
      dPrev = dNext;
    }
    const double dA = delta(n - 3), dB = delta(n - 2);
    const double hA = h[n - 3], hB = h[n - 2];
    b[n - 1] = (hB * hB * dA + (2.0 * (hA + hB) + hB) * hA * dB) / (hA + hB);
    return;
  }
  double dPrev = delta(n - 1);
  for (int i = 0; i < n; ++i) {
    const double dNext = delta(i);
    b[i] = 3.0 * (h[i] * dPrev + h[(i + n - 1) % n] * dNext);
    dPrev = dNext;
  }
}

void SplineSlopes::calcSlopes(const Eigen::Ref<const Eigen::MatrixXd>& f,
                              Eigen::Ref<Eigen::MatrixXd> slopes) const {
  for (Eigen::Index col = 0; col < f.cols(); ++col) {
    double* m = slopes.col(col).data();
    rhs(f.col(col).data(), m);
    if (!closed_ && n_ <= 3)
      continue;
    solveTridiagonal(m);
    if (closed_) {
      const double factor = (m[0] + smBetaOverGamma_ * m[n_ - 1]) / smDenominator_;
      for (int i = 0; i < n_; ++i)
        m[i] -= factor * smZ_[i];
    }
  }
}

}  // namespace pistondyn::mapping::detail
