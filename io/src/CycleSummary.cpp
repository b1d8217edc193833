#include "pistondyn/io/CycleSummary.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pistondyn/common/CrankAngle.h"

namespace pistondyn::io {
namespace {

// Index of a crank-train column in the fixed list CycleSimulation::crankTrainColumns().
std::size_t crankTrainColumn(const std::string& name) {
  static const std::vector<std::string> columns = plugin::CycleSimulation::crankTrainColumns();
  for (std::size_t j = 0; j < columns.size(); ++j) {
    if (columns[j] == name)
      return j;
  }
  throw std::logic_error("CycleSummarySink: no crank-train column '" + name + "'");
}

const std::size_t kAngle = crankTrainColumn("crank_angle_deg");
const std::size_t kSpeed = crankTrainColumn("crank_speed_rpm");
const std::size_t kConrod = crankTrainColumn("conrod_force_N");
const std::size_t kCrankTrainSide = crankTrainColumn("crank_train_side_force_N");
const std::size_t kCrankTorque = crankTrainColumn("crank_torque_Nm");
const std::size_t kDriveTorque = crankTrainColumn("drive_torque_Nm");

}  // namespace

void addDeckFigures(const EngineDeck& deck, CycleSummary& s) {
  const mbd::SliderCrank kin(deck.engine.geometry);
  const mbd::CylinderVolume vol(kin, deck.engine.piston.bore_m,
                                deck.engine.geometry.compressionRatio);
  s.imep_Pa = mbd::calcImep_Pa(*deck.cylinderPressure, vol);
  // Peak of the table itself (not of the output rows, which may step over it).
  s.peakCylinderPressure_Pa = deck.cylinderPressure->getPeakPressure_Pa();
  s.peakCylinderPressureAngle_deg = deck.cylinderPressure->getPeakPressureAngle_deg();
  s.displacement_m3 = vol.displacement_m3();
  s.kinematicStroke_m = kin.stroke_m();
}

CycleSummarySink::CycleSummarySink(const EngineDeck& deck, const plugin::PistonAssemblyModel& model)
    : deck_(deck), model_(model), perCycle_(deck.simulation.stepsPerCycle()) {
  if (const plugin::LinerElement* liner = model_.findLinerElement())
    countersAtStart_ = liner->getSolverCounters();
}

void CycleSummarySink::beginRun(const std::vector<std::string>& columns) {
  const std::vector<std::string> crank = plugin::CycleSimulation::crankTrainColumns();
  if (columns.size() < crank.size() || !std::equal(crank.begin(), crank.end(), columns.begin())) {
    throw std::logic_error("CycleSummarySink: the rows do not start with the crank-train columns");
  }
  liner_ = model_.findLinerElement();
  summary_ = CycleSummary();
  cycles_.clear();
  rows_ = 0;
  rowInCycle_ = -1;
  closeWithNextRow_ = false;
}

void CycleSummarySink::resetCycle() {
  torque_ = drive_ = speed_ = 0.0;
  conrodMax_ = sideMax_ = rodSideMax_ = -INFINITY;
  conrodMin_ = sideMin_ = rodSideMin_ = INFINITY;
  sideMaxAngle_ = sideMinAngle_ = rodSideMaxAngle_ = rodSideMinAngle_ = 0.0;
  filmThrust_ = filmAntiThrust_ = sigmaThrust_ = sigmaAntiThrust_ = FilmMinimum();
  slap_ = SlapEvents();
  maxLateral_ = maxTilt_ = 0.0;
  timeAtCycleStart_s_ = timeAtCycleEnd_s_ = 0.0;
  workAtCycleStart_J_.reset();
  workAtCycleEnd_J_.reset();
  asperityWorkAtCycleStart_J_.reset();
  asperityWorkAtCycleEnd_J_.reset();
  dissipatedAtCycleStart_J_.reset();
  dissipatedAtCycleEnd_J_.reset();
  secondaryAtCycleStart_J_.reset();
  secondaryAtCycleEnd_J_.reset();
}

void CycleSummarySink::discardRows() {
  rows_ = 0;  // the figures start again at the next beginCycle()
}

void CycleSummarySink::beginCycle(int) {
  // A cycle that lacks only its closing row is closed by the next row (CycleSimulation
  // hands the row that closes one cycle over as the first row of the next).
  closeWithNextRow_ = rowInCycle_ == perCycle_;
  if (!closeWithNextRow_)
    resetCycle();
  rowInCycle_ = 0;
}

void CycleSummarySink::consumeRow(const SimTK::State& state, const std::vector<double>& r) {
  ++rows_;
  if (rowInCycle_ < 0)
    return;  // rows before the first cycle (none with CycleSimulation)
  if (closeWithNextRow_) {
    accumulate(state, r, perCycle_);
    cycles_.push_back(finishCycle());
    resetCycle();
    closeWithNextRow_ = false;
  }
  const long k = rowInCycle_++;
  if (k > perCycle_)
    return;
  accumulate(state, r, k);
}

void CycleSummarySink::accumulate(const SimTK::State& state, const std::vector<double>& r,
                                  long k) {
  if (k == 0 || k == perCycle_) {
    (k == 0 ? timeAtCycleStart_s_ : timeAtCycleEnd_s_) = state.getTime();
    if (liner_ != nullptr)
      (k == 0 ? workAtCycleStart_J_ : workAtCycleEnd_J_) = liner_->getFrictionWork_J(state);
    if (liner_ != nullptr) {
      (k == 0 ? asperityWorkAtCycleStart_J_ : asperityWorkAtCycleEnd_J_) =
          liner_->getAsperityFrictionWork_J(state);
      (k == 0 ? dissipatedAtCycleStart_J_ : dissipatedAtCycleEnd_J_) =
          liner_->getDissipatedEnergy_J(state);
      (k == 0 ? secondaryAtCycleStart_J_ : secondaryAtCycleEnd_J_) =
          liner_->getSecondaryMotionWork_J(state);
    }
  }
  // Slap events: a change of the last completed event's energy since the previous row is
  // an event completed in between (the closing row's change belongs to this cycle).
  if (liner_ != nullptr && slap_.valid) {
    const std::optional<double> last = liner_->getLastSlapEnergy_J(state);
    if (!last) {
      slap_.valid = false;
    } else {
      if (k > 0 && *last != slap_.previous_J)
        slap_.max_J = std::max(slap_.max_J, *last);
      slap_.previous_J = *last;
    }
  }
  if (k == perCycle_)
    return;  // the row closing the cycle: same crank angle as its first row

  const double angle = common::wrapCrankAngle_deg(r[kAngle]);
  const mbd::CrankTrain& ct = model_.getCrankTrain();
  maxLateral_ = std::max(maxLateral_, std::abs(ct.getLateralDisplacement_m(state)));
  maxTilt_ = std::max(maxTilt_, std::abs(ct.getTilt_rad(state)));
  if (liner_ != nullptr) {
    const double side = liner_->getSideForce_N(state);
    if (side > sideMax_) {
      sideMax_ = side;
      sideMaxAngle_ = angle;
    }
    if (side < sideMin_) {
      sideMin_ = side;
      sideMinAngle_ = angle;
    }
    auto track = [&](FilmMinimum& m, const std::optional<double>& v) {
      if (!v) {
        m.valid = false;
      } else if (m.valid && (k == 0 || *v < m.value_m)) {
        m.value_m = *v;
        m.angle_deg = angle;
      }
    };
    for (const plugin::SkirtSide sideOfSkirt :
         {plugin::SkirtSide::Thrust, plugin::SkirtSide::AntiThrust}) {
      const bool thrust = sideOfSkirt == plugin::SkirtSide::Thrust;
      track(thrust ? filmThrust_ : filmAntiThrust_,
            liner_->getMinFilmThickness_m(state, sideOfSkirt));
      track(thrust ? sigmaThrust_ : sigmaAntiThrust_,
            liner_->getMinGapOverSigma(state, sideOfSkirt));
    }
  }
  conrodMax_ = std::max(conrodMax_, r[kConrod]);
  conrodMin_ = std::min(conrodMin_, r[kConrod]);
  if (r[kCrankTrainSide] > rodSideMax_) {
    rodSideMax_ = r[kCrankTrainSide];
    rodSideMaxAngle_ = angle;
  }
  if (r[kCrankTrainSide] < rodSideMin_) {
    rodSideMin_ = r[kCrankTrainSide];
    rodSideMinAngle_ = angle;
  }
  torque_ += r[kCrankTorque];
  drive_ += r[kDriveTorque];
  speed_ += r[kSpeed] * M_PI / 30.0;
}

void CycleSummarySink::endRun() {
  if (rowInCycle_ != perCycle_ + 1) {
    throw std::runtime_error("CycleSummarySink: the run ended without completing a 720 deg cycle");
  }
  summary_ = finishCycle();
  cycles_.push_back(summary_);
}

CycleSummary CycleSummarySink::finishCycle() const {
  CycleSummary s;
  addDeckFigures(deck_, s);
  const double n = static_cast<double>(perCycle_);
  s.conrodForceMax_N = conrodMax_;
  s.conrodForceMin_N = conrodMin_;
  s.crankTrainSideForceMax_N = rodSideMax_;
  s.crankTrainSideForceMaxAngle_deg = rodSideMaxAngle_;
  s.crankTrainSideForceMin_N = rodSideMin_;
  s.crankTrainSideForceMinAngle_deg = rodSideMinAngle_;
  s.meanCrankTorque_Nm = torque_ / n;
  s.meanDriveTorque_Nm = drive_ / n;
  s.indicatedPower_W = s.meanCrankTorque_Nm * speed_ / n;
  s.maxAbsLateralDisplacement_m = maxLateral_;
  s.maxAbsTilt_rad = maxTilt_;
  if (liner_ != nullptr) {
    CycleSummary::LinerFigures f;
    f.sideForceMax_N = sideMax_;
    f.sideForceMaxAngle_deg = sideMaxAngle_;
    f.sideForceMin_N = sideMin_;
    f.sideForceMinAngle_deg = sideMinAngle_;
    if (filmThrust_.valid) {
      f.minFilmThicknessThrust_m = filmThrust_.value_m;
      f.minFilmThicknessThrustAngle_deg = filmThrust_.angle_deg;
    }
    if (filmAntiThrust_.valid) {
      f.minFilmThicknessAntiThrust_m = filmAntiThrust_.value_m;
      f.minFilmThicknessAntiThrustAngle_deg = filmAntiThrust_.angle_deg;
    }
    if (sigmaThrust_.valid) {
      f.minGapOverSigmaThrust = sigmaThrust_.value_m;
      f.minGapOverSigmaThrustAngle_deg = sigmaThrust_.angle_deg;
    }
    if (sigmaAntiThrust_.valid) {
      f.minGapOverSigmaAntiThrust = sigmaAntiThrust_.value_m;
      f.minGapOverSigmaAntiThrustAngle_deg = sigmaAntiThrust_.angle_deg;
    }
    if (workAtCycleStart_J_ && workAtCycleEnd_J_) {
      f.frictionWork_J = *workAtCycleEnd_J_ - *workAtCycleStart_J_;
      f.fmep_Pa = *f.frictionWork_J / s.displacement_m3;
      const double duration_s = timeAtCycleEnd_s_ - timeAtCycleStart_s_;
      if (duration_s > 0.0)
        f.frictionPowerMean_W = *f.frictionWork_J / duration_s;
    }
    if (asperityWorkAtCycleStart_J_ && asperityWorkAtCycleEnd_J_)
      f.asperityFrictionWork_J = *asperityWorkAtCycleEnd_J_ - *asperityWorkAtCycleStart_J_;
    if (dissipatedAtCycleStart_J_ && dissipatedAtCycleEnd_J_)
      f.dissipatedEnergy_J = *dissipatedAtCycleEnd_J_ - *dissipatedAtCycleStart_J_;
    if (secondaryAtCycleStart_J_ && secondaryAtCycleEnd_J_)
      f.secondaryMotionWork_J = *secondaryAtCycleEnd_J_ - *secondaryAtCycleStart_J_;
    if (slap_.valid)
      f.slapEnergyMax_J = slap_.max_J;
    f.hotRunningClearance_m = liner_->getHotRunningClearance_m();
    if (const std::optional<plugin::SolverCounters> c = liner_->getSolverCounters()) {
      const plugin::SolverCounters start = countersAtStart_.value_or(plugin::SolverCounters());
      f.filmSolves = c->filmSolves - start.filmSolves;
      f.filmFallbacks = c->filmFallbacks - start.filmFallbacks;
      f.filmDerivativeFailures = c->derivativeFailures - start.derivativeFailures;
    }
    s.liner = f;
  }
  return s;
}

}  // namespace pistondyn::io
