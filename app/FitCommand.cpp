// pistondyn fit FIT.yaml --out DIR [--jobs N] [--set key.path=value]... [--quiet]
//
// Named uncertain inputs of a base deck calibrated to measured traces by bounded least
// squares (design/Fit.h); every evaluation a case of the sweep machinery on threads or MPI
// ranks (DesignSupport.h), resumable. Writes
//   DIR/design.json, DIR/evaluations/<id>/   as every design study
//   DIR/result.json           fitted values, standard errors or why a parameter is not
//                             identifiable, correlations, sum of squares, rank
//   DIR/residuals.csv         measured, fitted and residual at every measured angle
//   DIR/history.csv           the Levenberg-Marquardt steps
//   DIR/fitted/engine.yaml    the base deck with the fitted values; fitted/run/ its run
//   DIR/report.html           DesignReport.h

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "DesignReport.h"
#include "DesignSupport.h"
#include "Subcommand.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/design/Fit.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/Version.h"

namespace pistondyn::app {
namespace {

using Json = nlohmann::ordered_json;
using common::formatNumber;

Json number(double v) {
  return std::isfinite(v) ? Json(v) : Json(nullptr);
}

class FitTask final : public DesignTask {
 public:
  explicit FitTask(const DesignOptions& options) : options_(options) {}

  int prepare() override {
    if (const int code = checkDesignOutPath(options_.outDir); code != kExitOk)
      return code;
    const auto failed = reportPrepareError("fit", [&] {
      spec_.emplace(design::loadFitDeck(options_.deck, options_.overrides));
      folder_ =
          design::openDesignFolder(options_.outDir, "fit", spec_->fingerprint, spec_->description);
      store_.emplace(folder_.dir, spec_->study.baseDeckPath, spec_->study.fixedOverrides,
                     spec_->study.contextSha256);
    });
    return failed.value_or(kExitOk);
  }

  const design::EvaluationStore& getStore() const override { return *store_; }

  int run(design::Executor& executor) override {
    const ProgressPrinter progress("fit", options_.quiet);
    if (folder_.resumed)
      progress("resuming " + options_.outDir + ": evaluations found there are not run again");
    const design::FitOutcome o =
        design::runFit(*spec_, executor, [&](const std::string& l) { progress(l); });
    if (!o.ok) {
      std::cerr << "pistondyn: the fit failed: " << o.message << "\n";
      return kExitFailed;
    }
    try {
      writeResults(o, executor);
    } catch (const std::exception& e) {
      std::cerr << "pistondyn: the fit's results could not be written: " << e.what() << "\n";
      return kExitFailed;
    }
    return kExitOk;
  }

 private:
  void writeResults(const design::FitOutcome& o, const design::Executor& executor) {
    const design::FitSpec& spec = *spec_;
    Json result;
    result["pistondyn_version"] = io::getVersion();
    result["study"] = spec.study.deckPath;
    result["fingerprint"] = spec.fingerprint;
    result["stopped"] = o.stopReason;
    result["steps"] = o.iterations.size() - 1;
    result["points"] = o.points;
    result["sum_of_squares"] = o.sumOfSquares;
    result["residual_standard_deviation"] = o.residualStd;
    result["jacobian_rank"] = o.rank;
    result["evaluations_run_now"] = executor.getRunCount();
    result["evaluations_from_earlier_run"] = executor.getEarlierCount();
    result["evaluation"] = "evaluations/" + o.best.id;
    Json params = Json::array();
    for (const auto& p : o.parameters) {
      Json j;
      j["key"] = p.key;
      j["start"] = p.start;
      j["value"] = p.identifiable ? Json(p.value) : Json(nullptr);
      j["last_value"] = p.value;
      j["standard_error"] = p.standardError ? Json(*p.standardError) : Json(nullptr);
      j["identifiable"] = p.identifiable;
      j["at_bound"] = p.atBound;
      j["note"] = p.note;
      params.push_back(j);
    }
    result["parameters"] = params;
    Json corr = Json::array();
    for (const auto& row : o.correlation) {
      Json r = Json::array();
      for (const double c : row)
        r.push_back(number(c));
      corr.push_back(r);
    }
    result["correlation"] = corr;
    writeDesignDeck(spec.study, o.bestX, o.best.folder,
                    (std::filesystem::path(folder_.dir) / "fitted").string(),
                    {"pistondyn fit: the fitted values of " + spec.study.deckPath +
                     " (sum of squares " + formatNumber(o.sumOfSquares) + ")"});
    io::writeFilesAtomically(
        folder_.dir,
        {{"result.json", result.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"},
         {"residuals.csv", design::makeResidualsCsv(spec, o)},
         {"history.csv", design::makeFitHistoryCsv(spec, o)},
         {"report.html", makeFitReport(spec, o)}});
    std::printf(
        "pistondyn fit: %s after %zu steps; %d points, sum of squares %s, residual "
        "standard deviation %s\n",
        o.stopReason.c_str(), o.iterations.size() - 1, o.points,
        formatNumber(o.sumOfSquares).c_str(), formatNumber(o.residualStd).c_str());
    for (const auto& p : o.parameters) {
      if (p.identifiable)
        std::printf("  %s = %s +- %s (one standard error)%s\n", p.key.c_str(),
                    formatNumber(p.value).c_str(), formatNumber(*p.standardError).c_str(),
                    p.atBound ? " at a bound" : "");
      else
        std::printf("  %s: %s\n", p.key.c_str(), p.note.c_str());
    }
    std::printf(
        "  wrote %s/result.json, residuals.csv, history.csv, fitted/engine.yaml and "
        "report.html\n",
        options_.outDir.c_str());
  }

  const DesignOptions& options_;
  std::optional<design::FitSpec> spec_;
  design::DesignFolder folder_;
  std::optional<design::EvaluationStore> store_;
};

class FitCommand final : public Subcommand {
 public:
  explicit FitCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "fit",
            "calibrate uncertain deck inputs to measured traces (tilt, lateral displacement "
            "against crank angle) by bounded least squares, with standard errors and "
            "correlations; each evaluation a case run on all cores or MPI ranks")) {
    addDesignOptions(*app_, options_, "FIT.yaml",
                     "fit deck (YAML: base_deck, set, parameters, profile, measured, method; "
                     "README.md, Calibration)",
                     "output folder (created if needed): design.json, evaluations/<id>/, "
                     "result.json, residuals.csv, history.csv, fitted/engine.yaml and "
                     "fitted/run/, report.html; a folder of the same fit is resumed, one of "
                     "another refused");
    app_->footer(
        "Bounded Levenberg-Marquardt in parameters scaled to their bounds, each Jacobian one "
        "batch of\ncentral differences run side by side. Standard errors and correlations "
        "from the Jacobian\nat the optimum (s^2 (J'J)^-1, s^2 = SSR / (points - parameters)); "
        "a parameter the traces cannot\ndetermine (a zero or dependent column, rank "
        "tolerance; or a correlation beyond the limit) is\nreported as not identifiable, "
        "without a value. Measured traces: CSV crank_angle_deg,<column>\nwith strictly "
        "increasing angles in 0 .. 720 deg (0 = firing TDC). Under `mpirun -np K pistondyn\n"
        "fit ...` the ranks share the evaluations with the same result.\n"
        "Exit codes: 0 fitted; 1 bad input (deck, parameter, trace file, fewer points than "
        "parameters),\nnothing written; 2 bad command line or --out refused, nothing written; "
        "3 the run at the start\nfailed or the results could not be written.");
  }
  int execute() override {
    FitTask task(options_);
    return runDesignTask(options_, task);
  }

 private:
  DesignOptions options_;
};

}  // namespace

std::unique_ptr<Subcommand> addFitCommand(CLI::App& program) {
  return std::make_unique<FitCommand>(program);
}

}  // namespace pistondyn::app
