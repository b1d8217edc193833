#include "ActiveSetSolver.h"

#include <algorithm>
#include <cmath>

namespace pistondyn::lubrication::detail {

namespace {

// Rows that carry a balance equation in the linear system (the others are identity rows).
inline bool isEquationRow(const FilmSystem& s, int m) {
  return s.status[m] == kFull || (s.status[m] == kCav && s.jfo);
}

constexpr double kInnerSafety = 0.5;      // inner target = kInnerSafety * tolerance
constexpr double kLooseFraction = 3e-2;   // inexact solves while the active set moves
// Mass-conserving model: from this active-set step on, a step that cavitates nodes does not also
// return cavitated nodes to full film (deferred to a step that cavitates none). The plain
// primal-dual rule flips both at once and can cycle on the unsymmetric JFO system: on a starved
// film (supply ~ 0) full nodes feed theta > 1 into the cavitated nodes downstream while losing
// pressure themselves, and the sets repeat with period 4 forever. Deferring makes the cavitated
// set grow monotonically between reformations, which breaks such cycles. The first steps keep
// the plain rule, so solves that settle within them (warm-started calls take 1-3) are unchanged.
constexpr int kDeferReformationAfter = 6;
// Automatic after a multigrid failure: calls with the factorisation before multigrid is tried
// again, doubled after every further failure up to the longest pause (ActiveSetSolver.h).
constexpr int kMultigridFirstPause = 8;
constexpr int kMultigridLongestPause = 1024;

}  // namespace

void SparseFactors::reset() {
  cholState_ = kluState_ = FactorState::None;
}

void SparseFactors::drop() {
  for (FactorState* state : {&cholState_, &kluState_})
    if (*state >= FactorState::Factored)
      *state = FactorState::Analysed;
}

void SparseFactors::jacobianChanged() {
  for (FactorState* state : {&cholState_, &kluState_})
    if (*state == FactorState::Exact)
      *state = FactorState::Factored;
}

bool SparseFactors::factorise(StencilPattern& pat, bool jfo) {
  // KLU keeps its pivot order while it has a valid factorisation (CHOLMOD has no choice).
  return factoriseWithPivots(pat, jfo, kluState_ < FactorState::Factored);
}

bool SparseFactors::factoriseWithFreshPivots(StencilPattern& pat, bool jfo) {
  return factoriseWithPivots(pat, jfo, true);
}

bool SparseFactors::factoriseWithPivots(StencilPattern& pat, bool jfo, bool freshPivots) {
  FactorState& state = jfo ? kluState_ : cholState_;
  if (state == FactorState::None) {
    if (jfo)
      klu_.analyze(pat);
    else
      chol_.analyze(pat);
    state = FactorState::Analysed;
  }
  const bool ok = jfo ? klu_.factorize(pat, freshPivots) : chol_.factorize(pat);
  state = ok ? FactorState::Exact : FactorState::Analysed;
  return ok;
}

void SparseFactors::solve(bool jfo, double* rhs, int columns) {
  if (!jfo)
    chol_.solve(rhs, rhs, columns);
  else
    klu_.solve(rhs, columns);
}

void MultigridPause::reset() {
  pausedCalls_ = 0;
  nextPause_ = kMultigridFirstPause;
}

bool MultigridPause::beginCall() {
  const bool paused = pausedCalls_ > 0;
  if (paused)
    --pausedCalls_;
  failedThisCall_ = false;
  return paused;
}

void MultigridPause::recordFailure() {
  failedThisCall_ = true;
  pausedCalls_ = nextPause_;
  nextPause_ = std::min(2 * nextPause_, kMultigridLongestPause);
}

void MultigridPause::recordConvergedCall() {
  if (!failedThisCall_)
    nextPause_ = kMultigridFirstPause;  // multigrid suits the operator again
}

void ActiveSetSolver::prepare(const FilmSystem& sys) {
  const GridShape shape{sys.n, sys.nx, sys.periodicX};
  if (shape == shape_)
    return;
  pat_.build(sys);
  multigrid_.levels.prepare(sys);
  multigrid_.built = false;
  multigrid_.pause.reset();
  shape_ = shape;
  factors_.reset();
  jacobian_ = JacobianState::Stale;
  refresh_.cancel();
  const int n = sys.n;
  for (Eigen::VectorXd* v : {&rhs_, &step_, &x_, &r_, &z_, &p_, &q_})
    v->setZero(n);
  gmres_.resize(n);
  eqRow_.assign(n, 0);
  pRow_.assign(n, 0);
  mgRhs_.setZero(n);
  eqMask_.setZero(n);
  colType_.assign(n, 0);
  factorColType_.assign(n, 0);
  changedRhs_.setZero(n);
  cavResidual_.setZero(n);
  factorDiag_.setOnes(n);
  precondScale_.setOnes(n);
}

void ActiveSetSolver::fillJacobian(const FilmSystem& s) {
  for (int k = 0; k < s.n; ++k) {
    eqRow_[k] = isEquationRow(s, k) ? 1 : 0;
    eqMask_[k] = eqRow_[k] ? 1.0 : 0.0;
    colType_[k] = !eqRow_[k] ? 0 : (s.status[k] == kFull ? 1 : 2);
    pRow_[k] = colType_[k] == 1 ? 1 : 0;
  }
  factors_.jacobianChanged();
  jacobian_ = JacobianState::RowsOnly;
  // The multigrid preconditioner works on the stencil of FilmSystem directly; the unsymmetric
  // product (mass-conserving model) needs the sparse values.
  if (usesMultigrid())
    multigrid_.levels.setFineOperator(s, pRow_.data());
  if (!usesMultigrid() || s.jfo)
    fillValues(s);
}

void ActiveSetSolver::fillValues(const FilmSystem& s) {
  std::fill(pat_.values.begin(), pat_.values.end(), 0.0);
  // Identity rows get the node's own Poiseuille diagonal (the film's conductance varies by
  // orders of magnitude): pivot-ratio checks stay meaningful and, should the node become an
  // unknown later, the lagged factorisation acts on it like a Jacobi step. Where that diagonal is
  // not positive, the mean over the non-fixed nodes (FilmSystem::meanFreeDiagP).
  const double scale = s.meanFreeDiagP;
  double* v = pat_.values.data();
  for (int k = 0; k < s.n; ++k) {
    if (!eqRow_[k]) {
      v[pat_.posSelf[k]] = s.diagP[k] > 0.0 ? s.diagP[k] : scale;
      continue;
    }
    const int e = s.nbE[k], w = s.nbW[k], no = s.nbN[k], so = s.nbS[k];
    if (s.status[k] == kFull) {
      // Column of p_k: Poiseuille coupling.
      v[pat_.posSelf[k]] = s.diagP[k];
      if (e != k && eqRow_[e])
        v[pat_.posE[k]] = -s.tE[k];
      if (w != k && eqRow_[w])
        v[pat_.posW[k]] = -s.tW[k];
      if (no != k && eqRow_[no])
        v[pat_.posN[k]] = -s.tN[k];
      if (so != k && eqRow_[so])
        v[pat_.posS[k]] = -s.tS[k];
    }
  }
  if (s.jfo) {
    // Columns of theta_k (cavitated): Couette outflow and storage in the own row, inflow into
    // the downstream rows. Done after all eqRow_ flags are known.
    for (int k = 0; k < s.n; ++k) {
      if (s.status[k] != kCav)
        continue;
      const int e = s.nbE[k], w = s.nbW[k], no = s.nbN[k], so = s.nbS[k];
      v[pat_.posSelf[k]] = s.thetaCoef[k];
      if (e != k && s.inIx[e] == k && eqRow_[e])
        v[pat_.posE[k]] -= s.inCx[e];
      if (w != k && s.inIx[w] == k && eqRow_[w])
        v[pat_.posW[k]] -= s.inCx[w];
      if (no != k && s.inIy[no] == k && eqRow_[no])
        v[pat_.posN[k]] -= s.inCy[no];
      if (so != k && s.inIy[so] == k && eqRow_[so])
        v[pat_.posS[k]] -= s.inCy[so];
    }
  }
  jacobian_ = JacobianState::Values;
  updatePreconditionerScaling();
}

// The Jacobian drifts between calls mostly by a smooth rescaling of the film conductance
// (h^3 changes with the gap): J_new ~ S J_old S with S = diag(sqrt(diag J_new / diag J_old)).
// Scaling the lagged factorisation the same way, M^-1 -> S^-1 M^-1 S^-1, absorbs that part of
// the drift at the cost of two diagonal scalings per application.
void ActiveSetSolver::updatePreconditionerScaling() {
  const double* v = pat_.values.data();
  for (int k = 0; k < pat_.n; ++k) {
    const double now = v[pat_.posSelf[k]], then = factorDiag_[k];
    precondScale_[k] = (then > 0.0 && now > 0.0) ? std::sqrt(then / now) : 1.0;
  }
}

bool ActiveSetSolver::factorValues(const FilmSystem& s, bool freshPivots) {
  const bool ok = freshPivots ? factors_.factoriseWithFreshPivots(pat_, s.jfo)
                              : factors_.factorise(pat_, s.jfo);
  ++factorisations_;
  return ok;
}

bool ActiveSetSolver::factorCurrent(const FilmSystem& s) {
  const bool ok = factorValues(s, false);
  factorColType_ = colType_;
  for (int k = 0; k < pat_.n; ++k)
    factorDiag_[k] = pat_.values[pat_.posSelf[k]];
  precondScale_.setOnes();
  // The direct solve that follows costs nothing more.
  refresh_.restart(factors_.factorCostInIterations(s.jfo), 1);
  return ok;
}

void ActiveSetSolver::multiply(const FilmSystem& s, const double* x, double* y) const {
  if (!s.jfo) {
    // Symmetric case: the Poiseuille stencil on the equation rows (x vanishes elsewhere), the
    // rows masked by a multiplication (no branch); interior nodes with fixed neighbour offsets.
    const int nx = s.nx, ny = s.ny;
    const double *tE = s.tE.data(), *tW = s.tW.data(), *tN = s.tN.data(), *tS = s.tS.data(),
                 *dg = s.diagP.data(), *m = eqMask_.data();
    const int *nE = s.nbE.data(), *nW = s.nbW.data(), *nN = s.nbN.data(), *nS = s.nbS.data();
    for (int j = 0; j < ny; ++j) {
      const int base = nx * j;
      const bool edgeRow = j == 0 || j == ny - 1;
      for (int i = 0; i < nx; ++i) {
        const int k = base + i;
        if (edgeRow || i == 0 || i == nx - 1)
          y[k] = m[k] * (dg[k] * x[k] - (tE[k] * x[nE[k]] + tW[k] * x[nW[k]] + tN[k] * x[nN[k]] +
                                         tS[k] * x[nS[k]]));
        else
          y[k] = m[k] * (dg[k] * x[k] - (tE[k] * x[k + 1] + tW[k] * x[k - 1] + tN[k] * x[k + nx] +
                                         tS[k] * x[k - nx]));
      }
    }
    return;
  }
  std::fill(y, y + pat_.n, 0.0);
  const double* v = pat_.values.data();
  for (int c = 0; c < pat_.n; ++c) {
    const double xc = x[c];
    if (xc == 0.0)
      continue;
    for (int q = pat_.colPtr[c]; q < pat_.colPtr[c + 1]; ++q)
      y[pat_.rowIdx[q]] += v[q] * xc;
  }
}

// Block preconditioner: the lagged factorisation on the nodes whose unknown (p, theta or none)
// is the same as when it was computed, a Jacobi step with the current diagonal on the nodes
// that changed role since (they would otherwise see a row of another physical kind).
void ActiveSetSolver::applyPreconditioner(const FilmSystem& s, double* v) {
  const double* diag = pat_.values.data();
  for (int k = 0; k < s.n; ++k) {
    changedRhs_[k] = 0.0;
    if (eqRow_[k] && colType_[k] != factorColType_[k]) {
      changedRhs_[k] = v[k];
      v[k] = 0.0;
    } else {
      v[k] *= precondScale_[k];
    }
  }
  solveWithFactor(s, v, 1);
  for (int k = 0; k < s.n; ++k) {
    if (!eqRow_[k])
      v[k] = 0.0;
    else if (colType_[k] != factorColType_[k])
      v[k] = changedRhs_[k] / diag[pat_.posSelf[k]];
    else
      v[k] *= precondScale_[k];
  }
}

void ActiveSetSolver::precondition(const FilmSystem& s, const double* r, double* z) {
  if (usesMultigrid() && !s.jfo) {
    multigrid_.levels.apply(s, r, z);
    return;
  }
  if (usesMultigrid()) {
    // Mass-conserving Jacobian [A B; C D] (rows and columns: pressures of the full nodes, fill
    // fractions of the cavitated ones). Block lower-triangular preconditioner: z_p = MG(r_p)
    // for the Poiseuille block A, then z_theta = D^-1 (r_theta - C z_p) by one sweep along the
    // sliding direction (D, the upwind Couette transport of the fill fraction, is triangular in
    // that order). The coupling B (fill fraction carried into full nodes, only at reformation
    // fronts) is left to GMRES.
    for (int k = 0; k < s.n; ++k)
      mgRhs_[k] = colType_[k] == 1 ? r[k] : 0.0;
    multigrid_.levels.apply(s, mgRhs_.data(), z);
    for (const int k : s.order) {
      if (colType_[k] != 2)
        continue;
      double t = r[k];
      const int e = s.nbE[k], w = s.nbW[k], no = s.nbN[k], so = s.nbS[k];
      if (colType_[e] == 1)
        t += s.tE[k] * z[e];
      if (colType_[w] == 1)
        t += s.tW[k] * z[w];
      if (colType_[no] == 1)
        t += s.tN[k] * z[no];
      if (colType_[so] == 1)
        t += s.tS[k] * z[so];
      const int ix = s.inIx[k], iy = s.inIy[k];
      if (ix != k && colType_[ix] == 2)
        t += s.inCx[k] * z[ix];
      if (iy != k && colType_[iy] == 2)
        t += s.inCy[k] * z[iy];
      const double a = s.thetaCoef[k];
      z[k] = a > 0.0 ? t / a : 0.0;
    }
    return;
  }
  std::copy(r, r + s.n, z);
  applyPreconditioner(s, z);
}

bool ActiveSetSolver::rebuildMultigrid(const FilmSystem& s) {
  multigrid_.built = multigrid_.levels.rebuild(s, pRow_.data());
  ++multigridBuilds_;
  // Cost bookkeeping as for a factorisation, except that no direct solve follows.
  refresh_.restart(multigrid_.levels.rebuildCostInIterations(), 0);
  return multigrid_.built;
}

// Multigrid-preconditioned CG (GMRES for the mass-conserving model). The hierarchy's coarse
// levels are lagged like the factorisation of the sparse-direct path (refreshed by the same cost
// balance); its finest level always uses the current matrix. Should the Krylov solve fail even
// with a fresh hierarchy, the current Jacobian is factorised (CHOLMOD / KLU) and solved directly.
LinearSolveOutcome ActiveSetSolver::linearSolveMultigrid(const FilmSystem& s, double* b,
                                                         double target, double looseTarget) {
  Eigen::Map<Eigen::VectorXd> bv(b, s.n);
  bool fresh = false;
  if (!multigrid_.built || refresh_.isDue())
    fresh = rebuildMultigrid(s);
  rhs_ = bv;
  for (int attempt = 0; attempt < 2 && multigrid_.built; ++attempt) {
    const LinearSolveOutcome outcome = krylovSolve(s, b, target, looseTarget);
    if (outcome != LinearSolveOutcome::Failed)
      return outcome;
    bv = rhs_;
    if (fresh)
      break;
    fresh = rebuildMultigrid(s);
  }
  // Multigrid does not suit this operator (e.g. opposite anisotropies in one grid, or a
  // degenerate one such as a steady film without sliding): Automatic factorises for a pause
  // of calls, twice as many after each further failure (at most kMultigridLongestPause), and
  // tries multigrid again after them: one bad operator must not cost the rest of a run.
  multigrid_.pause.recordFailure();
  if (jacobian_ != JacobianState::Values)
    fillValues(s);
  // Fresh pivots: the Krylov failure says this operator differs from any earlier one.
  if (!factorValues(s, true))
    return LinearSolveOutcome::Failed;
  solveWithFactor(s, b, 1);
  return LinearSolveOutcome::Solved;
}

void ActiveSetSolver::solveWithFactor(const FilmSystem& s, double* b, int columns) {
  factors_.solve(s.jfo, b, columns);
}

LinearSolveOutcome ActiveSetSolver::krylovSolve(const FilmSystem& s, double* b, double target,
                                                double looseTarget) {
  const int before = krylovIterations_;
  LinearSolveOutcome outcome;
  if (s.jfo) {
    // GMRES forms its iterate only at the end of a cycle: solve to the loose target and let the
    // active-set loop decide (a second, tight solve follows when the set did not move).
    outcome = !gmres(s, b, looseTarget) ? LinearSolveOutcome::Failed
              : looseTarget > target    ? LinearSolveOutcome::SolvedLoose
                                        : LinearSolveOutcome::Solved;
  } else {
    outcome = pcg(s, b, target, looseTarget, kMaxKrylovIterations);
  }
  if (outcome == LinearSolveOutcome::Failed)
    return outcome;
  // Refresh the preconditioner when this solve cost more than the average per solve since it
  // was built (after a factorisation the count starts at 1 for its own direct solve; after a
  // multigrid build at 0, so the first solve is never judged against itself).
  refresh_.book(krylovIterations_ - before);
  return outcome;
}

bool ActiveSetSolver::wouldChangeSet(const FilmSystem& s, const Eigen::VectorXd& dz,
                                     double accuracy) const {
  if (s.model == CavitationModel::None)
    return false;
  const double rEps = std::max(0.5 * s.residualScale * tolerance_, accuracy);
  for (int k = 0; k < s.n; ++k) {
    if (s.status[k] == kFull) {
      if (s.p[k] + dz[k] < s.pCav - accuracy / s.diagP[k])
        return true;
    } else if (s.status[k] == kCav) {
      // Balance after the step; dz vanishes on the cavitated (masked) rows, so only the
      // neighbours' pressure changes enter.
      const double r = cavResidual_[k] + s.poiseuilleAt(k, dz.data());
      if (r < -rEps)
        return true;
    }
  }
  return false;
}

LinearSolveOutcome ActiveSetSolver::pcg(const FilmSystem& s, double* b, double target,
                                        double looseTarget, int maxIt) {
  const int n = s.n;
  Eigen::Map<Eigen::VectorXd> bv(b, n);
  x_.setZero();
  r_ = bv;
  if (r_.lpNorm<Eigen::Infinity>() <= target) {
    bv.setZero();
    return LinearSolveOutcome::Solved;
  }
  // While the active set may still move, stop at the loose target if the step would change it;
  // otherwise carry on in the same Krylov space to the tight target.
  bool checkLoose = looseTarget > target;
  precondition(s, r_.data(), z_.data());
  p_ = z_;
  double rz = r_.dot(z_);
  for (int it = 1; it <= maxIt; ++it) {
    multiply(s, p_.data(), q_.data());
    const double pq = p_.dot(q_);
    if (!(pq > 0.0))
      return LinearSolveOutcome::Failed;
    const double alpha = rz / pq;
    x_.noalias() += alpha * p_;
    r_.noalias() -= alpha * q_;
    ++krylovIterations_;
    const double rMax = r_.lpNorm<Eigen::Infinity>();
    if (rMax <= target) {
      bv = x_;
      return LinearSolveOutcome::Solved;
    }
    if (checkLoose && rMax <= looseTarget) {
      checkLoose = false;
      if (wouldChangeSet(s, x_, looseTarget)) {
        bv = x_;
        return LinearSolveOutcome::SolvedLoose;
      }
    }
    precondition(s, r_.data(), z_.data());
    const double rzNew = r_.dot(z_);
    const double beta = rzNew / rz;
    rz = rzNew;
    p_ = z_ + beta * p_;
  }
  return LinearSolveOutcome::Failed;
}

bool ActiveSetSolver::gmres(const FilmSystem& s, double* b, double target) {
  Eigen::Map<Eigen::VectorXd> bv(b, s.n);
  GmresMaxNormTarget stop(target);
  const GmresReport report = gmres_.solve(
      [&](const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& y) {
        multiply(s, x.data(), y.data());
        return true;
      },
      [&](const Eigen::Ref<const Eigen::VectorXd>& r, Eigen::Ref<Eigen::VectorXd> z) {
        precondition(s, r.data(), z.data());
      },
      bv, stop);
  krylovIterations_ += report.iterations;
  if (report.converged)
    bv = gmres_.solution();
  return report.converged;
}

LinearSolveOutcome ActiveSetSolver::linearSolve(const FilmSystem& s, double* b, double target,
                                                double looseTarget) {
  Eigen::Map<Eigen::VectorXd> bv(b, s.n);
  if (bv.lpNorm<Eigen::Infinity>() <= target) {  // already converged: nothing to factorise
    bv.setZero();
    return LinearSolveOutcome::Solved;
  }
  // A factorisation of this very Jacobian exists (sparse-direct path, or the multigrid path's
  // fallback): solve directly. No refresh can be due here: it only becomes due after a Krylov
  // solve, which does not run while the factorisation is exact, and every build restarts it.
  if (factors_.isExact(s.jfo)) {
    solveWithFactor(s, b, 1);
    return LinearSolveOutcome::Solved;
  }
  if (usesMultigrid())
    return linearSolveMultigrid(s, b, target, looseTarget);
  if (!factors_.hasFactor(s.jfo) || refresh_.isDue()) {
    if (!factorCurrent(s))
      return LinearSolveOutcome::Failed;
    solveWithFactor(s, b, 1);  // the fresh factorisation is of the current Jacobian
    return LinearSolveOutcome::Solved;
  }
  rhs_ = Eigen::Map<Eigen::VectorXd>(b, s.n);  // keep the right-hand side for a fallback
  const LinearSolveOutcome outcome = krylovSolve(s, b, target, looseTarget);
  if (outcome != LinearSolveOutcome::Failed)
    return outcome;
  // The lagged factorisation is too far from the current Jacobian: factorise it.
  if (!factorCurrent(s))
    return LinearSolveOutcome::Failed;
  Eigen::Map<Eigen::VectorXd>(b, s.n) = rhs_;
  solveWithFactor(s, b, 1);
  return LinearSolveOutcome::Solved;
}

void ActiveSetSolver::choosePreconditioner(const FilmSystem& s, const FilmSolverOptions& opt) {
  const bool paused = multigrid_.pause.beginCall();
  const bool mg =
      opt.linearSolver == FastLinearSolver::Multigrid ||
      (opt.linearSolver == FastLinearSolver::Automatic && s.n >= kMultigridMinNodes && !paused);
  const PreconditionerKind kind =
      mg ? PreconditionerKind::Multigrid : PreconditionerKind::LaggedFactor;
  if (kind == preconditioner_)
    return;
  // The lagged preconditioner of the other path is stale: start afresh.
  preconditioner_ = kind;
  multigrid_.built = false;
  factors_.drop();
  refresh_.cancel();
}

IterationReport ActiveSetSolver::solve(FilmSystem& s, const FilmSolverOptions& opt) {
  prepare(s);
  choosePreconditioner(s, opt);
  jacobian_ = JacobianState::Stale;
  IterationReport rep;
  double* p = s.p.data();
  double* th = s.theta.data();
  const double tol = opt.tolerance;
  tolerance_ = tol;
  const double innerTarget = kInnerSafety * tol * s.residualScale;
  // Inexact active-set iteration: while the sets are still moving, a linear solve only needs to
  // be accurate enough to decide them (kLooseFraction of the current residual); the tight target
  // is used once a step left the sets unchanged. Without cavitation there is no set to find.
  bool setStable = s.model == CavitationModel::None;
  for (int it = 1; it <= opt.maxActiveSetIterations; ++it) {
    rep.iterations = it;
    // Put the iterate on the current sets, then one Newton step: J dz = -R.
    for (int k = 0; k < s.n; ++k) {
      if (s.status[k] == kFull && s.jfo)
        th[k] = 1.0;
      if (s.status[k] == kCav)
        p[k] = s.pCav;
    }
    fillJacobian(s);
    Eigen::VectorXd& step = step_;
    double rNorm = 0.0;
    for (int k = 0; k < s.n; ++k) {
      step[k] = eqRow_[k] ? -s.residualAt(k) : 0.0;
      rNorm = std::max(rNorm, std::abs(step[k]));
    }
    const double loose = setStable ? innerTarget : std::max(innerTarget, kLooseFraction * rNorm);
    if (!s.jfo)
      for (int k = 0; k < s.n; ++k)
        cavResidual_[k] = s.status[k] == kCav ? s.residualAt(k) : 0.0;
    const LinearSolveOutcome outcome = linearSolve(s, step.data(), innerTarget, loose);
    if (outcome == LinearSolveOutcome::Failed) {
      projectOntoConstraints(s);
      rep.residual = s.relativeResidual();
      return rep;
    }
    // The accuracy of this step.
    const double target = outcome == LinearSolveOutcome::SolvedLoose ? loose : innerTarget;
    double pScale = 0.0;
    for (int k = 0; k < s.n; ++k) {
      if (s.status[k] == kFull) {
        p[k] += step[k];
        pScale = std::max(pScale, std::abs(p[k] - s.pCav));
      } else if (s.status[k] == kCav && s.jfo) {
        th[k] += step[k];
      }
    }
    // Update the sets (primal-dual active-set rule). Violations below round-off, or below the
    // accuracy of an inexact solve, do not flip a node; they are projected away below.
    const double pEps = 1e-12 * pScale;
    const double rEps = std::max(0.5 * tol * s.residualScale, target);
    auto ruptures = [&](int k) {
      const double pTol = std::max(pEps, target > innerTarget ? target / s.diagP[k] : 0.0);
      return s.model != CavitationModel::None && p[k] < s.pCav - pTol;
    };
    bool deferReformation = false;
    if (s.jfo && it > kDeferReformationAfter)
      for (int k = 0; k < s.n && !deferReformation; ++k)
        deferReformation = s.status[k] == kFull && ruptures(k);
    bool changed = false;
    for (int k = 0; k < s.n; ++k) {
      if (s.status[k] == kFull) {
        if (ruptures(k)) {
          s.status[k] = kCav;
          p[k] = s.pCav;
          changed = true;
        }
      } else if (s.status[k] == kCav && !deferReformation) {
        const double a = s.thetaCoef[k];
        const double thTol = std::max(1e-10, target > innerTarget && a > 0.0 ? target / a : 0.0);
        const bool toFull =
            s.jfo ? (th[k] > 1.0 + thTol || th[k] < -thTol) : (s.residualAt(k) < -rEps);
        if (toFull) {
          s.status[k] = kFull;
          th[k] = 1.0;
          changed = true;
        }
      }
    }
    if (changed) {
      jacobian_ = JacobianState::Stale;
      setStable = false;
      continue;
    }
    setStable = true;
    projectOntoConstraints(s);
    rep.residual = s.relativeResidual();
    if (rep.residual <= tol) {
      rep.converged = true;
      if (usesMultigrid())
        multigrid_.pause.recordConvergedCall();
      return rep;
    }
    // Same sets but not yet accurate (inexact inner solve, round-off): another Newton step.
  }
  // Out of iterations right after a set change: the nodes that kept their set may still violate
  // the bounds by up to the (loose) step accuracy (theta > 1, p < p_cav). The caller gets this
  // iterate, and so does the Gauss-Seidel fallback, whose Elrod-Adams sweep never resets the
  // fill fraction of a full node (theta >= 1) and would carry a theta > 1 into its result.
  projectOntoConstraints(s);
  rep.residual = s.relativeResidual();
  return rep;
}

void ActiveSetSolver::projectOntoConstraints(FilmSystem& s) const {
  for (int k = 0; k < s.n; ++k) {
    if (s.status[k] == kFull) {
      if (s.jfo)
        s.theta[k] = 1.0;
      if (s.model != CavitationModel::None)
        s.p[k] = std::max(s.p[k], s.pCav);
    } else if (s.status[k] == kCav) {
      s.p[k] = s.pCav;
      if (s.jfo)
        s.theta[k] = std::clamp(s.theta[k], 0.0, 1.0);
    }
  }
}

bool ActiveSetSolver::solveWithCurrentSet(FilmSystem& s, Eigen::MatrixXd& rhs, double relTol,
                                          bool mayFactorise) {
  prepare(s);
  if (jacobian_ == JacobianState::Stale)
    fillJacobian(s);
  for (int k = 0; k < s.n; ++k)
    if (!eqRow_[k])
      rhs.row(k).setZero();
  const Eigen::Index m = rhs.cols();
  for (Eigen::Index c = 0; c < m; ++c) {
    if (factors_.isExact(s.jfo)) {  // the remaining columns are contiguous (column-major)
      solveWithFactor(s, rhs.col(c).data(), static_cast<int>(m - c));
      return true;
    }
    const double target = relTol * rhs.col(c).lpNorm<Eigen::Infinity>();
    const int before = krylovIterations_;
    if (linearSolve(s, rhs.col(c).data(), target, target) == LinearSolveOutcome::Failed) {
      rhs.setZero();
      return false;
    }
    // The Krylov cost of this column, repeated for the rest, against one factorisation of the
    // current Jacobian plus a back-substitution per column (each about one iteration). The
    // factorisation's cost is in iterations of the sparse-direct path; a multigrid-
    // preconditioned iteration costs no less, so the rule only errs towards Krylov there.
    const double remaining = static_cast<double>(m - c - 1);
    const int k = krylovIterations_ - before;
    if (!mayFactorise || remaining <= 0.0 || k <= 1)
      continue;
    if (remaining * (k - 1) <= factors_.factorCostInIterations(s.jfo))
      continue;
    if (usesMultigrid()) {
      // The factorisation serves only these columns: the multigrid's refresh rule (shared with
      // factorisations) is left as it was.
      if (jacobian_ != JacobianState::Values)
        fillValues(s);
      factorValues(s, false);
    } else {
      factorCurrent(s);
    }
    // A failed factorisation is not exact: the next columns go on with Krylov (sparse-direct
    // path: linearSolve then tries to factorise once more and reports failure).
  }
  return true;
}

}  // namespace pistondyn::lubrication::detail
