// pistondyn run DECK.yaml --out DIR [--set key.path=value]... [--quiet]

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <unistd.h>

#include "CommandSupport.h"
#include "Subcommand.h"
#include "pistondyn/io/RunDeck.h"

namespace pistondyn::app {
namespace {

void printSummary(const io::EngineDeck& deck, const io::RunOutcome& o, const std::string& outDir) {
  const auto& s = o.summary;
  std::printf("pistondyn: %s\n", deck.engine.name.c_str());
  std::printf("  %d cycle(s) at %.0f rpm, %ld rows, %.3f s wall time, %ld integrator steps\n",
              deck.simulation.cycles, deck.engine.drive.speed_radps * 30.0 / M_PI, o.rows,
              o.stats.wallTime_s, o.stats.integratorSteps);
  std::printf("  imep %.1f kPa   peak cylinder pressure %.2f bar at %.1f deg\n", s.imep_Pa / 1e3,
              s.peakCylinderPressure_Pa / 1e5, s.peakCylinderPressureAngle_deg);
  if (s.liner) {
    std::printf("  side force %+.0f N at %.1f deg (thrust), %+.0f N at %.1f deg (anti-thrust)\n",
                s.liner->sideForceMax_N, s.liner->sideForceMaxAngle_deg, s.liner->sideForceMin_N,
                s.liner->sideForceMinAngle_deg);
  } else {
    std::printf("  side force: the model has no liner element\n");
  }
  std::printf("  conrod force %+.0f .. %+.0f N   mean crank torque %.2f N m   power %.2f kW\n",
              s.conrodForceMin_N, s.conrodForceMax_N, s.meanCrankTorque_Nm,
              s.indicatedPower_W / 1e3);
  std::printf("  wrote %s/cycle.csv and %s/summary.json (crank angle 0 = firing TDC)\n",
              outDir.c_str(), outDir.c_str());
}

class RunCommand final : public Subcommand {
 public:
  explicit RunCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "run", "simulate an engine deck and write DIR/cycle.csv and DIR/summary.json")) {
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
    app_->add_flag("--quiet", quiet_, "no progress line (default: progress on a terminal)");
    app_->set_help_flag("-h,--help", "print this help and exit");
    app_->footer(deckHelpFooter());
  }

  int execute() override {
    // Refuse an unusable output path now, not after the simulation.
    std::error_code ec;
    if (std::filesystem::exists(outDir_, ec) && !std::filesystem::is_directory(outDir_, ec)) {
      std::cerr << "pistondyn: --out " << outDir_ << " is not a folder\n";
      return kExitUsage;
    }
    const auto deck = loadDeckOrReport(deck_, overrides_);
    if (!deck)
      return kExitBadInput;
    try {
      // A progress line only makes sense on a terminal; logs get the summary alone.
      const bool showProgress = !quiet_ && isatty(fileno(stderr)) != 0;
      int lastPercent = -1;
      auto progress = [&](double f) {
        const int p = static_cast<int>(f * 100.0);
        if (showProgress && p / 10 != lastPercent / 10) {
          std::fprintf(stderr, "\rpistondyn: %3d %%", p);
          lastPercent = p;
        }
      };
      const io::RunOutcome outcome = io::runDeck(*deck, outDir_, progress);
      if (!quiet_)
        std::fprintf(stderr, "\r");
      printSummary(*deck, outcome, outDir_);
    } catch (const std::exception& e) {
      std::cerr << "\npistondyn: the run failed; no results were written: " << e.what() << "\n";
      return kExitFailed;
    }
    return kExitOk;
  }

 private:
  std::string deck_, outDir_;
  std::vector<std::string> overrides_;
  bool quiet_ = false;
};

}  // namespace

std::unique_ptr<Subcommand> addRunCommand(CLI::App& program) {
  return std::make_unique<RunCommand>(program);
}

}  // namespace pistondyn::app
