// pistondyn report DIR [--log-level LEVEL]

#include <filesystem>
#include <iostream>
#include <optional>

#include <spdlog/spdlog.h>

#include "CommandSupport.h"
#include "FieldAnimation.h"
#include "Gnuplot.h"
#include "HtmlReport.h"
#include "Logging.h"
#include "ResultPlots.h"
#include "Subcommand.h"
#include "pistondyn/common/Cancellation.h"
#include "pistondyn/io/ResultWriters.h"

namespace pistondyn::app {
namespace {

class ReportCommand final : public Subcommand {
 public:
  explicit ReportCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "report", "write DIR/report.html: summary, plots, inputs and an animation of the "
                      "secondary motion, in one self-contained file")) {
    app_->add_option("DIR", dir_, "a folder `pistondyn run --out DIR` wrote")
        ->required()
        ->type_name("DIR");
    addLogLevelOption(*app_, logLevel_);
    app_->set_help_flag("-h,--help", "print this help and exit");
    app_->footer(
        "report.html needs no network: images are embedded (base64), style and script inline.\n"
        "It (re)draws DIR/plots/ first (as pistondyn plot); without gnuplot the page says so\n"
        "and has no figures. A headline (fmep, friction power, asperity share, min h/sigma\n"
        "per side, slap, tilt, clearance, convergence) opens it; the summary table gives\n"
        "every figure of summary.json in engineering units (bar, kPa, mm, um, mrad, mJ).\n"
        "The inputs are a table in the deck's units with each value's source (the marks of\n"
        "the deck's comments: EST, [T], ...; --set; default) and the deck's text (deck_file\n"
        "of summary.json, an absolute path). The animation draws the piston over the last\n"
        "cycle, lateral motion, clearance and tilt exaggerated by the factor the page states;\n"
        "with the lubricated skirt a map of each side's film follows it. Exit codes: 0 ok; 1 DIR is not a result folder; 2 bad\n"
        "command line, or another pistondyn process is writing DIR now; 3 writing failed.");
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
    std::string fieldFrames;
    try {
      folder = io::readResultFolder(dir_);
      checkResultPlotColumns(folder);
      fieldFrames = makeFieldAnimationJson(folder);
    } catch (const std::exception& e) {
      std::cerr << "pistondyn: cannot write a report: " << e.what() << "\n";
      return kExitBadInput;
    }
    std::vector<std::string> pngs;
    std::string note;
    try {
      pngs = writeResultPlots(folder);
    } catch (const common::Cancelled&) {
      throw;  // main reports it; no figure changed, no report written
    } catch (const std::exception& e) {
      note = std::string("No plots: ") + e.what();
      std::cerr << "pistondyn: the report has no plots: " << e.what() << "\n";
    }
    try {
      common::throwIfCancelled();
      io::writeFilesAtomically(dir_, {{"report.html", makeHtmlReport(folder, pngs, note, fieldFrames)}});
    } catch (const common::Cancelled&) {
      throw;
    } catch (const std::exception& e) {
      std::cerr << "pistondyn: the report could not be written: " << e.what() << "\n";
      return kExitFailed;
    }
    std::cout << "pistondyn: wrote " << (std::filesystem::path(dir_) / "report.html").string()
              << " (" << pngs.size() << " figures)\n";
    return kExitOk;
  }

 private:
  std::string dir_, logLevel_ = "warn";
};

}  // namespace

std::unique_ptr<Subcommand> addReportCommand(CLI::App& program) {
  return std::make_unique<ReportCommand>(program);
}

}  // namespace pistondyn::app
