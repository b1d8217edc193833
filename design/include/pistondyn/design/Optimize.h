#pragma once
/// @file
/// `pistondyn optimize OPT.yaml --out DIR`: the design variables (DesignStudy.h) chosen to
/// minimise an objective of the run's figures under constraints on others. README.md,
/// "Design optimisation", documents the deck:
///
/// ~~~
///   objective: fmep_kPa                 # or {fmep_kPa: 1, slap_energy_max_mJ: 0.2}: a
///                                       # weighted sum of figures (Figures.h)
///   constraints:                        # each {min: a} and/or {max: b}
///     min_h_over_sigma_thrust: {min: 1.0}
///     slap_energy_max_mJ: {max: 2.0}
///   method:
///     doe_samples: 12       # Latin hypercube over the bounds (default 4 x variables + 4)
///     seed: 1               # of the hypercube (and of ISRES)
///     starts: 2             # local searches from the best DOE points (default 1)
///     local: cobyla         # cobyla (constraints) or bobyqa (bounds only)
///     max_evaluations: 60   # per local search
///     tolerance: 1e-3       # on the variables, relative to their ranges
///     initial_step: 0.1     # the local search's first step, relative to the ranges
///     constraint_tolerance: 1e-4   # relative to each bound
///     global: none          # or isres: NLopt's ISRES over the bounds first
///     global_evaluations: 200
/// ~~~
///
/// The loop: the baseline (the base deck as it is) and the Latin-hypercube points are
/// evaluated together; local searches (NLopt, in coordinates scaled to [0, 1]) start from
/// the best of them, side by side; every evaluation is a case run by an Executor
/// (Evaluations.h: threads or MPI ranks, resumable). A run that fails is infeasible: the
/// search sees a penalty above every objective of the DOE and violated constraints. The
/// optimum is the best feasible design evaluated (the baseline excluded).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pistondyn/design/DesignStudy.h"
#include "pistondyn/design/Evaluations.h"

namespace pistondyn::design {

/// One term of the objective: weight x figure, summed over the terms and minimised.
struct ObjectiveTerm {
  std::string figure;  ///< Figures.h
  double weight = 1.0;  ///< deck `objective: {figure: weight}`; 1 for a single figure
};

/// A bound on one figure of the run (deck `constraints`); at least one of the two is set.
struct DesignConstraint {
  std::string figure;  ///< Figures.h
  ///@{
  std::optional<double> minimum, maximum;  ///< figure >= minimum, figure <= maximum
  ///@}
};

/// The deck's `method` section (this file's comment has the keys and defaults).
struct OptimizeMethod {
  long doeSamples = 0;  ///< 0: 4 x variables + 4
  std::uint64_t seed = 1;  ///< of the Latin hypercube and of ISRES
  int starts = 1;  ///< local searches, each from one of the best DOE points
  std::string local;  ///< "cobyla" or "bobyqa"; "" : cobyla with constraints, else bobyqa
  int maxEvaluations = 60;  ///< per local search
  double tolerance = 1e-3;  ///< on the variables, relative to their ranges
  double initialStep = 0.1;  ///< the local search's first step, relative to the ranges
  double constraintTolerance = 1e-4;  ///< relative to each bound
  std::string global = "none";  ///< "none" or "isres" (NLopt's ISRES over the bounds first)
  int globalEvaluations = 200;  ///< evaluations of the global search
};

/// OPT.yaml read and checked (loadOptimizeDeck).
struct OptimizeSpec {
  DesignStudy study;  ///< the variables and what every evaluation shares
  std::vector<ObjectiveTerm> objective;  ///< summed, minimised
  std::vector<DesignConstraint> constraints;  ///< may be empty
  OptimizeMethod method;  ///< the loop's settings
  std::string description;  ///< the normalised deck as JSON (design.json)
  std::string fingerprint;  ///< SHA-256 of the kind, the context and the description
};

/// Reads and checks OPT.yaml; `commandLineOverrides` are shared by every evaluation. Throws
/// io::DeckError listing every problem ("opt.yaml:12: objective: ...").
OptimizeSpec loadOptimizeDeck(const std::string& path,
                              const std::vector<std::string>& commandLineOverrides = {},
                              const io::LinerRegistry& registry = io::LinerRegistry::getGlobal());

/// One evaluation as the optimiser saw it.
struct DesignPoint {
  std::string stage;      ///< "baseline", "doe", "global", "local 1", ...
  std::vector<double> x;  ///< variables in their units (empty for the baseline)
  EvaluationResult result;  ///< the run (its folder, summary.json, failure message)
  std::optional<double> objective;                      ///< nullopt: failed
  std::vector<std::optional<double>> constraintValues;  ///< the figures, per constraint
  double violation = 0.0;  ///< largest constraint violation relative to its bound (0: none)
  bool feasible = false;   ///< ok, every constraint within the tolerance
};

/// One local search of the loop.
struct LocalSearchSummary {
  std::string stage;  ///< "local 1", "local 2", ... (DesignPoint::stage of its evaluations)
  std::vector<double> start;  ///< its starting design, variables in their units
  int evaluations = 0;              ///< requests the search made (repeats included)
  std::string stopReason;           ///< NLopt's
  std::optional<std::size_t> best;  ///< index in the history
};

/// What runOptimization() found: every evaluation in order, the local searches and the
/// optimum.
struct OptimizeOutcome {
  std::vector<DesignPoint> history;  ///< baseline, DOE, global, each local search in turn
  std::vector<LocalSearchSummary> searches;  ///< in start order
  std::optional<std::size_t> optimum;  ///< best feasible (not the baseline)
  double failurePenalty = 0.0;         ///< objective a failed run showed the searches
};

/// One line per finished stage or evaluation, for the progress display (any thread).
using OptimizeProgress = std::function<void(const std::string& line)>;

/// Runs the loop of this file's comment on `executor`; a failed run is an infeasible point,
/// not an exception.
OptimizeOutcome runOptimization(
const OptimizeSpec& spec, Executor& executor,
                                const OptimizeProgress& progress = {});

/// The evaluation's figures as the optimiser reads them (a missing figure fails it).
DesignPoint assessPoint(const OptimizeSpec& spec, std::string stage, std::vector<double> x,
                        EvaluationResult result);

/// history.csv: '#' lines, then per evaluation request: number, stage, the variables,
/// objective, each constraint's figure, violation, feasible, status, evaluation folder
/// (relative to DIR), message. Nothing that depends on timing or on which worker ran it.
std::string makeHistoryCsv(const OptimizeSpec& spec, const OptimizeOutcome& outcome);

/// A deck file equal to `baseDeckPath` with `overrides` applied, file paths made absolute
/// (so it runs from any folder), with '#' lines naming where it came from.
std::string makeDeckWithOverrides(const std::string& baseDeckPath,
                                  const std::vector<std::string>& overrides,
                                  const std::vector<std::string>& headerLines);

}  // namespace pistondyn::design
