// Result writers: numbers round-trip doubles, files are written all-or-nothing.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include <charconv>
#include <cstring>
#include <functional>
#include <limits>
#include <map>

#include "ScratchDeck.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/RunDeck.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

// Results are written with the shortest text that reads back to the same double.
TEST(ResultWriters, NumbersRoundTrip) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const double x = unit(rng) * std::pow(10.0, static_cast<int>(rng() % 40) - 20);
    EXPECT_EQ(std::strtod(pistondyn::io::formatNumber(x).c_str(), nullptr), x);
  }
  // A metre-valued position keeps sub-nanometre resolution.
  const double y = 0.179999305554216;
  EXPECT_EQ(std::strtod(pistondyn::io::formatNumber(y + 3e-13).c_str(), nullptr), y + 3e-13);
}

// All-or-nothing: if any file cannot be placed, the folder is left exactly as it was
// (old results intact, no new or temporary files), whichever file fails.
TEST(ResultWriters, AtomicWriteLeavesTheFolderAsItWasOnFailure) {
  const fs::path dir =
      fs::temp_directory_path() / ("pistondyn_atomic_" + std::to_string(::getpid()));
  for (const char* blocked : {"cycle.csv", "summary.json"}) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "cycle.csv") << "old cycle";
    std::ofstream(dir / "summary.json") << "old summary";
    fs::remove(dir / blocked);
    fs::create_directories(dir / blocked);  // a folder where a result file must go
    EXPECT_THROW(pistondyn::io::writeFilesAtomically(
                     dir.string(), {{"cycle.csv", "new cycle"}, {"summary.json", "new summary"}}),
                 std::runtime_error);
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
      names.push_back(e.path().filename());
    EXPECT_EQ(names.size(), 2u) << blocked;
    EXPECT_TRUE(fs::is_directory(dir / blocked));
    const std::string other = std::string(blocked) == "cycle.csv" ? "summary.json" : "cycle.csv";
    EXPECT_EQ(readFile(dir / other), other == "cycle.csv" ? "old cycle" : "old summary") << blocked;
  }
  // And the success path replaces old results.
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "cycle.csv") << "old cycle";
  pistondyn::io::writeFilesAtomically(dir.string(), {{"cycle.csv", "new"}, {"summary.json", "s"}});
  EXPECT_EQ(readFile(dir / "cycle.csv"), "new");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
  fs::remove_all(dir);
}

// summary.json is written by nlohmann/json, whose double output (Grisu2) must read back
// to the identical double. Checked on random bit patterns (every exponent, subnormals)
// and on hard cases; how often its text is longer than the shortest (std::to_chars) is
// recorded, not asserted: it is allowed to be, as long as it round-trips.
TEST(SummaryJson, NlohmannDoublesReadBackBitForBit) {
  std::mt19937_64 rng(2024);
  std::vector<double> values = {0.0,
                                -0.0,
                                0.1,
                                1.0 / 3.0,
                                1e23,
                                5e-324,
                                2.2250738585072014e-308,
                                std::numeric_limits<double>::max(),
                                -std::numeric_limits<double>::max(),
                                9007199254740993.0,
                                0.179999305554216 + 3e-13};
  for (int i = 0; i < 300000; ++i) {
    const std::uint64_t bits = rng();
    double x = 0.0;
    std::memcpy(&x, &bits, sizeof x);
    if (std::isfinite(x))
      values.push_back(x);
  }
  // Significant digits of a number's text (mantissa without leading/trailing zeros).
  auto digits = [](const std::string& text) {
    std::string m;
    for (const char c : text) {
      if (c == 'e' || c == 'E')
        break;
      if (c >= '0' && c <= '9')
        m += c;
    }
    const auto first = m.find_first_not_of('0');
    return first == std::string::npos ? std::size_t(1) : m.find_last_not_of('0') - first + 1;
  };
  long longer = 0;
  for (const double x : values) {
    const std::string text = nlohmann::json(x).dump();
    const double y = std::strtod(text.c_str(), nullptr);
    ASSERT_EQ(std::memcmp(&x, &y, sizeof x), 0) << text;
    if (digits(text) > digits(pistondyn::io::formatNumber(x)))
      ++longer;
  }
  RecordProperty("values", static_cast<int>(values.size()));
  RecordProperty("longer_than_shortest", static_cast<int>(longer));
}

// Every number in a real summary.json, parsed back, is bit for bit the double the run
// computed (inputs, results, timings).
TEST_F(ScratchDeck, EveryNumberInSummaryJsonIsTheComputedDouble) {
  namespace io = pistondyn::io;
  const auto d = io::loadEngineDeck(deck(), {"simulation.output_step_deg=4"});
  const fs::path out = dir_ / "results";
  const io::RunOutcome o = io::runDeck(d, out.string());
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& e = d.engine;
  const auto& s = o.summary;
  const std::map<std::string, double> expected = {
      // Inputs under the deck's keys, the unit replaced by the SI one (geometry.stroke_mm
      // as stroke_m = 2 x the crank radius, exactly).
      {"/inputs/geometry/bore_m", e.piston.bore_m},
      {"/inputs/geometry/stroke_m", 2.0 * e.geometry.crankRadius_m},
      {"/inputs/geometry/conrod_length_m", e.geometry.conrodLength_m},
      {"/inputs/geometry/pin_offset_m", e.geometry.pinOffset_m},
      {"/inputs/geometry/crank_offset_m", e.geometry.crankOffset_m},
      {"/inputs/geometry/compression_ratio", e.geometry.compressionRatio},
      {"/inputs/piston/compression_height_m", e.piston.compressionHeight_m},
      {"/inputs/piston/skirt_length_m", e.piston.skirtLength_m},
      {"/inputs/piston/skirt_top_above_pin_m", e.piston.skirtTopAbovePin_m},
      {"/inputs/piston/mass_kg", e.mass.piston.mass_kg},
      {"/inputs/piston/com_towards_thrust_m", e.mass.piston.comX_m},
      {"/inputs/piston/com_above_pin_m", e.mass.piston.comY_m},
      {"/inputs/piston/inertia_kg_m2", e.mass.piston.inertiaZZ_kgm2},
      {"/inputs/pin/mass_kg", e.mass.pin.mass_kg},
      {"/inputs/pin/inertia_kg_m2", e.mass.pin.inertiaZZ_kgm2},
      {"/inputs/conrod/mass_kg", e.mass.conrod.mass_kg},
      {"/inputs/conrod/com_from_big_end_m", e.mass.conrod.comY_m},
      {"/inputs/conrod/inertia_kg_m2", e.mass.conrod.inertiaZZ_kgm2},
      {"/inputs/crank/mass_kg", e.mass.crank.mass_kg},
      {"/inputs/crank/com_radius_m", e.mass.crank.comY_m},
      {"/inputs/crank/inertia_kg_m2", e.mass.crank.inertiaZZ_kgm2},
      {"/inputs/drive/speed_rad_per_s", e.drive.speed_radps},
      {"/inputs/drive/flywheel_inertia_kg_m2", e.drive.flywheelInertia_kgm2},
      {"/inputs/drive/load_torque_Nm", e.drive.loadTorque_Nm},
      {"/inputs/gas/crankcase_pressure_Pa", d.crankcasePressure_Pa},
      {"/inputs/gas/stated_imep_Pa", *d.statedImep_Pa},
      {"/inputs/simulation/start_angle_deg", d.simulation.startAngle_deg},
      {"/inputs/simulation/cycles", static_cast<double>(d.simulation.cycles)},
      {"/inputs/simulation/output_step_deg", d.simulation.outputStep_deg},
      {"/inputs/simulation/accuracy", d.simulation.accuracy},
      {"/model/constraint_tolerance", d.simulation.constraintTolerance},
      {"/inputs/simulation/gravity_mps2", e.gravity_mps2},
      {"/inputs/simulation/pose_tolerance_m", d.simulation.poseTolerance_m},
      {"/inputs/simulation/max_step_deg", d.simulation.maxStep_deg},
      {"/inputs/simulation/stepper_order", static_cast<double>(d.simulation.stepperOrder)},
      {"/inputs/simulation/jacobian_reuse_steps",
       static_cast<double>(d.simulation.jacobianReuseSteps)},
      {"/inputs/simulation/max_steps", static_cast<double>(d.simulation.maxSteps)},
      {"/inputs/simulation/periodic_fmep_tolerance", d.simulation.periodicFmepTolerance},
      {"/inputs/simulation/periodic_pose_tolerance_m", d.simulation.periodicPoseTolerance_m},
      {"/results/imep_kPa", s.imep_Pa / 1e3},
      {"/results/displacement_m3", s.displacement_m3},
      {"/results/kinematic_stroke_m", s.kinematicStroke_m},
      {"/results/peak_cylinder_pressure_Pa", s.peakCylinderPressure_Pa},
      {"/results/peak_cylinder_pressure_angle_deg", s.peakCylinderPressureAngle_deg},
      {"/results/side_force_max_N", s.liner->sideForceMax_N},
      {"/results/side_force_max_angle_deg", s.liner->sideForceMaxAngle_deg},
      {"/results/side_force_min_N", s.liner->sideForceMin_N},
      {"/results/side_force_min_angle_deg", s.liner->sideForceMinAngle_deg},
      {"/results/conrod_force_max_N", s.conrodForceMax_N},
      {"/results/conrod_force_min_N", s.conrodForceMin_N},
      {"/results/crank_train_side_force_max_N", s.crankTrainSideForceMax_N},
      {"/results/crank_train_side_force_max_angle_deg", s.crankTrainSideForceMaxAngle_deg},
      {"/results/crank_train_side_force_min_N", s.crankTrainSideForceMin_N},
      {"/results/crank_train_side_force_min_angle_deg", s.crankTrainSideForceMinAngle_deg},
      {"/results/mean_crank_torque_Nm", s.meanCrankTorque_Nm},
      {"/results/mean_drive_torque_Nm", s.meanDriveTorque_Nm},
      {"/results/indicated_power_W", s.indicatedPower_W},
      {"/results/cycles_run", static_cast<double>(o.stats.cyclesRun)},
      {"/results/rejected_steps", static_cast<double>(o.stats.rejectedSteps)},
      {"/results/failed_evaluations", static_cast<double>(o.stats.failedEvaluations)},
      {"/results/wall_time_s", o.stats.wallTime_s},
      {"/wall_time_s", o.stats.wallTime_s},
      {"/integrator_steps", static_cast<double>(o.stats.integratorSteps)},
  };
  // Walk every number of the file: each must be expected, and equal bit for bit.
  std::size_t seen = 0;
  std::function<void(const nlohmann::json&, const std::string&)> walk =
      [&](const nlohmann::json& node, const std::string& path) {
        if (node.is_object()) {
          for (const auto& kv : node.items())
            walk(kv.value(), path + "/" + kv.key());
        } else if (node.is_number()) {
          ++seen;
          const auto it = expected.find(path);
          ASSERT_NE(it, expected.end()) << "unexpected number " << path;
          const double v = node.get<double>();
          EXPECT_EQ(std::memcmp(&v, &it->second, sizeof v), 0)
              << path << ": " << v << " vs " << it->second;
        }
      };
  walk(j, "");
  EXPECT_EQ(seen, expected.size());
  // One cycle, not run to periodic steady state: no number of cycles to converge.
  ASSERT_FALSE(o.stats.converged);
  EXPECT_TRUE(j["results"]["cycles_to_converge"].is_null());
}

}  // namespace
