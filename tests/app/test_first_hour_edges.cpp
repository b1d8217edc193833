// The edges issue 37 found when the program was tried as a new user would, each through
// the built program: two runs into one folder, SIGINT / SIGTERM during run, plot and sweep,
// a Matrix Market header that claims a huge matrix, a newline in the deck's path, result
// folders that are not what plot and report expect, and the messages of a stalled free
// crank, a stated imep of 0, an --out that cannot be written and a huge --set value.
//
// Processes that must overlap are made to: the first is stopped (SIGSTOP) as soon as it
// has started writing, the second runs or the signal is sent, then the first continues
// (SIGCONT). No test depends on how fast anything runs.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "ScratchDeck.h"

extern char** environ;

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

// The ideal guide for several cycles at a fine output step: seconds of simulation, long
// enough to be stopped while it writes.
const std::string kLongIdealRun =
    "--set simulation.cycles=6 --set simulation.output_step_deg=0.25 --quiet --no-plot";

// Process helpers over a scratch folder (both fixtures below).
struct Processes {
  fs::path dir;
  // Starts `/bin/sh -c "exec <command>"` (the shell replaced by the command: the pid is the
  // program's) with stdout and stderr to <tag>.out and <tag>.err in `dir`; returns the pid.
  pid_t start(const std::string& command, const std::string& tag) const {
    const std::string script = "exec " + command + " > " + (dir / (tag + ".out")).string() +
                               " 2> " + (dir / (tag + ".err")).string();
    std::vector<char*> argv{const_cast<char*>("/bin/sh"), const_cast<char*>("-c"),
                            const_cast<char*>(script.c_str()), nullptr};
    pid_t pid = 0;
    EXPECT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, argv.data(), environ), 0);
    return pid;
  }
  // The exit code, or 1000 + signal if the process was killed by one.
  static int finish(pid_t pid) {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
  }
  // Waits (without a deadline: ctest's timeout ends a hang) until `path` exists and holds at
  // least `bytes` bytes, or the process has ended (then false).
  static bool waitFor(const fs::path& path, pid_t pid, std::uintmax_t bytes = 1) {
    for (;;) {
      std::error_code ec;
      if (fs::exists(path, ec) && fs::file_size(path, ec) >= bytes && !ec)
        return true;
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid)
        return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  std::string output(const std::string& tag, const char* stream = "err") const {
    return readFile(dir / (tag + "." + stream));
  }
};

// Every entry under `dir` (files and folders), relative names, sorted.
std::vector<std::string> listTree(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  if (!fs::exists(dir, ec))
    return names;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    names.push_back(fs::relative(e.path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

class FirstHourEdges : public ScratchDeck {
 protected:
  void SetUp() override {
    ScratchDeck::SetUp();
    procs_.dir = dir_;
  }
  pid_t start(const std::string& command, const std::string& tag) const {
    return procs_.start(command, tag);
  }
  static int finish(pid_t pid) { return Processes::finish(pid); }
  static bool waitFor(const fs::path& path, pid_t pid, std::uintmax_t bytes = 1) {
    return Processes::waitFor(path, pid, bytes);
  }
  std::string output(const std::string& tag) const { return procs_.output(tag); }
  std::string runCommand(const fs::path& out, const std::string& args) const {
    return std::string(PISTONDYN_EXE) + " run " + deck() + " --out " + out.string() + " " + args;
  }
  Processes procs_;
};

// A whole cycle.csv: comment lines, one header, rows of as many fields as the header, the
// crank angle advancing by one output step per row from 0. Returns the row count.
long expectWholeCycleCsv(const fs::path& path, double step_deg) {
  std::ifstream in(path);
  std::string line;
  std::size_t fields = 0;
  long rows = 0;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0) {
      EXPECT_EQ(fields, 0u) << "a comment line after the header: " << line;
      continue;
    }
    const std::size_t n = static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
    if (fields == 0) {
      EXPECT_EQ(line.rfind("time_s,crank_angle_deg,", 0), 0u) << line;
      fields = n;
      continue;
    }
    EXPECT_EQ(n, fields) << "row " << rows << ": " << line;
    const std::size_t a = line.find(',') + 1;
    EXPECT_DOUBLE_EQ(std::stod(line.substr(a, line.find(',', a) - a)),
                     static_cast<double>(rows) * step_deg)
        << "row " << rows;
    ++rows;
  }
  return rows;
}

// Two runs into one --out at once: the second is refused (exit 2, before simulating), the
// first's files are whole and its own; the lock is gone afterwards.
TEST_F(FirstHourEdges, TwoRunsIntoOneFolderNeverMix) {
  const fs::path out = dir_ / "results";
  const pid_t first = start(runCommand(out, kLongIdealRun), "first");
  ASSERT_TRUE(waitFor(out / ".cycle.csv.partial", first, 20000)) << output("first");
  ::kill(first, SIGSTOP);  // it holds the folder and is mid-run
  const pid_t second =
      start(runCommand(out, kLongIdealRun + " --set drive.speed_rpm=3000"), "second");
  const int secondCode = finish(second);
  ::kill(first, SIGCONT);
  EXPECT_EQ(secondCode, 2) << output("second");
  EXPECT_NE(output("second").find("is in use by another pistondyn process"), std::string::npos)
      << output("second");
  EXPECT_NE(output("second").find("nothing was simulated or written"), std::string::npos);
  ASSERT_EQ(finish(first), 0) << output("first");
  EXPECT_EQ(expectWholeCycleCsv(out / "cycle.csv", 0.25), 6 * 2880 + 1);
  // The first run's own speed (the refused one asked for 3000 rpm).
  const auto summary = nlohmann::json::parse(readFile(out / "summary.json"));
  EXPECT_NEAR(summary["inputs"]["drive"]["speed_rad_per_s"].get<double>(), 2000 * M_PI / 30, 1e-9);
  EXPECT_EQ(listTree(out),
            (std::vector<std::string>{"cycle.csv", "summary.json", "warm_start.json"}));
}

// SIGINT and SIGTERM during a run into a new folder: exit 130 / 143, and nothing the run
// created is left (no partial file, no lock, not the folder nor its new parent).
TEST_F(FirstHourEdges, SignalDuringRunLeavesNothing) {
  for (const int signal : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(signal);
    const fs::path parent = dir_ / "new_parent";
    const pid_t run = start(runCommand(parent / "results", kLongIdealRun), "run");
    ASSERT_TRUE(waitFor(parent / "results" / ".cycle.csv.partial", run, 20000)) << output("run");
    ::kill(run, SIGSTOP);
    ::kill(run, signal);  // delivered when it continues
    ::kill(run, SIGCONT);
    EXPECT_EQ(finish(run), 128 + signal) << output("run");
    EXPECT_NE(
        output("run").find(signal == SIGINT ? "interrupted by SIGINT" : "interrupted by SIGTERM"),
        std::string::npos)
        << output("run");
    EXPECT_FALSE(fs::exists(parent)) << "left: " << ::testing::PrintToString(listTree(parent));
  }
}

// The same into a folder holding an earlier run: the earlier results stay as they were.
TEST_F(FirstHourEdges, SignalDuringRunKeepsEarlierResults) {
  const fs::path out = dir_ / "results";
  ASSERT_EQ(runProgram("", out), 0) << programStderr();
  const std::string csv = readFile(out / "cycle.csv"), json = readFile(out / "summary.json");
  const pid_t run = start(runCommand(out, kLongIdealRun), "run");
  ASSERT_TRUE(waitFor(out / ".cycle.csv.partial", run, 20000)) << output("run");
  ::kill(run, SIGSTOP);
  ::kill(run, SIGINT);
  ::kill(run, SIGCONT);
  EXPECT_EQ(finish(run), 130) << output("run");
  EXPECT_EQ(listTree(out),
            (std::vector<std::string>{"cycle.csv", "summary.json", "warm_start.json"}));
  EXPECT_EQ(readFile(out / "cycle.csv"), csv);
  EXPECT_EQ(readFile(out / "summary.json"), json);
}

// SIGINT / SIGTERM while gnuplot draws: gnuplot is ended, no staged figure, no temporary
// folder, the earlier figures as they were. A stand-in gnuplot writes the figures the
// script names (as gnuplot starts to) and then takes its time.
TEST_F(FirstHourEdges, SignalDuringPlotLeavesNoPartialFigureOrTemporaryFolder) {
  const fs::path out = dir_ / "results";
  ASSERT_EQ(runProgram("", out), 0) << programStderr();
  fs::create_directories(out / "plots");
  std::ofstream(out / "plots" / "side_force.png") << "earlier figure";
  const fs::path tmp = dir_ / "tmp";
  fs::create_directories(tmp);
  const fs::path gnuplot = dir_ / "slow_gnuplot.sh";
  std::ofstream(gnuplot) << "#!/bin/sh\n"
                            "grep -o 'set output \"[^\"]*\"' \"$1\" | sed 's/set output \"//; "
                            "s/\"$//' | while read f; do echo partial > \"$f\"; done\n"
                            ": > \"$(dirname \"$1\")/started\"\n"
                            "exec sleep 600\n";
  fs::permissions(gnuplot, fs::perms::owner_all);
  for (const std::string command : {"plot", "report"}) {
    for (const int signal : {SIGINT, SIGTERM}) {
      SCOPED_TRACE(command + " " + std::to_string(signal));
      const pid_t plot =
          start("env TMPDIR=" + tmp.string() + " PISTONDYN_GNUPLOT=" + gnuplot.string() + " " +
                    PISTONDYN_EXE + " " + command + " " + out.string(),
                "plot");
      // The stand-in has started: the staged figures exist.
      for (bool started = false; !started;) {
        for (const auto& e : fs::directory_iterator(tmp))
          started = started || fs::exists(e.path() / "started");
        int status = 0;
        ASSERT_NE(::waitpid(plot, &status, WNOHANG), plot) << output("plot");
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      ::kill(plot, signal);
      EXPECT_EQ(finish(plot), 128 + signal) << output("plot");
      EXPECT_EQ(listTree(out),
                (std::vector<std::string>{"cycle.csv", "plots", "plots/side_force.png",
                                          "summary.json", "warm_start.json"}));
      EXPECT_EQ(readFile(out / "plots" / "side_force.png"), "earlier figure");
      EXPECT_TRUE(listTree(tmp).empty()) << ::testing::PrintToString(listTree(tmp));
    }
  }
}

// SIGINT during a sweep: the running case's folder is removed, sweep.json stays (the sweep
// resumes), exit 130.
TEST_F(FirstHourEdges, SignalDuringSweepRemovesTheRunningCase) {
  std::ofstream(dir_ / "sweep.yaml") << "base_deck: engine.yaml\n"
                                        "set:\n  simulation.cycles: 6\n"
                                        "  simulation.output_step_deg: 0.25\n"
                                        "cartesian:\n  drive.speed_rpm: [2000, 3000]\n";
  const fs::path out = dir_ / "sweep";
  const pid_t sweep =
      start(std::string(PISTONDYN_EXE) + " sweep " + (dir_ / "sweep.yaml").string() + " --out " +
                out.string() + " --jobs 1 --quiet --no-plot",
            "sweep");
  ASSERT_TRUE(waitFor(out / "case_0001" / ".cycle.csv.partial", sweep, 20000)) << output("sweep");
  ::kill(sweep, SIGSTOP);
  ::kill(sweep, SIGINT);
  ::kill(sweep, SIGCONT);
  EXPECT_EQ(finish(sweep), 130) << output("sweep");
  const auto left = listTree(out);
  EXPECT_TRUE(std::find(left.begin(), left.end(), "sweep.json") != left.end());
  for (const auto& name : left) {
    EXPECT_EQ(name.find("case_"), std::string::npos) << name;
    EXPECT_EQ(name.find(".partial"), std::string::npos) << name;
  }
}

}  // namespace

// plot and report refuse a folder whose summary.json or cycle.csv is not as run writes
// it - naming the file and what is wrong, exit 1, nothing written - instead of drawing
// without the figure that needs the missing piece.
TEST_F(FirstHourEdges, PlotAndReportRefuseAMalformedResultFolder) {
  const fs::path good = dir_ / "good";
  ASSERT_EQ(runProgram("", good), 0) << programStderr();
  const std::string summary = readFile(good / "summary.json"), csv = readFile(good / "cycle.csv");
  // cycle.csv without one column (header and rows).
  auto withoutColumn = [&](const std::string& column) {
    std::istringstream in(csv);
    std::string line, out;
    std::size_t drop = std::string::npos;
    while (std::getline(in, line)) {
      if (line.rfind("#", 0) != 0) {
        std::vector<std::string> fields;
        std::stringstream ss(line);
        for (std::string f; std::getline(ss, f, ',');)
          fields.push_back(f);
        if (drop == std::string::npos)
          drop = static_cast<std::size_t>(std::find(fields.begin(), fields.end(), column) -
                                          fields.begin());
        fields.erase(fields.begin() + static_cast<long>(drop));
        line.clear();
        for (const auto& f : fields)
          line += (line.empty() ? "" : ",") + f;
      }
      out += line + "\n";
    }
    return out;
  };
  auto json = nlohmann::json::parse(summary);
  json["results"]["imep_kPa"] = "598 kPa";
  struct Case {
    std::string name, file, text, expected;
  };
  const std::vector<Case> cases = {
      {"summary.json is []", "summary.json", "[]",
       "summary.json: expected a JSON object, found an array"},
      {"summary.json without results", "summary.json", R"({"inputs": {}})",
       "summary.json: no \"results\" object"},
      {"text where a number belongs", "summary.json", json.dump(2),
       "summary.json: results.imep_kPa: expected a number, found the text \"598 kPa\""},
      {"cycle.csv without the conrod force", "cycle.csv", withoutColumn("conrod_force_N"),
       "cycle.csv: no column conrod_force_<unit>, which the figure crank_train_forces.png"},
      {"cycle.csv without the ideal guide's moment", "cycle.csv", withoutColumn("guide_moment_Nm"),
       "cycle.csv: no column guide_moment_<unit>, which the figure side_force.png"},
  };
  for (const Case& c : cases) {
    for (const std::string command : {"plot", "report"}) {
      SCOPED_TRACE(c.name + ", " + command);
      const fs::path bad = dir_ / "bad";
      fs::remove_all(bad);
      fs::create_directories(bad);
      std::ofstream(bad / "summary.json") << summary;
      std::ofstream(bad / "cycle.csv") << csv;
      std::ofstream(bad / c.file) << c.text;
      const auto before = listTree(bad);
      const pid_t p = start(std::string(PISTONDYN_EXE) + " " + command + " " + bad.string(), "p");
      EXPECT_EQ(finish(p), 1) << output("p");
      EXPECT_NE(output("p").find((bad / c.expected.substr(0, c.expected.find(':'))).string() +
                                 c.expected.substr(c.expected.find(':'))),
                std::string::npos)
          << output("p");
      EXPECT_EQ(listTree(bad), before);
    }
  }
}

// An --out on a file system nobody can write (/proc) is a refused --out: exit 2 as the
// README says, before the deck is simulated, for run and sweep alike.
TEST_F(FirstHourEdges, AnOutFolderOnProcIsARefusedOut) {
  std::ofstream(dir_ / "sweep.yaml") << "base_deck: engine.yaml\n"
                                        "cartesian:\n  drive.speed_rpm: [2000, 3000]\n";
  const std::string out = "/proc/pistondyn_test_" + std::to_string(::getpid()) + "/results";
  for (const std::string& command :
       {runCommand(out, "--quiet --no-plot"), std::string(PISTONDYN_EXE) + " sweep " +
                                                  (dir_ / "sweep.yaml").string() + " --out " + out +
                                                  " --quiet --no-plot"}) {
    SCOPED_TRACE(command);
    const pid_t p = start(command, "p");
    EXPECT_EQ(finish(p), 2) << output("p");
    // As root the probe folder answers ("no folder can be made in /proc"), else access().
    EXPECT_NE(output("p").find("--out " + out + " cannot be written: "), std::string::npos)
        << output("p");
    EXPECT_NE(output("p").find("nothing was simulated or written"), std::string::npos);
  }
}

// Item 4: the crank train's own side force beside the liner's, under its own name in
// cycle.csv, summary.json and the printed summary - on the ideal guide the two agree; and
// cycles_to_converge is null for a run that did not converge (a number when it did).
TEST_F(FirstHourEdges, CrankTrainSideForceBesideTheLinersAndNoCountWithoutConvergence) {
  const fs::path out = dir_ / "results";
  ASSERT_EQ(runProgram("", out), 0) << programStderr();
  const std::string printed = readFile(dir_ / "stdout.txt");
  const auto json = nlohmann::json::parse(readFile(out / "summary.json"));
  const auto& r = json["results"];
  const double ctMax = r["crank_train_side_force_max_N"].get<double>();
  const double ctMin = r["crank_train_side_force_min_N"].get<double>();
  EXPECT_NEAR(ctMax, r["side_force_max_N"].get<double>(), 1e-9 * std::abs(ctMax));
  EXPECT_NEAR(ctMin, r["side_force_min_N"].get<double>(), 1e-9 * std::abs(ctMax));
  EXPECT_EQ(r["crank_train_side_force_max_angle_deg"], r["side_force_max_angle_deg"]);
  // The extremes are those of the column over the cycle (its closing row repeats 0 deg).
  std::ifstream in(out / "cycle.csv");
  std::string line;
  std::vector<std::string> header;
  double colMax = -INFINITY, colMin = INFINITY;
  std::size_t column = 0;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0)
      continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');)
      f.push_back(x);
    if (header.empty()) {
      header = f;
      column = static_cast<std::size_t>(
          std::find(header.begin(), header.end(), "crank_train_side_force_N") - header.begin());
      ASSERT_LT(column, header.size()) << line;
      continue;
    }
    colMax = std::max(colMax, std::stod(f[column]));
    colMin = std::min(colMin, std::stod(f[column]));
  }
  EXPECT_EQ(colMax, ctMax);
  EXPECT_EQ(colMin, ctMin);
  EXPECT_NE(printed.find("crank-train side force (from the rod) +"), std::string::npos) << printed;
  EXPECT_NE(printed.find("side force on the liner +"), std::string::npos) << printed;
  // One cycle, not run to periodic steady state: no count.
  EXPECT_FALSE(r["converged"].get<bool>());
  EXPECT_TRUE(r["cycles_to_converge"].is_null()) << r.dump();
  // The ideal guide's pose never changes between cycles: periodic after two.
  ASSERT_EQ(runProgram("--set simulation.until_periodic=true --set simulation.cycles=3", out), 0)
      << programStderr();
  const auto periodic = nlohmann::json::parse(readFile(out / "summary.json"))["results"];
  EXPECT_TRUE(periodic["converged"].get<bool>());
  EXPECT_EQ(periodic["cycles_to_converge"], 2);
  EXPECT_FALSE(periodic.contains("last_cycles"));  // only a run that did not converge has it
  EXPECT_NE(readFile(dir_ / "stdout.txt").find("periodic after 2 cycles"), std::string::npos);
}

namespace {

class FirstHourSkirtEdges : public SkirtScratchDeck {};

// --fidelity preview through the program: check says what the preview changes; a run
// records it in summary.json (fidelity, fidelity_note, the grid among inputs and
// overrides) and in the printed summary. The deck set to 32 x 24 becomes 16 x 20.
TEST_F(FirstHourSkirtEdges, PreviewFidelityIsRecordedAndPrinted) {
  const std::string grid =
      " --set liner.grid.nodes_circumferential=32 --set liner.grid.nodes_axial=24";
  const ProgramRun check = invokeInScratch("check " + deck() + grid + " --fidelity preview");
  ASSERT_EQ(check.exitCode, 0) << check.err;
  EXPECT_NE(check.out.find("fidelity preview: film grid 16 x 20 nodes per side, the deck's 32 x "
                           "24 coarsened"),
            std::string::npos)
      << check.out;
  const fs::path out = dir_ / "results";
  ASSERT_EQ(runProgram(grid + " --set simulation.until_periodic=false --set simulation.cycles=1"
                              " --set simulation.output_step_deg=4 --fidelity preview",
                       out),
            0)
      << programStderr();
  const auto summary = nlohmann::json::parse(readFile(out / "summary.json"));
  EXPECT_EQ(summary["fidelity"], "preview");
  EXPECT_NE(summary["fidelity_note"].get<std::string>().find("film grid 16 x 20"),
            std::string::npos);
  EXPECT_EQ(summary["inputs"]["liner"]["grid"]["nodes_circumferential"], 16);
  EXPECT_EQ(summary["inputs"]["liner"]["grid"]["nodes_axial"], 20);
  EXPECT_EQ(summary["overrides"].back(), "liner.grid.nodes_axial=20");
  EXPECT_NE(readFile(dir_ / "stdout.txt").find("fidelity preview: film grid 16 x 20"),
            std::string::npos)
      << readFile(dir_ / "stdout.txt");
  // The stepper's step error estimate is printed with the summary.json figure's digits.
  char estimate[64];
  std::snprintf(estimate, sizeof estimate, "step error estimate %.3f um",
                summary["results"]["step_error_estimate_um"].get<double>());
  EXPECT_NE(readFile(dir_ / "stdout.txt").find(estimate), std::string::npos)
      << readFile(dir_ / "stdout.txt");
  // The report's inputs table names the preview as the grid's source (the user's own grid
  // assignment came before it), the user's other assignments as --set.
  ASSERT_EQ(invokeInScratch("report " + out.string()).exitCode, 0);
  const std::string html = readFile(out / "report.html");
  const auto row = [&html](const std::string& key) {
    const std::size_t at = html.find("<code>" + key + "</code>");
    return at == std::string::npos ? std::string() : html.substr(at, html.find("</tr>", at) - at);
  };
  EXPECT_NE(row("liner.grid.nodes_axial").find("<td>--fidelity preview</td>"), std::string::npos)
      << row("liner.grid.nodes_axial");
  EXPECT_NE(row("liner.grid.nodes_circumferential").find("<td>--fidelity preview</td>"),
            std::string::npos);
  EXPECT_NE(row("simulation.cycles").find("<td>--set</td>"), std::string::npos)
      << row("simulation.cycles");
  // An unknown fidelity is a bad command line.
  EXPECT_EQ(invokeInScratch("check " + deck() + " --fidelity coarse").exitCode, 2);
}

// run --warm-start DIR through the program: a run's folder holds warm_start.json, a later run
// starts from it and says so (stdout, summary.json); a folder without one, or the end of a run
// on another film grid, is bad input (exit 1) with nothing written.
TEST_F(FirstHourSkirtEdges, WarmStartThroughTheProgram) {
  const std::string coarse =
      " --set liner.grid.nodes_circumferential=12 --set liner.grid.nodes_axial=8"
      " --set simulation.until_periodic=false --set simulation.cycles=1"
      " --set simulation.output_step_deg=4";
  const fs::path first = dir_ / "first", second = dir_ / "second", refused = dir_ / "refused";
  ASSERT_EQ(runProgram(coarse, first), 0) << programStderr();
  ASSERT_TRUE(fs::exists(first / "warm_start.json"));
  ASSERT_EQ(runProgram(coarse + " --warm-start " + first.string(), second), 0) << programStderr();
  EXPECT_NE(readFile(dir_ / "stdout.txt").find("warm start from " + first.string()),
            std::string::npos)
      << readFile(dir_ / "stdout.txt");
  const auto summary = nlohmann::json::parse(readFile(second / "summary.json"));
  EXPECT_EQ(summary["warm_start_from"].get<std::string>(), first.string());

  EXPECT_EQ(runProgram(coarse + " --warm-start " + (dir_ / "nowhere").string(), refused), 1);
  EXPECT_NE(programStderr().find("--warm-start " + (dir_ / "nowhere").string() +
                                 ": " + (dir_ / "nowhere").string() + ": not a folder"),
            std::string::npos)
      << programStderr();
  EXPECT_FALSE(fs::exists(refused));
  EXPECT_EQ(runProgram(coarse + " --set liner.grid.nodes_axial=10 --warm-start " + first.string(),
                       refused),
            1);
  EXPECT_NE(programStderr().find("another film grid: 12 x 8 nodes, this one 12 x 10"),
            std::string::npos)
      << programStderr();
  EXPECT_NE(programStderr().find("nothing was simulated or written"), std::string::npos);
  EXPECT_FALSE(fs::exists(refused));
}

// sweep --fidelity preview: the preview grid joins the overrides every case shares (and so
// the fingerprint); a sweep that varies the grid itself is refused.
TEST_F(FirstHourSkirtEdges, PreviewSweepSharesThePreviewGrid) {
  std::ofstream(dir_ / "sweep.yaml")
      << "base_deck: engine.yaml\n"
         "set:\n  liner.grid.nodes_circumferential: 32\n  liner.grid.nodes_axial: 24\n"
         "  simulation.until_periodic: false\n  simulation.cycles: 1\n"
         "  simulation.output_step_deg: 4\n"
         "cases:\n  - {piston.mass_g: 210}\n";
  const ProgramRun r =
      invokeInScratch("sweep sweep.yaml --out preview --fidelity preview --quiet --no-plot");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto sweep = nlohmann::json::parse(readFile(dir_ / "preview" / "sweep.json"));
  const std::string text = sweep.dump();
  EXPECT_NE(text.find("liner.grid.nodes_circumferential=16"), std::string::npos) << text;
  EXPECT_NE(text.find("liner.grid.nodes_axial=20"), std::string::npos) << text;
  const auto summary =
      nlohmann::json::parse(readFile(dir_ / "preview" / "case_0001" / "summary.json"));
  EXPECT_EQ(summary["inputs"]["liner"]["grid"]["nodes_circumferential"], 16);
  EXPECT_EQ(summary["inputs"]["liner"]["grid"]["nodes_axial"], 20);
  // The full sweep into the same folder is another sweep: refused, never mixed.
  EXPECT_EQ(invokeInScratch("sweep sweep.yaml --out preview --quiet --no-plot").exitCode, 2);
  std::ofstream(dir_ / "grid.yaml") << "base_deck: engine.yaml\n"
                                       "cartesian:\n  liner.grid.nodes_axial: [12, 24]\n";
  const ProgramRun grid = invokeInScratch("sweep grid.yaml --list --fidelity preview");
  EXPECT_EQ(grid.exitCode, 1);
  EXPECT_NE(grid.err.find("--fidelity preview coarsens the film grid every case shares, but "
                          "this sweep varies it"),
            std::string::npos)
      << grid.err;
}

// AddressSanitizer reserves terabytes of shadow address space at start, so a program built
// with it cannot start under an address-space limit; the sanitizer build (the test and the
// program are built alike) checks the message without the limit.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kBuiltWithAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kBuiltWithAddressSanitizer = true;
#else
constexpr bool kBuiltWithAddressSanitizer = false;
#endif
#else
constexpr bool kBuiltWithAddressSanitizer = false;
#endif

// A compliance whose Matrix Market header claims 20000 x 20000 with one entry, beside a
// node table of 4 nodes: refused from the size line, before the 3.2 GB matrix is
// allocated - checked under a 1.5 GB address-space limit, where the allocation would fail
// with std::bad_alloc instead of the message (without the limit under AddressSanitizer).
TEST_F(FirstHourSkirtEdges, HugeMatrixMarketHeaderIsRefusedBeforeAllocating) {
  writeFile("nodes.csv", "node,phi_deg,y_mm\n1,0,-1\n2,30,-1\n3,0,3\n4,30,3\n");
  writeFile("c.mtx", "%%MatrixMarket matrix coordinate real symmetric\n20000 20000 1\n1 1 4e-9\n");
  const Processes p{dir_};
  const std::string limit = kBuiltWithAddressSanitizer ? "" : "ulimit -v 1500000 && ";
  const pid_t check = p.start("sh -c '" + limit + "exec " + std::string(PISTONDYN_EXE) +
                                  " check " + deck() +
                                  " --set liner.elastic_skirt.compliance_file=c.mtx"
                                  " --set liner.elastic_skirt.nodes_file=nodes.csv'",
                              "check");
  const ProgramRun r{Processes::finish(check), p.output("check", "out"), p.output("check")};
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("liner.elastic_skirt.compliance_file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("c.mtx: 20000 x 20000 matrix, expected 4 x 4 for the 4 nodes of"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("bad_alloc"), std::string::npos) << r.err;
}

// A newline (and a tab) in the deck's path: cycle.csv's comment line holds the path with
// the characters escaped, so the file keeps its shape (comments, header, rows) and reads
// back; the summary holds the path as it is (JSON escapes it).
TEST_F(FirstHourEdges, NewlineInTheDeckPathKeepsCycleCsvWhole) {
  const fs::path odd = dir_ / "new\nline\tfolder";
  fs::create_directories(odd);
  for (const auto& e : fs::directory_iterator(dir_)) {
    if (e.is_regular_file() && e.path().extension() != ".txt")
      fs::copy_file(e.path(), odd / e.path().filename());
  }
  const fs::path out = dir_ / "results";
  const std::string cmd = std::string(PISTONDYN_EXE) + " run '" + (odd / "engine.yaml").string() +
                          "' --out " + out.string() + " --quiet --no-plot";
  const pid_t run = start(cmd, "run");
  ASSERT_EQ(finish(run), 0) << output("run");
  EXPECT_EQ(expectWholeCycleCsv(out / "cycle.csv", 1.0), 721);
  const std::string csv = readFile(out / "cycle.csv");
  EXPECT_NE(csv.find("# pistondyn " PISTONDYN_VERSION " cycle results for " + dir_.string() +
                     "/new\\nline\\tfolder/engine.yaml\n"),
            std::string::npos)
      << csv.substr(0, 400);
  const auto summary = nlohmann::json::parse(readFile(out / "summary.json"));
  EXPECT_EQ(summary["deck_file"].get<std::string>(), (odd / "engine.yaml").string());
}

}  // namespace
