// Rigid against elastic whole cycles of the passenger-car example (issue 11's study (c) as
// tests): the deck with the test's overrides, on 32 x 24 per side, the film at 1e-11 (the
// coupling's tolerance needs it), both cases on the nodal-mean faces the elastic skirt needs,
// the elastic case with the committed FE skirt compliance and gas field. Shared by the starved
// (slow) and the fully flooded (default run) comparisons.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "SkirtTestDeck.h"
#include "pistondyn/plugin/CycleSimulation.h"

namespace pistondyn::testsupport {

struct CycleOutcome {
  plugin::ResultTable lastCycle;
  plugin::SimulationStats stats;
};

// The deck's parameters on 32 x 24 with `extra` overrides; `elastic` adds the FE skirt.
inline plugin::LubricatedSkirtParameters comparisonParameters(
    bool elastic, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> overrides = {"liner.grid.nodes_circumferential=32",
                                        "liner.grid.nodes_axial=24", "liner.film.tolerance=1e-11",
                                        "liner.parallel_sides=false",
                                        // both cases on the faces the elastic skirt needs
                                        "liner.film.faces=nodal_mean"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  if (elastic) {
    const std::vector<std::string> fe = gasolineElasticSkirtOverrides();
    overrides.insert(overrides.end(), fe.begin(), fe.end());
  }
  return deckSkirtParameters(io::loadEngineDeck(gasolineDeckPath(), overrides));
}

// Two cycles from the deck's start with the deck's stepper; the second cycle's rows.
inline CycleOutcome runTwoCycles(const plugin::LubricatedSkirtParameters& p) {
  SkirtModel m = makeGasolineSkirtModel(32, 24, &p);
  plugin::SimulationSettings s = deckStepperSettings(2);
  s.untilPeriodic = false;
  plugin::CycleSimulation sim(*m.model, s);
  plugin::ResultTableSink table;
  sim.run({&table});
  return {table.releaseTable(), sim.getStats()};
}

inline double minOfColumn(const plugin::ResultTable& t, const std::string& column) {
  const auto v = t.column(column);
  return *std::min_element(v.begin(), v.end());
}

// The crank angle (0 .. 720 deg) at which `column` is largest, and that value.
inline std::pair<double, double> peakOfColumn(const plugin::ResultTable& t,
                                              const std::string& column) {
  const auto angle = t.column("crank_angle_deg");
  const auto v = t.column(column);
  const auto peak = std::max_element(v.begin(), v.end());
  return {std::fmod(angle[std::size_t(peak - v.begin())], 720.0), *peak};
}

}  // namespace pistondyn::testsupport
