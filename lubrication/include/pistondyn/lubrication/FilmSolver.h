#pragma once
/// \file
/// Film solver for the average Reynolds equation (Patir & Cheng) on a FilmGrid with the
/// cavitation models of FilmProblem.h, and the loads, friction and diagnostics of FilmResult.
///
/// Two solvers, chosen at run time (FilmSolverOptions::solver), same discrete problem, same
/// residual definition (FilmProblem.h):
///  * ReferenceGaussSeidel - the thesis' point Gauss-Seidel with over-relaxation; projected onto
///    p >= p_cav for the Reynolds condition (Cryer's PSOR); for the mass-conserving model the
///    Elrod-Adams form of Ausas et al. (2009): a node is updated in pressure while full and in
///    fill fraction while cavitated. Sweeps follow the sliding direction.
///  * FastActiveSet - a primal-dual active-set (semismooth Newton) iteration on the
///    complementarity problem; for a fixed split into full and cavitated nodes the balance is
///    linear and one Newton step solves it. The linear systems are solved by Krylov iterations
///    with preconditioners kept between calls while the matrix drifts:
///     - symmetric Reynolds / full-Sommerfeld matrix: PCG, preconditioned (FilmSolverOptions::
///       linearSolver, FilmProblem.h) either by a geometric multigrid V-cycle on the grid
///       (Galerkin coarse levels, red-black Gauss-Seidel, cavitated and prescribed nodes masked;
///       cost linear in the node count, iteration counts independent of it) or by a lagged
///       CHOLMOD factorisation (simplicial LDL', rescaled by the drift of the diagonal);
///     - unsymmetric mass-conserving matrix: GMRES, preconditioned either by the same multigrid
///       on the pressure block followed by one upwind sweep for the fill fractions
///       (block-triangular) or by a lagged KLU factorisation.
///    The default picks multigrid from kMultigridMinNodes nodes up, where it is the faster one.
///    The lagged part (multigrid coarse levels, factorisation) is refreshed when a Krylov solve
///    costs more than the running average since the last refresh; while the active set still
///    moves, solves are inexact. Warm-started in an engine simulation a call typically takes a
///    few active-set steps of a few Krylov iterations each (measured counts: BENCHMARKS.md).
///    If the iteration does not settle, the reference solver finishes from its iterate
///    (FilmSolverOptions::fallbackToReference, reported in FilmResult::usedFallback).
///  Both enforce p >= p_cav, 0 <= theta <= 1 and p (1 - theta) = 0 exactly; they differ only in
///  how the balance residual is driven below the tolerance.
///
/// The object keeps its workspace between calls: at a fixed grid size a call allocates nothing
/// (checked with a malloc counter, tests/lubrication/test_film_allocation.cpp) and the symbolic
/// analyses and multigrid levels are reused while the grid's shape is unchanged. It holds no
/// global state and uses no SuiteSparse component with global state (orderings by AMD, not
/// METIS); use one solver object per thread (a FlowFactorModel may be shared: it is
/// immutable). Results are deterministic for a given sequence of calls. Not copyable (it owns
/// SuiteSparse handles), movable. The squeeze derivatives of FilmProblem::squeezeBasis cost one
/// extra linear solve per basis column with the final active set (reference solver: with the fast
/// solver's machinery).
///
/// Errors: bad input throws std::invalid_argument naming the argument (gap not positive/finite,
/// grid < 3x3, viscosity not positive, array sizes inconsistent with the grid, ...). A solve
/// that does not reach the tolerance returns converged = false with the last finite iterate.

#include <memory>

#include "pistondyn/lubrication/FilmGrid.h"
#include "pistondyn/lubrication/FilmProblem.h"

namespace pistondyn::lubrication {

/// The film solver of the documentation of FilmSolver.h: reference or fast solver behind one call,
/// with a workspace kept between calls (one object per thread).
class FilmSolver {
 public:
  /// A solver with the given options (checked; throws std::invalid_argument).
  explicit FilmSolver(const FilmSolverOptions& options = FilmSolverOptions());
  ~FilmSolver();
  FilmSolver(FilmSolver&&) noexcept;             ///< moves the workspace
  FilmSolver& operator=(FilmSolver&&) noexcept;  ///< moves the workspace
  FilmSolver(const FilmSolver&) = delete;
  FilmSolver& operator=(const FilmSolver&) = delete;

  const FilmSolverOptions& getOptions() const;        ///< the options in use
  void setOptions(const FilmSolverOptions& options);  ///< throws on invalid options

  /// Solves the film problem on the grid and writes everything into result (whose storage is
  /// reused between calls).
  /// Inputs:
  ///   grid       film region (FilmGrid.h)
  ///   problem    gap, gap rate, sliding velocity, viscosity, flow factors, cavitation model,
  ///              boundary, JFO history, squeeze basis (units in FilmProblem.h)
  ///   warmStart  state of a previous solve on the same grid (result.state), or nullptr
  /// Outputs:
  ///   result     pressure, fill fraction, loads, friction, h/sigma, minimum film, derivatives,
  ///              iterations, residual, converged flag
  void solve(const FilmGrid& grid, const FilmProblem& problem, const FilmState* warmStart,
             FilmResult& result);

  /// Convenience form returning a fresh result (allocates).
  FilmResult solve(const FilmGrid& grid, const FilmProblem& problem,
                   const FilmState* warmStart = nullptr);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pistondyn::lubrication
