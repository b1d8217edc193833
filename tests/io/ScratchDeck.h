#pragma once
// A scratch copy of the gasoline example engine's deck and table, edited per test
// (tests/io and tests/app). PISTONDYN_SOURCE_DIR (and, for runProgram(), PISTONDYN_EXE)
// come from the test's CMakeLists.txt.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/EngineDeck.h"

namespace pistondyn_test {

namespace fs = std::filesystem;

inline const std::string kEngineDir =
    std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/gasoline_1400_2000rpm";
inline const std::string kTable = "cylinder_pressure_fired_imep598kPa.csv";

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
    fs::copy_file(kEngineDir + "/engine.yaml", dir_ / "engine.yaml");
    fs::copy_file(kEngineDir + "/" + kTable, dir_ / kTable);
  }
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
  // Runs the real program; returns its exit code.
  int runProgram(const std::string& args, const fs::path& out) const {
    const std::string cmd =
        std::string(PISTONDYN_EXE) + " run " + deck() + " --out " + out.string() + " --quiet " +
        args + " > " + (dir_ / "stdout.txt").string() + " 2> " + (dir_ / "stderr.txt").string();
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string programStderr() const {
    return readFile(dir_ / "stderr.txt");
  }
#endif

  fs::path dir_;
};

// Message shape: "<file>:<line>: <key>: <problem>".
inline void expectNames(const std::string& msg, const std::string& file, int line,
                        const std::string& key, const std::string& problem) {
  EXPECT_NE(msg.find(file + ":" + std::to_string(line) + ": " + key), std::string::npos) << msg;
  EXPECT_NE(msg.find(problem), std::string::npos) << msg;
}

}  // namespace pistondyn_test
