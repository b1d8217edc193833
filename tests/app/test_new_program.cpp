// `pistondyn new` through the built program: a deck from a drawing that `check` passes,
// estimates that follow the documented rules as the bore changes (README.md, "A deck from
// a drawing"), bad option values refused naming the option with nothing written.
// (The short run of such a deck: test_new_deck_run.cpp.)

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "NewDeckProgram.h"

namespace {

namespace fs = std::filesystem;
using namespace pistondyn_test::new_deck;

TEST_F(NewDeckProgram, NewThenCheckPasses) {
  const Invocation made = invoke("new " + (dir_ / "engine_a").string() +
                                 " --bore-mm 81 --stroke-mm 86.4 --speed-rpm 2500 --imep-kPa 700");
  ASSERT_EQ(made.exitCode, 0) << made.err;
  EXPECT_NE(made.out.find("values estimated"), std::string::npos) << made.out;
  EXPECT_EQ(made.err, "");
  const Invocation check = invoke("check " + (dir_ / "engine_a" / "engine.yaml").string());
  EXPECT_EQ(check.exitCode, 0) << check.err;
  EXPECT_NE(check.out.find("is valid (imep from its pressure table: 70"), std::string::npos)
      << check.out;
  // The engine is named after the folder, the values given are in the deck as given.
  const YAML::Node deck = YAML::LoadFile((dir_ / "engine_a" / "engine.yaml").string());
  EXPECT_EQ(deck["engine"]["name"].as<std::string>(), "engine_a");
  EXPECT_DOUBLE_EQ(deck["geometry"]["bore_mm"].as<double>(), 81.0);
  EXPECT_DOUBLE_EQ(deck["drive"]["speed_rpm"].as<double>(), 2500.0);
  EXPECT_DOUBLE_EQ(deck["gas"]["stated_imep_kPa"].as<double>(), 700.0);
  // --help documents the command.
  const Invocation help = invoke("new --help");
  EXPECT_EQ(help.exitCode, 0);
  for (const char* text : {"--bore-mm", "--stroke-mm", "--rod-mm", "--speed-rpm", "--imep-kPa",
                           "--pressure-table", "--motored", "--type", "EST"})
    EXPECT_NE(help.out.find(text), std::string::npos) << text;
}

// The gasoline rules (README.md): skirt length 0.40 x bore to 0.1 mm, running radial clearance
// 0.13 per mille of the bore to 1 um; a larger bore gets the larger skirt and clearance.
TEST_F(NewDeckProgram, EstimatesScaleWithTheBoreByTheDocumentedRule) {
  std::vector<double> skirt_mm, clearance_um;
  for (const double bore_mm : {72.0, 96.0}) {
    const fs::path folder = dir_ / ("bore_" + std::to_string(static_cast<int>(bore_mm)));
    std::ostringstream args;
    args << "new " << folder.string() << " --bore-mm " << bore_mm << " --stroke-mm 84";
    const Invocation made = invoke(args.str());
    ASSERT_EQ(made.exitCode, 0) << made.err;
    const YAML::Node deck = YAML::LoadFile((folder / "engine.yaml").string());
    skirt_mm.push_back(deck["piston"]["skirt_length_mm"].as<double>());
    clearance_um.push_back(deck["liner"]["cold_radial_clearance_um"].as<double>());
    EXPECT_NEAR(skirt_mm.back(), 0.40 * bore_mm, 0.05 + 1e-9) << bore_mm;
    EXPECT_NEAR(clearance_um.back(), 0.13 * bore_mm, 0.5 + 1e-9) << bore_mm;
    // The rule is stated beside the value.
    const std::string text = readFile(folder / "engine.yaml");
    EXPECT_NE(text.find("EST: skirt length 0.4 x bore"), std::string::npos);
    EXPECT_NE(text.find("EST: 0.13 per mille of the bore"), std::string::npos);
  }
  EXPECT_GT(skirt_mm[1], skirt_mm[0]);
  EXPECT_GT(clearance_um[1], clearance_um[0]);
}

// Each bad value: a non-zero exit, a message naming the option and what it expects,
// nothing written (not the folder, nothing temporary beside it).
TEST_F(NewDeckProgram, ABadOptionValueFailsNamingTheOptionAndWritesNothing) {
  const std::string folder = (dir_ / "bad").string();
  struct Case {
    std::string args, expected;
  };
  for (const Case& c : {
           Case{"--bore-mm -80 --stroke-mm 80", "--bore-mm -80 mm: the bore must be positive"},
           Case{"--bore-mm abc --stroke-mm 80", "--bore-mm"},
           Case{"--bore-mm 0.08 --stroke-mm 80", "--bore-mm 0.08 mm: implausible"},
           Case{"--bore-mm 80 --stroke-mm 80 --rod-mm 60", "--rod-mm 60 is too short"},
           Case{"--bore-mm 80 --stroke-mm 80 --speed-rpm 20000", "--speed-rpm 20000"},
           Case{"--bore-mm 80 --stroke-mm 80 --imep-kPa 0", "--imep-kPa 0 kPa"},
           Case{"--bore-mm 80 --stroke-mm 80 --type truck", "--type"},
           Case{"--bore-mm 80 --stroke-mm 80 --imep-kPa 600 --motored", "--imep-kPa"},
           Case{"--stroke-mm 80", "--bore-mm"},
       }) {
    const Invocation r = invoke("new " + folder + " " + c.args);
    EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(folder)) << c.args;
    EXPECT_EQ(listFolder(dir_), std::vector<std::string>{}) << c.args;
  }
  // A pressure table that is not one: bad input (1), the file named.
  std::ofstream(dir_ / "table.csv") << "crank_angle_deg,pressure_bar\n0,1\n";
  const Invocation table = invoke("new " + folder + " --bore-mm 80 --stroke-mm 80 " +
                                  "--pressure-table " + (dir_ / "table.csv").string());
  EXPECT_EQ(table.exitCode, 1) << table.err;
  EXPECT_NE(table.err.find("--pressure-table"), std::string::npos) << table.err;
  EXPECT_FALSE(fs::exists(folder));
}

// An existing folder that is not empty is refused (exit 2) and left as it was.
TEST_F(NewDeckProgram, AFolderThatIsNotEmptyIsRefusedAndLeftAsItWas) {
  const fs::path folder = dir_ / "taken";
  fs::create_directories(folder);
  std::ofstream(folder / "notes.txt") << "keep me";
  const Invocation r = invoke("new " + folder.string() + " --bore-mm 80 --stroke-mm 80");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("not empty"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nothing was written"), std::string::npos) << r.err;
  EXPECT_EQ(listFolder(folder), std::vector<std::string>{"notes.txt"});
  EXPECT_EQ(readFile(folder / "notes.txt"), "keep me");
  EXPECT_EQ(listFolder(dir_), std::vector<std::string>{"taken"});
}

#ifdef PISTONDYN_MAKE_PRESSURE_CURVE
// The lines of a CSV that are not comments.
std::string withoutComments(const std::string& text) {
  std::istringstream in(text);
  std::string line, kept;
  while (std::getline(in, line)) {
    if (line.rfind('#', 0) != 0)
      kept += line + "\n";
  }
  return kept;
}

// The generated table's header names the make_pressure_curve command that makes the same
// table (the deck says so): the installed generator run with it writes the same knots.
TEST_F(NewDeckProgram, TheGeneratedTablesHeaderCommandMakesTheSameTable) {
  const fs::path folder = dir_ / "diesel";
  const Invocation made =
      invoke("new " + folder.string() + " --type diesel --bore-mm 84 --stroke-mm 90 --imep-kPa 900");
  ASSERT_EQ(made.exitCode, 0) << made.err;
  const fs::path table = folder / "cylinder_pressure_fired_imep900kPa.csv";
  const std::string text = readFile(table);
  const std::string lead = "# the same table: make_pressure_curve ";
  const std::size_t at = text.find(lead);
  ASSERT_NE(at, std::string::npos) << text.substr(0, 400);
  std::string args = text.substr(at + lead.size(), text.find('\n', at) - at - lead.size());
  const std::string out = "--out FILE.csv";
  ASSERT_NE(args.find(out), std::string::npos) << args;
  args.replace(args.find(out), out.size(), "--out " + (io_ / "again.csv").string());
  const std::string cmd = std::string(PISTONDYN_MAKE_PRESSURE_CURVE) + " " + args + " > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  EXPECT_EQ(withoutComments(readFile(io_ / "again.csv")), withoutComments(text));
}
#endif

}  // namespace
