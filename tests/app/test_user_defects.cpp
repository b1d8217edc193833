// The defects issue 13 lists as "found when the program was tried as a new user would",
// each through the real program: the deck reference generated from the key table (README
// holds it verbatim), help that needs no source tree, check running every validation run
// does, the summary's inputs under the deck's own key names and its deck file absolute,
// exact crank angles for a negative start, ignored input rejected, clear messages for
// hostile files, --out refused before anything is simulated, make_pressure_curve --help.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "NumericCsv.h"
#include "ScratchDeck.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

class UserDefects : public ScratchDeck {
 protected:
  using Result = ProgramRun;
  Result program(const std::string& args) const { return invokeInScratch(args); }
};

// README.md's deck reference is the program's `keys --markdown`, byte for byte.
TEST_F(UserDefects, ReadmeHoldsTheGeneratedDeckReference) {
  const Result r = program("keys --markdown");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string readme = readFile(fs::path(PISTONDYN_SOURCE_DIR) / "README.md");
  const std::string begin = r.out.substr(0, r.out.find('\n') + 1);
  const auto at = readme.find(begin);
  ASSERT_NE(at, std::string::npos) << "README.md has no generated deck reference";
  const std::string block = readme.substr(at, r.out.size());
  EXPECT_TRUE(block == r.out)
      << "README.md's deck reference differs from `pistondyn keys --markdown`: regenerate it "
         "with scripts/update-deck-reference.sh (or paste the program's output between the "
         "markers)";
  // The plain text lists the same keys with the limits the code enforces.
  const Result text = program("keys");
  for (const char* s : {"drive.speed_rpm  [rpm]  default —  [1, 50000]",
                        "simulation.cycles  [whole number]  default 1  1 … 1000",
                        "simulation.output_step_deg  [°]  default 1  [0.001, 720]",
                        "simulation.accuracy  [–]  default 1e-9  [1e-14, 0.01]",
                        "simulation.gravity_mps2  [m/s²]  default 9.80665  [0, 100]",
                        "simulation.start_angle_deg  [°]  default 0  [−720, 720]"})
    EXPECT_NE(text.out.find(s), std::string::npos) << s;
}

// An installed program has no source tree: no help text sends the user to README.md for
// the deck's keys; `pistondyn keys` is named instead.
TEST_F(UserDefects, HelpNamesTheKeysCommandNotTheReadme) {
  for (const char* c : {"--help", "run --help", "check --help", "keys --help"}) {
    const Result r = program(c);
    EXPECT_EQ(r.exitCode, 0) << c;
    EXPECT_EQ(r.out.find("README"), std::string::npos) << c << "\n" << r.out;
  }
  EXPECT_NE(program("--help").out.find("pistondyn keys"), std::string::npos);
  EXPECT_NE(program("run --help").out.find("`pistondyn keys`"), std::string::npos);
  EXPECT_NE(program("run --help").out.find("--quiet"), std::string::npos);
}

// `check` runs every validation `run` does: the same exit code and message, and run
// writes nothing.
TEST_F(UserDefects, CheckAndRunRejectTheSameDecksNamingTheKey) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--set gas.crankcase_pressure_bar=1e308", "--set gas.crankcase_pressure_bar: must be"},
      {"--set geometry.bore_mm=1e-300", "--set geometry.bore_mm: 1e-300 mm is outside"},
      {"--set geometry.bore_mm=0.0745", "given in m (0.0745 m = 74.5 mm)?"},
      {"--set piston.mass_g=0.21", "given in kg (0.21 kg = 210 g)?"},
      {"--set pin.inertia_kg_mm2=0", "--set pin.inertia_kg_mm2: must be positive"},
      {"--set pin.inertia_kg_mm2=1e-9", "--set pin.inertia_kg_mm2: 1e-09 kg_mm2 is outside"},
  };
  for (const auto& [args, expected] : cases) {
    const Result check = program("check engine.yaml " + args);
    EXPECT_EQ(check.exitCode, 1) << args;
    EXPECT_NE(check.err.find(expected), std::string::npos) << args << "\n" << check.err;
    EXPECT_EQ(check.out.find("nan"), std::string::npos) << check.out;
    const Result run = program("run engine.yaml --quiet --no-plot --out results " + args);
    EXPECT_EQ(run.exitCode, 1) << args;
    EXPECT_NE(run.err.find(expected), std::string::npos) << args << "\n" << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "results")) << args;
  }
  // A bore allowed as implausible whose imep cannot be computed: still bad input, named
  // (the pin on the axis: an offset of 0.5 mm would be outside a bore of 1e-300 mm).
  const Result nan = program(
      "check engine.yaml --set geometry.bore_mm=1e-300 --set geometry.pin_offset_mm=0 "
      "--set 'checks.allow_implausible=[geometry.bore_mm]'");
  EXPECT_EQ(nan.exitCode, 1);
  EXPECT_NE(nan.err.find("gas.cylinder_pressure_file: the imep of the pressure table cannot"),
            std::string::npos)
      << nan.err;
}

// summary.json: the deck file absolute, the inputs under the deck's own key names with the
// unit replaced by the SI one (nothing renamed), angles of a negative start exact and in
// [0, 720); cycle.csv's angles exactly start + k * step.
TEST_F(UserDefects, SummaryNamesInputsByTheDeckKeysAndAnglesAreExact) {
  ASSERT_EQ(program("run engine.yaml --quiet --no-plot --out results "
                    "--set simulation.start_angle_deg=-90 --set drive.mode=free "
                    "--set drive.flywheel_inertia_kg_m2=0.5 --set drive.load_torque_Nm=2")
                .exitCode,
            0)
      << readFile(dir_ / "stderr.txt");
  std::ifstream in(dir_ / "results" / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  EXPECT_EQ(s["deck_file"], fs::absolute(dir_ / "engine.yaml").lexically_normal().string());
  const nlohmann::json& i = s["inputs"];
  // The deck's values (gasoline example) converted by hand: one product each.
  EXPECT_EQ(i["geometry"]["bore_m"].get<double>(), 74.5 * 1e-3);
  EXPECT_EQ(i["geometry"]["stroke_m"].get<double>(), 80.0 * 1e-3);
  EXPECT_EQ(i["piston"]["mass_kg"].get<double>(), 210.0 * 1e-3);
  EXPECT_EQ(i["drive"]["speed_rad_per_s"].get<double>(), 2000.0 * (M_PI / 30.0));
  EXPECT_EQ(i["drive"]["load_torque_Nm"].get<double>(), 2.0);
  EXPECT_EQ(i["drive"]["flywheel_inertia_kg_m2"].get<double>(), 0.5);
  EXPECT_EQ(i["simulation"]["gravity_mps2"].get<double>(), 9.80665);
  EXPECT_EQ(i["simulation"]["start_angle_deg"].get<double>(), -90.0);
  EXPECT_EQ(i["simulation"]["cycles"], 1);
  EXPECT_TRUE(i["simulation"]["cycles"].is_number_integer());
  EXPECT_EQ(i["engine"]["name"].get<std::string>().rfind("Gasoline", 0), 0u);
  EXPECT_EQ(i["gas"]["cylinder_pressure_file"],
            fs::absolute(dir_ / kTable).lexically_normal().string());
  const std::string text = s.dump();
  for (const char* renamed :
       {"load_torque_N_m", "gravity_m_per_s2", "crank_radius_m", "engine_name", "liner_model"})
    EXPECT_EQ(text.find(renamed), std::string::npos) << renamed;
  for (const auto& [key, value] : s["results"].items()) {
    if (key.find("angle_deg") == std::string::npos)
      continue;
    const double a = value.get<double>();
    EXPECT_GE(a, 0.0) << key;
    EXPECT_LT(a, 720.0) << key;
    EXPECT_EQ(a, std::floor(a)) << key << " = " << a << " is not an output angle (step 1)";
  }
  const auto csv = pistondyn::test::readNumericCsv(dir_ / "results" / "cycle.csv");
  const auto angles = csv.column("crank_angle_deg");
  ASSERT_EQ(angles.size(), 721u);
  for (std::size_t k = 0; k < angles.size(); ++k)
    ASSERT_EQ(angles[k], -90.0 + static_cast<double>(k)) << k;
}

// Input that would be ignored is rejected, naming where it is.
TEST_F(UserDefects, IgnoredInputIsRejected) {
  std::ofstream(dir_ / "engine.yaml", std::ios::app) << "---\nengine: {name: second}\n";
  Result r = program("check engine.yaml");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("a second YAML document (after '---')"), std::string::npos) << r.err;
  std::ofstream(dir_ / "engine.yaml") << readFile(kEngineDir + "/engine.yaml");
  r = program("check engine.yaml --set drive.flywheel_inertia_kg_m2=0.5");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--set drive.flywheel_inertia_kg_m2: is read only with drive.mode: free"),
            std::string::npos)
      << r.err;
  r = program("check engine.yaml --set drive.mode=free --set drive.load_torque_Nm=-5");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--set drive.load_torque_Nm: must not be negative"), std::string::npos)
      << r.err;
}

// Hostile files and overrides get a message that says what is wrong.
TEST_F(UserDefects, MessagesNameTheRealProblem) {
  std::ofstream(dir_ / "deep.yaml") << "a: " << std::string(3000, '[') << "\n";
  Result r = program("check deep.yaml");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("deep.yaml:2: nested deeper than the YAML reader takes"), std::string::npos)
      << r.err;
  std::ofstream(dir_ / "nul.yaml", std::ios::binary)
      << std::string("engine:\n  name: \"a\0m\"\n", 22);
  r = program("check nul.yaml");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("nul.yaml:2: holds a NUL byte"), std::string::npos) << r.err;
  fs::create_directories(dir_ / "a_folder");
  r = program("check engine.yaml --set gas.cylinder_pressure_file=a_folder");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--set gas.cylinder_pressure_file: '"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("a_folder' is a folder, not a file"), std::string::npos) << r.err;
  r = program("check engine.yaml --set geometry=5");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--set geometry: 'geometry' is a section of the deck, not a value"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("missing key"), std::string::npos) << r.err;
}

// --out is refused before the deck is simulated (the run below would take seconds).
TEST_F(UserDefects, AnUnusableOutputFolderIsRefusedBeforeSimulating) {
  std::ofstream(dir_ / "a_file") << "keep";
  for (const char* out : {"a_file", "a_file/results"}) {
    const auto start = std::chrono::steady_clock::now();
    const Result r = program(std::string("run engine.yaml --quiet --no-plot --out ") + out +
                             " --set simulation.cycles=3");
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exitCode, 2) << out;
    EXPECT_NE(r.err.find("is a file, not a folder; nothing was simulated or written"),
              std::string::npos)
        << r.err;
    EXPECT_LT(s, 0.5 * 3.0) << "refused only after simulating?";
  }
  EXPECT_EQ(readFile(dir_ / "a_file"), "keep");
}

#ifdef PISTONDYN_MAKE_PRESSURE_CURVE
// The table generator a user makes a deck's pressure table with: --help, clear errors.
TEST_F(UserDefects, MakePressureCurveHasHelpAndNamesBadArguments) {
  auto tool = [&](const std::string& args) {
    const std::string cmd = std::string(PISTONDYN_MAKE_PRESSURE_CURVE) + " " + args + " > " +
                            (dir_ / "stdout.txt").string() + " 2> " +
                            (dir_ / "stderr.txt").string();
    const int status = std::system(cmd.c_str());
    return Result{WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(dir_ / "stdout.txt"),
                  readFile(dir_ / "stderr.txt")};
  };
  const Result help = tool("--help");
  EXPECT_EQ(help.exitCode, 0);
  for (const char* s : {"--bore-mm B", "[mm]", "--target-imep-kPa", "[kPa]", "(default 1.30)",
                        "firing TDC", "Exit codes"})
    EXPECT_NE(help.out.find(s), std::string::npos) << s;
  Result bad = tool("--bore-mm 74.5 --stroke-mm 80 --rod-mm 140 --cr 10");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--out FILE.csv is required"), std::string::npos) << bad.err;
  bad = tool("--bore-mm abc");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--bore-mm abc: not a number"), std::string::npos) << bad.err;
  bad = tool("--bores-mm 74.5");
  EXPECT_NE(bad.err.find("unknown option --bores-mm"), std::string::npos) << bad.err;
  // A motored table it writes is a table the deck reads (the gasoline geometry).
  const Result ok = tool("--bore-mm 74.5 --stroke-mm 80 --rod-mm 140 --cr 10 --out " +
                         (dir_ / "motored.csv").string());
  ASSERT_EQ(ok.exitCode, 0) << ok.err;
  EXPECT_EQ(program("check engine.yaml --set gas.cylinder_pressure_file=motored.csv "
                    "--set gas.stated_imep_kPa=null")
                .exitCode,
            0)
      << readFile(dir_ / "stderr.txt");
}
#endif

}  // namespace
