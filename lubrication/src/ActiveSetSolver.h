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

#include <Eigen/Core>

#include "pistondyn/lubrication/Gmres.h"

#include "GridMultigrid.h"
#include "ReferenceSolver.h"
#include "SparseFactor.h"

namespace pistondyn::lubrication::detail {

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
  void invalidate() { jacobianCurrent_ = false; }

  int factorisations() const { return factorisations_; }
  int krylovIterations() const { return krylovIterations_; }
  int multigridBuilds() const { return multigridBuilds_; }

 private:
  void fillJacobian(const FilmSystem& sys);  // row flags, and values unless multigrid is used
  void fillValues(const FilmSystem& sys);    // sparse Jacobian values (factorisations)
  bool linearSolveMultigrid(const FilmSystem& sys, double* rhs, double absTarget,
                            double looseTarget);
  bool rebuildMultigrid(const FilmSystem& sys);
  void precondition(const FilmSystem& sys, const double* r, double* z);  // z = M^-1 r
  void updatePreconditionerScaling();
  // Analyse (once per shape) and factorise the current sparse values; KLU refreshes its pivot
  // order when freshPivots. Updates the factorisation counters and factorExact_.
  bool factorValues(const FilmSystem& sys, bool freshPivots);
  bool factorCurrent(const FilmSystem& sys);
  // rhs -> solution in place, residual max norm <= absTarget (equation rows). False on failure.
  // With looseTarget > absTarget the solve may stop at looseTarget (stoppedLoose_) when the step
  // would change the active set (PCG), or always does (GMRES).
  bool linearSolve(const FilmSystem& sys, double* rhs, double absTarget, double looseTarget);
  // Puts the iterate on the constraints of its sets: p >= p_cav and (JFO) theta = 1 on full
  // nodes, p = p_cav and 0 <= theta <= 1 on cavitated ones.
  void projectOntoConstraints(FilmSystem& s) const;
  // Direct solve with the current factorisation (CHOLMOD, or KLU for JFO), in place.
  void solveWithFactor(const FilmSystem& sys, double* rhs, int columns);
  // One Krylov solve with the current preconditioner; books its cost for the refresh rule.
  // False when it did not reach its target within kMaxKrylovIterations.
  bool krylovSolve(const FilmSystem& sys, double* rhs, double absTarget, double looseTarget);
  bool wouldChangeSet(const FilmSystem& sys, const Eigen::VectorXd& dz, double accuracy) const;
  void applyPreconditioner(const FilmSystem& sys, double* v);  // v <- M^-1 v, zero off-set
  void multiply(const FilmSystem& sys, const double* x, double* y) const;  // y = J x
  bool pcg(const FilmSystem& sys, double* b, double absTarget, double looseTarget, int maxIt);
  // GMRES to a max-norm target (GmresMaxNormTarget), preconditioned by precondition().
  bool gmres(const FilmSystem& sys, double* b, double absTarget);

  StencilPattern pat_;
  GridMultigrid mg_;
  bool useMg_ = false;
  bool mgBuilt_ = false;
  // Automatic after a multigrid failure: calls left with the factorisation, and the next pause
  // (doubled per failure, reset when a multigrid call succeeds).
  int mgPausedCalls_ = 0;
  int mgPause_ = 0;
  bool gaveUpThisCall_ = false;
  bool valuesCurrent_ = false;  // pat_.values hold the current Jacobian (multigrid mode)
  int multigridBuilds_ = 0;
  CholmodLdl chol_;
  KluLu klu_;
  int shapeN_ = -1, shapeNx_ = -1;
  bool shapePeriodic_ = false;
  bool cholAnalysed_ = false, kluAnalysed_ = false;
  bool cholFactored_ = false, kluFactored_ = false;
  bool factorExact_ = false;      // the stored factorisation is of the current Jacobian values
  bool jacobianCurrent_ = false;  // pat_.values hold the Jacobian of the current active set
  bool refactorNext_ = false;     // refresh the factorisation before the next solve
  // Cost bookkeeping since the last factorisation, in Krylov iterations (see linearSolve).
  double costSinceFactor_ = 0.0;
  int solvesSinceFactor_ = 0;
  int factorisations_ = 0, krylovIterations_ = 0;
  bool stoppedLoose_ = false;
  double tolerance_ = 1e-8;
  Eigen::VectorXd cavResidual_;  // Reynolds: balance of the cavitated nodes before the step
  Eigen::VectorXd factorDiag_, precondScale_;  // diagonal at factorisation, drift scaling

  Eigen::VectorXd rhs_, step_, x_, r_, z_, p_, q_;  // PCG's vectors, right-hand side, step
  // Beyond kMaxKrylovIterations a Krylov solve gives up: the current Jacobian is factorised.
  static constexpr int kMaxKrylovIterations = 40;
  // GMRES (mass-conserving model): 30 directions per cycle, standard form; the max-norm target
  // is checked on the true residual after each cycle (GmresMaxNormTarget).
  Gmres gmres_{GmresOptions{30, kMaxKrylovIterations, false, false}};
  Eigen::VectorXd changedRhs_;
  std::vector<std::uint8_t> eqRow_;
  Eigen::VectorXd eqMask_;          // 1.0 on equation rows, 0.0 elsewhere
  std::vector<std::uint8_t> pRow_;  // pressure unknowns (full nodes): the multigrid's rows
  Eigen::VectorXd mgRhs_;           // mass-conserving model: pressure block of a right-hand side
  std::vector<std::uint8_t> colType_, factorColType_;  // 0 identity, 1 pressure, 2 fill
};

}  // namespace pistondyn::lubrication::detail
