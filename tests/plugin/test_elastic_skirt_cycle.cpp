// Whole engine cycles with the elastic skirt (issue 11): the passenger-car example at its
// operating point, partially flooded (the deck's 0.5 um supply), with its committed FE skirt
// compliance and gas field (examples/fe/gasoline_1400_2000rpm), the deck's coupling defaults
// (modal Newton, 20 modes per side, the elastic rate in the squeeze term) and the film solved
// to 1e-11 (the coupling's tolerance needs it, plugin/README.md). On 32 x 24 per side, two
// cycles each, rigid and elastic with the same numerics. Checked against the thesis (§4.3):
//   - the elastic skirt raises the thrust side's minimum h/sigma over the cycle (thesis:
//     3.15 -> 4.76);
//   - the thrust side's deformation peaks in the expansion stroke.
// Also: the elastic cycle runs to its end (a coupling that does not converge throws, and the
// stepper gives up after its retries). Its fmep against the rigid one (thesis: -0.8 %) is
// printed, not checked: plugin/README.md reports it.
// Label `slow` (about 10 min): outside the default test run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "SkirtTestDeck.h"
#include "pistondyn/plugin/CycleSimulation.h"

namespace {

using namespace pistondyn;
namespace ts = pistondyn::testsupport;

struct Outcome {
  plugin::ResultTable lastCycle;
  plugin::SimulationStats stats;
};

plugin::LubricatedSkirtParameters deckParameters(bool elastic) {
  std::vector<std::string> overrides = {"liner.grid.nodes_circumferential=32",
                                        "liner.grid.nodes_axial=24", "liner.film.tolerance=1e-11",
                                        "liner.parallel_sides=false",
                                        // both cases on the faces the elastic skirt needs
                                        "liner.film.faces=nodal_mean"};
  if (elastic) {
    const std::vector<std::string> fe = ts::gasolineElasticSkirtOverrides();
    overrides.insert(overrides.end(), fe.begin(), fe.end());
  }
  return ts::deckSkirtParameters(io::loadEngineDeck(ts::gasolineDeckPath(), overrides));
}

Outcome run(const plugin::LubricatedSkirtParameters& p) {
  ts::SkirtModel m = ts::makeGasolineSkirtModel(32, 24, &p);
  plugin::SimulationSettings s = ts::deckStepperSettings(2);
  s.untilPeriodic = false;
  plugin::CycleSimulation sim(*m.model, s);
  plugin::ResultTableSink table;
  sim.run({&table});
  return {table.releaseTable(), sim.getStats()};
}

double minOf(const plugin::ResultTable& t, const std::string& column) {
  const auto v = t.column(column);
  return *std::min_element(v.begin(), v.end());
}

TEST(ElasticSkirtCycle, WholeCycleRunsAndFollowsTheThesisTrends) {
  const plugin::LubricatedSkirtParameters rigidParameters = deckParameters(false);
  const plugin::LubricatedSkirtParameters elasticParameters = deckParameters(true);
  ASSERT_FALSE(rigidParameters.elasticSkirt.enabled);
  ASSERT_TRUE(elasticParameters.elasticSkirt.enabled);
  ASSERT_EQ(elasticParameters.elasticSkirt.coupling.scheme, skirt::ElasticCouplingScheme::Modal);

  const Outcome rigid = run(rigidParameters);
  Outcome elastic;
  ASSERT_NO_THROW(elastic = run(elasticParameters));

  const double hRigid = minOf(rigid.lastCycle, "min_h_over_sigma_thrust");
  const double hElastic = minOf(elastic.lastCycle, "min_h_over_sigma_thrust");
  const double fmepRigid = rigid.stats.cycleFmep_Pa.back() / 1e3;
  const double fmepElastic = elastic.stats.cycleFmep_Pa.back() / 1e3;
  std::printf(
      "[ElasticSkirtCycle] 32 x 24, second cycle: min h/sigma thrust %.3f rigid, %.3f elastic; "
      "fmep %.3f rigid, %.3f elastic kPa (%+.1f %%); wall %.1f s rigid, %.1f s elastic\n",
      hRigid, hElastic, fmepRigid, fmepElastic, 100.0 * (fmepElastic / fmepRigid - 1.0),
      rigid.stats.wallTime_s, elastic.stats.wallTime_s);
  EXPECT_GT(hElastic, hRigid);

  // The thrust side's deformation peaks in the expansion stroke (0 .. 180 deg after firing
  // TDC).
  const auto angle = elastic.lastCycle.column("crank_angle_deg");
  const auto deformation = elastic.lastCycle.column("max_elastic_deformation_thrust_um");
  const auto peak = std::max_element(deformation.begin(), deformation.end());
  const double peakAngle_deg = std::fmod(angle[std::size_t(peak - deformation.begin())], 720.0);
  std::printf("[ElasticSkirtCycle] thrust deformation peak %.2f um at %.0f deg\n", *peak,
              peakAngle_deg);
  EXPECT_GE(peakAngle_deg, 0.0);
  EXPECT_LE(peakAngle_deg, 180.0);
}

}  // namespace
