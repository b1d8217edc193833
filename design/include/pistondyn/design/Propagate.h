#pragma once
/// @file
/// `pistondyn propagate PROP.yaml --out DIR`: what the uncertain inputs of a deck cost in
/// certainty. A Latin hypercube over the inputs' ranges (uniform), each sample a run, and
/// the 5 / 50 / 95 % points of the run's figures and, at every output crank angle, of its
/// curves. README.md, "Uncertainty bands", documents the deck:
///
/// ~~~
///   inputs:                          # DesignStudy's variables: [lower, upper], uniform
///     piston.mass_g: [70, 80]
///   est_inputs: 0.1                  # optional: every number the base deck's comment
///                                    # marks EST, varied by +-10 % of its value (a key under
///                                    # inputs keeps its range, one under set or --set its
///                                    # value; zeros are left out)
///   samples: 32                      # Latin-hypercube samples (default 32)
///   seed: 1
///   figures: [fmep_kPa, min_h_over_sigma, slap_energy_max_mJ]    # default these
///   curves: [u_lat_um, tilt_mrad]    # cycle.csv columns, default these
/// ~~~
///
/// Percentiles are of the samples that ran (linear interpolation between order statistics,
/// numpy's default: the p-quantile of x(0) <= ... <= x(n-1) is x(k) + f (x(k+1) - x(k))
/// with k + f = (n - 1) p). For one input and a response linear in it, a Latin hypercube's
/// p-quantile lies within (range of the response) / n of the exact one: each sample is in
/// its own of the n equal strata.

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pistondyn/design/DesignStudy.h"
#include "pistondyn/design/Evaluations.h"

namespace pistondyn::design {

/// PROP.yaml read and checked (loadPropagateDeck): the study, the sample count and seed,
/// and which figures and curves get bands.
struct PropagateSpec {
  DesignStudy study;  ///< its variables are the uncertain inputs (uniform over their range)
  long samples = 32;  ///< Latin-hypercube samples (deck `samples`)
  std::uint64_t seed = 1;  ///< seed of the Latin hypercube (deck `seed`): same seed, same samples
  ///@{
  /// summary.json figures and cycle.csv curves that get bands (deck `figures`, `curves`).
  std::vector<std::string> figures, curves;
  ///@}
  std::vector<std::string> estKeys;     ///< inputs taken from the deck's EST marks
  std::vector<std::string> estSkipped;  ///< EST-marked numbers left out (zero), for the report
  ///@{
  /// The study's normalised content (design.json) and the SHA-256 hex of what decides its
  /// results (openDesignFolder()).
  std::string description, fingerprint;
  ///@}
};

/// Reads and checks PROP.yaml (this file's comment) with the command line's --set
/// assignments. Throws io::DeckError listing every problem found.
PropagateSpec loadPropagateDeck(const std::string& path,
                                const std::vector<std::string>& commandLineOverrides = {},
                                const io::LinerRegistry& registry = io::LinerRegistry::getGlobal());

/// The p-quantile (0 <= p <= 1) of values, linear between order statistics; NaN if empty.
double calcQuantile(std::vector<double> values, double p);

/// Statistics of one quantity over the samples that ran: the 5 / 50 / 95 % points
/// (calcQuantile), mean, sample standard deviation (n - 1; 0 for one value), minimum and
/// maximum, in the quantity's unit; all NaN when there are no values.
struct Band {
  ///@{
  /// See Band.
  double p05 = 0.0, p50 = 0.0, p95 = 0.0, mean = 0.0, std = 0.0, min = 0.0, max = 0.0;
  ///@}
  int count = 0;  ///< values the statistics are of
};
/// The Band of `values`.
Band calcBand(const std::vector<double>& values);

/// What runPropagation() found: the samples and their runs, the figures' bands and the
/// curves' bands at every output crank angle of the last cycle, and the baseline run.
struct PropagateOutcome {
  std::vector<std::vector<double>> samples;  ///< inputs per sample
  std::vector<EvaluationResult> runs;        ///< per sample
  EvaluationResult baseline;  ///< the base deck with the shared overrides only
  std::vector<std::vector<std::optional<double>>> figureValues;  ///< [sample][figure]
  std::map<std::string, Band> figureBands;                       ///< per figure
  std::vector<double> angle_deg;                        ///< the curves' crank angles (last cycle)
  std::map<std::string, std::vector<Band>> curveBands;  ///< per curve, per angle
  /// The baseline run's curves at angle_deg, per curve; empty when the baseline failed or
  /// its crank angles differ from the samples'.
  std::map<std::string, std::vector<double>> baselineCurves;
  int failed = 0;  ///< samples whose run failed (left out of the bands)
};

/// Receives one line of progress text per event (may be empty: no progress).
using PropagateProgress = std::function<void(const std::string& line)>;

/// Runs the baseline and the Latin-hypercube samples on `executor` and computes the bands.
/// A failed sample is counted in PropagateOutcome::failed, not thrown; throws
/// std::runtime_error when two samples' runs have different crank angles, or a result folder
/// cannot be read.
PropagateOutcome runPropagation(
const PropagateSpec& spec, Executor& executor,
                                const PropagateProgress& progress = {});

/// samples.csv: per sample its inputs, status, the figures, evaluation folder, message.
std::string makeSamplesCsv(const PropagateSpec& spec, const PropagateOutcome& outcome);
/// bands.csv: crank_angle_deg, then per curve `<curve>_p05`, `_p50`, `_p95`, `_baseline`.
std::string makeBandsCsv(const PropagateSpec& spec, const PropagateOutcome& outcome);

/// The numeric keys of a deck file whose line comment holds the word EST: key path (as
/// --set takes it) and value, in file order. Block-style YAML as the example decks are
/// written; flow sections and lists are not looked into.
std::vector<std::pair<std::string, double>> findEstimatedKeys(const std::string& deckPath);

}  // namespace pistondyn::design
