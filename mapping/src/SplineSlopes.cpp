#include "pistondyn/mapping/detail/SplineSlopes.h"

#include <cmath>
#include <stdexcept>

#include "Cells.h"

namespace pistondyn::mapping::detail {

namespace {
// A zero pivot cannot occur for strictly increasing nodes (the closed system is strictly
// diagonally dominant; the not-a-knot elimination keeps positive pivots), so this is an
// internal error, not an argument error.
double inverse(double p) {
  if (!(std::abs(p) > 0.0) || !std::isfinite(p))
    throw std::logic_error("SplineSlopes: zero pivot in the spline slope system");
  return 1.0 / p;
}
}  // namespace

SplineSlopes::SplineSlopes(const Eigen::VectorXd& x, bool closed, double period)
    : n_(static_cast<int>(x.size())), closed_(closed), solve_(closed || x.size() >= 4) {
  const int n = n_;
  const int cells = closed ? n : n - 1;
  const Eigen::VectorXd h = cellWidths(x, closed, period);

  // Stencils of the right-hand side. With divided differences d_c = (f_{c+1} - f_c)/h_c,
  // a combination alpha*d_{c} + beta*d_{c+1} over nodes (c, c+1, c+2) has coefficients
  // (-alpha/h_c, alpha/h_c - beta/h_{c+1}, beta/h_{c+1}).
  index_.assign(3 * static_cast<size_t>(n), 0);
  coeff_.assign(3 * static_cast<size_t>(n), 0.0);
  auto setStencil = [&](int row, int c, double alpha, double beta) {
    const int i0 = c, i1 = (c + 1) % n, i2 = (c + 2) % n;
    const double hA = h[c], hB = h[(c + 1) % cells];
    index_[3 * row] = i0;
    index_[3 * row + 1] = i1;
    index_[3 * row + 2] = i2;
    coeff_[3 * row] = -alpha / hA;
    coeff_[3 * row + 1] = alpha / hA - beta / hB;
    coeff_[3 * row + 2] = beta / hB;
  };
  if (!closed && n == 2) {  // chord slope at both nodes: d_0 (stencil over nodes 0, 1)
    for (int row = 0; row < 2; ++row) {
      index_[3 * row] = 0;
      index_[3 * row + 1] = 1;
      index_[3 * row + 2] = 1;
      coeff_[3 * row] = -1.0 / h[0];
      coeff_[3 * row + 1] = 1.0 / h[0];
    }
    return;
  }
  if (!closed && n == 3) {
    // Parabola through the three points: with q2 = (d1 - d0)/(h0 + h1),
    // m0 = d0 - q2 h0, m1 = d0 + q2 h0, m2 = d0 + q2 (h0 + 2 h1).
    const double s = h[0] + h[1];
    auto parabola = [&](int row, double w) {  // m = d0 + w * (d1 - d0) / s
      setStencil(row, 0, 1.0 - w / s, w / s);
    };
    parabola(0, -h[0]);
    parabola(1, h[0]);
    parabola(2, h[0] + 2.0 * h[1]);
    return;
  }

  // Tridiagonal coefficients: a (sub), b (diag), c (super), and the stencils.
  std::vector<double> a(n, 0.0), b(n, 0.0), c(n, 0.0);
  if (!closed) {
    b[0] = h[1];
    c[0] = h[0] + h[1];
    setStencil(0, 0, (h[0] + 2.0 * (h[0] + h[1])) * h[1] / (h[0] + h[1]),
               h[0] * h[0] / (h[0] + h[1]));
    for (int i = 1; i < n - 1; ++i) {
      a[i] = h[i];
      b[i] = 2.0 * (h[i - 1] + h[i]);
      c[i] = h[i - 1];
      setStencil(i, i - 1, 3.0 * h[i], 3.0 * h[i - 1]);
    }
    const double hA = h[n - 3], hB = h[n - 2];
    a[n - 1] = hB + hA;
    b[n - 1] = hA;
    setStencil(n - 1, n - 3, hB * hB / (hA + hB), (2.0 * (hA + hB) + hB) * hA / (hA + hB));
  } else {
    for (int i = 0; i < n; ++i) {
      const int prev = (i + n - 1) % n;
      a[i] = h[i];  // coefficient of m_{i-1}
      b[i] = 2.0 * (h[prev] + h[i]);
      c[i] = h[prev];  // coefficient of m_{i+1}
      setStencil(i, prev, 3.0 * h[i], 3.0 * h[prev]);
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
  invPivot_.assign(n, 0.0);
  upper_ = c;
  double pivot = b[0];
  invPivot_[0] = inverse(pivot);
  for (int i = 1; i < n; ++i) {
    lower_[i] = a[i] * invPivot_[i - 1];
    pivot = b[i] - lower_[i] * c[i - 1];
    invPivot_[i] = inverse(pivot);
  }
  if (closed) {
    std::vector<double>& z = smZ_;
    for (int i = 1; i < n; ++i)
      z[i] -= lower_[i] * z[i - 1];
    z[n - 1] *= invPivot_[n - 1];
    for (int i = n - 2; i >= 0; --i)
      z[i] = (z[i] - upper_[i] * z[i + 1]) * invPivot_[i];
    smInvDenominator_ = inverse(1.0 + z[0] + smBetaOverGamma_ * z[n - 1]);
  }
}

template <class Node>
void SplineSlopes::run(const Eigen::Ref<const Eigen::MatrixXd>& f, Eigen::Ref<Eigen::MatrixXd>& m,
                       Node node, Eigen::VectorXd& scratch) const {
  const int n = n_;
  for (int i = 0; i < n; ++i)
    node(m, i) = coeff_[3 * i] * node(f, index_[3 * i]) +
                 coeff_[3 * i + 1] * node(f, index_[3 * i + 1]) +
                 coeff_[3 * i + 2] * node(f, index_[3 * i + 2]);
  if (!solve_)
    return;
  for (int i = 1; i < n; ++i)
    node(m, i) -= lower_[i] * node(m, i - 1);
  node(m, n - 1) *= invPivot_[n - 1];
  for (int i = n - 2; i >= 0; --i)
    node(m, i) = (node(m, i) - upper_[i] * node(m, i + 1)) * invPivot_[i];
  if (!closed_)
    return;
  // x = y - z (v.y) / (1 + v.z), v = (1, 0, ..., beta/gamma), for every line at once.
  scratch = (node(m, 0) + smBetaOverGamma_ * node(m, n - 1)).transpose() * smInvDenominator_;
  for (int i = 0; i < n; ++i)
    node(m, i) -= smZ_[i] * scratch.transpose();
}

void SplineSlopes::calcSlopes(const Eigen::Ref<const Eigen::MatrixXd>& f,
                              Eigen::Ref<Eigen::MatrixXd> slopes, Lines lines,
                              Eigen::VectorXd& scratch) const {
  if (lines == Lines::InColumns) {
    scratch.resize(f.cols());
    run(
        f, slopes, [](auto& mat, int i) { return mat.row(i); }, scratch);
  } else {
    scratch.resize(f.rows());
    run(
        f, slopes, [](auto& mat, int i) { return mat.col(i).transpose(); }, scratch);
  }
}

}  // namespace pistondyn::mapping::detail
