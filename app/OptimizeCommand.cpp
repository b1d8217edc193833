// pistondyn optimize OPT.yaml --out DIR [--jobs N] [--set key.path=value]... [--quiet]
//
// The design variables of an optimisation deck (design/Optimize.h) chosen to minimise its
// objective under its constraints; every evaluation a case of the sweep machinery on
// threads or MPI ranks (DesignSupport.h), resumable. Writes
//   DIR/design.json           the study (kind, fingerprint), written first
//   DIR/evaluations/<id>/     one run folder per distinct design
//   DIR/history.csv           every design the optimiser evaluated, stage by stage
//   DIR/optimum/engine.yaml   the base deck with the optimum's values (and its
//                             skirt_profile.csv), runnable anywhere; optimum/run/ its results
//   DIR/result.json           the optimum, the baseline, the constraints, the searches
//   DIR/report.html           DesignReport.h

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "DesignReport.h"
#include "DesignSupport.h"
#include "Subcommand.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/design/Figures.h"
#include "pistondyn/design/Optimize.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/Version.h"

namespace pistondyn::app {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using common::formatNumber;

Json pointJson(const design::OptimizeSpec& spec, const design::DesignPoint& p, std::size_t number) {
  Json j;
  j["history_number"] = number;
  j["stage"] = p.stage;
  j["evaluation"] = p.result.id.empty() ? Json(nullptr) : Json("evaluations/" + p.result.id);
  Json vars = Json::object();
  for (std::size_t i = 0; i < spec.study.variables.size(); ++i) {
    if (std::isfinite(p.x[i]))
      vars[spec.study.variables[i].key] = p.x[i];
  }
  j["variables"] = vars;
  j["objective"] = p.objective ? Json(*p.objective) : Json(nullptr);
  j["feasible"] = p.feasible;
  Json figures = Json::object();
  for (std::size_t c = 0; c < spec.constraints.size(); ++c)
    figures[spec.constraints[c].figure] =
        p.constraintValues[c] ? Json(*p.constraintValues[c]) : Json(nullptr);
  j["constraint_figures"] = figures;
  if (!p.result.ok)
    j["message"] = p.result.message;
  return j;
}

class OptimizeTask final : public DesignTask {
 public:
  explicit OptimizeTask(const DesignOptions& options) : options_(options) {}

  int prepare() override {
    if (const int code = checkDesignOutPath(options_.outDir); code != kExitOk)
      return code;
    const auto failed = reportPrepareError("optimisation", [&] {
      spec_.emplace(design::loadOptimizeDeck(options_.deck, options_.overrides));
      folder_ = design::openDesignFolder(options_.outDir, "optimize", spec_->fingerprint,
                                         spec_->description);
      store_.emplace(folder_.dir, spec_->study.baseDeckPath, spec_->study.fixedOverrides,
                     spec_->study.contextSha256);
    });
    return failed.value_or(kExitOk);
  }

  const design::EvaluationStore& getStore() const override { return *store_; }

  int run(design::Executor& executor) override {
    const ProgressPrinter progress("optimize", options_.quiet);
    if (folder_.resumed)
      progress("resuming " + options_.outDir + ": evaluations found there are not run again");
    const design::OptimizeOutcome o =
        design::runOptimization(*spec_, executor, [&](const std::string& l) { progress(l); });
    try {
      writeResults(o, executor);
    } catch (const std::exception& e) {
      std::cerr << "pistondyn: the optimisation's results could not be written: " << e.what()
                << "\n";
      return kExitFailed;
    }
    return o.optimum ? kExitOk : kExitSomeCasesFailed;
  }

 private:
  void writeResults(const design::OptimizeOutcome& o, const design::Executor& executor) {
    const design::OptimizeSpec& spec = *spec_;
    const std::string dir = folder_.dir;
    std::vector<std::pair<std::string, std::string>> top = {
        {"history.csv", design::makeHistoryCsv(spec, o)}};
    Json result;
    result["pistondyn_version"] = io::getVersion();
    result["study"] = spec.study.deckPath;
    result["fingerprint"] = spec.fingerprint;
    result["status"] = o.optimum ? "optimum found" : "no feasible design";
    result["designs"] = o.history.size();
    result["evaluations_run_now"] = executor.getRunCount();
    result["evaluations_from_earlier_run"] = executor.getEarlierCount();
    result["baseline"] = pointJson(spec, o.history.front(), 1);
    result["optimum"] =
        o.optimum ? pointJson(spec, o.history[*o.optimum], *o.optimum + 1) : Json(nullptr);
    Json searches = Json::array();
    for (const auto& s : o.searches) {
      searches.push_back({{"stage", s.stage},
                          {"nlopt_evaluations", s.evaluations},
                          {"stopped", s.stopReason},
                          {"best_history_number", s.best ? Json(*s.best + 1) : Json(nullptr)}});
    }
    result["searches"] = searches;
    if (o.optimum) {
      const design::DesignPoint& best = o.history[*o.optimum];
      const design::RunFigures figures(best.result.summaryJson);
      Json active = Json::array();
      for (const auto& c : spec.constraints) {
        const double v = figures.get(c.figure).value_or(std::nan(""));
        for (const auto& b : {c.minimum, c.maximum}) {
          if (b && std::fabs(v - *b) / (*b != 0.0 ? std::fabs(*b) : 1.0) <= kActiveConstraintShare)
            active.push_back(c.figure);
        }
      }
      result["active_constraints"] = active;
      writeDesignDeck(
          spec.study, best.x, best.result.folder, (std::filesystem::path(dir) / "optimum").string(),
          {"pistondyn optimize: the optimum of " + spec.study.deckPath + " (history.csv number " +
           std::to_string(*o.optimum + 1) + ", objective " + formatNumber(*best.objective) + ")"});
    }
    top.emplace_back("result.json",
                     result.dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
    top.emplace_back("report.html", makeOptimizeReport(spec, o));
    io::writeFilesAtomically(dir, top);
    // The closing report on stdout.
    std::printf(
        "pistondyn optimize: %zu designs evaluated (%d runs now, %d found from an earlier "
        "run)\n",
        o.history.size(), executor.getRunCount(), executor.getEarlierCount());
    if (o.optimum) {
      const design::DesignPoint& best = o.history[*o.optimum];
      std::printf("  optimum (history.csv number %zu, %s): objective %s", *o.optimum + 1,
                  best.stage.c_str(), formatNumber(*best.objective).c_str());
      if (o.history.front().objective)
        std::printf(" (baseline %s)", formatNumber(*o.history.front().objective).c_str());
      std::printf("\n");
      for (std::size_t i = 0; i < spec.study.variables.size(); ++i)
        std::printf("    %s = %s\n", spec.study.variables[i].key.c_str(),
                    formatNumber(best.x[i]).c_str());
      std::printf(
          "  wrote %s/history.csv, %s/optimum/engine.yaml (its run in optimum/run/), "
          "%s/result.json and %s/report.html\n",
          options_.outDir.c_str(), options_.outDir.c_str(), options_.outDir.c_str(),
          options_.outDir.c_str());
    } else {
      std::printf(
          "  no feasible design found; wrote %s/history.csv, %s/result.json and "
          "%s/report.html\n",
          options_.outDir.c_str(), options_.outDir.c_str(), options_.outDir.c_str());
    }
  }

  const DesignOptions& options_;
  std::optional<design::OptimizeSpec> spec_;
  design::DesignFolder folder_;
  std::optional<design::EvaluationStore> store_;
};

class OptimizeCommand final : public Subcommand {
 public:
  explicit OptimizeCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "optimize",
            "choose design variables (numeric deck keys, a parametric skirt profile) that "
            "minimise an objective (fmep, friction power, slap energy, a weighted sum) under "
            "constraints, with NLopt; each evaluation a case run on all cores or MPI ranks")) {
    addDesignOptions(
        *app_, options_, "OPT.yaml",
        "optimisation deck (YAML: base_deck, set, variables, profile, objective, constraints, "
        "method; README.md, Design optimisation)",
        "output folder (created if needed): design.json, evaluations/<id>/ (one run per "
        "design), history.csv, optimum/engine.yaml and optimum/run/, result.json, "
        "report.html; a folder of the same optimisation is resumed, one of another refused");
    app_->footer(
        "The baseline and a Latin-hypercube DOE are evaluated first; local searches (NLopt "
        "COBYLA with\nconstraints, BOBYQA for bounds only; in coordinates scaled to the bounds) "
        "start from the best\nDOE points, side by side; method.global: isres adds NLopt's ISRES "
        "before them. A failed run is\ninfeasible. Under `mpirun -np K pistondyn optimize ...` "
        "the ranks share the evaluations with\nthe same history and optimum. Rerunning the "
        "command after an interruption replays the search\nand runs only what is missing.\n"
        "Exit codes: 0 optimum found; 1 bad input (deck, variable, figure), nothing written; 2 "
        "bad\ncommand line or --out refused (a file, another study's folder), nothing written; 3 "
        "the\nresults could not be written; 4 no feasible design (history.csv and report.html "
        "say why).");
  }
  int execute() override {
    OptimizeTask task(options_);
    return runDesignTask(options_, task);
  }

 private:
  DesignOptions options_;
};

}  // namespace

std::unique_ptr<Subcommand> addOptimizeCommand(CLI::App& program) {
  return std::make_unique<OptimizeCommand>(program);
}

}  // namespace pistondyn::app
