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

// The deck's parameters on 32 x 24 with `extra` overrides; `elastic` adds the FE skirt,
// `elasticLiner` (with elastic) the FE liner in series with it. The cold shapes, as in the
// thesis' rigid/elastic study (the deck's expansion coefficients 0: SkirtTestDeck.h), and the
// deck's supply unless `extra` sets another.
inline plugin::LubricatedSkirtParameters comparisonParameters(
    bool elastic, const std::vector<std::string>& extra = {}, bool elasticLiner = false) {
  std::vector<std::string> overrides = {"liner.grid.nodes_circumferential=32",
                                        "liner.grid.nodes_axial=24", "liner.film.tolerance=1e-11",
                                        "liner.parallel_sides=false",
                                        "liner.thermal.piston_expansion_per_K=0",
                                        "liner.thermal.liner_expansion_per_K=0",
                                        // both cases on the faces the elastic skirt needs
                                        "liner.film.faces=nodal_mean"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  if (elastic) {
    const std::vector<std::string> fe = gasolineElasticSkirtOverrides();
    overrides.insert(overrides.end(), fe.begin(), fe.end());
  }
  if (elasticLiner) {
    overrides.push_back(
        "liner.elastic_skirt.liner_compliance_file=../../fe/gasoline_1400_2000rpm/"
        "liner_compliance.mtx");
    overrides.push_back(
        "liner.elastic_skirt.liner_nodes_file=../../fe/gasoline_1400_2000rpm/liner_nodes.csv");
  }
  return deckSkirtParameters(io::loadEngineDeck(gasolineDeckPath(), overrides));
}

// The rows of the table's last 720 deg (its first row is the one 720 deg before its last): a
// run that is not stopped at a periodic state keeps the rows of every cycle.
inline plugin::ResultTable lastCycleOf(plugin::ResultTable t) {
  const std::size_t a = t.columnIndex("crank_angle_deg");
  const double start_deg = t.rows.back()[a] - 720.0;
  const auto first = std::find_if(t.rows.begin(), t.rows.end(), [&](const auto& row) {
    return row[a] >= start_deg - 1e-9;
  });
  t.rows.erase(t.rows.begin(), first);
  return t;
}

// Two cycles from the deck's start with BDF2 at 0.25 deg (the elastic study's stepper); the
// second cycle's rows.
inline CycleOutcome runTwoCycles(const plugin::LubricatedSkirtParameters& p) {
  SkirtModel m = makeGasolineSkirtModel(32, 24, &p);
  plugin::SimulationSettings s = bdf2StepperSettings(2);
  s.untilPeriodic = false;
  plugin::CycleSimulation sim(*m.model, s);
  plugin::ResultTableSink table;
  sim.run({&table});
  return {lastCycleOf(table.releaseTable()), sim.getStats()};
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

// Friction work [J] between crank angles from_deg and to_deg (0 .. 720) of the table's last
// 720 deg (the cumulative friction_work_J column at the rows nearest to those angles).
inline double frictionWorkBetween_J(const plugin::ResultTable& t, double from_deg,
                                    double to_deg) {
  const auto angle = t.column("crank_angle_deg");
  const auto work = t.column("friction_work_J");
  const double cycleStart_deg = angle.back() - 720.0;
  auto at = [&](double a_deg) {
    const double target = cycleStart_deg + a_deg;
    const auto it = std::min_element(angle.begin(), angle.end(), [&](double x, double y) {
      return std::abs(x - target) < std::abs(y - target);
    });
    return work[std::size_t(it - angle.begin())];
  };
  return at(to_deg) - at(from_deg);
}

}  // namespace pistondyn::testsupport
