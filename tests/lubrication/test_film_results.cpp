// Result fields and solver-object behaviour: closed-form loads and moments of a uniform
// pressure, Couette shear of a uniform gap, minimum film, warm starts, reuse of one solver
// object across grids and models, and independent solver objects on several threads.
#include <gtest/gtest.h>

#include <cmath>

#include "test_film_support.h"

namespace pistondyn::lubrication {
namespace {

// No motion, all edges at p0: p = p0 everywhere (any other field violates the maximum
// principle of the Reynolds operator). Load = (p0 - pref) A, first moments about (x0, y0) are
// (p0 - pref) A (xc - x0) and (p0 - pref) A (yc - y0) with the rectangle's centroid (xc, yc).
TEST(FilmResults, UniformPressureLoadAndMoments) {
  const FilmGrid g = FilmGrid::fromCoordinates(FilmGrid::clusteredCoordinates(11, 0.0, 0.03, 1.0),
                                               FilmGrid::clusteredCoordinates(9, 0.01, 0.04, 0.5));
  FilmProblem pr;
  pr.gap_m.setConstant(g.nodeCount(), 10e-6);
  pr.viscosity_Pas = 0.01;
  pr.cavitation = CavitationModel::Reynolds;
  const double p0 = 2e5;
  for (FilmEdge* e : {&pr.boundary.xMin, &pr.boundary.xMax, &pr.boundary.yMin, &pr.boundary.yMax})
    e->pressure_Pa = p0;
  pr.referencePressure_Pa = 0.5e5;
  pr.momentPoint_m = {0.005, 0.02};
  FilmSolver solver;
  const FilmResult r = solver.solve(g, pr);
  ASSERT_TRUE(r.converged);
  const double A = 0.03 * 0.03, q = p0 - pr.referencePressure_Pa;
  EXPECT_NEAR(r.load_N, q * A, 1e-9 * q * A);
  EXPECT_NEAR(r.firstMomentX_Nm, q * A * (0.015 - 0.005), 1e-9 * q * A * 0.01);
  EXPECT_NEAR(r.firstMomentY_Nm, q * A * (0.025 - 0.02), 1e-9 * q * A * 0.005);
  EXPECT_EQ(r.areaWeights_m2.size(), g.nodeCount());
  EXPECT_NEAR(r.areaWeights_m2.sum(), A, 1e-15);
  EXPECT_NEAR(r.shearOnSurface1.force_N().norm(), 0.0, 1e-12);
}

// Uniform gap, sliding along x, ambient edges: no pressure, pure Couette shear. The film drags
// surface 2 along +U with eta U / h and holds surface 1 back with -eta U / h; integrated over
// the area they are exact. The in-plane moment of the drag on surface 2 about (x0, y0) is
// -(yc - y0) F (force along +x acting at the centroid).
TEST(FilmResults, CouetteShearOfUniformGap) {
  const FilmGrid g = FilmGrid::uniform(9, 0.02, 7, 0.01);
  FilmProblem pr;
  const double h = 8e-6, eta = 0.012, U = 3.0;
  pr.gap_m.setConstant(g.nodeCount(), h);
  pr.viscosity_Pas = eta;
  pr.slidingVelocity_mps = {U, 0.0};
  pr.momentPoint_m = {0.0, 0.0};
  FilmSolver solver;
  const FilmResult r = solver.solve(g, pr);
  ASSERT_TRUE(r.converged);
  const double F = eta * U / h * 0.02 * 0.01;
  EXPECT_NEAR(r.pressure_Pa().abs().maxCoeff(), 0.0, 1e-9);
  EXPECT_NEAR(r.shearOnSurface2.couetteForce_N.x(), F, 1e-12 * F);
  EXPECT_NEAR(r.shearOnSurface1.couetteForce_N.x(), -F, 1e-12 * F);
  EXPECT_NEAR(r.shearOnSurface2.couetteForce_N.y(), 0.0, 1e-12 * F);
  EXPECT_NEAR(r.shearOnSurface2.couetteMoment_Nm, -0.005 * F, 1e-12 * F);
  EXPECT_NEAR(r.shearOnSurface2.poiseuilleForce_N.norm(), 0.0, 1e-9 * F);
}

// Minimum film thickness and its location; h/sigma is empty for smooth surfaces.
TEST(FilmResults, MinimumFilmThicknessAndLocation) {
  const test::SkirtPatch sp;
  const FilmGrid g = sp.grid(14, 12);
  FilmProblem pr = sp.problem(g, CavitationModel::Reynolds);
  pr.gap_m[g.nodeIndex(5, 7)] = 0.5e-6;
  FilmSolver solver;
  const FilmResult r = solver.solve(g, pr);
  EXPECT_EQ(r.minFilmThickness_m, 0.5e-6);
  EXPECT_EQ(r.minFilmNode, g.nodeIndex(5, 7));
  EXPECT_EQ(r.minFilmLocation_m, Eigen::Vector2d(g.x_m()[5], g.y_m()[7]));
  EXPECT_EQ(r.gapOverSigma.size(), 0);
}

// Re-solving the same problem from its own state costs nothing: the reference solver starts
// below the tolerance (0 sweeps) and the fast solver needs one check without a factorisation.
TEST(FilmResults, WarmStartFromOwnStateIsFree) {
  const test::SkirtPatch sp;
  const FilmGrid g = sp.grid(30, 24);
  for (CavitationModel model : {CavitationModel::Reynolds, CavitationModel::MassConserving}) {
    FilmProblem pr = sp.problem(g, model);
    pr.timeStep_s = 1e-4;
    for (FilmSolverType type :
         {FilmSolverType::FastActiveSet, FilmSolverType::ReferenceGaussSeidel}) {
      FilmSolver solver(test::tightOptions(type, 1e-10));
      const FilmResult first = solver.solve(g, pr);
      ASSERT_TRUE(first.converged);
      const FilmState stored = first.state;  // what the caller keeps between steps
      const FilmResult again = solver.solve(g, pr, &stored);
      ASSERT_TRUE(again.converged);
      if (type == FilmSolverType::ReferenceGaussSeidel) {
        EXPECT_EQ(again.iterations, 0);
      } else {
        EXPECT_EQ(again.activeSetIterations, 1);
        EXPECT_EQ(again.factorisations, 0);
      }
      EXPECT_NEAR(again.load_N, first.load_N, 1e-9 * std::abs(first.load_N));
    }
  }
}

// One solver object serves different grid sizes, periodicities and models in turn (its
// workspace and symbolic analysis follow the grid), giving what fresh objects give.
TEST(FilmResults, SolverObjectFollowsGridAndModelChanges) {
  const test::SkirtPatch sp;
  const test::JournalBearing jb;
  const FilmGrid g1 = sp.grid(20, 16);
  const FilmGrid g2 = jb.grid(36, FilmGrid::clusteredCoordinates(9, 0.0, 0.02, 0.0));
  FilmSolver shared;
  for (int round = 0; round < 2; ++round) {
    for (CavitationModel m :
         {CavitationModel::Reynolds, CavitationModel::MassConserving, CavitationModel::None}) {
      FilmProblem p1 = sp.problem(g1, m);
      p1.timeStep_s = 1e-4;
      FilmProblem p2 = jb.problem(g2, m);
      p2.timeStep_s = 1e-4;
      for (auto [g, p] : {std::pair{&g1, &p1}, std::pair{&g2, &p2}}) {
        FilmSolver fresh;
        const FilmResult a = shared.solve(*g, *p);
        const FilmResult b = fresh.solve(*g, *p);
        ASSERT_TRUE(a.converged && b.converged);
        EXPECT_LT((a.pressure_Pa() - b.pressure_Pa()).abs().maxCoeff(),
                  1e-7 * b.pressure_Pa().abs().maxCoeff());
      }
    }
  }
}

// Independent solver objects on several threads give exactly the answers of the same call
// sequence run serially (no shared mutable state; the solver is deterministic).
TEST(FilmResults, IndependentSolversOnThreads) {
  test::expectSameLoadsOnThreads(FilmSolverOptions{}, 30, 24);
}

// Reynolds-model partial flooding: dry nodes ahead of the meniscus carry no oil (fill 0), hence
// no Couette shear.
TEST(FilmResults, DryInletNodesCarryNoShear) {
  const test::InclinedSlider s;
  const FilmGrid g = s.grid(101);
  FilmProblem pr = s.problem(g);
  pr.cavitation = CavitationModel::Reynolds;
  pr.boundary.yMin.supplyFilm_m = 3.5e-6;  // flooded where h <= 7 um, i.e. y >= 0.667 B
  FilmSolver solver;
  const FilmResult r = solver.solve(g, pr);
  ASSERT_TRUE(r.converged);
  int dry = 0;
  for (int j = 0; j < g.ny(); ++j) {
    const int k = g.nodeIndex(0, j);
    const bool expectDry = pr.gap_m[k] > 7e-6;
    EXPECT_EQ(r.fillFraction()[k], expectDry ? 0.0 : 1.0) << j;
    if (expectDry) {
      EXPECT_EQ(r.shearOnSurface1.couetteY_Pa[k], 0.0);
      EXPECT_EQ(r.pressure_Pa()[k], 0.0);
      ++dry;
    }
  }
  EXPECT_GT(dry, 50);
}

}  // namespace
}  // namespace pistondyn::lubrication
