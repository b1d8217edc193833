// The pistondyn program (app/): exit codes, messages and files at process level.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <unistd.h>

#include "ScratchDeck.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

// Process level: exit code 1, a message naming the key, and no result files.
TEST_F(ScratchDeck, ProgramRejectsBadInputWithoutWritingAnything) {
  editDeck("bore_mm: 74.5", "bore_mm: -74.5");
  const fs::path out = dir_ / "results";
  EXPECT_EQ(runProgram("", out), 1);
  EXPECT_NE(programStderr().find("geometry.bore_mm: must be positive"), std::string::npos)
      << programStderr();
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(ScratchDeck, ProgramUsageErrorsExitWithTwo) {
  const std::string cmd = std::string(PISTONDYN_EXE) + " run " + deck() + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 2);  // no --out
}

// Process level, good deck: required columns with units, TDC convention stated,
// summary.json with SI inputs, imep and wall time; --set reaches the run.
TEST_F(ScratchDeck, ProgramWritesCycleAndSummary) {
  const fs::path out = dir_ / "results";
  ASSERT_EQ(runProgram("--set simulation.output_step_deg=2 --set drive.speed_rpm=2500", out), 0)
      << programStderr();
  const std::string csv = readFile(out / "cycle.csv");
  EXPECT_NE(csv.find("crank angle 0 deg = firing TDC"), std::string::npos);
  for (const char* col : {"crank_angle_deg", "piston_y_m", "piston_vy_mps", "piston_ay_mps2",
                          "gas_force_N", "side_force_N", "conrod_force_N", "crank_torque_Nm"}) {
    EXPECT_TRUE(std::regex_search(csv, std::regex(std::string("(^|\n|,)") + col + "(,|\n)")))
        << col;
  }
  const YAML::Node summary = YAML::LoadFile((out / "summary.json").string());
  EXPECT_NEAR(summary["inputs"]["drive"]["speed_rad_per_s"].as<double>(), 2500 * M_PI / 30, 1e-9);
  EXPECT_NEAR(summary["inputs"]["geometry"]["bore_m"].as<double>(), 0.0745, 1e-15);
  EXPECT_NEAR(summary["results"]["imep_kPa"].as<double>(), 598.0, 0.005 * 598.0);
  EXPECT_GT(summary["wall_time_s"].as<double>(), 0.0);
  EXPECT_NE(summary["crank_angle_convention"].as<std::string>().find("firing TDC"),
            std::string::npos);
  EXPECT_EQ(summary["overrides"].size(), 2u);
  // No temporary files left next to the results.
  for (const auto& entry : fs::directory_iterator(out)) {
    EXPECT_TRUE(entry.path().filename() == "cycle.csv" ||
                entry.path().filename() == "summary.json" ||
                entry.path().filename() == "warm_start.json")
        << entry.path();
  }
}

TEST_F(ScratchDeck, ProgramRefusesAnOutputPathThatIsAFileBeforeSimulating) {
  const fs::path out = dir_ / "a_file";
  std::ofstream(out) << "keep me";
  EXPECT_EQ(runProgram("", out), 2);
  EXPECT_NE(programStderr().find("is a file, not a folder"), std::string::npos) << programStderr();
  EXPECT_EQ(readFile(out), "keep me");
}

// Runs the program with `args`; returns the exit code, stdout and stderr.
struct Invocation {
  int exitCode;
  std::string out, err;
};
Invocation invoke(const std::string& args) {
  const fs::path dir = fs::temp_directory_path() / ("pistondyn_app_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string cmd = std::string(PISTONDYN_EXE) + " " + args + " > " +
                          (dir / "out.txt").string() + " 2> " + (dir / "err.txt").string();
  const int status = std::system(cmd.c_str());
  Invocation r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(dir / "out.txt"),
               readFile(dir / "err.txt")};
  fs::remove_all(dir);
  return r;
}

TEST(Program, HelpAndVersionExitZero) {
  const Invocation help = invoke("--help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("run"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("check"), std::string::npos) << help.out;
  EXPECT_EQ(invoke("-h").exitCode, 0);
  const Invocation version = invoke("--version");
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_EQ(version.out, std::string("pistondyn ") + PISTONDYN_VERSION + "\n");
}

// Each subcommand's --help names its options, the units of deck keys and the defaults.
TEST(Program, SubcommandHelpNamesOptionsUnitsAndDefaults) {
  const Invocation run = invoke("run --help");
  EXPECT_EQ(run.exitCode, 0);
  for (const char* text :
       {"--out", "--set", "--quiet", "DECK", "speed_rpm", "bore_mm", "output_step_deg 1",
        "cycles 1", "rk_merson", "ideal_guide", "firing TDC", "Exit codes"}) {
    EXPECT_NE(run.out.find(text), std::string::npos) << text << "\n" << run.out;
  }
  const Invocation check = invoke("check --help");
  EXPECT_EQ(check.exitCode, 0);
  EXPECT_NE(check.out.find("--set"), std::string::npos) << check.out;
  EXPECT_EQ(check.out.find("--out"), std::string::npos) << check.out;
}

TEST(Program, CommandLineErrorsExitWithTwo) {
  const std::string deck =
      std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/briggs_stratton_500/engine.yaml";
  for (const std::string& args : std::vector<std::string>{
           "", "frobnicate " + deck, "run", "check", "run " + deck + " --out",
           "run " + deck + " --out x --bogus", "run " + deck + " --out x --set",
           "check " + deck + " extra.yaml", "--bogus"}) {
    const Invocation r = invoke(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("usage: pistondyn"), std::string::npos) << args << "\n" << r.err;
  }
}

TEST_F(ScratchDeck, CheckExitsZeroForAGoodDeckAndOneForABadOne) {
  Invocation r = invoke("check " + deck() + " --set drive.speed_rpm=2500");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("is valid"), std::string::npos) << r.out;
  r = invoke("check " + deck() + " --set liner.model=no_such_liner");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--set liner.model: 'no_such_liner' is not one of: ideal_guide"),
            std::string::npos)
      << r.err;
}

// A simulation that fails part-way (a free crank stalled by its load): exit 3, and the
// output folder keeps exactly what it had.
TEST_F(ScratchDeck, ProgramRunThatFailsExitsWithThreeAndWritesNothing) {
  const fs::path out = dir_ / "results";
  fs::create_directories(out);
  std::ofstream(out / "cycle.csv") << "old cycle";
  EXPECT_EQ(runProgram("--set drive.mode=free --set drive.speed_rpm=300 "
                       "--set drive.flywheel_inertia_kg_m2=0.001 --set drive.load_torque_Nm=200",
                       out),
            3)
      << programStderr();
  EXPECT_NE(programStderr().find("the run failed; no results were written"), std::string::npos)
      << programStderr();
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(out))
    names.push_back(e.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"cycle.csv"});
  EXPECT_EQ(readFile(out / "cycle.csv"), "old cycle");
  const fs::path fresh = dir_ / "fresh";
  EXPECT_EQ(runProgram("--set drive.mode=free --set drive.speed_rpm=300 "
                       "--set drive.flywheel_inertia_kg_m2=0.001 --set drive.load_torque_Nm=200",
                       fresh),
            3);
  EXPECT_FALSE(fs::exists(fresh));
}

}  // namespace
