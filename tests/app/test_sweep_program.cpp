// `pistondyn sweep` at process level: sweep.csv with one row per case, a failing case
// (exit 4, the others finish), every case equal to the same case run alone with
// `pistondyn run --set ...`, resume (complete cases kept, half-finished and foreign case
// folders rerun, another sweep's folder refused), bad sweep input (exit 1, file:line and
// key, nothing written) and, when MPI was found, the same sweep under mpirun.
//
// The cases run the scratch engine on the ideal guide (ScratchDeck: rk_merson, one cycle),
// about a second each; the sweep deck coarsens the output step.

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

#include <nlohmann/json.hpp>

#include "ScratchDeck.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

// ---- reading what the program wrote ----------------------------------------------------

// One CSV record (RFC 4180 quoting, as sweep.csv writes a message).
std::vector<std::string> splitCsvLine(const std::string& line) {
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

// A CSV file without its '#' lines: the header and the rows, each row as header -> cell.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
};

Csv readCsv(const fs::path& p) {
  Csv csv;
  std::istringstream in(readFile(p));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    const auto cells = splitCsvLine(line);
    if (csv.header.empty()) {
      csv.header = cells;
      continue;
    }
    EXPECT_EQ(cells.size(), csv.header.size()) << p << ": " << line;
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < cells.size() && i < csv.header.size(); ++i)
      row[csv.header[i]] = cells[i];
    csv.rows.push_back(row);
  }
  return csv;
}

// |a - b| <= 1e-12 max(|a|, |b|), exact zero included; a non-number never passes.
bool sameNumber(double a, double b) {
  return std::isfinite(a) && std::isfinite(b) &&
         std::fabs(a - b) <= 1e-12 * std::max(std::fabs(a), std::fabs(b));
}

double toNumber(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return (end != text.c_str() && *end == '\0') ? v : std::nan("");
}

// Two cycle.csv files hold the same columns and the same numbers to 1e-12 relative.
void expectSameCycle(const fs::path& a, const fs::path& b) {
  const Csv x = readCsv(a), y = readCsv(b);
  ASSERT_EQ(x.header, y.header) << a << " vs " << b;
  ASSERT_EQ(x.rows.size(), y.rows.size()) << a << " vs " << b;
  ASSERT_GT(x.rows.size(), 10u);
  int cells = 0;
  for (std::size_t r = 0; r < x.rows.size(); ++r) {
    for (const auto& col : x.header) {
      const double u = toNumber(x.rows[r].at(col)), v = toNumber(y.rows[r].at(col));
      ASSERT_TRUE(sameNumber(u, v)) << a << " row " << r << " " << col << ": "
                                    << x.rows[r].at(col) << " vs " << y.rows[r].at(col);
      ++cells;
    }
  }
  EXPECT_GT(cells, 100);
}

nlohmann::json readJson(const fs::path& p) {
  return nlohmann::json::parse(readFile(p));
}

// A figure under "results" that measures the run, not the engine.
bool isTiming(const std::string& key) {
  return key == "wall_time_s";
}

// Every number under "results" of two summary.json files agrees to 1e-12 relative (but
// the wall time).
void expectSameResults(const nlohmann::json& a, const nlohmann::json& b) {
  ASSERT_TRUE(a.at("results").is_object());
  int figures = 0;
  for (const auto& [key, value] : a.at("results").items()) {
    if (!value.is_number() || isTiming(key))
      continue;
    ASSERT_TRUE(b.at("results").contains(key)) << key;
    EXPECT_TRUE(sameNumber(value.get<double>(), b["results"][key].get<double>()))
        << key << ": " << value << " vs " << b["results"][key];
    ++figures;
  }
  EXPECT_GT(figures, 5);
}

struct Invocation {
  int exitCode;
  std::string out, err;
};

// ---- the fixture ------------------------------------------------------------------------

// Two good cases and, optionally, one that passes every check and then fails in the run
// (a free crank stalled by its load: the run ends with an exception, as in test_app.cpp).
const char* kSweepHead =
    "name: scratch sweep\n"
    "base_deck: engine.yaml\n"
    "set:\n"
    "  simulation.output_step_deg: 10\n"
    "cases:\n"
    "  - {geometry.pin_offset_mm: -0.5, drive.speed_rpm: 1500}\n"
    "  - {geometry.pin_offset_mm: 0.8, drive.speed_rpm: 3000}\n";
const char* kFailingCase =
    "  - {drive.mode: free, drive.speed_rpm: 300, drive.flywheel_inertia_kg_m2: 0.001, "
    "drive.load_torque_Nm: 200}\n";

class SweepProgram : public ScratchDeck {
 protected:
  std::string writeSweep(const std::string& text, const std::string& name = "sweep.yaml") {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  // `pistondyn <args>` with stdout and stderr captured, run in the scratch folder.
  Invocation invoke(const std::string& args, const std::string& launcher = "") const {
    const std::string cmd = "cd " + dir_.string() + " && " + launcher +
                            (launcher.empty() ? "" : " ") + std::string(PISTONDYN_EXE) + " " +
                            args + " > " + (dir_ / "stdout.txt").string() + " 2> " +
                            (dir_ / "stderr.txt").string();
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(dir_ / "stdout.txt"),
            readFile(dir_ / "stderr.txt")};
  }
  static long modificationTime_ns(const fs::path& p) {
    struct stat s {};
    if (::stat(p.c_str(), &s) != 0)
      return -1;
    return s.st_mtim.tv_sec * 1000000000L + s.st_mtim.tv_nsec;
  }
};

TEST_F(SweepProgram, OneRowPerCaseAndAFailingCaseExitsFourWhileTheOthersFinish) {
  writeSweep(std::string(kSweepHead) + kFailingCase);
  const Invocation r = invoke("sweep sweep.yaml --out results --jobs 2 --quiet");
  EXPECT_EQ(r.exitCode, 4) << r.out << r.err;
  EXPECT_NE(r.out.find("3 cases: 2 ok, 1 failed"), std::string::npos) << r.out;
  const Csv csv = readCsv(dir_ / "results" / "sweep.csv");
  ASSERT_EQ(csv.rows.size(), 3u);
  // Columns: case, the swept keys in deck order, status, the figures, run figures, message.
  ASSERT_GE(csv.header.size(), 8u);
  EXPECT_EQ(std::vector<std::string>(csv.header.begin(), csv.header.begin() + 8),
            (std::vector<std::string>{"case", "geometry.pin_offset_mm", "drive.speed_rpm",
                                      "drive.mode", "drive.flywheel_inertia_kg_m2",
                                      "drive.load_torque_Nm", "status", csv.header[7]}));
  EXPECT_EQ(csv.header.back(), "message");
  // One column per name; the run's true/false figure is there too.
  EXPECT_EQ(std::set<std::string>(csv.header.begin(), csv.header.end()).size(),
            csv.header.size());
  EXPECT_EQ(csv.rows[0].at("converged"), "false");  // one cycle, until_periodic off
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(csv.rows[static_cast<std::size_t>(i)].at("case"), std::to_string(i + 1));
  EXPECT_EQ(csv.rows[0].at("geometry.pin_offset_mm"), "-0.5");
  EXPECT_EQ(csv.rows[1].at("drive.speed_rpm"), "3000");
  EXPECT_EQ(csv.rows[2].at("geometry.pin_offset_mm"), "");  // the case does not set it
  EXPECT_EQ(csv.rows[0].at("status"), "ok");
  EXPECT_EQ(csv.rows[1].at("status"), "ok");
  EXPECT_EQ(csv.rows[2].at("status"), "failed");
  EXPECT_FALSE(csv.rows[2].at("message").empty());
  EXPECT_EQ(csv.rows[0].at("message"), "");
  // The good cases' figures are there, the failed case has none (and nothing is nan).
  EXPECT_GT(toNumber(csv.rows[0].at("imep_kPa")), 500.0);
  EXPECT_EQ(csv.rows[2].at("imep_kPa"), "");
  EXPECT_EQ(readFile(dir_ / "results" / "sweep.csv").find("nan"), std::string::npos);
  // Run folders of the good cases, none of the failed one.
  for (const char* c : {"case_0001", "case_0002"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / "results" / c / "cycle.csv")) << c;
    EXPECT_TRUE(fs::is_regular_file(dir_ / "results" / c / "summary.json")) << c;
    EXPECT_TRUE(fs::is_regular_file(dir_ / "results" / c / "case.json")) << c;
  }
  EXPECT_FALSE(fs::exists(dir_ / "results" / "case_0003"));
}

// The independent check of the sweep's bookkeeping: each case of the sweep gives the
// numbers of the same deck and overrides run alone, and sweep.csv copies its summary.
TEST_F(SweepProgram, EachCaseEqualsTheSameCaseRunAlone) {
  writeSweep(kSweepHead);
  ASSERT_EQ(invoke("sweep sweep.yaml --out results --jobs 2 --quiet").exitCode, 0)
      << readFile(dir_ / "stderr.txt");
  const std::vector<std::string> alone = {
      "--set simulation.output_step_deg=10 --set geometry.pin_offset_mm=-0.5 "
      "--set drive.speed_rpm=1500",
      "--set simulation.output_step_deg=10 --set geometry.pin_offset_mm=0.8 "
      "--set drive.speed_rpm=3000"};
  const Csv csv = readCsv(dir_ / "results" / "sweep.csv");
  ASSERT_EQ(csv.rows.size(), 2u);
  for (std::size_t i = 0; i < alone.size(); ++i) {
    SCOPED_TRACE(i + 1);
    const fs::path single = dir_ / ("alone_" + std::to_string(i + 1));
    ASSERT_EQ(invoke("run engine.yaml --quiet --out " + single.string() + " " + alone[i]).exitCode,
              0)
        << readFile(dir_ / "stderr.txt");
    const fs::path inSweep = dir_ / "results" / (i == 0 ? "case_0001" : "case_0002");
    expectSameCycle(inSweep / "cycle.csv", single / "cycle.csv");
    const auto a = readJson(inSweep / "summary.json");
    const auto b = readJson(single / "summary.json");
    expectSameResults(a, b);
    // The two cases differ (the check above could not pass by comparing a case with itself).
    EXPECT_NE(b["inputs"]["drive"]["speed_rad_per_s"].get<double>(),
              i == 0 ? 3000 * M_PI / 30 : 1500 * M_PI / 30);
    // sweep.csv: every figure of the run alone, in its column.
    int columns = 0;
    for (const auto& [key, value] : b.at("results").items()) {
      if (!value.is_number() || isTiming(key))
        continue;
      ASSERT_TRUE(csv.rows[i].count(key)) << key;
      EXPECT_TRUE(sameNumber(toNumber(csv.rows[i].at(key)), value.get<double>()))
          << key << ": " << csv.rows[i].at(key) << " vs " << value;
      ++columns;
    }
    EXPECT_GT(columns, 5);
  }
  // The two cases' results differ from each other.
  EXPECT_NE(csv.rows[0].at("side_force_max_N"), csv.rows[1].at("side_force_max_N"));
}

TEST_F(SweepProgram, ResumeKeepsCompleteCasesAndRerunsHalfFinishedAndForeignOnes) {
  writeSweep(kSweepHead);
  ASSERT_EQ(invoke("sweep sweep.yaml --out results --quiet").exitCode, 0);
  const fs::path out = dir_ / "results";
  const std::string first = readFile(out / "case_0001" / "summary.json");
  const long t1 = modificationTime_ns(out / "case_0001" / "summary.json");
  const long t2 = modificationTime_ns(out / "case_0002" / "summary.json");
  ASSERT_GT(t1, 0);

  // Nothing to do: both cases found complete by their fingerprint, neither rerun.
  Invocation r = invoke("sweep sweep.yaml --out results");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("2 complete from an earlier run, 0 run now"), std::string::npos) << r.out;
  EXPECT_EQ(modificationTime_ns(out / "case_0001" / "summary.json"), t1);
  EXPECT_EQ(modificationTime_ns(out / "case_0002" / "summary.json"), t2);
  EXPECT_EQ(readCsv(out / "sweep.csv").rows.size(), 2u);

  // Case 2 interrupted before it was marked complete (no case.json): rerun, case 1 kept.
  fs::remove(out / "case_0002" / "case.json");
  r = invoke("sweep sweep.yaml --out results");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("1 half-finished, rerun"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("1 complete from an earlier run, 1 run now"), std::string::npos) << r.out;
  EXPECT_EQ(modificationTime_ns(out / "case_0001" / "summary.json"), t1);
  EXPECT_NE(modificationTime_ns(out / "case_0002" / "summary.json"), t2);
  EXPECT_TRUE(fs::is_regular_file(out / "case_0002" / "case.json"));

  // A case folder marked with another sweep's fingerprint (copied in from elsewhere) is
  // not this sweep's result: rerun.
  {
    auto marker = readJson(out / "case_0001" / "case.json");
    std::string fp = marker.at("sweep_fingerprint").get<std::string>();
    fp[0] = fp[0] == '0' ? '1' : '0';
    marker["sweep_fingerprint"] = fp;
    std::ofstream(out / "case_0001" / "case.json") << marker.dump(2);
  }
  r = invoke("sweep sweep.yaml --out results");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("1 complete from an earlier run, 1 run now"), std::string::npos) << r.out;
  EXPECT_NE(modificationTime_ns(out / "case_0001" / "summary.json"), t1);
  EXPECT_EQ(readFile(out / "case_0001" / "summary.json").size() > 0, true);
  expectSameResults(readJson(out / "case_0001" / "summary.json"), nlohmann::json::parse(first));

  // A changed sweep (one case's value) into the same folder: refused, nothing touched.
  const std::string before = readFile(out / "sweep.csv");
  std::string changed = kSweepHead;
  changed.replace(changed.find("0.8"), 3, "0.9");
  writeSweep(changed);
  r = invoke("sweep sweep.yaml --out results");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("holds the results of a different sweep"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("case 2's overrides differ"), std::string::npos) << r.err;
  EXPECT_EQ(readFile(out / "sweep.csv"), before);
  // The same for a changed base deck.
  writeSweep(kSweepHead);
  editDeck("mass_g: 210.0", "mass_g: 211.0");
  r = invoke("sweep sweep.yaml --out results");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("the base deck's content differs"), std::string::npos) << r.err;
  EXPECT_EQ(readFile(out / "sweep.csv"), before);
}

TEST_F(SweepProgram, BadSweepInputExitsOneNamingFileLineAndKeyAndWritesNothing) {
  writeSweep(std::string(kSweepHead) + "  - {geometry.pin_ofset_mm: 0.2}\n");
  const Invocation r = invoke("sweep sweep.yaml --out results");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("sweep.yaml:8: cases[3].geometry.pin_ofset_mm: case 3 "
                       "(geometry.pin_ofset_mm=0.2): unknown key"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "results"));
  // Zero Latin-hypercube samples; an output folder that is not a sweep's.
  writeSweep(
      "base_deck: engine.yaml\nlatin_hypercube:\n  samples: 0\n  ranges:\n"
      "    drive.speed_rpm: [1500, 3000]\n",
      "lhs.yaml");
  const Invocation z = invoke("sweep lhs.yaml --out results");
  EXPECT_EQ(z.exitCode, 1);
  EXPECT_NE(z.err.find("lhs.yaml:3: latin_hypercube.samples:"), std::string::npos) << z.err;
  EXPECT_FALSE(fs::exists(dir_ / "results"));
  writeSweep(kSweepHead);
  fs::create_directories(dir_ / "other");
  std::ofstream(dir_ / "other" / "notes.txt") << "mine";
  const Invocation o = invoke("sweep sweep.yaml --out other");
  EXPECT_EQ(o.exitCode, 2);
  EXPECT_NE(o.err.find("holds no sweep.json"), std::string::npos) << o.err;
  EXPECT_EQ(fs::directory_iterator(dir_ / "other")->path().filename(), "notes.txt");
  EXPECT_FALSE(fs::exists(dir_ / "other" / "sweep.json"));
}

TEST_F(SweepProgram, ListPrintsTheCasesAndRunsNothing) {
  writeSweep(kSweepHead);
  const Invocation r = invoke("sweep sweep.yaml --list");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "case,geometry.pin_offset_mm,drive.speed_rpm\n1,-0.5,1500\n2,0.8,3000\n");
}

TEST_F(SweepProgram, HelpNamesTheOptionsDefaultsAndExitCodes) {
  const Invocation r = invoke("sweep --help");
  EXPECT_EQ(r.exitCode, 0);
  for (const char* text : {"SWEEP.yaml", "--out", "--jobs", "--set", "--list", "--quiet",
                           "default: the cores", "mpirun -np K", "Exit codes", "4 some cases"}) {
    EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
  }
  // --out is required unless --list: a usage error, nothing written.
  writeSweep(kSweepHead);
  EXPECT_EQ(invoke("sweep sweep.yaml").exitCode, 2);
}

#ifdef PISTONDYN_MPIEXEC
// The same sweep across two MPI ranks: the same sweep.csv as the threaded run (but for
// the wall time) and the same case folders.
TEST_F(SweepProgram, MpiRunEqualsTheThreadedRun) {
  writeSweep(std::string(kSweepHead) + kFailingCase +
             "  - {geometry.pin_offset_mm: 0.2, drive.speed_rpm: 2000}\n");
  const Invocation threads = invoke("sweep sweep.yaml --out threaded --jobs 2 --quiet");
  ASSERT_EQ(threads.exitCode, 4) << threads.err;
  const Invocation mpi = invoke("sweep sweep.yaml --out mpi --quiet",
                                std::string(PISTONDYN_MPIEXEC) +
                                    " -n 2 --oversubscribe --allow-run-as-root");
  ASSERT_EQ(mpi.exitCode, 4) << mpi.out << mpi.err;
  std::vector<std::string> a, b;
  for (const auto& [dir, lines] : {std::pair{"threaded", &a}, std::pair{"mpi", &b}}) {
    const Csv csv = readCsv(dir_ / dir / "sweep.csv");
    lines->push_back([&] {
      std::string h;
      for (const auto& c : csv.header)
        h += c + ",";
      return h;
    }());
    for (const auto& row : csv.rows) {
      std::string line;
      for (const auto& c : csv.header)
        line += (c == "wall_time_s" ? std::string("-") : row.at(c)) + ",";
      lines->push_back(line);
    }
  }
  ASSERT_EQ(a.size(), 5u);
  EXPECT_EQ(a, b);
  for (const char* c : {"case_0001", "case_0002", "case_0004"})
    expectSameCycle(dir_ / "threaded" / c / "cycle.csv", dir_ / "mpi" / c / "cycle.csv");
  EXPECT_FALSE(fs::exists(dir_ / "mpi" / "case_0003"));
}
#endif

}  // namespace
