#include "pistondyn/plugin/LinearlyImplicitStepper.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "pistondyn/common/Validation.h"

namespace pistondyn::plugin {
namespace {

// One accepted point of the trajectory: time and free coordinates y = (q_f, u_f, z).
struct Point {
  double t = 0.0;
  Eigen::VectorXd y;
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

  // Three states, held by pointer so that acceptance swaps pointers instead of copying:
  //  base     the start of the next step, with the history installed (after the swap of
  //           the auto-update variables): the trial of each step is a copy of it;
  //  current  the accepted state getState() returns, with the history of the step that
  //           led to it NOT yet installed, so that realizing it (an output row) evaluates
  //           the elements exactly as that step did (t - lastUpdateTime = h) and
  //           recomputes the update values there;
  //  trial    scratch for the predictor evaluation.
  // Simbody keeps update values only while q and u are unchanged, and a State copy keeps
  // only what was realized through Stage::Instance: hence the swap into the trial right
  // after its evaluation, before the corrected y is installed.
  std::unique_ptr<SimTK::State> basePtr = std::make_unique<SimTK::State>();
  std::unique_ptr<SimTK::State> currentPtr = std::make_unique<SimTK::State>();
  std::unique_ptr<SimTK::State> trialPtr = std::make_unique<SimTK::State>();
  bool currentAwaitsSwap = false;  // current holds an accepted step's end, history pending
  SimTK::Array_<SimTK::QIndex> freeQ;
  SimTK::Array_<SimTK::UIndex> freeU;
  int nq = 0, nu = 0, nz = 0, n = 0;
  Eigen::VectorXd absTol;        // per q_f, u_f entry
  std::array<Point, 3> history;  // history[0] newest accepted point
  int historySize = 0;
  Eigen::VectorXd f0;  // derivative at the initial state (first predictor)
  double hNext = 0.0;  // proposed next step
  int failuresInRow = 0;

  // Workspaces (sized at initialize).
  Eigen::VectorXd yp, fp, r, delta, y1, weights;
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

  void pack(const SimTK::State& s, Eigen::VectorXd& y) const {
    y.resize(n);
    const SimTK::Vector& q = s.getQ();
    const SimTK::Vector& u = s.getU();
    const SimTK::Vector& z = s.getZ();
    for (int i = 0; i < nq; ++i)
      y[i] = q[freeQ[i]];
    for (int i = 0; i < nu; ++i)
      y[nq + i] = u[freeU[i]];
    for (int i = 0; i < nz; ++i)
      y[nq + nu + i] = z[i];
  }

  void unpack(const Eigen::VectorXd& y, double t, SimTK::State& s) const {
    // Only a new time invalidates Stage::Time (and with it the auto-update values).
    if (s.getTime() != t)
      s.setTime(t);
    SimTK::Vector& q = s.updQ();
    for (int i = 0; i < nq; ++i)
      q[freeQ[i]] = y[i];
    SimTK::Vector& u = s.updU();
    for (int i = 0; i < nu; ++i)
      u[freeU[i]] = y[nq + i];
    if (nz > 0) {
      SimTK::Vector& z = s.updZ();
      for (int i = 0; i < nz; ++i)
        z[i] = y[nq + nu + i];
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
  bool evaluate(SimTK::State& s, std::string& reason) {
    ++stats.forceEvaluations;
    try {
      system.realize(s, SimTK::Stage::Acceleration);
    } catch (const std::exception& e) {
      reason = e.what();
      return false;
    }
    return true;
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
    std::string reason;
    if (!evaluate(current, reason))
      fail(current.getTime(), "initial state: " + reason);
    computeTolerances(current);
    derivatives(current, f0);
    current.autoUpdateDiscreteVariables();
    *basePtr = current;
    currentAwaitsSwap = false;
    history[0].t = current.getTime();
    pack(current, history[0].y);
    historySize = 1;
    hNext = std::min(options.initialStep_s, options.maxStep_s);
    failuresInRow = 0;
    M.resize(nu, nu);
    K.resize(nu, nq);
    C.resize(nu, nu);
    A.resize(nu, nu);
    weights.resize(nq + nu);
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

  void predict(double h, Eigen::VectorXd& y) const {
    const Point& p0 = history[0];
    if (historySize == 1) {
      y = p0.y + h * f0;
      return;
    }
    const Point& p1 = history[1];
    const double t = p0.t + h;
    if (historySize == 2) {
      y = p0.y + (t - p0.t) / (p0.t - p1.t) * (p0.y - p1.y);
      return;
    }
    const Point& p2 = history[2];
    // Lagrange form of the quadratic through the three points.
    const double l0 = (t - p1.t) * (t - p2.t) / ((p0.t - p1.t) * (p0.t - p2.t));
    const double l1 = (t - p0.t) * (t - p2.t) / ((p1.t - p0.t) * (p1.t - p2.t));
    const double l2 = (t - p0.t) * (t - p1.t) / ((p2.t - p0.t) * (p2.t - p1.t));
    y = l0 * p0.y + l1 * p1.y + l2 * p2.y;
  }

  // Tries one step from the newest point to t1 (h = t1 - t0). Returns true if accepted;
  // sets hNext either way.
  bool tryStep(double t1) {
    const double t0 = history[0].t, h = t1 - t0;
    const int order = historySize >= 3 ? 2 : 1;
    predict(h, yp);
    SimTK::State& trial = *trialPtr;
    trial = *basePtr;
    unpack(yp, t1, trial);
    std::string reason;
    if (!evaluate(trial, reason)) {
      ++stats.failedEvaluations;
      if (++failuresInRow > options.maxConsecutiveFailures) {
        fail(t1, "the force evaluation failed " + std::to_string(failuresInRow) +
                     " times in a row, the last at step size " + formatTime(h) + " s: " + reason);
      }
      hNext = 0.25 * h;
      return false;
    }
    derivatives(trial, fp);

    // BDF coefficients.
    double a0 = 1.0, a1 = 0.0, beta = 1.0;
    if (order == 2) {
      const double w = h / (t0 - history[1].t);
      a0 = (1.0 + w) * (1.0 + w) / (1.0 + 2.0 * w);
      a1 = -w * w / (1.0 + 2.0 * w);
      beta = (1.0 + w) / (1.0 + 2.0 * w);
    }
    const double g = beta * h;
    r = a0 * history[0].y - yp + g * fp;
    if (order == 2)
      r += a1 * history[1].y;

    // The approximate Jacobian at the predictor.
    matter.calcM(trial, mFull);
    model.calcElementForceJacobian(trial, jac);
    for (int i = 0; i < nu; ++i) {
      for (int j = 0; j < nu; ++j) {
        M(i, j) = mFull(freeU[i], freeU[j]);
        C(i, j) = jac.dfdu(freeU[i], freeU[j]);
      }
      for (int j = 0; j < nq; ++j)
        K(i, j) = jac.dfdq(freeU[i], freeQ[j]);
    }
    A = M - g * C - g * g * K;
    const Eigen::VectorXd rq = r.head(nq), ru = r.segment(nq, nu);
    const Eigen::VectorXd du = A.partialPivLu().solve(M * ru + g * (K * rq));
    delta.resize(n);
    delta.head(nq) = rq + g * du;
    delta.segment(nq, nu) = du;
    if (nz > 0)
      delta.tail(nz) = r.tail(nz);
    y1 = yp + delta;
    if (!y1.allFinite()) {
      ++stats.failedEvaluations;
      if (++failuresInRow > options.maxConsecutiveFailures) {
        fail(t1, "the step solution is not finite at step size " + formatTime(h) + " s");
      }
      hNext = 0.25 * h;
      return false;
    }

    // Local error estimate in the weighted RMS norm over (q_f, u_f).
    const double factor = std::abs(errorFactor(h, order));
    double sum = 0.0;
    for (int i = 0; i < nq + nu; ++i) {
      const double scale = absTol[i] + options.relativeTolerance *
                                           std::max(std::abs(history[0].y[i]), std::abs(y1[i]));
      const double e = factor * delta[i] / scale;
      sum += e * e;
    }
    const double err = nq + nu > 0 ? std::sqrt(sum / (nq + nu)) : 0.0;
    const double exponent = order == 2 ? 1.0 / 3.0 : 0.5;
    const double grow = err > 0.0 ? 0.9 * std::pow(err, -exponent) : 2.0;
    if (err > 1.0) {
      ++stats.rejectedSteps;
      if (++failuresInRow > options.maxConsecutiveFailures) {
        fail(t1, "the error test failed " + std::to_string(failuresInRow) +
                     " times in a row, the last at step size " + formatTime(h) + " s");
      }
      hNext = h * std::clamp(grow, 0.2, 0.9);
      return false;
    }

    // Accept. The next step starts from the predictor's history with y1 installed; the
    // state returned holds y1 with the history as it was during the step.
    failuresInRow = 0;
    ++stats.steps;
    trial.autoUpdateDiscreteVariables();
    unpack(y1, t1, trial);
    *currentPtr = *basePtr;
    unpack(y1, t1, *currentPtr);
    std::swap(basePtr, trialPtr);
    currentAwaitsSwap = true;
    history[2] = std::move(history[1]);
    history[1] = std::move(history[0]);
    history[0].t = t1;
    history[0].y = y1;
    historySize = std::min(historySize + 1, 3);
    // BDF2 stays zero-stable for step ratios below 1 + sqrt(2); keep below 2.
    hNext = h * std::clamp(grow, 0.2, 2.0);
    return true;
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
      // The step starts. If the accepted state was realized since (an output row), its
      // update values are the better ones (computed at y1, not at the predictor): start
      // from it with them installed.
      if (currentAwaitsSwap && currentPtr->getSystemStage() >= SimTK::Stage::Dynamics) {
        currentPtr->autoUpdateDiscreteVariables();
        *basePtr = *currentPtr;
      }
      currentAwaitsSwap = false;
      double h = std::min(hNext, options.maxStep_s);
      const double remaining = tOut - history[0].t;
      if (h >= remaining * (1.0 - 1e-12)) {
        h = remaining;
      } else if (h > 0.5 * remaining) {
        h = 0.5 * remaining;  // two even steps rather than a long one and a sliver
      }
      if (h < options.minStep_s) {
        fail(history[0].t, "the step size fell to " + formatTime(h) + " s (below the minimum " +
                               formatTime(options.minStep_s) + " s)");
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
