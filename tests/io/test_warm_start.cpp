// A run started where an earlier run of the same engine ended (`run --warm-start DIR`,
// plugin::WarmStart, io/WarmStartFile.h). The references are the runs themselves: a run from
// an earlier run's end must continue that run (a longer run without the break gives the same
// cycle within the periodic test's tolerances), and a run from a periodic state must find
// it periodic after its first cycle.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "NumericCsv.h"
#include "ScratchDeck.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/RunDeck.h"
#include "pistondyn/io/WarmStartFile.h"

using namespace pistondyn_test;
namespace io = pistondyn::io;
namespace plugin = pistondyn::plugin;

namespace {

// The gasoline example skirt on a coarse film grid: a cycle in about a second.
const std::vector<std::string> kCoarse = {
    "liner.grid.nodes_circumferential=12", "liner.grid.nodes_axial=8",
    "simulation.output_step_deg=2", "liner.parallel_sides=false"};

std::vector<std::string> coarseWith(std::vector<std::string> more) {
  std::vector<std::string> o = kCoarse;
  o.insert(o.end(), more.begin(), more.end());
  return o;
}

// Largest difference of a column between two cycles of rows (each 360 rows + 1).
double largestDifference(const pistondyn::test::NumericCsv& a, std::size_t firstA,
                         const pistondyn::test::NumericCsv& b, std::size_t firstB,
                         const std::string& column) {
  const std::size_t ca = a.col(column), cb = b.col(column);
  double d = 0.0;
  for (std::size_t k = 0; k <= 360; ++k)
    d = std::max(d, std::abs(a.rows[firstA + k][ca] - b.rows[firstB + k][cb]));
  return d;
}

// From where a run of two cycles ended, one cycle gives the third cycle of a run of three: the
// piston's pose and rates and the films' fill fraction (the starved skirt's slow memory) carry
// over. The same start without the elements' records (the films full) misses it by far more:
// what the check would miss if the fill fraction were not carried.
TEST_F(SkirtScratchDeck, ARunFromAnEarlierRunsEndContinuesIt) {
  const fs::path two = dir_ / "two", three = dir_ / "three", warm = dir_ / "warm";
  const auto deckOf = [&](int cycles) {
    return io::loadEngineDeck(
        deck(), coarseWith({"simulation.cycles=" + std::to_string(cycles),
                            "simulation.until_periodic=false"}));
  };
  const io::RunOutcome r2 = io::runDeck(deckOf(2), two.string());
  io::runDeck(deckOf(3), three.string());
  ASSERT_TRUE(r2.stats.endState);
  EXPECT_EQ(r2.stats.endState->crankAngle_deg, 1440.0);
  ASSERT_EQ(r2.stats.endState->elements.size(), 1u);  // the skirt's two sides

  io::EngineDeck fromEnd = deckOf(1);
  fromEnd.simulation.warmStart = io::readWarmStart(two.string());
  fromEnd.warmStartFrom = two.string();
  const io::RunOutcome r1 = io::runDeck(fromEnd, warm.string());
  io::EngineDeck poseOnly = deckOf(1);
  poseOnly.simulation.warmStart = *r2.stats.endState;
  poseOnly.simulation.warmStart->elements.clear();
  io::runDeck(poseOnly, (dir_ / "pose").string());

  const auto csv3 = pistondyn::test::readNumericCsv(three / "cycle.csv");
  const auto csvW = pistondyn::test::readNumericCsv(warm / "cycle.csv");
  const auto csvP = pistondyn::test::readNumericCsv(dir_ / "pose" / "cycle.csv");
  ASSERT_EQ(csv3.rows.size(), 3u * 360u + 1u);
  ASSERT_EQ(csvW.rows.size(), 361u);
  // The first row is the end state itself: the pose set, and the film solved again at that
  // instant from the carried fill fraction (not a steady film) gives the earlier run's last
  // row's film figures.
  const auto csv2 = pistondyn::test::readNumericCsv(two / "cycle.csv");
  for (const char* column : {"u_lat_um", "tilt_mrad"}) {
    EXPECT_NEAR(csvW.rows[0][csvW.col(column)], csv2.rows.back()[csv2.col(column)], 1e-9)
        << column;
  }
  // Measured 1e-4 relative (one first-order step of the last step's length from the carried
  // fill fraction, where the earlier run took its second-order one); a steady film at that
  // instant held 4 % of the anti-thrust side's oil in the Briggs & Stratton deck.
  for (const char* column : {"film_oil_volume_thrust_mm3", "film_oil_volume_antithrust_mm3",
                             "side_force_N", "hydrodynamic_friction_N"}) {
    const double was = csv2.rows.back()[csv2.col(column)], is = csvW.rows[0][csvW.col(column)];
    EXPECT_NEAR(is, was, 1e-3 * std::abs(was)) << column;
  }
  const double dLat = largestDifference(csv3, 720, csvW, 0, "u_lat_um");
  const double dLatPose = largestDifference(csv3, 720, csvP, 0, "u_lat_um");
  EXPECT_LT(dLat, 0.2);  // um: the periodic test's pose tolerance
  EXPECT_GT(dLatPose, 5.0 * dLat) << dLat << " " << dLatPose;
  const auto summary3 = nlohmann::json::parse(readFile(three / "summary.json"))["results"];
  const double third_kPa = summary3["cycle_fmep_kPa"][2].get<double>();
  EXPECT_NEAR(r1.stats.cycleFmep_Pa.at(0) / 1e3, third_kPa, 0.005 * third_kPa);
  const auto summaryW = nlohmann::json::parse(readFile(warm / "summary.json"));
  EXPECT_NE(summaryW["warm_start_from"].get<std::string>().find("two"), std::string::npos);
}

// From a periodic run's end, the first cycle agrees with the warm start's last: periodic after
// one cycle, with that cycle's figures.
TEST_F(SkirtScratchDeck, ARunFromAPeriodicStateIsPeriodicAfterOneCycle) {
  // 24 x 16: the coarsest film grid on which the example's cycles repeat to 0.2 um.
  const auto o = coarseWith({"liner.grid.nodes_circumferential=24", "liner.grid.nodes_axial=16",
                             "simulation.cycles=8", "simulation.until_periodic=true"});
  const io::RunOutcome first = io::runDeck(io::loadEngineDeck(deck(), o), (dir_ / "a").string());
  ASSERT_TRUE(first.stats.converged);
  io::EngineDeck again = io::loadEngineDeck(deck(), o);
  again.simulation.warmStart = io::readWarmStart((dir_ / "a").string());
  const io::RunOutcome second = io::runDeck(again, (dir_ / "b").string());
  EXPECT_TRUE(second.stats.converged);
  EXPECT_EQ(second.stats.cyclesToConverge, 1);
  EXPECT_NEAR(second.stats.cycleFmep_Pa.at(0), first.stats.cycleFmep_Pa.back(),
              0.005 * first.stats.cycleFmep_Pa.back());
  // The comparison is with the warm start's last cycle: moved by 1 um (five times the deck's
  // pose tolerance), the first cycle no longer agrees with it.
  io::EngineDeck shifted = io::loadEngineDeck(deck(), o);
  shifted.simulation.warmStart = io::readWarmStart((dir_ / "a").string());
  for (double& x : shifted.simulation.warmStart->lastCycleLateral_m)
    x += 1e-6;
  const io::RunOutcome third = io::runDeck(shifted, (dir_ / "c").string());
  EXPECT_NE(third.stats.cyclesToConverge, 1);
}

// What does not fit is refused before a step is taken, naming the file or what differs.
TEST_F(SkirtScratchDeck, AWarmStartThatDoesNotFitIsRefusedWithItsReason) {
  const auto what = [](const auto& f) -> std::string {
    try {
      f();
    } catch (const std::exception& e) {
      return e.what();
    }
    return "(accepted)";
  };
  EXPECT_NE(what([&] { io::readWarmStart((dir_ / "none").string()); }).find("not a folder"),
            std::string::npos);
  fs::create_directories(dir_ / "empty");
  EXPECT_NE(what([&] { io::readWarmStart((dir_ / "empty").string()); })
                .find("warm_start.json: cannot be read"),
            std::string::npos);
  fs::create_directories(dir_ / "bad");
  std::ofstream(dir_ / "bad" / "warm_start.json") << "{\"crank_angle_deg\": 0}";
  EXPECT_NE(what([&] { io::readWarmStart((dir_ / "bad").string()); })
                .find("warm_start.json: no key output_step_deg"),
            std::string::npos);

  // The end of a run on another film grid, another output step, another start angle.
  const auto o = coarseWith({"simulation.cycles=1", "simulation.until_periodic=false"});
  io::runDeck(io::loadEngineDeck(deck(), o), (dir_ / "a").string());
  const plugin::WarmStart end = io::readWarmStart((dir_ / "a").string());
  io::EngineDeck finer = io::loadEngineDeck(
      deck(), coarseWith({"simulation.cycles=1", "simulation.until_periodic=false",
                          "liner.grid.nodes_axial=10"}));
  finer.simulation.warmStart = end;
  EXPECT_NE(what([&] { io::runDeck(finer, ""); })
                .find("another film grid: 12 x 8 nodes, this one 12 x 10"),
            std::string::npos)
      << what([&] { io::runDeck(finer, ""); });
  io::EngineDeck step = io::loadEngineDeck(
      deck(), coarseWith({"simulation.output_step_deg=1", "simulation.until_periodic=false"}));
  EXPECT_NE(what([&] { plugin::validateWarmStart(end, step.simulation); })
                .find("output step 2 deg is not this run's (1 deg)"),
            std::string::npos);
  io::EngineDeck start = io::loadEngineDeck(
      deck(), coarseWith({"simulation.start_angle_deg=90", "simulation.until_periodic=false"}));
  EXPECT_NE(what([&] { plugin::validateWarmStart(end, start.simulation); })
                .find("not the start angle modulo 720 deg"),
            std::string::npos);
}

}  // namespace
