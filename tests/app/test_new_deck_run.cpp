// A deck made by `pistondyn new` runs: a short run (preview fidelity on the coarsest grid it
// takes, 16 x 12 nodes per side; two cycles) of the lubricated skirt through the built
// program finishes and writes finite results (~10 s of CPU). Whole cycles: label cycle
// (test_new_program.cpp holds the quick tests of the command).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "NewDeckProgram.h"

namespace {

using namespace pistondyn_test::new_deck;

// Every number under `node` is finite (nulls allowed: cycles_to_converge of a run that did
// not converge); `where` names the first that is not.
void expectFinite(const nlohmann::json& node, const std::string& where) {
  if (node.is_number()) {
    EXPECT_TRUE(std::isfinite(node.get<double>())) << where;
  } else if (node.is_object()) {
    for (auto it = node.begin(); it != node.end(); ++it)
      expectFinite(it.value(), where + "." + it.key());
  } else if (node.is_array()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      expectFinite(node[i], where + "[" + std::to_string(i) + "]");
  }
}

TEST_F(NewDeckProgram, AShortRunOfANewDeckFinishesWithFiniteResults) {
  const fs::path folder = dir_ / "small_gasoline";
  const Invocation made = invoke("new " + folder.string() + " --bore-mm 72 --stroke-mm 78");
  ASSERT_EQ(made.exitCode, 0) << made.err;
  const fs::path out = dir_ / "results";
  const Invocation run = invoke("run " + (folder / "engine.yaml").string() + " --out " +
                                out.string() +
                                " --fidelity preview --set liner.grid.nodes_circumferential=16"
                                " --set liner.grid.nodes_axial=12 --set simulation.cycles=2"
                                " --set simulation.until_periodic=false --quiet --no-plot");
  ASSERT_EQ(run.exitCode, 0) << run.err << run.out;
  const nlohmann::json summary = nlohmann::json::parse(readFile(out / "summary.json"));
  expectFinite(summary, "summary");
  const nlohmann::json& results = summary.at("results");
  EXPECT_EQ(results.at("cycles_run").get<int>(), 2);
  // A fired engine's skirt: friction losses, a film that carries the side force somewhere.
  EXPECT_GT(results.at("fmep_kPa").get<double>(), 0.0);
  EXPECT_GT(results.at("friction_power_mean_W").get<double>(), 0.0);
  EXPECT_NEAR(results.at("imep_kPa").get<double>(), 600.0, 3.0);
  EXPECT_EQ(summary.at("fidelity").get<std::string>(), "preview");
}

}  // namespace

namespace {

// A new deck of every type runs to a periodic state (issue 37: `run` gives a periodic result):
// the rules' running clearance and oil supply, at the deck's preview fidelity (24 x 40 nodes
// per side), at most 6 cycles.
TEST_F(NewDeckProgram, ANewDeckOfEveryTypeBecomesPeriodic) {
  for (const char* engine : {"--type gasoline --bore-mm 80 --stroke-mm 86",
                             "--type small-air-cooled --bore-mm 68 --stroke-mm 54",
                             "--type diesel --bore-mm 81 --stroke-mm 95.5"}) {
    SCOPED_TRACE(engine);
    const fs::path folder = dir_ / "periodic";
    fs::remove_all(folder);
    const Invocation made = invoke("new " + folder.string() + " " + engine);
    ASSERT_EQ(made.exitCode, 0) << made.err;
    const fs::path out = dir_ / "periodic_results";
    const Invocation run = invoke("run " + (folder / "engine.yaml").string() + " --out " +
                                  out.string() +
                                  " --fidelity preview --set simulation.cycles=6"
                                  " --set liner.parallel_sides=false --quiet --no-plot");
    ASSERT_EQ(run.exitCode, 0) << run.err << run.out;
    const nlohmann::json r =
        nlohmann::json::parse(readFile(out / "summary.json")).at("results");
    EXPECT_TRUE(r.at("converged").get<bool>()) << r.dump(1);
    EXPECT_LE(r.at("cycles_to_converge").get<int>(), 6);
    // A film on both sides: the nominal gap stays open (asperities may touch at its rim).
    EXPECT_GT(r.at("min_film_thickness_thrust_um").get<double>(), 0.0);
    EXPECT_GT(r.at("min_film_thickness_antithrust_um").get<double>(), 0.0);
  }
}

}  // namespace
