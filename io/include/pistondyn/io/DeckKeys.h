#pragma once
/// \file
/// The table of deck keys: every key of an engine deck (getEngineDeckKeys()) and of the
/// lubricated skirt's liner section (getLubricatedSkirtDeckKeys(), LubricatedSkirtDeck.h)
/// with its unit, default, valid range, plausible range and meaning. It is the one source:
/// the deck readers take each key's requirement, default and ranges from it (the getters of
/// YamlDeck / DeckSection that take a DeckKey), `pistondyn keys` prints it, and README.md's
/// deck reference is generated from it (DeckReference.h; a test fails when they differ).
///
/// Two ranges per number, both in the key's own unit:
///   valid      outside it a value cannot be simulated or is certainly wrong: an error;
///   plausible  what the engines the tool is for have (a 20 .. 1000 mm bore). Outside it a
///              value is almost surely a unit slip (a bore given in metres): an error that
///              names the unit that would make it plausible. A deck that means such a value
///              lists the key under `checks.allow_implausible` (kAllowImplausibleKey).
///
/// A liner model a user registers (LinerRegistry.h) reads its keys with DeckSection's plain
/// getters; they are checked the same way but are not part of this reference.

#include <optional>
#include <string>
#include <vector>

#include "pistondyn/io/Units.h"
#include "pistondyn/io/YamlDeck.h"

namespace pistondyn::io {

/// What kind of value a deck key takes.
enum class DeckValueKind {
  Number,       ///< a number in the key's unit
  WholeNumber,  ///< a whole number
  Switch,       ///< true / false
  Text,         ///< free text
  Choice,       ///< one of `choices`
  File,         ///< a path, relative to the deck's folder
  NumberList,   ///< [a, b, ...] in the key's unit
  KeyList,      ///< [key.path, ...]
};

/// One deck key of the key table: requirement, default, valid and plausible range, meaning.
struct DeckKey {
  std::string path;                            ///< full key path with its unit: "geometry.bore_mm"
  DeckValueKind kind = DeckValueKind::Number;  ///< the kind of value
  std::optional<Quantity> quantity;            ///< set: the key's unit suffix converts it to SI
  bool required = false;                       ///< the deck must give it (no default)
  std::optional<double> defaultValue;          ///< in the key's unit (a switch: 0 or 1)
  std::string defaultText;           ///< the default as the reference shows it, if not a number
  Bounds valid;                      ///< in the key's unit; whole numbers: [minimum, maximum]
  std::optional<Bounds> plausible;   ///< in the key's unit
  std::vector<std::string> choices;  ///< Choice
  std::string unitText;              ///< the reference's unit column if not derived from the key
  std::string meaning;               ///< one sentence or two; cross-key rules included
  std::string rangeReason;           ///< why the valid range ends where it does (in messages)

  // ---- builders: DeckKey::number("geometry.bore_mm", Quantity::Length).require()... ----
  /// A number, converted to SI when a quantity is given.
  static DeckKey number(std::string path, std::optional<Quantity> quantity = std::nullopt);
  /// A whole number in [minimum, maximum].
  static DeckKey wholeNumber(std::string path, long minimum, long maximum);
  static DeckKey onOff(std::string path);  ///< a switch (true / false)
  static DeckKey text(std::string path);   ///< free text
  /// One of `choices`.
  static DeckKey choice(std::string path, std::vector<std::string> choices);
  /// A file; `content` describes it for the reference ("CSV `depth_mm, temperature_degC`").
  static DeckKey file(std::string path, std::string content);
  /// A list of numbers, converted to SI when a quantity is given.
  static DeckKey numberList(std::string path, std::optional<Quantity> quantity = std::nullopt);
  static DeckKey keyList(std::string path);  ///< a list of key paths
  DeckKey& require();                        ///< marks the key required
  DeckKey& byDefault(double value);          ///< its default, in the key's unit
  DeckKey& byDefault(std::string text);      ///< a choice's name, or a default that is not a number
  DeckKey& within(const Bounds& bounds);     ///< the valid range, in the key's unit
  /// The plausible range [minimum, maximum], in the key's unit (the unit-slip check).
  DeckKey& plausibleWithin(double minimum, double maximum);
  DeckKey& unit(std::string text);       ///< the reference's unit column (unitText)
  DeckKey& means(std::string text);      ///< the meaning
  DeckKey& because(std::string reason);  ///< rangeReason

  /// The unit the key's name ends with ("mm" of geometry.bore_mm); nullopt without a quantity.
  std::optional<UnitSuffix> getUnit() const;
};

/// An ordered set of keys: one table of the reference.
class DeckKeyTable {
 public:
  /// A table with its title, its introduction (Markdown) and its keys in order.
  DeckKeyTable(std::string title, std::string introduction, std::vector<DeckKey> keys);
  const std::string& getTitle() const { return title_; }                ///< the title
  const std::string& getIntroduction() const { return introduction_; }  ///< the introduction
  const std::vector<DeckKey>& getKeys() const { return keys_; }         ///< the keys in order
  /// nullptr if the table has no such key.
  const DeckKey* find(const std::string& path) const;
  /// The key; std::logic_error if absent (a reader asking for a key the table lacks is a
  /// programming error, caught by the tests that load every example deck).
  const DeckKey& at(const std::string& path) const;

 private:
  std::string title_, introduction_;
  std::vector<DeckKey> keys_;
};

/// The engine deck's keys outside the liner section's model keys (liner.model included).
const DeckKeyTable& getEngineDeckKeys();

/// `checks.allow_implausible`: keys whose plausible range the deck waives.
inline const char* const kAllowImplausibleKey = "checks.allow_implausible";

/// Why `value` (in the key's unit) may be a unit slip: the other units of the key's
/// quantity in which it would lie in the plausible (else valid) range, e.g.
/// "given in m? 0.0745 m = 74.5 mm". Empty if there is none.
std::string describeUnitSlip(const DeckKey& key, double value);

}  // namespace pistondyn::io
