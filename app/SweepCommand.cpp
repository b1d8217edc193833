// pistondyn sweep SWEEP.yaml --out DIR [--jobs N] [--set key.path=value]... [--list] [--quiet]
//
// Runs every case of a sweep deck (io/SweepDeck.h) into DIR (io/SweepRun.h): one thread
// per case, each case its own model; under mpirun the ranks share the cases
// (SweepMpi.cpp, built when MPI is found).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "CommandSupport.h"
#include "ComparisonPlots.h"
#include "ComparisonReport.h"
#include "Subcommand.h"
#include "SweepSupport.h"
#include "pistondyn/common/Cancellation.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/ResultWriters.h"

namespace pistondyn::app {

// ---- shared with SweepMpi.cpp -----------------------------------------------------------

int checkOutPath(const SweepOptions& options) {
  if (options.outDir.empty())
    return kExitOk;  // --list writes nothing
  if (const std::string problem = findOutputFolderProblem(options.outDir); !problem.empty()) {
    std::cerr << "pistondyn: --out " << options.outDir << " " << problem
              << "; nothing was simulated or written\n";
    return kExitUsage;
  }
  return kExitOk;
}

namespace {

// The --set assignments of the base deck's preview grid (none when its liner has none).
std::vector<std::string> previewOverrides(const io::SweepPlan& plan) {
  const io::EngineDeck preview =
      io::loadEngineDeck(plan.baseDeckPath, plan.fixedOverrides, io::Fidelity::Preview);
  return {preview.overrides.begin() + static_cast<long>(plan.fixedOverrides.size()),
          preview.overrides.end()};
}

}  // namespace

std::optional<io::SweepPlan> loadSweepOrReport(const SweepOptions& options) {
  try {
    io::SweepPlan plan = io::loadSweepDeck(options.sweepDeck, options.overrides);
    if (toFidelity(options.fidelity) == io::Fidelity::Full)
      return plan;
    const std::vector<std::string> preview = previewOverrides(plan);
    for (const auto& k : plan.sweptKeys) {
      if (k.key.rfind("liner.grid.nodes_", 0) == 0) {
        std::cerr << "pistondyn: the sweep was rejected; nothing was simulated or written:\n"
                  << k.origin
                  << ": --fidelity preview coarsens the film grid every case shares, but this "
                     "sweep varies it: run it at --fidelity full\n";
        return std::nullopt;
      }
    }
    if (preview.empty())
      return plan;  // no film grid: the same sweep
    std::vector<std::string> overrides = options.overrides;
    overrides.insert(overrides.end(), preview.begin(), preview.end());
    return io::loadSweepDeck(options.sweepDeck, overrides);
  } catch (const io::DeckError& e) {
    std::cerr << "pistondyn: the sweep was rejected; nothing was simulated or written:\n"
              << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "pistondyn: " << options.sweepDeck << ": the sweep deck could not be read; "
              << "nothing was simulated or written: " << e.what() << "\n";
  }
  return std::nullopt;
}

void printCaseList(const io::SweepPlan& plan) {
  std::cout << "case";
  for (const auto& k : plan.sweptKeys)
    std::cout << ',' << k.key;
  std::cout << '\n';
  for (const auto& c : plan.cases) {
    std::cout << c.index;
    for (const auto& k : plan.sweptKeys) {
      std::cout << ',';
      for (const auto& a : c.assignments) {
        if (a.key == k.key)
          std::cout << a.value;
      }
    }
    std::cout << '\n';
  }
}

void printSweepStart(const SweepOptions& options, const io::SweepPlan& plan,
                     const io::SweepOutputState& state, const std::string& workers) {
  if (options.quiet)
    return;
  std::fprintf(stderr, "pistondyn sweep: %zu cases", plan.cases.size());
  if (state.resumed) {
    std::fprintf(stderr, " (resuming %s: %zu complete, not rerun", options.outDir.c_str(),
                 state.complete.size());
    if (!state.halfFinished.empty())
      std::fprintf(stderr, "; %zu half-finished, rerun", state.halfFinished.size());
    std::fprintf(stderr, ")");
  }
  std::fprintf(stderr, ", %zu to run on %s\n", state.toRun.size(), workers.c_str());
}

void printCaseDone(const SweepOptions& options, const io::SweepPlan& plan,
                   const io::SweepCaseResult& r, int done, int total, const std::string& where) {
  if (options.quiet)
    return;
  if (r.ok) {
    std::fprintf(stderr, "pistondyn sweep: [%d/%d] case %d ok, %.1f s%s\n", done, total, r.index,
                 r.wallTime_s, where.c_str());
  } else {
    std::fprintf(stderr, "pistondyn sweep: [%d/%d] case %d failed%s: %s\n", done, total, r.index,
                 where.c_str(), r.message.c_str());
  }
  (void)plan;
}

int reportSweep(const SweepOptions& options, const io::SweepPlan& plan, const io::SweepOutcome& o,
                double wallTime_s) {
  const int ok = o.earlier + o.ran - o.failed;
  std::printf("pistondyn sweep: %d cases: %d ok, %d failed", o.cases, ok, o.failed);
  if (o.earlier > 0)
    std::printf(" (%d complete from an earlier run, %d run now)", o.earlier, o.ran);
  std::printf("; %.1f s wall time\n", wallTime_s);
  std::printf(
      "  wrote %s/sweep.csv (one row per case: overrides, status, summary figures) and "
      "the run folders %s/%s/ ...\n",
      options.outDir.c_str(), options.outDir.c_str(), plan.getCaseFolderName(1).c_str());
  if (o.failed > 0) {
    std::printf(
        "  %d case(s) failed: their messages are in sweep.csv; a rerun of the same "
        "command retries them and keeps the complete cases\n",
        o.failed);
    return kExitSomeCasesFailed;
  }
  return kExitOk;
}

std::vector<io::SweepCaseResult> runCasesHere(const SweepOptions& options,
                                              const io::SweepPlan& plan, io::SweepOutcome& outcome,
                                              double& wallTime_s) {
  const int jobs = options.jobs > 0 ? options.jobs : io::getAvailableCores();
  const auto start = std::chrono::steady_clock::now();
  const io::SweepOutputState state = io::openSweepOutput(plan, options.outDir);
  const int threads = std::max(1, std::min<int>(jobs, static_cast<int>(state.toRun.size())));
  printSweepStart(options, plan, state,
                  std::to_string(threads) + (threads == 1 ? " thread" : " threads"));
  std::vector<io::SweepCaseResult> results = state.complete;
  // Called on this thread (io::runSweep collects the pool's results here).
  auto progress = [&](const io::SweepCaseResult& r, int done, int total) {
    printCaseDone(options, plan, r, done, total, "");
    results.push_back(r);
  };
  outcome = io::runSweep(plan, options.outDir, state, jobs, progress);
  wallTime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return results;
}

void drawComparisonPlots(const SweepOptions& options, const io::StudyComparison& comparison) {
  std::vector<ComparisonCase> cases;
  for (const auto& row : comparison.rows) {
    if (!row.ok)
      continue;
    cases.push_back({io::describeCase(comparison, row), {}});
    cases.back().folder.directory = (std::filesystem::path(options.outDir) / row.folder).string();
  }
  if (cases.size() > kMaxComparedCases) {
    std::printf("  no comparison figures: %zu cases finished, more than the %zu curves a figure "
                "can tell apart (sweep.csv holds every case)\n",
                cases.size(), kMaxComparedCases);
    return;
  }
  try {
    for (auto& c : cases)
      c.folder = io::readResultFolder(c.folder.directory);
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::cerr << "pistondyn: warning: no comparison figures and no comparison.html (the results "
                 "are written): "
              << e.what() << "\n";
    return;
  }
  const std::string title = comparison.name.empty() ? comparison.studyDeckPath : comparison.name;
  std::vector<std::string> files;
  std::string note;
  try {
    files = writeComparisonPlots(cases, options.outDir, title);
    std::printf("  and %zu comparison figures (%s/plots/comparison_*.png)\n", files.size(),
                options.outDir.c_str());
  } catch (const std::exception& e) {
    note = std::string("No comparison figures: ") + e.what();
    std::fflush(stdout);
    std::cerr << "pistondyn: warning: no comparison figures (the results are written): "
              << e.what() << "\n";
  }
  // The cases side by side in one page, with the figures when there are any.
  try {
    io::writeFilesAtomically(options.outDir,
                             {{"comparison.html", makeComparisonHtml(title, cases, files, note)}});
    std::printf("  and the cases side by side in %s/comparison.html\n", options.outDir.c_str());
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::cerr << "pistondyn: warning: no comparison.html (the results are written): " << e.what()
              << "\n";
  }
}

namespace {

// The launcher's size variable, if any (OpenMPI, MPICH / Hydra and PMI, Slurm with PMIx).
const char* launchSizeVariable() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"}) {
    if (std::getenv(name) != nullptr)
      return name;
  }
  return nullptr;
}

}  // namespace

bool isMpiLaunch() {
  return launchSizeVariable() != nullptr || std::getenv("PMIX_RANK") != nullptr ||
         std::getenv("PMI_RANK") != nullptr;
}

int getMpiLaunchSize() {
  const char* name = launchSizeVariable();
  if (name == nullptr)
    return 1;
  const int n = std::atoi(std::getenv(name));
  return n > 0 ? n : 1;
}

// ---- the subcommand ---------------------------------------------------------------------

namespace {

class SweepCommand final : public Subcommand {
 public:
  explicit SweepCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "sweep",
            "run every case of a sweep deck (a base engine deck and --set-style overrides: "
            "cartesian product, listed cases, Latin hypercube) into DIR, all cores busy")) {
    app_->add_option("SWEEP", options_.sweepDeck,
                     "sweep deck (YAML: base_deck, set, cartesian, cases, latin_hypercube; "
                     "README.md, Design sweeps; installed in share/doc/pistondyn)")
        ->required()
        ->type_name("SWEEP.yaml");
    app_->add_option("--out", options_.outDir,
                     "output folder (created if needed): sweep.json (the sweep's fingerprint), "
                     "sweep.csv (one row per case) and one run folder per case (case_0001/ "
                     "with cycle.csv and summary.json); a folder of the same sweep is resumed, "
                     "one of another sweep refused (required unless --list)")
        ->type_name("DIR");
    app_->add_option("--jobs", options_.jobs,
                     "cases run at the same time, one thread and one model each (default: the "
                     "cores this process may use; under mpirun: per rank, default 1)")
        ->check(CLI::PositiveNumber)
        ->type_name("N");
    addSetOption(*app_, options_.overrides);
    addFidelityOption(*app_, options_.fidelity);
    app_->add_flag("--list", options_.list,
                   "check the sweep and every case, print the cases (CSV), run nothing");
    app_->add_flag("--quiet", options_.quiet, "no progress lines (default: one line per case)");
    app_->add_flag("--no-plot", options_.noPlot,
                   "no comparison figures (default: DIR/plots/comparison_*.png with gnuplot, "
                   "one curve per case, when at most 12 cases finished; a missing gnuplot is "
                   "a warning)");
    app_->set_help_flag("-h,--help", "print this help and exit");
    app_->footer(
        "Every case is checked against the base deck before anything runs. Cases run with "
        "all cores\nbusy: a thread per case, each with its own model (--jobs); under "
        "`mpirun -np K pistondyn sweep ...`\nthe ranks share the cases (rank 0 hands them "
        "out as ranks ask), with the same results.\nRerunning the command after an "
        "interruption keeps the complete cases and reruns the rest.\nExit codes: 0 every "
        "case ok; 1 bad input (sweep deck, a case's deck), nothing written; 2 bad\ncommand "
        "line, or --out is a file, another sweep's folder or a non-empty folder without\n"
        "sweep.json, nothing written; 3 the sweep could not write its folder or sweep.csv; 4 "
        "some cases\nfailed (each listed in sweep.csv with its message, the others' results "
        "written); 130 / 143\ninterrupted by SIGINT / SIGTERM (the running cases removed, the "
        "finished kept: rerun to resume).");
  }

  int execute() override {
    if (options_.outDir.empty() && !options_.list) {
      std::cerr << "pistondyn: sweep: --out DIR is required (unless --list)\n\nusage: "
                   "pistondyn sweep SWEEP.yaml --out DIR [--jobs N] [--set key.path=value]... "
                   "[--list] [--quiet]\n";
      return kExitUsage;
    }
    if (isMpiLaunch()) {
#ifdef PISTONDYN_WITH_MPI
      return runSweepMpi(options_);
#else
      if (getMpiLaunchSize() > 1) {
        std::cerr << "pistondyn: this pistondyn was built without MPI, so under mpirun every "
                     "process would run the whole sweep; run it without mpirun (it uses every "
                     "core with threads), or rebuild with MPI (libopenmpi-dev, README.md)\n";
        return kExitUsage;
      }
#endif
    }
    return runHere();
  }

 private:
  int runHere() {
    if (const int code = checkOutPath(options_); code != kExitOk)
      return code;
    const auto plan = loadSweepOrReport(options_);
    if (!plan)
      return kExitBadInput;
    if (options_.list) {
      printCaseList(*plan);
      return kExitOk;
    }
    try {
      io::SweepOutcome outcome;
      double wall = 0.0;
      const auto results = runCasesHere(options_, *plan, outcome, wall);
      const int code = reportSweep(options_, *plan, outcome, wall);
      if (!options_.noPlot)
        drawComparisonPlots(options_, io::makeStudyComparison(*plan, results));
      return code;
    } catch (const common::Cancelled&) {
      throw;  // main reports it; the complete cases are kept, a rerun resumes
    } catch (const io::SweepOutputError& e) {
      std::cerr << "pistondyn: --out " << e.what() << "; nothing was simulated or written\n";
      return kExitUsage;
    } catch (const std::exception& e) {
      std::cerr << "pistondyn: the sweep failed: " << e.what() << "\n";
      return kExitFailed;
    }
  }

  SweepOptions options_;
};

}  // namespace

std::unique_ptr<Subcommand> addSweepCommand(CLI::App& program) {
  return std::make_unique<SweepCommand>(program);
}

}  // namespace pistondyn::app
