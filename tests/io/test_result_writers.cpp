// Result writers: numbers round-trip doubles, files are written all-or-nothing.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>


#include "ScratchDeck.h"
#include "pistondyn/io/ResultWriters.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

// Results are written with the shortest text that reads back to the same double.
TEST(ResultWriters, NumbersRoundTrip) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const double x = unit(rng) * std::pow(10.0, static_cast<int>(rng() % 40) - 20);
    EXPECT_EQ(std::strtod(pistondyn::io::formatNumber(x).c_str(), nullptr), x);
  }
  // A metre-valued position keeps sub-nanometre resolution.
  const double y = 0.179999305554216;
  EXPECT_EQ(std::strtod(pistondyn::io::formatNumber(y + 3e-13).c_str(), nullptr), y + 3e-13);
}

// All-or-nothing: if any file cannot be placed, the folder is left exactly as it was
// (old results intact, no new or temporary files), whichever file fails.
TEST(ResultWriters, AtomicWriteLeavesTheFolderAsItWasOnFailure) {
  const fs::path dir =
      fs::temp_directory_path() / ("pistondyn_atomic_" + std::to_string(::getpid()));
  for (const char* blocked : {"cycle.csv", "summary.json"}) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "cycle.csv") << "old cycle";
    std::ofstream(dir / "summary.json") << "old summary";
    fs::remove(dir / blocked);
    fs::create_directories(dir / blocked);  // a folder where a result file must go
    EXPECT_THROW(pistondyn::io::writeFilesAtomically(
                     dir.string(), {{"cycle.csv", "new cycle"}, {"summary.json", "new summary"}}),
                 std::runtime_error);
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
      names.push_back(e.path().filename());
    EXPECT_EQ(names.size(), 2u) << blocked;
    EXPECT_TRUE(fs::is_directory(dir / blocked));
    const std::string other = std::string(blocked) == "cycle.csv" ? "summary.json" : "cycle.csv";
    EXPECT_EQ(readFile(dir / other), other == "cycle.csv" ? "old cycle" : "old summary") << blocked;
  }
  // And the success path replaces old results.
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "cycle.csv") << "old cycle";
  pistondyn::io::writeFilesAtomically(dir.string(), {{"cycle.csv", "new"}, {"summary.json", "s"}});
  EXPECT_EQ(readFile(dir / "cycle.csv"), "new");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
  fs::remove_all(dir);
}

}  // namespace
