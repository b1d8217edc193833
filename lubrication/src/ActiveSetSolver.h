#pragma once
// Internal: the fast solver. Not installed.
//
// Outer loop: a primal-dual active-set iteration (equivalently, semismooth Newton on the
// min-function of the complementarity conditions). For a given split of the unknown nodes into
// full (unknown p, theta = 1) and cavitated (p = p_cav; JFO: unknown theta) the balance is
// linear, so one Newton step solves it. The sets are then updated:
//   full -> cavitated   where p < p_cav,
//   cavitated -> full   Reynolds: where the balance shows a mass deficit (R < 0, the node wants
//                       pressure); JFO: where theta > 1 (or theta < 0: no consistent cavitated
//                       state),
// until no node changes.
//
// Inner linear solves: sparse direct factorisation, CHOLMOD LDL' for the symmetric Reynolds /
// full-Sommerfeld Jacobian, KLU LU for the unsymmetric mass-conserving one. The symbolic
// analysis is kept while the grid's shape is unchanged. The numeric factorisation is *lagged*:
// a factorisation of an earlier Jacobian (previous step, previous active set) serves as the
// preconditioner of a Krylov solve (PCG for the symmetric, GMRES for the unsymmetric case) on
// the current one. It is refreshed when the last Krylov solve cost more than the average cost
// per solve since the last factorisation (factorisation included, in iteration units from the
// factorisation's flop count): the rule that minimises the long-run average cost when the
// preconditioner's quality decays steadily.
// Consecutive calls of an engine simulation differ little, so most calls cost a handful of
// back-substitutions instead of a factorisation.
//
// Multigrid (FastLinearSolver::Multigrid, or Automatic on grids of kMultigridMinNodes nodes and
// more): one V-cycle of GridMultigrid on the Poiseuille block of the full nodes replaces the
// factorisation. Symmetric case: it is the PCG preconditioner. Mass-conserving case: GMRES with
// the block lower-triangular preconditioner [MG 0; C D] (D, the upwind fill-fraction transport
// of the cavitated nodes, inverted by one sweep along the sliding direction). The finest level
// always uses the current Jacobian and active set; the Galerkin coarse levels are lagged and
// refreshed by the same cost balance (their build cost in Krylov iterations from operation
// counts; the first solve after a rebuild is iterative too). Should the Krylov solve fail even
// with a fresh hierarchy, the current Jacobian is factorised (CHOLMOD / KLU) and solved
// directly; Automatic then factorises for a pause of 8 calls, doubled after each further
// failure up to 1024, and tries multigrid again after it (a multigrid call that succeeds
// resets the pause): a degenerate first call of a run (a steady film without sliding at
// TDC) once left a whole engine cycle on KLU, 3-4 times slower per solve.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "pistondyn/lubrication/Gmres.h"

#include "GridMultigrid.h"
#include "ReferenceSolver.h"
#include "SparseFactor.h"

namespace pistondyn::lubrication::detail {

// The preconditioner strategy of a call (chosen by FilmSolverOptions::linearSolver).
enum class PreconditionerKind : std::uint8_t {
  LaggedFactor,  // a sparse factorisation of an earlier Jacobian (SparseFactors)
  Multigrid,     // one V-cycle of GridMultigrid (MultigridPreconditioner)
};

// How far a sparse factorisation has got for the current grid shape.
enum class FactorState : std::uint8_t {
  None,      // no symbolic analysis yet
  Analysed,  // symbolic analysis only: no usable numeric factorisation (none yet, or dropped, or
             // the last one failed)
  Factored,  // a numeric factorisation of an earlier Jacobian: the lagged preconditioner
  Exact,     // a numeric factorisation of the current Jacobian: a solve with it is direct
};

// What the row flags and the sparse values (StencilPattern::values) hold.
enum class JacobianState : std::uint8_t {
  Stale,     // they belong to an earlier active set (or none)
  RowsOnly,  // the row flags (and the multigrid's finest level) are current, the values are not
  Values,    // both are current
};

// How a linear solve ended.
enum class LinearSolveOutcome : std::uint8_t {
  Failed,       // no solution: Krylov and the factorisation behind it failed (a singular Jacobian)
  Solved,       // to the tight target, or directly
  SolvedLoose,  // stopped at the loose target: the step is accurate only to it
};

// The sparse factorisations and their states: CHOLMOD LDL' for the symmetric (Reynolds, full-
// Sommerfeld) Jacobian, KLU LU for the mass-conserving one (`jfo`). The symbolic analysis is
// kept while the grid's shape is unchanged.
class SparseFactors {
 public:
  void reset();            // a new grid shape: nothing analysed
  void drop();             // the numeric factorisations no longer serve (Analysed)
  void jacobianChanged();  // an Exact factorisation becomes the lagged one (Factored)
  bool hasFactor(bool jfo) const { return state(jfo) >= FactorState::Factored; }
  bool isExact(bool jfo) const { return state(jfo) == FactorState::Exact; }
  // Analyses when needed and factorises pat.values: Exact on success, Analysed on failure.
  // KLU keeps its pivot order while it has a valid factorisation (a refactor is cheaper);
  // factoriseWithFreshPivots always chooses new pivots.
  bool factorise(StencilPattern& pat, bool jfo);
  bool factoriseWithFreshPivots(StencilPattern& pat, bool jfo);
  // Direct solve in place (column-major, `columns` right-hand sides) with the factorisation.
  void solve(bool jfo, double* rhs, int columns);
  // Cost of one factorisation in Krylov iterations (SparseFactor.h).
  double factorCostInIterations(bool jfo) const {
    return jfo ? klu_.factorCostInIterations() : chol_.factorCostInIterations();
  }

 private:
  FactorState state(bool jfo) const { return jfo ? kluState_ : cholState_; }
  bool factoriseWithPivots(StencilPattern& pat, bool jfo, bool freshPivots);
  CholmodLdl chol_;
  KluLu klu_;
  FactorState cholState_ = FactorState::None, kluState_ = FactorState::None;
};

// When a lagged preconditioner (the factorisation, or the multigrid's coarse levels) is
// refreshed: when the last Krylov solve cost more than the average cost per solve since it was
// built, the build included, in Krylov iterations. It is the rule that minimises the long-run
// average cost when the preconditioner's quality decays steadily.
class RefreshRule {
 public:
  // A build of `buildCost` iterations, followed by `directSolves` solves that cost nothing more
  // (1 after a factorisation: its own direct solve; 0 after a multigrid build). Not due.
  void restart(double buildCost, int directSolves) {
    cost_ = buildCost;
    solves_ = directSolves;
    due_ = false;
  }
  // Books a Krylov solve of `iterations`; the refresh becomes due when it cost more than the
  // average (never for the first solve after a build).
  void book(int iterations) {
    if (iterations <= 0)
      return;
    cost_ += iterations;
    ++solves_;
    if (solves_ > 1 && iterations > cost_ / solves_)
      due_ = true;
  }
  bool isDue() const { return due_; }
  void cancel() { due_ = false; }  // the preconditioner it judged is gone

 private:
  double cost_ = 0.0;
  int solves_ = 0;
  bool due_ = false;
};

// FastLinearSolver::Automatic after a multigrid failure: the factorisation serves for a pause of
// calls, doubled after each further failure up to a longest pause; a multigrid call that
// succeeds resets it.
class MultigridPause {
 public:
  void reset();  // no pause; the next one is the first
  // At the start of a call: true while the pause lasts (the call is counted).
  bool beginCall();
  void recordFailure();        // multigrid failed in this call: pause
  void recordConvergedCall();  // a multigrid call converged: reset the pause unless it failed
 private:
  int pausedCalls_ = 0;  // calls left with the factorisation
  int nextPause_ = 0;    // the pause after the next failure
  bool failedThisCall_ = false;
};

// The multigrid strategy: the hierarchy (its finest level always uses the current Jacobian,
// the Galerkin coarse levels are lagged) and Automatic's pause.
struct MultigridPreconditioner {
  GridMultigrid levels;
  bool built = false;  // the coarse levels exist (they may be lagged)
  MultigridPause pause;
};

// The node-count, row-length and periodicity the workspaces were built for.
struct GridShape {
  int n = -1, nx = -1;
  bool periodicX = false;
  bool operator==(const GridShape& o) const {
    return n == o.n && nx == o.nx && periodicX == o.periodicX;
  }
};

class ActiveSetSolver {
 public:
  // Builds the stencil pattern and resets the factorisations when the grid shape changed.
  void prepare(const FilmSystem& sys);

  // Runs the active-set iteration from sys.p / sys.theta / sys.status.
  IterationReport solve(FilmSystem& sys, const FilmSolverOptions& options);

  // Solves J dz = rhs (column-major, n x nrhs, in place) with the Jacobian of the current
  // active set, to a relative accuracy `relTol` of each column's max norm. Krylov solves with
  // the current preconditioner, unless (mayFactorise) a column's Krylov cost shows that
  // factorising the current Jacobian and back-substituting the rest is cheaper.
  // Returns false when a column's linear solve failed (Krylov and the factorisation behind it:
  // a singular Jacobian); rhs is then all zero, which the caller must report.
  [[nodiscard]] bool solveWithCurrentSet(FilmSystem& sys, Eigen::MatrixXd& rhs, double relTol,
                                         bool mayFactorise);

  // Marks that the stored Jacobian values no longer belong to the current active set.
  void invalidate() { jacobian_ = JacobianState::Stale; }

  int factorisations() const { return factorisations_; }
  int krylovIterations() const { return krylovIterations_; }
  int multigridBuilds() const { return multigridBuilds_; }

 private:
  bool usesMultigrid() const { return preconditioner_ == PreconditionerKind::Multigrid; }
  // Chooses the call's preconditioner strategy; a change drops the other one's lagged state.
  void choosePreconditioner(const FilmSystem& sys, const FilmSolverOptions& options);
  void fillJacobian(const FilmSystem& sys);  // row flags, and values unless multigrid is used
  void fillValues(const FilmSystem& sys);    // sparse Jacobian values (factorisations)
  LinearSolveOutcome linearSolveMultigrid(const FilmSystem& sys, double* rhs, double absTarget,
                                          double looseTarget);
  bool rebuildMultigrid(const FilmSystem& sys);
  void precondition(const FilmSystem& sys, const double* r, double* z);  // z = M^-1 r
  void updatePreconditionerScaling();
  // Factorises the current sparse values (SparseFactors; fresh KLU pivots when asked) and
  // counts it; the state becomes Exact on success.
  bool factorValues(const FilmSystem& sys, bool freshPivots);
  // factorValues as the new lagged preconditioner: its column types, diagonal and cost.
  bool factorCurrent(const FilmSystem& sys);
  // rhs -> solution in place, residual max norm <= absTarget (equation rows), or Failed.
  // With looseTarget > absTarget the solve may stop at looseTarget (SolvedLoose) when the step
  // would change the active set (PCG), or always does (GMRES).
  LinearSolveOutcome linearSolve(const FilmSystem& sys, double* rhs, double absTarget,
                                 double looseTarget);
  // Puts the iterate on the constraints of its sets: p >= p_cav and (JFO) theta = 1 on full
  // nodes, p = p_cav and 0 <= theta <= 1 on cavitated ones.
  void projectOntoConstraints(FilmSystem& s) const;
  // Direct solve with the current factorisation (CHOLMOD, or KLU for JFO), in place.
  void solveWithFactor(const FilmSystem& sys, double* rhs, int columns);
  // One Krylov solve with the current preconditioner; books its cost for the refresh rule.
  // Failed when it did not reach its target within kMaxKrylovIterations.
  LinearSolveOutcome krylovSolve(const FilmSystem& sys, double* rhs, double absTarget,
                                 double looseTarget);
  bool wouldChangeSet(const FilmSystem& sys, const Eigen::VectorXd& dz, double accuracy) const;
  void applyPreconditioner(const FilmSystem& sys, double* v);  // v <- M^-1 v, zero off-set
  void multiply(const FilmSystem& sys, const double* x, double* y) const;  // y = J x
  LinearSolveOutcome pcg(const FilmSystem& sys, double* b, double absTarget, double looseTarget,
                         int maxIt);
  // GMRES to a max-norm target (GmresMaxNormTarget), preconditioned by precondition().
  bool gmres(const FilmSystem& sys, double* b, double absTarget);

  GridShape shape_;
  StencilPattern pat_;
  PreconditionerKind preconditioner_ = PreconditionerKind::LaggedFactor;
  JacobianState jacobian_ = JacobianState::Stale;
  SparseFactors factors_;
  MultigridPreconditioner multigrid_;
  RefreshRule refresh_;
  int factorisations_ = 0, krylovIterations_ = 0, multigridBuilds_ = 0;
  double tolerance_ = 1e-8;
  Eigen::VectorXd cavResidual_;  // Reynolds: balance of the cavitated nodes before the step
  Eigen::VectorXd factorDiag_, precondScale_;  // diagonal at factorisation, drift scaling

  Eigen::VectorXd rhs_, step_, x_, r_, z_, p_, q_;  // PCG's vectors, right-hand side, step
  // Beyond kMaxKrylovIterations a Krylov solve gives up: the current Jacobian is factorised.
  static constexpr int kMaxKrylovIterations = 40;
  // GMRES (mass-conserving model): 30 directions per cycle, standard form; the max-norm target
  // is checked on the true residual after each cycle (GmresMaxNormTarget).
  Gmres gmres_{GmresOptions{/*restart=*/30, /*maxIterations=*/kMaxKrylovIterations,
                            /*flexible=*/false, /*skipDegenerateDirections=*/false}};
  Eigen::VectorXd changedRhs_;
  std::vector<std::uint8_t> eqRow_;
  Eigen::VectorXd eqMask_;          // 1.0 on equation rows, 0.0 elsewhere
  std::vector<std::uint8_t> pRow_;  // pressure unknowns (full nodes): the multigrid's rows
  Eigen::VectorXd mgRhs_;           // mass-conserving model: pressure block of a right-hand side
  std::vector<std::uint8_t> colType_, factorColType_;  // 0 identity, 1 pressure, 2 fill
};

}  // namespace pistondyn::lubrication::detail
