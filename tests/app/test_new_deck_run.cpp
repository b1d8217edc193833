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
