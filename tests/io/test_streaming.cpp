// Streamed, all-or-nothing runs (io::runDeck / runModel): rows reach the disk while the
// simulation runs, the summary is accumulated by a sink from the liner role interface
// and the crank-train columns, typed outputs name the columns, and a run that fails
// part-way leaves no result files (earlier results kept).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "NumericCsv.h"
#include "ProbeLiner.h"
#include "ScratchDeck.h"
#include "pistondyn/io/RunDeck.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;
namespace io = pistondyn::io;

namespace {

io::LinerRegistry probeRegistry() {
  io::LinerRegistry r;
  registerProbeLiner(r);
  return r;
}

std::vector<std::string> folderContents(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// cycle.csv read back (tests/support/NumericCsv.h).
using Csv = pistondyn::test::NumericCsv;
Csv readCsv(const fs::path& p) {
  return pistondyn::test::readNumericCsv(p);
}

nlohmann::json readJson(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// A user liner whose typed outputs are not its role's figures: the columns are named by
// the outputs (name_unit), the summary's liner figures come from the role.
TEST_F(ScratchDeck, TypedOutputsNameTheColumnsAndTheLinerRoleDrivesTheSummary) {
  const auto d = io::loadEngineDeck(
      deck(),
      {"liner.model=probe_liner", "liner.role_offset_N=1000", "simulation.output_step_deg=5"},
      probeRegistry());
  const fs::path out = dir_ / "results";
  const io::RunOutcome o = io::runDeck(d, out.string());
  const Csv csv = readCsv(out / "cycle.csv");
  EXPECT_NO_THROW(csv.col("spring_push_kN"));
  EXPECT_NO_THROW(csv.col("probe_index"));  // unit "1": no suffix
  EXPECT_THROW(csv.col("side_force_N"), std::out_of_range);
  EXPECT_EQ(csv.rows.size(), 145u);
  EXPECT_EQ(csv.rows[10][csv.col("probe_index")], 7.0);

  // Role: side force = 1000 N + crank angle in deg; over the rows 0, 5, ..., 715 deg.
  // 1e-9 N: the crank angle of a row is omega * t, the nominal angle to rounding.
  const nlohmann::json r = readJson(out / "summary.json")["results"];
  EXPECT_NEAR(r["side_force_max_N"].get<double>(), 1715.0, 1e-9);
  // Angles are the rows' nominal crank angles, k * 5 deg to rounding.
  EXPECT_NEAR(r["side_force_max_angle_deg"].get<double>(), 715.0, 1e-9);
  EXPECT_NEAR(r["side_force_min_N"].get<double>(), 1000.0, 1e-9);
  EXPECT_NEAR(r["side_force_min_angle_deg"].get<double>(), 0.0, 1e-9);
  // Film: (2 + cos theta) um on the thrust side, smallest at 180 deg; none anti-thrust.
  EXPECT_NEAR(r["min_film_thickness_thrust_um"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(r["min_film_thickness_thrust_crank_angle_deg"].get<double>(), 180.0, 1e-9);
  EXPECT_FALSE(r.contains("min_film_thickness_antithrust_um"));
  // It reports no h/sigma, slap energy, clearance or film solves: none are invented.
  for (const char* key :
       {"min_h_over_sigma_thrust", "slap_energy_max_mJ", "hot_clearance_um", "film_solves"})
    EXPECT_FALSE(r.contains(key)) << key;
  // Friction work: 3 J/rad over 4 pi rad.
  EXPECT_NEAR(r["friction_work_J"].get<double>(), 12.0 * M_PI, 1e-9);
  EXPECT_EQ(r["side_force_max_N"].get<double>(), o.summary.liner->sideForceMax_N);
}

// The ideal guide reports no film and no friction work: those figures are absent, and
// the summary has exactly the keys it always had, and the run's statistics.
TEST_F(ScratchDeck, FiguresALinerDoesNotReportAreNotInvented) {
  const auto d = io::loadEngineDeck(deck(), {"simulation.output_step_deg=10"});
  const fs::path out = dir_ / "results";
  io::runDeck(d, out.string());
  const nlohmann::json r = readJson(out / "summary.json")["results"];
  std::vector<std::string> keys;
  for (const auto& kv : r.items())
    keys.push_back(kv.key());
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(keys, (std::vector<std::string>{"conrod_force_max_N",
                                            "conrod_force_min_N",
                                            "converged",
                                            "crank_train_side_force_max_N",
                                            "crank_train_side_force_max_angle_deg",
                                            "crank_train_side_force_min_N",
                                            "crank_train_side_force_min_angle_deg",
                                            "cycle_force_evaluations",
                                            "cycle_integrator_steps",
                                            "cycle_rejected_steps",
                                            "cycles_run",
                                            "cycles_to_converge",
                                            "displacement_m3",
                                            "failed_evaluations",
                                            "imep_kPa",
                                            "indicated_power_W",
                                            "kinematic_stroke_m",
                                            "mean_crank_torque_Nm",
                                            "mean_drive_torque_Nm",
                                            "note",
                                            "peak_cylinder_pressure_Pa",
                                            "peak_cylinder_pressure_angle_deg",
                                            "rejected_steps",
                                            "side_force_max_N",
                                            "side_force_max_angle_deg",
                                            "side_force_min_N",
                                            "side_force_min_angle_deg",
                                            "wall_time_s"}));
}

// A model without a liner element gets no side-force figures at all.
TEST_F(ScratchDeck, AModelWithoutALinerHasNoSideForceFigures) {
  const auto d = io::loadEngineDeck(deck(), {"simulation.output_step_deg=10"});
  auto model = io::buildModel(d);
  model->replaceElement("ideal_liner_guide", std::make_unique<SpringsWithoutRole>());
  ASSERT_EQ(model->findLinerElement(), nullptr);
  const fs::path out = dir_ / "results";
  const io::RunOutcome o = io::runModel(d, *model, out.string());
  EXPECT_FALSE(o.summary.liner.has_value());
  EXPECT_FALSE(readJson(out / "summary.json")["results"].contains("side_force_max_N"));
  EXPECT_NE(o.summary.meanCrankTorque_Nm, 0.0);
}

// The summary sink, from the liner role and the crank-train columns, gives exactly the
// figures computed afterwards from the columns of the written cycle.csv (for the ideal
// guide its side_force_N output is its role getter): bit for bit, through the files.
TEST_F(ScratchDeck, SummaryAgreesBitForBitWithTheWrittenCycleCsv) {
  const auto d =
      io::loadEngineDeck(deck(), {"simulation.output_step_deg=2", "simulation.cycles=2"});
  const fs::path out = dir_ / "results";
  io::runDeck(d, out.string());
  const Csv csv = readCsv(out / "cycle.csv");
  const nlohmann::json r = readJson(out / "summary.json")["results"];
  // The last cycle: the final 360 rows before the closing one (as the table-based
  // summary of earlier versions took them).
  const std::size_t end = csv.rows.size() - 1, begin = end - 360;
  double smax = -INFINITY, smin = INFINITY, amax = 0, amin = 0, cmax = -INFINITY, cmin = INFINITY;
  double torque = 0, drive = 0, speed = 0;
  for (std::size_t k = begin; k < end; ++k) {
    const auto& row = csv.rows[k];
    const double side = row[csv.col("side_force_N")];
    const double angle = std::fmod(row[csv.col("crank_angle_deg")], 720.0);
    if (side > smax) {
      smax = side;
      amax = angle;
    }
    if (side < smin) {
      smin = side;
      amin = angle;
    }
    cmax = std::max(cmax, row[csv.col("conrod_force_N")]);
    cmin = std::min(cmin, row[csv.col("conrod_force_N")]);
    torque += row[csv.col("crank_torque_Nm")];
    drive += row[csv.col("drive_torque_Nm")];
    speed += row[csv.col("crank_speed_rpm")] * M_PI / 30.0;
  }
  EXPECT_TRUE(sameBits(r["side_force_max_N"].get<double>(), smax));
  EXPECT_TRUE(sameBits(r["side_force_max_angle_deg"].get<double>(), amax));
  EXPECT_TRUE(sameBits(r["side_force_min_N"].get<double>(), smin));
  EXPECT_TRUE(sameBits(r["side_force_min_angle_deg"].get<double>(), amin));
  EXPECT_TRUE(sameBits(r["conrod_force_max_N"].get<double>(), cmax));
  EXPECT_TRUE(sameBits(r["conrod_force_min_N"].get<double>(), cmin));
  EXPECT_TRUE(sameBits(r["mean_crank_torque_Nm"].get<double>(), torque / 360));
  EXPECT_TRUE(sameBits(r["mean_drive_torque_Nm"].get<double>(), drive / 360));
  EXPECT_TRUE(sameBits(r["indicated_power_W"].get<double>(), torque / 360 * speed / 360));
}

// A run to periodic steady state drops the earlier cycles (RowSink::discardRows): the
// streamed cycle.csv holds the last cycle only, and the summary is that cycle's. The
// ideal guide repeats itself exactly, so the second cycle already agrees with the first.
TEST_F(ScratchDeck, APeriodicRunWritesOnlyTheLastCycle) {
  auto d = io::loadEngineDeck(deck(), {"simulation.output_step_deg=10"});
  d.simulation.untilPeriodic = true;
  d.simulation.cycles = 4;
  const fs::path out = dir_ / "results";
  const io::RunOutcome o = io::runDeck(d, out.string());
  ASSERT_TRUE(o.stats.converged);
  EXPECT_EQ(o.stats.cyclesToConverge, 2);
  const Csv csv = readCsv(out / "cycle.csv");
  ASSERT_EQ(csv.rows.size(), 73u);  // one cycle and the row that closes it
  EXPECT_EQ(o.rows, 73);
  EXPECT_NEAR(csv.rows.front()[csv.col("crank_angle_deg")], 720.0, 1e-9);
  EXPECT_NEAR(csv.rows.back()[csv.col("crank_angle_deg")], 1440.0, 1e-9);
  double torque = 0.0;
  for (std::size_t k = 0; k + 1 < csv.rows.size(); ++k)
    torque += csv.rows[k][csv.col("crank_torque_Nm")];
  const nlohmann::json r = readJson(out / "summary.json")["results"];
  EXPECT_TRUE(sameBits(r["mean_crank_torque_Nm"].get<double>(), torque / 72));
}

// Rows are on disk while the run goes on, under a temporary name; cycle.csv appears only
// at the end.
TEST_F(ScratchDeck, RowsReachTheDiskWhileTheSimulationRuns) {
  struct Watcher final : pistondyn::plugin::RowSink {
    fs::path dir;
    long rows = 0;
    std::uintmax_t partialBytesAtRow200 = 0;
    bool finalExistedDuringRun = false;
    void consumeRow(const SimTK::State&, const std::vector<double>&) override {
      if (++rows == 200) {
        std::error_code ec;
        partialBytesAtRow200 = fs::file_size(dir / ".cycle.csv.partial", ec);
        finalExistedDuringRun = fs::exists(dir / "cycle.csv");
      }
    }
    void discardRows() override {}
  } watcher;
  watcher.dir = dir_ / "results";
  const auto d = io::loadEngineDeck(deck(), {});
  io::runDeck(d, watcher.dir.string(), {}, {&watcher});
  // 200 rows of ~270 characters; the stream buffer holds at most a few kB of them.
  EXPECT_GT(watcher.partialBytesAtRow200, 20000u);
  EXPECT_FALSE(watcher.finalExistedDuringRun);
  EXPECT_EQ(folderContents(watcher.dir),
            (std::vector<std::string>{"cycle.csv", "summary.json", "warm_start.json"}));
}

// An element that throws at 200 deg: the run fails, earlier results stay as they were,
// nothing new (not even a temporary) is left; a folder the run created is removed.
TEST_F(ScratchDeck, ARunThatFailsPartWayLeavesNoResults) {
  const auto d = io::loadEngineDeck(deck(), {"liner.model=probe_liner", "liner.throw_at_deg=200"},
                                    probeRegistry());
  const fs::path out = dir_ / "results";
  fs::create_directories(out);
  std::ofstream(out / "cycle.csv") << "old cycle";
  std::ofstream(out / "summary.json") << "old summary";
  long rowsSeen = 0;
  struct Counter final : pistondyn::plugin::RowSink {
    long* n;
    void consumeRow(const SimTK::State&, const std::vector<double>&) override { ++*n; }
    void discardRows() override {}
  } counter;
  counter.n = &rowsSeen;
  EXPECT_ANY_THROW(io::runDeck(d, out.string(), {}, {&counter}));
  EXPECT_GT(rowsSeen, 150);  // it failed part-way, after streaming rows
  EXPECT_LT(rowsSeen, 720);
  EXPECT_EQ(folderContents(out), (std::vector<std::string>{"cycle.csv", "summary.json"}));
  EXPECT_EQ(readFile(out / "cycle.csv"), "old cycle");
  EXPECT_EQ(readFile(out / "summary.json"), "old summary");

  const fs::path fresh = dir_ / "new" / "results";
  EXPECT_ANY_THROW(io::runDeck(d, fresh.string()));
  EXPECT_FALSE(fs::exists(dir_ / "new"));
}

}  // namespace
