#pragma once
// A scratch folder and the built program (PISTONDYN_EXE) for the `pistondyn new` tests
// (test_new_program.cpp, test_new_deck_run.cpp).

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace pistondyn_test::new_deck {

namespace fs = std::filesystem;

inline std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every entry of `dir`, sorted ({} if it does not exist).
inline std::vector<std::string> listFolder(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  if (!fs::exists(dir, ec))
    return names;
  for (const auto& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The exit code, stdout and stderr of one run of the program.
struct Invocation {
  int exitCode;
  std::string out, err;
};

class NewDeckProgram : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() / ("pistondyn_new_" + std::to_string(::getpid()) + "_" + name);
    io_ = fs::temp_directory_path() / ("pistondyn_new_io_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir_);
    fs::remove_all(io_);
    fs::create_directories(dir_);
    fs::create_directories(io_);
  }
  void TearDown() override {
    fs::remove_all(dir_);
    fs::remove_all(io_);
  }
  // Runs `pistondyn <args>` (the shell splits `args`); its output is kept outside dir_ so
  // that dir_ holds only what the program wrote.
  Invocation invoke(const std::string& args) const {
    const std::string cmd = std::string(PISTONDYN_EXE) + " " + args + " > " +
                            (io_ / "out.txt").string() + " 2> " + (io_ / "err.txt").string();
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(io_ / "out.txt"),
            readFile(io_ / "err.txt")};
  }
  fs::path dir_, io_;
};

}  // namespace pistondyn_test::new_deck
