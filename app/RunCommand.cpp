// pistondyn run DECK.yaml --out DIR [--set key.path=value]... [--fidelity full|preview]
//               [--warm-start DIR] [--quiet] [--no-plot] [--log-level LEVEL]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>

#include <unistd.h>

#include <spdlog/spdlog.h>

#include "CommandSupport.h"
#include "Logging.h"
#include "ProgressLine.h"
#include "ResultPlots.h"
#include "Subcommand.h"
#include "pistondyn/common/Cancellation.h"
#include "pistondyn/io/OutputFolderLock.h"
#include "pistondyn/io/ResultFolder.h"
#include "pistondyn/io/RunDeck.h"
#include "pistondyn/io/WarmStartFile.h"

namespace pistondyn::app {
namespace {

// The figures a lubricated liner reports (each line only when it reports them).
void printLinerFigures(const io::CycleSummary::LinerFigures& f, const io::CycleSummary& s,
                       const plugin::SimulationStats& stats) {
  if (!stats.cycleFmep_Pa.empty()) {
    std::printf("  fmep %.3f kPa", stats.cycleFmep_Pa.back() / 1e3);
    if (f.frictionPowerMean_W)
      std::printf("   mean friction power %.1f W", *f.frictionPowerMean_W);
    if (stats.cycleFmep_Pa.size() > 1) {
      std::printf("   (per cycle:");
      for (double v : stats.cycleFmep_Pa)
        std::printf(" %.3f", v / 1e3);
      std::printf(" kPa)");
    }
    std::printf("\n");
  }
  if (f.minGapOverSigmaThrust && f.minGapOverSigmaAntiThrust) {
    std::printf("  min h/sigma %.2f at %.1f deg (thrust), %.2f at %.1f deg (anti-thrust)\n",
                *f.minGapOverSigmaThrust, *f.minGapOverSigmaThrustAngle_deg,
                *f.minGapOverSigmaAntiThrust, *f.minGapOverSigmaAntiThrustAngle_deg);
  }
  if (f.minFilmThicknessThrust_m && f.minFilmThicknessAntiThrust_m) {
    std::printf("  min film %.3f um at %.1f deg (thrust), %.3f um at %.1f deg (anti-thrust)\n",
                *f.minFilmThicknessThrust_m * 1e6, *f.minFilmThicknessThrustAngle_deg,
                *f.minFilmThicknessAntiThrust_m * 1e6, *f.minFilmThicknessAntiThrustAngle_deg);
    std::printf("  max |u_lat| %.2f um   max |tilt| %.4f deg", s.maxAbsLateralDisplacement_m * 1e6,
                s.maxAbsTilt_rad * 180.0 / M_PI);
    if (f.slapEnergyMax_J)
      std::printf("   largest slap %.4f mJ", *f.slapEnergyMax_J * 1e3);
    std::printf("\n");
  }
  if (f.hotRunningClearance_m)
    std::printf("  hot running clearance %.2f um\n", *f.hotRunningClearance_m * 1e6);
  if (f.filmSolves) {
    std::printf("  %ld film solves (%ld with the reference-solver fallback, %ld without squeeze "
                "derivatives), %ld rejected steps\n",
                *f.filmSolves, f.filmFallbacks.value_or(0), f.filmDerivativeFailures.value_or(0),
                stats.rejectedSteps);
  }
  // linearly_implicit_bdf2's own estimate (summary.json: results.step_error_estimate_um).
  if (!stats.cycleStepErrorEstimate_um.empty() &&
      std::isfinite(stats.cycleStepErrorEstimate_um.back())) {
    std::printf("  step error estimate %.3f um on the pose over the last cycle (the stepper's "
                "local error estimates, summed)\n",
                stats.cycleStepErrorEstimate_um.back());
  }
}

// The range (smallest .. largest) of the main figures over the last cycles of a run that did
// not become periodic (summary.json: results.last_cycles).
void printLastCyclesRange(const std::vector<io::CycleSummary>& cycles) {
  const std::size_t n = std::min(io::kLastCyclesSummarised, cycles.size());
  if (n < 2)
    return;
  using Figure = std::function<std::optional<double>(const io::CycleSummary&)>;
  const auto range = [&](const char* name, const char* unit, const char* format,
                         const Figure& figure) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = cycles.size() - n; i < cycles.size(); ++i) {
      const std::optional<double> v = figure(cycles[i]);
      if (!v)
        return;
      lo = std::min(lo, *v);
      hi = std::max(hi, *v);
    }
    const std::string pattern = std::string("  %s ") + format + " .. " + format + " %s";
    std::printf(pattern.c_str(), name, lo, hi, unit);
  };
  const auto liner = [](auto get) {
    return [get](const io::CycleSummary& c) -> std::optional<double> {
      return c.liner ? get(*c.liner) : std::nullopt;
    };
  };
  std::printf("  over the last %zu cycles: ", n);
  range("fmep", "kPa", "%.3f", liner([](const auto& f) {
          return f.fmep_Pa ? std::optional<double>(*f.fmep_Pa / 1e3) : std::nullopt;
        }));
  range("min h/sigma thrust", "", "%.2f",
        liner([](const auto& f) { return f.minGapOverSigmaThrust; }));
  range("anti-thrust", "", "%.2f", liner([](const auto& f) { return f.minGapOverSigmaAntiThrust; }));
  range("max |u_lat|", "um", "%.2f", [](const io::CycleSummary& c) -> std::optional<double> {
    return c.maxAbsLateralDisplacement_m * 1e6;
  });
  range("largest slap", "mJ", "%.3f", liner([](const auto& f) {
          return f.slapEnergyMax_J ? std::optional<double>(*f.slapEnergyMax_J * 1e3)
                                   : std::nullopt;
        }));
  std::printf("\n");
}

void printSummary(const io::EngineDeck& deck, const io::RunOutcome& o, const std::string& outDir) {
  const auto& s = o.summary;
  std::printf("pistondyn: %s\n", deck.engine.name.c_str());
  std::printf("  %d cycle(s) at %.0f rpm, %ld rows, %.3f s wall time, %ld integrator steps\n",
              o.stats.cyclesRun, deck.engine.drive.speed_radps * 30.0 / M_PI, o.rows,
              o.stats.wallTime_s, o.stats.integratorSteps);
  if (deck.fidelity == io::Fidelity::Preview) {
    std::printf("  fidelity preview: %s\n", deck.fidelityNote.empty()
                                                ? "the same as full (the liner has no film grid)"
                                                : deck.fidelityNote.c_str());
  } else {
    std::printf("  fidelity full: the deck as written\n");
  }
  if (!deck.warmStartFrom.empty()) {
    std::printf("  warm start from %s%s\n", deck.warmStartFrom.c_str(),
                deck.simulation.untilPeriodic ? " (the first cycle compared with its last)" : "");
  }
  if (deck.simulation.untilPeriodic) {
    if (o.stats.converged) {
      std::printf("  periodic after %d cycle%s (of at most %d)\n", o.stats.cyclesToConverge,
                  o.stats.cyclesToConverge == 1 ? "" : "s", deck.simulation.cycles);
    } else {
      std::printf("  NOT periodic after %d cycles: the figures are those of the last one\n",
                  o.stats.cyclesRun);
      printLastCyclesRange(o.cycleSummaries);
    }
  }
  std::printf("  imep %.1f kPa   peak cylinder pressure %.2f bar at %.1f deg\n", s.imep_Pa / 1e3,
              s.peakCylinderPressure_Pa / 1e5, s.peakCylinderPressureAngle_deg);
  std::printf("  crank-train side force (from the rod) %+.0f N at %.1f deg, %+.0f N at %.1f deg\n",
              s.crankTrainSideForceMax_N, s.crankTrainSideForceMaxAngle_deg,
              s.crankTrainSideForceMin_N, s.crankTrainSideForceMinAngle_deg);
  if (s.liner) {
    std::printf(
        "  side force on the liner %+.0f N at %.1f deg (thrust), %+.0f N at %.1f deg "
        "(anti-thrust)\n",
        s.liner->sideForceMax_N, s.liner->sideForceMaxAngle_deg, s.liner->sideForceMin_N,
        s.liner->sideForceMinAngle_deg);
    printLinerFigures(*s.liner, s, o.stats);
  } else {
    std::printf("  side force on the liner: the model has no liner element\n");
  }
  std::printf("  conrod force %+.0f .. %+.0f N   mean crank torque %.2f N m   power %.2f kW\n",
              s.conrodForceMin_N, s.conrodForceMax_N, s.meanCrankTorque_Nm,
              s.indicatedPower_W / 1e3);
  std::printf("  wrote %s/cycle.csv and %s/summary.json (crank angle 0 = firing TDC)\n",
              outDir.c_str(), outDir.c_str());
  if (!deck.fieldDumpAngles_deg.empty()) {
    std::printf("  and %zu field dumps (%s/field_dump_*deg_{thrust,antithrust}.csv)\n",
                2 * deck.fieldDumpAngles_deg.size(), outDir.c_str());
  }
}

class RunCommand final : public Subcommand {
 public:
  explicit RunCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "run", "simulate an engine deck and write DIR/cycle.csv, DIR/summary.json and "
                   "the figures DIR/plots/*.png")) {
    app_->add_option("DECK", deck_, "engine deck (YAML; every key names its unit, e.g. bore_mm)")
        ->required()
        ->type_name("DECK.yaml");
    app_->add_option("--out", outDir_,
                     "output folder (created if needed); cycle.csv (one row per output crank "
                     "angle, units in every column name) and summary.json (inputs in SI, "
                     "results of the last 720 deg cycle) are written all-or-nothing")
        ->required()
        ->type_name("DIR");
    addSetOption(*app_, overrides_);
    addFidelityOption(*app_, fidelity_);
    app_->add_option("--warm-start", warmStart_,
                     "start from where an earlier run of the same engine ended (its folder's "
                     "warm_start.json: the piston's pose and rates, the films' fill fraction, "
                     "the liner oil and an elastic skirt's deformation, and its last cycle, with "
                     "which the first cycle is compared): a run from a periodic state is "
                     "periodic after one cycle")
        ->type_name("DIR");
    app_->add_flag("--quiet", quiet_,
                   "no progress line on stderr; the summary on stdout, warnings and errors "
                   "stay (default: runs longer than 1 s show cycle, crank angle and the "
                   "estimated time left on stderr; rewritten in place on a terminal, a plain "
                   "line every 15 s otherwise, never a carriage return)");
    app_->add_flag("--no-plot", noPlot_,
                   "do not draw DIR/plots/*.png after the run (default: drawn with gnuplot, "
                   "as `pistondyn plot DIR`; a missing gnuplot is a warning, the results stay)");
    addLogLevelOption(*app_, logLevel_);
    app_->set_help_flag("-h,--help", "print this help and exit");
    app_->footer(deckHelpFooter());
  }

  int execute() override {
    setUpLogging(logLevel_);
    // Refuse an unusable output path now, not after the simulation.
    if (const std::string problem = findOutputFolderProblem(outDir_); !problem.empty()) {
      std::cerr << "pistondyn: --out " << outDir_ << " " << problem
                << "; nothing was simulated or written\n";
      return kExitUsage;
    }
    auto deck = loadDeckOrReport(deck_, overrides_, toFidelity(fidelity_));
    if (!deck)
      return kExitBadInput;
    if (!warmStart_.empty()) {
      try {
        deck->simulation.warmStart = io::readWarmStart(warmStart_);
        io::checkWarmStartFits(*deck);
        deck->warmStartFrom = warmStart_;
      } catch (const std::exception& e) {
        std::cerr << "pistondyn: --warm-start " << warmStart_ << ": " << e.what()
                  << "; nothing was simulated or written\n";
        return kExitBadInput;
      }
    }
    // One process at a time writes the folder, from here to the last figure.
    std::optional<io::OutputFolderLock> lock;
    if (const int refused =
            lockOutputFolder(outDir_, lock, "--out ", "nothing was simulated or written");
        refused != kExitOk)
      return refused;
    spdlog::info("run: deck {} ({}), liner {}, {} cycle(s) of {} rows, results to {}", deck_,
                 deck->engine.name, deck->linerModel, deck->simulation.cycles,
                 deck->simulation.stepsPerCycle(), outDir_);
    const bool terminal = isatty(fileno(stderr)) != 0;
    ProgressLine progress(stderr, terminal, deck->simulation.stepsPerCycle(),
                          deck->simulation.cycles, deck->simulation.untilPeriodic);
    std::vector<plugin::RowSink*> sinks;
    if (!quiet_)
      sinks.push_back(&progress);
    try {
      const io::RunOutcome outcome = io::runDeck(*deck, outDir_, {}, sinks);
      progress.finish();
      printSummary(*deck, outcome, outDir_);
    } catch (const common::Cancelled&) {
      progress.finish();
      throw;  // main reports it; the folder is as it was
    } catch (const std::exception& e) {
      progress.finish();
      std::cerr << "pistondyn: the run failed; no results were written: " << e.what() << "\n";
      return kExitFailed;
    }
    if (!noPlot_) {
      // The results are complete and written: a plot that fails is a warning, not a failed run.
      try {
        const auto files = writeResultPlots(io::readResultFolder(outDir_));
        std::printf("  and %zu figures (%s/plots/*.png)\n", files.size(), outDir_.c_str());
      } catch (const common::Cancelled&) {
        throw;
      } catch (const std::exception& e) {
        std::fflush(stdout);
        std::cerr << "pistondyn: warning: no plots (the results are written; `pistondyn plot "
                  << outDir_ << "` draws them later): " << e.what() << "\n";
      }
    }
    return kExitOk;
  }

 private:
  std::string deck_, outDir_, warmStart_;
  std::vector<std::string> overrides_;
  std::string logLevel_ = "warn", fidelity_ = "full";
  bool quiet_ = false, noPlot_ = false;
};

}  // namespace

std::unique_ptr<Subcommand> addRunCommand(CLI::App& program) {
  return std::make_unique<RunCommand>(program);
}

}  // namespace pistondyn::app
