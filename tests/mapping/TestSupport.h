#pragma once
// Helpers for the mapping tests that do not use the library under test: Gauss-Legendre
// rules (Newton iteration on the Legendre recurrence), random graded node vectors, the
// bilinear interpolant of one cell, a loop over grid cells clipped to a rectangle, and an
// exception-message check.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "GaussLegendre.h"

namespace pistondyn::mapping::test {

constexpr double kPi = 3.14159265358979323846264338327950;

// n-point Gauss-Legendre nodes and weights on [-1, 1] (tests/support/GaussLegendre.h).
using pistondyn::test::gaussLegendre;

// Integral of f over [a, b] x [c, d] with an nx x ny Gauss rule.
template <class F>
double integrateRectangle(double a, double b, double c, double d, int nx, int ny, F&& f) {
  const auto [gx, wx] = gaussLegendre(nx);
  const auto [gy, wy] = gaussLegendre(ny);
  double sum = 0.0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const double x = 0.5 * (a + b) + 0.5 * (b - a) * gx[i];
      const double y = 0.5 * (c + d) + 0.5 * (d - c) * gy[j];
      sum += wx[i] * wy[j] * f(x, y);
    }
  return sum * 0.25 * (b - a) * (d - c);
}

// count strictly increasing nodes from first to last with random spacing ratios in
// [1, maxRatio] (graded grids).
inline Eigen::VectorXd randomNodes(std::mt19937& rng, double first, double last, int count,
                                   double maxRatio = 3.0) {
  std::uniform_real_distribution<double> u(1.0, maxRatio);
  Eigen::VectorXd h(count - 1);
  for (int k = 0; k < count - 1; ++k)
    h[k] = u(rng);
  h *= (last - first) / h.sum();
  Eigen::VectorXd x(count);
  x[0] = first;
  for (int k = 1; k < count; ++k)
    x[k] = x[k - 1] + h[k - 1];
  x[count - 1] = last;
  return x;
}

inline Eigen::VectorXd randomVector(std::mt19937& rng, int n, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  Eigen::VectorXd v(n);
  for (int k = 0; k < n; ++k)
    v[k] = u(rng);
  return v;
}

// Bilinear interpolant on the rectangle [x0, x1] x [y0, y1] with corner values
// f00 (x0, y0), f10 (x1, y0), f01 (x0, y1), f11 (x1, y1).
inline double bilinear(double x0, double x1, double y0, double y1, double f00, double f10,
                       double f01, double f11, double x, double y) {
  const double t = (x - x0) / (x1 - x0), u = (y - y0) / (y1 - y0);
  return (1 - t) * (1 - u) * f00 + t * (1 - u) * f10 + (1 - t) * u * f01 + t * u * f11;
}

// Calls f(i, j, cell, clip) for every cell (i, j) of an open grid with nodes (x, y)
// shifted by (dx, dy), where cell = {a, b, c, d} is the shifted cell [a, b] x [c, d] and
// clip = {lo, hi, ylo, yhi} its non-empty intersection with [xLo, xHi] x [yLo, yHi];
// cells outside are skipped.
template <class F>
void forEachClippedCell(const Eigen::VectorXd& x, const Eigen::VectorXd& y, double dx, double dy,
                        double xLo, double xHi, double yLo, double yHi, F&& f) {
  for (Eigen::Index j = 0; j + 1 < y.size(); ++j)
    for (Eigen::Index i = 0; i + 1 < x.size(); ++i) {
      const double a = x[i] + dx, b = x[i + 1] + dx, c = y[j] + dy, d = y[j + 1] + dy;
      const double lo = std::max(a, xLo), hi = std::min(b, xHi);
      const double ylo = std::max(c, yLo), yhi = std::min(d, yHi);
      if (!(hi > lo && yhi > ylo))
        continue;
      f(static_cast<int>(i), static_cast<int>(j), std::array<double, 4>{a, b, c, d},
        std::array<double, 4>{lo, hi, ylo, yhi});
    }
}

}  // namespace pistondyn::mapping::test
