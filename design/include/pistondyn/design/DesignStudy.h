#pragma once
/// @file
/// What the three design-loop decks (OPT.yaml, FIT.yaml, PROP.yaml; README.md, "The design
/// loop") share: the base engine deck, the overrides every evaluation shares, the design
/// variables (numeric deck keys with bounds, and the parametric skirt profile's numbers),
/// the study's fingerprint and its output folder.
///
/// ~~~
///   base_deck: ../engines/gasoline_1400_2000rpm/engine.yaml   # relative to this file
///   set: {simulation.cycles: 1}          # overrides every evaluation shares (optional)
///   <variables block>:                   # variables (optimize), parameters (fit),
///     geometry.pin_offset_mm: [-1, 1]    # inputs (propagate): [lower, upper], key's unit
///   profile:                             # optional: the parametric skirt profile
///     top_drop_um: [10, 40]              # a range: a variable; a number: fixed
///     bottom_drop_um: 15
///     min_clearance_height_mm: [-12, 0]
///     curvature_um_per_mm2: 0.12
/// ~~~
///
/// A variable is a deck key the base deck's readers read as a number (deck key path as
/// --set takes it, its unit in its name); its bounds are checked by loading the base deck
/// with each bound, so a bound the deck rejects is reported before anything runs.

#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "pistondyn/design/Evaluations.h"
#include "pistondyn/design/SkirtProfileDesign.h"
#include "pistondyn/io/LinerRegistry.h"
#include "pistondyn/io/SweepDeck.h"

namespace pistondyn::design {

/// One design variable: a numeric deck key (or a number of the parametric skirt profile)
/// varied between bounds, in the key's own unit.
struct DesignVariable {
  std::string key;                  ///< "geometry.pin_offset_mm", or "profile.top_drop_um"
  ///@{
  double lower = 0.0, upper = 0.0;  ///< in the key's unit, lower < upper
  ///@}
  std::optional<double> start;      ///< fit: the starting value (default: mid-range)
  std::optional<double> baseline;   ///< its value in the base deck (with `set`), if known
  std::string origin;               ///< "opt.yaml:12: variables.geometry.pin_offset_mm"
  /// True for a number of the parametric skirt profile (key "profile.*"), not a deck key.
  bool isProfile() const { return key.rfind("profile.", 0) == 0; }
};

/// The four numbers of the parametric skirt profile (SkirtProfileDesign.h), in the order
/// top_drop_um, bottom_drop_um, min_clearance_height_mm, curvature_um_per_mm2.
struct ProfileSpec {
  /// The deck names of the four numbers, in the order above.
  static const std::array<const char*, 4> kNames;
  bool enabled = false;  ///< the study deck has a profile section
  std::array<std::optional<double>, 4> fixed;  ///< nullopt: a design variable
  /// Rows of the generated profile table (profile.rows, 5 .. 10000; makeProfileTable()).
  int rows = 41;
};

/// A study deck read and checked (the part that optimize, fit and propagate share): the base
/// engine deck, the shared overrides, the variables and the optional skirt profile, with
/// the fingerprint of what every evaluation shares. Builds the evaluation of a design point.
struct DesignStudy {
  std::string kind;      ///< "optimize", "fit", "propagate"
  std::string deckPath;  ///< the study deck as given
  std::string name;      ///< the deck's `name` ("" when not given), for reports
  std::string baseDeckPath;  ///< absolute
  std::string baseDeckSha256;  ///< SHA-256 hex of the base deck file's content
  std::vector<std::string> fixedOverrides;     ///< `set`, then the command line's --set
  std::vector<io::SweepInputFile> inputFiles;  ///< tables the base deck reads, by content
  std::vector<DesignVariable> variables;       ///< deck keys first, then the profile's
  ProfileSpec profile;  ///< the parametric skirt profile (profile.enabled) or none
  ///@{
  double skirtBottom_mm = 0.0, skirtTop_mm = 0.0;  ///< of the base deck (profile designs)
  ///@}
  /// SHA-256 of what every evaluation shares: the base deck's and its tables' contents,
  /// the shared overrides (evaluation ids, EvaluationStore).
  std::string contextSha256;

  /// The evaluation of the design `x` (one value per variable, in its unit): the deck keys'
  /// overrides and, with a profile, the table written for it.
  EvaluationRequest makeRequest(const std::vector<double>& x) const;
  /// The base deck with the shared overrides only (its own profile table).
  EvaluationRequest makeBaselineRequest() const { return {}; }
  /// "key=value" of the deck-key variables for `x`.
  std::vector<std::string> getOverrides(const std::vector<double>& x) const;
  /// The variables' bounds as [lower, upper] pairs.
  std::vector<std::pair<double, double>> getBounds() const;
};

/// The output folder is not this study's: a file, another study's folder, a non-empty
/// folder without design.json, or in use. Nothing has been written.
class DesignOutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The folder of a study: DIR/design.json (kind, fingerprint, the normalised deck), locked
/// while the study runs; DIR/evaluations/ (EvaluationStore).
struct DesignFolder {
  std::string dir;  ///< absolute
  bool resumed = false;  ///< design.json was there with the same kind and fingerprint
  /// The study's lock on DIR/.design.lock (flock, exclusive); released when the last copy
  /// goes.
  std::shared_ptr<const void> lock;
};

/// Creates `dir` and writes design.json (kind, fingerprint and `description`, the study's
/// normalised content), or checks that its design.json holds the same kind and fingerprint
/// (a resumed study). Throws DesignOutputError naming what differs, std::runtime_error if
/// it cannot be written.
DesignFolder openDesignFolder(const std::string& dir, const std::string& kind,
                              const std::string& fingerprint, const std::string& description);

namespace detail {
class StudyDeckReader;
}

/// The SHA-256 hex of a text (the study fingerprints).
std::string hashText(const std::string& text);

}  // namespace pistondyn::design
