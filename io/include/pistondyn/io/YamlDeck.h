#pragma once
/// \file
/// A YAML engine deck with a schema enforced by use: every getter marks its key as
/// known; finish() reports every key that nobody asked for as unknown. Problems are
/// collected (not thrown one by one) so the user sees all of them at once, each as
/// `FILE:LINE: KEY.PATH: what is wrong and what is expected`. Values overridden on the
/// command line (`--set a.b.c=value`) are reported as `--set KEY.PATH: ...`.
///
/// Getters here take the full key path ("geometry.bore_mm"). Code that reads one section
/// (a liner model's factory) uses a DeckSection (DeckSection.h) instead: the same getters
/// relative to the section, plus SI conversion by the key's unit, file paths, lists and
/// nested sections.

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace pistondyn::io {

class DeckSection;
struct DeckKey;
class DeckKeyTable;

/// Accepted values of a number, in the unit written in its key. Converts from Sign so
/// that getters take either.
struct Bounds {
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();  ///< +inf
  double minimum = -kInfinity;  ///< smallest accepted value, in the key's unit
  double maximum = kInfinity;   ///< largest accepted value, in the key's unit
  bool excludeMinimum = false;  ///< the minimum itself is refused
  bool excludeMaximum = false;  ///< the maximum itself is refused

  static Bounds any() { return {}; }                               ///< every number
  static Bounds positive() { return {0.0, kInfinity, true}; }      ///< (0, inf]
  static Bounds nonNegative() { return {0.0, kInfinity, false}; }  ///< [0, inf]
  /// [minimum, maximum]
  static Bounds between(double minimum, double maximum) { return {minimum, maximum, false}; }
  /// True when v lies in the bounds.
  bool contains(double v) const {
    return (excludeMinimum ? v > minimum : v >= minimum) &&
           (excludeMaximum ? v < maximum : v <= maximum);
  }
};

/// A value read through a DeckSection, as resolved (defaults included), for summaries:
/// siPath is the key with its unit replaced by the SI one when the getter converted it
/// ("liner.film.viscosity_mPas" -> "liner.film.viscosity_Pas"), else the key itself.
struct ResolvedInput {
  /// long: a whole number of the key table (simulation.cycles), written as an integer.
  using Value = std::variant<double, bool, std::string, std::vector<double>, long>;
  std::string path;    ///< the key as written in the deck ("liner.film.viscosity_mPas")
  std::string siPath;  ///< the key with its SI unit ("liner.film.viscosity_Pas")
  Value value;         ///< the value in SI
};

/// A YAML engine deck with its schema enforced by use (the documentation of YamlDeck.h).
class YamlDeck {
 public:
  /// Loads and parses the file; throws DeckError (with line) on unreadable/invalid YAML.
  explicit YamlDeck(std::string filePath);
  ~YamlDeck();
  YamlDeck(YamlDeck&&) noexcept;             ///< moves the parsed deck
  YamlDeck& operator=(YamlDeck&&) noexcept;  ///< moves the parsed deck

  /// "a.b.c=value": value parsed as a YAML scalar. Creates missing maps on the path
  /// (a misspelt key is then reported as unknown by finish()). Throws DeckError.
  void applyOverride(const std::string& assignment);

  const std::string& getFilePath() const;  ///< the deck file as given
  /// Directory of the deck file, for resolving relative paths ("" = current directory).
  std::string getDirectory() const;
  /// `path` as written in the deck, resolved against getDirectory() unless absolute.
  std::string resolvePath(const std::string& path) const;

  // ---- schema getters: record a problem and return a harmless value on failure ----
  /// The sign a number must have.
  enum class Sign {
    Any,          ///< any finite number
    Positive,     ///< > 0
    NonNegative,  ///< >= 0
  };
  /// A required number (0 and a problem when absent or invalid).
  double getNumber(const std::string& path, Sign sign = Sign::Any);
  /// An optional number: nullopt when absent (or invalid: a problem).
  std::optional<double> getOptionalNumber(const std::string& path, Sign sign = Sign::Any);
  /// A number with a default for when it is absent.
  double getNumberOr(const std::string& path, double fallback, Sign sign = Sign::Any);
  /// A whole number in [minimum, maximum] with a default for when it is absent.
  long getIntegerOr(const std::string& path, long fallback, long minimum, long maximum);
  /// A number that must lie in [minimum, maximum] (the unit is named in the message);
  /// nullopt when absent or out of range (the latter recorded as a problem).
  std::optional<double> getNumberInRange(const std::string& path, bool required, double minimum,
                                         double maximum, const std::string& unit);
  /// Required text ("" and a problem when absent).
  std::string getString(const std::string& path);
  /// One of `choices`, `fallback` when absent (a problem when another text is given).
  std::string getChoiceOr(const std::string& path, const std::vector<std::string>& choices,
                          const std::string& fallback);
  bool has(const std::string& path) const;  ///< the deck (or a --set) gives `path`

  /// The general number reader behind the getters: nullopt when absent (a problem if
  /// `required`) or invalid (always a problem). `unit` is named in range messages.
  std::optional<double> readNumber(const std::string& path, const Bounds& bounds, bool required,
                                   const std::string& unit = {});
  /// true/false; nullopt when absent (a problem if `required`) or not a boolean.
  std::optional<bool> readBool(const std::string& path, bool required);
  /// Text; nullopt when absent (a problem if `required`) or not a scalar.
  std::optional<std::string> readString(const std::string& path, bool required);
  /// A list of numbers ([1, 2, 3] or one item per line); nullopt when absent (a problem if
  /// `required`) or invalid.
  std::optional<std::vector<double>> readNumberList(const std::string& path, const Bounds& bounds,
                                                    bool required, const std::string& unit = {});

  // ---- keys of the key table (DeckKeys.h): requirement, default and ranges from it ----
  /// A Number or WholeNumber key in its own unit: the default when absent (nullopt without
  /// one; a problem if required), nullopt when invalid, outside the valid range or outside
  /// the plausible range unless checks.allow_implausible lists it (problems recorded, with
  /// the unit slip the value suggests).
  std::optional<double> readKeyNumber(const DeckKey& key);
  /// Reads checks.allow_implausible (a list of key paths of `tables` that have a plausible
  /// range); call once before reading the keys it may name.
  void readAllowedImplausible(const std::vector<const DeckKeyTable*>& tables);
  /// True if checks.allow_implausible lists `path`.
  bool isImplausibleAllowed(const std::string& path) const;
  /// Every key a getter asked for (the schema as used), sorted.
  std::vector<std::string> getKnownKeys() const;

  /// A view of the section at `path` (e.g. "liner", "liner.film"; "" = the whole deck).
  /// Records a problem if `path` holds a value instead of a section.
  DeckSection getSection(const std::string& path);
  /// Keys below `path` are never reported as unknown (e.g. the section of a model that
  /// could not be selected: its keys are not the problem).
  void ignoreSection(const std::string& path);
  /// Marks `path` (and the sections above it) as part of the schema.
  void markKnown(const std::string& path);
  /// Keys below `path` written in the deck file are never reported as unknown, while keys
  /// given by --set still are (the deck's liner section describes another liner model than
  /// the one a --set liner.model chose: its keys are that model's data, not misspellings).
  void ignoreFileKeys(const std::string& path);
  /// The text a plain value had in the deck file before a --set replaced it; nullopt if the
  /// key was not in the file, was not a plain value or was not overridden.
  std::optional<std::string> getFileValue(const std::string& path) const;

  /// Values read through DeckSection getters, in the order they were read.
  const std::vector<ResolvedInput>& getResolvedInputs() const;
  /// Adds one, or replaces the one of the same path (DeckSection's getters call it).
  void recordInput(ResolvedInput input);

  /// `FILE:LINE: key` (the key's line, else its nearest section's) or `--set ...`.
  std::string where(const std::string& path) const;
  /// Adds a problem about `path` found by a later, cross-key check (e.g. rod too short).
  void addProblem(const std::string& path, const std::string& message);
  bool hasProblems() const;  ///< a problem has been recorded
  /// Reports unknown keys, then throws DeckError listing every problem (if any).
  void finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pistondyn::io
