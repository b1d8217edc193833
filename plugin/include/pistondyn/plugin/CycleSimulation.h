#pragma once
/// \file
/// Runs a PistonAssemblyModel over whole 720 deg cycles and records one row per output
/// crank angle: the crank-train columns below, then every element's outputs
/// (ElementOutput.h) in registration order. Rows go to a RowSink as they are computed
/// (a file writer streams them to disk; ResultTableSink keeps them in memory).
///
/// Crank-train columns (units in the names; crank angle 0 = firing TDC):
///   time_s, crank_angle_deg (continuous from the start angle), crank_speed_rpm,
///   piston_y_m (height of the piston axis at pin height above the crank axis),
///   piston_vy_mps, piston_ay_mps2, u_lat_um (+ thrust), tilt_mrad (+ crown towards
///   thrust), u_tran_um (+ along pin axis z), conrod_force_N (+ compression),
///   crank_train_side_force_N (the rod's lateral force across the small end, + towards
///   thrust: what an ideal guide carries; CrankTrain::getConrodLateralForce_N),
///   crank_torque_Nm (rod on crank, + along rotation), drive_torque_Nm (drive on crank,
///   + along rotation).
///
/// Rows are taken at the crank angles start + k * step: with a constant-speed crank at
/// the matching times, with a free crank by iterating the time until the crank angle
/// is reached to 1e-12 rad (relative beyond 1 rad: 1e-12 |theta|), or with
/// LinearlyImplicitBDF to within its shortest step (1e-9 of a crank degree). crank_angle_deg holds that
/// nominal angle, unwrapped (it keeps growing past 720 deg over several cycles).
///
/// Periodic steady state (SimulationSettings::untilPeriodic): cycles are run until two
/// consecutive cycles agree - fmep (from the liner element's friction work, LinerElement.h)
/// within periodicFmepTolerance relative, and the lateral displacement and the tilt times
/// the skirt length at every output angle within periodicPoseTolerance_m - or until
/// `cycles` cycles are done; only the last cycle's rows are kept (the sinks are told to
/// discard the earlier ones), and the stats say whether and after how many cycles the run
/// converged. A run from a warm start (SimulationSettings::warmStart) compares its first cycle
/// with the warm start's last one.
///
/// Cancellation (common/Cancellation.h): a run checks the process's cancellation request
/// before every output row (and every step of Simbody's integrators) and stops by throwing
/// common::Cancelled, which leaves run() as it is (not wrapped in a runtime_error); the
/// sinks see it as any failure (no endRun()).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pistondyn/plugin/PistonAssemblyModel.h"
#include "pistondyn/plugin/ResultTable.h"

namespace pistondyn::plugin {

/// The piston's secondary state at one instant: pose and rates (PistonPose.h's signs), and
/// the crank speed.
struct SecondaryState {
  double lateral_m = 0.0;           ///< lateral displacement, + towards thrust [m]
  double tilt_rad = 0.0;            ///< tilt, + crown towards thrust [rad]
  double transverse_m = 0.0;        ///< tertiary displacement along the pin axis [m]
  double lateralRate_mps = 0.0;     ///< its rate [m/s]
  double tiltRate_radps = 0.0;      ///< its rate [rad/s]
  double transverseRate_mps = 0.0;  ///< its rate [m/s]
  double crankSpeed_radps = 0.0;    ///< crank speed [rad/s]
};

/// Where an earlier run of the same engine ended, as a later run's start (SimulationSettings::
/// warmStart; written by `pistondyn run` as warm_start.json): the secondary state at its last
/// row, the elements' own state there (ForceElement::getWarmStartRecord: the films' fill
/// fraction, the liner oil, an elastic skirt's deformation) and the pose of the whole cycle
/// that led to it. A run started from it compares its first cycle with `lastCycle*` as with a
/// cycle of its own, so a run of an unchanged engine started from its periodic state is
/// periodic after one cycle. The integrator restarts at first order; the elements' integrals
/// (friction work, wear) start at zero.
struct WarmStart {
  /// One element's record (ForceElement::getWarmStartRecord), by the element's name.
  struct ElementRecord {
    std::string element;         ///< ForceElement::getName()
    std::vector<double> record;  ///< in the element's own layout
  };
  double crankAngle_deg = 0.0;   ///< nominal crank angle of the state (its run's last row) [deg]
  double outputStep_deg = 1.0;   ///< its run's output step [deg]
  SecondaryState state;          ///< at crankAngle_deg
  /// Lateral displacement [m] and tilt [rad] at the output angles of the last cycle, its first
  /// row (crankAngle_deg - 720) first, 720 / outputStep_deg values each.
  std::vector<double> lastCycleLateral_m;
  std::vector<double> lastCycleTilt_rad;  ///< see lastCycleLateral_m
  /// The last cycle's fmep [Pa], if the liner integrates the friction work.
  std::optional<double> lastCycleFmep_Pa;
  /// The elements' records (those with a non-empty one); each must name an element of the
  /// model run from it.
  std::vector<ElementRecord> elements;
};

/// How a CycleSimulation runs: rows, cycles, integrator and its tolerances (each member
/// states its default).
struct SimulationSettings {
  static constexpr int kMaxCycles = 1000;             ///< largest `cycles`
  static constexpr double kMinOutputStep_deg = 1e-3;  ///< smallest output step [deg]
  static constexpr double kMaxRows = 1e7;             ///< rows are kept in memory

  double startAngle_deg = 0.0;  ///< crank angle of the first row [deg]
  /// The piston's secondary pose at the start (CrankTrain::setPose), at rest relative to the
  /// primary motion: lateral displacement [m], tilt [rad], tertiary displacement [m] (needs
  /// EngineDescription::tertiaryMotion). Default: centred and upright.
  double initialLateral_m = 0.0;
  double initialTilt_rad = 0.0;      ///< see initialLateral_m
  double initialTransverse_m = 0.0;  ///< see initialLateral_m
  /// Start from an earlier run's end instead (WarmStart): its secondary state replaces the
  /// initial pose above (and, with a free crank, the drive's speed); its crankAngle_deg must
  /// equal startAngle_deg modulo 720 deg and its output step this one's.
  std::optional<WarmStart> warmStart;
  int cycles = 1;               ///< number of 720 deg cycles (the maximum if untilPeriodic), >= 1
  double outputStep_deg = 1.0;  ///< output interval [deg], > 0, must divide 720
  /// The time integrator.
  enum class Integrator {
    RungeKuttaMerson,    ///< Simbody's, explicit (for the ideal guide, smooth elements)
    RungeKuttaFeldberg,  ///< Simbody's, explicit
    CPodesBDF,           ///< Simbody's CPodes BDF with Newton iterations (numerical Jacobian)
    /// LinearlyImplicitStepper.h, variable-step BDF of order stepperOrder (2 or 3): for the
    /// stiff squeeze film (deck value linearly_implicit_bdf2)
    LinearlyImplicitBDF,
  };
  Integrator integrator = Integrator::RungeKuttaMerson;  ///< default RungeKuttaMerson
  double accuracy = 1e-9;              ///< Simbody integrators' relative accuracy [-]
  double constraintTolerance = 1e-11;  ///< constraint projection tolerance [-]
  /// LinearlyImplicitBDF only: per-step tolerance on the piston pose (lateral, tertiary,
  /// tilt x skirt length) [m], > 0, default 10 nm; the rates get poseTolerance_m per time of
  /// one crank degree.
  double poseTolerance_m = 1e-8;
  /// LinearlyImplicitBDF: largest step [deg of crank], > 0, default 0.25. The error test
  /// alone would let 0.5 deg steps through the flooded example skirt, which lag its
  /// secondary motion by 1.4 um and move fmep by 4 % against CPodes (plugin/README.md).
  double maxStep_deg = 0.25;
  /// LinearlyImplicitBDF: order of the BDF formula, 2 (default) or 3 (LinearlyImplicitStepper
  /// Options::maxOrder: the third order for the global error of the slow secondary motion).
  int stepperOrder = 2;
  /// LinearlyImplicitBDF: steps over which the elements' Jacobian may be kept (Linearly
  /// ImplicitStepperOptions::jacobianReuseSteps), 0 (default: evaluated every time) or more.
  int jacobianReuseSteps = 0;
  /// Step budget of the whole run (every integrator): a run that needs more steps stops with
  /// an error naming the crank angle reached, never hangs. Default 2e7.
  long maxSteps = 20000000;

  bool untilPeriodic = false;               ///< run to periodic steady state (see the top)
  double periodicFmepTolerance = 0.005;     ///< relative change of fmep between cycles [-]
  double periodicPoseTolerance_m = 0.2e-6;  ///< change of the pose at equal crank angles [m]

  /// 720 / outputStep_deg, not rounded [-].
  double outputStepsPerCycle() const { return 720.0 / outputStep_deg; }
  /// True when outputStep_deg divides 720 deg into a whole number of steps (to 1e-9).
  bool outputStepDividesCycle() const;
  /// Output steps per 720 deg cycle, rounded (for settings that pass validate()).
  long stepsPerCycle() const;
};

/// Throws std::invalid_argument naming the member when settings are unusable.
void validate(const SimulationSettings& settings);
/// Throws std::invalid_argument naming what does not fit when a warm start cannot start a run
/// with these settings (validate() calls it for settings.warmStart).
void validateWarmStart(const WarmStart& warmStart, const SimulationSettings& settings);

/// Puts a warm start into a state of the (built) model, as a run from it begins: the pose and
/// rates at the start angle (the crank speed the drive's, or with a free crank the warm
/// start's) and every element's record. Throws std::invalid_argument naming what does not fit
/// (a transverse motion on a crank train without tertiary motion, an element the model lacks,
/// a record of another grid).
void applyWarmStart(const PistonAssemblyModel& model, SimTK::State& state,
                    const WarmStart& warmStart, double startAngle_deg);

/// Where a simulation puts its rows. The simulation calls beginRun() once with the column
/// names, beginCycle() at the first row of every 720 deg cycle, consumeRow() for every
/// row (the state is realized through Stage::Acceleration, so a sink may also evaluate
/// outputs or role interfaces of its own), and endRun() after the last row. In a run to
/// periodic steady state, discardRows() says that every row consumed so far is not part of
/// the result (an earlier cycle), just before beginCycle() of the next cycle, whose first
/// row is the one that closed the discarded cycle. If the run fails, the exception leaves the
/// simulation before endRun(): a file-writing sink then discards what it wrote (all-or-nothing).
class RowSink {
 public:
  virtual ~RowSink() = default;
  /// Once, before the first row, with the column names.
  virtual void beginRun(const std::vector<std::string>& /*columns*/) {}
  /// cycle = 0, 1, ...; the row of crank angle start + 720 * cycle.
  virtual void beginCycle(int /*cycle*/) {}
  /// Every row: its values in column order, the state realized through Stage::Acceleration.
  virtual void consumeRow(const SimTK::State& state, const std::vector<double>& values) = 0;
  /// Forget the rows consumed so far (pure: every sink must decide what that means).
  virtual void discardRows() = 0;
  /// Once, after the last row of a run that succeeded.
  virtual void endRun() {}
};

/// Keeps every row in a ResultTable.
class ResultTableSink final : public RowSink {
 public:
  void beginRun(const std::vector<std::string>& columns) override;  ///< starts a new table
  /// Appends the row.
  void consumeRow(const SimTK::State& state, const std::vector<double>& values) override;
  void discardRows() override { table_.rows.clear(); }      ///< clears the rows
  const ResultTable& getTable() const { return table_; }    ///< the rows so far
  ResultTable releaseTable() { return std::move(table_); }  ///< moves the table out

 private:
  ResultTable table_;
};

/// What a run did.
struct SimulationStats {
  double wallTime_s = 0.0;     ///< wall time of the run [s]
  long integratorSteps = 0;    ///< accepted integrator steps
  long realizations = 0;       ///< number of Stage::Dynamics realizations taken by the integrator
  long rejectedSteps = 0;      ///< LinearlyImplicitBDF: steps rejected by the error test
  long failedEvaluations = 0;  ///< LinearlyImplicitBDF: steps retried after an element threw
  /// LinearlyImplicitBDF: wall time in its force evaluations (realize through Acceleration:
  /// Simbody and the elements) [s]; 0 for Simbody's integrators (not separable there).
  double realizeTime_s = 0.0;
  int cyclesRun = 0;                 ///< whole cycles simulated
  bool converged = false;            ///< untilPeriodic: the last two cycles agreed
  int cyclesToConverge = 0;          ///< untilPeriodic: cycles run when they did (0 if not)
  /// The run's end as a later run's warm start (its last row is a cycle's last): set when the
  /// run completed at least one whole cycle.
  std::optional<WarmStart> endState;
  std::vector<double> cycleFmep_Pa;  ///< fmep of every cycle run, if the liner integrates it
  /// Per cycle run, in order (each sums to its whole-run figure above over the cycles; the
  /// steps before the first cycle's first row, none with CycleSimulation's start, belong to
  /// the first): accepted steps, rejected steps, force evaluations (realizations).
  std::vector<long> cycleIntegratorSteps;
  std::vector<long> cycleRejectedSteps;      ///< see cycleIntegratorSteps
  std::vector<long> cycleRealizations;       ///< see cycleIntegratorSteps
  /// Per cycle run: the step error estimate of the pose [um], the sum of the cycle's accepted
  /// steps' local error estimates (LinearlyImplicitStepperStats::poseErrorSum_m): an estimate
  /// of the error the cycle's steps add to the lateral motion and tilt x skirt length (within
  /// a factor of 3 on a test problem; a free crank's landing restarts do not count the steps
  /// they discard). NaN with Simbody's integrators (not estimated).
  std::vector<double> cycleStepErrorEstimate_um;
};

/// Runs a model over whole cycles (the documentation of CycleSimulation.h).
class CycleSimulation {
 public:
  /// Validates the settings (throws std::invalid_argument naming the member). The model must
  /// outlive the simulation.
  CycleSimulation(PistonAssemblyModel& model, SimulationSettings settings);

  /// Progress: called after every row with the fraction done in [0, 1].
  using Progress = std::function<void(double)>;
  /// Row observer: called at every output row with the state realized through
  /// Stage::Acceleration (custom outputs, checks), before the row is stored.
  using RowObserver = std::function<void(const SimTK::State&)>;
  /// Runs and keeps every row in memory.
  ResultTable run(const Progress& progress = {}, const RowObserver& observer = {});
  /// Runs and hands every row to each sink, in order.
  void run(const std::vector<RowSink*>& sinks, const Progress& progress = {});
  const SimulationStats& getStats() const { return stats_; }  ///< of the last run

  /// All columns of a run of this model: crankTrainColumns() then the elements' outputs.
  std::vector<std::string> getColumns() const;
  /// The crank-train columns listed above, and their values at a state realized
  /// through Stage::Acceleration (also usable outside a run).
  static std::vector<std::string> crankTrainColumns();
  /// The crank-train columns' values at a state realized through Stage::Acceleration.
  static void calcCrankTrainRow(const mbd::CrankTrain& crankTrain, const SimTK::State& s,
                                std::vector<double>& values);

 private:
  PistonAssemblyModel& model_;
  SimulationSettings settings_;
  SimulationStats stats_;
};

}  // namespace pistondyn::plugin
