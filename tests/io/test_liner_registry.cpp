// Liner models selected from a deck through the registry: the built-in ideal guide, a
// user's element registered by its program and selected by the deck or by --set, the
// section's keys read by the model's factory (unknown ones still reported), and its
// inputs in summary.json.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "../../examples/custom_element/SpringLinerGuide.h"
#include "ScratchDeck.h"
#include "pistondyn/io/LinerRegistry.h"
#include "pistondyn/io/RunDeck.h"
#include "pistondyn/plugin/IdealLinerGuide.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;
using pistondyn::examples::SpringLinerGuide;
namespace io = pistondyn::io;

namespace {

// A registry like a user's program builds: the built-ins plus the example's springs.
io::LinerRegistry springRegistry() {
  io::LinerRegistry r;
  pistondyn::examples::registerSpringLinerGuide(r);
  return r;
}

const SpringLinerGuide::Parameters& springParameters(
    const pistondyn::plugin::PistonAssemblyModel& m) {
  return m.getElementAs<SpringLinerGuide>("spring_liner_guide").getParameters();
}

class LinerDeck : public ScratchDeck {
 protected:
  std::string rejection(const std::vector<std::string>& overrides,
                        const io::LinerRegistry& registry) const {
    try {
      io::loadEngineDeck(deck(), overrides, registry);
    } catch (const io::DeckError& e) {
      return e.what();
    }
    return "";
  }
};

TEST(LinerRegistry, IdealGuideIsRegisteredByDefault) {
  const io::LinerRegistry r;
  EXPECT_TRUE(r.has("ideal_guide"));
  EXPECT_TRUE(r.has("lubricated_skirt"));
  EXPECT_TRUE(io::LinerRegistry::getGlobal().has("ideal_guide"));
  EXPECT_FALSE(r.getDescription("ideal_guide").empty());
}

TEST(LinerRegistry, NamesAreCheckedAndUnique) {
  io::LinerRegistry r = springRegistry();
  EXPECT_EQ(r.getNames(),
            (std::vector<std::string>{"ideal_guide", "lubricated_skirt", "spring_guide"}));
  EXPECT_THROW(pistondyn::examples::registerSpringLinerGuide(r), std::invalid_argument);
  EXPECT_THROW(r.add("Spring Guide", "", pistondyn::examples::readSpringLinerGuide),
               std::invalid_argument);
  EXPECT_THROW(r.add("empty", "", nullptr), std::invalid_argument);
  r.remove("spring_guide");
  EXPECT_FALSE(r.has("spring_guide"));
  EXPECT_THROW(r.getFactory("spring_guide"), std::invalid_argument);
}

TEST_F(LinerDeck, TheDeckSelectsTheIdealGuideByDefault) {
  const auto d = io::loadEngineDeck(deck(), {});
  EXPECT_EQ(d.linerModel, "ideal_guide");
  EXPECT_TRUE(d.linerInputs.empty());
  const auto model = io::buildModel(d);
  EXPECT_NO_THROW(model->getElementAs<pistondyn::plugin::IdealLinerGuide>("ideal_liner_guide"));
}

TEST_F(LinerDeck, AUserLinerIsSelectedFromTheDeck) {
  editDeck("  model: ideal_guide\n",
           "  model: spring_guide\n  lateral_stiffness_N_per_mm: 3.0e4\n"
           "  tilt_damping_Nms_per_rad: 5\n");
  const auto d = io::loadEngineDeck(deck(), {}, springRegistry());
  EXPECT_EQ(d.linerModel, "spring_guide");
  const auto model = io::buildModel(d);
  EXPECT_EQ(model->getElementNames(),
            (std::vector<std::string>{"gas_force", "spring_liner_guide"}));
  EXPECT_DOUBLE_EQ(springParameters(*model).lateralStiffness_Npm, 3.0e7);  // N/mm -> N/m
  EXPECT_DOUBLE_EQ(springParameters(*model).tiltDamping_Nmsprad, 5.0);
  EXPECT_DOUBLE_EQ(springParameters(*model).axialDamping_Nspm, 2e3);  // default
  // Each buildModel() makes a new element.
  const auto second = io::buildModel(d);
  EXPECT_NE(&second->getElement("spring_liner_guide"), &model->getElement("spring_liner_guide"));
}

TEST_F(LinerDeck, AUserLinerIsSelectedWithSet) {
  const auto d = io::loadEngineDeck(
      deck(), {"liner.model=spring_guide", "liner.axial_stiffness_N_per_mm=1e4"}, springRegistry());
  EXPECT_EQ(d.linerModel, "spring_guide");
  EXPECT_DOUBLE_EQ(springParameters(*io::buildModel(d)).axialStiffness_Npm, 1e7);
}

// A program registers its model once, in the global registry, and every deck it loads
// can select it without passing a registry.
TEST_F(LinerDeck, AProgramRegistersItsLinerGlobally) {
  if (!io::LinerRegistry::getGlobal().has("spring_guide"))
    pistondyn::examples::registerSpringLinerGuide();
  const auto d = io::loadEngineDeck(deck(), {"liner.model=spring_guide"});
  EXPECT_EQ(d.linerModel, "spring_guide");
  EXPECT_EQ(io::buildModel(d)->getElementNames().back(), "spring_liner_guide");
}

TEST_F(LinerDeck, UnknownKeysOfTheLinerSectionAreStillErrors) {
  // The ideal guide reads no keys: any key besides model is unknown.
  EXPECT_NE(rejection({"liner.lateral_stiffness_N_per_mm=3e4"}, springRegistry())
                .find("--set liner.lateral_stiffness_N_per_mm: unknown key"),
            std::string::npos);
  editDeck("  model: ideal_guide\n", "  model: spring_guide\n  lateral_stifness_N_per_mm: 3e4\n");
  const std::string m = rejection({}, springRegistry());
  expectNames(m, deck(), lineOf("lateral_stifness"), "liner.lateral_stifness_N_per_mm",
              "unknown key");
}

TEST_F(LinerDeck, TheFactoryReportsBadValuesLikeTheRestOfTheDeck) {
  editDeck("  model: ideal_guide\n", "  model: spring_guide\n  lateral_stiffness_N_per_mm: -1\n");
  const std::string m = rejection({"drive.speed_rpm=fast"}, springRegistry());
  expectNames(m, deck(), lineOf("lateral_stiffness"), "liner.lateral_stiffness_N_per_mm",
              "must be positive (got -1)");
  EXPECT_NE(m.find("--set drive.speed_rpm: 'fast' is not a number"), std::string::npos) << m;
}

TEST_F(LinerDeck, AnUnknownModelIsOneProblemNamingTheRegisteredOnes) {
  const std::string m =
      rejection({"liner.model=my_liner", "liner.clearance_um=20"}, springRegistry());
  EXPECT_NE(m.find("--set liner.model: 'my_liner' is not one of: ideal_guide, "
                   "lubricated_skirt, spring_guide"),
            std::string::npos)
      << m;
  EXPECT_EQ(m.find("clearance_um"), std::string::npos) << m;  // not also "unknown key"
}

TEST_F(LinerDeck, AnElementThatRejectsItsParametersIsBadInput) {
  io::LinerRegistry r;
  r.add("picky", "throws from its constructor", [](io::DeckSection&) -> io::LinerElementMaker {
    return []() -> std::unique_ptr<pistondyn::plugin::LinerElement> {
      throw std::invalid_argument("Picky: clearance must exceed roughness");
    };
  });
  const std::string m = rejection({"liner.model=picky"}, r);
  EXPECT_NE(m.find("liner: the liner model 'picky' rejected its parameters: Picky: clearance"),
            std::string::npos)
      << m;
}

// summary.json lists the liner model's inputs as its factory resolved them, in SI.
TEST_F(LinerDeck, SummaryListsTheLinerInputsInSI) {
  const auto d =
      io::loadEngineDeck(deck(),
                         {"liner.model=spring_guide", "liner.lateral_stiffness_N_per_mm=3e4",
                          "simulation.output_step_deg=10"},
                         springRegistry());
  const fs::path out = dir_ / "results";
  const io::RunOutcome o = io::runDeck(d, out.string());
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["inputs"]["liner"]["model"], "spring_guide");
  EXPECT_EQ(j["inputs"]["liner"]["lateral_stiffness_N_per_m"].get<double>(), 3e7);
  EXPECT_EQ(j["inputs"]["liner"]["axial_damping_Ns_per_m"].get<double>(), 2e3);
  EXPECT_EQ(j["results"]["side_force_max_N"].get<double>(), o.summary.liner->sideForceMax_N);
}

}  // namespace
