#pragma once
/// \file
/// Restarted GMRES (Saad & Schultz 1986) with right preconditioning, for the project's two
/// Krylov solves: the mass-conserving film's Newton steps (lubrication's active-set solver)
/// and the Newton coupling of an elastic skirt (plugin/skirt, NewtonCoupling.h).
///
/// A cycle builds an orthonormal basis V of the Krylov space of A M^-1 by Arnoldi with
/// modified Gram-Schmidt, reduces its Hessenberg matrix by Givens rotations as it grows and
/// reads the residual's 2-norm off the rotated right-hand side. At the end of a cycle the
/// iterate takes the least-squares combination y of the cycle's directions:
///   * standard form: x += M^-1 (V y), one more preconditioner application;
///   * flexible form (Saad 1993): x += Z y with Z = M^-1 V kept column by column: for a
///     preconditioner that may differ between applications, or an operator whose products
///     are only defined for the preconditioned directions themselves (a finite difference).
/// The start is x0 = 0. What ends the solve is a stopping test (below), a type with the hooks
/// that Gmres::solve calls: GmresMaxNormTarget and GmresRelativeReduction are the two in use.
///
/// The workspace is sized by resize() (the constructor calls it); solve() allocates nothing.
/// A Gmres object is used by one thread at a time.
///
/// Eigen's unsupported GMRES does not serve here: it allocates in every solve, stops only on
/// the relative 2-norm of the residual, and orthogonalises by Householder reflections, so it
/// would neither meet the film solver's max-norm target nor repeat its arithmetic.

#include <cmath>

#include <Eigen/Core>

namespace pistondyn::lubrication {

/// Sizes and variants of a Gmres workspace.
struct GmresOptions {
  int restart = 30;        ///< Krylov directions per cycle (>= 1)
  int maxIterations = 40;  ///< Arnoldi steps per solve over all cycles (>= 1)
  bool flexible = false;   ///< keep Z = M^-1 V (flexible form) instead of applying M^-1 once more
  /// A direction whose Givens rotation is degenerate (the rotated diagonal is zero or not
  /// finite: the product added nothing, or was not finite) is left out and ends the cycle. When
  /// false it is kept (cosine 1, sine 0), the back substitution then divides by zero and the
  /// true residual shows the failure.
  bool skipDegenerateDirections = false;
};

/// What one Gmres::solve did.
struct GmresReport {
  bool converged = false;       ///< the stopping test accepted the solution
  int iterations = 0;           ///< Arnoldi steps whose direction was kept, over all cycles
  int lastCycleDirections = 0;  ///< directions that the last cycle added to the solution
};

/// Stopping test on the residual's max norm, |r|_inf <= target (an absolute target): the
/// film's balance is judged node by node. GMRES knows only the residual's 2-norm during a
/// cycle, which is up to sqrt(n) times the max norm: a cycle stops when the 2-norm, scaled by
/// the max-to-2-norm ratio of the cycle's starting residual, reaches the target. The true
/// residual b - A x is then formed and checked; should its shape have changed so that it
/// misses, a restart carries on, stopping on the 2-norm itself.
class GmresMaxNormTarget {
 public:
  /// target >= 0: the accepted max norm of b - A x.
  explicit GmresMaxNormTarget(double target) : target_(target) {}
  /// x0 = 0 already meets the target (r0 = b, norm2 its 2-norm).
  bool initiallyConverged(const Eigen::VectorXd& r0, double /*norm2*/) const {
    return r0.lpNorm<Eigen::Infinity>() <= target_;
  }
  /// A cycle starts from residual r (2-norm norm2); restarted after a missed true check.
  void startCycle(const Eigen::VectorXd& r, double norm2, bool restarted) {
    normRatio_ = restarted ? 1.0 : r.lpNorm<Eigen::Infinity>() / norm2;
  }
  /// The cycle's estimate of the residual's 2-norm meets the target.
  bool estimateConverged(double residualNorm2) const {
    return residualNorm2 * normRatio_ <= target_;
  }
  /// Every cycle ends by forming the true residual.
  static constexpr bool verifiesTrueResidual() { return true; }
  /// The true residual meets the target.
  bool trueResidualConverged(const Eigen::VectorXd& r) const {
    return r.lpNorm<Eigen::Infinity>() <= target_;
  }

 private:
  double target_;
  double normRatio_ = 1.0;
};

/// Stopping test on the reduction of the residual's 2-norm, |r|_2 <= tolerance |b|_2, as the
/// cycle estimates it (no true residual is formed: each product may cost a film evaluation).
/// A zero or non-finite |b|_2 ends the solve at x = 0.
class GmresRelativeReduction {
 public:
  /// tolerance in (0, 1): the reduction asked for.
  explicit GmresRelativeReduction(double tolerance) : tolerance_(tolerance) {}
  /// b is zero (or not finite): x = 0.
  bool initiallyConverged(const Eigen::VectorXd& /*r0*/, double norm2) const {
    return !(norm2 > 0.0);
  }
  /// Keeps |b|_2 from the first cycle.
  void startCycle(const Eigen::VectorXd& /*r*/, double norm2, bool restarted) {
    if (!restarted)
      initialNorm2_ = norm2;
  }
  /// The cycle's estimate of the residual's 2-norm is within tolerance |b|_2.
  bool estimateConverged(double residualNorm2) const {
    return residualNorm2 <= tolerance_ * initialNorm2_;
  }
  /// The estimate is trusted: a cycle forms the true residual only to restart.
  static constexpr bool verifiesTrueResidual() { return false; }
  /// Not called (verifiesTrueResidual() is false).
  bool trueResidualConverged(const Eigen::VectorXd& /*r*/) const { return false; }

 private:
  double tolerance_;
  double initialNorm2_ = 0.0;
};

/// Restarted, right-preconditioned GMRES with its workspace (this file's top comment).
class Gmres {
 public:
  /// Options as documented in GmresOptions; n: the system's size (resize()).
  explicit Gmres(const GmresOptions& options = {}, Eigen::Index n = 0) : options_(options) {
    resize(n);
  }

  /// Sizes the workspace for systems of size n (>= 0); allocates only when n changes.
  void resize(Eigen::Index n) {
    if (n == x_.size() && basis_.cols() == options_.restart + 1)
      return;
    const int m = options_.restart;
    basis_.setZero(n, m + 1);
    preconditionedBasis_.setZero(options_.flexible ? n : 0, options_.flexible ? m : 0);
    hessenberg_.setZero(m + 1, m);
    rotatedRhs_.setZero(m + 1);
    givensCos_.setZero(m);
    givensSin_.setZero(m);
    combination_.setZero(m);
    for (Eigen::VectorXd* v : {&x_, &residual_, &preconditioned_, &product_})
      v->setZero(n);
  }

  /// The options in use.
  const GmresOptions& getOptions() const { return options_; }

  /// Solves A x = b approximately from x0 = 0 (solution()).
  /// Inputs:
  ///   applyOperator: bool(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& y),
  ///     y = A x; false when it cannot give the product (e.g. a budget of evaluations is spent,
  ///     or x is zero): the direction is left out and the solve ends with what it has.
  ///   applyPreconditioner: void(const Eigen::Ref<const Eigen::VectorXd>& r,
  ///     Eigen::Ref<Eigen::VectorXd> z), z = M^-1 r (r and z do not overlap).
  ///   b: the right-hand side, size as in resize(); not overlapping the workspace.
  ///   stop: the stopping test (GmresMaxNormTarget, GmresRelativeReduction, or a type with
  ///     the same members).
  /// Outputs: the report; solution() holds x (zero when the test accepted x0 = 0).
  /// The solve ends when the test accepts, after options.maxIterations Arnoldi steps, when
  /// the operator refuses a product, at a skipped degenerate direction, or when the true
  /// residual is not finite.
  template <class Operator, class Preconditioner, class StoppingTest>
  GmresReport solve(Operator&& applyOperator, Preconditioner&& applyPreconditioner,
                    const Eigen::Ref<const Eigen::VectorXd>& b, StoppingTest& stop);

  /// The last solve's solution.
  const Eigen::VectorXd& solution() const { return x_; }

 private:
  enum class CycleEnd { Full, Converged, OutOfIterations, Breakdown, Refused, Degenerate };

  /// One cycle from residual_ (2-norm norm2): Arnoldi steps until the test accepts the
  /// estimate or the cycle ends; returns why, and the directions kept in `directions`.
  template <class Operator, class Preconditioner, class StoppingTest>
  CycleEnd runCycle(Operator& applyOperator, Preconditioner& applyPreconditioner, double norm2,
                    StoppingTest& stop, int& iterations, int& directions);
  /// x += the cycle's least-squares combination of its first `directions` directions.
  template <class Preconditioner>
  void addCycleSolution(Preconditioner& applyPreconditioner, int directions);

  GmresOptions options_;
  Eigen::MatrixXd basis_;                ///< V: n x (restart + 1), orthonormal columns
  Eigen::MatrixXd preconditionedBasis_;  ///< flexible form: Z = M^-1 V, n x restart
  Eigen::MatrixXd hessenberg_;           ///< its upper triangle: R of the rotated Hessenberg
  Eigen::VectorXd rotatedRhs_;           ///< |r| e_1 under the rotations (residual estimates)
  Eigen::VectorXd givensCos_, givensSin_, combination_;  ///< rotations; y of R y = g
  Eigen::VectorXd x_, residual_;              ///< iterate; residual b - A x at a cycle's start
  Eigen::VectorXd preconditioned_, product_;  ///< M^-1 v (standard form); A z, then Arnoldi
};

template <class Operator, class Preconditioner, class StoppingTest>
GmresReport Gmres::solve(Operator&& applyOperator, Preconditioner&& applyPreconditioner,
                         const Eigen::Ref<const Eigen::VectorXd>& b, StoppingTest& stop) {
  GmresReport report;
  x_.setZero();
  residual_ = b;
  double norm2 = residual_.norm();
  if (stop.initiallyConverged(residual_, norm2)) {
    report.converged = true;
    return report;
  }
  bool restarted = false;
  while (true) {
    stop.startCycle(residual_, norm2, restarted);
    int directions = 0;
    const CycleEnd end =
        runCycle(applyOperator, applyPreconditioner, norm2, stop, report.iterations, directions);
    report.lastCycleDirections = directions;
    if (directions > 0)
      addCycleSolution(applyPreconditioner, directions);
    if (!stop.verifiesTrueResidual() && end != CycleEnd::Full) {
      // The estimate's verdict is final; the solve has nothing more to try.
      report.converged = end == CycleEnd::Converged || end == CycleEnd::Breakdown;
      return report;
    }
    if (end == CycleEnd::Refused || end == CycleEnd::Degenerate)
      return report;
    if (!applyOperator(x_, product_))
      return report;
    residual_ = b - product_;
    if (stop.verifiesTrueResidual() && stop.trueResidualConverged(residual_)) {
      report.converged = true;
      return report;
    }
    if (report.iterations >= options_.maxIterations || !residual_.allFinite())
      return report;
    restarted = true;
    norm2 = residual_.norm();
  }
}

template <class Operator, class Preconditioner, class StoppingTest>
Gmres::CycleEnd Gmres::runCycle(Operator& applyOperator, Preconditioner& applyPreconditioner,
                                double norm2, StoppingTest& stop, int& iterations,
                                int& directions) {
  Eigen::MatrixXd& V = basis_;
  Eigen::MatrixXd& H = hessenberg_;
  Eigen::VectorXd& g = rotatedRhs_;
  Eigen::VectorXd& q = product_;
  V.col(0) = residual_ / norm2;
  g.setZero();
  g[0] = norm2;
  int j = 0;
  while (j < options_.restart) {
    if (options_.flexible) {
      applyPreconditioner(V.col(j), preconditionedBasis_.col(j));
      if (!applyOperator(preconditionedBasis_.col(j), q))
        return CycleEnd::Refused;
    } else {
      applyPreconditioner(V.col(j), preconditioned_);
      if (!applyOperator(preconditioned_, q))
        return CycleEnd::Refused;
    }
    for (int i = 0; i <= j; ++i) {  // modified Gram-Schmidt
      H(i, j) = q.dot(V.col(i));
      q.noalias() -= H(i, j) * V.col(i);
    }
    const double hNext = q.norm();
    if (hNext > 0.0)
      V.col(j + 1) = q / hNext;
    for (int i = 0; i < j; ++i) {  // the previous Givens rotations
      const double t = givensCos_[i] * H(i, j) + givensSin_[i] * H(i + 1, j);
      H(i + 1, j) = -givensSin_[i] * H(i, j) + givensCos_[i] * H(i + 1, j);
      H(i, j) = t;
    }
    const double d = std::hypot(H(j, j), hNext);
    if (options_.skipDegenerateDirections && !(d > 0.0 && std::isfinite(d)))
      return CycleEnd::Degenerate;
    givensCos_[j] = d > 0.0 ? H(j, j) / d : 1.0;
    givensSin_[j] = d > 0.0 ? hNext / d : 0.0;
    H(j, j) = d;
    g[j + 1] = -givensSin_[j] * g[j];
    g[j] = givensCos_[j] * g[j];
    ++j;
    ++iterations;
    directions = j;
    // |g_j| is the 2-norm of the residual with the cycle's j directions.
    if (stop.estimateConverged(std::abs(g[j])))
      return CycleEnd::Converged;
    if (iterations >= options_.maxIterations)
      return CycleEnd::OutOfIterations;
    if (hNext == 0.0)
      return CycleEnd::Breakdown;
  }
  return CycleEnd::Full;
}

template <class Preconditioner>
void Gmres::addCycleSolution(Preconditioner& applyPreconditioner, int directions) {
  const int j = directions;
  const Eigen::MatrixXd& H = hessenberg_;
  Eigen::VectorXd& y = combination_;
  for (int i = j - 1; i >= 0; --i) {  // back substitution R y = g
    double t = rotatedRhs_[i];
    for (int l = i + 1; l < j; ++l)
      t -= H(i, l) * y[l];
    y[i] = t / H(i, i);
  }
  if (options_.flexible) {
    x_.noalias() += preconditionedBasis_.leftCols(j) * y.head(j);
  } else {
    product_.noalias() = basis_.leftCols(j) * y.head(j);
    applyPreconditioner(product_, preconditioned_);
    x_ += preconditioned_;
  }
}

}  // namespace pistondyn::lubrication
