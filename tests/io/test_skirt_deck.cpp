// The liner model lubricated_skirt read from a deck (io/LubricatedSkirtDeck.h): the
// factory turns every key into the element's SI parameters (checked here against hand
// conversions of the deck's values), the switches that reach beyond the liner section
// (tertiary motion into the crank train, the integrator the stiff film needs), and the
// ideal guide selectable from the same deck.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "FullSkirtDeck.h"
#include "NumericCsv.h"
#include "ScratchDeck.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/RunDeck.h"
#include "pistondyn/mbd_models/SliderCrank.h"
#include "pistondyn/lubrication/OilGrades.h"
#include "pistondyn/plugin/LubricatedSkirtElement.h"

using namespace pistondyn_test;
namespace io = pistondyn::io;
namespace plugin = pistondyn::plugin;

namespace {

// The element the deck's model builds, and its parameters.
struct Built {
  io::EngineDeck deck;
  std::unique_ptr<plugin::PistonAssemblyModel> model;
  const plugin::LubricatedSkirtElement& skirt() const {
    return model->getElementAs<plugin::LubricatedSkirtElement>("lubricated_skirt");
  }
};

Built build(const std::string& deckPath, const std::vector<std::string>& overrides = {}) {
  Built b{io::loadEngineDeck(deckPath, overrides), nullptr};
  b.model = io::buildModel(b.deck);
  b.model->buildSystem();  // the element joins the engine (addToModel)
  return b;
}

constexpr double kDeg = M_PI / 180.0;

// The example deck's section as the element's parameters, by hand: um -> 1e-6 m, deg ->
// pi/180 rad, GPa -> 1e9 Pa, mm/s -> 1e-3 m/s (each a single product, compared exactly).
TEST(SkirtDeck, TheGasolineExampleSectionBecomesTheElementsParametersInSI) {
  const Built b = build(kEngineDir + "/engine.yaml");
  EXPECT_EQ(b.deck.linerModel, "lubricated_skirt");
  const plugin::LubricatedSkirtParameters& p = b.skirt().getParameters();
  EXPECT_EQ(p.gap.coldRadialClearance_m, 40.0 * 1e-6);
  EXPECT_EQ(p.gap.referenceTemperature_degC, 20.0);
  EXPECT_EQ(p.grid.arcWidth_rad, 80.0 * kDeg);
  EXPECT_EQ(p.grid.nPhi, 64);
  EXPECT_EQ(p.grid.nY, 48);
  EXPECT_EQ(p.grid.axialClustering, 0.0);
  // The profile table: 101 rows, -25 .. +25 mm, 0.12 um/mm^2 (y + 6 mm)^2.
  const auto& axial = p.gap.skirtProfile.axial;
  ASSERT_EQ(axial.height_m.size(), 101);
  EXPECT_EQ(axial.height_m[0], -25.0 * 1e-3);
  EXPECT_EQ(axial.height_m[100], 25.0 * 1e-3);
  for (Eigen::Index i = 0; i < axial.height_m.size(); ++i) {
    const double d_mm = axial.height_m[i] * 1e3 + 6.0;
    // The table's decimal text against the closed form: a few ulps of 40 um.
    EXPECT_NEAR(axial.radialDrop_m[i], 0.12 * d_mm * d_mm * 1e-6, 1e-18) << i;
  }
  EXPECT_FALSE(axial.mirrored);
  EXPECT_EQ(p.gap.skirtProfile.ovality.model, pistondyn::skirt::OvalityModel::Law);
  EXPECT_EQ(p.gap.skirtProfile.ovality.diametralOvality_m, 300.0 * 1e-6);
  EXPECT_EQ(p.gap.skirtProfile.ovality.cos4Coefficient, 0.0);
  EXPECT_TRUE(p.gap.linerShape.orders.empty());  // ideal cylinder
  // The hot shapes: the tables beside the deck (their rows as written) and the coefficients.
  EXPECT_EQ(p.gap.pistonThermal.expansionCoefficient_perK, 20.5e-6);
  ASSERT_EQ(p.gap.pistonThermal.height_m.size(), 5);
  EXPECT_EQ(p.gap.pistonThermal.height_m[0], -18.0 * 1e-3);
  EXPECT_EQ(p.gap.pistonThermal.temperature_degC[0], 120.0);
  EXPECT_EQ(p.gap.pistonThermal.height_m[4], 28.0 * 1e-3);
  EXPECT_EQ(p.gap.pistonThermal.temperature_degC[4], 220.0);
  EXPECT_EQ(p.gap.linerThermal.expansionCoefficient_perK, 17.0e-6);
  ASSERT_EQ(p.gap.linerThermal.depth_m.size(), 3);
  EXPECT_EQ(p.gap.linerThermal.depth_m[1], 40.0 * 1e-3);
  EXPECT_EQ(p.gap.linerThermal.temperature_degC[1], 110.0);
  // Oil: the grade's data sheet, at 105 degC.
  const auto grade =
      pistondyn::lubrication::makeSaeGradeOilSpec(pistondyn::lubrication::SaeGrade::k0W30);
  EXPECT_EQ(p.oil.name, grade.name);
  EXPECT_EQ(p.oil.kinematicViscosity1_m2ps, grade.kinematicViscosity1_m2ps);
  EXPECT_EQ(p.oil.kinematicViscosity2_m2ps, grade.kinematicViscosity2_m2ps);
  EXPECT_EQ(p.oilTemperature_degC, 105.0);
  // Partially flooded: a constant 1 um supply film.
  EXPECT_EQ(p.supplyFilm.constant_m, 1.0 * 1e-6);
  EXPECT_TRUE(p.supplyFilm.crankAngle_deg.empty());
  // One roughness pair for both the flow factors and the contact.
  EXPECT_EQ(p.roughness.rq1_m, 0.4 * 1e-6);
  EXPECT_EQ(p.roughness.rq2_m, 0.6 * 1e-6);
  EXPECT_EQ(p.roughness.peklenik1, 1.0);
  EXPECT_EQ(p.roughness.peklenik2, 1.0);
  EXPECT_EQ(p.asperity.roughnessParameter, 0.04);
  EXPECT_EQ(p.asperity.sigmaOverBeta, 0.001);
  EXPECT_EQ(p.asperity.surface1.youngsModulus_Pa, 115.0 * 1e9);
  EXPECT_EQ(p.asperity.surface1.poissonRatio, 0.26);
  EXPECT_EQ(p.asperity.surface2.youngsModulus_Pa, 75.0 * 1e9);
  EXPECT_EQ(p.asperity.surface2.poissonRatio, 0.33);
  EXPECT_EQ(p.asperity.roughnessSurface1_m, 0.4 * 1e-6);  // set from roughness at addToModel
  EXPECT_EQ(p.boundaryFriction.frictionCoefficient, 0.1);
  EXPECT_EQ(p.boundaryFriction.regularisationSpeed_mps, 1.0 * 1e-3);
  EXPECT_EQ(p.lubrication.wearCoefficient_m2pN, 0.0);
  EXPECT_EQ(p.lubrication.cavitation, pistondyn::lubrication::CavitationModel::MassConserving);
  // Second order along the sliding direction (the deck's choice, not the keys' defaults).
  EXPECT_EQ(p.lubrication.faceValues, pistondyn::lubrication::FaceValues::LinearGap);
  EXPECT_EQ(p.lubrication.fillFractionFlux,
            pistondyn::lubrication::FillFractionFlux::LimitedSecondOrder);
  EXPECT_EQ(p.lubrication.solver.solver, pistondyn::lubrication::FilmSolverType::FastActiveSet);
  EXPECT_EQ(p.lubrication.solver.tolerance, 1e-8);
  EXPECT_TRUE(p.lubrication.solver.fallbackToReference);  // the key's default
  // The one tertiary switch reaches the element and the crank train.
  EXPECT_FALSE(p.tertiaryMotion);
  EXPECT_FALSE(b.deck.engine.tertiaryMotion);
  EXPECT_EQ(b.deck.engine.piston.skirtTopAbovePin_m, 12.0 * 1e-3);
  // Simulation settings.
  const plugin::SimulationSettings& s = b.deck.simulation;
  EXPECT_EQ(s.integrator, plugin::SimulationSettings::Integrator::LinearlyImplicitBDF);
  EXPECT_TRUE(s.untilPeriodic);
  EXPECT_EQ(s.cycles, 8);
  EXPECT_EQ(s.poseTolerance_m, 1.0 * 1e-9);
  EXPECT_EQ(s.maxStep_deg, 1.0);
  EXPECT_EQ(s.stepperOrder, 3);
  EXPECT_EQ(s.periodicFmepTolerance, 0.005);
  EXPECT_EQ(s.periodicPoseTolerance_m, 0.2 * 1e-6);
  // The hot running clearance: below the cold one (the skirt grows more than the bore); without
  // thermal growth it is the cold one at the profile's zero-drop line (inside the skirt: -6 mm).
  EXPECT_LT(*b.skirt().getHotRunningClearance_m(), 40e-6);
  const Built cold = build(kEngineDir + "/engine.yaml", {"liner.thermal.piston_expansion_per_K=0",
                                    "liner.thermal.liner_expansion_per_K=0"});
  EXPECT_NEAR(*cold.skirt().getHotRunningClearance_m(), 40e-6, 1e-15);
}

TEST(SkirtDeck, TheBriggsAndStrattonExampleHasTheThesisClearance) {
  const Built b = build(std::string(PISTONDYN_SOURCE_DIR) +
                        "/examples/engines/briggs_stratton_500/engine.yaml");
  const plugin::LubricatedSkirtParameters& p = b.skirt().getParameters();
  EXPECT_EQ(p.gap.coldRadialClearance_m, 53.0 * 1e-6);
  EXPECT_EQ(p.gap.skirtProfile.ovality.diametralOvality_m, 260.0 * 1e-6);
  EXPECT_EQ(p.oilTemperature_degC, 40.0);
  EXPECT_FALSE(b.deck.engine.tertiaryMotion);
}

TEST_F(FullSkirtDeck, EveryKeyReachesTheElementInSI) {
  const Built b = build(deck());
  const plugin::LubricatedSkirtParameters& p = b.skirt().getParameters();
  EXPECT_EQ(p.gap.coldRadialClearance_m, 60.0 * 1e-6);
  EXPECT_EQ(p.gap.referenceTemperature_degC, 25.0);
  EXPECT_EQ(p.grid.arcWidth_rad, 90.0 * kDeg);
  EXPECT_EQ(p.grid.nPhi, 20);
  EXPECT_EQ(p.grid.nY, 14);
  EXPECT_EQ(p.grid.axialClustering, 1.0);
  EXPECT_EQ(p.grid.circumferentialClustering, 1.5);
  EXPECT_TRUE(p.gap.skirtProfile.axial.mirrored);
  const auto& ov = p.gap.skirtProfile.ovality;
  ASSERT_EQ(ov.model, pistondyn::skirt::OvalityModel::Table);
  ASSERT_EQ(ov.tableAngle_rad.size(), 3);
  EXPECT_EQ(ov.tableAngle_rad[1], 45.0 * kDeg);
  EXPECT_EQ(ov.tableRadialDrop_m[2], 150.0 * 1e-6);
  // Bore distortion: orders 0 and 2, rows grouped by order in file order.
  const auto& orders = p.gap.linerShape.orders;
  ASSERT_EQ(orders.size(), 2u);
  EXPECT_EQ(orders[0].order, 0);
  EXPECT_EQ(orders[1].order, 2);
  ASSERT_EQ(orders[1].depth_m.size(), 3);
  EXPECT_EQ(orders[1].depth_m[1], 60.0 * 1e-3);
  EXPECT_EQ(orders[1].amplitude_m[0], 5.0 * 1e-6);
  EXPECT_EQ(orders[1].phase_rad[1], 45.0 * kDeg);
  EXPECT_EQ(orders[0].amplitude_m[1], 4.0 * 1e-6);
  EXPECT_EQ(p.gap.linerTopHeight_m, 250.0 * 1e-3);
  EXPECT_EQ(p.gap.pistonThermal.expansionCoefficient_perK, 2.1e-5);
  EXPECT_EQ(p.gap.pistonThermal.height_m[0], -18.0 * 1e-3);
  EXPECT_EQ(p.gap.pistonThermal.temperature_degC[1], 70.0);
  EXPECT_EQ(p.gap.linerThermal.expansionCoefficient_perK, 1.1e-5);
  EXPECT_EQ(p.gap.linerThermal.depth_m[1], 140.0 * 1e-3);
  EXPECT_EQ(p.gap.linerThermal.temperature_degC[0], 130.0);
  // A user oil from two viscosities.
  EXPECT_EQ(p.oil.kinematicViscosity1_m2ps, 60.0 * 1e-6);
  EXPECT_EQ(p.oil.kinematicViscosity2_m2ps, 10.0 * 1e-6);
  EXPECT_EQ(p.oil.temperature1_degC, 40.0);
  EXPECT_EQ(p.oil.temperature2_degC, 100.0);
  EXPECT_EQ(p.oil.density_kgpm3, 850.0);
  EXPECT_EQ(p.oilTemperature_degC, 90.0);
  // The supply film over the cycle.
  ASSERT_EQ(p.supplyFilm.crankAngle_deg.size(), 3u);
  EXPECT_EQ(p.supplyFilm.crankAngle_deg[1], 360.0);
  EXPECT_EQ(p.supplyFilm.thickness_m[1], 2.0 * 1e-6);
  EXPECT_EQ(p.roughness.rq1_m, 0.3 * 1e-6);
  EXPECT_EQ(p.roughness.rq2_m, 0.5 * 1e-6);
  EXPECT_EQ(p.roughness.peklenik1, 2.0);
  EXPECT_EQ(p.roughness.peklenik2, 2.0);
  EXPECT_EQ(p.asperity.roughnessParameter, 0.05);
  EXPECT_EQ(p.asperity.sigmaOverBeta, 0.002);
  EXPECT_EQ(p.asperity.surface1.youngsModulus_Pa, 110.0 * 1e9);
  EXPECT_EQ(p.asperity.surface1.poissonRatio, 0.27);
  EXPECT_EQ(p.asperity.surface2.youngsModulus_Pa, 70.0 * 1e9);
  EXPECT_EQ(p.asperity.surface2.poissonRatio, 0.32);
  EXPECT_EQ(p.boundaryFriction.frictionCoefficient, 0.12);
  EXPECT_EQ(p.boundaryFriction.regularisationSpeed_mps, 2.0 * 1e-3);
  EXPECT_EQ(p.lubrication.wearCoefficient_m2pN, 1e-6 * 1e-9);  // mm^3/(N m) -> m^3/(N m)
  EXPECT_EQ(p.lubrication.cavitation, pistondyn::lubrication::CavitationModel::Reynolds);
  EXPECT_EQ(p.lubrication.faceValues, pistondyn::lubrication::FaceValues::LinearGap);
  EXPECT_EQ(p.lubrication.fillFractionFlux,
            pistondyn::lubrication::FillFractionFlux::LimitedSecondOrder);
  EXPECT_EQ(p.lubrication.solver.solver,
            pistondyn::lubrication::FilmSolverType::ReferenceGaussSeidel);
  EXPECT_EQ(p.lubrication.solver.tolerance, 1e-7);
  EXPECT_FALSE(p.lubrication.solver.fallbackToReference);
  EXPECT_TRUE(p.tertiaryMotion);
  EXPECT_TRUE(b.deck.engine.tertiaryMotion);  // the crank train gets the pin-axis mobility
  EXPECT_EQ(p.pinRetainerPlay_m, 0.3 * 1e-3);
  EXPECT_EQ(p.pinRetainerStiffness_Npm, 1e4 * 1e3);
  EXPECT_EQ(b.deck.fieldDumpAngles_deg, (std::vector<double>{0.0, 370.0}));
  EXPECT_TRUE(p.elasticSkirt.enabled);
  EXPECT_EQ(p.elasticSkirt.compliance.nodeCount(), 24 * 11);
  EXPECT_EQ(p.elasticSkirt.coupling.absoluteTolerance_m, 2.0 * 1e-9);
  EXPECT_EQ(p.elasticSkirt.coupling.relativeTolerance, 2e-3);
  EXPECT_EQ(p.elasticSkirt.coupling.maxIterations, 40);
  // Thermal growth: the skirt grows by R alpha_p (T_p - T_ref) (60..70 degC), the bore by
  // R alpha_l (T_l - T_ref) (100..130 degC), T_ref = 25 degC. The hot clearance is the
  // smallest c0 + drop + both terms: at most its value on the mirrored profile's zero-drop
  // line (skirt at least 60 degC, bore at most 130 degC there), at least c0 with the
  // hottest skirt and the coolest bore (the drop is >= 0).
  const double R = 0.5 * 74.5e-3, hot = *b.skirt().getHotRunningClearance_m();
  EXPECT_LE(hot, 60e-6 + R * 1.1e-5 * (130.0 - 25.0) - R * 2.1e-5 * (60.0 - 25.0));
  EXPECT_GE(hot, 60e-6 + R * 1.1e-5 * (100.0 - 25.0) - R * 2.1e-5 * (70.0 - 25.0));
}

// The ideal guide stays selectable from the skirt deck: --set liner.model=ideal_guide (with
// an integrator for constraints); the deck's skirt keys are then the file's model's data,
// not reported, but a misspelt key given by --set still is.
TEST_F(SkirtScratchDeck, TheIdealGuideIsSelectableFromTheSkirtDeck) {
  const std::vector<std::string> ideal = {"liner.model=ideal_guide",
                                          "simulation.integrator=rk_merson"};
  const auto d = io::loadEngineDeck(deck(), ideal);
  EXPECT_EQ(d.linerModel, "ideal_guide");
  EXPECT_TRUE(d.linerInputs.empty());
  EXPECT_TRUE(d.engine.tertiaryMotion);  // the ideal guide's default: held by a constraint
  std::vector<std::string> typo = ideal;
  typo.push_back("liner.grid.nodes_axal=12");
  EXPECT_NE(rejection(typo).find("--set liner.grid.nodes_axal: unknown key"), std::string::npos)
      << rejection(typo);
  // Without the integrator: the deck's linearly_implicit_bdf2 cannot take constraints.
  const std::string m = rejection({"liner.model=ideal_guide"});
  expectNames(m, deck(), lineOf("integrator:"), "simulation.integrator",
              "linearly_implicit_bdf2 integrates models without constraints");
}

// --fidelity preview: the film grid coarsened to 3/8 of the nodes around the arc and 5/6 along
// the skirt (rounded up), not below 16 x 12, never finer than the deck's; the preview's
// assignments follow the user's overrides, its grid is what the element gets, and the note
// says what changed. The ideal guide has no grid.
TEST_F(SkirtScratchDeck, PreviewFidelityCoarsensTheFilmGridNotBelowSixteenByTwelve) {
  struct Case {
    int phi, y, previewPhi, previewY;
  };
  for (const Case& c : {Case{64, 48, 24, 40}, Case{32, 24, 16, 20}, Case{33, 25, 16, 21},
                        Case{48, 36, 18, 30}, Case{40, 13, 16, 12}, Case{20, 14, 16, 12},
                        Case{10, 8, 10, 8}}) {
    SCOPED_TRACE(std::to_string(c.phi) + " x " + std::to_string(c.y));
    const std::vector<std::string> user = {
        "liner.grid.nodes_circumferential=" + std::to_string(c.phi),
        "liner.grid.nodes_axial=" + std::to_string(c.y)};
    const io::EngineDeck full = io::loadEngineDeck(deck(), user, io::Fidelity::Full);
    EXPECT_EQ(full.fidelity, io::Fidelity::Full);
    EXPECT_EQ(full.overrides, user);
    EXPECT_TRUE(full.fidelityNote.empty());
    const io::EngineDeck preview = io::loadEngineDeck(deck(), user, io::Fidelity::Preview);
    EXPECT_EQ(preview.fidelity, io::Fidelity::Preview);
    std::vector<std::string> expected = user;
    expected.push_back("liner.grid.nodes_circumferential=" + std::to_string(c.previewPhi));
    expected.push_back("liner.grid.nodes_axial=" + std::to_string(c.previewY));
    EXPECT_EQ(preview.overrides, expected);
    auto model = io::buildModel(preview);
    model->buildSystem();
    const auto& grid = model->getElementAs<plugin::LubricatedSkirtElement>("lubricated_skirt")
                           .getParameters()
                           .grid;
    EXPECT_EQ(grid.nPhi, c.previewPhi);
    EXPECT_EQ(grid.nY, c.previewY);
    EXPECT_NE(
        preview.fidelityNote.find("film grid " + std::to_string(c.previewPhi) + " x " +
                                  std::to_string(c.previewY) + " nodes per side, the deck's " +
                                  std::to_string(c.phi) + " x " + std::to_string(c.y)),
        std::string::npos)
        << preview.fidelityNote;
  }
  const io::EngineDeck guide =
      io::loadEngineDeck(deck(), {"liner.model=ideal_guide", "simulation.integrator=rk_merson"},
                         io::Fidelity::Preview);
  EXPECT_EQ(guide.fidelity, io::Fidelity::Preview);
  EXPECT_TRUE(guide.fidelityNote.empty());
  EXPECT_EQ(guide.overrides.size(), 2u);
}

// The skirt's film is stiff: Simbody's explicit integrators are rejected, saying why.
TEST_F(SkirtScratchDeck, AnExplicitIntegratorIsRejectedForTheSkirt) {
  for (const char* integrator : {"rk_merson", "rk_feldberg"}) {
    const std::string m = rejection({std::string("simulation.integrator=") + integrator});
    EXPECT_NE(m.find("--set simulation.integrator: '" + std::string(integrator) +
                     "' is an explicit integrator, but the liner model 'lubricated_skirt' "
                     "makes the system stiff"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("use linearly_implicit_bdf2 (or cpodes_bdf)"), std::string::npos) << m;
  }
  EXPECT_EQ(rejection({"simulation.integrator=cpodes_bdf"}), "");
}

// A skirt deck that names no integrator gets the one that carries it, not the explicit
// default it would then refuse (issue 35); a deck without a stiff liner keeps rk_merson.
TEST_F(SkirtScratchDeck, ASkirtDeckWithoutAnIntegratorGetsTheLinearlyImplicitStepper) {
  const io::EngineDeck skirt = io::loadEngineDeck(deck(), {"simulation.integrator=null"});
  EXPECT_EQ(skirt.simulation.integrator,
            plugin::SimulationSettings::Integrator::LinearlyImplicitBDF);
  const io::EngineDeck guide = io::loadEngineDeck(
      deck(), {"simulation.integrator=null", "liner.model=ideal_guide"});
  EXPECT_EQ(guide.simulation.integrator,
            plugin::SimulationSettings::Integrator::RungeKuttaMerson);
}

TEST_F(SkirtScratchDeck, TheStepperOrderIsTwoOrThree) {
  EXPECT_EQ(rejection({"simulation.stepper_order=3"}), "");
  for (const char* bad : {"1", "4", "2.5"}) {
    const std::string m = rejection({std::string("simulation.stepper_order=") + bad});
    EXPECT_NE(m.find("simulation.stepper_order"), std::string::npos) << m;
  }
}

TEST_F(SkirtScratchDeck, UntilPeriodicNeedsTwoCycles) {
  const std::string m = rejection({"simulation.cycles=1"});
  EXPECT_NE(m.find("--set simulation.cycles: with simulation.until_periodic: true"),
            std::string::npos)
      << m;
}

// Found by the fuzz targets skirt_profile, ovality and bore_distortion (fuzz/): a table
// of finite but absurd values (1e308 mm, 1e308 um) passed every check, or failed deep in
// the gap assembly with "hot running clearance -1.8e262 m" naming no table. Each is now
// rejected at its file:line, with the plausible range, like a deck key out of range.
TEST_F(SkirtScratchDeck, TableValuesBeyondAnyEngineAreRejectedAtTheirLine) {
  const std::string profile = (dir_ / kProfileTable).string();
  writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um\n-1e308,-1e308\n1e308,1e308\n");
  std::string m = rejection();
  EXPECT_NE(m.find(profile + ":2: height_above_pin_mm -1e+308 mm is not a height on a piston"),
            std::string::npos)
      << m;
  writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um\n-25,40\n25,2001\n");
  m = rejection();
  EXPECT_NE(m.find(profile + ":3: radial_drop_um 2001 um is not a skirt's radial drop"),
            std::string::npos)
      << m;
  writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um\n-25,40\n25,2000\n");
  EXPECT_EQ(rejection(), "");  // the limit itself is accepted
  writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um\n-25,10\n25,10\n");

  editDeck("    ovality_diametral_um: 300.0", "    ovality_file: ovality.csv\n    #");
  editDeck("    ovality_cos4_coefficient: 0.0", "    # no law");
  writeFile("ovality.csv", "angle_from_thrust_deg,radial_drop_um\n0,0\n90,-1e300\n");
  m = rejection();
  EXPECT_NE(m.find((dir_ / "ovality.csv").string() +
                   ":3: radial_drop_um -1e+300 um is not an ovality's radial drop"),
            std::string::npos)
      << m;
  EXPECT_EQ(m.find("hot running clearance"), std::string::npos) << m;

  editDeck("  model: lubricated_skirt\n",
           "  model: lubricated_skirt\n  bore_distortion: {file: bore.csv}\n");
  writeFile("ovality.csv", "angle_from_thrust_deg,radial_drop_um\n0,0\n90,150\n");
  const std::string bore = (dir_ / "bore.csv").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0,2,1e308,0", ":2: amplitude_um 1e+308 um is not a bore distortion"},
      {"0,2,5,1e308", ":2: phase_deg 1e+308 deg is not a phase in [-360, 360] deg"},
      {"1e308,2,5,0", ":2: depth_mm 1e+308 mm is deeper than a liner"}};
  for (const auto& [row, message] : cases) {
    writeFile("bore.csv", "depth_mm,order,amplitude_um,phase_deg\n" + row + "\n");
    m = rejection();
    EXPECT_NE(m.find(bore + message), std::string::npos) << row << "\n" << m;
  }
  writeFile("bore.csv", "depth_mm,order,amplitude_um,phase_deg\n0,2,5,-360\n2000,2,5,360\n");
  EXPECT_EQ(rejection(), "");

  editDeck("  model: lubricated_skirt\n",
           "  model: lubricated_skirt\n  thermal: {piston_expansion_per_K: 2.1e-5, "
           "piston_temperature_file: piston_t.csv}\n");
  writeFile("piston_t.csv", "height_above_pin_mm,temperature_degC\n-1e308,60\n0,70\n");
  m = rejection();
  EXPECT_NE(m.find((dir_ / "piston_t.csv").string() +
                   ":2: height_above_pin_mm -1e+308 mm is not a position on a piston or liner"),
            std::string::npos)
      << m;
}

}  // namespace

// ---- liner.oil_supply.liner_transport --------------------------------------------------

namespace liner_transport {

const std::vector<std::string> kTransport = {
    "liner.oil_supply.film_um=null",
    "liner.oil_supply.liner_transport.ring_height_above_pin_mm=13",
    "liner.oil_supply.liner_transport.ring_film_um=0.8"};

std::vector<std::string> with(std::vector<std::string> extra) {
  std::vector<std::string> o = kTransport;
  o.insert(o.end(), extra.begin(), extra.end());
  return o;
}

}  // namespace liner_transport

// The section reaches the element in SI (um -> 1e-6 m, mm -> 1e-3 m, mm/s -> 1e-3 m/s).
TEST(SkirtDeck, TheLinerTransportSectionBecomesTheElementsLinerOilInSI) {
  const Built b = build(kEngineDir + "/engine.yaml",
                        liner_transport::with({"liner.oil_supply.liner_transport.flooded_below_mm=95",
                                               "liner.oil_supply.liner_transport.splash_rate_mm_per_s=2",
                                               "liner.oil_supply.liner_transport.splash_below_mm=110",
                                               "liner.oil_supply.liner_transport.max_film_um=20",
                                               "liner.oil_supply.liner_transport.skirt_share=0.3",
                                               "liner.oil_supply.liner_transport.initial_film_um=2"}));
  const plugin::LubricatedSkirtParameters& p = b.skirt().getParameters();
  ASSERT_TRUE(p.linerOil.has_value());
  EXPECT_EQ(p.linerOil->ringHeightAbovePin_m, 13.0 * 1e-3);
  EXPECT_EQ(p.linerOil->ringFilm_m, 0.8 * 1e-6);
  EXPECT_EQ(p.linerOil->floodedBelow_m, 95.0 * 1e-3);
  EXPECT_EQ(p.linerOil->splashRate_mps, 2.0 * 1e-3);
  EXPECT_EQ(p.linerOil->splashBelow_m, 110.0 * 1e-3);
  EXPECT_EQ(p.linerOil->maxFilm_m, 20.0 * 1e-6);
  EXPECT_EQ(p.linerOil->skirtShare, 0.3);
  EXPECT_EQ(p.linerOil->initialFilm_m, 2.0 * 1e-6);
  // The element then offers its liner film to the edge (io/, app/).
  EXPECT_NE(b.skirt().getLinerOil(), nullptr);
  EXPECT_GT(b.skirt().getLinerOilRowHeights_m().size(), 100);
}

TEST_F(SkirtScratchDeck, LinerTransportMistakesNameTheirKey) {
  using liner_transport::with;
  EXPECT_EQ(rejection(with({})), "");
  struct Case {
    std::vector<std::string> overrides;
    std::string key, words;
  };
  const std::vector<Case> cases = {
      {with({"liner.film.cavitation=reynolds"}), "liner.oil_supply.liner_transport",
       "mass_conserving"},
      {with({"liner.oil_supply.film_um=0.5"}), "liner.oil_supply.liner_transport",
       "exactly one of"},
      {with({"liner.oil_supply.liner_transport.ring_height_above_pin_mm=null"}),
       "liner.oil_supply.liner_transport.ring_height_above_pin_mm", "missing"},
      {with({"liner.oil_supply.liner_transport.ring_height_above_pin_mm=5"}),
       "liner.oil_supply.liner_transport.ring_height_above_pin_mm", "below the skirt's top"},
      {with({"liner.oil_supply.liner_transport.ring_film_um=null"}),
       "liner.oil_supply.liner_transport.ring_film_um", "exactly one of"},
      {with({"liner.oil_supply.liner_transport.splash_rate_mm_per_s=3"}),
       "liner.oil_supply.liner_transport.splash_rate_mm_per_s", "splash_below_mm"},
      {with({"liner.oil_supply.liner_transport.skirt_share=1.5"}),
       "liner.oil_supply.liner_transport.skirt_share", ""},
  };
  for (const Case& c : cases) {
    const std::string m = rejection(c.overrides);
    EXPECT_NE(m.find(c.key), std::string::npos) << c.overrides.back() << "\n" << m;
    EXPECT_NE(m.find(c.words), std::string::npos) << c.overrides.back() << "\n" << m;
  }
}

// A coarse cycle with the oil carried on the liner, through runDeck: liner_film.csv holds the
// last cycle's film along the bore on both sides at every output row, finite, within [0,
// max_film]; the rows above the skirt's reach (and above the row its top edge leaves oil in)
// that the oil-control ring passes hold exactly the ring's film once it passed them (nothing
// else reaches them); and the summary's balance over the cycle closes to round-off of the oil
// that moved.
TEST_F(SkirtScratchDeck, LinerTransportWritesTheFilmAlongTheBoreAndClosesItsBalance) {
  const std::vector<std::string> o = liner_transport::with(
      {"liner.oil_supply.liner_transport.flooded_below_mm=95",
       "liner.oil_supply.liner_transport.ring_height_above_pin_mm=20",
       "liner.oil_supply.liner_transport.initial_film_um=0.5",
       "liner.oil_supply.liner_transport.max_film_um=20", "simulation.cycles=1",
       "simulation.until_periodic=false", "liner.grid.nodes_circumferential=16",
       "liner.grid.nodes_axial=12", "simulation.output_step_deg=5"});
  const io::EngineDeck d = io::loadEngineDeck(deck(), o);
  const fs::path out = dir_ / "transport";
  const io::RunOutcome r = io::runDeck(d, out.string());
  ASSERT_TRUE(r.linerOilLastCycle.has_value());
  const plugin::LinerOilBalance& b = *r.linerOilLastCycle;
  const pistondyn::skirt::LinerOilFlows& f = b.flows;
  const double moved = f.ringSource_m3 + f.splashSource_m3 + f.skirtShareLoss_m3 +
                       std::abs(f.filmIntake_m3) + b.stored_m3;
  EXPECT_NE(f.ringSource_m3, 0.0);  // here a net sink: it scrapes what the skirt carried up
  EXPECT_GT(f.splashSource_m3, 0.0);
  EXPECT_NEAR(b.stored_m3 - b.initial_m3,
              f.ringSource_m3 + f.splashSource_m3 + f.deficitSource_m3 - f.drainLoss_m3 -
                  f.filmIntake_m3 - f.sideLeakage_m3 - f.skirtShareLoss_m3,
              1e-12 * moved);
  // The file: 4 columns, every value finite, films within [0, 20] um.
  std::ifstream in(out / "liner_film.csv");
  ASSERT_TRUE(in.good());
  std::string line;
  int rows = 0, ringRows = 0;
  std::set<double> heights;
  const double skirtTopAtTdc_mm = 1e3 * (d.engine.piston.skirtTopAbovePin_m +
                                        pistondyn::mbd::SliderCrank(d.engine.geometry).pinHeightAtTdc_m());
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("crank_angle_deg", 0) == 0)
      continue;
    double a, h, ft, fa;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &a, &h, &ft, &fa), 4) << line;
    ASSERT_TRUE(std::isfinite(ft) && std::isfinite(fa)) << line;
    EXPECT_GE(std::min(ft, fa), 0.0) << line;
    EXPECT_LE(std::max(ft, fa), 20.0 * (1 + 1e-12)) << line;
    ++rows;
    heights.insert(h);
    // Over 3 mm (a liner row) above the skirt's top at TDC, below the ring's lower edge at
    // TDC (8 mm above it): only the ring's film once the ring has passed (it starts at TDC,
    // 0 deg, and is far below these rows by 90 deg).
    if (h > skirtTopAtTdc_mm + 3.0 && h < skirtTopAtTdc_mm + 7.95 && a > 90.0) {
      EXPECT_NEAR(ft, 0.8, 1e-9) << line;
      EXPECT_NEAR(fa, 0.8, 1e-9) << line;
      ++ringRows;
    }
  }
  EXPECT_GT(heights.size(), 40u);  // the 12 axial nodes' spacing along 120 mm of bore
  EXPECT_EQ(rows, 144 * static_cast<int>(heights.size()));  // 144 output rows of 5 deg
  EXPECT_GT(ringRows, 0);
}

// Every cycle of a run is summarised, not only the last: each cycle's fmep equals the one the
// simulation integrated for that cycle (CycleSimulation, its own code), each cycle's largest
// |u_lat| the largest of that cycle's rows in cycle.csv (a run not to periodic steady state
// writes every cycle); and a run that did not become periodic reports its last cycles' mean
// and spread (largest - smallest) of each figure in summary.json, results.last_cycles - here
// checked against those independent per-cycle figures. A run to periodic steady state that
// did not converge summarises its discarded cycles too.
TEST_F(SkirtScratchDeck, EveryCycleIsSummarisedAndANonPeriodicRunReportsItsLastCyclesSpread) {
  const std::vector<std::string> coarse = {
      "liner.grid.nodes_circumferential=12", "liner.grid.nodes_axial=8",
      "simulation.output_step_deg=2", "liner.parallel_sides=false"};
  std::vector<std::string> o = coarse;
  o.insert(o.end(), {"simulation.cycles=2", "simulation.until_periodic=false"});
  const fs::path out = dir_ / "two";
  const io::RunOutcome r = io::runDeck(io::loadEngineDeck(deck(), o), out.string());
  ASSERT_EQ(r.cycleSummaries.size(), 2u);
  ASSERT_EQ(r.stats.cycleFmep_Pa.size(), 2u);
  const pistondyn::test::NumericCsv csv = pistondyn::test::readNumericCsv(out / "cycle.csv");
  ASSERT_EQ(csv.rows.size(), 2u * 360u + 1u);
  const std::size_t uLat = csv.col("u_lat_um");
  std::vector<double> fmep_kPa, maxULat_um;
  for (std::size_t c = 0; c < 2; ++c) {
    const io::CycleSummary& s = r.cycleSummaries[c];
    ASSERT_TRUE(s.liner && s.liner->fmep_Pa);
    EXPECT_NEAR(*s.liner->fmep_Pa, r.stats.cycleFmep_Pa[c], 1e-12 * r.stats.cycleFmep_Pa[c]);
    double largest = 0.0;
    for (std::size_t k = 360 * c; k < 360 * (c + 1); ++k)
      largest = std::max(largest, std::abs(csv.rows[k][uLat]));
    EXPECT_NEAR(s.maxAbsLateralDisplacement_m * 1e6, largest, 1e-9);
    fmep_kPa.push_back(r.stats.cycleFmep_Pa[c] / 1e3);
    maxULat_um.push_back(largest);
  }
  EXPECT_EQ(*r.cycleSummaries.back().liner->fmep_Pa, *r.summary.liner->fmep_Pa);
  EXPECT_NE(fmep_kPa[0], fmep_kPa[1]);  // the start-up cycle differs: the check can fail

  const auto json = nlohmann::json::parse(readFile(out / "summary.json"))["results"];
  ASSERT_FALSE(json["converged"].get<bool>());
  ASSERT_TRUE(json.contains("last_cycles")) << json.dump();
  const auto& last = json["last_cycles"];
  EXPECT_EQ(last["cycles"], nlohmann::json::array({1, 2}));
  const auto expectMeanAndSpread = [&](const std::string& key, const std::vector<double>& v,
                                       double tol) {
    EXPECT_NEAR(last["mean"][key].get<double>(), 0.5 * (v[0] + v[1]), tol) << key;
    EXPECT_NEAR(last["spread"][key].get<double>(), std::abs(v[0] - v[1]), tol) << key;
  };
  expectMeanAndSpread("fmep_kPa", fmep_kPa, 1e-12);
  // The integrator's work per cycle sums to the run's.
  const auto whole = nlohmann::json::parse(readFile(out / "summary.json"));
  const auto total = [&json](const char* key) {
    long sum = 0;
    for (const auto& v : json[key])
      sum += v.get<long>();
    EXPECT_EQ(json[key].size(), 2u) << key;
    return sum;
  };
  EXPECT_EQ(total("cycle_integrator_steps"), whole["integrator_steps"].get<long>());
  EXPECT_EQ(total("cycle_rejected_steps"), json["rejected_steps"].get<long>());
  EXPECT_EQ(total("cycle_force_evaluations"), r.stats.realizations);
  EXPECT_GE(json["cycle_integrator_steps"][1].get<long>(), 720);  // the 1 deg cap
  // The stepper's step error estimate per cycle: positive, finite, the last one the results'.
  ASSERT_EQ(json["cycle_step_error_estimate_um"].size(), 2u);
  for (const auto& e : json["cycle_step_error_estimate_um"])
    EXPECT_GT(e.get<double>(), 0.0);
  EXPECT_EQ(json["step_error_estimate_um"], json["cycle_step_error_estimate_um"][1]);
  expectMeanAndSpread("max_abs_u_lat_um", maxULat_um, 1e-9);
  // Every figure of the last cycle is averaged, none of the deck's own (the same in each).
  for (const auto& [key, value] : last["mean"].items())
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_FALSE(last["mean"].contains("imep_kPa"));
  EXPECT_TRUE(last["mean"].contains("min_h_over_sigma_thrust"));
  EXPECT_TRUE(last["mean"].contains("slap_energy_max_mJ"));

  // To periodic steady state, not reached (a tolerance no run meets): the discarded cycles are
  // summarised as well, the spread over the last three.
  o = coarse;
  o.insert(o.end(), {"simulation.cycles=4", "simulation.until_periodic=true",
                     "simulation.periodic_fmep_tolerance=1e-12"});
  const fs::path out4 = dir_ / "four";
  const io::RunOutcome r4 = io::runDeck(io::loadEngineDeck(deck(), o), out4.string());
  ASSERT_EQ(r4.cycleSummaries.size(), 4u);
  for (std::size_t c = 0; c < 4; ++c)
    EXPECT_NEAR(*r4.cycleSummaries[c].liner->fmep_Pa, r4.stats.cycleFmep_Pa[c],
                1e-12 * r4.stats.cycleFmep_Pa[c]);
  const auto json4 = nlohmann::json::parse(readFile(out4 / "summary.json"))["results"];
  EXPECT_EQ(json4["last_cycles"]["cycles"], nlohmann::json::array({2, 3, 4}));
  const double mean4 =
      (r4.stats.cycleFmep_Pa[1] + r4.stats.cycleFmep_Pa[2] + r4.stats.cycleFmep_Pa[3]) / 3e3;
  EXPECT_NEAR(json4["last_cycles"]["mean"]["fmep_kPa"].get<double>(), mean4, 1e-12);
}
