// CONVENTIONS.md: a solver that runs every force evaluation allocates nothing after the first
// call at a given grid size. Reference: this executable interposes glibc's malloc, calloc and
// realloc (Eigen allocates with malloc, operator new ends there too) and counts the calls made
// while a flag is set, as tests/mapping/test_mapping_allocation.cpp does.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>

#include "test_film_support.h"

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void __libc_free(void*);

void* malloc(std::size_t size) {
  if (counting.load())
    ++allocations;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  if (counting.load())
    ++allocations;
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  if (counting.load())
    ++allocations;
  return __libc_realloc(p, size);
}
void free(void* p) {
  __libc_free(p);
}
}

namespace pistondyn::lubrication {
namespace {

// Warm calls on a drifting skirt problem (the gap rate changes every call, so the active set,
// the lagged preconditioners and their refresh logic all move), with squeeze derivatives.
long allocationsOfWarmCalls(FilmSolverOptions options, CavitationModel model) {
  const test::SkirtPatch sp;
  const test::GaussianRoughFactors rough(0.8e-6);
  const FilmGrid g = sp.grid(64, 48);
  FilmProblem pr = sp.problem(g, model);
  pr.flowFactors = &rough;
  pr.timeStep_s = 1e-4;
  pr.previousFillFraction.setOnes(g.nodeCount());
  pr.squeezeBasis = sp.squeezeBasis(g);
  options.tolerance = 1e-8;
  FilmSolver solver(options);
  FilmResult r;
  const Eigen::ArrayXd rate0 = pr.gapRate_mps;
  long count = 0;
  for (int call = 0; call < 12; ++call) {
    pr.gapRate_mps = rate0 * (1.0 + 0.2 * std::sin(0.7 * call));  // in place: same size
    if (call >= 2) {  // the first calls size the workspaces
      allocations = 0;
      counting = true;
    }
    solver.solve(g, pr, call > 0 ? &r.state : nullptr, r);
    counting = false;
    if (call >= 2)
      count += allocations.load();
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
  allocations = 0;
  counting = true;
  solver.solve(g, pr, nullptr, r);
  counting = false;
  EXPECT_GT(allocations.load(), 0);
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
}

}  // namespace
}  // namespace pistondyn::lubrication
