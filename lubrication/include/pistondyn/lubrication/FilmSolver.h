#pragma once
// Film solver for the average Reynolds equation (Patir & Cheng) on a FilmGrid with the
// cavitation models of FilmProblem.h, and the loads, friction and diagnostics of FilmResult.
//
// Two solvers, chosen at run time (FilmSolverOptions::solver), same discrete problem, same
// residual definition (FilmProblem.h):
//  * ReferenceGaussSeidel - the thesis' point Gauss-Seidel with over-relaxation; projected onto
//    p >= p_cav for the Reynolds condition (Cryer's PSOR); for the mass-conserving model the
//    Elrod-Adams form of Ausas et al. (2009): a node is updated in pressure while full and in
//    fill fraction while cavitated. Sweeps follow the sliding direction.
//  * FastActiveSet - sparse direct solves inside a primal-dual active-set (semismooth Newton)
//    iteration on the complementarity problem: CHOLMOD (LDL', symbolic analysis kept between
//    calls) for the symmetric Reynolds problem, KLU (symbolic kept, refactorisation) for the
//    unsymmetric mass-conserving one. Warm-started from the previous active set it usually
//    needs one or two factorisations per call.
//
// The object keeps its workspace between calls: at a fixed grid size nothing is reallocated
// and the symbolic factorisation is reused while the grid's shape is unchanged. It holds no
// global state; use one solver object per thread. Not copyable (it owns SuiteSparse handles),
// movable.
//
// Errors: bad input throws std::invalid_argument naming the argument (gap not positive/finite,
// grid < 3x3, viscosity not positive, array sizes inconsistent with the grid, ...). A solve
// that does not reach the tolerance returns converged = false with the last finite iterate.

#include <memory>

#include "pistondyn/lubrication/FilmGrid.h"
#include "pistondyn/lubrication/FilmProblem.h"

namespace pistondyn::lubrication {

class FilmSolver {
 public:
  explicit FilmSolver(const FilmSolverOptions& options = FilmSolverOptions());
  ~FilmSolver();
  FilmSolver(FilmSolver&&) noexcept;
  FilmSolver& operator=(FilmSolver&&) noexcept;
  FilmSolver(const FilmSolver&) = delete;
  FilmSolver& operator=(const FilmSolver&) = delete;

  const FilmSolverOptions& getOptions() const;
  void setOptions(const FilmSolverOptions& options);  // throws on invalid options

  // Solves the film problem on the grid and writes everything into result (whose storage is
  // reused between calls).
  // Inputs:
  //   grid       film region (FilmGrid.h)
  //   problem    gap, gap rate, sliding velocity, viscosity, flow factors, cavitation model,
  //              boundary, JFO history, squeeze basis (units in FilmProblem.h)
  //   warmStart  state of a previous solve on the same grid (result.state), or nullptr
  // Outputs:
  //   result     pressure, fill fraction, loads, friction, h/sigma, minimum film, derivatives,
  //              iterations, residual, converged flag
  void solve(const FilmGrid& grid, const FilmProblem& problem, const FilmState* warmStart,
             FilmResult& result);

  // Convenience form returning a fresh result (allocates).
  FilmResult solve(const FilmGrid& grid, const FilmProblem& problem,
                   const FilmState* warmStart = nullptr);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pistondyn::lubrication
