#include "pistondyn/io/RunDeck.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "pistondyn/io/ResultWriters.h"

#ifndef PISTONDYN_VERSION
#define PISTONDYN_VERSION "unknown"
#endif

namespace pistondyn::io {
namespace {

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
    case plugin::SimulationSettings::Integrator::RungeKuttaFeldberg: return "rk_feldberg";
    case plugin::SimulationSettings::Integrator::CPodesBDF: return "cpodes_bdf";
    case plugin::SimulationSettings::Integrator::RungeKuttaMerson:
    default: return "rk_merson";
  }
}

void writeBody(JsonWriter& j, const std::string& key, const mbd::PlanarMassProperties& b) {
  j.beginObject(key)
      .value("mass_kg", b.mass_kg)
      .value("com_x_m", b.comX_m)
      .value("com_y_m", b.comY_m)
      .value("inertia_zz_kg_m2", b.inertiaZZ_kgm2)
      .endObject();
}

}  // namespace

CycleSummary summarize(const EngineDeck& deck, const plugin::ResultTable& table) {
  CycleSummary s;
  const mbd::SliderCrank kin(deck.engine.geometry);
  const mbd::CylinderVolume vol(kin, deck.engine.piston.bore_m,
                                deck.engine.geometry.compressionRatio);
  s.imep_Pa = mbd::calcImep_Pa(*deck.cylinderPressure, vol);
  // Peak of the table itself (not of the output rows, which may step over it).
  s.peakCylinderPressure_Pa = deck.cylinderPressure->getPeakPressure_Pa();
  s.peakCylinderPressureAngle_deg = deck.cylinderPressure->getPeakPressureAngle_deg();
  s.displacement_m3 = vol.displacement_m3();
  s.kinematicStroke_m = kin.stroke_m();

  // Last cycle: the final 720/step rows (the first row of the cycle repeats as the
  // last one, so it is left out of the means).
  const auto perCycle = static_cast<std::size_t>(deck.simulation.stepsPerCycle());
  const std::size_t end = table.rows.size() - 1, begin = end - perCycle;
  const std::size_t ia = table.columnIndex("crank_angle_deg");
  const std::size_t is = table.columnIndex("side_force_N");
  const std::size_t ic = table.columnIndex("conrod_force_N");
  const std::size_t it = table.columnIndex("crank_torque_Nm");
  const std::size_t id = table.columnIndex("drive_torque_Nm");
  const std::size_t iw = table.columnIndex("crank_speed_rpm");
  s.sideForceMax_N = -INFINITY;
  s.sideForceMin_N = INFINITY;
  s.conrodForceMax_N = -INFINITY;
  s.conrodForceMin_N = INFINITY;
  double torque = 0.0, drive = 0.0, speed = 0.0;
  for (std::size_t k = begin; k < end; ++k) {
    const auto& r = table.rows[k];
    const double angle = std::fmod(r[ia], 720.0);
    if (r[is] > s.sideForceMax_N) {
      s.sideForceMax_N = r[is];
      s.sideForceMaxAngle_deg = angle;
    }
    if (r[is] < s.sideForceMin_N) {
      s.sideForceMin_N = r[is];
      s.sideForceMinAngle_deg = angle;
    }
    s.conrodForceMax_N = std::max(s.conrodForceMax_N, r[ic]);
    s.conrodForceMin_N = std::min(s.conrodForceMin_N, r[ic]);
    torque += r[it];
    drive += r[id];
    speed += r[iw] * M_PI / 30.0;
  }
  const double n = static_cast<double>(perCycle);
  s.meanCrankTorque_Nm = torque / n;
  s.meanDriveTorque_Nm = drive / n;
  s.indicatedPower_W = s.meanCrankTorque_Nm * speed / n;
  return s;
}

std::string makeSummaryJson(const EngineDeck& deck, const RunOutcome& o) {
  std::ostringstream out;
  JsonWriter j(out);
  const mbd::EngineDescription& e = deck.engine;
  const plugin::SimulationSettings& st = deck.simulation;
  j.beginObject();
  j.value("pistondyn_version", PISTONDYN_VERSION);
  j.value("crank_angle_convention", kAngleConvention);
  j.value("frame_convention", kFrameConvention);
  j.value("deck_file", deck.deckPath);
  j.beginArray("overrides");
  for (const auto& ov : deck.overrides)
    j.arrayValue(ov);
  j.endArray();

  j.beginObject("inputs");
  j.value("engine_name", e.name);
  j.beginObject("geometry")
      .value("bore_m", e.piston.bore_m)
      .value("crank_radius_m", e.geometry.crankRadius_m)
      .value("conrod_length_m", e.geometry.conrodLength_m)
      .value("pin_offset_m", e.geometry.pinOffset_m)
      .value("crank_offset_m", e.geometry.crankOffset_m)
      .value("compression_ratio", e.geometry.compressionRatio)
      .endObject();
  j.beginObject("piston")
      .value("compression_height_m", e.piston.compressionHeight_m)
      .value("skirt_length_m", e.piston.skirtLength_m)
      .value("skirt_top_above_pin_m", e.piston.skirtTopAbovePin_m)
      .endObject();
  j.beginObject("mass");
  writeBody(j, "piston", e.mass.piston);
  writeBody(j, "pin", e.mass.pin);
  writeBody(j, "conrod", e.mass.conrod);
  writeBody(j, "crank", e.mass.crank);
  j.endObject();
  j.value("pin_joint", pinJointName(e.pinJoint));
  j.beginObject("drive")
      .value("mode", e.drive.mode == mbd::CrankDrive::Mode::Free ? "free" : "constant_speed")
      .value("speed_rad_per_s", e.drive.speed_radps)
      .value("flywheel_inertia_kg_m2", e.drive.flywheelInertia_kgm2)
      .value("load_torque_N_m", e.drive.loadTorque_Nm)
      .endObject();
  j.beginObject("gas")
      .value("cylinder_pressure_file", deck.cylinderPressureFile)
      .value("crankcase_pressure_Pa", deck.crankcasePressure_Pa);
  if (deck.statedImep_Pa)
    j.value("stated_imep_Pa", *deck.statedImep_Pa);
  j.endObject();
  j.value("liner_model", deck.linerModel);
  j.beginObject("simulation")
      .value("integrator", integratorName(st.integrator))
      .value("start_angle_rad", st.startAngle_deg * M_PI / 180.0)
      .value("cycles", static_cast<long>(st.cycles))
      .value("output_step_rad", st.outputStep_deg * M_PI / 180.0)
      .value("accuracy", st.accuracy)
      .value("constraint_tolerance", st.constraintTolerance)
      .value("gravity_m_per_s2", e.gravity_mps2)
      .endObject();
  j.endObject();

  const CycleSummary& s = o.summary;
  j.beginObject("results");
  j.value("note", "figures of the last simulated 720 deg cycle");
  j.value("imep_kPa", s.imep_Pa / 1e3);
  j.value("displacement_m3", s.displacement_m3);
  j.value("kinematic_stroke_m", s.kinematicStroke_m);
  j.value("peak_cylinder_pressure_Pa", s.peakCylinderPressure_Pa);
  j.value("peak_cylinder_pressure_angle_deg", s.peakCylinderPressureAngle_deg);
  j.value("side_force_max_N", s.sideForceMax_N);
  j.value("side_force_max_angle_deg", s.sideForceMaxAngle_deg);
  j.value("side_force_min_N", s.sideForceMin_N);
  j.value("side_force_min_angle_deg", s.sideForceMinAngle_deg);
  j.value("conrod_force_max_N", s.conrodForceMax_N);
  j.value("conrod_force_min_N", s.conrodForceMin_N);
  j.value("mean_crank_torque_Nm", s.meanCrankTorque_Nm);
  j.value("mean_drive_torque_Nm", s.meanDriveTorque_Nm);
  j.value("indicated_power_W", s.indicatedPower_W);
  j.endObject();
  j.value("wall_time_s", o.stats.wallTime_s);
  j.value("integrator_steps", o.stats.integratorSteps);
  j.endObject();
  return out.str();
}

RunOutcome runDeck(const EngineDeck& deck, const std::string& outDir,
                   const plugin::CycleSimulation::Progress& progress) {
  auto model = buildModel(deck);
  plugin::CycleSimulation sim(*model, deck.simulation);
  RunOutcome o;
  o.table = sim.run(progress);
  o.stats = sim.getStats();
  o.summary = summarize(deck, o.table);
  if (!outDir.empty()) {
    std::ostringstream csv;
    writeCsv(csv, o.table,
             {std::string("pistondyn ") + PISTONDYN_VERSION + " cycle results for " + deck.deckPath,
              kAngleConvention, kFrameConvention});
    writeFilesAtomically(outDir,
                         {{"cycle.csv", csv.str()}, {"summary.json", makeSummaryJson(deck, o)}});
  }
  return o;
}

}  // namespace pistondyn::io
