// Decks and tables (pistondyn::io): every class of bad input named in issue 2 is
// rejected before any simulation, with a message naming the file, the key or line, and
// what is wrong. The program-level checks (exit codes, no result files) are in tests/app.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ScratchDeck.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/EngineDeck.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

TEST_F(ScratchDeck, TheUneditedDeckLoads) {
  EXPECT_EQ(rejection(), "");
}

TEST_F(ScratchDeck, MissingKey) {
  editDeck("  bore_mm: 74.5               # [V]\n", "");
  const std::string m = rejection();
  EXPECT_NE(m.find(deck()), std::string::npos) << m;
  EXPECT_NE(m.find("geometry.bore_mm: missing key"), std::string::npos) << m;
}

TEST_F(ScratchDeck, UnknownKey) {
  editDeck("  stroke_mm: 80.0", "  strok_mm: 80.0");
  const std::string m = rejection();
  expectNames(m, deck(), lineOf("strok_mm"), "geometry.strok_mm", "unknown key");
  EXPECT_NE(m.find("geometry.stroke_mm: missing key"), std::string::npos) << m;
}

TEST_F(ScratchDeck, NegativeLength) {
  editDeck("bore_mm: 74.5", "bore_mm: -74.5");
  expectNames(rejection(), deck(), lineOf("bore_mm"), "geometry.bore_mm", "must be positive");
}

TEST_F(ScratchDeck, ZeroLength) {
  editDeck("skirt_length_mm: 30.0", "skirt_length_mm: 0");
  expectNames(rejection(), deck(), lineOf("skirt_length_mm"), "piston.skirt_length_mm",
              "must be positive");
}

TEST_F(ScratchDeck, RodShorterThanCrankRadius) {
  editDeck("conrod_length_mm: 140.0", "conrod_length_mm: 35.0");
  expectNames(rejection(), deck(), lineOf("conrod_length_mm"), "geometry.conrod_length_mm",
              "the rod must be longer than half the stroke");
}

TEST_F(ScratchDeck, NonNumericValue) {
  editDeck("speed_rpm: 2000", "speed_rpm: fast");
  expectNames(rejection(), deck(), lineOf("speed_rpm"), "drive.speed_rpm",
              "'fast' is not a number");
}

TEST_F(ScratchDeck, BadChoice) {
  editDeck("joint: floating", "joint: welded");
  expectNames(rejection(), deck(), lineOf("joint:"), "pin.joint", "not one of");
}

TEST_F(ScratchDeck, AllProblemsAreReportedTogether) {
  editDeck("bore_mm: 74.5", "bore_mm: -1");
  editDeck("speed_rpm: 2000", "speed_rpm: x");
  const std::string m = rejection();
  EXPECT_NE(m.find("geometry.bore_mm"), std::string::npos);
  EXPECT_NE(m.find("drive.speed_rpm"), std::string::npos);
}

TEST_F(ScratchDeck, PressureTableNotIncreasing) {
  writeTable("crank_angle_deg,pressure_bar\n0,1\n180,1\n170,1\n540,1\n");
  const std::string m = rejection();
  EXPECT_NE(m.find((dir_ / kTable).string() + ":4: crank angle 170"), std::string::npos) << m;
  EXPECT_NE(m.find("angles must increase"), std::string::npos) << m;
}

TEST_F(ScratchDeck, PressureTableNotCoveringTheCycle) {
  writeTable("# partial\ncrank_angle_deg,pressure_bar\n0,1\n90,2\n180,3\n270,2\n360,1\n");
  const std::string m = rejection();
  EXPECT_NE(m.find((dir_ / kTable).string()), std::string::npos) << m;
  EXPECT_NE(m.find("does not cover the 720 deg cycle"), std::string::npos) << m;
}

TEST_F(ScratchDeck, PressureTableNonNumericAndBadHeader) {
  writeTable("crank_angle_deg,pressure_bar\n0,1\n90,abc\n");
  EXPECT_NE(rejection().find(":3: pressure 'abc' is not a number"), std::string::npos);
  writeTable("angle,pressure\n0,1\n");
  EXPECT_NE(rejection().find(":1: expected the header"), std::string::npos);
}

TEST_F(ScratchDeck, StatedImepDisagreeingWithTheTable) {
  editDeck("stated_imep_kPa: 598.0", "stated_imep_kPa: 650.0");
  const std::string m = rejection();
  EXPECT_NE(m.find("gas.stated_imep_kPa"), std::string::npos) << m;
  EXPECT_NE(m.find("tolerance 0.5 %"), std::string::npos) << m;
}

TEST_F(ScratchDeck, InvalidYamlNamesTheLine) {
  editDeck("  stroke_mm: 80.0", "  stroke_mm: [80.0");
  const std::string m = rejection();
  EXPECT_NE(m.find(deck() + ":"), std::string::npos) << m;
  EXPECT_NE(m.find("not valid YAML"), std::string::npos) << m;
}

// yaml-cpp 0.7's LoadAll loops for ever, allocating, on a document that starts with ','
// (yaml-cpp issue #1040; the fuzzer found it, fuzz/regressions/deck/). The deck reader
// parses at most two documents, so these end with a message instead of a hang.
TEST_F(ScratchDeck, DocumentsThatStartWithACommaAreRejectedNotLoopedOn) {
  std::ofstream(deck(), std::ios::trunc) << ",\n";
  EXPECT_NE(rejection().find("must be a YAML mapping"), std::string::npos) << rejection();
  SetUp();
  std::ofstream(deck(), std::ios::app) << "---\n,\n";
  const std::string m = rejection();
  EXPECT_NE(m.find("a second YAML document (after '---')"), std::string::npos) << m;
}

TEST_F(ScratchDeck, OverridesAreAppliedAndBadOnesNamed) {
  const auto d = pistondyn::io::loadEngineDeck(deck(), {"drive.speed_rpm=3000"});
  EXPECT_DOUBLE_EQ(d.engine.drive.speed_radps, 3000 * M_PI / 30);
  EXPECT_NE(rejection({"drive.sped_rpm=3000"}).find("--set drive.sped_rpm: unknown key"),
            std::string::npos);
  EXPECT_NE(rejection({"geometry.bore_mm=-3"}).find("--set geometry.bore_mm: must be positive"),
            std::string::npos);
  EXPECT_NE(rejection({"geometry"}).find("expected key.path=value"), std::string::npos);
}

TEST_F(ScratchDeck, PressureTableWithBomAndUnderflowIsReadNanIsNot) {
  writeTable("\xEF\xBB\xBF" + readFile(kEngineDir + "/" + kTable));
  EXPECT_EQ(rejection(), "");
  writeTable("crank_angle_deg,pressure_bar\n0,1\n180,1e-400\n360,1\n540,1\n");
  EXPECT_NE(rejection().find(":3: pressure 1e-400 must be positive"), std::string::npos)
      << rejection();
  writeTable("crank_angle_deg,pressure_bar\nnan,1\n180,1\n360,1\n540,1\n");
  EXPECT_NE(rejection().find(":2: crank angle 'nan' is not a number"), std::string::npos)
      << rejection();
}

// A coarse table around a sharp peak makes the cubic spline undershoot below zero
// absolute pressure between knots: rejected, naming the interval.
TEST_F(ScratchDeck, PressureTableWhoseSplineUndershootsIsRejected) {
  std::string t = "crank_angle_deg,pressure_bar\n";
  for (int a = 0; a < 720; a += 30)
    t += std::to_string(a) + "," + (a == 360 ? "60" : "1") + "\n";
  writeTable(t);
  const std::string m = rejection();
  EXPECT_NE(m.find("the interpolated pressure falls to"), std::string::npos) << m;
  EXPECT_NE(m.find("too coarse"), std::string::npos) << m;
  // The curve's 0-based row is reported as the file's line (header on line 1: row r is on
  // line r + 2).
  const std::size_t at = m.find("between row ");
  ASSERT_NE(at, std::string::npos) << m;
  const int row = std::stoi(m.substr(at + 12));
  EXPECT_NE(m.find(":" + std::to_string(row + 2) + ": "), std::string::npos) << m;
}

// Inputs that used to crash, hang or be silently misread.
TEST_F(ScratchDeck, HostileInputsAreRejectedCleanly) {
  // a complex (list) key
  editDeck("engine:\n", "[a, b]: 1\nengine:\n");
  EXPECT_NE(rejection().find("keys must be plain names"), std::string::npos) << rejection();
  SetUp();
  // a duplicate section
  std::ofstream(deck(), std::ios::app) << "geometry:\n  bore_mm: 80\n";
  EXPECT_NE(rejection().find("duplicate key"), std::string::npos) << rejection();
  SetUp();
  EXPECT_NE(rejection({"geometry.bore_mm.=1"}).find("empty key in the path"), std::string::npos);
  EXPECT_NE(rejection({".=1"}).find("empty key in the path"), std::string::npos);
  EXPECT_NE(rejection({"simulation.cycles=4294967297"}).find("simulation.cycles: must be a whole"),
            std::string::npos);
  EXPECT_NE(rejection({"simulation.cycles=1e300"}).find("simulation.cycles: must be a whole"),
            std::string::npos);
  EXPECT_NE(rejection({"drive.speed_rpm=1e-10"}).find("drive.speed_rpm: must be between"),
            std::string::npos);
  EXPECT_NE(rejection({"simulation.output_step_deg=1e-7"}).find("simulation.output_step_deg"),
            std::string::npos);
  EXPECT_NE(rejection({"simulation.output_step_deg=0.7"}).find("must divide 720"),
            std::string::npos);
  EXPECT_NE(rejection({"simulation.start_angle_deg=1e12"}).find("simulation.start_angle_deg"),
            std::string::npos);
  // a section replaced by a value on the command line: one problem, named as the --set
  // (not one "missing key" per key of the section)
  EXPECT_EQ(rejection({"geometry=5"}),
            "--set geometry: 'geometry' is a section of the deck, not a value: set one of its "
            "keys (e.g. --set geometry.bore_mm=...)");
  // a key created by --set has no line number
  const std::string m = rejection({"foo.bar=1"});
  EXPECT_NE(m.find("--set foo.bar: unknown key"), std::string::npos) << m;
  EXPECT_EQ(m.find(":0:"), std::string::npos) << m;
}

// Checked before yaml-cpp opens it: yaml-cpp leaks when the stream of a folder fails
// (LeakSanitizer found it in this test).
TEST_F(ScratchDeck, DeckPathThatIsAFolderIsRejected) {
  try {
    pistondyn::io::loadEngineDeck(dir_.string(), {});
    ADD_FAILURE() << "accepted a folder as deck";
  } catch (const pistondyn::io::DeckError& e) {
    EXPECT_EQ(std::string(e.what()), dir_.string() + ": is a folder, not a deck file");
  }
}

// A pressure table that is a folder used to read as "empty table (no header line)".
TEST_F(ScratchDeck, PressureTableThatIsAFolderIsRejectedAsAFolder) {
  fs::create_directories(dir_ / "a_folder");
  const std::string m = rejection({"gas.cylinder_pressure_file=a_folder"});
  EXPECT_NE(m.find("--set gas.cylinder_pressure_file: '" + (dir_ / "a_folder").string() +
                   "' is a folder, not a file"),
            std::string::npos)
      << m;
}

}  // namespace
