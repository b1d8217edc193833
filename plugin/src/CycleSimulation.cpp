#include "pistondyn/plugin/CycleSimulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "pistondyn/common/Cancellation.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/mbd_models/SliderCrank.h"
#include "pistondyn/plugin/LinearlyImplicitStepper.h"
#include "pistondyn/plugin/PistonPose.h"

namespace pistondyn::plugin {

bool SimulationSettings::outputStepDividesCycle() const {
  const double perCycle = outputStepsPerCycle();
  return std::abs(perCycle - std::round(perCycle)) <= 1e-9 * perCycle;
}

long SimulationSettings::stepsPerCycle() const {
  return std::lround(outputStepsPerCycle());
}

void validate(const SimulationSettings& s) {
  auto fail = [](const std::string& m) { throw std::invalid_argument("SimulationSettings: " + m); };
  if (!std::isfinite(s.startAngle_deg) || std::abs(s.startAngle_deg) > 720.0) {
    fail("startAngle_deg must be within [-720, 720] deg");
  }
  if (!std::isfinite(s.initialLateral_m) || std::abs(s.initialLateral_m) > 1e-3)
    fail("initialLateral_m must be within [-1, 1] mm");
  if (!std::isfinite(s.initialTilt_rad) || std::abs(s.initialTilt_rad) > 0.05)
    fail("initialTilt_rad must be within [-0.05, 0.05] rad");
  if (!std::isfinite(s.initialTransverse_m) || std::abs(s.initialTransverse_m) > 5e-3)
    fail("initialTransverse_m must be within [-5, 5] mm");
  if (s.cycles < 1 || s.cycles > SimulationSettings::kMaxCycles) {
    fail(common::message("cycles must be between 1 and ", SimulationSettings::kMaxCycles));
  }
  if (!(s.outputStep_deg >= SimulationSettings::kMinOutputStep_deg) ||
      !std::isfinite(s.outputStep_deg) || s.outputStep_deg > 720.0) {
    fail(common::message("outputStep_deg must be between ", SimulationSettings::kMinOutputStep_deg,
                         " and 720 deg"));
  }
  if (!s.outputStepDividesCycle()) {
    fail("outputStep_deg must divide 720 deg into a whole number of steps");
  }
  if (s.outputStepsPerCycle() * s.cycles > SimulationSettings::kMaxRows) {
    fail(common::message("cycles x 720 / outputStep_deg exceeds ",
                         static_cast<long>(SimulationSettings::kMaxRows), " output rows"));
  }
  if (!(s.accuracy > 0.0 && s.accuracy < 1.0))
    fail("accuracy must be in (0, 1)");
  if (!(s.constraintTolerance > 0.0 && s.constraintTolerance < 1.0)) {
    fail("constraintTolerance must be in (0, 1)");
  }
  if (!(s.poseTolerance_m > 0.0 && s.poseTolerance_m < 1e-3))
    fail("poseTolerance_m must be in (0, 1e-3) m");
  if (!(s.maxStep_deg > 0.0 && s.maxStep_deg <= 10.0))
    fail("maxStep_deg must be in (0, 10] deg");
  if (s.stepperOrder != 2 && s.stepperOrder != 3)
    fail("stepperOrder must be 2 or 3");
  if (s.jacobianReuseSteps < 0)
    fail("jacobianReuseSteps must be 0 or positive");
  if (s.maxSteps < 1)
    fail("maxSteps must be at least 1");
  if (!(s.periodicFmepTolerance > 0.0 && s.periodicFmepTolerance < 1.0))
    fail("periodicFmepTolerance must be in (0, 1)");
  if (!(s.periodicPoseTolerance_m > 0.0 && s.periodicPoseTolerance_m < 1e-3))
    fail("periodicPoseTolerance_m must be in (0, 1e-3) m");
  if (s.untilPeriodic && s.cycles < 2)
    fail("untilPeriodic needs cycles >= 2 (two cycles to compare)");
  if (s.warmStart)
    validateWarmStart(*s.warmStart, s);
}

void applyWarmStart(const PistonAssemblyModel& model, SimTK::State& state, const WarmStart& w,
                    double startAngle_deg) {
  const mbd::CrankTrain& ct = model.getCrankTrain();
  const mbd::EngineDescription& engine = ct.getEngine();
  const SecondaryState& x = w.state;
  if ((x.transverse_m != 0.0 || x.transverseRate_mps != 0.0) && !engine.tertiaryMotion) {
    throw std::invalid_argument(
        "the warm start has a tertiary (transverse) motion, this crank train has none");
  }
  const bool prescribed = engine.drive.mode == mbd::CrankDrive::Mode::ConstantSpeed;
  ct.setPose(state, startAngle_deg * M_PI / 180.0, x.lateral_m, x.tilt_rad, x.transverse_m);
  ct.setRates(state, prescribed ? engine.drive.speed_radps : x.crankSpeed_radps,
              x.lateralRate_mps, x.tiltRate_radps, x.transverseRate_mps);
  for (const WarmStart::ElementRecord& e : w.elements) {
    if (!model.hasElement(e.element))
      throw std::invalid_argument("the model has no element '" + e.element + "' to start from");
    model.getElement(e.element).setWarmStartRecord(state, e.record);
  }
}

void validateWarmStart(const WarmStart& w, const SimulationSettings& s) {
  auto fail = [](const std::string& m) {
    throw std::invalid_argument("SimulationSettings: warmStart: " + m);
  };
  const SecondaryState& x = w.state;
  for (double v : {w.crankAngle_deg, w.outputStep_deg, x.lateral_m, x.tilt_rad, x.transverse_m,
                   x.lateralRate_mps, x.tiltRate_radps, x.transverseRate_mps, x.crankSpeed_radps}) {
    if (!std::isfinite(v))
      fail("every value must be finite");
  }
  if (!(x.crankSpeed_radps > 0.0))
    fail("the crank speed must be positive");
  if (std::abs(x.lateral_m) > 1e-3 || std::abs(x.tilt_rad) > 0.05 ||
      std::abs(x.transverse_m) > 5e-3) {
    fail("the pose is outside the bounds of the initial pose (1 mm, 0.05 rad, 5 mm)");
  }
  const double shift = std::remainder(w.crankAngle_deg - s.startAngle_deg, 720.0);
  if (std::abs(shift) > 1e-9 * std::max(1.0, std::abs(w.crankAngle_deg))) {
    fail(common::message("its crank angle ", w.crankAngle_deg,
                         " deg is not the start angle modulo 720 deg (", s.startAngle_deg,
                         " deg)"));
  }
  if (std::abs(w.outputStep_deg - s.outputStep_deg) > 1e-12 * s.outputStep_deg) {
    fail(common::message("its output step ", w.outputStep_deg, " deg is not this run's (",
                         s.outputStep_deg, " deg): the cycles could not be compared"));
  }
  const auto perCycle = static_cast<std::size_t>(s.stepsPerCycle());
  if (w.lastCycleLateral_m.size() != perCycle || w.lastCycleTilt_rad.size() != perCycle) {
    fail(common::message("its last cycle must hold ", perCycle,
                         " lateral displacements and tilts (one per output angle)"));
  }
  for (std::size_t i = 0; i < perCycle; ++i) {
    if (!std::isfinite(w.lastCycleLateral_m[i]) || !std::isfinite(w.lastCycleTilt_rad[i]))
      fail("its last cycle's pose must be finite");
  }
  if (w.lastCycleFmep_Pa && !std::isfinite(*w.lastCycleFmep_Pa))
    fail("its last cycle's fmep must be finite");
}

void ResultTableSink::beginRun(const std::vector<std::string>& columns) {
  table_ = ResultTable();
  table_.columns = columns;
}

void ResultTableSink::consumeRow(const SimTK::State&, const std::vector<double>& values) {
  table_.rows.push_back(values);
}

bool ResultTable::hasColumn(const std::string& name) const {
  for (const auto& c : columns) {
    if (c == name)
      return true;
  }
  return false;
}

std::size_t ResultTable::columnIndex(const std::string& name) const {
  for (std::size_t j = 0; j < columns.size(); ++j) {
    if (columns[j] == name)
      return j;
  }
  throw std::out_of_range("ResultTable: no column '" + name + "'");
}

std::vector<double> ResultTable::column(const std::string& name) const {
  const std::size_t j = columnIndex(name);
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& r : rows)
    out.push_back(r[j]);
  return out;
}

CycleSimulation::CycleSimulation(PistonAssemblyModel& model, SimulationSettings settings)
    : model_(model), settings_(settings) {
  validate(settings_);
}

namespace {

// Crank angles in messages: the shortest text that reads back to the same double.
std::string formatAngle(double deg) {
  return common::formatNumber(deg);
}

// One interface over Simbody's integrators and LinearlyImplicitStepper: advance the state to
// a time, restart from a state, report counts.
class Advancer {
 public:
  virtual ~Advancer() = default;
  virtual void initialize(const SimTK::State& s) = 0;
  virtual void advanceTo(double t) = 0;
  virtual const SimTK::State& getState() const = 0;
  virtual double getTime() const = 0;
  virtual long getSteps() const = 0;
  virtual long getRealizations() const = 0;
  virtual long getRejectedSteps() const { return 0; }
  virtual long getFailedEvaluations() const { return 0; }
  // Wall time in force evaluations [s] where the advancer can tell (0: it cannot).
  virtual double getRealizeTime_s() const { return 0.0; }
  // The shortest step it takes [s] (0: any).
  virtual double getMinStep_s() const { return 0.0; }
  // Sum of the accepted steps' local error estimates on the pose [m] (LinearlyImplicitStepper
  // Stats::poseErrorSum_m); NaN where the advancer does not estimate it.
  virtual double getPoseErrorSum_m() const { return std::numeric_limits<double>::quiet_NaN(); }
  // After a restart from an earlier state: the sum as it was at that state (the steps beyond
  // it are discarded, so their error estimates must not count).
  virtual void resetPoseErrorSum_m(double /*sum_m*/) {}
};

class SimbodyAdvancer final : public Advancer {
 public:
  SimbodyAdvancer(const SimTK::MultibodySystem& system, const SimulationSettings& settings)
      : maxSteps_(settings.maxSteps) {
    switch (settings.integrator) {
      case SimulationSettings::Integrator::RungeKuttaFeldberg:
        integ_ = std::make_unique<SimTK::RungeKuttaFeldbergIntegrator>(system);
        break;
      case SimulationSettings::Integrator::CPodesBDF:
        integ_ = std::make_unique<SimTK::CPodesIntegrator>(system, SimTK::CPodes::BDF,
                                                           SimTK::CPodes::Newton);
        break;
      case SimulationSettings::Integrator::RungeKuttaMerson:
      default:
        integ_ = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system);
        break;
    }
    integ_->setAccuracy(settings.accuracy);
    integ_->setConstraintTolerance(settings.constraintTolerance);
  }
  void initialize(const SimTK::State& s) override {
    if (initialized_) {  // a restart (the free crank's landing): keep the counts
      stepsBefore_ += integ_->getNumStepsTaken();
      realizationsBefore_ += integ_->getNumRealizations();
    }
    integ_->initialize(s);
    initialized_ = true;
  }
  void advanceTo(double tOut) override {
    while (integ_->getTime() < tOut) {
      common::throwIfCancelled();
      if (getSteps() >= maxSteps_) {
        throw std::runtime_error("the step budget of " + std::to_string(maxSteps_) +
                                 " integrator steps is used up");
      }
      if (integ_->stepTo(tOut) == SimTK::Integrator::EndOfSimulation) {
        throw std::runtime_error("integrator stopped: " + integ_->getTerminationReasonString(
                                                              integ_->getTerminationReason()));
      }
    }
  }
  const SimTK::State& getState() const override { return integ_->getState(); }
  double getTime() const override { return integ_->getTime(); }
  long getSteps() const override { return stepsBefore_ + integ_->getNumStepsTaken(); }
  long getRealizations() const override {
    return realizationsBefore_ + integ_->getNumRealizations();
  }

 private:
  std::unique_ptr<SimTK::Integrator> integ_;
  long maxSteps_;
  long stepsBefore_ = 0, realizationsBefore_ = 0;
  bool initialized_ = false;
};

class StepperAdvancer final : public Advancer {
 public:
  StepperAdvancer(const PistonAssemblyModel& model, const SimulationSettings& settings)
      : model_(model) {
    const double degree_s = (M_PI / 180.0) / model.getCrankTrain().getEngine().drive.speed_radps;
    LinearlyImplicitStepperOptions o;
    o.positionTolerance_m = settings.poseTolerance_m;
    o.velocityTolerance_mps = settings.poseTolerance_m / degree_s;
    o.maxStep_s = settings.maxStep_deg * degree_s;
    o.initialStep_s = std::min(1e-3 * degree_s, o.maxStep_s);
    o.minStep_s = std::min(1e-9 * degree_s, o.initialStep_s);
    o.maxSteps = settings.maxSteps;
    o.maxOrder = settings.stepperOrder;
    o.jacobianReuseSteps = settings.jacobianReuseSteps;
    options_ = o;
  }
  void initialize(const SimTK::State& s) override {
    // A restart (the free crank's landing) begins a new BDF history from s.
    if (stepper_)
      accumulate();
    // The step budget is the run's: a restart gets what the earlier steppers left.
    LinearlyImplicitStepperOptions o = options_;
    o.maxSteps = std::max(1L, options_.maxSteps - before_.steps);
    if (before_.steps >= options_.maxSteps) {
      throw std::runtime_error("the step budget of " + std::to_string(options_.maxSteps) +
                               " integrator steps is used up");
    }
    stepper_ = std::make_unique<LinearlyImplicitStepper>(model_, o);
    stepper_->initialize(s);
  }
  void advanceTo(double t) override { stepper_->stepTo(t); }
  const SimTK::State& getState() const override { return stepper_->getState(); }
  double getTime() const override { return stepper_->getTime(); }
  long getSteps() const override { return before_.steps + stepper_->getStats().steps; }
  long getRealizations() const override {
    return before_.forceEvaluations + stepper_->getStats().forceEvaluations;
  }
  long getRejectedSteps() const override {
    return before_.rejectedSteps + stepper_->getStats().rejectedSteps;
  }
  long getFailedEvaluations() const override {
    return before_.failedEvaluations + stepper_->getStats().failedEvaluations;
  }
  double getRealizeTime_s() const override {
    return before_.realizeTime_s + stepper_->getStats().realizeTime_s;
  }
  double getMinStep_s() const override { return options_.minStep_s; }
  double getPoseErrorSum_m() const override {
    return before_.poseErrorSum_m + stepper_->getStats().poseErrorSum_m;
  }
  void resetPoseErrorSum_m(double sum_m) override {
    before_.poseErrorSum_m = sum_m - stepper_->getStats().poseErrorSum_m;
  }

 private:
  void accumulate() {
    const auto& s = stepper_->getStats();
    before_.steps += s.steps;
    before_.forceEvaluations += s.forceEvaluations;
    before_.rejectedSteps += s.rejectedSteps;
    before_.failedEvaluations += s.failedEvaluations;
    before_.realizeTime_s += s.realizeTime_s;
    before_.poseErrorSum_m += s.poseErrorSum_m;
  }
  const PistonAssemblyModel& model_;
  LinearlyImplicitStepperOptions options_;
  std::unique_ptr<LinearlyImplicitStepper> stepper_;
  LinearlyImplicitStepperStats before_;
};

// Free crank: advance until the crank angle equals thetaTarget (to 1e-12 rad), by a
// secant/Newton iteration on the time using the crank speed. An overshoot restarts
// the integrator from the previous row's state.
void landOnCrankAngle(Advancer& integ, const mbd::CrankTrain& ct, double thetaTarget) {
  const SimTK::State start = integ.getState();
  const double errorSumAtStart_m = integ.getPoseErrorSum_m();
  const double tol = 1e-12 * std::max(1.0, std::abs(thetaTarget));
  double t =
      start.getTime() + (thetaTarget - ct.getCrankAngle_rad(start)) / ct.getCrankSpeed_radps(start);
  for (int iter = 0; iter < 50; ++iter) {
    if (t < integ.getTime()) {
      integ.initialize(start);
      integ.resetPoseErrorSum_m(errorSumAtStart_m);
    }
    integ.advanceTo(t);
    const SimTK::State& s = integ.getState();
    const double err = thetaTarget - ct.getCrankAngle_rad(s);
    if (std::abs(err) <= tol)
      return;
    const double speed = ct.getCrankSpeed_radps(s);
    if (!(speed > 0.0)) {
      throw std::runtime_error(common::message("the free crank stopped or reversed (speed ", speed,
                                               " rad/s at t = ", s.getTime(),
                                               " s); raise the speed or lower the load"));
    }
    // Closer than the integrator's shortest step: landed (the stepper's floor is 1e-9 of a
    // crank degree, so the row is within that of its angle).
    if (std::abs(err) / speed <= integ.getMinStep_s())
      return;
    t = s.getTime() + err / speed;
  }
  throw std::runtime_error(
      common::message("could not land on crank angle ", thetaTarget * 180.0 / M_PI, " deg"));
}

// Appends to `perCycle` the part of the run's figure `runTotal` that the cycles already in it
// do not hold: the cycle that closed now.
template <typename T>
void appendCycleShare(std::vector<T>& perCycle, T runTotal) {
  perCycle.push_back(runTotal - std::accumulate(perCycle.begin(), perCycle.end(), T{}));
}

// The steps, rejected steps, realizations and step error estimate of the cycle that closed
// now: the integrator's figures since the previous cycle closed (or since the start).
void recordCycleCounts(const Advancer& integ, SimulationStats& stats) {
  appendCycleShare(stats.cycleIntegratorSteps, integ.getSteps());
  appendCycleShare(stats.cycleRejectedSteps, integ.getRejectedSteps());
  appendCycleShare(stats.cycleRealizations, integ.getRealizations());
  appendCycleShare(stats.cycleStepErrorEstimate_um, 1e6 * integ.getPoseErrorSum_m());
}

// The run's end as a warm start: the state of its last row (a cycle's last) and the pose of
// the cycle it closed (lateral, tilt x skirt length per output angle, interleaved).
WarmStart makeEndState(const PistonAssemblyModel& model, const SimTK::State& s,
                       const SimulationSettings& settings, long lastRow,
                       const std::vector<double>& lastPose, double skirt_m,
                       const std::vector<double>& cycleFmep_Pa) {
  WarmStart w;
  w.crankAngle_deg =
      settings.startAngle_deg + static_cast<double>(lastRow) * settings.outputStep_deg;
  w.outputStep_deg = settings.outputStep_deg;
  const mbd::CrankTrain& ct = model.getCrankTrain();
  const PistonPose p = calcPistonPose(ct, s);
  w.state = {p.lateral_m,       p.tilt_rad,       p.transverse_m,           p.lateralRate_mps,
             p.tiltRate_radps, p.transverseRate_mps, ct.getCrankSpeed_radps(s)};
  for (std::size_t i = 0; i + 1 < lastPose.size(); i += 2) {
    w.lastCycleLateral_m.push_back(lastPose[i]);
    w.lastCycleTilt_rad.push_back(lastPose[i + 1] / skirt_m);
  }
  if (!cycleFmep_Pa.empty())
    w.lastCycleFmep_Pa = cycleFmep_Pa.back();
  for (const std::string& name : model.getElementNames()) {
    std::vector<double> record = model.getElement(name).getWarmStartRecord(s);
    if (!record.empty())
      w.elements.push_back({name, std::move(record)});
  }
  return w;
}

}  // namespace

std::vector<std::string> CycleSimulation::getColumns() const {
  std::vector<std::string> columns = crankTrainColumns();
  model_.buildSystem();
  for (auto& c : model_.getElementOutputColumns())
    columns.push_back(std::move(c));
  return columns;
}

std::vector<std::string> CycleSimulation::crankTrainColumns() {
  return {"time_s",
          "crank_angle_deg",
          "crank_speed_rpm",
          "piston_y_m",
          "piston_vy_mps",
          "piston_ay_mps2",
          "u_lat_um",
          "tilt_mrad",
          "u_tran_um",
          "conrod_force_N",
          "crank_train_side_force_N",
          "crank_torque_Nm",
          "drive_torque_Nm"};
}

void CycleSimulation::calcCrankTrainRow(const mbd::CrankTrain& ct, const SimTK::State& s,
                                        std::vector<double>& v) {
  const SimTK::MobilizedBody& piston = ct.getPiston();
  v.push_back(s.getTime());
  v.push_back(ct.getCrankAngle_rad(s) * 180.0 / M_PI);
  v.push_back(ct.getCrankSpeed_radps(s) * 30.0 / M_PI);
  v.push_back(ct.getPistonHeight_m(s));
  v.push_back(piston.getBodyOriginVelocity(s)[1]);
  v.push_back(piston.getBodyOriginAcceleration(s)[1]);
  v.push_back(ct.getLateralDisplacement_m(s) * 1e6);
  v.push_back(ct.getTilt_rad(s) * 1e3);
  v.push_back(ct.getTransverseDisplacement_m(s) * 1e6);
  v.push_back(ct.getConrodAxialForce_N(s));
  v.push_back(ct.getConrodLateralForce_N(s));
  v.push_back(ct.getCrankTorqueFromConrod_Nm(s));
  v.push_back(ct.getDriveTorque_Nm(s));
}

ResultTable CycleSimulation::run(const Progress& progress, const RowObserver& observer) {
  // The observer sees each row's state before the row is stored, as a sink placed first.
  struct ObserverSink final : RowSink {
    explicit ObserverSink(const RowObserver& o) : observe(o) {}
    void consumeRow(const SimTK::State& s, const std::vector<double>&) override { observe(s); }
    void discardRows() override {}
    const RowObserver& observe;
  } observerSink(observer);
  ResultTableSink tableSink;
  std::vector<RowSink*> sinks;
  if (observer)
    sinks.push_back(&observerSink);
  sinks.push_back(&tableSink);
  run(sinks, progress);
  return tableSink.releaseTable();
}

void CycleSimulation::run(const std::vector<RowSink*>& sinks, const Progress& progress) {
  const auto wallStart = std::chrono::steady_clock::now();
  stats_ = SimulationStats();
  model_.buildSystem();
  const SimTK::MultibodySystem& system = model_.getSystem();
  SimTK::State state = model_.getDefaultState();
  const mbd::CrankTrain& ct = model_.getCrankTrain();
  const mbd::EngineDescription& engine = ct.getEngine();
  const mbd::CrankDrive& drive = engine.drive;
  const double omega = drive.speed_radps;
  const double theta0 = settings_.startAngle_deg * M_PI / 180.0;
  const LinerElement* liner = model_.findLinerElement();

  // Constant speed: the Motion prescribes theta = omega t, so setPose puts the state at
  // t0 = theta0 / omega; a free crank starts at t = 0.
  const bool prescribed = drive.mode == mbd::CrankDrive::Mode::ConstantSpeed;
  if (settings_.initialTransverse_m != 0.0 && !engine.tertiaryMotion) {
    throw std::invalid_argument(
        "SimulationSettings: initialTransverse_m needs a crank train with tertiary motion");
  }
  const std::optional<WarmStart>& warm = settings_.warmStart;
  if (warm) {
    try {
      applyWarmStart(model_, state, *warm, settings_.startAngle_deg);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("SimulationSettings: warmStart: ") + e.what());
    }
  } else {
    ct.setPose(state, theta0, settings_.initialLateral_m, settings_.initialTilt_rad,
               settings_.initialTransverse_m);
    ct.setRates(state, omega);
  }
  const double t0 = state.getTime();

  std::unique_ptr<Advancer> integ;
  if (settings_.integrator == SimulationSettings::Integrator::LinearlyImplicitBDF) {
    integ = std::make_unique<StepperAdvancer>(model_, settings_);
  } else {
    integ = std::make_unique<SimbodyAdvancer>(system, settings_);
  }
  integ->initialize(state);

  const std::vector<std::string> columns = getColumns();
  for (RowSink* sink : sinks)
    sink->beginRun(columns);

  const long perCycle = settings_.stepsPerCycle();
  const long nRows = perCycle * settings_.cycles + 1;
  const double dTheta = settings_.outputStep_deg * M_PI / 180.0;
  const mbd::SliderCrank kinematics(engine.geometry);
  const double displacement_m3 =
      mbd::CylinderVolume(kinematics, engine.piston.bore_m, engine.geometry.compressionRatio)
          .displacement_m3();
  const double skirt_m = engine.piston.skirtLength_m;
  // Pose of the previous and the current cycle at every output angle, and friction work.
  std::vector<double> previousPose(2 * perCycle), currentPose(2 * perCycle);
  // The first cycle compared: the second, or from a warm start the first (with its last one).
  int firstCompared = 2;
  if (warm) {
    for (long i = 0; i < perCycle; ++i) {
      previousPose[2 * i] = warm->lastCycleLateral_m[i];
      previousPose[2 * i + 1] = warm->lastCycleTilt_rad[i] * skirt_m;
    }
    firstCompared = 1;
  }
  double workAtCycleStart = 0.0;
  std::vector<double> row;
  row.reserve(columns.size());
  long k = 0;
  try {
    for (k = 0; k < nRows; ++k) {
      common::throwIfCancelled();
      const double thetaTarget = theta0 + static_cast<double>(k) * dTheta;
      if (k > 0) {
        if (prescribed) {
          // theta = omega t exactly: step to the row's time.
          integ->advanceTo(t0 + static_cast<double>(k) * dTheta / omega);
        } else {
          landOnCrankAngle(*integ, ct, thetaTarget);
        }
      }
      const SimTK::State& s = integ->getState();
      system.realize(s, SimTK::Stage::Acceleration);
      row.clear();
      calcCrankTrainRow(ct, s, row);
      // The nominal angle the row was taken at, start + k * step in degrees as the deck
      // wrote them (through radians, 30 deg would read 29.999999999999993).
      row[1] = settings_.startAngle_deg + static_cast<double>(k) * settings_.outputStep_deg;
      model_.calcElementOutputs(s, row);
      for (std::size_t j = 0; j < row.size(); ++j) {
        if (!std::isfinite(row[j])) {
          throw std::runtime_error("non-finite value of " + columns[j]);
        }
      }
      const long inCycle = k % perCycle;
      const std::optional<double> work = liner ? liner->getFrictionWork_J(s) : std::nullopt;
      bool stop = false;
      if (inCycle == 0 && k > 0) {
        // A cycle closes at this row.
        const int cycle = static_cast<int>(k / perCycle);
        stats_.cyclesRun = cycle;
        if (work)
          stats_.cycleFmep_Pa.push_back((*work - workAtCycleStart) / displacement_m3);
        recordCycleCounts(*integ, stats_);
        if (settings_.untilPeriodic && cycle >= firstCompared) {
          double poseChange = 0.0;
          for (std::size_t i = 0; i < currentPose.size(); ++i)
            poseChange = std::max(poseChange, std::abs(currentPose[i] - previousPose[i]));
          // The cycle before this one: the run's own, or the warm start's.
          std::optional<double> before;
          if (stats_.cycleFmep_Pa.size() >= 2)
            before = stats_.cycleFmep_Pa.rbegin()[1];
          else if (warm)
            before = warm->lastCycleFmep_Pa;
          bool fmepSettled = true;
          if (work && before) {
            const double a = stats_.cycleFmep_Pa.back();
            fmepSettled = std::abs(a - *before) <= settings_.periodicFmepTolerance * std::abs(a);
          }
          if (fmepSettled && poseChange <= settings_.periodicPoseTolerance_m) {
            stats_.converged = true;
            stats_.cyclesToConverge = cycle;
          }
        }
        stop = stats_.converged || k == nRows - 1;
        std::swap(previousPose, currentPose);
      }
      if (inCycle == 0 && !stop) {
        if (k > 0 && settings_.untilPeriodic) {
          // The cycle just closed is not the result: keep only the next one.
          for (RowSink* sink : sinks)
            sink->discardRows();
        }
        for (RowSink* sink : sinks)
          sink->beginCycle(static_cast<int>(k / perCycle));
        if (work)
          workAtCycleStart = *work;
      }
      if (!stop) {
        currentPose[2 * inCycle] = ct.getLateralDisplacement_m(s);
        currentPose[2 * inCycle + 1] = ct.getTilt_rad(s) * skirt_m;
      }
      for (RowSink* sink : sinks)
        sink->consumeRow(s, row);
      if (progress)
        progress(static_cast<double>(k) / static_cast<double>(nRows - 1));
      if (stop)
        break;
    }
  } catch (const common::Cancelled&) {
    throw;  // not a failure of the simulation: the caller asked it to stop
  } catch (const std::exception& e) {
    const double reached = settings_.startAngle_deg +
                           static_cast<double>(std::max(k - 1, 0L)) * settings_.outputStep_deg;
    throw std::runtime_error(
        "CycleSimulation: stopped before crank angle " +
        formatAngle(settings_.startAngle_deg + static_cast<double>(k) * settings_.outputStep_deg) +
        " deg (last row written at " + formatAngle(reached) + " deg): " + e.what());
  }
  if (stats_.cyclesRun >= 1)
    stats_.endState = makeEndState(model_, integ->getState(), settings_, k, previousPose,
                                   skirt_m, stats_.cycleFmep_Pa);
  stats_.integratorSteps = integ->getSteps();
  stats_.realizations = integ->getRealizations();
  stats_.rejectedSteps = integ->getRejectedSteps();
  stats_.failedEvaluations = integ->getFailedEvaluations();
  stats_.realizeTime_s = integ->getRealizeTime_s();
  stats_.wallTime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  for (RowSink* sink : sinks)
    sink->endRun();
}

}  // namespace pistondyn::plugin
