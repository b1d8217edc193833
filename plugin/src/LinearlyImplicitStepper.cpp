#include "pistondyn/plugin/LinearlyImplicitStepper.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "pistondyn/common/Validation.h"

namespace pistondyn::plugin {
namespace {

// Jacobian reuse: the share of newtonTolerance below which an iterate corrected with a kept
// (not freshly evaluated) damping C is accepted. A factor 2 covers the squeeze damping halving
// over the reuse window (the film opening by 26 %); a larger change shows as a second Newton
// iteration, which takes a fresh Jacobian.
constexpr double kKeptJacobianAcceptance = 0.5;

// One accepted point of the trajectory: time, free coordinates y = (q_f, u_f, z) and their
// time derivatives f there (every accepted point is evaluated).
struct Point {
  double t = 0.0;
  Eigen::VectorXd y, f;
};

// Times and step sizes in messages: the shortest text that reads back to the same double.
std::string formatTime(double t) {
  return common::formatNumber(t);
}

}  // namespace

struct LinearlyImplicitStepper::Impl {
  const PistonAssemblyModel& model;
  const SimTK::MultibodySystem& system;
  const SimTK::SimbodyMatterSubsystem& matter;
  LinearlyImplicitStepperOptions options;
  LinearlyImplicitStepperStats stats;
  FailureDescriber describe;

  // Two states, held by pointer so that acceptance swaps pointers instead of copying:
  //  current  the accepted state getState() returns: the evaluated iterate of the last step,
  //           realized, with the history of that step installed (the auto-update variables
  //           swapped in place: the swap and the corrected z invalidate Stage::Dynamics only,
  //           so the element results cached at that state stay valid and an output row
  //           reads them instead of evaluating the elements again); every iterate of the
  //           next step is a copy of it;
  //  trial    the iterate being evaluated.
  // Simbody keeps update values only while t, q and u are unchanged, and a State copy keeps
  // only what was realized through Stage::Instance: hence the swap in place in the
  // evaluated iterate itself.
  std::unique_ptr<SimTK::State> currentPtr = std::make_unique<SimTK::State>();
  std::unique_ptr<SimTK::State> trialPtr = std::make_unique<SimTK::State>();
  SimTK::Array_<SimTK::QIndex> freeQ;
  SimTK::Array_<SimTK::UIndex> freeU;
  int nq = 0, nu = 0, nz = 0, n = 0;
  Eigen::VectorXd absTol;        // per q_f, u_f entry
  std::array<Point, 4> history;  // history[0] newest accepted point (4 for the third order)
  int historySize = 0;
  double hNext = 0.0;  // proposed next step
  int failuresInRow = 0;
  int jacobianAge = 0;             // accepted steps since C was evaluated
  bool freshJacobianNext = false;  // a step failed since: evaluate C again
  // Why the last step failed, since the last accepted one ("" if none did): for the message
  // when the step collapses.
  std::string lastFailure;

  // Workspaces (sized at initialize).
  Eigen::VectorXd yp, fpred, ft, base, r, delta, y, weights;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;  // of A = M - g C - g^2 K for the current g
  Eigen::MatrixXd M, K, C, A;
  SimTK::Matrix mFull;
  ForceJacobian jac;

  Impl(const PistonAssemblyModel& m, const LinearlyImplicitStepperOptions& o)
      : model(m), system(m.getSystem()), matter(m.getMatter()), options(o) {}

  [[noreturn]] void fail(double t, const std::string& reason) const {
    throw std::runtime_error(describe ? describe(t, reason)
                                      : "LinearlyImplicitStepper: at t = " + formatTime(t) +
                                            " s: " + reason);
  }

  void pack(const SimTK::State& s, Eigen::VectorXd& packed) const {
    packed.resize(n);
    const SimTK::Vector& q = s.getQ();
    const SimTK::Vector& u = s.getU();
    const SimTK::Vector& z = s.getZ();
    for (int i = 0; i < nq; ++i)
      packed[i] = q[freeQ[i]];
    for (int i = 0; i < nu; ++i)
      packed[nq + i] = u[freeU[i]];
    for (int i = 0; i < nz; ++i)
      packed[nq + nu + i] = z[i];
  }

  void unpack(const Eigen::VectorXd& packed, double t, SimTK::State& s) const {
    // Only a new time invalidates Stage::Time (and with it the auto-update values).
    if (s.getTime() != t)
      s.setTime(t);
    SimTK::Vector& q = s.updQ();
    for (int i = 0; i < nq; ++i)
      q[freeQ[i]] = packed[i];
    SimTK::Vector& u = s.updU();
    for (int i = 0; i < nu; ++i)
      u[freeU[i]] = packed[nq + i];
    if (nz > 0) {
      SimTK::Vector& z = s.updZ();
      for (int i = 0; i < nz; ++i)
        z[i] = packed[nq + nu + i];
    }
    system.prescribe(s);
  }

  void derivatives(const SimTK::State& s, Eigen::VectorXd& f) const {
    f.resize(n);
    const SimTK::Vector& qdot = s.getQDot();
    const SimTK::Vector& udot = s.getUDot();
    for (int i = 0; i < nq; ++i)
      f[i] = qdot[freeQ[i]];
    for (int i = 0; i < nu; ++i)
      f[nq + i] = udot[freeU[i]];
    if (nz > 0) {
      const SimTK::Vector& zdot = s.getZDot();
      for (int i = 0; i < nz; ++i)
        f[nq + nu + i] = zdot[i];
    }
  }

  // Pose levers: how far the piston pose moves per unit of each free coordinate [m].
  void computeTolerances(const SimTK::State& s) {
    const mbd::CrankTrain& ct = model.getCrankTrain();
    const SimTK::MobilizedBodyIndex piston = ct.getPiston().getMobilizedBodyIndex();
    const double skirt = ct.getEngine().piston.skirtLength_m;
    absTol.resize(nq + nu);
    SimTK::Vector unit(s.getNU(), 0.0);
    for (int i = 0; i < nu; ++i) {
      unit = 0.0;
      unit[freeU[i]] = 1.0;
      const SimTK::SpatialVec v = matter.multiplyByFrameJacobian(s, piston, SimTK::Vec3(0), unit);
      const double w = v[0][2] * skirt;  // tilt rate times the skirt length
      double lever = std::sqrt(v[1].normSqr() + w * w);
      lever = std::max(lever, 1e-3);  // a coordinate that barely moves the piston: 1 mm lever
      absTol[i] = options.positionTolerance_m / lever;
      absTol[nq + i] = options.velocityTolerance_mps / lever;
    }
  }

  // Realizes `s` through Acceleration; false (and the reason) if an element threw.
  // withJacobian: whether the elements' Jacobian will be read at `s` (updateJacobian).
  bool evaluate(SimTK::State& s, std::string& reason, bool withJacobian = true) {
    ++stats.forceEvaluations;
    if (withJacobian)
      ++stats.jacobianEvaluations;
    model.setForceJacobianWanted(withJacobian);
    bool ok = true;
    const auto start = std::chrono::steady_clock::now();
    try {
      system.realize(s, SimTK::Stage::Acceleration);
    } catch (const std::exception& e) {
      reason = e.what();
      ok = false;
    }
    stats.realizeTime_s +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    model.setForceJacobianWanted(true);  // anyone else realizing gets the default
    return ok;
  }

  void initialize(const SimTK::State& s0) {
    SimTK::State& current = *currentPtr;
    current = s0;
    system.realize(current, SimTK::Stage::Instance);
    for (SimTK::ConstraintIndex c(0); c < matter.getNumConstraints(); ++c) {
      if (!matter.getConstraint(c).isDisabled(current)) {
        throw std::invalid_argument(
            "LinearlyImplicitStepper: the model has enabled constraints (e.g. the ideal liner "
            "guide); use a Simbody integrator for it");
      }
    }
    freeQ = matter.getFreeQIndex(current);
    freeU = matter.getFreeUIndex(current);
    if (current.getNQ() != current.getNU() || freeQ.size() != freeU.size()) {
      throw std::invalid_argument(
          "LinearlyImplicitStepper: needs mobilizers with qdot = u (no quaternions)");
    }
    nq = static_cast<int>(freeQ.size());
    nu = static_cast<int>(freeU.size());
    nz = current.getNZ();
    n = nq + nu + nz;
    system.prescribe(current);
    M.resize(nu, nu);
    K.resize(nu, nq);
    C.resize(nu, nu);
    A.resize(nu, nu);
    weights.resize(nq + nu);
    std::string reason;
    if (!evaluate(current, reason))
      fail(current.getTime(), "initial state: " + reason);
    computeTolerances(current);
    updateJacobian(current);
    history[0].t = current.getTime();
    pack(current, history[0].y);
    derivatives(current, history[0].f);
    current.autoUpdateDiscreteVariables();
    historySize = 1;
    hNext = std::min(options.initialStep_s, options.maxStep_s);
    failuresInRow = 0;
  }

  // M, K = d f_gen / d q and C = d f_gen / d u of the free mobilities at an evaluated state
  // (the elements' parts, ForceElement::addForceJacobian).
  void updateJacobian(const SimTK::State& s) {
    updateMassAndStiffness(s);
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nu; ++j)
        C(i, j) = jac.dfdu(freeU[i], freeU[j]);
    jacobianAge = 0;
    freshJacobianNext = false;
  }
  // M and K (an evaluation without the elements' damping part: C is kept; K, the contact
  // stiffness that switches within a step, is cheap and read at every evaluation).
  void updateMassAndStiffness(const SimTK::State& s) {
    matter.calcM(s, mFull);
    model.calcElementForceJacobian(s, jac);  // its dfdu may be NaN here: not read
    for (int i = 0; i < nu; ++i) {
      for (int j = 0; j < nu; ++j)
        M(i, j) = mFull(freeU[i], freeU[j]);
      for (int j = 0; j < nq; ++j)
        K(i, j) = jac.dfdq(freeU[i], freeQ[j]);
    }
  }

  // Solves (I - g W) d = rhs for W = [[0, I, 0], [M^-1 K, M^-1 C, 0], [0, 0, 0]] with the
  // factorisation `lu` of A = M - g C - g^2 K.
  void solveCorrection(double g, const Eigen::VectorXd& rhs, Eigen::VectorXd& d) const {
    const Eigen::VectorXd rq = rhs.head(nq), ru = rhs.segment(nq, nu);
    const Eigen::VectorXd du = lu.solve(M * ru + g * (K * rq));
    d.resize(n);
    d.head(nq) = rq + g * du;
    d.segment(nq, nu) = du;
    if (nz > 0)
      d.tail(nz) = rhs.tail(nz);
  }

  // Weighted RMS norm of v over (q_f, u_f) in units of the absolute tolerances.
  double weightedNorm(const Eigen::VectorXd& v, double scale) const {
    double sum = 0.0;
    for (int i = 0; i < nq + nu; ++i) {
      const double tol = absTol[i] + options.relativeTolerance *
                                         std::max(std::abs(history[0].y[i]), std::abs(y[i]));
      const double e = scale * v[i] / tol;
      sum += e * e;
    }
    return nq + nu > 0 ? std::sqrt(sum / (nq + nu)) : 0.0;
  }

  // The pose part of a step's local error estimate `scale` v [m]: the largest over the free q
  // of the error times its pose lever (positionTolerance_m / absTol).
  double poseError(const Eigen::VectorXd& v, double scale) const {
    double largest = 0.0;
    for (int i = 0; i < nq; ++i)
      largest = std::max(largest, std::abs(scale * v[i]) * options.positionTolerance_m / absTol[i]);
    return largest;
  }

  // Error constants (solution error / y''' or y'') of the corrector and of the predictor
  // for the current step pattern; the estimate is Ec / (Ec - Ep) * (y1 - yp).
  double errorFactor(double h, int order) const {
    if (order == 1) {
      if (historySize == 1)
        return 0.5;  // backward Euler with the Euler predictor
      const double h1 = history[0].t - history[1].t;
      return h / (2.0 * h + h1);  // backward Euler with linear extrapolation
    }
    const double h1 = history[0].t - history[1].t;
    const double h2 = history[1].t - history[2].t;
    const double w = h / h1;
    const double a1 = -w * w / (1.0 + 2.0 * w), beta = (1.0 + w) / (1.0 + 2.0 * w);
    const double ec = -(h * h * h / 6.0 + a1 * h1 * h1 * h1 / 6.0 - beta * h * h * h / 2.0);
    const double ep = -h * (h + h1) * (h + h1 + h2) / 6.0;
    return ec / (ec - ep);
  }

  // Variable-step BDF3 (maxOrder 3): y1 = sum_j c_j y_{n+1-j} + g f(y1) from the derivative
  // at t1 of the cubic through t1 and the last three accepted points: alpha_j = l_j'(t1) of
  // its Lagrange basis, g = 1 / alpha_0, c_j = -alpha_j / alpha_0. Also the error factor
  // Ec / (Ec - Ep) of the estimate, with Ec = -sum_{j>=1} alpha_j (t_j - t1)^4 / alpha_0 (the
  // corrector's local error per unit y^(4) / 4!) and Ep = -prod_{j=0..3} (t1 - t_j) (the cubic
  // predictor's). For BDF2 the same construction gives errorFactor above (checked: 2/11 for
  // constant steps); BDF3 with constant steps: g = 6 h / 11, factor 0.12.
  void bdf3Coefficients(double t1, std::array<double, 3>& c, double& g, double& factor) const {
    const std::array<double, 4> tau = {t1, history[0].t, history[1].t, history[2].t};
    std::array<double, 4> alpha{};
    alpha[0] = 1.0 / (t1 - tau[1]) + 1.0 / (t1 - tau[2]) + 1.0 / (t1 - tau[3]);
    for (int j = 1; j < 4; ++j) {
      double num = 1.0, den = 1.0;
      for (int m = 1; m < 4; ++m)
        if (m != j)
          num *= t1 - tau[m];
      for (int m = 0; m < 4; ++m)
        if (m != j)
          den *= tau[j] - tau[m];
      alpha[j] = num / den;
    }
    g = 1.0 / alpha[0];
    double ec = 0.0;
    for (int j = 1; j < 4; ++j) {
      c[j - 1] = -alpha[j] * g;
      const double d = tau[j] - t1;
      ec -= alpha[j] * d * d * d * d * g;
    }
    const double ep = -(t1 - history[0].t) * (t1 - history[1].t) * (t1 - history[2].t) *
                      (t1 - history[3].t);
    factor = ec / (ec - ep);
  }

  // Extrapolates the accepted points' y and f to t0 + h (the same polynomial weights).
  void predict(double h, Eigen::VectorXd& yOut, Eigen::VectorXd& fOut) const {
    const Point& p0 = history[0];
    if (historySize == 4) {  // maxOrder 3: the cubic through the four points
      const double t = p0.t + h;
      std::array<double, 4> l{};
      for (int j = 0; j < 4; ++j) {
        l[j] = 1.0;
        for (int m = 0; m < 4; ++m)
          if (m != j)
            l[j] *= (t - history[m].t) / (history[j].t - history[m].t);
      }
      yOut = l[0] * p0.y + l[1] * history[1].y + l[2] * history[2].y + l[3] * history[3].y;
      fOut = l[0] * p0.f + l[1] * history[1].f + l[2] * history[2].f + l[3] * history[3].f;
      return;
    }
    if (historySize == 1) {
      yOut = p0.y + h * p0.f;
      fOut = p0.f;
      return;
    }
    const Point& p1 = history[1];
    const double t = p0.t + h;
    if (historySize == 2) {
      const double w = (t - p0.t) / (p0.t - p1.t);
      yOut = p0.y + w * (p0.y - p1.y);
      fOut = p0.f + w * (p0.f - p1.f);
      return;
    }
    const Point& p2 = history[2];
    // Lagrange form of the quadratic through the three points.
    const double l0 = (t - p1.t) * (t - p2.t) / ((p0.t - p1.t) * (p0.t - p2.t));
    const double l1 = (t - p0.t) * (t - p2.t) / ((p1.t - p0.t) * (p1.t - p2.t));
    const double l2 = (t - p0.t) * (t - p1.t) / ((p2.t - p0.t) * (p2.t - p1.t));
    yOut = l0 * p0.y + l1 * p1.y + l2 * p2.y;
    fOut = l0 * p0.f + l1 * p1.f + l2 * p2.f;
  }

  // A step that did not work out: count it, give up after too many in a row, retry shorter.
  bool retry(double t1, double h, double shrink, const std::string& what) {
    if (++failuresInRow > options.maxConsecutiveFailures) {
      fail(t1, what + " " + std::to_string(failuresInRow) +
                   " times in a row, the last at step size " + formatTime(h) + " s");
    }
    hNext = shrink * h;
    lastFailure = what;
    freshJacobianNext = true;
    return false;
  }

  // Tries one step from the newest point to t1 (h = t1 - t0). Returns true if accepted;
  // sets hNext either way.
  bool tryStep(double t1) {
    const double t0 = history[0].t, h = t1 - t0;
    const int order = historySize == 4 ? 3 : (historySize >= 3 ? 2 : 1);
    predict(h, yp, fpred);

    // BDF coefficients: y1 = base + g f(y1); base = a0 y_n + a1 y_{n-1} (orders 1 and 2) or
    // c3 on the last three points (order 3).
    double g = h, factor3 = 0.0;
    if (order == 3) {
      std::array<double, 3> c3{};
      bdf3Coefficients(t1, c3, g, factor3);
      base = c3[0] * history[0].y + c3[1] * history[1].y + c3[2] * history[2].y;
    } else {
      double a0 = 1.0, a1 = 0.0;
      if (order == 2) {
        const double w = h / (t0 - history[1].t);
        a0 = (1.0 + w) * (1.0 + w) / (1.0 + 2.0 * w);
        a1 = -w * w / (1.0 + 2.0 * w);
        g = (1.0 + w) / (1.0 + 2.0 * w) * h;
      }
      base = a0 * history[0].y;
      if (order == 2)
        base += a1 * history[1].y;
    }

    // First iterate: one linearised step from the predictor with the extrapolated
    // derivative and the Jacobian of the last evaluated state (no evaluation yet).
    A = M - g * C - g * g * K;
    lu.compute(A);
    r = base + g * fpred - yp;
    solveCorrection(g, r, delta);
    y = yp + delta;

    // Newton iterations: evaluate the iterate, correct it with the BDF residual there.
    SimTK::State& trial = *trialPtr;
    double previousNorm = 0.0;
    bool previousFresh = true;
    for (int it = 1;; ++it) {
      if (!y.allFinite())
        return retry(t1, h, 0.25, "the step solution was not finite");
      trial = *currentPtr;
      unpack(y, t1, trial);
      std::string reason;
      // Jacobian reuse (options.jacobianReuseSteps): the first evaluation of a step keeps the
      // elements' C while it is young enough and nothing failed since; a second Newton
      // iteration always gets it fresh.
      const bool withJacobian = options.jacobianReuseSteps == 0 || it > 1 || freshJacobianNext ||
                                jacobianAge > options.jacobianReuseSteps;
      if (!evaluate(trial, reason, withJacobian)) {
        ++stats.failedEvaluations;
        return retry(t1, h, 0.25, "the force evaluation failed (" + reason + ")");
      }
      derivatives(trial, ft);
      if (withJacobian)
        updateJacobian(trial);
      else
        updateMassAndStiffness(trial);
      A = M - g * C - g * g * K;
      lu.compute(A);
      r = base + g * ft - y;
      solveCorrection(g, r, delta);
      const double norm = weightedNorm(delta, 1.0);
      // A kept C may overstate the squeeze damping (the film has opened since: C ~ 1/h^3),
      // which shrinks the correction: on a kept Jacobian the iterate is accepted only below
      // kKeptJacobianAcceptance of the tolerance.
      if (norm <= options.newtonTolerance * (withJacobian ? 1.0 : kKeptJacobianAcceptance))
        break;  // converged: the evaluated iterate is the step's solution
      if (!withJacobian && it >= options.maxNewtonIterations) {
        // No iteration left to take with a fresh Jacobian: the same step again, with one.
        ++stats.newtonFailures;
        return retry(t1, h, 1.0, "the step's Newton iteration on a kept Jacobian did not converge");
      }
      // The contraction test compares corrections of the same Jacobian only.
      if (it >= options.maxNewtonIterations ||
          (it > 1 && previousFresh && norm > 0.9 * previousNorm)) {
        ++stats.newtonFailures;
        return retry(t1, h, 0.25, "the step's Newton iteration did not converge");
      }
      previousNorm = norm;
      previousFresh = withJacobian;
      y += delta;
    }
    // The z are quadratures: the BDF formula with the rates of the evaluated solution.
    if (nz > 0)
      y.tail(nz) = base.tail(nz) + g * ft.tail(nz);

    // Local error estimate from the corrector-predictor difference.
    delta = y - yp;
    const double errorScale = std::abs(order == 3 ? factor3 : errorFactor(h, order));
    const double err = weightedNorm(delta, errorScale);
    const double exponent = 1.0 / (order + 1);
    const double grow = err > 0.0 ? 0.9 * std::pow(err, -exponent) : 2.0;
    if (err > 1.0) {
      ++stats.rejectedSteps;
      return retry(t1, h, std::clamp(grow, 0.2, 0.9), "the error test failed");
    }

    // Accept the evaluated iterate with the history of this step installed.
    failuresInRow = 0;
    lastFailure.clear();
    ++stats.steps;
    stats.poseErrorSum_m += poseError(delta, errorScale);
    ++jacobianAge;
    trial.autoUpdateDiscreteVariables();
    if (nz > 0)
      setZ(y, trial);
    std::swap(currentPtr, trialPtr);
    history[3] = std::move(history[2]);
    history[2] = std::move(history[1]);
    history[1] = std::move(history[0]);
    history[0].t = t1;
    history[0].y = y;
    history[0].f = ft;
    historySize = std::min(historySize + 1, options.maxOrder + 1);
    // BDF2 stays zero-stable for step ratios below 1 + sqrt(2): keep below 2. Variable-step
    // BDF3 is zero-stable for a steady ratio below about 1.6 (1.6: a perturbation of y' = 0
    // decays only by 0.98 per step; 1.7 grows by 1.09). Its rule here: at most 2 after a step
    // that did not grow (by more than 1 %: the steps are differences of rounded times), else
    // 1.5. Checked on the homogeneous recurrence over every repeating pattern of up to four
    // ratios the rule allows (review, 2026-12-05): the slowest decay is a steady 1.5 (0.878 per
    // step), then 1, 2, 1.5, 1.5 (0.870) and 2, 1 (0.790). The doubling lets the steps reach
    // the output interval: stepTo splits a step a little shorter than the rest of an interval
    // into two halves, and with growth capped at 1.5 steps of half an interval would repeat.
    const bool grewLastTime = historySize >= 3 && h > 1.01 * (history[1].t - history[2].t);
    const double maxRatio = options.maxOrder == 3 && grewLastTime ? 1.5 : 2.0;
    hNext = h * std::clamp(grow, 0.2, maxRatio);
    return true;
  }

  void setZ(const Eigen::VectorXd& v, SimTK::State& s) const {
    SimTK::Vector& z = s.updZ();
    for (int i = 0; i < nz; ++i)
      z[i] = v[nq + nu + i];
  }

  void stepTo(double tOut) {
    if (!(tOut > history[0].t)) {
      if (tOut == history[0].t)
        return;
      throw std::invalid_argument(
          "LinearlyImplicitStepper::stepTo: tOut is before the current time");
    }
    while (history[0].t < tOut) {
      if (stats.steps >= options.maxSteps) {
        fail(history[0].t,
             "the step budget of " + std::to_string(options.maxSteps) + " steps is used up");
      }
      double h = std::min(hNext, options.maxStep_s);
      const double remaining = tOut - history[0].t;
      if (h >= remaining * (1.0 - 1e-12)) {
        h = remaining;
      } else if (h > 0.5 * remaining) {
        h = 0.5 * remaining;  // two even steps rather than a long one and a sliver
      }
      if (h < options.minStep_s) {
        // Either steps kept failing, or the caller asked for a time closer than the minimum
        // step (a free crank landing on an output crank angle iterates the time that finely).
        const std::string why =
            !lastFailure.empty()
                ? "the last failed step: " + lastFailure
                : "no step failed since the last accepted one: the time asked for, t = " +
                      formatTime(tOut) + " s, is only " + formatTime(remaining) +
                      " s ahead of it (a free crank landing on an output crank angle asks for "
                      "such times)";
        fail(history[0].t, "the step size fell to " + formatTime(h) + " s (below the minimum " +
                               formatTime(options.minStep_s) + " s); " + why);
      }
      // Land exactly on tOut (no rounding drift of the time).
      tryStep(h == remaining ? tOut : history[0].t + h);
    }
  }
};

LinearlyImplicitStepper::LinearlyImplicitStepper(const PistonAssemblyModel& model,
                                                 const LinearlyImplicitStepperOptions& o)
    : impl_(std::make_unique<Impl>(model, o)) {
  auto bad = [](const char* what) {
    throw std::invalid_argument(std::string("LinearlyImplicitStepperOptions: ") + what);
  };
  if (!(o.positionTolerance_m > 0.0) || !std::isfinite(o.positionTolerance_m))
    bad("positionTolerance_m must be positive and finite");
  if (!(o.velocityTolerance_mps > 0.0) || !std::isfinite(o.velocityTolerance_mps))
    bad("velocityTolerance_mps must be positive and finite");
  if (!(o.relativeTolerance >= 0.0 && o.relativeTolerance < 1.0))
    bad("relativeTolerance must be in [0, 1)");
  if (!(o.minStep_s > 0.0 && o.minStep_s <= o.initialStep_s && o.initialStep_s <= o.maxStep_s) ||
      !std::isfinite(o.maxStep_s))
    bad("steps must satisfy 0 < minStep_s <= initialStep_s <= maxStep_s < inf");
  if (o.maxSteps < 1)
    bad("maxSteps must be at least 1");
  if (o.maxConsecutiveFailures < 1)
    bad("maxConsecutiveFailures must be at least 1");
  if (!(o.newtonTolerance > 0.0) || !std::isfinite(o.newtonTolerance))
    bad("newtonTolerance must be positive and finite");
  if (o.maxNewtonIterations < 1)
    bad("maxNewtonIterations must be at least 1");
  if (o.maxOrder != 2 && o.maxOrder != 3)
    bad("maxOrder must be 2 or 3");
  if (o.jacobianReuseSteps < 0)
    bad("jacobianReuseSteps must be 0 or positive");
}

LinearlyImplicitStepper::~LinearlyImplicitStepper() = default;

void LinearlyImplicitStepper::initialize(const SimTK::State& state) {
  impl_->initialize(state);
}
void LinearlyImplicitStepper::stepTo(double tOut) {
  impl_->stepTo(tOut);
}
double LinearlyImplicitStepper::getTime() const {
  return impl_->history[0].t;
}
const SimTK::State& LinearlyImplicitStepper::getState() const {
  return *impl_->currentPtr;
}
const LinearlyImplicitStepperStats& LinearlyImplicitStepper::getStats() const {
  return impl_->stats;
}
const LinearlyImplicitStepperOptions& LinearlyImplicitStepper::getOptions() const {
  return impl_->options;
}
void LinearlyImplicitStepper::setFailureDescriber(FailureDescriber describer) {
  impl_->describe = std::move(describer);
}

}  // namespace pistondyn::plugin
