#pragma once
// A scratch copy of the gasoline example engine's deck and tables, edited per test
// (tests/io and tests/app). PISTONDYN_SOURCE_DIR (and, for runProgram(), PISTONDYN_EXE)
// come from the test's CMakeLists.txt.
//
// ScratchDeck: the engine on the ideal guide - the deck's liner and simulation sections
// replaced by `liner: model: ideal_guide` and one cycle with rk_merson (kIdealGuideLiner,
// kIdealGuideSimulation), the deck the deck-machinery tests were written for; a run takes a
// second. SkirtScratchDeck: the example deck as it is (the lubricated skirt).

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/EngineDeck.h"

namespace pistondyn_test {

namespace fs = std::filesystem;

inline const std::string kEngineDir =
    std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/gasoline_1400_2000rpm";
inline const std::string kTable = "cylinder_pressure_fired_imep598kPa.csv";
inline const std::string kProfileTable = "skirt_profile.csv";

inline const std::string kIdealGuideLiner = "liner:\n  model: ideal_guide\n\n";
inline const std::string kIdealGuideSimulation =
    "simulation:\n"
    "  start_angle_deg: 0\n"
    "  cycles: 1\n"
    "  output_step_deg: 1.0\n"
    "  integrator: rk_merson\n"
    "  accuracy: 1.0e-9\n"
    "  gravity_mps2: 9.80665\n";

// `text` with its top-level section `name` (from the line "name:" to the next line that
// starts a top-level key, or the end) replaced by `section`.
inline std::string replaceSection(const std::string& text, const std::string& name,
                                  const std::string& section) {
  const std::string head = name + ":\n";
  const std::size_t begin = text.rfind("\n" + head) != std::string::npos
                                ? text.rfind("\n" + head) + 1
                                : (text.rfind(head, 0) == 0 ? 0 : std::string::npos);
  if (begin == std::string::npos)
    throw std::invalid_argument("replaceSection: no section '" + name + "'");
  std::size_t end = begin + head.size();
  while (end < text.size()) {
    const std::size_t next = text.find('\n', end);
    const char c = text[end];
    if (c != ' ' && c != '#' && c != '\n')
      break;
    end = next == std::string::npos ? text.size() : next + 1;
  }
  return text.substr(0, begin) + section + text.substr(end);
}

inline std::string readFile(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A scratch copy of the gasoline engine's deck and table, edited per test.
class ScratchDeck : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pistondyn_io_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // The deck and every table beside it (pressure, skirt profile, temperatures).
    fs::copy_file(kEngineDir + "/engine.yaml", dir_ / "engine.yaml");
    for (const auto& entry : fs::directory_iterator(kEngineDir)) {
      if (entry.path().extension() == ".csv")
        fs::copy_file(entry.path(), dir_ / entry.path().filename());
    }
    if (!keepsTheExampleLiner()) {
      std::string text = readFile(deck());
      text = replaceSection(text, "liner", kIdealGuideLiner);
      text = replaceSection(text, "simulation", kIdealGuideSimulation);
      std::ofstream(deck()) << text;
    }
  }
  // SkirtScratchDeck keeps the example's lubricated skirt.
  virtual bool keepsTheExampleLiner() const { return false; }
  void TearDown() override { fs::remove_all(dir_); }

  std::string deck() const { return (dir_ / "engine.yaml").string(); }
  // Replace the first occurrence of `from` in the deck (the edit must apply).
  void editDeck(const std::string& from, const std::string& to) {
    std::string text = readFile(deck());
    const auto pos = text.find(from);
    ASSERT_NE(pos, std::string::npos) << from;
    text.replace(pos, from.size(), to);
    std::ofstream(deck()) << text;
  }
  void writeTable(const std::string& text) { std::ofstream(dir_ / kTable) << text; }
  // Writes a file beside the deck (e.g. a skirt table the deck names).
  void writeFile(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  int lineOf(const std::string& needle) const {
    std::ifstream in(deck());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      if (line.find(needle) != std::string::npos)
        return n;
    }
    return -1;
  }
  // The DeckError message of loading the deck ("" if it loads).
  std::string rejection(const std::vector<std::string>& overrides = {}) const {
    try {
      pistondyn::io::loadEngineDeck(deck(), overrides);
    } catch (const pistondyn::io::DeckError& e) {
      return e.what();
    }
    return "";
  }
#ifdef PISTONDYN_EXE
  // Runs the real program (no progress line, no plots: tests/app/test_plots_report.cpp
  // checks those); returns its exit code.
  int runProgram(const std::string& args, const fs::path& out) const {
    const std::string cmd =
        std::string(PISTONDYN_EXE) + " run " + deck() + " --out " + out.string() +
        " --quiet --no-plot " + args + " > " + (dir_ / "stdout.txt").string() + " 2> " + (dir_ / "stderr.txt").string();
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string programStderr() const {
    return readFile(dir_ / "stderr.txt");
  }
  // `pistondyn <args>` run in the scratch folder (relative paths start there): the exit
  // code and what it printed.
  struct ProgramRun {
    int exitCode;
    std::string out, err;
  };
  ProgramRun invokeInScratch(const std::string& args) const {
    const std::string cmd = "cd " + dir_.string() + " && " + PISTONDYN_EXE + " " + args + " > " +
                            (dir_ / "stdout.txt").string() + " 2> " +
                            (dir_ / "stderr.txt").string();
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(dir_ / "stdout.txt"),
            readFile(dir_ / "stderr.txt")};
  }
#endif

  fs::path dir_;
};

// The example deck as it is: the lubricated skirt.
class SkirtScratchDeck : public ScratchDeck {
 protected:
  bool keepsTheExampleLiner() const override { return true; }
};

// Message shape: "<file>:<line>: <key>: <problem>".
inline void expectNames(const std::string& msg, const std::string& file, int line,
                        const std::string& key, const std::string& problem) {
  EXPECT_NE(msg.find(file + ":" + std::to_string(line) + ": " + key), std::string::npos) << msg;
  EXPECT_NE(msg.find(problem), std::string::npos) << msg;
}

}  // namespace pistondyn_test
