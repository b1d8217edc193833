// The lubricated skirt element with the elastic skirt (LubricatedSkirtParameters::elasticSkirt,
// skirt::ElasticCoupling) on the passenger-car example engine with its committed FE skirt
// compliance (examples/fe/gasoline_1400_2000rpm), at fixed poses (no cycle):
//   - off by default, and off the deck's elastic keys change nothing;
//   - at the same pose the elastic skirt's converged deformation opens the gap (the sign), the
//     coupling converges and reports its iterations, and the same pose again starts from the
//     last converged deformation (one film evaluation);
//   - with the elastic rate in the squeeze term, a skirt that gives way to an approaching
//     piston carries less and deforms less than one whose film sees the rigid approach;
//   - the deck keys liner.elastic_skirt.* switch it on, and half of them is an error.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "SkirtTestDeck.h"
#include "pistondyn/io/ComplianceInput.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/plugin/LubricatedSkirtElement.h"

namespace {

using namespace pistondyn;
namespace ts = pistondyn::testsupport;

const std::string kFe = std::string(PISTONDYN_SOURCE_DIR) + "/examples/fe/gasoline_1400_2000rpm/";

struct Evaluation {
  plugin::LubricatedSkirtResults::Side thrust;
  bool hasElasticOutput = false;
};

// The thrust side at 20 deg after firing TDC, the piston 38 um towards thrust (2 um rigid gap at
// the barrel's minimum-clearance line), no tilt.
Evaluation evaluate(const ts::SkirtModel& m, int times = 1) {
  m.model->buildSystem();
  const auto& ct = m.model->getCrankTrain();
  Evaluation e;
  for (int i = 0; i < times; ++i) {
    SimTK::State st = m.model->getDefaultState();
    ct.setPose(st, 20.0 * M_PI / 180.0, 38e-6);
    ct.setRates(st, m.engine.drive.speed_radps);
    m.model->getSystem().realize(st, SimTK::Stage::Dynamics);
    e.thrust = m.skirt().getResults(st).sides[0];
  }
  for (const auto& o : m.skirt().getOutputs())
    e.hasElasticOutput = e.hasElasticOutput || o.name == "elastic_iterations_thrust";
  return e;
}

TEST(ElasticSkirtElement, OpensTheGapAtAFixedPoseAndWarmStarts) {
  plugin::LubricatedSkirtParameters rigid = ts::exampleSkirtParameters(32, 24);
  EXPECT_FALSE(rigid.elasticSkirt.enabled);  // off by default
  plugin::LubricatedSkirtParameters elastic = rigid;
  elastic.elasticSkirt.enabled = true;
  elastic.elasticSkirt.compliance =
      io::readStructuralCompliance(kFe + "skirt_compliance.mtx", kFe + "skirt_nodes.csv");

  const Evaluation r = evaluate(ts::makeGasolineSkirtModel(32, 24, &rigid));
  const ts::SkirtModel em = ts::makeGasolineSkirtModel(32, 24, &elastic);
  const Evaluation e = evaluate(em);
  std::printf(
      "[ElasticSkirtElement] thrust side, 20 deg, e = 38 um: min film %.3f um rigid, "
      "%.3f um elastic (peak deformation %.3f um, %d film evaluations); normal force "
      "%.1f N rigid, %.1f N elastic\n",
      r.thrust.minFilmThickness_m * 1e6, e.thrust.minFilmThickness_m * 1e6,
      e.thrust.maxElasticDeformation_m * 1e6, e.thrust.elasticIterations,
      r.thrust.hydrodynamicNormalForce_N + r.thrust.asperityNormalForce_N,
      e.thrust.hydrodynamicNormalForce_N + e.thrust.asperityNormalForce_N);
  EXPECT_FALSE(r.hasElasticOutput);
  EXPECT_TRUE(e.hasElasticOutput);
  EXPECT_EQ(r.thrust.elasticIterations, 0);
  EXPECT_GT(e.thrust.elasticIterations, 1);
  EXPECT_GT(e.thrust.maxElasticDeformation_m, 1e-6);
  // The film pushes the skirt in: a thicker film and a smaller load at the same pose.
  EXPECT_GT(e.thrust.minFilmThickness_m, r.thrust.minFilmThickness_m + 1e-6);
  EXPECT_LT(e.thrust.hydrodynamicNormalForce_N + e.thrust.asperityNormalForce_N,
            r.thrust.hydrodynamicNormalForce_N + r.thrust.asperityNormalForce_N);
  // A new state at the same pose: the coupling starts from its last converged deformation.
  const Evaluation again = evaluate(em);
  EXPECT_EQ(again.thrust.elasticIterations, 1);
  EXPECT_NEAR(again.thrust.minFilmThickness_m, e.thrust.minFilmThickness_m, 2e-9);
}

// The elastic rate in the squeeze term (ElasticSkirtParameters::squeezeRate): the piston
// approaches the thrust side at 0.1 m/s over one accepted step of 20 us (from 36 to 38 um). A
// skirt that gives way lowers the squeeze rate the film sees, so with the rate the film
// carries less and the skirt deforms less than when the film sees the rigid approach in full
// (the physics the option adds; its size is not compared with anything).
TEST(ElasticSkirtElement, SqueezeRateLetsTheSkirtGiveWayToAnApproachingPiston) {
  plugin::LubricatedSkirtParameters base = ts::exampleSkirtParameters(32, 24);
  base.elasticSkirt.enabled = true;
  base.elasticSkirt.compliance =
      io::readStructuralCompliance(kFe + "skirt_compliance.mtx", kFe + "skirt_nodes.csv");
  base.elasticSkirt.coupling.scheme = skirt::ElasticCouplingScheme::Newton;
  ASSERT_EQ(base.lubrication.cavitation, lubrication::CavitationModel::MassConserving);
  const auto stepped = [&](bool rate) {
    plugin::LubricatedSkirtParameters p = base;
    p.elasticSkirt.squeezeRate = rate;
    const ts::SkirtModel m = ts::makeGasolineSkirtModel(32, 24, &p);
    m.model->buildSystem();
    const auto& ct = m.model->getCrankTrain();
    const double omega = m.engine.drive.speed_radps, v = 0.1, dt = 20e-6;
    SimTK::State st = m.model->getDefaultState();
    st.setTime(0.0);
    ct.setPose(st, 20.0 * M_PI / 180.0, 36e-6);
    ct.setRates(st, omega, v);
    m.model->getSystem().realize(st, SimTK::Stage::Dynamics);
    (void)m.skirt().getResults(st);
    st.autoUpdateDiscreteVariables();  // the step to t = 0 is accepted
    st.setTime(dt);
    ct.setPose(st, 20.0 * M_PI / 180.0 + omega * dt, 36e-6 + v * dt);
    ct.setRates(st, omega, v);
    m.model->getSystem().realize(st, SimTK::Stage::Dynamics);
    return m.skirt().getResults(st).sides[0];
  };
  const auto off = stepped(false), on = stepped(true);
  std::printf(
      "[ElasticSkirtElement] approach 0.1 m/s, 20 us step: normal force %.1f N without the "
      "elastic rate, %.1f N with it; peak deformation %.3f / %.3f um; min film %.3f / %.3f "
      "um; film evaluations %d / %d\n",
      off.hydrodynamicNormalForce_N + off.asperityNormalForce_N,
      on.hydrodynamicNormalForce_N + on.asperityNormalForce_N, off.maxElasticDeformation_m * 1e6,
      on.maxElasticDeformation_m * 1e6, off.minFilmThickness_m * 1e6,
      on.minFilmThickness_m * 1e6, off.elasticIterations, on.elasticIterations);
  EXPECT_LT(on.hydrodynamicNormalForce_N + on.asperityNormalForce_N,
            off.hydrodynamicNormalForce_N + off.asperityNormalForce_N);
  EXPECT_LT(on.maxElasticDeformation_m, off.maxElasticDeformation_m);
}

TEST(ElasticSkirtElement, DeckKeysSwitchItOn) {
  const std::string deck = ts::gasolineDeckPath();
  // The committed FE skirt, paths relative to the deck's folder.
  const std::string mtx = ts::gasolineElasticSkirtOverrides()[0];
  const std::string nodes = ts::gasolineElasticSkirtOverrides()[1];
  {
    const io::EngineDeck d =
        io::loadEngineDeck(deck, {mtx, nodes, "liner.elastic_skirt.max_iterations=25"});
    const auto liner = d.makeLinerElement();
    const auto& p = dynamic_cast<const plugin::LubricatedSkirtElement&>(*liner).getParameters();
    EXPECT_TRUE(p.elasticSkirt.enabled);
    EXPECT_EQ(p.elasticSkirt.compliance.nodeCount(), 264);
    EXPECT_EQ(p.elasticSkirt.coupling.maxIterations, 25);
    EXPECT_DOUBLE_EQ(p.elasticSkirt.coupling.absoluteTolerance_m, 1e-9);
    // The deck's defaults are the ones that carry whole cycles (plugin/README.md).
    EXPECT_EQ(p.elasticSkirt.coupling.scheme, skirt::ElasticCouplingScheme::Modal);
    EXPECT_EQ(p.elasticSkirt.coupling.modes, 20);
    EXPECT_DOUBLE_EQ(p.elasticSkirt.coupling.deformationRelativeTolerance, 1e-3);
    EXPECT_TRUE(p.elasticSkirt.squeezeRate);
    // ... and a C++ user who sets only the compliance gets the same coupling (two sources of
    // defaults, the deck's key table and the struct, kept equal).
    const plugin::ElasticSkirtParameters byStruct;
    EXPECT_EQ(byStruct.coupling.scheme, p.elasticSkirt.coupling.scheme);
    EXPECT_EQ(byStruct.squeezeRate, p.elasticSkirt.squeezeRate);
    EXPECT_EQ(byStruct.coupling.modes, p.elasticSkirt.coupling.modes);
    EXPECT_EQ(byStruct.coupling.maxIterations, 60);
    EXPECT_DOUBLE_EQ(byStruct.coupling.absoluteTolerance_m,
                     p.elasticSkirt.coupling.absoluteTolerance_m);
    EXPECT_DOUBLE_EQ(byStruct.coupling.relativeTolerance, p.elasticSkirt.coupling.relativeTolerance);
    EXPECT_DOUBLE_EQ(byStruct.coupling.deformationRelativeTolerance,
                     p.elasticSkirt.coupling.deformationRelativeTolerance);
    // The committed node table has the gas column: the deck's pressure table scales it.
    ASSERT_TRUE(p.elasticSkirt.compliance.hasGasDisplacement());
    ASSERT_NE(p.elasticSkirt.cylinderPressure, nullptr);
    EXPECT_DOUBLE_EQ(p.elasticSkirt.cylinderPressure->getPeakPressure_Pa(),
                     d.cylinderPressure->getPeakPressure_Pa());
    EXPECT_DOUBLE_EQ(p.elasticSkirt.crankcasePressure_Pa, d.crankcasePressure_Pa);
  }
  {
    const io::EngineDeck d =
        io::loadEngineDeck(deck, {mtx, nodes, "liner.elastic_skirt.gas_deformation=false"});
    const auto liner = d.makeLinerElement();
    const auto& p = dynamic_cast<const plugin::LubricatedSkirtElement&>(*liner).getParameters();
    EXPECT_EQ(p.elasticSkirt.cylinderPressure, nullptr);
  }
  {
    const io::EngineDeck d = io::loadEngineDeck(
        deck, {mtx, nodes, "liner.elastic_skirt.scheme=newton",
               "liner.elastic_skirt.squeeze_rate=false", "liner.elastic_skirt.modes=12",
               "liner.elastic_skirt.deformation_relative_tolerance=1e-4"});
    const auto liner = d.makeLinerElement();
    const auto& p = dynamic_cast<const plugin::LubricatedSkirtElement&>(*liner).getParameters();
    EXPECT_EQ(p.elasticSkirt.coupling.scheme, skirt::ElasticCouplingScheme::Newton);
    EXPECT_FALSE(p.elasticSkirt.squeezeRate);
    EXPECT_EQ(p.elasticSkirt.coupling.modes, 12);
    EXPECT_DOUBLE_EQ(p.elasticSkirt.coupling.deformationRelativeTolerance, 1e-4);
  }
  {
    const io::EngineDeck d = io::loadEngineDeck(deck, {});
    const auto liner = d.makeLinerElement();
    EXPECT_FALSE(dynamic_cast<const plugin::LubricatedSkirtElement&>(*liner)
                     .getParameters()
                     .elasticSkirt.enabled);
  }
  // A skirt reaching 2 mm above the structural grid's top row (12 mm above the pin).
  try {
    (void)io::loadEngineDeck(deck, {mtx, nodes, "piston.skirt_top_above_pin_mm=14"});
    ADD_FAILURE() << "a compliance that does not cover the skirt was accepted";
  } catch (const io::DeckError& ex) {
    EXPECT_NE(std::string(ex.what()).find("the compliance does not fit this skirt"),
              std::string::npos)
        << ex.what();
  }
  try {
    (void)io::loadEngineDeck(deck, {mtx});
    ADD_FAILURE() << "a compliance without its node table was accepted";
  } catch (const io::DeckError& ex) {
    EXPECT_NE(std::string(ex.what()).find("nodes_file"), std::string::npos) << ex.what();
  }
}

// The elastic liner's keys: the committed FE liner in series with the skirt; the liner without
// the skirt, half a pair, and a liner that does not cover this engine's stroke are refused,
// naming the key.
TEST(ElasticSkirtElement, LinerKeysAddTheLinerOrSayWhyNot) {
  const std::string deck = ts::gasolineDeckPath();
  const std::string mtx = ts::gasolineElasticSkirtOverrides()[0];
  const std::string nodes = ts::gasolineElasticSkirtOverrides()[1];
  const std::string linerMtx =
      "liner.elastic_skirt.liner_compliance_file=../../fe/gasoline_1400_2000rpm/"
      "liner_compliance.mtx";
  const std::string linerNodes =
      "liner.elastic_skirt.liner_nodes_file=../../fe/gasoline_1400_2000rpm/liner_nodes.csv";
  {
    const io::EngineDeck d = io::loadEngineDeck(deck, {mtx, nodes, linerMtx, linerNodes});
    const auto liner = d.makeLinerElement();
    const auto& p = dynamic_cast<const plugin::LubricatedSkirtElement&>(*liner).getParameters();
    ASSERT_TRUE(p.elasticSkirt.liner.has_value());
    EXPECT_EQ(p.elasticSkirt.liner->nodeCount(), 552);  // 24 x 23 (examples/fe/README.md)
    EXPECT_TRUE(p.elasticSkirt.liner->fullCircle);
  }
  const auto refused = [&](const std::vector<std::string>& sets, const std::string& text) {
    try {
      (void)io::loadEngineDeck(deck, sets);
      ADD_FAILURE() << "accepted; expected an error with: " << text;
    } catch (const io::DeckError& ex) {
      EXPECT_NE(std::string(ex.what()).find(text), std::string::npos) << ex.what();
    }
  };
  refused({linerMtx, linerNodes}, "give the skirt's compliance_file and nodes_file too");
  refused({mtx, nodes, linerMtx}, "liner_nodes_file");
  // The Briggs & Stratton liner (rows 5 mm apart over its own, shorter stroke) under the
  // gasoline skirt: off the liner at one end of the stroke.
  refused({mtx, nodes,
           "liner.elastic_skirt.liner_compliance_file=../../fe/briggs_stratton_500/"
           "liner_compliance.mtx",
           "liner.elastic_skirt.liner_nodes_file=../../fe/briggs_stratton_500/liner_nodes.csv"},
          "the liner compliance does not fit this engine");
}

}  // namespace
