#pragma once
/// \file
/// One section of a deck ("liner", "liner.film"), read with typed getters relative to it.
/// This is what a liner model's factory (LinerRegistry.h) gets: it reads its own keys and
/// nothing else needs to know them. The rules are the deck's own:
///   - every key read is part of the schema; any other key of the section is reported as
///     unknown when the deck is finished (a misspelt key is never silently ignored);
///   - problems are recorded, not thrown: a getter returns a harmless value and the deck
///     lists every problem at once as `FILE:LINE: liner.key: what is expected`;
///   - units are part of the key. getSI() reads "radial_clearance_um" as a length and
///     returns metres; bounds and defaults are given in the key's unit, as in the deck
///     reference;
///   - every value read (defaults included) is recorded with its SI key for summary.json
///     (YamlDeck::getResolvedInputs());
///   - the product's own keys are read by the getters taking a DeckKey (DeckKeys.h), whose
///     requirement, default, valid and plausible ranges come from the key table.
///
/// \code
///   LinerElementMaker makeMyLiner(io::DeckSection& liner) {
///     MyLiner::Parameters p;
///     p.clearance_m = liner.getSI("radial_clearance_um", io::Quantity::Length,
///                                 io::Bounds::positive());
///     p.roughness_m = liner.getSIOr("roughness_rq_um", io::Quantity::Length, 0.5);
///     p.cavitation = liner.getChoiceOr<Cavitation>(
///         "cavitation", {{"reynolds", Cavitation::Reynolds}, {"jfo", Cavitation::JFO}},
///         Cavitation::Reynolds);
///     io::DeckSection film = liner.getSection("film");            // liner.film.*
///     p.oil = film.getString("grade");
///     const auto profile = liner.getCsvTable("skirt_profile_file",
///                                            {"axial_position_mm", "radial_drop_um"});
///     return [p] { return std::make_unique<MyLiner>(p); };
///   }
/// \endcode

#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <stdexcept>

#include "pistondyn/io/CsvTable.h"
#include "pistondyn/io/DeckKeys.h"
#include "pistondyn/io/Units.h"
#include "pistondyn/io/YamlDeck.h"

namespace pistondyn::io {

/// One section of a deck read with typed getters relative to it (this file's
/// documentation). Every getter records a problem and returns a harmless value on failure.
class DeckSection {
 public:
  /// The section at `path` of `deck` ("" = the whole deck). Prefer YamlDeck::getSection().
  DeckSection(YamlDeck& deck, std::string path);

  /// "liner", "liner.film" ("" for the whole deck).
  const std::string& getPath() const { return path_; }
  /// Full path of a key of this section: "liner.film" + "grade" -> "liner.film.grade".
  std::string getKeyPath(const std::string& key) const;
  YamlDeck& getDeck() const { return *deck_; }  ///< the deck the section belongs to

  /// A nested section: getSection("film") of "liner" is "liner.film".
  DeckSection getSection(const std::string& name) const;
  /// True if the key is present (and not null).
  bool has(const std::string& key) const;

  // ---- numbers in the key's own unit (no conversion) ---------------------------------
  /// A required number in the key's unit.
  double getNumber(const std::string& key, const Bounds& bounds = {});
  /// A number with a default (in the key's unit) for when it is absent.
  double getNumberOr(const std::string& key, double fallback, const Bounds& bounds = {});
  /// An optional number: nullopt when absent or invalid.
  std::optional<double> getOptionalNumber(const std::string& key, const Bounds& bounds = {});
  /// A whole number in [minimum, maximum].
  long getInteger(const std::string& key, long minimum, long maximum);
  /// A whole number in [minimum, maximum] with a default.
  long getIntegerOr(const std::string& key, long fallback, long minimum, long maximum);

  // ---- physical quantities, converted to SI by the key's unit (Units.h) ---------------
  /// The key must end with a unit of `quantity` ("bore_mm" for a Length); a key without
  /// one is a programming error (std::logic_error). Bounds and fallbacks are in the key's
  /// unit, like the values in the deck.
  double getSI(const std::string& key, Quantity quantity, const Bounds& bounds = {});
  /// As getSI, with a default in the key's unit for when the key is absent.
  double getSIOr(const std::string& key, Quantity quantity, double fallbackInKeyUnit,
                 const Bounds& bounds = {});
  /// As getSI; nullopt when absent or invalid.
  std::optional<double> getOptionalSI(const std::string& key, Quantity quantity,
                                      const Bounds& bounds = {});
  /// A required list of numbers, each converted to SI by the key's unit.
  std::vector<double> getSIList(const std::string& key, Quantity quantity,
                                const Bounds& bounds = {});
  /// As getSIList, with a default list in the key's unit.
  std::vector<double> getSIListOr(const std::string& key, Quantity quantity,
                                  const std::vector<double>& fallbackInKeyUnit,
                                  const Bounds& bounds = {});

  // ---- lists of numbers in the key's unit: [1, 2, 3] -----------------------------------
  /// A required list of numbers in the key's unit.
  std::vector<double> getNumberList(const std::string& key, const Bounds& bounds = {});
  /// A list of numbers with a default list.
  std::vector<double> getNumberListOr(const std::string& key, const std::vector<double>& fallback,
                                      const Bounds& bounds = {});

  // ---- text, switches and choices ----------------------------------------------------
  std::string getString(const std::string& key);  ///< required text
  /// Text with a default.
  std::string getStringOr(const std::string& key, const std::string& fallback);
  bool getBoolOr(const std::string& key, bool fallback);  ///< true/false with a default
  /// Required text that must be one of `choices`.
  std::string getChoice(const std::string& key, const std::vector<std::string>& choices);
  /// One of `choices`, with a default.
  std::string getChoiceOr(const std::string& key, const std::vector<std::string>& choices,
                          const std::string& fallback);
  /// A choice mapped to a value: getChoiceOr<Mode>("mode", {{"a", Mode::A}, ...}, Mode::A).
  template <class T, class = std::enable_if_t<!std::is_convertible_v<T, std::string>>>
  T getChoiceOr(const std::string& key, const std::vector<std::pair<std::string, T>>& choices,
                T fallback);

  // ---- files ---------------------------------------------------------------------------
  /// A file path, relative to the deck's folder unless absolute; a problem if it cannot
  /// be opened for reading. Returns the resolved path.
  std::string getFilePath(const std::string& key);
  std::optional<std::string> getOptionalFilePath(const std::string& key);  ///< nullopt if absent
  /// A CSV table (CsvTable.h) named by a file key; `requiredColumns` must be in its
  /// header. Problems (unreadable file, bad row `FILE:LINE: ...`, missing column) are
  /// recorded against the key; nullopt then, and when the key is absent and optional.
  std::optional<CsvTable> getCsvTable(const std::string& key,
                                      const std::vector<std::string>& requiredColumns = {});
  /// As getCsvTable for an optional key.
  std::optional<CsvTable> getOptionalCsvTable(const std::string& key,
                                              const std::vector<std::string>& requiredColumns = {});

  // ---- keys of the key table (DeckKeys.h) ------------------------------------------------
  /// The key's path must lie below this section. Requirement, default, valid and plausible
  /// ranges come from the key; every value read (defaults included) is recorded for
  /// summary.json. On a problem (recorded) the getters return the default or a harmless value.
  /// A number converted to SI by the key's unit (a key without a quantity: std::logic_error).
  double getSI(const DeckKey& key);
  /// nullopt when absent without a default, or invalid.
  std::optional<double> getOptionalSI(const DeckKey& key);
  /// A number in the key's unit (no conversion).
  double getNumber(const DeckKey& key);
  std::optional<double> getOptionalNumber(const DeckKey& key);  ///< nullopt when absent
  long getInteger(const DeckKey& key);                          ///< a WholeNumber key
  bool getBool(const DeckKey& key);                             ///< an OnOff key
  std::string getString(const DeckKey& key);                    ///< a Text key
  std::string getChoice(const DeckKey& key);  ///< a Choice key: one of its choices
  /// A choice mapped to a value; the key's default names the fallback.
  template <class T>
  T getChoice(const DeckKey& key, const std::vector<std::pair<std::string, T>>& values);

  // ---- problems found by the factory's own checks -------------------------------------
  /// Records `FILE:LINE: liner.key: message` (or `--set liner.key: ...`).
  void addProblem(const std::string& key, const std::string& message);
  bool hasProblems() const { return deck_->hasProblems(); }  ///< the deck has a problem

 private:
  std::optional<double> readSI(const std::string& key, Quantity quantity, const Bounds& bounds,
                               bool required, std::optional<double> fallbackInKeyUnit);
  std::optional<std::vector<double>> readSIList(const std::string& key, Quantity quantity,
                                                const Bounds& bounds, bool required,
                                                const std::vector<double>* fallbackInKeyUnit);
  std::optional<CsvTable> readCsvTable(const std::string& key,
                                       const std::vector<std::string>& requiredColumns,
                                       bool required);
  void record(const std::string& key, const std::string& siKey, ResolvedInput::Value value);
  std::string relativeKey(const DeckKey& key) const;
  std::optional<double> readKey(const DeckKey& key, bool toSI);
  std::optional<std::string> readChoice(const std::string& key,
                                        const std::vector<std::string>& choices, bool required);

  YamlDeck* deck_;
  std::string path_;
};

template <class T>
T DeckSection::getChoice(const DeckKey& key, const std::vector<std::pair<std::string, T>>& values) {
  const std::string name = getChoice(key);
  for (const auto& v : values) {
    if (v.first == name)
      return v.second;
  }
  throw std::logic_error("DeckSection::getChoice: no value for '" + name + "' of " + key.path);
}

template <class T, class>
T DeckSection::getChoiceOr(const std::string& key,
                           const std::vector<std::pair<std::string, T>>& choices, T fallback) {
  std::vector<std::string> names;
  std::string fallbackName;
  names.reserve(choices.size());
  for (const auto& c : choices) {
    names.push_back(c.first);
    if (fallbackName.empty() && c.second == fallback)
      fallbackName = c.first;
  }
  const std::string name = getChoiceOr(key, names, fallbackName);
  for (const auto& c : choices) {
    if (c.first == name)
      return c.second;
  }
  return fallback;
}

}  // namespace pistondyn::io
