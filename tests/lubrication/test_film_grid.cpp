// FilmGrid weights: the nodal area and first-moment weights integrate the bilinear interpolant
// exactly (closed-form integrals of bilinear functions over the rectangle).
#include <gtest/gtest.h>

#include <cmath>

#include "test_film_support.h"

namespace pistondyn::lubrication {
namespace {

// f(x, y) = a + b x + c y + d x y is its own bilinear interpolant on any grid, so
// sum_k w_k f_k must equal the exact integral over [x0, x1] x [y0, y1], and the first-moment
// weights must give int x f dA and int y f dA exactly.
TEST(FilmGrid, WeightsIntegrateBilinearFieldsExactly) {
  const Eigen::VectorXd x = FilmGrid::clusteredCoordinates(9, 0.01, 0.05, 1.3);
  const Eigen::VectorXd y = FilmGrid::clusteredCoordinates(7, -0.02, 0.01, 0.8);
  const FilmGrid g = FilmGrid::fromCoordinates(x, y);
  const double a = 3.0, b = -40.0, c = 25.0, d = 900.0;
  Eigen::ArrayXd f(g.nodeCount());
  for (int j = 0; j < g.ny(); ++j)
    for (int i = 0; i < g.nx(); ++i)
      f[g.nodeIndex(i, j)] = a + b * x[i] + c * y[j] + d * x[i] * y[j];
  const double x0 = 0.01, x1 = 0.05, y0 = -0.02, y1 = 0.01;
  // Antiderivatives of the monomials.
  auto I = [](double lo, double hi, int power) {
    return (std::pow(hi, power + 1) - std::pow(lo, power + 1)) / (power + 1);
  };
  const double exact = a * I(x0, x1, 0) * I(y0, y1, 0) + b * I(x0, x1, 1) * I(y0, y1, 0) +
                       c * I(x0, x1, 0) * I(y0, y1, 1) + d * I(x0, x1, 1) * I(y0, y1, 1);
  const double exactX = a * I(x0, x1, 1) * I(y0, y1, 0) + b * I(x0, x1, 2) * I(y0, y1, 0) +
                        c * I(x0, x1, 1) * I(y0, y1, 1) + d * I(x0, x1, 2) * I(y0, y1, 1);
  const double exactY = a * I(x0, x1, 0) * I(y0, y1, 1) + b * I(x0, x1, 1) * I(y0, y1, 1) +
                        c * I(x0, x1, 0) * I(y0, y1, 2) + d * I(x0, x1, 1) * I(y0, y1, 2);
  EXPECT_NEAR((g.areaWeights_m2() * f).sum(), exact, 1e-14 * std::abs(exact));
  EXPECT_NEAR((g.xFirstMomentWeights_m3() * f).sum(), exactX, 1e-14 * std::abs(exactX));
  EXPECT_NEAR((g.yFirstMomentWeights_m3() * f).sum(), exactY, 1e-14 * std::abs(exactY));
  EXPECT_NEAR(g.area_m2(), (x1 - x0) * (y1 - y0), 1e-18);
}

// Periodic x: the closing cell counts once, the total area is period x length, and the spacing
// from the last node wraps to the first.
TEST(FilmGrid, PeriodicGridClosesTheCircle) {
  const double R = 0.04, L = 0.03;
  const FilmGrid g = FilmGrid::uniform(50, 2.0 * test::kPi * R, 6, L, true);
  EXPECT_NEAR(g.area_m2(), 2.0 * test::kPi * R * L, 1e-15);
  EXPECT_NEAR(g.dxEast_m(49), 2.0 * test::kPi * R / 50, 1e-15);
  EXPECT_NEAR(g.xWeights_m()[0], g.xWeights_m()[25], 1e-15);  // rounding of x0 + period - x49
  // int x dA over [0, 2 pi R) x [0, L] = (2 pi R)^2 / 2 * L
  EXPECT_NEAR(g.xFirstMomentWeights_m3().sum(), 0.5 * std::pow(2.0 * test::kPi * R, 2) * L, 1e-15);
}

}  // namespace
}  // namespace pistondyn::lubrication
