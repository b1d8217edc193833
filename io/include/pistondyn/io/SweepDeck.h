#pragma once
/// \file
/// A sweep deck: one base engine deck and the cases to run it with, each case a list of
/// --set-style overrides. README.md ("Design sweeps") documents the schema:
///
///   base_deck: ../engines/gasoline_1400_2000rpm/engine.yaml   # relative to this file
///   set:                                # overrides every case shares (optional)
///     simulation.output_step_deg: 2
///   cartesian:                          # every combination (first key varies slowest)
///     geometry.pin_offset_mm: [-0.5, 0.0, 0.5]
///     drive.speed_rpm: [1500, 2000]
///   cases:                              # listed cases (optional)
///     - {geometry.crank_offset_mm: 0.0}
///     - {geometry.crank_offset_mm: 1.0, piston.mass_g: 200}
///   latin_hypercube:                    # stratified random samples (optional)
///     samples: 8
///     seed: 1
///     ranges:
///       piston.com_above_pin_mm: [3.0, 7.0]
///
/// The blocks present (cases, latin_hypercube, cartesian) are combined as a product: every
/// listed case with every sample with every grid point, in that nesting (cases outermost).
/// A key belongs to one block only.
///
/// loadSweepDeck() reads the deck and then loads the base deck with the overrides of every
/// case (io::loadEngineDeck), so an unknown key or a bad value in any case is reported
/// before anything runs, with the sweep deck's line, the key and the case.

#include <cstdint>
#include <string>
#include <vector>

#include "pistondyn/io/LinerRegistry.h"

namespace pistondyn::io {

/// One override of a case: the deck key and the value as handed to --set (numbers in the
/// shortest text that reads back to the same double).
struct SweepAssignment {
  std::string key;    ///< "geometry.pin_offset_mm"
  std::string value;  ///< "0.5"
};

/// One case of a sweep: its index and its overrides.
struct SweepCase {
  int index = 0;  ///< 1-based: its row in sweep.csv and its folder (case_0001)
  std::vector<SweepAssignment> assignments;  ///< in the order of SweepPlan::sweptKeys
};

/// A key the sweep varies, and where the sweep deck names it.
struct SweepKey {
  std::string key;     ///< "geometry.pin_offset_mm"
  std::string origin;  ///< "sweep.yaml:9: cartesian.geometry.pin_offset_mm"
};

/// A file a case reads (the pressure table, a liner table), by its content.
struct SweepInputFile {
  std::string path;    ///< as resolved when the cases were checked
  std::string sha256;  ///< of its content, lower-case hex (as sha256sum prints)
};

/// A sweep deck as loaded and checked: its cases, shared overrides, inputs and fingerprint.
struct SweepPlan {
  static constexpr long kMaxCases = 1000000;  ///< most cases a sweep may have

  std::string sweepDeckPath;   ///< as given
  std::string name;            ///< optional label (sweep deck key `name`)
  std::string baseDeckPath;    ///< absolute
  std::string baseDeckSha256;  ///< SHA-256 of the base deck's content, lower-case hex
  /// Overrides every case shares: the sweep deck's `set`, then the command line's --set.
  std::vector<std::string> fixedOverrides;
  std::vector<SweepKey> sweptKeys;         ///< the columns of sweep.csv, in deck order
  std::vector<SweepCase> cases;            ///< in case order
  std::vector<SweepInputFile> inputFiles;  ///< distinct contents, sorted by hash
  /// SHA-256 of everything that decides the cases' results: the base deck's and the input
  /// files' contents, the shared overrides and every case's overrides (not the file
  /// paths: a moved folder is the same sweep).
  std::string fingerprint;

  /// Every --set of case `c`: the shared overrides, then the case's own.
  std::vector<std::string> getOverrides(const SweepCase& c) const;
  /// "case_0001" (at least four digits, more for sweeps of 10,000 cases or more).
  std::string getCaseFolderName(int index) const;
  /// The case with this index (1-based); throws std::out_of_range.
  const SweepCase& getCase(int index) const;
};

/// Reads a sweep deck, generates its cases and checks every case against the base deck.
/// `commandLineOverrides` ("key=value") are shared by every case, after the deck's `set`.
/// Throws DeckError listing every problem as `FILE:LINE: BLOCK.KEY: ...` (for a case:
/// `... case 3 (key=value): what is wrong`).
SweepPlan loadSweepDeck(const std::string& sweepDeckPath,
                        const std::vector<std::string>& commandLineOverrides = {},
                        const LinerRegistry& registry = LinerRegistry::getGlobal());

/// The normalised content of a sweep, as DIR/sweep.json holds it: base deck, input files,
/// shared overrides, swept keys, the cases with their overrides, the fingerprint.
std::string makeSweepJson(const SweepPlan& plan);
/// Reads makeSweepJson()'s text back (the folder's sweep.json; the plan MPI ranks are
/// sent). Throws std::runtime_error if it is not such a text.
SweepPlan parseSweepJson(const std::string& text);

/// The Latin hypercube behind the `latin_hypercube` block: `samples` points in the box
/// given by `ranges` ([minimum, maximum] per key, minimum < maximum). Each key's range is
/// cut into `samples` equal intervals and every interval holds exactly one sample:
/// floor((v - minimum) / (maximum - minimum) * samples) takes each value 0 .. samples-1
/// once per key. The intervals are paired by an independent random permutation per key and
/// each sample lies uniformly inside its interval. Reproducible: the same seed gives the
/// same samples on every platform (std::mt19937_64, whose output the C++ standard fixes,
/// with the project's own integer and [0, 1) mappings).
/// Result: samples[i][k] is sample i's value of key k.
std::vector<std::vector<double>> makeLatinHypercube(
    const std::vector<std::pair<double, double>>& ranges, long samples, std::uint64_t seed);

}  // namespace pistondyn::io
