#pragma once
// The design loop's commands through the program with the analytic test liner
// (AnalyticProgram.cpp): a scratch copy of the gasoline deck whose liner is `analytic_test`
// (closed-form fmep, h/sigma and signal; tests/support/AnalyticTestLiner.h) and whose run is
// one coarse rk_merson cycle (about 0.1 s).

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "ScratchDeck.h"

namespace pistondyn_test {

struct Invocation {
  int exitCode;
  std::string out, err;
};

// One CSV record (RFC 4180 quoting).
inline std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cells.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

struct CsvRows {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  double number(std::size_t row, const std::string& column) const {
    const std::string& t = rows.at(row).at(column);
    return t.empty() ? std::nan("") : std::stod(t);
  }
};

inline CsvRows readCsvRows(const fs::path& p) {
  CsvRows csv;
  std::istringstream in(readFile(p));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    const auto cells = splitCsv(line);
    if (csv.header.empty()) {
      csv.header = cells;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < cells.size() && i < csv.header.size(); ++i)
      row[csv.header[i]] = cells[i];
    csv.rows.push_back(row);
  }
  return csv;
}

inline const char* kAnalyticLiner =
    "liner:\n"
    "  model: analytic_test\n"
    "  clearance_um: 40\n\n";
inline const char* kAnalyticSimulation =
    "simulation:\n"
    "  cycles: 1\n"
    "  output_step_deg: 10\n"
    "  integrator: rk_merson\n"
    "  accuracy: 1.0e-6\n";

class DesignProgram : public ScratchDeck {
 protected:
  void SetUp() override {
    ScratchDeck::SetUp();
    std::string text = readFile(deck());
    text = replaceSection(text, "liner", kAnalyticLiner);
    text = replaceSection(text, "simulation", kAnalyticSimulation);
    std::ofstream(deck()) << text;
  }
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }
  Invocation invoke(const std::string& args, const std::string& launcher = "") const {
    const std::string cmd = "cd " + dir_.string() + " && " + launcher +
                            (launcher.empty() ? "" : " ") + std::string(PISTONDYN_EXE) + " " +
                            args + " > " + (dir_ / "stdout.txt").string() + " 2> " +
                            (dir_ / "stderr.txt").string();
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(dir_ / "stdout.txt"),
            readFile(dir_ / "stderr.txt")};
  }
  // Every file below `p` (relative), for "nothing was written" checks.
  std::set<std::string> listFiles() const {
    std::set<std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(dir_)) {
      const std::string rel = fs::relative(e.path(), dir_).string();
      if (rel != "stdout.txt" && rel != "stderr.txt")
        out.insert(rel);
    }
    return out;
  }
};

}  // namespace pistondyn_test
