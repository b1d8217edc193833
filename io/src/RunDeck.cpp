#include "pistondyn/io/RunDeck.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/Version.h"

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

const char* pinJointName(mbd::PinJoint j) {
  switch (j) {
    case mbd::PinJoint::FixedInRod:
      return "fixed_in_rod";
    case mbd::PinJoint::FixedInPiston:
      return "fixed_in_piston";
    case mbd::PinJoint::Floating:
    default:
      return "floating";
  }
}

const char* integratorName(plugin::SimulationSettings::Integrator i) {
  switch (i) {
    case plugin::SimulationSettings::Integrator::RungeKuttaFeldberg:
      return "rk_feldberg";
    case plugin::SimulationSettings::Integrator::CPodesBDF:
      return "cpodes_bdf";
    case plugin::SimulationSettings::Integrator::RungeKuttaMerson:
    default:
      return "rk_merson";
  }
}

Json body(const mbd::PlanarMassProperties& b) {
  Json j;
  j["mass_kg"] = b.mass_kg;
  j["com_x_m"] = b.comX_m;
  j["com_y_m"] = b.comY_m;
  j["inertia_zz_kg_m2"] = b.inertiaZZ_kgm2;
  return j;
}

// The liner model's inputs as read by its factory, nested by their SI key paths
// (liner.film.viscosity_Pas -> {"film": {"viscosity_Pas": ...}}).
Json linerInputs(const std::vector<ResolvedInput>& inputs) {
  Json liner = Json::object();
  for (const auto& in : inputs) {
    std::string path = in.siPath.substr(std::string("liner.").size());
    Json* node = &liner;
    for (auto dot = path.find('.'); dot != std::string::npos; dot = path.find('.')) {
      node = &(*node)[path.substr(0, dot)];
      path.erase(0, dot + 1);
    }
    std::visit([&](const auto& v) { (*node)[path] = v; }, in.value);
  }
  return liner;
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
  j["deck_file"] = deck.deckPath;
  j["overrides"] = deck.overrides;

  Json& in = j["inputs"];
  in["engine_name"] = e.name;
  Json& g = in["geometry"];
  g["bore_m"] = e.piston.bore_m;
  g["crank_radius_m"] = e.geometry.crankRadius_m;
  g["conrod_length_m"] = e.geometry.conrodLength_m;
  g["pin_offset_m"] = e.geometry.pinOffset_m;
  g["crank_offset_m"] = e.geometry.crankOffset_m;
  g["compression_ratio"] = e.geometry.compressionRatio;
  Json& p = in["piston"];
  p["compression_height_m"] = e.piston.compressionHeight_m;
  p["skirt_length_m"] = e.piston.skirtLength_m;
  p["skirt_top_above_pin_m"] = e.piston.skirtTopAbovePin_m;
  Json& m = in["mass"];
  m["piston"] = body(e.mass.piston);
  m["pin"] = body(e.mass.pin);
  m["conrod"] = body(e.mass.conrod);
  m["crank"] = body(e.mass.crank);
  in["pin_joint"] = pinJointName(e.pinJoint);
  Json& d = in["drive"];
  d["mode"] = e.drive.mode == mbd::CrankDrive::Mode::Free ? "free" : "constant_speed";
  d["speed_rad_per_s"] = e.drive.speed_radps;
  d["flywheel_inertia_kg_m2"] = e.drive.flywheelInertia_kgm2;
  d["load_torque_N_m"] = e.drive.loadTorque_Nm;
  Json& gas = in["gas"];
  gas["cylinder_pressure_file"] = deck.cylinderPressureFile;
  gas["crankcase_pressure_Pa"] = deck.crankcasePressure_Pa;
  if (deck.statedImep_Pa)
    gas["stated_imep_Pa"] = *deck.statedImep_Pa;
  in["liner_model"] = deck.linerModel;
  if (!deck.linerInputs.empty())
    in["liner"] = linerInputs(deck.linerInputs);
  Json& sim = in["simulation"];
  sim["integrator"] = integratorName(st.integrator);
  sim["start_angle_rad"] = st.startAngle_deg * M_PI / 180.0;
  sim["cycles"] = static_cast<long>(st.cycles);
  sim["output_step_rad"] = st.outputStep_deg * M_PI / 180.0;
  sim["accuracy"] = st.accuracy;
  sim["constraint_tolerance"] = st.constraintTolerance;
  sim["gravity_m_per_s2"] = e.gravity_mps2;

  const CycleSummary& s = o.summary;
  Json& r = j["results"];
  r["note"] = "figures of the last simulated 720 deg cycle";
  r["imep_kPa"] = s.imep_Pa / 1e3;
  r["displacement_m3"] = s.displacement_m3;
  r["kinematic_stroke_m"] = s.kinematicStroke_m;
  r["peak_cylinder_pressure_Pa"] = s.peakCylinderPressure_Pa;
  r["peak_cylinder_pressure_angle_deg"] = s.peakCylinderPressureAngle_deg;
  if (s.liner) {
    // From the liner element's role interface (plugin::LinerElement), if there is one.
    const CycleSummary::LinerFigures& f = *s.liner;
    r["side_force_max_N"] = f.sideForceMax_N;
    r["side_force_max_angle_deg"] = f.sideForceMaxAngle_deg;
    r["side_force_min_N"] = f.sideForceMin_N;
    r["side_force_min_angle_deg"] = f.sideForceMinAngle_deg;
    auto optional = [&](const char* key, const std::optional<double>& v) {
      if (v)
        r[key] = *v;
    };
    optional("min_film_thickness_thrust_m", f.minFilmThicknessThrust_m);
    optional("min_film_thickness_thrust_angle_deg", f.minFilmThicknessThrustAngle_deg);
    optional("min_film_thickness_anti_thrust_m", f.minFilmThicknessAntiThrust_m);
    optional("min_film_thickness_anti_thrust_angle_deg", f.minFilmThicknessAntiThrustAngle_deg);
    optional("friction_work_J", f.frictionWork_J);
  }
  r["conrod_force_max_N"] = s.conrodForceMax_N;
  r["conrod_force_min_N"] = s.conrodForceMin_N;
  r["mean_crank_torque_Nm"] = s.meanCrankTorque_Nm;
  r["mean_drive_torque_Nm"] = s.meanDriveTorque_Nm;
  r["indicated_power_W"] = s.indicatedPower_W;
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
  sinks.insert(sinks.end(), extraSinks.begin(), extraSinks.end());
  sim.run(sinks, progress);

  RunOutcome o;
  o.summary = summary.getSummary();
  o.stats = sim.getStats();
  o.rows = summary.getRowCount();
  if (files) {
    const std::string path = files->stage("summary.json");
    std::ofstream out(path, std::ios::binary);
    out << makeSummaryJson(deck, o);
    out.close();
    if (!out)
      throw std::runtime_error(outDir + "/summary.json: write failed");
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
