// pistondyn plot DIR [--log-level LEVEL]

#include <filesystem>
#include <iostream>
#include <optional>

#include <spdlog/spdlog.h>

#include "CommandSupport.h"
#include "Gnuplot.h"
#include "Logging.h"
#include "ResultPlots.h"
#include "Subcommand.h"
#include "pistondyn/common/Cancellation.h"

namespace pistondyn::app {
namespace {

class PlotCommand final : public Subcommand {
 public:
  explicit PlotCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "plot", "draw the figures of a run's result folder into DIR/plots/*.png (gnuplot)")) {
    app_->add_option("DIR", dir_,
                     "a folder `pistondyn run --out DIR` wrote (cycle.csv, summary.json, field "
                     "dumps)")
        ->required()
        ->type_name("DIR");
    addLogLevelOption(*app_, logLevel_);
    app_->set_help_flag("-h,--help", "print this help and exit");
    app_->footer(
        "Figures (PNG, 1200 px wide) over the last 720 deg cycle, crank angle 0 deg = firing "
        "TDC:\n  crank_train_forces (kN, N m), side_force (N, N m); with the lubricated skirt "
        "also\n  secondary_motion (um, mrad), friction (N, W), film_thickness (um, h/sigma),\n"
        "  regime_shares (area shares), field_map_<angle>deg (MPa, fill fraction, um) per "
        "field dump.\ngnuplot: $PISTONDYN_GNUPLOT or the first gnuplot on PATH (Debian package "
        "gnuplot).\nExit codes: 0 ok; 1 DIR is not a result folder, or its summary.json or "
        "cycle.csv\nis not as run writes it (the file and what is wrong named); 2 bad command "
        "line, or\nanother pistondyn process is writing DIR now; 3 plotting failed (gnuplot "
        "missing or\nfailing), no figure changed; 130 / 143 interrupted, no figure changed.");
  }

  int execute() override {
    setUpLogging(logLevel_);
    // One process at a time writes the folder (a run finishing there, another plot).
    std::optional<io::OutputFolderLock> lock;
    if (std::filesystem::is_directory(dir_)) {
      if (const int refused = lockOutputFolder(dir_, lock, "", "nothing was written");
          refused != kExitOk)
        return refused;
    }
    io::ResultFolder folder;
    try {
      folder = io::readResultFolder(dir_);
      checkResultPlotColumns(folder);
    } catch (const std::exception& e) {
      std::cerr << "pistondyn: cannot plot: " << e.what() << "\n";
      return kExitBadInput;
    }
    try {
      const auto files = writeResultPlots(folder);
      std::cout << "pistondyn: wrote " << files.size() << " figures to " << dir_ << "/plots/\n";
      for (const auto& f : files)
        spdlog::info("plot: {}", f);
    } catch (const common::Cancelled&) {
      throw;  // main reports it; no figure changed
    } catch (const GnuplotMissing& e) {
      std::cerr << "pistondyn: no plots: " << e.what() << "\n";
      return kExitFailed;
    } catch (const std::exception& e) {
      std::cerr << "pistondyn: plotting failed, no figure changed: " << e.what() << "\n";
      return kExitFailed;
    }
    return kExitOk;
  }

 private:
  std::string dir_, logLevel_ = "warn";
};

}  // namespace

std::unique_ptr<Subcommand> addPlotCommand(CLI::App& program) {
  return std::make_unique<PlotCommand>(program);
}

}  // namespace pistondyn::app
