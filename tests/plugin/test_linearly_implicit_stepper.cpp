// LinearlyImplicitStepper on a stiff model: the piston held by a squeeze-film-like damper
// (damping ~ 1/h^3 at two heights of the skirt, so the lateral and tilt motion are both
// stiff) and a steep repulsion near the walls. Checked against Simbody's CPodes BDF
// integrator run at a tight tolerance (an independent implementation with its own
// finite-difference Jacobians), for second-order convergence under step refinement, and
// for the history semantics of auto-update variables.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "WearingSpringLiner.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/GasForceElement.h"
#include "pistondyn/plugin/IdealLinerGuide.h"
#include "pistondyn/plugin/LinearlyImplicitStepper.h"
#include "pistondyn/plugin/PistonAssemblyModel.h"
#include "pistondyn/plugin/PistonPose.h"

namespace {

using namespace pistondyn;

mbd::EngineDescription testEngine() {
  mbd::EngineDescription e;
  e.name = "stiff";
  e.geometry.crankRadius_m = 0.04;
  e.geometry.conrodLength_m = 0.14;
  e.geometry.pinOffset_m = 0.0005;
  e.piston = {0.08, 0.03, 0.04, 0.01};
  e.mass.crank = {2, 0, -0.01, 3e-3};
  e.mass.conrod = {0.5, 0, 0.04, 2e-3};
  e.mass.pin = {0.06, 0, 0, 5e-6};
  e.mass.piston = {0.25, 0, 0.005, 2e-4};
  e.drive.speed_radps = 2000 * M_PI / 30;
  return e;
}

mbd::CylinderPressureCurve testPressure() {
  std::vector<double> a, p;
  for (int i = 0; i < 720; ++i) {
    a.push_back(i);
    const double d = std::min(std::abs(i - 10.0), std::abs(i - 730.0));
    p.push_back(1e5 + 40e5 * std::exp(-d * d / 900.0));
  }
  return mbd::CylinderPressureCurve(a, p);
}

// Squeeze dampers at the skirt top and bottom: F_k = -c0 [(c/h+)^3 + (c/h-)^3] dx_k/dt
// with h+- = c -+ x_k and x_k = e + y_k alpha; a repulsion A [exp(-h-/l) - exp(-h+/l)]
// keeps the skirt off the walls; a soft spring-damper holds the tertiary motion. The
// exact squeeze damping and repulsion stiffness are given as the force Jacobian; the
// change of the damping coefficient with x is left out (as for the real film).
class SqueezeDamperGuide final : public plugin::LinerElement {
 public:
  struct Parameters {
    double clearance_m = 20e-6;
    double dampingAtCentre_Nspm = 2e4;  // c0 per height: time constant m / c ~ 1e-5 s centred
    double repulsion_N = 50.0;          // A
    double repulsionLength_m = 1e-6;    // l
    double gapFloor_m = 0.2e-6;         // smooth floor of the squeeze gaps
    double tertiaryStiffness_Npm = 1e6, tertiaryDamping_Nspm = 200.0;
  };
  explicit SqueezeDamperGuide(const Parameters& p) : p_(p) {}
  std::string getName() const override { return "squeeze_damper_guide"; }
  void addToModel(const plugin::ModelBuildContext& c) override {
    ct_ = &c.crankTrain;
    const auto& pg = ct_->getEngine().piston;
    heights_ = {pg.skirtTopAbovePin_m, pg.skirtTopAbovePin_m - pg.skirtLength_m};
  }
  void realizeTopology(SimTK::State&, plugin::ElementStateAllocator& a) const override {
    cache_.allocate(a);
  }
  void calcForces(const SimTK::State& s, plugin::AppliedForces& forces) const override {
    const Results& r = getResults(s);
    plugin::applyPoseForces(*ct_, s, r.Q, 0.0, 0.0, forces);
  }
  bool addForceJacobian(const SimTK::State& s, plugin::ForceJacobian& j) const override {
    const Results& r = getResults(s);
    plugin::addPoseForceJacobian(*ct_, s, r.dQ_dp, r.dQ_dpdot, j);
    return true;
  }
  // Like the lubricated skirt: an evaluation that is told no leaves the damping part out
  // (NaN: should the stepper read it, its steps turn NaN and the test fails).
  void setForceJacobianWanted(bool wanted) const override { wanted_ = wanted; }
  long getEvaluationsWithoutJacobian() const { return withoutJacobian_; }
  double getSideForce_N(const SimTK::State& s) const override { return -getResults(s).Q[0]; }
  // Smallest gap of the four squeeze gaps [m] (to see how close the skirt comes).
  double getMinGap_m(const SimTK::State& s) const { return getResults(s).minGap_m; }

 private:
  struct Results {
    Eigen::Vector3d Q = Eigen::Vector3d::Zero();
    Eigen::Matrix3d dQ_dp = Eigen::Matrix3d::Zero(), dQ_dpdot = Eigen::Matrix3d::Zero();
    double minGap_m = 0.0;
  };
  double floorGap(double h) const {  // smooth, >= gapFloor
    const double f = p_.gapFloor_m;
    return 0.5 * (h + f + std::sqrt((h - f) * (h - f) + f * f));
  }
  const Results& getResults(const SimTK::State& s) const {
    return cache_.getOrCalc(s, [&](Results& r) {
      const plugin::PistonPose pose = plugin::calcPistonPose(*ct_, s);
      r = Results();
      r.minGap_m = 1.0;
      const double c = p_.clearance_m;
      for (double y : heights_) {
        const double x = pose.lateral_m + y * pose.tilt_rad;
        const double xdot = pose.lateralRate_mps + y * pose.tiltRate_radps;
        const double hp = floorGap(c - x), hm = floorGap(c + x);
        r.minGap_m = std::min({r.minGap_m, c - x, c + x});
        const double damping =
            p_.dampingAtCentre_Nspm * (std::pow(c / hp, 3) + std::pow(c / hm, 3));
        const double ep = std::exp(-(c - x) / p_.repulsionLength_m);
        const double em = std::exp(-(c + x) / p_.repulsionLength_m);
        const double f = -damping * xdot + p_.repulsion_N * (em - ep);
        const double stiffness = p_.repulsion_N / p_.repulsionLength_m * (em + ep);  // -dF/dx
        const Eigen::Vector3d dxdp(1.0, y, 0.0);  // x = e + y alpha
        r.Q += f * dxdp;
        r.dQ_dpdot -= damping * dxdp * dxdp.transpose();
        r.dQ_dp -= stiffness * dxdp * dxdp.transpose();
      }
      r.Q[2] = -p_.tertiaryStiffness_Npm * pose.transverse_m -
               p_.tertiaryDamping_Nspm * pose.transverseRate_mps;
      r.dQ_dp(2, 2) = -p_.tertiaryStiffness_Npm;
      r.dQ_dpdot(2, 2) = -p_.tertiaryDamping_Nspm;
      if (!wanted_) {
        r.dQ_dpdot.setConstant(std::numeric_limits<double>::quiet_NaN());
        ++withoutJacobian_;
      }
    });
  }
  Parameters p_;
  mutable bool wanted_ = true;
  mutable long withoutJacobian_ = 0;
  const mbd::CrankTrain* ct_ = nullptr;
  std::array<double, 2> heights_{};
  plugin::ElementCache<Results> cache_;
};

struct Model {
  Model() : model(testEngine()) {
    model.addElement(std::make_unique<plugin::GasForceElement>(testPressure(), 1e5));
    model.addElement(std::make_unique<SqueezeDamperGuide>(SqueezeDamperGuide::Parameters{}));
    start = model.getDefaultState();
    model.getCrankTrain().setPose(start, 0.0);
    model.getCrankTrain().setRates(start, testEngine().drive.speed_radps);
  }
  plugin::PistonAssemblyModel model;
  SimTK::State start;
};

constexpr double kDegree_s = (M_PI / 180.0) / (2000 * M_PI / 30);  // time of 1 deg at 2000 rpm

// Lateral displacement and tilt at every 5 deg over [0, 180] deg with our stepper.
std::vector<Eigen::Vector2d> runStepper(Model& m, const plugin::LinearlyImplicitStepperOptions& o,
                                        plugin::LinearlyImplicitStepperStats* stats = nullptr) {
  plugin::LinearlyImplicitStepper stepper(m.model, o);
  stepper.initialize(m.start);
  std::vector<Eigen::Vector2d> out;
  const auto& ct = m.model.getCrankTrain();
  for (int k = 1; k <= 36; ++k) {
    stepper.stepTo(m.start.getTime() + 5.0 * k * kDegree_s);
    const SimTK::State& s = stepper.getState();
    m.model.getSystem().realize(s, SimTK::Stage::Position);
    out.emplace_back(ct.getLateralDisplacement_m(s), ct.getTilt_rad(s));
  }
  if (stats)
    *stats = stepper.getStats();
  return out;
}

std::vector<Eigen::Vector2d> runCpodes(Model& m, double accuracy) {
  SimTK::CPodesIntegrator integ(m.model.getSystem(), SimTK::CPodes::BDF, SimTK::CPodes::Newton);
  integ.setAccuracy(accuracy);
  integ.initialize(m.start);
  std::vector<Eigen::Vector2d> out;
  const auto& ct = m.model.getCrankTrain();
  for (int k = 1; k <= 36; ++k) {
    const double t = m.start.getTime() + 5.0 * k * kDegree_s;
    while (integ.getTime() < t)
      integ.stepTo(t);
    const SimTK::State& s = integ.getState();
    out.emplace_back(ct.getLateralDisplacement_m(s), ct.getTilt_rad(s));
  }
  return out;
}

// Largest difference in lateral displacement [m] and in tilt times the skirt length [m].
double poseDifference_m(const std::vector<Eigen::Vector2d>& a,
                        const std::vector<Eigen::Vector2d>& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    worst = std::max({worst, std::abs(a[k][0] - b[k][0]), 0.03 * std::abs(a[k][1] - b[k][1])});
  }
  return worst;
}

// Our stepper as compared with CPodes: per-step tolerance tol [m] on the pose, steps of at
// most 0.5 deg.
plugin::LinearlyImplicitStepperOptions cpodesComparisonOptions(double tol) {
  plugin::LinearlyImplicitStepperOptions o;
  o.positionTolerance_m = tol;
  o.velocityTolerance_mps = tol * 209.4;
  o.maxStep_s = 0.5 * kDegree_s;
  return o;
}

// The tolerances are per step, so the global error is about the number of steps times the
// tolerance; the test therefore checks that our trajectory converges to CPodes' as the
// tolerance falls, and that at 1e-12 m per step it is within 1e-8 m (5e-4 of the
// clearance, well below any physical effect).
TEST(LinearlyImplicitStepper, AgreesWithCpodesOnAStiffSqueezeDamper) {
  Model reference;
  const auto ref = runCpodes(reference, 1e-11);
  double range = 0.0;
  for (const auto& p : ref)
    range = std::max(range, std::abs(p[0]));
  ASSERT_GT(range, 5e-6);  // the piston crosses a good part of the 20 um clearance
  std::vector<double> diffs;
  for (double tol : {1e-11, 1e-12}) {
    Model ours;
    plugin::LinearlyImplicitStepperStats stats;
    diffs.push_back(
        poseDifference_m(runStepper(ours, cpodesComparisonOptions(tol), &stats), ref));
    // The stiffness: near the wall the damping reaches c0 (c/h)^3 at both heights; the
    // piston's time constant m/c there is far below the steps taken.
    std::printf(
        "  tolerance %.0e m: %ld steps (%ld rejected) over 180 deg, mean %.2e s; "
        "difference to CPodes %.3e um (lateral range %.2f um)\n",
        tol, stats.steps, stats.rejectedSteps, 180.0 * kDegree_s / stats.steps, diffs.back() * 1e6,
        range * 1e6);
  }
  EXPECT_LT(diffs[1], diffs[0] / 3.0);
  EXPECT_LT(diffs[1], 1e-8);
}

// Jacobian reuse (jacobianReuseSteps): most evaluations realize the damper without its
// damping Jacobian (which it then leaves NaN), and the trajectory still converges
// to CPodes' like the stepper that evaluates the Jacobian every time: the Newton iteration, not
// the Jacobian, decides the step's solution. The damping grows like (c/h)^3 as the skirt
// nears the wall, so a Jacobian kept over steps is visibly stale there.
TEST(LinearlyImplicitStepper, ReusedJacobianKeepsTheTrajectory) {
  Model reference;
  const auto ref = runCpodes(reference, 1e-11);
  for (int reuse : {0, 10}) {
    std::vector<double> diffs;
    for (double tol : {1e-11, 1e-12}) {
      Model ours;
      plugin::LinearlyImplicitStepperOptions o = cpodesComparisonOptions(tol);
      o.jacobianReuseSteps = reuse;
      plugin::LinearlyImplicitStepperStats st;
      diffs.push_back(poseDifference_m(runStepper(ours, o, &st), ref));
      // The stepper told the element each time it did not want the Jacobian.
      EXPECT_EQ(ours.model.getElementAs<SqueezeDamperGuide>("squeeze_damper_guide")
                    .getEvaluationsWithoutJacobian(),
                st.forceEvaluations - st.jacobianEvaluations);
      std::printf("  reuse %d, tolerance %.0e m: %ld steps (%ld rejected), %ld evaluations, %ld "
                  "with the Jacobian; difference to CPodes %.3e um\n",
                  reuse, tol, st.steps, st.rejectedSteps, st.forceEvaluations,
                  st.jacobianEvaluations, diffs.back() * 1e6);
      if (reuse == 0) {
        EXPECT_EQ(st.jacobianEvaluations, st.forceEvaluations);
      } else {
        EXPECT_LT(st.jacobianEvaluations, st.forceEvaluations / 2);
      }
    }
    EXPECT_LT(diffs[1], diffs[0] / 3.0) << "reuse " << reuse;
    EXPECT_LT(diffs[1], 1e-8) << "reuse " << reuse;
  }
  plugin::PistonAssemblyModel model(testEngine());
  plugin::LinearlyImplicitStepperOptions o;
  o.jacobianReuseSteps = -1;
  EXPECT_THROW(plugin::LinearlyImplicitStepper(model, o), std::invalid_argument);
}

// With the step size held by maxStep_s (tolerances loose), halving the step quarters the
// error against a fine reference: second order.
TEST(LinearlyImplicitStepper, ConvergesAtSecondOrderInTheStepSize) {
  plugin::LinearlyImplicitStepperOptions o;
  o.positionTolerance_m = 1e-3;  // never binding: the step is the maximum step
  o.velocityTolerance_mps = 1e3;
  o.relativeTolerance = 0.5;
  auto run = [&](double step) {
    Model m;
    o.maxStep_s = step;
    o.initialStep_s = step;
    return runStepper(m, o);
  };
  const auto fine = run(0.025 * kDegree_s);
  std::vector<double> errors;
  for (double step : {0.4, 0.2, 0.1})
    errors.push_back(poseDifference_m(run(step * kDegree_s), fine));
  const double order1 = std::log2(errors[0] / errors[1]), order2 = std::log2(errors[1] / errors[2]);
  std::printf("  errors %.3e %.3e %.3e m; observed orders %.2f %.2f\n", errors[0], errors[1],
              errors[2], order1, order2);
  EXPECT_GT(order1, 1.7);
  EXPECT_GT(order2, 1.7);
}

// maxOrder 3: halving the step divides the error by about eight (variable-step BDF3 after
// the short first- and second-order start-up steps), and at the same step the error is far
// below BDF2's.
TEST(LinearlyImplicitStepper, ConvergesAtThirdOrderWithMaxOrderThree) {
  plugin::LinearlyImplicitStepperOptions o;
  o.positionTolerance_m = 1e-3;  // never binding: the step is the maximum step
  o.velocityTolerance_mps = 1e3;
  o.relativeTolerance = 0.5;
  auto run = [&](double step, int order) {
    Model m;
    o.maxStep_s = step;
    // a short start (the first-order start-up step would add its own second-order error),
    // then steps growing (by 2 and 1.5 in turn) to the maximum
    o.initialStep_s = 1e-4 * kDegree_s;
    o.maxOrder = order;
    return runStepper(m, o);
  };
  const auto fine = run(0.0125 * kDegree_s, 3);
  std::vector<double> errors;
  for (double step : {0.4, 0.2, 0.1})
    errors.push_back(poseDifference_m(run(step * kDegree_s, 3), fine));
  const double bdf2 = poseDifference_m(run(0.2 * kDegree_s, 2), fine);
  const double order1 = std::log2(errors[0] / errors[1]), order2 = std::log2(errors[1] / errors[2]);
  std::printf("  BDF3 errors %.3e %.3e %.3e m; observed orders %.2f %.2f; BDF2 at 0.2 deg %.3e m\n",
              errors[0], errors[1], errors[2], order1, order2, bdf2);
  EXPECT_GT(order1, 2.6);
  EXPECT_GT(order2, 2.6);
  EXPECT_LT(errors[1], 0.2 * bdf2);
  plugin::PistonAssemblyModel model(testEngine());
  o.maxOrder = 4;
  EXPECT_THROW(plugin::LinearlyImplicitStepper(model, o), std::invalid_argument);
}

// The step error estimate (Stats::poseErrorSum_m, the sum of the accepted steps' local error
// estimates on the pose) against the true global error, from a reference with 1/400 of the
// step and 1/1000 of the tolerance, where the tolerance sets the steps: within a factor of 3
// of it either way with BDF2 and BDF3 (measured: BDF2 about 2x, BDF3 0.6-0.7x the error), and
// falling with the tolerance.
TEST(LinearlyImplicitStepper, StepErrorEstimateFollowsTheGlobalPoseError) {
  const auto options = [](double tol, int order) {
    plugin::LinearlyImplicitStepperOptions o = cpodesComparisonOptions(tol);
    o.maxOrder = order;
    o.maxStep_s = 2.0 * kDegree_s;  // the tolerance sets the steps
    o.initialStep_s = 1e-4 * kDegree_s;
    return o;
  };
  Model reference;
  const auto fine = runStepper(reference, [&] {
    plugin::LinearlyImplicitStepperOptions o = options(1e-13, 3);
    o.maxStep_s = 0.005 * kDegree_s;
    o.initialStep_s = 1e-4 * kDegree_s;
    return o;
  }());
  for (int order : {2, 3}) {
    double previousEstimate = 0.0;
    for (double tol : {1e-8, 1e-9, 1e-10}) {
      Model m;
      plugin::LinearlyImplicitStepperStats stats;
      const double error = poseDifference_m(runStepper(m, options(tol, order), &stats), fine);
      std::printf("  BDF%d, tolerance %.0e m: global pose error %.3e m, estimate %.3e m (%.1fx), "
                  "%ld steps\n",
                  order, tol, error, stats.poseErrorSum_m, stats.poseErrorSum_m / error, stats.steps);
      EXPECT_GT(stats.poseErrorSum_m, error / 3.0) << "BDF" << order << " " << tol;
      EXPECT_LT(stats.poseErrorSum_m, 3.0 * error) << "BDF" << order << " " << tol;
      if (previousEstimate > 0.0) {
        EXPECT_LT(stats.poseErrorSum_m, 0.5 * previousEstimate) << "BDF" << order;
      }
      previousEstimate = stats.poseErrorSum_m;
    }
  }
}

// Auto-update variables: one swap at initialize() and one per accepted step, none for a
// rejected one.
TEST(LinearlyImplicitStepper, AdvancesHistoryOncePerAcceptedStep) {
  plugin::PistonAssemblyModel m(testEngine());
  m.addElement(std::make_unique<plugin::GasForceElement>(testPressure(), 1e5));
  m.addElement(
      std::make_unique<examples::WearingSpringLiner>(examples::WearingSpringLiner::Parameters{}));
  SimTK::State s0 = m.getDefaultState();
  m.getCrankTrain().setPose(s0, 0.0);
  m.getCrankTrain().setRates(s0, testEngine().drive.speed_radps);
  plugin::LinearlyImplicitStepperOptions o;
  o.initialStep_s = 1e-4;  // too large at first: rejections
  o.maxStep_s = 1e-4;
  plugin::LinearlyImplicitStepper stepper(m, o);
  stepper.initialize(s0);
  stepper.stepTo(s0.getTime() + 0.01);
  stepper.stepTo(s0.getTime() + 0.02);
  const auto& liner = m.getElementAs<examples::WearingSpringLiner>("wearing_spring_liner");
  const auto& st = stepper.getStats();
  std::printf("  %ld steps, %ld rejected, %ld evaluations\n", st.steps, st.rejectedSteps,
              st.forceEvaluations);
  ASSERT_GT(st.rejectedSteps, 0);
  // One update at initialize() and one per accepted step, swapped in as each step is
  // accepted (as Simbody's integrators count: N accepted steps, N + 1 updates); rejected
  // attempts and the Newton iterates that were not accepted leave no trace.
  EXPECT_EQ(liner.getAcceptedUpdates(stepper.getState()), st.steps + 1);
  EXPECT_GT(liner.getWearDepth_m(stepper.getState()), 0.0);
}

TEST(LinearlyImplicitStepper, RefusesConstraintsAndReportsFailures) {
  plugin::PistonAssemblyModel guided(testEngine());
  guided.addElement(std::make_unique<plugin::IdealLinerGuide>());
  plugin::LinearlyImplicitStepper stepper(guided, {});
  EXPECT_THROW(stepper.initialize(guided.getDefaultState()), std::invalid_argument);

  plugin::LinearlyImplicitStepperOptions bad;
  bad.minStep_s = 0.0;
  Model m;
  EXPECT_THROW(plugin::LinearlyImplicitStepper(m.model, bad), std::invalid_argument);

  // A step budget: the run stops with a message naming the time, never hangs.
  plugin::LinearlyImplicitStepperOptions tiny;
  tiny.maxSteps = 5;
  plugin::LinearlyImplicitStepper limited(m.model, tiny);
  limited.initialize(m.start);
  try {
    limited.stepTo(m.start.getTime() + 0.01);
    FAIL() << "expected the step budget to stop the run";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("step budget"), std::string::npos) << e.what();
  }
}

// A time asked for closer than the minimum step (a free crank landing on its output angle
// iterates the time that finely) is refused with that reason, not with an empty "the last
// failed step: " (issue 37): no step had failed.
TEST(LinearlyImplicitStepper, SaysWhyTheStepFellBelowTheMinimum) {
  Model m;
  plugin::LinearlyImplicitStepperOptions o;
  plugin::LinearlyImplicitStepper stepper(m.model, o);
  stepper.initialize(m.start);
  stepper.stepTo(m.start.getTime() + 1e-4);
  try {
    stepper.stepTo(stepper.getTime() + 0.25 * o.minStep_s);
    FAIL() << "expected the step below the minimum to be refused";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no step failed since the last accepted one"), std::string::npos) << what;
    EXPECT_NE(what.find("is only"), std::string::npos) << what;
    EXPECT_EQ(what.find("the last failed step: "), std::string::npos) << what;
  }
}

// CycleSimulation with the stepper runs to a periodic steady state and keeps the last cycle.
TEST(LinearlyImplicitStepper, CycleSimulationRunsToPeriodicSteadyStateAndKeepsTheLastCycle) {
  Model m;
  plugin::SimulationSettings s;
  s.integrator = plugin::SimulationSettings::Integrator::LinearlyImplicitBDF;
  s.outputStep_deg = 5.0;
  s.cycles = 8;
  s.untilPeriodic = true;
  s.periodicPoseTolerance_m = 0.5e-6;  // this damper centres slowly: 1.4, 0.65, 0.41 um
  plugin::CycleSimulation sim(m.model, s);
  const plugin::ResultTable table = sim.run();
  const auto& st = sim.getStats();
  std::printf("  converged %d after %d cycles (%d run), %ld steps, %ld realizations\n",
              static_cast<int>(st.converged), st.cyclesToConverge, st.cyclesRun, st.integratorSteps,
              st.realizations);
  ASSERT_TRUE(st.converged);
  ASSERT_GE(st.cyclesToConverge, 2);
  // Exactly the last cycle: 720 / 5 + 1 rows from start + 720 (N - 1) to start + 720 N.
  ASSERT_EQ(table.rows.size(), 145u);
  const auto angle = table.column("crank_angle_deg");
  EXPECT_DOUBLE_EQ(angle.front(), 720.0 * (st.cyclesToConverge - 1));
  EXPECT_DOUBLE_EQ(angle.back(), 720.0 * st.cyclesToConverge);
  // The last cycle is periodic to the tolerance: its first and last rows nearly agree.
  const auto u = table.column("u_lat_um");
  EXPECT_NEAR(u.front(), u.back(), 0.5);
}

}  // namespace
