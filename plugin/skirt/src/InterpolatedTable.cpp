#include "pistondyn/skirt/InterpolatedTable.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "Checks.h"

namespace pistondyn::skirt {

namespace {

double sign(double v) {
  return (v > 0.0) - (v < 0.0);
}

// Fritsch-Butland weighted-harmonic-mean slopes with the shape-preserving end formula (see
// the header). n >= 3.
Eigen::VectorXd pchipSlopes(const Eigen::VectorXd& x, const Eigen::VectorXd& f) {
  const Eigen::Index n = x.size();
  Eigen::VectorXd h(n - 1), delta(n - 1), d(n);
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    h[k] = x[k + 1] - x[k];
    delta[k] = (f[k + 1] - f[k]) / h[k];
  }
  for (Eigen::Index k = 1; k + 1 < n; ++k) {
    if (delta[k - 1] * delta[k] <= 0.0) {
      d[k] = 0.0;  // a local extremum or a flat interval: no overshoot
    } else {
      const double w1 = 2.0 * h[k] + h[k - 1];
      const double w2 = h[k] + 2.0 * h[k - 1];
      d[k] = (w1 + w2) / (w1 / delta[k - 1] + w2 / delta[k]);
    }
  }
  // End slope from the one-sided three-point formula, kept shape preserving.
  const auto endSlope = [](double h0, double h1, double del0, double del1) {
    double s = ((2.0 * h0 + h1) * del0 - h0 * del1) / (h0 + h1);
    if (sign(s) != sign(del0))
      s = 0.0;
    else if (sign(del0) != sign(del1) && std::abs(s) > 3.0 * std::abs(del0))
      s = 3.0 * del0;
    return s;
  };
  d[0] = endSlope(h[0], h[1], delta[0], delta[1]);
  d[n - 1] = endSlope(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]);
  return d;
}

}  // namespace

InterpolatedTable::InterpolatedTable(Eigen::VectorXd x, Eigen::VectorXd f, Interpolation method,
                                     const std::string& where, const std::string& xName,
                                     const std::string& xUnit, const std::string& fName,
                                     const std::string& fUnit)
    : x_(std::move(x)), f_(std::move(f)), method_(method) {
  detail::requireIncreasing(where, xName, x_, xUnit, 1);
  detail::requireSameSize(where, fName, f_.size(), xName, x_.size());
  detail::requireFiniteEntries(where, fName, f_, fUnit);
  const Eigen::Index n = x_.size();
  if (n == 1) {
    d_ = Eigen::VectorXd::Zero(method_ == Interpolation::Pchip ? 1 : 0);
  } else if (method_ == Interpolation::Linear || n == 2) {
    Eigen::VectorXd secants(n - 1);
    for (Eigen::Index k = 0; k + 1 < n; ++k)
      secants[k] = (f_[k + 1] - f_[k]) / (x_[k + 1] - x_[k]);
    if (method_ == Interpolation::Linear)
      d_ = std::move(secants);
    else
      d_ = Eigen::VectorXd::Constant(2, secants[0]);  // PCHIP of two rows: the straight line
  } else {
    d_ = pchipSlopes(x_, f_);
  }
}

TableSample InterpolatedTable::evaluate(double x) const {
  const Eigen::Index n = x_.size();
  if (n == 0)
    return {};
  // Strictly outside (or NaN, kept out of the interval search): the end value, slope 0. The
  // ends themselves belong to the end intervals, so their derivative is the one-sided slope.
  if (n == 1 || !(x >= x_[0]))
    return {f_[0], 0.0};
  if (x > x_[n - 1])
    return {f_[n - 1], 0.0};
  // Interval k with x_k <= x < x_{k+1} (the last interval also takes x = x_last).
  const double* begin = x_.data();
  const Eigen::Index k =
      std::min<Eigen::Index>(std::upper_bound(begin, begin + n, x) - begin - 1, n - 2);
  const double h = x_[k + 1] - x_[k];
  const double t = (x - x_[k]) / h;
  if (method_ == Interpolation::Linear)
    return {f_[k] + t * (f_[k + 1] - f_[k]), d_[k]};
  // Cubic Hermite basis on [0, 1]: value through the rows exactly at t = 0 and t = 1.
  const double s = 1.0 - t;
  const double h00 = (1.0 + 2.0 * t) * s * s;
  const double h10 = t * s * s;
  const double h01 = t * t * (3.0 - 2.0 * t);
  const double h11 = -t * t * s;
  const double dh00 = 6.0 * t * (t - 1.0);  // d/dt; dh01 = -dh00
  const double dh10 = (3.0 * t - 1.0) * (t - 1.0);
  const double dh11 = t * (3.0 * t - 2.0);
  TableSample out;
  out.value = h00 * f_[k] + h01 * f_[k + 1] + h * (h10 * d_[k] + h11 * d_[k + 1]);
  out.derivative = dh00 * (f_[k] - f_[k + 1]) / h + dh10 * d_[k] + dh11 * d_[k + 1];
  return out;
}

}  // namespace pistondyn::skirt
