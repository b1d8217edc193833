#pragma once
/// \file
/// The figures summary.json reports for the last simulated 720 deg cycle, and the row
/// sink that accumulates them while the simulation runs (no table is kept in memory).
///
/// Where each figure comes from:
///   - imep, displacement, stroke, peak cylinder pressure: the deck (pressure table and
///     geometry), not the rows;
///   - side force (and, if the liner provides them, minimum film thickness and h/sigma,
///     friction work and mean friction power, slap energy, hot running clearance, film
///     solves): the model's liner element through its role interface plugin::LinerElement,
///     evaluated on each row's state; without a liner element (or for figures the liner
///     does not report, like the ideal guide's film) these figures are absent, never
///     invented from a column;
///   - the largest |lateral displacement| and |tilt|: the crank train, at each row's state;
///   - conrod force, crank-train side force, crank and drive torque, crank speed: the
///     crank-train columns, which CycleSimulation::crankTrainColumns() fixes, found by their
///     index in that list.

#include <optional>
#include <vector>

#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/LinerElement.h"

namespace pistondyn::io {

/// The figures of one cycle that summary.json reports (the documentation of CycleSummary.h says
/// where each comes from).
struct CycleSummary {
  double imep_Pa = 0.0;                        ///< from the pressure table
  double displacement_m3 = 0.0;                ///< swept volume V_d [m^3]
  double kinematicStroke_m = 0.0;              ///< TDC to BDC pin travel (> 2r with offsets) [m]
  double peakCylinderPressure_Pa = 0.0;        ///< largest knot of the table [Pa]
  double peakCylinderPressureAngle_deg = 0.0;  ///< its crank angle [deg]

  /// From the liner element's role interface (absent if the model has none).
  struct LinerFigures {
    double sideForceMax_N = 0.0;         ///< largest side force, towards thrust [N]
    double sideForceMaxAngle_deg = 0.0;  ///< its crank angle [deg]
    double sideForceMin_N = 0.0;         ///< smallest side force, towards anti-thrust (< 0) [N]
    double sideForceMinAngle_deg = 0.0;  ///< its crank angle [deg]
    /// Only if the liner reports them at every row of the cycle (angles in [0, 720) deg):
    /// smallest nominal gap on the thrust side [m].
    std::optional<double> minFilmThicknessThrust_m;
    std::optional<double> minFilmThicknessThrustAngle_deg;      ///< its crank angle [deg]
    std::optional<double> minFilmThicknessAntiThrust_m;         ///< anti-thrust side [m]
    std::optional<double> minFilmThicknessAntiThrustAngle_deg;  ///< its crank angle [deg]
    std::optional<double> minGapOverSigmaThrust;                ///< smallest h/sigma, thrust
    std::optional<double> minGapOverSigmaThrustAngle_deg;       ///< its crank angle [deg]
    std::optional<double> minGapOverSigmaAntiThrust;            ///< smallest h/sigma, anti-thrust
    std::optional<double> minGapOverSigmaAntiThrustAngle_deg;   ///< its crank angle [deg]
    std::optional<double> frictionWork_J;                       ///< dissipated over the cycle, >= 0
    /// Friction mean effective pressure: frictionWork_J / displacement_m3 [Pa] (the same
    /// figure as SimulationStats::cycleFmep_Pa of the cycle).
    std::optional<double> fmep_Pa;
    /// The part of it dissipated by asperity (boundary) friction, from the lubricated
    /// liner's integrated state (plugin::LinerElement::getAsperityFrictionWork_J).
    std::optional<double> asperityFrictionWork_J;
    /// Energy the liner's films and friction dissipated over the cycle [J], >= 0
    /// (plugin::LinerElement::getDissipatedEnergy_J).
    std::optional<double> dissipatedEnergy_J;
    /// Work the liner's forces took from the piston's secondary motion over the cycle [J]; over
    /// a periodic cycle frictionWork_J + secondaryMotionWork_J = dissipatedEnergy_J.
    std::optional<double> secondaryMotionWork_J;
    /// Friction work over the cycle / the cycle's duration: the exact time average [W].
    std::optional<double> frictionPowerMean_W;
    /// Largest impact energy of the slap events that completed in the cycle [J] (0: none).
    /// An event is seen where LinerElement::getLastSlapEnergy_J changes from one row to the
    /// next (the closing row of the cycle included), so several events completing within
    /// one output step count as the last of them.
    std::optional<double> slapEnergyMax_J;
    std::optional<double> hotRunningClearance_m;  ///< LinerElement::getHotRunningClearance_m
    /// Film solves, their fallbacks and failed squeeze-derivative solves, as the liner
    /// counted them from the sink's construction to the end of the run.
    std::optional<long> filmSolves;
    std::optional<long> filmFallbacks;           ///< see filmSolves
    std::optional<long> filmDerivativeFailures;  ///< see filmSolves
  };
  std::optional<LinerFigures> liner;  ///< absent when the model has no liner element

  /// Secondary motion over the cycle (crank train, every model).
  double maxAbsLateralDisplacement_m = 0.0;  ///< largest |u_lat| [m]
  double maxAbsTilt_rad = 0.0;               ///< largest |tilt| [rad]

  double conrodForceMax_N = 0.0;    ///< largest conrod force, compression > 0 [N]
  double conrodForceMin_N = 0.0;    ///< smallest conrod force [N]
  /// The crank train's own side force (crank_train_side_force_N: the rod's lateral force
  /// across the small end), every model: largest towards thrust [N] ...
  double crankTrainSideForceMax_N = 0.0;
  double crankTrainSideForceMaxAngle_deg = 0.0;  ///< ... its crank angle in [0, 720) [deg]
  double crankTrainSideForceMin_N = 0.0;  ///< largest towards anti-thrust (< 0) [N]
  double crankTrainSideForceMinAngle_deg = 0.0;  ///< its crank angle in [0, 720) [deg]
  double meanCrankTorque_Nm = 0.0;  ///< rod on crank, cycle mean [N m]
  double meanDriveTorque_Nm = 0.0;  ///< drive on crank, cycle mean [N m]
  double indicatedPower_W = 0.0;    ///< mean crank torque x mean speed
};

/// The deck-level figures (imep, displacement, stroke, peak pressure) of a summary.
void addDeckFigures(const EngineDeck& deck, CycleSummary& summary);

/// Accumulates the figures of every cycle of a run of `model` with `settings`: at every
/// beginCycle() it starts again, so after endRun() getSummary() holds the last cycle's (also
/// in a run to periodic steady state, whose earlier cycles are discarded from the files), and
/// getCycleSummaries() every completed cycle's, in order. The row that closes a cycle
/// (crank angle start + 720 * (cycle + 1)) is not part of the means or extremes, as the
/// first row of the cycle already stands for that angle; it gives the cycle's end values
/// (friction work, slap events). Where the simulation hands that row over as the first row
/// of the next cycle (CycleSimulation: beginCycle() comes first), the sink closes the
/// previous cycle with it before starting the next.
class CycleSummarySink final : public plugin::RowSink {
 public:
  /// `model` must outlive the sink; its liner element (if any) is looked up at beginRun()
  /// (its film-solve counts already at construction).
  CycleSummarySink(const EngineDeck& deck, const plugin::PistonAssemblyModel& model);
  void beginRun(const std::vector<std::string>& columns) override;
  void beginCycle(int cycle) override;
  void consumeRow(const SimTK::State& state, const std::vector<double>& values) override;
  void discardRows() override;
  /// Throws std::runtime_error if the run did not complete a cycle.
  void endRun() override;

  /// Valid after endRun().
  const CycleSummary& getSummary() const { return summary_; }
  /// Every completed cycle's figures, the first cycle first; the last is getSummary().
  /// Valid after endRun().
  const std::vector<CycleSummary>& getCycleSummaries() const { return cycles_; }
  /// Rows kept (consumed since the start or the last discardRows()).
  long getRowCount() const { return rows_; }

 private:
  struct FilmMinimum {
    bool valid = true;  ///< the liner reported a value at every row so far
    double value_m = 0.0, angle_deg = 0.0;
  };
  void resetCycle();
  /// Adds one row at index k of the current cycle (k = perCycle_ closes it).
  void accumulate(const SimTK::State& state, const std::vector<double>& values, long k);
  /// The figures of the cycle accumulated so far (its closing row seen).
  CycleSummary finishCycle() const;

  const EngineDeck& deck_;
  const plugin::PistonAssemblyModel& model_;
  struct SlapEvents {
    bool valid = true;  ///< the liner reported a value at every row so far
    double previous_J = 0.0, max_J = 0.0;
  };
  const plugin::LinerElement* liner_ = nullptr;
  std::optional<plugin::SolverCounters> countersAtStart_;  ///< the liner's at the run's start
  long perCycle_;
  long rows_ = 0;
  long rowInCycle_ = -1;  ///< -1 before the first beginCycle()
  /// beginCycle() came after every row of a cycle but its closing one: the next row closes it.
  bool closeWithNextRow_ = false;
  CycleSummary summary_;
  std::vector<CycleSummary> cycles_;
  /// Running figures of the current cycle.
  double torque_ = 0.0, drive_ = 0.0, speed_ = 0.0;
  double conrodMax_ = 0.0, conrodMin_ = 0.0;
  double rodSideMax_ = 0.0, rodSideMaxAngle_ = 0.0, rodSideMin_ = 0.0, rodSideMinAngle_ = 0.0;
  double sideMax_ = 0.0, sideMaxAngle_ = 0.0, sideMin_ = 0.0, sideMinAngle_ = 0.0;
  FilmMinimum filmThrust_, filmAntiThrust_, sigmaThrust_, sigmaAntiThrust_;
  SlapEvents slap_;
  double maxLateral_ = 0.0, maxTilt_ = 0.0;
  double timeAtCycleStart_s_ = 0.0, timeAtCycleEnd_s_ = 0.0;
  std::optional<double> workAtCycleStart_J_, workAtCycleEnd_J_;
  std::optional<double> asperityWorkAtCycleStart_J_, asperityWorkAtCycleEnd_J_;
  std::optional<double> dissipatedAtCycleStart_J_, dissipatedAtCycleEnd_J_;
  std::optional<double> secondaryAtCycleStart_J_, secondaryAtCycleEnd_J_;
};

}  // namespace pistondyn::io
