#include "pistondyn/lubrication/FilmGrid.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "pistondyn/common/Validation.h"

namespace pistondyn::lubrication {

namespace {

void checkCoordinates(const Eigen::VectorXd& c, const char* what) {
  constexpr const char* kWhere = "FilmGrid";
  if (c.size() < 3)
    common::throwInvalidArgument(
        kWhere, common::message(what, " has ", c.size(), " nodes; at least 3 are needed"));
  for (Eigen::Index k = 0; k < c.size(); ++k) {
    if (!std::isfinite(c[k]))
      common::throwNotFinite(c[k], kWhere, common::message(what, "[", k, "]"), "m");
    if (k > 0 && !(c[k] > c[k - 1]))
      common::throwInvalidArgument(
          kWhere, common::message(what, " must be strictly increasing, but ", what, "[", k, "] = ",
                                  c[k], " m <= ", what, "[", k - 1, "] = ", c[k - 1], " m"));
  }
}

// Trapezoid weights w_i = integral of the hat function N_i and first-moment weights
// m_i = integral of s * N_i(s) ds, cell by cell (exact for piecewise-linear N_i).
void oneDimensionalWeights(const Eigen::VectorXd& c, bool periodic, double period,
                           Eigen::VectorXd& w, Eigen::VectorXd& m) {
  const Eigen::Index n = c.size();
  w.setZero(n);
  m.setZero(n);
  const Eigen::Index cells = periodic ? n : n - 1;
  for (Eigen::Index e = 0; e < cells; ++e) {
    const Eigen::Index ia = e;
    const Eigen::Index ib = (e + 1) % n;
    const double a = c[ia];
    const double b = (e + 1 < n) ? c[ib] : c[0] + period;
    const double d = b - a;
    w[ia] += 0.5 * d;
    w[ib] += 0.5 * d;
    m[ia] += d * (2.0 * a + b) / 6.0;
    m[ib] += d * (a + 2.0 * b) / 6.0;
  }
}

}  // namespace

FilmGrid FilmGrid::uniform(int nx, double lengthX_m, int ny, double lengthY_m, bool periodicX,
                           double x0_m, double y0_m) {
  constexpr const char* kWhere = "FilmGrid::uniform";
  if (nx < 3)
    common::throwInvalidArgument(kWhere, common::message("nx = ", nx, " must be >= 3"));
  if (ny < 3)
    common::throwInvalidArgument(kWhere, common::message("ny = ", ny, " must be >= 3"));
  common::requirePositiveFinite(lengthX_m, kWhere, "lengthX_m", "m");
  common::requirePositiveFinite(lengthY_m, kWhere, "lengthY_m", "m");
  common::requireFinite(x0_m, kWhere, "origin x0_m", "m");
  common::requireFinite(y0_m, kWhere, "origin y0_m", "m");
  Eigen::VectorXd x(nx), y(ny);
  const double dx = periodicX ? lengthX_m / nx : lengthX_m / (nx - 1);
  for (int i = 0; i < nx; ++i)
    x[i] = x0_m + dx * i;
  for (int j = 0; j < ny; ++j)
    y[j] = y0_m + lengthY_m * j / (ny - 1);
  return fromCoordinates(std::move(x), std::move(y), periodicX, periodicX ? lengthX_m : 0.0);
}

FilmGrid FilmGrid::fromCoordinates(Eigen::VectorXd x_m, Eigen::VectorXd y_m, bool periodicX,
                                   double periodX_m) {
  checkCoordinates(x_m, "x_m");
  checkCoordinates(y_m, "y_m");
  if (periodicX) {
    const double span = x_m[x_m.size() - 1] - x_m[0];
    if (!(std::isfinite(periodX_m) && periodX_m > span))
      common::throwInvalidValue(
          "FilmGrid::fromCoordinates", "periodX_m", periodX_m, "m",
          common::message("finite and larger than the x span of the nodes, ", span, " m"));
  }
  FilmGrid g;
  g.x_ = std::move(x_m);
  g.y_ = std::move(y_m);
  g.periodicX_ = periodicX;
  g.periodX_ = periodicX ? periodX_m : 0.0;
  g.computeWeights();
  return g;
}

Eigen::VectorXd FilmGrid::clusteredCoordinates(int n, double a, double b, double clustering) {
  constexpr const char* kWhere = "FilmGrid::clusteredCoordinates";
  if (n < 2)
    common::throwInvalidArgument(kWhere, common::message("n = ", n, " must be >= 2"));
  if (!(std::isfinite(a) && std::isfinite(b) && b > a))
    common::throwInvalidArgument(kWhere,
                                 common::message("need finite a < b, got a = ", a, ", b = ", b));
  common::requireNonNegativeFinite(clustering, kWhere, "clustering", "");
  Eigen::VectorXd c(n);
  for (int k = 0; k < n; ++k) {
    const double s = static_cast<double>(k) / (n - 1);  // 0..1
    double t = s;
    if (clustering > 0.0)
      t = 0.5 * (1.0 + std::tanh(clustering * (2.0 * s - 1.0)) / std::tanh(clustering));
    c[k] = a + (b - a) * t;
  }
  c[0] = a;
  c[n - 1] = b;
  return c;
}

double FilmGrid::dxEast_m(int i) const {
  if (i + 1 < nx())
    return x_[i + 1] - x_[i];
  return periodicX_ ? x_[0] + periodX_ - x_[i] : 0.0;
}

void FilmGrid::computeWeights() {
  oneDimensionalWeights(x_, periodicX_, periodX_, wx_, mx_);
  oneDimensionalWeights(y_, false, 0.0, wy_, my_);
  const int n = nodeCount();
  area_.resize(n);
  areaMx_.resize(n);
  areaMy_.resize(n);
  for (int j = 0; j < ny(); ++j) {
    for (int i = 0; i < nx(); ++i) {
      const int k = nodeIndex(i, j);
      area_[k] = wx_[i] * wy_[j];
      areaMx_[k] = mx_[i] * wy_[j];
      areaMy_[k] = wx_[i] * my_[j];
    }
  }
}

}  // namespace pistondyn::lubrication
