// pistondyn study STUDY.yaml --out DIR [--jobs N] [--set key.path=value]... [--quiet]
//                 [--no-plot]
//
// A study is a sweep deck with a few cases to compare (examples/studies/): the cases run
// as `pistondyn sweep` runs them (the same folder: sweep.json, case_NNNN/, sweep.csv,
// resume), then the study writes what a piston designer compares them by:
//   DIR/comparison.csv, DIR/comparison.md   one row per case (io/StudyComparison.h)
//   DIR/plots/comparison_*.png              the cases on common axes (ComparisonPlots.h)
// The cases run on threads in this process (no MPI: a study has a handful of cases).

#include <cstdio>
#include <iostream>

#include "CommandSupport.h"
#include "ComparisonPlots.h"
#include "Subcommand.h"
#include "SweepSupport.h"
#include "pistondyn/common/Cancellation.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/StudyComparison.h"

namespace pistondyn::app {
namespace {

class StudyCommand final : public Subcommand {
 public:
  explicit StudyCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "study",
            "run the cases of a study (a sweep deck with a few cases, examples/studies/) into "
            "DIR and compare them: comparison.csv, comparison.md and comparison figures")) {
    app_->add_option("STUDY", options_.sweepDeck,
                     "study deck: a sweep deck (YAML: base_deck, set, cases, cartesian, "
                     "latin_hypercube; `pistondyn sweep --help`)")
        ->required()
        ->type_name("STUDY.yaml");
    app_->add_option("--out", options_.outDir,
                     "output folder (created if needed): the sweep's files (sweep.json, "
                     "sweep.csv, case_0001/ ...), comparison.csv, comparison.md and "
                     "plots/comparison_*.png; a folder of the same study is resumed")
        ->required()
        ->type_name("DIR");
    app_->add_option("--jobs", options_.jobs,
                     "cases run at the same time, one thread and one model each (default: the "
                     "cores this process may use)")
        ->check(CLI::PositiveNumber)
        ->type_name("N");
    addSetOption(*app_, options_.overrides);
    addFidelityOption(*app_, options_.fidelity);
    app_->add_flag("--quiet", options_.quiet, "no progress lines (default: one line per case)");
    app_->add_flag("--no-plot", options_.noPlot,
                   "no comparison figures (default: drawn with gnuplot; a missing gnuplot is a "
                   "warning, the tables are still written)");
    app_->set_help_flag("-h,--help", "print this help and exit");
    app_->footer(
        "comparison.csv and comparison.md: per case its overrides, status, fmep_kPa,\n"
        "friction_power_mean_W, asperity_friction_work_share, min h/sigma per side with its\n"
        "crank angle (deg), min film per side (um), max |u_lat| (um), max |tilt| (deg),\n"
        "slap_energy_max_mJ, side_force_max_N, cycles_to_converge, converged (of the last\n"
        "720 deg cycle; crank angle 0 deg = firing TDC). The figures draw each case's last\n"
        "cycle against the crank angle 0..720 deg: side force (N), lateral displacement (um)\n"
        "and tilt (mrad), friction power (W), minimum film (um) and h/sigma per side.\n"
        "comparison.html (with the figures, not with --no-plot): the cases side by side,\n"
        "each case's headline in engineering units, and the figures, in one self-contained\n"
        "page.\n"
        "Exit codes: 0 every case ok; 1 bad input (study deck, a case's deck), nothing\n"
        "written; 2 bad command line or a refused --out, nothing written; 3 the folder or a\n"
        "table could not be written; 4 some cases failed (listed, the others compared); 130 / 143\n"
        "interrupted by SIGINT / SIGTERM (the running cases removed, the finished kept: rerun to\n"
        "resume).");
  }

  int execute() override {
    if (const int code = checkOutPath(options_); code != kExitOk)
      return code;
    const auto plan = loadSweepOrReport(options_);
    if (!plan)
      return kExitBadInput;
    int code = kExitOk;
    io::StudyComparison comparison;
    try {
      io::SweepOutcome outcome;
      double wall = 0.0;
      const auto results = runCasesHere(options_, *plan, outcome, wall);
      code = reportSweep(options_, *plan, outcome, wall);
      comparison = io::makeStudyComparison(*plan, results);
      io::writeFilesAtomically(options_.outDir,
                               {{"comparison.csv", io::makeComparisonCsv(comparison)},
                                {"comparison.md", io::makeComparisonMarkdown(comparison)}});
      std::printf("  and %s/comparison.csv, %s/comparison.md (one row per case)\n",
                  options_.outDir.c_str(), options_.outDir.c_str());
    } catch (const common::Cancelled&) {
      throw;  // main reports it; the complete cases are kept, a rerun resumes
    } catch (const io::SweepOutputError& e) {
      std::cerr << "pistondyn: --out " << e.what() << "; nothing was simulated or written\n";
      return kExitUsage;
    } catch (const std::exception& e) {
      std::cerr << "pistondyn: the study failed: " << e.what() << "\n";
      return kExitFailed;
    }
    if (!options_.noPlot)
      drawComparisonPlots(options_, comparison);
    return code;
  }

 private:
  SweepOptions options_;
};

}  // namespace

std::unique_ptr<Subcommand> addStudyCommand(CLI::App& program) {
  return std::make_unique<StudyCommand>(program);
}

}  // namespace pistondyn::app
