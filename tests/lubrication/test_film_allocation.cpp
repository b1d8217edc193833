// CONVENTIONS.md: a solver that runs every force evaluation allocates nothing after the first
// call at a given grid size. Reference: the allocation counter of tests/support, which
// interposes glibc's malloc, calloc and realloc.
#include <gtest/gtest.h>

#include "AllocationCounter.h"
#include "test_film_support.h"

namespace pistondyn::lubrication {
namespace {

// Warm calls on a drifting skirt problem (the gap rate changes every call, so the active set,
// the lagged preconditioners and their refresh logic all move), with squeeze derivatives.
long allocationsOfWarmCalls(FilmSolverOptions options, CavitationModel model,
                            bool gapColumns = false) {
  const test::SkirtPatch sp;
  const test::GaussianRoughFactors rough(0.8e-6);
  const FilmGrid g = sp.grid(64, 48);
  FilmProblem pr = sp.problem(g, model);
  pr.flowFactors = &rough;
  pr.timeStep_s = 1e-4;
  pr.history.last.fillFraction.setOnes(g.nodeCount());
  pr.squeezeBasis = sp.squeezeBasis(g);
  if (gapColumns) {  // the elastic skirt's columns (FilmProblem::gapBasis, gapRateBasis)
    pr.gapBasis = Eigen::MatrixXd::Ones(g.nodeCount(), 3);
    pr.gapRateBasis = pr.gapBasis / pr.timeStep_s;
  }
  options.tolerance = 1e-8;
  FilmSolver solver(options);
  FilmResult r;
  const Eigen::ArrayXd rate0 = pr.gapRate_mps;
  long count = 0;
  for (int call = 0; call < 12; ++call) {
    pr.gapRate_mps = rate0 * (1.0 + 0.2 * std::sin(0.7 * call));  // in place: same size
    const auto solve = [&] { solver.solve(g, pr, call > 0 ? &r.state : nullptr, r); };
    if (call >= 2)  // the first calls size the workspaces
      count += pistondyn::test::allocationsDuring(solve);
    else
      solve();
    EXPECT_TRUE(r.converged) << call;
  }
  return count;
}

TEST(FilmAllocation, CounterSeesTheFirstCall) {  // the interposition works
  const test::SkirtPatch sp;
  const FilmGrid g = sp.grid(20, 16);
  const FilmProblem pr = sp.problem(g, CavitationModel::Reynolds);
  FilmSolver solver;
  FilmResult r;
  EXPECT_GT(pistondyn::test::allocationsDuring([&] { solver.solve(g, pr, nullptr, r); }), 0);
}

TEST(FilmAllocation, WarmCallsAllocateNothing) {
  FilmSolverOptions mg, direct, reference;
  mg.linearSolver = FastLinearSolver::Multigrid;
  direct.linearSolver = FastLinearSolver::SparseDirect;
  reference.solver = FilmSolverType::ReferenceGaussSeidel;
  EXPECT_EQ(allocationsOfWarmCalls(mg, CavitationModel::Reynolds), 0);
  EXPECT_EQ(allocationsOfWarmCalls(mg, CavitationModel::None), 0);
  EXPECT_EQ(allocationsOfWarmCalls(direct, CavitationModel::Reynolds), 0);
  EXPECT_EQ(allocationsOfWarmCalls(mg, CavitationModel::MassConserving), 0);
  EXPECT_EQ(allocationsOfWarmCalls(direct, CavitationModel::MassConserving), 0);
  EXPECT_EQ(allocationsOfWarmCalls(reference, CavitationModel::Reynolds), 0);
  EXPECT_EQ(allocationsOfWarmCalls(mg, CavitationModel::MassConserving, true), 0);
  EXPECT_EQ(allocationsOfWarmCalls(direct, CavitationModel::Reynolds, true), 0);
}

}  // namespace
}  // namespace pistondyn::lubrication
