// `pistondyn optimize` through the program on the analytic test liner, whose constrained
// optimum is known in closed form (AnalyticTestLiner.h: c* = 44 um, e* = 0.4 mm, fmep* =
// 1.2 kPa under min h/sigma_thrust >= 4): found from three DOE seeds; every evaluation's
// objective is the closed form of its variables; a failing run is infeasible; resume
// replays the history; the optimum's deck reruns to the same figures; bad input and a
// foreign folder are refused with nothing written; and, with MPI, two ranks give the same
// history and optimum as threads.

#include <nlohmann/json.hpp>

#include "AnalyticTestLiner.h"
#include "DesignProgramFixture.h"
#include "SkirtStudyDeck.h"
#include "pistondyn/design/SkirtProfileDesign.h"
#include "pistondyn/io/CsvTable.h"

namespace {

using namespace pistondyn_test;

const char* kOptHead =
    "name: analytic constrained bowl\n"
    "base_deck: engine.yaml\n"
    "variables:\n"
    "  liner.clearance_um: [20, 60]\n"
    "  geometry.pin_offset_mm: [-1, 1]\n"
    "objective: fmep_kPa\n"
    "constraints:\n"
    "  min_h_over_sigma_thrust: {min: 4.0}\n";

std::string method(int seed, int evaluations = 80) {
  return "method:\n"
         "  doe_samples: 8\n"
         "  seed: " +
         std::to_string(seed) +
         "\n"
         "  starts: 2\n"
         "  max_evaluations: " +
         std::to_string(evaluations) +
         "\n"
         "  tolerance: 1e-7\n"
         "  constraint_tolerance: 1e-7\n";
}

nlohmann::json readJson(const fs::path& p) {
  return nlohmann::json::parse(readFile(p));
}

class OptimizeProgram : public DesignProgram {};

// The stated tolerance: variables within 1e-4 of their ranges (0.004 um, 0.0002 mm), the
// objective within 1e-6 kPa of 1.2 kPa; COBYLA converges on this quadratic to its
// tolerance 1e-7 (in scaled variables), the constraint within 1e-7 relative.
class OptimizeSeeds : public OptimizeProgram, public ::testing::WithParamInterface<int> {};

TEST_P(OptimizeSeeds, FindTheKnownConstrainedOptimum) {
  {
    const int seed = GetParam();
    write("opt.yaml", std::string(kOptHead) + method(seed));
    const std::string out = "out_" + std::to_string(seed);
    const Invocation r = invoke("optimize opt.yaml --out " + out + " --jobs 2 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    const auto result = readJson(dir_ / out / "result.json");
    const auto& best = result.at("optimum");
    const double c = best["variables"]["liner.clearance_um"].get<double>();
    const double e = best["variables"]["geometry.pin_offset_mm"].get<double>();
    EXPECT_NEAR(c, 44.0, 1e-4 * 40) << "seed " << seed;
    EXPECT_NEAR(e, 0.4, 1e-4 * 2) << "seed " << seed;
    EXPECT_NEAR(best["objective"].get<double>(), 1.2, 1e-6) << "seed " << seed;
    EXPECT_EQ(result["active_constraints"], nlohmann::json::array({"min_h_over_sigma_thrust"}));
    // Every design's objective and constraint figure are the closed forms of its variables
    // (the whole chain: overrides, the liner, the run's summary, the history).
    const CsvRows h = readCsvRows(dir_ / out / "history.csv");
    ASSERT_GT(h.rows.size(), 20u);
    double doeBest = 1e300;
    for (std::size_t i = 0; i < h.rows.size(); ++i) {
      AnalyticTestParameters p;
      p.clearance_um = h.number(i, "liner.clearance_um");
      p.pinOffset_mm = h.number(i, "geometry.pin_offset_mm");
      EXPECT_NEAR(h.number(i, "objective"), analyticFmep_kPa(p), 1e-12 * analyticFmep_kPa(p))
          << "history row " << i + 1;
      EXPECT_NEAR(h.number(i, "min_h_over_sigma_thrust"), p.clearance_um / 10 - p.pinOffset_mm,
                  1e-12);
      if (h.rows[i].at("stage") == "doe" && h.rows[i].at("feasible") == "true")
        doeBest = std::min(doeBest, h.number(i, "objective"));
    }
    EXPECT_EQ(h.rows.front().at("stage"), "baseline");
    EXPECT_EQ(h.rows.front().at("liner.clearance_um"), "40");
    EXPECT_LT(best["objective"].get<double>(), doeBest);
    EXPECT_TRUE(fs::exists(dir_ / out / "report.html"));
  }
}

// Three DOE seeds, each its own test (a few seconds each).
INSTANTIATE_TEST_SUITE_P(ThreeSeeds, OptimizeSeeds, ::testing::Values(1, 7, 123));

// The global option: NLopt's ISRES over the bounds (seeded), then a local search from its
// best point among the DOE's.
TEST_F(OptimizeProgram, TheGlobalStageFeedsTheLocalSearch) {
  write("opt.yaml", std::string(kOptHead) +
                        "method:\n  doe_samples: 4\n  global: isres\n  global_evaluations: 60\n"
                        "  max_evaluations: 60\n  tolerance: 1e-7\n  constraint_tolerance: 1e-7\n");
  const Invocation r = invoke("optimize opt.yaml --out out --jobs 2 --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const auto result = readJson(dir_ / "out" / "result.json");
  EXPECT_EQ(result["searches"][0]["stage"], "global");
  EXPECT_EQ(result["searches"][0]["nlopt_evaluations"].get<int>(), 60);
  const CsvRows h = readCsvRows(dir_ / "out" / "history.csv");
  int global = 0;
  for (const auto& row : h.rows)
    global += row.at("stage") == "global" ? 1 : 0;
  EXPECT_GT(global, 30);  // distinct designs of the 60 requests
  EXPECT_NEAR(result["optimum"]["objective"].get<double>(), 1.2, 1e-5);
}

TEST_F(OptimizeProgram, TheOptimumsDeckRunsToTheSameFigures) {
  write("opt.yaml", std::string(kOptHead) + method(3, 30));
  ASSERT_EQ(invoke("optimize opt.yaml --out out --quiet").exitCode, 0);
  const auto result = readJson(dir_ / "out" / "result.json");
  // Run from another folder: the deck's file paths are absolute.
  fs::create_directories(dir_ / "elsewhere");
  const std::string cmd =
      "cd " + (dir_ / "elsewhere").string() + " && " + PISTONDYN_EXE +
      " run ../out/optimum/engine.yaml --out ../rerun --quiet --no-plot > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const auto rerun = readJson(dir_ / "rerun" / "summary.json");
  const auto stored = readJson(dir_ / "out" / "optimum" / "run" / "summary.json");
  EXPECT_EQ(rerun["results"]["fmep_kPa"], stored["results"]["fmep_kPa"]);
  EXPECT_EQ(rerun["results"]["fmep_kPa"].get<double>(),
            result["optimum"]["objective"].get<double>());
  EXPECT_EQ(rerun["inputs"]["geometry"]["pin_offset_m"],
            stored["inputs"]["geometry"]["pin_offset_m"]);
  // Where the optimum's run ended is kept with it: its deck starts there.
  ASSERT_TRUE(fs::exists(dir_ / "out" / "optimum" / "run" / "warm_start.json"));
  const std::string warm = "cd " + (dir_ / "elsewhere").string() + " && " + PISTONDYN_EXE +
                           " run ../out/optimum/engine.yaml --out ../warm --quiet --no-plot"
                           " --warm-start ../out/optimum/run > /dev/null";
  EXPECT_EQ(std::system(warm.c_str()), 0);
}

TEST_F(OptimizeProgram, AFailedRunIsInfeasibleAndTheSearchGoesOn) {
  editDeck("  clearance_um: 40\n", "  clearance_um: 40\n  fail_below_clearance_um: 30\n");
  write("opt.yaml", std::string(kOptHead) + method(5, 40));
  const Invocation r = invoke("optimize opt.yaml --out out --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const CsvRows h = readCsvRows(dir_ / "out" / "history.csv");
  int failed = 0;
  for (std::size_t i = 0; i < h.rows.size(); ++i) {
    const bool fails = h.number(i, "liner.clearance_um") < 30.0;
    EXPECT_EQ(h.rows[i].at("status"), fails ? "failed" : "ok") << i + 1;
    if (fails) {
      ++failed;
      EXPECT_EQ(h.rows[i].at("feasible"), "false");
      EXPECT_EQ(h.rows[i].at("objective"), "");
      EXPECT_NE(h.rows[i].at("message").find("failing on purpose"), std::string::npos);
    }
  }
  EXPECT_GE(failed, 2);  // the Latin hypercube puts 2 of its 8 clearances below 30 um
  const auto result = readJson(dir_ / "out" / "result.json");
  EXPECT_NEAR(result["optimum"]["variables"]["liner.clearance_um"].get<double>(), 44.0, 0.05);
}

TEST_F(OptimizeProgram, ResumingReplaysTheHistoryAndRunsOnlyWhatIsMissing) {
  write("opt.yaml", std::string(kOptHead) + method(2, 25));
  ASSERT_EQ(invoke("optimize opt.yaml --out out --quiet").exitCode, 0);
  const std::string history = readFile(dir_ / "out" / "history.csv");
  const auto first = readJson(dir_ / "out" / "result.json");
  // An interruption: three evaluations lost, one left half-finished (no marker), the
  // results not yet written.
  std::vector<fs::path> folders;
  for (const auto& e : fs::directory_iterator(dir_ / "out" / "evaluations"))
    folders.push_back(e.path());
  std::sort(folders.begin(), folders.end());
  ASSERT_GT(folders.size(), 10u);
  for (int i = 0; i < 3; ++i)
    fs::remove_all(folders[static_cast<std::size_t>(i)]);
  fs::remove(folders[3] / "evaluation.json");
  for (const char* f : {"history.csv", "result.json", "report.html"})
    fs::remove(dir_ / "out" / f);
  const Invocation r = invoke("optimize opt.yaml --out out --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readFile(dir_ / "out" / "history.csv"), history);
  const auto second = readJson(dir_ / "out" / "result.json");
  EXPECT_EQ(second["evaluations_run_now"].get<int>(), 4);
  EXPECT_EQ(
      second["evaluations_run_now"].get<int>() + second["evaluations_from_earlier_run"].get<int>(),
      first["evaluations_run_now"].get<int>());
  EXPECT_EQ(second["optimum"], first["optimum"]);
}

TEST_F(OptimizeProgram, RefusesTheFolderOfADifferentOptimisationWritingNothing) {
  write("opt.yaml", std::string(kOptHead) + method(2, 5));
  ASSERT_EQ(invoke("optimize opt.yaml --out out --quiet").exitCode, 0);
  const auto before = listFiles();
  const std::string history = readFile(dir_ / "out" / "history.csv");
  std::string changed = std::string(kOptHead) + method(2, 5);
  changed.replace(changed.find("[20, 60]"), 8, "[25, 60]");
  write("opt2.yaml", changed);
  const Invocation r = invoke("optimize opt2.yaml --out out --quiet");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("out holds the results of a different optimisation"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("variables"), std::string::npos) << r.err;
  auto after = listFiles();
  after.erase("opt2.yaml");
  EXPECT_EQ(after, before);
  EXPECT_EQ(readFile(dir_ / "out" / "history.csv"), history);
  // A fit's folder is not an optimisation's either.
  fs::create_directories(dir_ / "fitdir");
  std::ofstream(dir_ / "fitdir" / "design.json")
      << R"({"format": "pistondyn design 1", "kind": "fit", "fingerprint": "x", "study": {}})";
  const Invocation f = invoke("optimize opt.yaml --out fitdir --quiet");
  EXPECT_EQ(f.exitCode, 2);
  EXPECT_NE(f.err.find("holds a fit, not an optimisation"), std::string::npos) << f.err;
}

struct BadInput {
  const char* name;
  std::string from, to;  // an edit of the good deck
  std::string expected;  // in the message, with the file:line where it applies
};

TEST_F(OptimizeProgram, BadInputIsRefusedNamingTheLineAndKeyWithNothingWritten) {
  const std::string good = std::string(kOptHead) + method(1, 5);
  const std::vector<BadInput> cases = {
      {"bounds reversed", "[-1, 1]", "[1, -1]",
       "opt.yaml:5: variables.geometry.pin_offset_mm: bounds [1, -1]: the lower bound must be "
       "less than the upper bound"},
      {"bounds equal", "[20, 60]", "[60, 60]",
       "opt.yaml:4: variables.liner.clearance_um: bounds [60, 60]"},
      {"not a numeric key", "  geometry.pin_offset_mm: [-1, 1]\n", "  pin.joint: [0, 1]\n",
       "opt.yaml:5: variables.pin.joint: "},
      {"not a deck key", "  geometry.pin_offset_mm: [-1, 1]\n",
       "  geometry.pin_ofset_mm: [-1, 1]\n",
       "opt.yaml:5: variables.geometry.pin_ofset_mm: the lower bound -1 is rejected by the base "
       "deck"},
      {"a bound the deck rejects", "[-1, 1]", "[-1, 100]",
       "opt.yaml:5: variables.geometry.pin_offset_mm: the upper bound 100 is rejected"},
      {"unknown objective", "objective: fmep_kPa", "objective: fmep",
       "opt.yaml:6: objective: 'fmep' is not a figure the design loop knows (one of: fmep_kPa"},
      {"unknown constraint figure", "min_h_over_sigma_thrust: {min: 4.0}", "min_h: {min: 4.0}",
       "opt.yaml:8: constraints.min_h: 'min_h' is not a figure"},
      {"unknown weighted figure", "objective: fmep_kPa", "objective: {fmep_kPa: 1, slap_mJ: 2}",
       "opt.yaml:6: objective: 'slap_mJ' is not a figure"},
      {"bobyqa with constraints", "  starts: 2\n", "  starts: 2\n  local: bobyqa\n",
       "method.local: bobyqa handles bounds only"},
      {"unknown key", "objective: fmep_kPa", "objectives: fmep_kPa",
       "opt.yaml:6: objectives: unknown key"},
      {"no base deck", "base_deck: engine.yaml", "base_deck: nowhere.yaml",
       "opt.yaml:2: base_deck: cannot open"},
  };
  for (const auto& c : cases) {
    std::string text = good;
    const auto pos = text.find(c.from);
    ASSERT_NE(pos, std::string::npos) << c.name;
    text.replace(pos, c.from.size(), c.to);
    write("bad.yaml", text);
    const auto before = listFiles();
    const Invocation r = invoke("optimize bad.yaml --out out --quiet");
    EXPECT_EQ(r.exitCode, 1) << c.name << "\n" << r.err;
    std::string expected = c.expected;
    if (expected.rfind("opt.yaml", 0) == 0)
      expected.replace(0, 8, "bad.yaml");
    EXPECT_NE(r.err.find(expected), std::string::npos) << c.name << "\n" << r.err;
    EXPECT_NE(r.err.find("nothing was simulated or written"), std::string::npos) << c.name;
    EXPECT_EQ(listFiles(), before) << c.name;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << c.name;
  }
  // --set on a variable, and an --out that is a file.
  write("opt.yaml", good);
  Invocation r = invoke("optimize opt.yaml --out out --set geometry.pin_offset_mm=0.1 --quiet");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--set geometry.pin_offset_mm: the study varies this key (opt.yaml:5"),
            std::string::npos)
      << r.err;
  write("afile", "x");
  r = invoke("optimize opt.yaml --out afile --quiet");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(OptimizeProgram, HelpNamesTheDeckOptionsAndExitCodes) {
  const Invocation r = invoke("optimize --help");
  EXPECT_EQ(r.exitCode, 0);
  for (const char* text : {"OPT", "--out", "--jobs", "--set", "--quiet", "COBYLA", "BOBYQA",
                           "mpirun -np K", "Exit codes", "4 no feasible design"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
  EXPECT_NE(invoke("--help").out.find("optimize"), std::string::npos);
}

// The parametric profile on the real skirt (the gasoline example, coarse: SkirtStudyDeck.h):
// every design runs the table of its own four numbers, and the optimum's deck names its
// copy. The drops are checked against the formula with the deck's skirt (12 mm above to
// 18 mm below the pin), written out here.
class ProfileProgram : public SkirtScratchDeck {
 protected:
  Invocation invoke(const std::string& args) const {
    const std::string cmd = "cd " + dir_.string() + " && " + PISTONDYN_EXE + " " + args + " > " +
                            (dir_ / "stdout.txt").string() + " 2> " +
                            (dir_ / "stderr.txt").string();
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(dir_ / "stdout.txt"),
            readFile(dir_ / "stderr.txt")};
  }
};

TEST_F(ProfileProgram, EveryDesignRunsTheTableOfItsOwnNumbers) {
  std::ofstream(dir_ / "opt.yaml") << "base_deck: engine.yaml\nset:\n" + fastSkirtSet() + gasolineColdShapesSet() +
                                          "variables:\n"
                                          "  liner.cold_radial_clearance_um: [30, 50]\n"
                                          "profile:\n"
                                          "  top_drop_um: [10, 60]\n"
                                          "  bottom_drop_um: 15\n"
                                          "  min_clearance_height_mm: [-12, 0]\n"
                                          "  curvature_um_per_mm2: 0.12\n"
                                          "  rows: 21\n"
                                          "objective: fmep_kPa\n"
                                          "method: {doe_samples: 3, max_evaluations: 3}\n";
  const Invocation r = invoke("optimize opt.yaml --out out --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const CsvRows h = readCsvRows(dir_ / "out" / "history.csv");
  ASSERT_GE(h.rows.size(), 5u);
  EXPECT_EQ(h.rows[0].at("profile.top_drop_um"), "");  // the baseline runs the deck's table
  for (std::size_t i = 1; i < h.rows.size(); ++i) {
    ASSERT_EQ(h.rows[i].at("status"), "ok") << h.rows[i].at("message");
    const fs::path folder = dir_ / "out" / "evaluations" / h.rows[i].at("evaluation");
    const pistondyn::design::SkirtProfileShape shape{h.number(i, "profile.top_drop_um"), 15.0,
                                                     h.number(i, "profile.min_clearance_height_mm"),
                                                     0.12};
    const pistondyn::io::CsvTable t = pistondyn::io::readCsvTable(
        (folder / "skirt_profile.csv").string(), {"height_above_pin_mm", "radial_drop_um"});
    EXPECT_GE(t.rows.size(), 21u);
    for (const auto& row : t.rows) {
      const double y = row[0];
      const double s = y - shape.minClearanceHeight_mm;
      const double L =
          s >= 0 ? 12.0 - shape.minClearanceHeight_mm : shape.minClearanceHeight_mm + 18.0;
      const double d = s >= 0 ? shape.topDrop_um : 15.0;
      EXPECT_NEAR(row[1], 0.12 * s * s + (d - 0.12 * L * L) * std::pow(s / L, 4), 1e-9) << y;
    }
    const auto summary = nlohmann::json::parse(readFile(folder / "summary.json"));
    EXPECT_EQ(summary["inputs"]["liner"]["skirt_profile"]["axial_profile_file"].get<std::string>(),
              fs::absolute(folder / "skirt_profile.csv").lexically_normal().string());
    EXPECT_EQ(summary["inputs"]["liner"]["skirt_profile"]["mirrored"].get<bool>(), false);
  }
  const std::string deck = readFile(dir_ / "out" / "optimum" / "engine.yaml");
  EXPECT_NE(deck.find((fs::absolute(dir_ / "out" / "optimum" / "skirt_profile.csv"))
                          .lexically_normal()
                          .string()),
            std::string::npos)
      << deck;
}

#ifdef PISTONDYN_MPIEXEC
// Two MPI ranks: the same history (every row, in the same order: the searches' decisions
// depend only on the results) and the same optimum as one process on threads.
TEST_F(OptimizeProgram, MpiGivesTheSameHistoryAndOptimumAsThreads) {
  if (std::system((std::string(PISTONDYN_MPIEXEC) + " --version > /dev/null 2>&1").c_str()) != 0)
    GTEST_SKIP() << "mpirun does not run here";
  write("opt.yaml", std::string(kOptHead) + method(4, 30));
  const Invocation threads = invoke("optimize opt.yaml --out threaded --jobs 2 --quiet");
  ASSERT_EQ(threads.exitCode, 0) << threads.err;
  const Invocation mpi =
      invoke("optimize opt.yaml --out mpi --quiet",
             std::string(PISTONDYN_MPIEXEC) + " -np 2 --oversubscribe --allow-run-as-root");
  ASSERT_EQ(mpi.exitCode, 0) << mpi.out << mpi.err;
  EXPECT_EQ(readFile(dir_ / "mpi" / "history.csv"), readFile(dir_ / "threaded" / "history.csv"));
  std::set<std::string> a, b;
  for (const auto& e : fs::directory_iterator(dir_ / "threaded" / "evaluations"))
    a.insert(e.path().filename().string());
  for (const auto& e : fs::directory_iterator(dir_ / "mpi" / "evaluations"))
    b.insert(e.path().filename().string());
  EXPECT_EQ(a, b);
  EXPECT_EQ(readJson(dir_ / "mpi" / "result.json")["optimum"],
            readJson(dir_ / "threaded" / "result.json")["optimum"]);
}
#endif

}  // namespace
