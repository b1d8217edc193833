// Bad input is rejected with std::invalid_argument naming the argument; a solve that cannot
// reach the tolerance says so (converged = false) and still returns finite fields.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "ExpectInvalidArgument.h"
#include "test_film_support.h"

namespace pistondyn::lubrication {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

using pistondyn::test::expectInvalidArgument;

struct BadInputCase {
  test::SkirtPatch sp;
  FilmGrid grid = sp.grid(12, 10);
  FilmProblem problem = sp.problem(grid, CavitationModel::Reynolds);
  FilmSolver solver;
  void solve(const FilmState* warm = nullptr) { solver.solve(grid, problem, warm); }
};

TEST(FilmBadInput, NonPositiveOrNaNGap) {
  for (double bad : {0.0, -2e-6, kNaN, std::numeric_limits<double>::infinity()}) {
    BadInputCase s;
    s.problem.gap_m[17] = bad;
    expectInvalidArgument([&] { s.solve(); }, {"FilmSolver::solve", "gap h[17]", "positive"});
  }
}

// A gap floor must be finite and >= 0, and the film gaps of a floored problem lie above it.
TEST(FilmBadInput, GapFloorNegativeAboveAGapOrWithNodalMeans) {
  for (double bad : {-1e-9, kNaN, std::numeric_limits<double>::infinity()}) {
    BadInputCase s;
    s.problem.gapFloor_m = bad;
    expectInvalidArgument([&] { s.solve(); }, {"FilmSolver::solve", "problem.gapFloor_m", ">= 0"});
  }
  BadInputCase s;
  s.problem.faces = FaceValues::LinearGap;
  s.problem.gapFloor_m = s.problem.gap_m[23];
  expectInvalidArgument([&] { s.solve(); }, {"gap h[", "above problem.gapFloor_m"});
  // The nodal means cannot honour a floor: said, not ignored.
  BadInputCase m;
  m.problem.gapFloor_m = 0.5 * m.problem.gap_m.minCoeff();
  expectInvalidArgument([&] { m.solve(); }, {"problem.gapFloor_m", "FaceValues::LinearGap"});
}

// Mass-conserving model with an open edge below p_cav (gauge edges against an absolute p_cav):
// rejected up front instead of running the solvers' whole budget into non-convergence. The
// Reynolds model is well posed there (the edge is simply a fixed pressure) and is accepted.
TEST(FilmBadInput, MassConservingEdgeBelowCavitationPressure) {
  BadInputCase s;
  s.problem.cavitation = CavitationModel::MassConserving;
  s.problem.cavitationPressure_Pa = 1e5;
  s.problem.boundary.yMin.pressure_Pa = s.problem.boundary.yMax.pressure_Pa = 1e5;
  s.problem.boundary.xMin.pressure_Pa = s.problem.boundary.xMax.pressure_Pa = 1e5;
  s.problem.boundary.xMax.pressure_Pa = 0.0;
  expectInvalidArgument([&] { s.solve(); },
                        {"problem.boundary.xMax.pressure_Pa", "cavitationPressure_Pa", "below"});
  s.problem.boundary.xMax.pressure_Pa = 1e5;
  EXPECT_NO_THROW(s.solve());
  s.problem.cavitation = CavitationModel::Reynolds;
  s.problem.boundary.yMin.pressure_Pa = 0.0;
  EXPECT_NO_THROW(s.solve());
}

TEST(FilmBadInput, GridSmallerThanThreeByThree) {
  expectInvalidArgument([] { FilmGrid::uniform(2, 0.01, 5, 0.01); }, {"nx = 2", ">= 3"});
  expectInvalidArgument([] { FilmGrid::uniform(5, 0.01, 2, 0.01); }, {"ny = 2", ">= 3"});
  expectInvalidArgument(
      [] { FilmGrid::fromCoordinates(Eigen::Vector3d(0, 1, 2), Eigen::Vector2d(0, 1)); },
      {"y_m", "at least 3"});
  expectInvalidArgument(
      [] { FilmGrid::fromCoordinates(Eigen::Vector3d(0, 2, 1), Eigen::Vector3d(0, 1, 2)); },
      {"x_m", "strictly increasing"});
  expectInvalidArgument([] { FilmGrid::uniform(5, -0.01, 5, 0.01); }, {"lengthX_m"});
  expectInvalidArgument(
      [] {
        FilmGrid::fromCoordinates(Eigen::Vector3d(0, 1, 2), Eigen::Vector3d(0, 1, 2), true, 2.0);
      },
      {"periodX_m"});
}

TEST(FilmBadInput, NegativeOrZeroViscosity) {
  {
    BadInputCase s;
    s.problem.viscosity_Pas = -0.01;
    expectInvalidArgument([&] { s.solve(); }, {"viscosity", "viscosity_Pas", "positive"});
  }
  {
    BadInputCase s;
    s.problem.viscosity_Pas = 0.0;
    expectInvalidArgument([&] { s.solve(); }, {"viscosity_Pas"});
  }
  {
    BadInputCase s;
    s.problem.viscosityPerNode_Pas.setConstant(s.grid.nodeCount(), 0.01);
    s.problem.viscosityPerNode_Pas[3] = -1.0;
    expectInvalidArgument([&] { s.solve(); }, {"viscosityPerNode_Pas[3]"});
  }
}

TEST(FilmBadInput, InconsistentArraySizes) {
  const int n = 12 * 10;
  {
    BadInputCase s;
    s.problem.gap_m.conservativeResize(n - 1);
    expectInvalidArgument([&] { s.solve(); }, {"problem.gap_m", "119", "120"});
  }
  {
    BadInputCase s;
    s.problem.gapRate_mps.resize(7);
    expectInvalidArgument([&] { s.solve(); }, {"problem.gapRate_mps"});
  }
  {
    BadInputCase s;
    s.problem.viscosityPerNode_Pas.setConstant(n + 1, 0.01);
    expectInvalidArgument([&] { s.solve(); }, {"problem.viscosityPerNode_Pas"});
  }
  {
    BadInputCase s;
    s.problem.cavitation = CavitationModel::MassConserving;
    s.problem.history.last.fillFraction.setOnes(5);
    expectInvalidArgument([&] { s.solve(); }, {"problem.history.last.fillFraction"});
  }
  {
    BadInputCase s;
    s.problem.squeezeBasis.setOnes(n - 3, 2);
    expectInvalidArgument([&] { s.solve(); }, {"problem.squeezeBasis"});
  }
  {
    BadInputCase s;
    s.problem.boundary.yMin.supplyFilmPerNode_m.setConstant(4, 1e-6);
    expectInvalidArgument([&] { s.solve(); }, {"problem.boundary.yMin.supplyFilmPerNode_m"});
  }
  {
    BadInputCase s;
    FilmState warm;
    warm.pressure_Pa.setZero(n + 4);
    expectInvalidArgument([&] { s.solve(&warm); }, {"warmStart->pressure_Pa"});
  }
}

TEST(FilmBadInput, OtherInvalidArguments) {
  {
    BadInputCase s;
    s.problem.slidingVelocity_mps.y() = kNaN;
    expectInvalidArgument([&] { s.solve(); }, {"slidingVelocity_mps"});
  }
  {
    BadInputCase s;
    s.problem.gapRate_mps[4] = kNaN;
    expectInvalidArgument([&] { s.solve(); }, {"gapRate_mps[4]"});
  }
  {
    BadInputCase s;
    s.problem.timeStep_s = 0.0;
    expectInvalidArgument([&] { s.solve(); }, {"timeStep_s"});
  }
  {
    BadInputCase s;
    s.problem.cavitation = CavitationModel::MassConserving;
    s.problem.history.last.fillFraction.setConstant(s.grid.nodeCount(), 1.2);
    expectInvalidArgument([&] { s.solve(); }, {"history.last.fillFraction[0]", "[0, 1]"});
  }
  {
    BadInputCase s;
    s.problem.boundary.yMax.supplyFilm_m = -1e-6;
    expectInvalidArgument([&] { s.solve(); }, {"yMax.supplyFilm_m"});
  }
  {
    BadInputCase s;
    s.problem.boundary.xMin.pressure_Pa = kNaN;
    expectInvalidArgument([&] { s.solve(); }, {"xMin.pressure_Pa"});
  }
  FilmSolverOptions o;
  o.tolerance = 0.0;
  expectInvalidArgument([&] { FilmSolver solver(o); }, {"tolerance"});
  o = FilmSolverOptions();
  o.overRelaxation = 2.0;
  expectInvalidArgument([&] { FilmSolver solver(o); }, {"overRelaxation"});
}

// A flow-factor model that misbehaves is caught before its numbers enter the matrices.
class BrokenFactors final : public FlowFactorModel {
 public:
  NodeFlowFactors calcFactors(double h) const override {
    NodeFlowFactors f;
    f.expectedGap_m = h;
    f.phiPressureSliding = -1.0;
    return f;
  }
  double compositeSigma_m() const override { return 1e-6; }
};

TEST(FilmBadInput, BrokenFlowFactorModel) {
  BadInputCase s;
  const BrokenFactors broken;
  s.problem.flowFactors = &broken;
  expectInvalidArgument([&] { s.solve(); }, {"problem.flowFactors"});
}

// Non-convergence is reported, not hidden: too few sweeps (reference) or active-set iterations
// without fallback (fast) give converged = false, the residual above the tolerance, finite
// fields and the constraints kept (p >= p_cav).
TEST(FilmBadInput, NonConvergenceIsReportedWithFiniteFields) {
  BadInputCase s;
  FilmSolverOptions o;
  o.solver = FilmSolverType::ReferenceGaussSeidel;
  o.maxSweeps = 3;
  s.solver.setOptions(o);
  FilmResult r = s.solver.solve(s.grid, s.problem);
  EXPECT_FALSE(r.converged);
  EXPECT_GT(r.residual, o.tolerance);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_TRUE(r.pressure_Pa().allFinite());
  EXPECT_GE(r.pressure_Pa().minCoeff(), s.problem.cavitationPressure_Pa);
  EXPECT_TRUE(std::isfinite(r.load_N));

  o = FilmSolverOptions();
  o.maxActiveSetIterations = 1;
  o.fallbackToReference = false;
  s.solver.setOptions(o);
  r = s.solver.solve(s.grid, s.problem);  // cold start: the active set must change at least once
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.usedFallback);
  EXPECT_TRUE(r.pressure_Pa().allFinite());
  EXPECT_TRUE(std::isfinite(r.load_N));

  o.fallbackToReference = true;  // the default: the reference solver finishes the job
  s.solver.setOptions(o);
  r = s.solver.solve(s.grid, s.problem);
  EXPECT_TRUE(r.converged);
  EXPECT_TRUE(r.usedFallback);
}

}  // namespace
}  // namespace pistondyn::lubrication
