// pistondyn propagate PROP.yaml --out DIR [--jobs N] [--set key.path=value]... [--quiet]
//
// Uncertainty bands (design/Propagate.h): a Latin hypercube over the uncertain inputs
// (listed with ranges, or the base deck's EST-marked numbers +- a share), each sample a
// case of the sweep machinery on threads or MPI ranks (DesignSupport.h), resumable; the 5 /
// 50 / 95 % points of the figures and of the curves. Writes
//   DIR/design.json, DIR/evaluations/<id>/   as every design study
//   DIR/samples.csv           per sample: inputs, status, figures
//   DIR/bands.csv             per output crank angle: each curve's 5 / 50 / 95 % and baseline
//   DIR/result.json           the figures' percentiles, mean, standard deviation, baseline
//   DIR/report.html           DesignReport.h

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "DesignReport.h"
#include "DesignSupport.h"
#include "Subcommand.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/design/Figures.h"
#include "pistondyn/design/Propagate.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/Version.h"

namespace pistondyn::app {
namespace {

using Json = nlohmann::ordered_json;
using common::formatNumber;

Json number(double v) {
  return std::isfinite(v) ? Json(v) : Json(nullptr);
}

class PropagateTask final : public DesignTask {
 public:
  explicit PropagateTask(const DesignOptions& options) : options_(options) {}

  int prepare() override {
    if (const int code = checkDesignOutPath(options_.outDir); code != kExitOk)
      return code;
    const auto failed = reportPrepareError("propagation", [&] {
      spec_.emplace(design::loadPropagateDeck(options_.deck, options_.overrides));
      folder_ = design::openDesignFolder(options_.outDir, "propagate", spec_->fingerprint,
                                         spec_->description);
      store_.emplace(folder_.dir, spec_->study.baseDeckPath, spec_->study.fixedOverrides,
                     spec_->study.contextSha256);
    });
    return failed.value_or(kExitOk);
  }

  const design::EvaluationStore& getStore() const override { return *store_; }

  int run(design::Executor& executor) override {
    const ProgressPrinter progress("propagate", options_.quiet);
    if (folder_.resumed)
      progress("resuming " + options_.outDir + ": evaluations found there are not run again");
    design::PropagateOutcome o;
    try {
      o = design::runPropagation(*spec_, executor, [&](const std::string& l) { progress(l); });
      writeResults(o, executor);
    } catch (const std::exception& e) {
      std::cerr << "pistondyn: the propagation failed: " << e.what() << "\n";
      return kExitFailed;
    }
    return o.failed > 0 ? kExitSomeCasesFailed : kExitOk;
  }

 private:
  void writeResults(const design::PropagateOutcome& o, const design::Executor& executor) {
    const design::PropagateSpec& spec = *spec_;
    Json result;
    result["pistondyn_version"] = io::getVersion();
    result["study"] = spec.study.deckPath;
    result["fingerprint"] = spec.fingerprint;
    result["samples"] = o.samples.size();
    result["failed"] = o.failed;
    result["evaluations_run_now"] = executor.getRunCount();
    result["evaluations_from_earlier_run"] = executor.getEarlierCount();
    Json inputs = Json::array();
    for (const auto& v : spec.study.variables) {
      const bool est =
          std::find(spec.estKeys.begin(), spec.estKeys.end(), v.key) != spec.estKeys.end();
      inputs.push_back({{"key", v.key},
                        {"lower", v.lower},
                        {"upper", v.upper},
                        {"baseline", v.baseline ? Json(*v.baseline) : Json(nullptr)},
                        {"from", est ? "EST" : "inputs"}});
    }
    result["inputs"] = inputs;
    result["est_zero_not_varied"] = spec.estSkipped;
    std::optional<design::RunFigures> base;
    if (o.baseline.ok)
      base.emplace(o.baseline.summaryJson);
    Json figures = Json::object();
    for (const auto& f : spec.figures) {
      const design::Band& b = o.figureBands.at(f);
      figures[f] = {
          {"p05", number(b.p05)},
          {"p50", number(b.p50)},
          {"p95", number(b.p95)},
          {"mean", number(b.mean)},
          {"std", number(b.std)},
          {"min", number(b.min)},
          {"max", number(b.max)},
          {"samples", b.count},
          {"baseline", base ? number(base->get(f).value_or(std::nan(""))) : Json(nullptr)}};
    }
    result["figures"] = figures;
    io::writeFilesAtomically(
        folder_.dir,
        {{"result.json", result.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"},
         {"samples.csv", design::makeSamplesCsv(spec, o)},
         {"bands.csv", design::makeBandsCsv(spec, o)},
         {"report.html", makePropagateReport(spec, o)}});
    std::printf("pistondyn propagate: %zu samples over %zu inputs (%d failed)\n", o.samples.size(),
                spec.study.variables.size(), o.failed);
    for (const auto& f : spec.figures) {
      const design::Band& b = o.figureBands.at(f);
      std::printf("  %s: 5 %% %s, 50 %% %s, 95 %% %s\n", f.c_str(), formatNumber(b.p05).c_str(),
                  formatNumber(b.p50).c_str(), formatNumber(b.p95).c_str());
    }
    std::printf("  wrote %s/result.json, samples.csv, bands.csv and report.html\n",
                options_.outDir.c_str());
  }

  const DesignOptions& options_;
  std::optional<design::PropagateSpec> spec_;
  design::DesignFolder folder_;
  std::optional<design::EvaluationStore> store_;
};

class PropagateCommand final : public Subcommand {
 public:
  explicit PropagateCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "propagate",
            "uncertainty bands: a Latin hypercube over uncertain inputs (listed ranges, or the "
            "base deck's EST-marked numbers +- a share) and the 5 / 50 / 95 % of the figures "
            "and of the secondary-motion curves; each sample a case run on all cores or MPI "
            "ranks")) {
    addDesignOptions(*app_, options_, "PROP.yaml",
                     "propagation deck (YAML: base_deck, set, inputs, est_inputs, profile, "
                     "samples, seed, figures, curves; README.md, Uncertainty bands)",
                     "output folder (created if needed): design.json, evaluations/<id>/, "
                     "samples.csv, bands.csv, result.json, report.html; a folder of the same "
                     "propagation is resumed, one of another refused");
    app_->footer(
        "Inputs are uniform over their ranges; percentiles are linear between order statistics "
        "(numpy's\ndefault). Under `mpirun -np K pistondyn propagate ...` the ranks share the "
        "samples with the same\nresult.\n"
        "Exit codes: 0 every sample ran; 1 bad input (deck, input, figure, curve), nothing "
        "written; 2 bad\ncommand line or --out refused, nothing written; 3 the results could not "
        "be written; 4 some\nsamples failed (listed in samples.csv; the bands are of the others).");
  }
  int execute() override {
    PropagateTask task(options_);
    return runDesignTask(options_, task);
  }

 private:
  DesignOptions options_;
};

}  // namespace

std::unique_ptr<Subcommand> addPropagateCommand(CLI::App& program) {
  return std::make_unique<PropagateCommand>(program);
}

}  // namespace pistondyn::app
