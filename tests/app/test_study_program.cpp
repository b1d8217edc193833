// `pistondyn study`: a sweep deck's cases run as `sweep` runs them, then compared in
// comparison.csv / comparison.md (each figure against the case's own summary.json, read
// here independently) and in comparison figures (real PNGs of the stated size, one per
// quantity the cases have); a failing case is listed, the others compared; `sweep` draws
// the same figures. On the ideal-guide scratch deck at a 5 deg output step (a case takes
// a second).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "PlotChecks.h"
#include "ScratchDeck.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

const char* kStudy =
    "name: scratch study\n"
    "base_deck: engine.yaml\n"
    "set:\n"
    "  simulation.output_step_deg: 5\n"
    "cases:\n"
    "  - {drive.speed_rpm: 1500}\n"
    "  - {drive.speed_rpm: 3000}\n";
// Passes every check, then stalls in the run (a free crank against its load).
const char* kStallingCase =
    "  - {drive.mode: free, drive.speed_rpm: 300, drive.flywheel_inertia_kg_m2: 0.001, "
    "drive.load_torque_Nm: 200}\n";

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::string cell(std::size_t row, const std::string& column) const {
    for (std::size_t j = 0; j < header.size(); ++j) {
      if (header[j] == column)
        return j < rows.at(row).size() ? rows[row][j] : "";
    }
    throw std::out_of_range(column);
  }
};

// comparison.csv without its '#' lines (fields split at commas; a quoted message last).
Table readComparison(const fs::path& p) {
  Table t;
  std::istringstream in(readFile(p));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#')
      continue;
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (const char c : line) {
      if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted) {
        cells.push_back(cell);
        cell.clear();
      } else
        cell += c;
    }
    cells.push_back(cell);
    (t.header.empty() ? t.header : t.rows.emplace_back()) = cells;
  }
  return t;
}

nlohmann::json readJson(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

class StudyProgram : public ScratchDeck {
 protected:
  int program(const std::string& args) const { return invokeInScratch(args).exitCode; }
  std::string out() const { return readFile(dir_ / "stdout.txt"); }
  std::string err() const { return readFile(dir_ / "stderr.txt"); }
};

TEST_F(StudyProgram, ComparesItsCasesInTablesAndFigures) {
  std::ofstream(dir_ / "study.yaml") << kStudy;
  ASSERT_EQ(program("study study.yaml --out results --quiet --jobs 2"), 0) << err();
  const fs::path r = dir_ / "results";
  for (const char* f : {"sweep.json", "sweep.csv", "case_0001/summary.json", "case_0002/cycle.csv",
                        "comparison.csv", "comparison.md"})
    EXPECT_TRUE(fs::is_regular_file(r / f)) << f;
  EXPECT_NE(out().find("comparison.csv"), std::string::npos) << out();

  // Every figure of the table is the case's summary.json figure, as written there.
  const Table t = readComparison(r / "comparison.csv");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.header.front(), "case");
  EXPECT_EQ(t.header[1], "drive.speed_rpm");
  EXPECT_EQ(t.header.back(), "message");
  for (std::size_t i = 0; i < 2; ++i) {
    const nlohmann::json res =
        readJson(r / ("case_000" + std::to_string(i + 1)) / "summary.json")["results"];
    EXPECT_EQ(t.cell(i, "case"), std::to_string(i + 1));
    EXPECT_EQ(t.cell(i, "drive.speed_rpm"), i == 0 ? "1500" : "3000");
    EXPECT_EQ(t.cell(i, "status"), "ok");
    int compared = 0;
    for (std::size_t j = 3; j + 1 < t.header.size(); ++j) {
      const std::string& key = t.header[j];
      if (!res.contains(key) || res[key].is_null()) {
        // The ideal guide has no film figures; a run that did not converge no
        // cycles_to_converge.
        EXPECT_EQ(t.rows[i][j], "") << key;
        continue;
      }
      if (res[key].is_boolean())
        EXPECT_EQ(t.rows[i][j], res[key].dump()) << key;
      else
        EXPECT_EQ(std::strtod(t.rows[i][j].c_str(), nullptr), res[key].get<double>()) << key;
      ++compared;
    }
    // The ideal guide's: side_force_max_N, converged (cycles_to_converge is null).
    EXPECT_EQ(compared, 2) << "figures of the ideal guide";
    EXPECT_EQ(t.cell(i, "converged"), "false");
    // The Markdown row: the case, its speed, ok and the side force to 4 digits.
    char side[32];
    std::snprintf(side, sizeof side, "%.4g", res["side_force_max_N"].get<double>());
    const std::string md = readFile(r / "comparison.md");
    const std::string row =
        "| " + std::to_string(i + 1) + " | " + (i == 0 ? "1500" : "3000") + " | ok |";
    const auto at = md.find(row);
    ASSERT_NE(at, std::string::npos) << md;
    EXPECT_NE(md.substr(at, md.find('\n', at) - at).find(std::string("| ") + side + " |"),
              std::string::npos)
        << md;
  }
  EXPECT_NE(readFile(r / "comparison.md").find("# scratch study"), std::string::npos);

  // The figures the ideal guide has: the side force, one panel, a curve per case (legend
  // "case N: speed_rpm=..." fits the 36-character margin: 900 + 8 x 36 px wide).
  EXPECT_EQ(listPngs(r / "plots"), std::vector<std::string>{"comparison_side_force.png"});
  const PngSize size = readPngSize(r / "plots" / "comparison_side_force.png");
  EXPECT_EQ(size.width, 1188);
  EXPECT_EQ(size.height, 470);

  // comparison.html (issue 37): the cases side by side, a column per case with its
  // headline in engineering units - the peak cylinder pressure in bar (from its Pa here),
  // no number in exponent form, the run not checked for periodicity "not converged" - the
  // figures embedded as the files hold them, rendered in Chromium without a script error.
  const std::string page = readFile(r / "comparison.html");
  const std::size_t tableAt = page.find("<table class=\"cases\" id=\"cases\">");
  ASSERT_NE(tableAt, std::string::npos) << page.substr(0, 2000);
  const std::string table = page.substr(tableAt, page.find("</table>", tableAt) - tableAt);
  EXPECT_NE(table.find("speed_rpm=1500"), std::string::npos) << table;
  EXPECT_NE(table.find("speed_rpm=3000"), std::string::npos) << table;
  EXPECT_EQ(table.find("e+"), std::string::npos) << table;
  for (int i = 1; i <= 2; ++i) {
    const nlohmann::json res = readJson(r / ("case_000" + std::to_string(i)) / "summary.json")["results"];
    char bar[32];
    std::snprintf(bar, sizeof bar, "%.1f", res["peak_cylinder_pressure_Pa"].get<double>() / 1e5);
    // 10 ... 100 bar: 3 significant digits are one decimal.
    ASSERT_GE(res["peak_cylinder_pressure_Pa"].get<double>(), 1e6);
    ASSERT_LT(res["peak_cylinder_pressure_Pa"].get<double>(), 1e7);
    EXPECT_NE(table.find(std::string("<td class=\"num\">") + bar + " bar at "), std::string::npos)
        << bar << "\n" << table;
    EXPECT_TRUE(res["cycles_to_converge"].is_null());
  }
  EXPECT_NE(table.find("<tr><th>periodic</th><td class=\"num\">not converged ("),
            std::string::npos)
      << table;
  checkReportEmbedsThePlots(page, r / "plots");
  renderInChromium(r / "comparison.html", 1, {}, false);

  // A sweep draws them too; --no-plot does not.
  ASSERT_EQ(program("sweep study.yaml --out swept --quiet"), 0) << err();
  EXPECT_EQ(listPngs(dir_ / "swept" / "plots"),
            std::vector<std::string>{"comparison_side_force.png"});
  ASSERT_EQ(program("sweep study.yaml --out bare --quiet --no-plot"), 0) << err();
  EXPECT_FALSE(fs::exists(dir_ / "bare" / "plots"));
  EXPECT_TRUE(fs::is_regular_file(dir_ / "swept" / "comparison.html"));
  EXPECT_FALSE(fs::exists(dir_ / "bare" / "comparison.html"));
}

TEST_F(StudyProgram, AFailedCaseIsListedAndTheOthersCompared) {
  std::ofstream(dir_ / "study.yaml") << std::string(kStudy) + kStallingCase;
  ASSERT_EQ(program("study study.yaml --out results --quiet --jobs 2"), 4) << err();
  const Table t = readComparison(dir_ / "results" / "comparison.csv");
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.cell(0, "status"), "ok");
  EXPECT_EQ(t.cell(2, "status"), "failed");
  EXPECT_EQ(t.cell(2, "side_force_max_N"), "");
  EXPECT_FALSE(t.cell(2, "message").empty());
  EXPECT_NE(readFile(dir_ / "results" / "comparison.md").find("| 3 |"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "results" / "plots" / "comparison_side_force.png"));
}

TEST_F(StudyProgram, BadInputAndABadOutputFolderWriteNothing) {
  std::ofstream(dir_ / "study.yaml")
      << "base_deck: engine.yaml\ncases:\n  - {drive.speed_rpm: 0}\n";
  EXPECT_EQ(program("study study.yaml --out results"), 1);
  EXPECT_NE(err().find("drive.speed_rpm"), std::string::npos) << err();
  EXPECT_FALSE(fs::exists(dir_ / "results"));
  std::ofstream(dir_ / "study.yaml") << kStudy;
  std::ofstream(dir_ / "a_file") << "x";
  EXPECT_EQ(program("study study.yaml --out a_file"), 2);
  EXPECT_NE(err().find("is a file, not a folder"), std::string::npos) << err();
  EXPECT_EQ(program("study --help"), 0);
  for (const char* s : {"comparison.csv", "comparison.md", "fmep_kPa", "h/sigma", "(mrad)",
                        "firing TDC", "Exit codes"})
    EXPECT_NE(out().find(s), std::string::npos) << s;
}

}  // namespace
