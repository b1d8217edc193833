#include "pistondyn/plugin/CycleSimulation.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

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
  if (s.cycles < 1 || s.cycles > SimulationSettings::kMaxCycles) {
    fail("cycles must be between 1 and " + std::to_string(SimulationSettings::kMaxCycles));
  }
  if (!(s.outputStep_deg >= SimulationSettings::kMinOutputStep_deg) ||
      !std::isfinite(s.outputStep_deg) || s.outputStep_deg > 720.0) {
    fail("outputStep_deg must be between " +
         std::to_string(SimulationSettings::kMinOutputStep_deg) + " and 720 deg");
  }
  if (!s.outputStepDividesCycle()) {
    fail("outputStep_deg must divide 720 deg into a whole number of steps");
  }
  if (s.outputStepsPerCycle() * s.cycles > SimulationSettings::kMaxRows) {
    fail("cycles x 720 / outputStep_deg exceeds " +
         std::to_string(static_cast<long>(SimulationSettings::kMaxRows)) + " output rows");
  }
  if (!(s.accuracy > 0.0 && s.accuracy < 1.0))
    fail("accuracy must be in (0, 1)");
  if (!(s.constraintTolerance > 0.0 && s.constraintTolerance < 1.0)) {
    fail("constraintTolerance must be in (0, 1)");
  }
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

std::vector<std::string> CycleSimulation::getColumns() const {
  std::vector<std::string> columns = crankTrainColumns();
  model_.buildSystem();
  for (auto& c : model_.getElementOutputColumns())
    columns.push_back(std::move(c));
  return columns;
}

std::vector<std::string> CycleSimulation::crankTrainColumns() {
  return {"time_s",        "crank_angle_deg", "crank_speed_rpm", "piston_y_m",
          "piston_vy_mps", "piston_ay_mps2",  "u_lat_um",        "tilt_mrad",
          "u_tran_um",     "conrod_force_N",  "crank_torque_Nm", "drive_torque_Nm"};
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
  v.push_back(ct.getCrankTorqueFromConrod_Nm(s));
  v.push_back(ct.getDriveTorque_Nm(s));
}

namespace {

std::unique_ptr<SimTK::Integrator> makeIntegrator(const SimTK::MultibodySystem& system,
                                                  SimulationSettings::Integrator kind) {
  switch (kind) {
    case SimulationSettings::Integrator::RungeKuttaFeldberg:
      return std::make_unique<SimTK::RungeKuttaFeldbergIntegrator>(system);
    case SimulationSettings::Integrator::CPodesBDF:
      return std::make_unique<SimTK::CPodesIntegrator>(system, SimTK::CPodes::BDF,
                                                       SimTK::CPodes::Newton);
    case SimulationSettings::Integrator::RungeKuttaMerson:
    default:
      return std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system);
  }
}

void advanceTo(SimTK::Integrator& integ, double tOut) {
  while (integ.getTime() < tOut) {
    if (integ.stepTo(tOut) == SimTK::Integrator::EndOfSimulation) {
      throw std::runtime_error("CycleSimulation: integrator stopped: " +
                               integ.getTerminationReasonString(integ.getTerminationReason()));
    }
  }
}

// Free crank: advance until the crank angle equals thetaTarget (to 1e-12 rad), by a
// secant/Newton iteration on the time using the crank speed. An overshoot restarts
// the integrator from the previous row's state. Returns the steps of abandoned runs.
long landOnCrankAngle(SimTK::Integrator& integ, const mbd::CrankTrain& ct, double thetaTarget) {
  const SimTK::State start = integ.getState();
  const double tol = 1e-12 * std::max(1.0, std::abs(thetaTarget));
  long abandonedSteps = 0;
  double t =
      start.getTime() + (thetaTarget - ct.getCrankAngle_rad(start)) / ct.getCrankSpeed_radps(start);
  for (int iter = 0; iter < 50; ++iter) {
    if (t < integ.getTime()) {
      abandonedSteps += integ.getNumStepsTaken();
      integ.initialize(start);
    }
    advanceTo(integ, t);
    const SimTK::State& s = integ.getState();
    const double err = thetaTarget - ct.getCrankAngle_rad(s);
    if (std::abs(err) <= tol)
      return abandonedSteps;
    const double speed = ct.getCrankSpeed_radps(s);
    if (!(speed > 0.0)) {
      throw std::runtime_error("CycleSimulation: the free crank stopped or reversed (speed " +
                               std::to_string(speed) +
                               " rad/s at t = " + std::to_string(s.getTime()) +
                               " s); raise the speed or lower the load");
    }
    t = s.getTime() + err / speed;
  }
  throw std::runtime_error("CycleSimulation: could not land on crank angle " +
                           std::to_string(thetaTarget * 180.0 / M_PI) + " deg");
}

}  // namespace

ResultTable CycleSimulation::run(const Progress& progress, const RowObserver& observer) {
  // The observer sees each row's state before the row is stored, as a sink placed first.
  struct ObserverSink final : RowSink {
    explicit ObserverSink(const RowObserver& o) : observe(o) {}
    void consumeRow(const SimTK::State& s, const std::vector<double>&) override { observe(s); }
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
  model_.buildSystem();
  const SimTK::MultibodySystem& system = model_.getSystem();
  SimTK::State state = model_.getDefaultState();
  const mbd::CrankTrain& ct = model_.getCrankTrain();
  const mbd::CrankDrive& drive = ct.getEngine().drive;
  const double omega = drive.speed_radps;
  const double theta0 = settings_.startAngle_deg * M_PI / 180.0;

  // Constant speed: the Motion prescribes theta = omega t, so setPose puts the state at
  // t0 = theta0 / omega; a free crank starts at t = 0.
  const bool prescribed = drive.mode == mbd::CrankDrive::Mode::ConstantSpeed;
  ct.setPose(state, theta0);
  const double t0 = state.getTime();
  ct.setRates(state, omega);

  std::unique_ptr<SimTK::Integrator> integ = makeIntegrator(system, settings_.integrator);
  integ->setAccuracy(settings_.accuracy);
  integ->setConstraintTolerance(settings_.constraintTolerance);
  integ->initialize(state);

  const std::vector<std::string> columns = getColumns();
  for (RowSink* sink : sinks)
    sink->beginRun(columns);

  const long perCycle = settings_.stepsPerCycle();
  const long nRows = perCycle * settings_.cycles + 1;
  const double dTheta = settings_.outputStep_deg * M_PI / 180.0;
  long stepsBeforeRestarts = 0;
  std::vector<double> row;
  row.reserve(columns.size());
  for (long k = 0; k < nRows; ++k) {
    const double thetaTarget = theta0 + static_cast<double>(k) * dTheta;
    if (k > 0) {
      if (prescribed) {
        // theta = omega t exactly: step to the row's time.
        advanceTo(*integ, t0 + static_cast<double>(k) * dTheta / omega);
      } else {
        stepsBeforeRestarts += landOnCrankAngle(*integ, ct, thetaTarget);
      }
    }
    const SimTK::State& s = integ->getState();
    system.realize(s, SimTK::Stage::Acceleration);
    row.clear();
    calcCrankTrainRow(ct, s, row);
    row[1] = thetaTarget * 180.0 / M_PI;  // the nominal angle the row was taken at
    model_.calcElementOutputs(s, row);
    for (double v : row) {
      if (!std::isfinite(v)) {
        throw std::runtime_error("CycleSimulation: non-finite result at crank angle " +
                                 std::to_string(row[1]) + " deg");
      }
    }
    if (k % perCycle == 0 && k < nRows - 1) {
      for (RowSink* sink : sinks)
        sink->beginCycle(static_cast<int>(k / perCycle));
    }
    for (RowSink* sink : sinks)
      sink->consumeRow(s, row);
    if (progress)
      progress(static_cast<double>(k) / static_cast<double>(nRows - 1));
  }
  stats_.integratorSteps = stepsBeforeRestarts + integ->getNumStepsTaken();
  stats_.realizations = integ->getNumRealizations();
  stats_.wallTime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  for (RowSink* sink : sinks)
    sink->endRun();
}

}  // namespace pistondyn::plugin
