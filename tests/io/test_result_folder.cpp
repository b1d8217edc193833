// Reading a result folder back (io/ResultFolder.h): the last cycle's rows on a 0-720 deg
// axis for runs that start anywhere and run several cycles, unit suffixes, the flattened
// summary and the field-dump listing. Expected values are worked out by hand here.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "pistondyn/io/ResultFolder.h"

namespace fs = std::filesystem;
using namespace pistondyn;

namespace {

io::CsvTable anglesTable(double start, double step, int rows) {
  io::CsvTable t;
  t.filePath = "cycle.csv";
  t.columns = {"time_s", "crank_angle_deg", "side_force_N"};
  for (int k = 0; k < rows; ++k) {
    const double a = start + k * step;
    t.rows.push_back({0.0, a, a});  // the side force carries the unmapped angle
  }
  return t;
}

TEST(ResultFolder, LastCycleOfARunFromTdcKeepsBothEnds) {
  // Two cycles from 0 in 90 deg steps: rows 0 ... 1440; the last cycle is 720 ... 1440.
  const auto t = anglesTable(0.0, 90.0, 17);
  const io::CycleWindow w = io::selectLastCycle(t);
  ASSERT_EQ(w.rows.size(), 9u);
  for (std::size_t i = 0; i < 9; ++i) {
    EXPECT_EQ(w.angle_deg[i], 90.0 * i);
    EXPECT_EQ(t.rows[w.rows[i]][2], 720.0 + 90.0 * i);
  }
}

TEST(ResultFolder, LastCycleOfARunFromElsewhereWrapsOnce) {
  // One cycle from 270 deg: rows 270 ... 990. Mapped: 990 -> 270 is the same cycle angle as
  // the first row, so it is kept once (the later row); 720 ... 900 -> 0 ... 180.
  const auto t = anglesTable(270.0, 90.0, 9);
  const io::CycleWindow w = io::selectLastCycle(t);
  const std::vector<double> mapped = {0, 90, 180, 270, 360, 450, 540, 630};
  const std::vector<double> original = {720, 810, 900, 990, 360, 450, 540, 630};
  ASSERT_EQ(w.angle_deg, mapped);
  for (std::size_t i = 0; i < mapped.size(); ++i)
    EXPECT_EQ(t.rows[w.rows[i]][2], original[i]) << i;
  // A negative start: -90 ... 630 -> 0 ... 630, the row at -90 dropped for 630.
  const io::CycleWindow n = io::selectLastCycle(anglesTable(-90.0, 90.0, 9));
  EXPECT_EQ(n.angle_deg, (std::vector<double>{0, 90, 180, 270, 360, 450, 540, 630}));
}

TEST(ResultFolder, UnitSuffixes) {
  EXPECT_EQ(io::getColumnUnit("side_force_N"), "N");
  EXPECT_EQ(io::getColumnUnit("crank_torque_Nm"), "Nm");
  EXPECT_EQ(io::getColumnUnit("piston_ay_mps2"), "mps2");
  EXPECT_EQ(io::getColumnUnit("piston_vy_mps"), "mps");
  EXPECT_EQ(io::getColumnUnit("tilt_mrad"), "mrad");
  EXPECT_EQ(io::getColumnUnit("u_lat_skirt_top_um"), "um");
  EXPECT_EQ(io::getColumnUnit("wear_rate_mm3ph"), "mm3ph");
  EXPECT_EQ(io::getColumnUnit("inertia_zz_kg_m2"), "kg_m2");
  EXPECT_EQ(io::getColumnUnit("min_h_over_sigma_thrust"), "");
  EXPECT_EQ(io::getColumnUnit("film_solves"), "");
  EXPECT_EQ(io::getColumnUnit("rejected_steps"), "");
}

TEST(ResultFolder, ReadsCsvSummaryAndFieldDumps) {
  const fs::path dir = fs::temp_directory_path() / ("pistondyn_rf_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "cycle.csv") << "# pistondyn test\n# crank angle 0 deg = firing TDC\n"
                                      "time_s,crank_angle_deg,side_force_N\n0,0,1\n1,720,2\n";
  std::ofstream(dir / "summary.json")
      << R"({"inputs": {"engine_name": "e", "geometry": {"bore_m": 0.0745}},
             "results": {"fmep_kPa": 2.5, "converged": false, "cycle_fmep_kPa": [2.4, 2.5],
                         "last_cycles": {"note": "n", "cycles": [1, 2],
                                         "mean": {"fmep_kPa": 2.45}, "spread": {"fmep_kPa": 0.1}}}})";
  for (const char* f : {"field_dump_380deg_thrust.csv", "field_dump_380deg_antithrust.csv",
                        "field_dump_0deg_antithrust.csv", "field_dump_0deg_thrust.csv",
                        "field_dump_notes.txt"})
    std::ofstream(dir / f) << "x\n";
  const io::ResultFolder r = io::readResultFolder(dir.string());
  EXPECT_EQ(r.cycle.rows.size(), 2u);
  EXPECT_EQ(r.cycleComments,
            (std::vector<std::string>{"pistondyn test", "crank angle 0 deg = firing TDC"}));
  EXPECT_EQ(r.getSummaryValue("inputs.engine_name"), "e");
  EXPECT_EQ(r.getSummaryValue("inputs.geometry.bore_m"), "0.0745");
  EXPECT_EQ(r.getSummaryValue("results.converged"), "false");
  EXPECT_EQ(r.getSummaryValue("results.cycle_fmep_kPa"), "[2.4, 2.5]");
  EXPECT_EQ(r.getSummaryValue("results.no_such_key"), "");
  EXPECT_EQ(r.getSummaryValue("results.last_cycles.mean.fmep_kPa"), "2.45");
  EXPECT_EQ(r.getSummaryValue("results.last_cycles.cycles"), "[1, 2]");
  ASSERT_EQ(r.fieldDumps.size(), 4u);
  EXPECT_EQ(r.fieldDumps[0].crankAngle_deg, 0.0);
  EXPECT_EQ(r.fieldDumps[0].side, "thrust");
  EXPECT_EQ(r.fieldDumps[1].side, "antithrust");
  EXPECT_EQ(r.fieldDumps[3].crankAngle_deg, 380.0);
  EXPECT_EQ(r.fieldDumps[3].side, "antithrust");
  // Not a result folder: the missing file named.
  fs::remove(dir / "summary.json");
  try {
    io::readResultFolder(dir.string());
    ADD_FAILURE() << "no error without summary.json";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("summary.json"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// A summary.json that is not as run writes it is refused naming the file and the first
// thing wrong; null (a figure run did not reach, e.g. cycles_to_converge) is a number's place.
TEST(ResultFolder, SummaryNotAsRunWritesItIsRefused) {
  const fs::path dir =
      fs::temp_directory_path() / ("pistondyn_rf_shape_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "cycle.csv") << "time_s,crank_angle_deg\n0,0\n1,720\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[]", "expected a JSON object, found an array"},
      {"{}", "no \"results\" object"},
      {R"({"results": [1]})", "\"results\" is an array, expected an object"},
      {R"({"results": {"fmep_kPa": "abc"}})",
       "results.fmep_kPa: expected a number, found the text \"abc\""},
      {R"({"results": {"note": 3}})", "results.note: expected text, found 3"},
      {R"({"results": {"last_cycles": {"mean": {"fmep_kPa": "x"}}}})",
       "results.last_cycles.mean.fmep_kPa: expected a number, found the text \"x\""},
      {R"({"results": {"last_cycles": {"mean": {"fmep": {"kPa": 1}}}}})",
       "results.last_cycles.mean.fmep: expected a number, found an object"},
      {R"({"results": {}, "wall_time_s": "fast"})", "wall_time_s: expected a number"},
      {R"({"results": {}, "inputs": {"geometry": {"bore_m": "wide"}}})",
       "inputs.geometry.bore_m: expected a number, found the text \"wide\""},
  };
  for (const auto& [text, expected] : cases) {
    SCOPED_TRACE(text);
    std::ofstream(dir / "summary.json") << text;
    try {
      io::readResultFolder(dir.string());
      ADD_FAILURE() << "accepted";
    } catch (const io::ResultFolderError& e) {
      EXPECT_NE(std::string(e.what()).find((dir / "summary.json").string() + ": " + expected),
                std::string::npos)
          << e.what();
    }
  }
  std::ofstream(dir / "summary.json")
      << R"({"results": {"cycles_to_converge": null, "converged": false, "note": "n",
                         "cycle_fmep_kPa": [1, 2]},
             "inputs": {"liner": {"model": "ideal_guide", "field_dumps": {"crank_angles_deg": [20]}},
                        "gas": {"cylinder_pressure_file": "/a/b.csv"}}})";
  EXPECT_NO_THROW(io::readResultFolder(dir.string()));
  fs::remove_all(dir);
}

}  // namespace
