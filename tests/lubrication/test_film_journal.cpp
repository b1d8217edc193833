// Journal bearings against the long-bearing (full Sommerfeld) and short-bearing (Ocvirk)
// closed forms (test_film_support.h). The bearing is the x-periodic case of the film grid.
#include <gtest/gtest.h>

#include <cmath>

#include "test_film_support.h"

namespace pistondyn::lubrication {
namespace {

using test::JournalBearing;
using test::kPi;

// Axial coordinates 0..L: two end zones of length 2D with a fixed clustered spacing (the end
// leakage is resolved identically whatever L is) and a uniform middle part.
Eigen::VectorXd axialNodes(double L, double D) {
  const Eigen::VectorXd end = FilmGrid::clusteredCoordinates(17, 0.0, 4.0 * D, 1.2);
  // Keep only the half of the clustered zone that is fine at y = 0 (0 .. 2D).
  std::vector<double> y;
  for (int k = 0; k < end.size() && end[k] <= 2.0 * D + 1e-15; ++k)
    y.push_back(end[k]);
  const double a = y.back(), b = L - a;
  const int mid = static_cast<int>(std::ceil((b - a) / (0.5 * D)));
  for (int k = 1; k < mid; ++k)
    y.push_back(a + (b - a) * k / mid);
  const int nEnd = static_cast<int>(y.size()) - (mid - 1);
  for (int k = nEnd - 1; k >= 0; --k)
    y.push_back(L - y[k]);
  return Eigen::Map<Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size()));
}

// Long bearing, L/D = 20, full Sommerfeld (no cavitation). Far from the ends the axial pressure
// gradient vanishes (the end effect decays like exp(-|y - y_end| / R)), so the load per unit
// length of the central cross-section must equal the Sommerfeld value; the 1 % acceptance is
// the issue's. The total load of a finite bearing is L W' minus a fixed end-leakage deficit at
// each end; that deficit cancels between L/D = 20 and 40, so (W40 - W20) / (L40 - L20) must
// equal W' too.
TEST(FilmJournalBearing, LongBearingMatchesFullSommerfeld) {
  const JournalBearing jb;
  const double D = 2.0 * jb.radius_m;
  const int nx = 160;
  FilmSolver solver(test::tightOptions(FilmSolverType::FastActiveSet, 1e-10));
  double totalLoad[2] = {0.0, 0.0}, length[2] = {20.0 * D, 40.0 * D};
  for (int c = 0; c < 2; ++c) {
    const FilmGrid g = jb.grid(nx, axialNodes(length[c], D));
    const FilmResult r = solver.solve(g, jb.problem(g, CavitationModel::None));
    ASSERT_TRUE(r.converged);
    const Eigen::Vector2d W = jb.loadComponents(g, r.pressure_Pa());
    totalLoad[c] = W.norm();
    if (c == 0) {
      // Central cross-section: trapezoid (spectral for periodic functions) around the bush.
      const int jm = g.ny() / 2;
      Eigen::Vector2d strip = Eigen::Vector2d::Zero();
      for (int i = 0; i < g.nx(); ++i) {
        const double t = g.x_m()[i] / jb.radius_m;
        strip += g.xWeights_m()[i] * r.pressure_Pa()[g.nodeIndex(i, jm)] *
                 Eigen::Vector2d(std::cos(t), std::sin(t));
      }
      const double err = strip.norm() / jb.sommerfeldLoadPerLength() - 1.0;
      test::reportFigure("longBearing.midplaneLoadRelError", err);
      test::reportFigure("longBearing.totalLoadOverLWprime",
                         W.norm() / (length[c] * jb.sommerfeldLoadPerLength()));
      EXPECT_LT(std::abs(err), 0.01);
      // Full Sommerfeld: load perpendicular to the line of centres.
      EXPECT_NEAR(std::atan2(std::abs(strip.y()), std::abs(strip.x())), 0.5 * kPi, 1e-3);
    }
  }
  const double perLength = (totalLoad[1] - totalLoad[0]) / (length[1] - length[0]);
  const double err = perLength / jb.sommerfeldLoadPerLength() - 1.0;
  test::reportFigure("longBearing.loadPerLengthFromTwoLengthsRelError", err);
  EXPECT_LT(std::abs(err), 0.01);
}

// Short bearing, L/D = 0.05, Reynolds cavitation (p >= 0): Ocvirk's short-bearing load and
// attitude angle (half-Sommerfeld). The 5 % acceptance is the issue's; the remaining difference
// is the short-bearing approximation itself (O((L/D)^2)) and the Reynolds vs half-Sommerfeld
// rupture condition.
TEST(FilmJournalBearing, ShortBearingMatchesOcvirk) {
  const JournalBearing jb;
  const double L = 0.05 * 2.0 * jb.radius_m;
  const FilmGrid g = jb.grid(240, FilmGrid::clusteredCoordinates(21, 0.0, L, 0.0));
  FilmSolver solver(test::tightOptions(FilmSolverType::FastActiveSet, 1e-10));
  const FilmResult r = solver.solve(g, jb.problem(g, CavitationModel::Reynolds));
  ASSERT_TRUE(r.converged);
  EXPECT_GE(r.pressure_Pa().minCoeff(), 0.0);
  const Eigen::Vector2d W = jb.loadComponents(g, r.pressure_Pa());
  const double err = W.norm() / jb.ocvirkLoad(L) - 1.0;
  test::reportFigure("shortBearing.loadRelError", err);
  EXPECT_LT(std::abs(err), 0.05);
  // Attitude angle between the load and the line of centres.
  const double attitude = std::atan2(std::abs(W.y()), std::abs(W.x()));
  test::reportFigure("shortBearing.attitudeRelError", attitude / jb.ocvirkAttitude_rad() - 1.0);
  EXPECT_NEAR(attitude / jb.ocvirkAttitude_rad(), 1.0, 0.05);
}

}  // namespace
}  // namespace pistondyn::lubrication
