#include "pistondyn/plugin/CycleSimulation.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace pistondyn::plugin {

void validate(const SimulationSettings& s) {
  auto fail = [](const std::string& m) { throw std::invalid_argument("SimulationSettings: " + m); };
  if (!std::isfinite(s.startAngle_deg))
    fail("startAngle_deg must be finite");
  if (s.cycles < 1)
    fail("cycles must be >= 1");
  if (!(s.outputStep_deg > 0.0) || !std::isfinite(s.outputStep_deg)) {
    fail("outputStep_deg must be positive");
  }
  const double perCycle = 720.0 / s.outputStep_deg;
  if (std::abs(perCycle - std::round(perCycle)) > 1e-9 * perCycle) {
    fail("outputStep_deg must divide 720 deg into a whole number of steps");
  }
  if (!(s.accuracy > 0.0 && s.accuracy < 1.0))
    fail("accuracy must be in (0, 1)");
  if (!(s.constraintTolerance > 0.0 && s.constraintTolerance < 1.0)) {
    fail("constraintTolerance must be in (0, 1)");
  }
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

}  // namespace

ResultTable CycleSimulation::run(const Progress& progress, const RowObserver& observer) {
  const auto wallStart = std::chrono::steady_clock::now();
  const SimTK::MultibodySystem& system = model_.getSystem();
  SimTK::State state = model_.getDefaultState();
  const mbd::CrankTrain& ct = model_.getCrankTrain();
  const mbd::CrankDrive& drive = ct.getEngine().drive;
  const double omega = drive.speed_radps;
  const double theta0 = settings_.startAngle_deg * M_PI / 180.0;

  // Constant speed: the Motion prescribes theta = omega t, so start at t0 = theta0/omega.
  const bool prescribed = drive.mode == mbd::CrankDrive::Mode::ConstantSpeed;
  const double t0 = prescribed ? theta0 / omega : 0.0;
  state.setTime(t0);
  ct.setPose(state, theta0);
  ct.setRates(state, omega);

  std::unique_ptr<SimTK::Integrator> integ = makeIntegrator(system, settings_.integrator);
  integ->setAccuracy(settings_.accuracy);
  integ->setConstraintTolerance(settings_.constraintTolerance);
  integ->initialize(state);

  ResultTable table;
  table.columns = crankTrainColumns();
  for (auto& c : model_.getElementReportColumns())
    table.columns.push_back(std::move(c));

  const long stepsPerCycle = std::lround(720.0 / settings_.outputStep_deg);
  const long nRows = stepsPerCycle * settings_.cycles + 1;
  const double dt = settings_.outputStep_deg * M_PI / 180.0 / omega;
  table.rows.reserve(static_cast<std::size_t>(nRows));
  for (long k = 0; k < nRows; ++k) {
    if (k > 0) {
      const double tOut = t0 + static_cast<double>(k) * dt;
      while (integ->getTime() < tOut) {
        const SimTK::Integrator::SuccessfulStepStatus status = integ->stepTo(tOut);
        if (status == SimTK::Integrator::EndOfSimulation) {
          throw std::runtime_error(
              "CycleSimulation: integrator stopped: " +
              integ->getTerminationReasonString(integ->getTerminationReason()));
        }
      }
    }
    const SimTK::State& s = integ->getState();
    system.realize(s, SimTK::Stage::Acceleration);
    if (observer)
      observer(s);
    std::vector<double> row;
    row.reserve(table.columns.size());
    calcCrankTrainRow(ct, s, row);
    model_.calcElementReports(s, row);
    for (double v : row) {
      if (!std::isfinite(v)) {
        throw std::runtime_error(
            "CycleSimulation: non-finite result at t = " + std::to_string(s.getTime()) + " s");
      }
    }
    table.rows.push_back(std::move(row));
    if (progress)
      progress(static_cast<double>(k) / static_cast<double>(nRows - 1));
  }
  stats_.integratorSteps = integ->getNumStepsTaken();
  stats_.realizations = integ->getNumRealizations();
  stats_.wallTime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  return table;
}

}  // namespace pistondyn::plugin
