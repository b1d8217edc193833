#include "pistondyn/io/RunDeck.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "CycleMaps.h"
#include "FieldDumps.h"
#include "LinerFilmDump.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/Version.h"
#include "pistondyn/io/WarmStartFile.h"

namespace pistondyn::io {
namespace {

// Keys keep the order they are written in (nlohmann::json would sort them).
using Json = nlohmann::ordered_json;

const char* kAngleConvention =
    "crank angle 0 deg = firing TDC (piston at top dead centre at the start of the expansion "
    "stroke); 720 deg four-stroke cycle";
const char* kFrameConvention =
    "x towards the thrust side, y along the cylinder axis towards the head, z along the pin "
    "axis; tilt > 0 = crown leaning towards the thrust side";

// The deck's inputs as read (defaults included), nested by their SI key paths
// (geometry.bore_mm read as geometry.bore_m -> {"geometry": {"bore_m": ...}}): the names
// of the deck with the unit the value is written in, nothing renamed.
Json nestedInputs(const std::vector<ResolvedInput>& inputs) {
  Json root = Json::object();
  for (const auto& in : inputs) {
    std::string path = in.siPath;
    Json* node = &root;
    for (auto dot = path.find('.'); dot != std::string::npos; dot = path.find('.')) {
      node = &(*node)[path.substr(0, dot)];
      path.erase(0, dot + 1);
    }
    std::visit([&](const auto& v) { (*node)[path] = v; }, in.value);
  }
  return root;
}

// Every number written is finite: a figure that is not would be a failed run, never a null in
// the summary.
double finite(const char* key, double v) {
  if (!std::isfinite(v))
    throw std::runtime_error(std::string("summary.json: ") + key + " is not finite");
  return v;
}

// The deck's figures of a summary (the same in every cycle), in the summary's names and units.
Json deckFigures(const CycleSummary& s) {
  Json r;
  r["imep_kPa"] = s.imep_Pa / 1e3;
  r["displacement_m3"] = s.displacement_m3;
  r["kinematic_stroke_m"] = s.kinematicStroke_m;
  r["peak_cylinder_pressure_Pa"] = s.peakCylinderPressure_Pa;
  r["peak_cylinder_pressure_angle_deg"] = s.peakCylinderPressureAngle_deg;
  return r;
}

// The simulated figures of one cycle, in the summary's names and units.
Json cycleFigures(const CycleSummary& s) {
  Json r = Json::object();
  if (s.liner) {
    // From the liner element's role interface (plugin::LinerElement), if there is one.
    const CycleSummary::LinerFigures& f = *s.liner;
    r["side_force_max_N"] = f.sideForceMax_N;
    r["side_force_max_angle_deg"] = f.sideForceMaxAngle_deg;
    r["side_force_min_N"] = f.sideForceMin_N;
    r["side_force_min_angle_deg"] = f.sideForceMinAngle_deg;
    // Figures the liner reports (absent when it does not, e.g. the ideal guide's film).
    auto optional = [&](const char* key, const std::optional<double>& v, double scale = 1.0) {
      if (v)
        r[key] = finite(key, *v * scale);
    };
    optional("fmep_kPa", f.fmep_Pa, 1e-3);
    optional("friction_work_J", f.frictionWork_J);
    optional("friction_power_mean_W", f.frictionPowerMean_W);
    optional("asperity_friction_work_J", f.asperityFrictionWork_J);
    // The asperity share of the friction work (the thesis' 0 -> 18 % when starved).
    if (f.asperityFrictionWork_J && f.frictionWork_J && *f.frictionWork_J > 0.0)
      r["asperity_friction_work_share"] =
          finite("asperity_friction_work_share", *f.asperityFrictionWork_J / *f.frictionWork_J);
    // The energy balance of the liner over the cycle (LinerElement.h): friction work and the
    // work taken from the secondary motion against what the films and friction dissipated.
    optional("dissipated_energy_J", f.dissipatedEnergy_J);
    optional("secondary_motion_work_J", f.secondaryMotionWork_J);
    if (f.dissipatedEnergy_J && f.frictionWork_J && f.secondaryMotionWork_J &&
        *f.dissipatedEnergy_J > 0.0)
      r["energy_balance_relative_error"] = finite(
          "energy_balance_relative_error",
          (*f.frictionWork_J + *f.secondaryMotionWork_J - *f.dissipatedEnergy_J) /
              *f.dissipatedEnergy_J);
    optional("min_h_over_sigma_thrust", f.minGapOverSigmaThrust);
    optional("min_h_over_sigma_thrust_crank_angle_deg", f.minGapOverSigmaThrustAngle_deg);
    optional("min_h_over_sigma_antithrust", f.minGapOverSigmaAntiThrust);
    optional("min_h_over_sigma_antithrust_crank_angle_deg", f.minGapOverSigmaAntiThrustAngle_deg);
    optional("min_film_thickness_thrust_um", f.minFilmThicknessThrust_m, 1e6);
    optional("min_film_thickness_thrust_crank_angle_deg", f.minFilmThicknessThrustAngle_deg);
    optional("min_film_thickness_antithrust_um", f.minFilmThicknessAntiThrust_m, 1e6);
    optional("min_film_thickness_antithrust_crank_angle_deg",
             f.minFilmThicknessAntiThrustAngle_deg);
    // The secondary motion matters where the liner has a film (a guide holds the piston on
    // the axis: its extremes would be the constraint tolerance).
    if (f.minFilmThicknessThrust_m || f.minFilmThicknessAntiThrust_m) {
      r["max_abs_u_lat_um"] = finite("max_abs_u_lat_um", s.maxAbsLateralDisplacement_m * 1e6);
      r["max_abs_tilt_deg"] = finite("max_abs_tilt_deg", s.maxAbsTilt_rad * 180.0 / M_PI);
    }
    optional("slap_energy_max_mJ", f.slapEnergyMax_J, 1e3);
    optional("hot_clearance_um", f.hotRunningClearance_m, 1e6);
  }
  r["conrod_force_max_N"] = s.conrodForceMax_N;
  r["conrod_force_min_N"] = s.conrodForceMin_N;
  // The crank train's own side force (from the rod), beside the liner's side_force_*.
  r["crank_train_side_force_max_N"] = s.crankTrainSideForceMax_N;
  r["crank_train_side_force_max_angle_deg"] = s.crankTrainSideForceMaxAngle_deg;
  r["crank_train_side_force_min_N"] = s.crankTrainSideForceMin_N;
  r["crank_train_side_force_min_angle_deg"] = s.crankTrainSideForceMinAngle_deg;
  r["mean_crank_torque_Nm"] = s.meanCrankTorque_Nm;
  r["mean_drive_torque_Nm"] = s.meanDriveTorque_Nm;
  r["indicated_power_W"] = s.indicatedPower_W;
  return r;
}

// The mean and the spread (largest minus smallest) of every figure of cycleFigures() over the
// last kLastCyclesSummarised cycles (fewer if fewer ran), and which cycles they are (1 = the first).
Json lastCyclesSpread(const std::vector<CycleSummary>& cycles) {
  const std::size_t n = std::min(kLastCyclesSummarised, cycles.size());
  std::vector<Json> figures;
  Json numbers = Json::array();
  for (std::size_t i = cycles.size() - n; i < cycles.size(); ++i) {
    figures.push_back(cycleFigures(cycles[i]));
    numbers.push_back(i + 1);
  }
  Json out;
  out["note"] = "the run did not become periodic: mean and spread (largest - smallest) of each "
                "figure over these cycles";
  out["cycles"] = numbers;
  Json& mean = out["mean"];
  Json& spread = out["spread"];
  for (const auto& item : figures.back().items()) {
    const std::string& key = item.key();
    double sum = 0.0, lo = INFINITY, hi = -INFINITY;
    bool everyCycle = true;
    for (const Json& f : figures) {
      const auto it = f.find(key);
      if (it == f.end() || !it->is_number()) {
        everyCycle = false;
        break;
      }
      const double v = it->get<double>();
      sum += v;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    if (!everyCycle)
      continue;  // a figure some cycle does not have is not averaged
    mean[key] = sum / static_cast<double>(n);
    spread[key] = hi - lo;
  }
  return out;
}

}  // namespace

std::vector<std::string> makeCycleCsvComments(const EngineDeck& deck) {
  return {"pistondyn " + getVersion() + " cycle results for " + deck.deckPath, kAngleConvention,
          kFrameConvention};
}

std::string makeSummaryJson(const EngineDeck& deck, const RunOutcome& o) {
  const mbd::EngineDescription& e = deck.engine;
  const plugin::SimulationSettings& st = deck.simulation;
  Json j;
  j["pistondyn_version"] = getVersion();
  j["crank_angle_convention"] = kAngleConvention;
  j["frame_convention"] = kFrameConvention;
  // Absolute: the summary names the deck wherever it is read from (the report reads it).
  std::error_code ec;
  const std::filesystem::path deckFile = std::filesystem::absolute(deck.deckPath, ec);
  j["deck_file"] = ec ? deck.deckPath : deckFile.lexically_normal().string();
  j["overrides"] = deck.overrides;
  // full: the deck as written; preview: a coarser film grid for a quick look (EngineDeck.h),
  // its assignments among the overrides above and its grid among the inputs below.
  j["fidelity"] = getFidelityName(deck.fidelity);
  if (!deck.fidelityNote.empty())
    j["fidelity_note"] = deck.fidelityNote;
  // Where the run started from: an earlier run's end (WarmStartFile.h), or the deck's pose.
  if (!deck.warmStartFrom.empty()) {
    const std::filesystem::path from = std::filesystem::absolute(deck.warmStartFrom, ec);
    j["warm_start_from"] = ec ? deck.warmStartFrom : from.lexically_normal().string();
  }

  j["inputs"] = nestedInputs(deck.inputs);
  // What the model uses besides the deck's keys.
  Json& model = j["model"];
  model["crank_train_tertiary_motion"] = e.tertiaryMotion;
  model["constraint_tolerance"] = st.constraintTolerance;

  Json& r = j["results"];
  r["note"] = "figures of the last simulated 720 deg cycle";
  r.update(deckFigures(o.summary));
  r.update(cycleFigures(o.summary));
  if (o.summary.liner) {
    // The run's own figures of a liner that reports them.
    if (!o.stats.cycleFmep_Pa.empty()) {
      Json list = Json::array();
      for (double v : o.stats.cycleFmep_Pa)
        list.push_back(finite("cycle_fmep_kPa", v / 1e3));
      r["cycle_fmep_kPa"] = list;
    }
    const CycleSummary::LinerFigures& f = *o.summary.liner;
    if (f.filmSolves)
      r["film_solves"] = *f.filmSolves;
    if (f.filmFallbacks)
      r["film_fallbacks"] = *f.filmFallbacks;
    if (f.filmDerivativeFailures)
      r["film_derivative_failures"] = *f.filmDerivativeFailures;
  }
  // The run itself (SimulationStats).
  r["cycles_run"] = o.stats.cyclesRun;
  r["converged"] = o.stats.converged;                  // until_periodic: the last two agreed
  // null unless converged: no number of cycles to converge is claimed for a run that did not.
  r["cycles_to_converge"] = o.stats.converged ? Json(o.stats.cyclesToConverge) : Json(nullptr);
  // A run of several cycles that did not reach a periodic state: its last cycles' spread says
  // how much the one cycle above stands for.
  if (!o.stats.converged && o.cycleSummaries.size() >= 2)
    r["last_cycles"] = lastCyclesSpread(o.cycleSummaries);
  r["rejected_steps"] = o.stats.rejectedSteps;         // linearly_implicit_bdf2's error test
  // The integrator's work per cycle run (each list sums to the run's figure).
  r["cycle_integrator_steps"] = o.stats.cycleIntegratorSteps;
  r["cycle_rejected_steps"] = o.stats.cycleRejectedSteps;
  r["cycle_force_evaluations"] = o.stats.cycleRealizations;
  // linearly_implicit_bdf2: its estimate of the step error per cycle (the sum of its steps'
  // local error estimates on the pose) and that of the cycle the figures above describe.
  const std::vector<double>& errors_um = o.stats.cycleStepErrorEstimate_um;
  if (!errors_um.empty() && std::isfinite(errors_um.back())) {
    r["cycle_step_error_estimate_um"] = errors_um;
    r["step_error_estimate_um"] = errors_um.back();
  }
  // linearly_implicit_bdf2: steps retried because an element threw, e.g. a film solve or an
  // elastic coupling that did not converge on a trial step (never silent, issue 12).
  r["failed_evaluations"] = o.stats.failedEvaluations;
  r["wall_time_s"] = o.stats.wallTime_s;
  if (o.linerOilLastCycle) {
    // The liner oil over the last cycle, results.liner_oil_*_mm3: what came and went, and
    // what closes the balance (round-off; periodic when the start and end agree).
    const plugin::LinerOilBalance& b = *o.linerOilLastCycle;
    const auto put = [&r](const std::string& name, double v_m3) {
      r["liner_oil_" + name + "_mm3"] = 1e9 * v_m3;
    };
    put("stored_start", b.initial_m3);
    put("stored_end", b.stored_m3);
    put("ring_source", b.flows.ringSource_m3);
    put("splash_source", b.flows.splashSource_m3);
    put("deficit_source", b.flows.deficitSource_m3);
    put("drain", b.flows.drainLoss_m3);
    put("skirt_film_intake", b.flows.filmIntake_m3);
    put("side_leakage", b.flows.sideLeakage_m3);
    put("left_on_skirt", b.flows.skirtShareLoss_m3);
    put("balance_residual", (b.stored_m3 - b.initial_m3) - b.flows.netSource_m3());
  }
  j["wall_time_s"] = o.stats.wallTime_s;
  j["integrator_steps"] = o.stats.integratorSteps;
  // nlohmann writes doubles in the shortest text that reads back to the same double
  // (tests/io: SummaryJson.*), NaN and infinities as null; text that is not UTF-8 (a
  // deck in Latin-1) is replaced, not a reason to lose the run.
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

RunOutcome runModel(const EngineDeck& deck, plugin::PistonAssemblyModel& model,
                    const std::string& outDir, const plugin::CycleSimulation::Progress& progress,
                    const std::vector<plugin::RowSink*>& extraSinks) {
  plugin::CycleSimulation sim(model, deck.simulation);
  CycleSummarySink summary(deck, model);
  std::vector<plugin::RowSink*> sinks{&summary};
  // The folder (created if needed) and cycle.csv streamed under a temporary name; a
  // throw from here on leaves the folder as it was (ResultFileSet's destructor).
  std::optional<ResultFileSet> files;
  std::optional<CsvRowSink> csv;
  if (!outDir.empty()) {
    files.emplace(outDir);
    csv.emplace(files->stage("cycle.csv"), makeCycleCsvComments(deck));
    sinks.push_back(&*csv);
  }
  // The liner's field dumps, staged with cycle.csv (all-or-nothing).
  std::optional<detail::FieldDumpSink> dumps;
  if (files && !deck.fieldDumpAngles_deg.empty()) {
    const plugin::LinerElement* liner =
        static_cast<const plugin::PistonAssemblyModel&>(model).findLinerElement();
    const plugin::NodalFieldSource* fields = liner ? liner->getNodalFields() : nullptr;
    if (fields == nullptr) {
      throw std::runtime_error(
          "liner.field_dumps: the model's liner element has no nodal fields; nothing to dump");
    }
    dumps.emplace(*fields, deck.fieldDumpAngles_deg, deck.simulation.stepsPerCycle(),
                  makeCycleCsvComments(deck), *files);
    sinks.push_back(&*dumps);
  }
  // The maps of the liner's nodal fields over the last cycle (CycleMaps.h), staged likewise.
  std::optional<detail::CycleMapSink> maps;
  if (files) {
    const plugin::LinerElement* liner =
        static_cast<const plugin::PistonAssemblyModel&>(model).findLinerElement();
    if (const plugin::NodalFieldSource* fields = liner ? liner->getNodalFields() : nullptr) {
      maps.emplace(*fields, deck.simulation.stepsPerCycle(), makeCycleCsvComments(deck), *files);
      sinks.push_back(&*maps);
    }
  }
  // The liner's oil film along the bore (liner_film.csv, staged) and its balance.
  std::optional<detail::LinerFilmSink> linerFilm;
  {
    const plugin::LinerElement* liner =
        static_cast<const plugin::PistonAssemblyModel&>(model).findLinerElement();
    if (const plugin::LinerOilSource* oil = liner ? liner->getLinerOil() : nullptr) {
      linerFilm.emplace(*oil, deck.simulation.stepsPerCycle(), makeCycleCsvComments(deck),
                        files ? &*files : nullptr);
      sinks.push_back(&*linerFilm);
    }
  }
  sinks.insert(sinks.end(), extraSinks.begin(), extraSinks.end());
  sim.run(sinks, progress);

  RunOutcome o;
  o.summary = summary.getSummary();
  o.cycleSummaries = summary.getCycleSummaries();
  o.stats = sim.getStats();
  o.rows = summary.getRowCount();
  if (linerFilm)
    o.linerOilLastCycle = linerFilm->getLastCycleBalance();
  if (files) {
    files->stageText("summary.json", makeSummaryJson(deck, o));
    if (o.stats.endState)  // the run's end, for a later run's warm start
      files->stageText(kWarmStartFile, makeWarmStartJson(*o.stats.endState));
    files->commit();
  }
  return o;
}

RunOutcome runDeck(const EngineDeck& deck, const std::string& outDir,
                   const plugin::CycleSimulation::Progress& progress,
                   const std::vector<plugin::RowSink*>& extraSinks) {
  auto model = buildModel(deck);
  return runModel(deck, *model, outDir, progress, extraSinks);
}

}  // namespace pistondyn::io
