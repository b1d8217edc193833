// pistondyn new's library (io/NewDeck.h): the deck made from a drawing loads as
// `pistondyn check` loads it, its estimates follow the documented rules (README.md, "A deck
// from a drawing"), every key it writes is a key of the deck key table, values given are
// written as given, and a refused request or folder writes nothing.

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "NewDeckText.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/NewDeck.h"

namespace {

namespace fs = std::filesystem;
using pistondyn::io::EngineType;
using pistondyn::io::NewDeckError;
using pistondyn::io::NewDeckRequest;

const std::string kGasolineDir =
    std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/gasoline_1400_2000rpm";

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every entry of `dir`, sorted (to see that nothing was added or left behind).
std::vector<std::string> listFolder(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The line of engine.yaml that writes `leaf` under the section `section` (its first).
std::string findKeyLine(const std::string& yaml, const std::string& section,
                        const std::string& leaf) {
  const std::size_t at = yaml.find("\n" + section + ":\n");
  if (at == std::string::npos)
    return {};
  const std::size_t key = yaml.find(" " + leaf + ":", at);
  if (key == std::string::npos)
    return {};
  const std::size_t begin = yaml.rfind('\n', key) + 1;
  return yaml.substr(begin, yaml.find('\n', key) - begin);
}

// A resolved liner input of the loaded deck (SI), by its deck path.
double getLinerInput(const pistondyn::io::EngineDeck& deck, const std::string& path) {
  for (const auto& input : deck.linerInputs) {
    if (input.path == path)
      return std::get<double>(input.value);
  }
  ADD_FAILURE() << "no liner input " << path;
  return NAN;
}

class NewDeckTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pistondyn_newdeck_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static NewDeckRequest request(double bore_mm, double stroke_mm) {
    NewDeckRequest r;
    r.name = "test engine";
    r.bore_mm = bore_mm;
    r.stroke_mm = stroke_mm;
    return r;
  }
  // Makes and writes the deck into dir_/<folder>; returns the loaded deck (as check does).
  pistondyn::io::EngineDeck makeAndLoad(const NewDeckRequest& r, const std::string& folder) {
    const pistondyn::io::NewDeck deck = pistondyn::io::makeNewDeck(r);
    pistondyn::io::writeNewDeck(deck, (dir_ / folder).string());
    return pistondyn::io::loadEngineDeck((dir_ / folder / "engine.yaml").string(), {});
  }
  // The message of the NewDeckError makeNewDeck throws, checking its kind ("" if none).
  static std::string refusal(const NewDeckRequest& r, NewDeckError::Kind kind) {
    try {
      pistondyn::io::makeNewDeck(r);
    } catch (const NewDeckError& e) {
      EXPECT_EQ(static_cast<int>(e.getKind()), static_cast<int>(kind)) << e.what();
      return e.what();
    }
    return {};
  }
  fs::path dir_;
};

TEST_F(NewDeckTest, TheDeckMadeFromBoreAndStrokeLoadsWithItsTables) {
  const NewDeckRequest r = request(74.5, 80.0);
  const pistondyn::io::NewDeck made = pistondyn::io::makeNewDeck(r);
  ASSERT_EQ(made.files.size(), 3u);
  EXPECT_EQ(made.files[0].name, "engine.yaml");
  EXPECT_EQ(made.files[1].name, "skirt_profile.csv");
  pistondyn::io::writeNewDeck(made, (dir_ / "deck").string());
  // Only the deck folder: no temporary folder left beside it.
  EXPECT_EQ(listFolder(dir_), std::vector<std::string>{"deck"});
  std::vector<std::string> names;
  for (const auto& f : made.files)
    names.push_back(f.name);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(listFolder(dir_ / "deck"), names);
  const auto deck = pistondyn::io::loadEngineDeck((dir_ / "deck" / "engine.yaml").string(), {});
  EXPECT_EQ(deck.engine.name, "test engine");
  EXPECT_DOUBLE_EQ(deck.engine.piston.bore_m, 0.0745);
  EXPECT_DOUBLE_EQ(deck.engine.geometry.crankRadius_m, 0.040);
  EXPECT_EQ(deck.linerModel, "lubricated_skirt");
  // The generated table meets the imep the deck states (the loader's 0.5 % check passed);
  // the type's part load, 600 kPa, since none was given.
  ASSERT_TRUE(deck.statedImep_Pa.has_value());
  EXPECT_DOUBLE_EQ(*deck.statedImep_Pa, 600e3);
  EXPECT_NEAR(pistondyn::io::calcDeckImep_Pa(deck), 600e3, 0.005 * 600e3);
  EXPECT_NEAR(made.imep_kPa, 600.0, 3.0);
}

// The documented rules of the gasoline type: skirt length 0.40 x bore (to 0.1 mm), running
// radial clearance 0.13 per mille of the bore (to 1 um). Read back from the loaded decks of
// two bores, so a rule changed without its documentation fails here.
TEST_F(NewDeckTest, SkirtLengthAndClearanceScaleWithTheBoreByTheirRules) {
  for (const double bore_mm : {70.0, 100.0}) {
    const std::string folder = "bore" + std::to_string(static_cast<int>(bore_mm));
    const auto deck = makeAndLoad(request(bore_mm, 80.0), folder);
    EXPECT_NEAR(deck.engine.piston.skirtLength_m * 1e3, 0.40 * bore_mm, 0.05 + 1e-9) << bore_mm;
    EXPECT_NEAR(getLinerInput(deck, "liner.cold_radial_clearance_um") * 1e6, 0.13e-3 * bore_mm * 1e3,
                0.5 + 1e-9)
        << bore_mm;
    const std::string yaml = readFile(dir_ / folder / "engine.yaml");
    EXPECT_NE(findKeyLine(yaml, "piston", "skirt_length_mm").find("EST: skirt length 0.4 x bore"),
              std::string::npos)
        << yaml;
    EXPECT_NE(findKeyLine(yaml, "liner", "cold_radial_clearance_um")
                  .find("EST: 0.13 per mille of the bore"),
              std::string::npos)
        << yaml;
  }
}

// Every key the deck lists as estimated is written with an EST note; the values given are
// written as given, marked [U] and not estimated.
TEST_F(NewDeckTest, EstimatesAreMarkedAndGivenValuesAreWrittenAsGiven) {
  NewDeckRequest r = request(81.0, 86.4);
  r.conrodLength_mm = 144.0;
  r.speed_rpm = 3000.0;
  r.coldRadialClearance_um = 35.0;
  const pistondyn::io::NewDeck made = pistondyn::io::makeNewDeck(r);
  const std::string& yaml = made.files[0].text;
  ASSERT_FALSE(made.estimated.empty());
  for (const std::string& key : made.estimated) {
    const std::size_t dot = key.find('.');
    const std::size_t last = key.rfind('.');
    const std::string line = findKeyLine(yaml, key.substr(0, dot), key.substr(last + 1));
    EXPECT_NE(line.find("# EST"), std::string::npos) << key << ": " << line;
  }
  for (const char* given : {"geometry.conrod_length_mm", "drive.speed_rpm",
                            "liner.cold_radial_clearance_um", "geometry.bore_mm"}) {
    EXPECT_EQ(std::count(made.estimated.begin(), made.estimated.end(), given), 0) << given;
  }
  EXPECT_NE(findKeyLine(yaml, "geometry", "conrod_length_mm").find("144  "), std::string::npos);
  EXPECT_NE(findKeyLine(yaml, "geometry", "conrod_length_mm").find("[U]"), std::string::npos);
  EXPECT_NE(findKeyLine(yaml, "drive", "speed_rpm").find("3000"), std::string::npos);
  EXPECT_NE(findKeyLine(yaml, "liner", "cold_radial_clearance_um").find("35  "),
            std::string::npos);
  // The estimated rod is L/r = 3.5 x the crank radius when not given (the rule).
  const pistondyn::io::NewDeck estimated = pistondyn::io::makeNewDeck(request(81.0, 86.4));
  EXPECT_NE(findKeyLine(estimated.files[0].text, "geometry", "conrod_length_mm").find("151.2"),
            std::string::npos);
}

// Each engine type, fired and motored, and a copied table: decks that load.
TEST_F(NewDeckTest, EveryTypeFiredAndMotoredMakesADeckThatLoads) {
  struct Case {
    EngineType type;
    double bore_mm, stroke_mm;
  };
  int n = 0;
  for (const Case c : {Case{EngineType::PassengerCarGasoline, 82.5, 92.8},
                       Case{EngineType::SmallAirCooled, 65.1, 61.9},
                       Case{EngineType::Diesel, 81.0, 95.5}}) {
    for (const bool motored : {false, true}) {
      NewDeckRequest r = request(c.bore_mm, c.stroke_mm);
      r.type = c.type;
      r.motored = motored;
      const auto deck = makeAndLoad(r, "deck" + std::to_string(n++));
      EXPECT_DOUBLE_EQ(deck.engine.piston.bore_m, c.bore_mm * 1e-3);
      EXPECT_EQ(deck.statedImep_Pa.has_value(), !motored);
      if (motored) {
        EXPECT_LT(pistondyn::io::calcDeckImep_Pa(deck), 0.0);  // pumping and compression loss
      }
    }
  }
}

TEST_F(NewDeckTest, AGivenPressureTableIsCopiedAsItIs) {
  NewDeckRequest r = request(74.5, 80.0);
  r.conrodLength_mm = 140.0;
  r.compressionRatio = 10.0;
  r.pinOffset_mm = 0.5;
  r.pressureTableFile = kGasolineDir + "/cylinder_pressure_fired_imep598kPa.csv";
  const auto deck = makeAndLoad(r, "deck");
  EXPECT_EQ(readFile(dir_ / "deck" / "cylinder_pressure.csv"), readFile(r.pressureTableFile));
  // The example engine's table on the example's crank train: its stated 598 kPa.
  EXPECT_NEAR(pistondyn::io::calcDeckImep_Pa(deck), 598e3, 0.005 * 598e3);
  EXPECT_FALSE(deck.statedImep_Pa.has_value());
}

TEST_F(NewDeckTest, BadValuesAreRefusedNamingTheOption) {
  using Kind = NewDeckError::Kind;
  NewDeckRequest r = request(-74.5, 80.0);
  EXPECT_NE(refusal(r, Kind::BadValue).find("--bore-mm -74.5"), std::string::npos);
  r = request(0.0745, 80.0);  // metres given as millimetres: named as a unit slip
  const std::string slip = refusal(r, Kind::BadValue);
  EXPECT_NE(slip.find("--bore-mm"), std::string::npos) << slip;
  EXPECT_NE(slip.find("implausible"), std::string::npos) << slip;
  r = request(74.5, 80.0);
  r.conrodLength_mm = 90.0;  // L/r 2.25
  EXPECT_NE(refusal(r, Kind::BadValue).find("--rod-mm 90 is too short"), std::string::npos);
  r = request(74.5, 80.0);
  r.speed_rpm = 15000.0;  // 40 m/s mean piston speed
  EXPECT_NE(refusal(r, Kind::BadValue).find("--speed-rpm 15000"), std::string::npos);
  r = request(74.5, 80.0);
  r.imep_kPa = -5.0;
  EXPECT_NE(refusal(r, Kind::BadValue).find("--imep-kPa -5"), std::string::npos);
  r = request(74.5, 80.0);
  r.oilGrade = "SAE 99";
  EXPECT_NE(refusal(r, Kind::BadValue).find("--oil-grade SAE 99"), std::string::npos);
  r = request(74.5, 80.0);
  r.imep_kPa = 600.0;
  r.pressureTableFile = kGasolineDir + "/cylinder_pressure_fired_imep598kPa.csv";
  EXPECT_NE(refusal(r, Kind::Conflict).find("--imep-kPa and --pressure-table"),
            std::string::npos);
  r = request(74.5, 80.0);
  r.name = "two\nlines";
  EXPECT_NE(refusal(r, Kind::BadValue).find("--name holds a control character"), std::string::npos);
}

TEST_F(NewDeckTest, AnUnreadablePressureTableIsRefusedNamingTheFile) {
  std::ofstream(dir_ / "bad.csv") << "crank_angle_deg,pressure_bar\n0,abc\n";
  NewDeckRequest r = request(74.5, 80.0);
  r.pressureTableFile = (dir_ / "bad.csv").string();
  const std::string message = refusal(r, NewDeckError::Kind::BadTable);
  EXPECT_NE(message.find("--pressure-table"), std::string::npos) << message;
  EXPECT_NE(message.find("bad.csv"), std::string::npos) << message;
  r.pressureTableFile = (dir_ / "missing.csv").string();
  EXPECT_NE(refusal(r, NewDeckError::Kind::BadTable).find("no such file"), std::string::npos);
}

// A folder that exists and holds something is refused and left as it was; an empty one is
// used; nothing temporary is left either way.
TEST_F(NewDeckTest, ANonEmptyFolderIsRefusedAndLeftAsItWas) {
  fs::create_directories(dir_ / "taken");
  std::ofstream(dir_ / "taken" / "engine.yaml") << "keep me";
  const pistondyn::io::NewDeck made = pistondyn::io::makeNewDeck(request(74.5, 80.0));
  try {
    pistondyn::io::writeNewDeck(made, (dir_ / "taken").string());
    ADD_FAILURE() << "a non-empty folder was written";
  } catch (const NewDeckError& e) {
    EXPECT_EQ(e.getKind(), NewDeckError::Kind::Folder);
    EXPECT_NE(std::string(e.what()).find("not empty"), std::string::npos) << e.what();
  }
  EXPECT_EQ(readFile(dir_ / "taken" / "engine.yaml"), "keep me");
  EXPECT_EQ(listFolder(dir_ / "taken"), std::vector<std::string>{"engine.yaml"});
  EXPECT_NE(pistondyn::io::findNewDeckFolderProblem((dir_ / "no" / "parent").string()), "");
  fs::create_directories(dir_ / "empty");
  pistondyn::io::writeNewDeck(made, (dir_ / "empty").string());
  EXPECT_TRUE(fs::exists(dir_ / "empty" / "engine.yaml"));
  EXPECT_EQ(listFolder(dir_), (std::vector<std::string>{"empty", "taken"}));
}

// The key check of the deck's text: a key the table lacks (a unit the key does not take)
// is a programming error, caught when the text is made.
TEST(NewDeckText, OnlyKeysOfTheDeckKeyTableCanBeWritten) {
  pistondyn::io::newdeck::DeckText d;
  d.section(0, "geometry");
  EXPECT_NO_THROW(d.entry(2, "bore_mm", "74.5"));
  EXPECT_THROW(d.entry(2, "bore_m", "0.0745"), std::logic_error);
  d.section(0, "liner");
  d.section(2, "grid");
  EXPECT_NO_THROW(d.entry(4, "nodes_axial", "24"));
  EXPECT_NO_THROW(d.entry(2, "cold_radial_clearance_um", "40"));  // closes liner.grid
  EXPECT_THROW(d.entry(4, "nodes_axial", "24"), std::logic_error);  // liner.nodes_axial
  EXPECT_EQ(d.getKeys(), (std::vector<std::string>{"geometry.bore_mm", "liner.grid.nodes_axial",
                                                   "liner.cold_radial_clearance_um"}));
}

}  // namespace
