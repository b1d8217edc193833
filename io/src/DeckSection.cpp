#include "pistondyn/io/DeckSection.h"

#include "MessageText.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "pistondyn/common/Validation.h"
#include "pistondyn/io/DeckError.h"

namespace pistondyn::io {
namespace {

UnitSuffix requireUnit(const std::string& keyPath, Quantity quantity) {
  const auto unit = findUnitSuffix(keyPath, quantity);
  if (!unit) {
    std::string known;
    for (const auto& u : getUnits(quantity))
      known += (known.empty() ? "" : ", ") + u.suffix;
    throw std::logic_error("DeckSection::getSI: key '" + keyPath + "' does not end with a " +
                           getQuantityName(quantity) + " unit (_" + known +
                           "); name the unit in the key or use getNumber()");
  }
  return *unit;
}

double toSI(double v, const UnitSuffix& u) {
  return u.offset == 0.0 ? v * u.factor : v * u.factor + u.offset;
}

// A finite value in the key's unit can overflow in SI (1e306 kN): never pass on an inf.
std::string overflowMessage(double v, const UnitSuffix& u) {
  return common::formatNumber(v) + " " + u.suffix + " is too large: it overflows when " +
         "converted to " + u.siSuffix;
}

}  // namespace

DeckSection::DeckSection(YamlDeck& deck, std::string path) : deck_(&deck), path_(std::move(path)) {}

std::string DeckSection::getKeyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

DeckSection DeckSection::getSection(const std::string& name) const {
  return deck_->getSection(getKeyPath(name));
}

bool DeckSection::has(const std::string& key) const {
  return deck_->has(getKeyPath(key));
}

void DeckSection::record(const std::string& key, const std::string& siKey,
                         ResolvedInput::Value value) {
  deck_->recordInput({getKeyPath(key), getKeyPath(siKey), std::move(value)});
}

void DeckSection::addProblem(const std::string& key, const std::string& message) {
  deck_->addProblem(getKeyPath(key), message);
}

// ---- numbers -------------------------------------------------------------------------

double DeckSection::getNumber(const std::string& key, const Bounds& bounds) {
  const auto v = deck_->readNumber(getKeyPath(key), bounds, true);
  if (v)
    record(key, key, *v);
  return v.value_or(1.0);
}

double DeckSection::getNumberOr(const std::string& key, double fallback, const Bounds& bounds) {
  const bool present = has(key);
  const auto v = deck_->readNumber(getKeyPath(key), bounds, false);
  if (v || !present)
    record(key, key, v.value_or(fallback));
  return v.value_or(fallback);
}

std::optional<double> DeckSection::getOptionalNumber(const std::string& key, const Bounds& bounds) {
  const auto v = deck_->readNumber(getKeyPath(key), bounds, false);
  if (v)
    record(key, key, *v);
  return v;
}

long DeckSection::getInteger(const std::string& key, long minimum, long maximum) {
  if (!has(key)) {
    deck_->readNumber(getKeyPath(key), Bounds::any(), true);  // "missing key"
    return minimum;
  }
  return getIntegerOr(key, minimum, minimum, maximum);
}

long DeckSection::getIntegerOr(const std::string& key, long fallback, long minimum, long maximum) {
  const bool present = has(key);
  const auto v = deck_->readNumber(getKeyPath(key), Bounds::any(), false);
  if (!v) {
    if (!present)
      record(key, key, static_cast<double>(fallback));
    return fallback;
  }
  // Range before the cast: the comparison is exact for doubles far outside long's range.
  if (*v != std::floor(*v) || *v < static_cast<double>(minimum) ||
      *v > static_cast<double>(maximum)) {
    addProblem(key, "must be a whole number from " + std::to_string(minimum) + " to " +
                        std::to_string(maximum));
    return fallback;
  }
  record(key, key, *v);
  return static_cast<long>(*v);
}

// ---- SI quantities --------------------------------------------------------------------

std::optional<double> DeckSection::readSI(const std::string& key, Quantity quantity,
                                          const Bounds& bounds, bool required,
                                          std::optional<double> fallbackInKeyUnit) {
  const UnitSuffix unit = requireUnit(getKeyPath(key), quantity);
  const bool present = has(key);
  const auto v = deck_->readNumber(getKeyPath(key), bounds, required, unit.suffix);
  if (!v && (present || !fallbackInKeyUnit))
    return std::nullopt;
  const double si = toSI(v ? *v : *fallbackInKeyUnit, unit);
  if (!std::isfinite(si)) {
    addProblem(key, overflowMessage(v ? *v : *fallbackInKeyUnit, unit));
    return std::nullopt;
  }
  record(key, toSIKey(key, unit), si);
  return si;
}

double DeckSection::getSI(const std::string& key, Quantity quantity, const Bounds& bounds) {
  return readSI(key, quantity, bounds, true, std::nullopt).value_or(1.0);
}

double DeckSection::getSIOr(const std::string& key, Quantity quantity, double fallbackInKeyUnit,
                            const Bounds& bounds) {
  const auto v = readSI(key, quantity, bounds, false, fallbackInKeyUnit);
  return v ? *v : toSI(fallbackInKeyUnit, requireUnit(getKeyPath(key), quantity));
}

std::optional<double> DeckSection::getOptionalSI(const std::string& key, Quantity quantity,
                                                 const Bounds& bounds) {
  return readSI(key, quantity, bounds, false, std::nullopt);
}

std::optional<std::vector<double>> DeckSection::readSIList(
    const std::string& key, Quantity quantity, const Bounds& bounds, bool required,
    const std::vector<double>* fallbackInKeyUnit) {
  const UnitSuffix unit = requireUnit(getKeyPath(key), quantity);
  const bool present = has(key);
  auto v = deck_->readNumberList(getKeyPath(key), bounds, required, unit.suffix);
  if (!v) {
    if (present || fallbackInKeyUnit == nullptr)
      return std::nullopt;
    v = *fallbackInKeyUnit;
  }
  for (std::size_t i = 0; i < v->size(); ++i) {
    const double si = toSI((*v)[i], unit);
    if (!std::isfinite(si)) {
      addProblem(key, "item " + std::to_string(i + 1) + ": " + overflowMessage((*v)[i], unit));
      return std::nullopt;
    }
    (*v)[i] = si;
  }
  record(key, toSIKey(key, unit), *v);
  return v;
}

std::vector<double> DeckSection::getSIList(const std::string& key, Quantity quantity,
                                           const Bounds& bounds) {
  return readSIList(key, quantity, bounds, true, nullptr).value_or(std::vector<double>());
}

std::vector<double> DeckSection::getSIListOr(const std::string& key, Quantity quantity,
                                             const std::vector<double>& fallbackInKeyUnit,
                                             const Bounds& bounds) {
  auto v = readSIList(key, quantity, bounds, false, &fallbackInKeyUnit);
  if (v)
    return *v;
  std::vector<double> si = fallbackInKeyUnit;
  const UnitSuffix unit = requireUnit(getKeyPath(key), quantity);
  for (double& x : si)
    x = toSI(x, unit);
  return si;
}

std::vector<double> DeckSection::getNumberList(const std::string& key, const Bounds& bounds) {
  const auto v = deck_->readNumberList(getKeyPath(key), bounds, true);
  if (v)
    record(key, key, *v);
  return v.value_or(std::vector<double>());
}

std::vector<double> DeckSection::getNumberListOr(const std::string& key,
                                                 const std::vector<double>& fallback,
                                                 const Bounds& bounds) {
  const bool present = has(key);
  const auto v = deck_->readNumberList(getKeyPath(key), bounds, false);
  if (v || !present)
    record(key, key, v.value_or(fallback));
  return v.value_or(fallback);
}

// ---- text, switches, choices -----------------------------------------------------------

std::string DeckSection::getString(const std::string& key) {
  const auto v = deck_->readString(getKeyPath(key), true);
  if (v)
    record(key, key, *v);
  return v.value_or(std::string());
}

std::string DeckSection::getStringOr(const std::string& key, const std::string& fallback) {
  const bool present = has(key);
  const auto v = deck_->readString(getKeyPath(key), false);
  if (v || !present)
    record(key, key, v.value_or(fallback));
  return v.value_or(fallback);
}

bool DeckSection::getBoolOr(const std::string& key, bool fallback) {
  const bool present = has(key);
  const auto v = deck_->readBool(getKeyPath(key), false);
  if (v || !present)
    record(key, key, v.value_or(fallback));
  return v.value_or(fallback);
}

std::optional<std::string> DeckSection::readChoice(const std::string& key,
                                                   const std::vector<std::string>& choices,
                                                   bool required) {
  const auto v = deck_->readString(getKeyPath(key), required);
  if (!v)
    return std::nullopt;
  for (const auto& c : choices) {
    if (*v == c) {
      record(key, key, *v);
      return v;
    }
  }
  std::string list;
  for (const auto& c : choices)
    list += (list.empty() ? "" : ", ") + c;
  addProblem(key, detail::quoteValue(*v) + " is not one of: " + list);
  return std::nullopt;
}

std::string DeckSection::getChoice(const std::string& key,
                                   const std::vector<std::string>& choices) {
  return readChoice(key, choices, true).value_or(choices.empty() ? std::string() : choices[0]);
}

std::string DeckSection::getChoiceOr(const std::string& key,
                                     const std::vector<std::string>& choices,
                                     const std::string& fallback) {
  const bool present = has(key);
  const auto v = readChoice(key, choices, false);
  if (!v && !present)
    record(key, key, fallback);
  return v.value_or(fallback);
}

// ---- keys of the key table -------------------------------------------------------------

std::string DeckSection::relativeKey(const DeckKey& key) const {
  if (path_.empty())
    return key.path;
  if (key.path.rfind(path_ + ".", 0) != 0)
    throw std::logic_error("DeckSection '" + path_ + "': the key " + key.path +
                           " is not in this section");
  return key.path.substr(path_.size() + 1);
}

std::optional<double> DeckSection::readKey(const DeckKey& key, bool convert) {
  const std::string rel = relativeKey(key);
  const std::optional<UnitSuffix> unit = key.getUnit();
  if (convert && !unit)
    throw std::logic_error("DeckSection::getSI: the key " + key.path + " has no unit");
  const std::optional<double> v = deck_->readKeyNumber(key);
  if (!v)
    return std::nullopt;
  if (!convert) {
    record(rel, rel, *v);
    return v;
  }
  const double si = toSI(*v, *unit);
  if (!std::isfinite(si)) {
    addProblem(rel, overflowMessage(*v, *unit));
    return std::nullopt;
  }
  record(rel, toSIKey(rel, *unit), si);
  return si;
}

double DeckSection::getSI(const DeckKey& key) {
  if (const auto v = readKey(key, true))
    return *v;
  const auto unit = key.getUnit();
  return key.defaultValue && unit ? toSI(*key.defaultValue, *unit) : 1.0;
}

std::optional<double> DeckSection::getOptionalSI(const DeckKey& key) {
  return readKey(key, true);
}

double DeckSection::getNumber(const DeckKey& key) {
  return readKey(key, false).value_or(key.defaultValue.value_or(1.0));
}

std::optional<double> DeckSection::getOptionalNumber(const DeckKey& key) {
  return readKey(key, false);
}

long DeckSection::getInteger(const DeckKey& key) {
  const std::string rel = relativeKey(key);
  const std::optional<double> v = deck_->readKeyNumber(key);
  if (v)
    record(rel, rel, static_cast<long>(*v));
  return static_cast<long>(v.value_or(key.defaultValue.value_or(key.valid.minimum)));
}

bool DeckSection::getBool(const DeckKey& key) {
  const std::string rel = relativeKey(key);
  const bool fallback = key.defaultValue.value_or(0.0) != 0.0;
  const bool present = has(rel);
  const auto v = deck_->readBool(key.path, key.required);
  if (v || !present)
    record(rel, rel, v.value_or(fallback));
  return v.value_or(fallback);
}

std::string DeckSection::getString(const DeckKey& key) {
  const std::string rel = relativeKey(key);
  const bool present = has(rel);
  const auto v = deck_->readString(key.path, key.required);
  if (v || (!present && !key.required))
    record(rel, rel, v.value_or(key.defaultText));
  return v.value_or(key.defaultText);
}

std::string DeckSection::getChoice(const DeckKey& key) {
  const std::string rel = relativeKey(key);
  const bool present = has(rel);
  const auto v = readChoice(rel, key.choices, key.required);
  if (!v && !present && !key.required)
    record(rel, rel, key.defaultText);
  return v.value_or(key.defaultText.empty() && !key.choices.empty() ? key.choices[0]
                                                                     : key.defaultText);
}

// ---- files -----------------------------------------------------------------------------

std::optional<std::string> DeckSection::getOptionalFilePath(const std::string& key) {
  const auto v = deck_->readString(getKeyPath(key), false);
  if (!v)
    return std::nullopt;
  if (v->empty()) {
    addProblem(key, "expected a file path, found an empty text");
    return std::nullopt;
  }
  const std::string path = deck_->resolvePath(*v);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    addProblem(key, detail::quoteValue(path) +
                        " is a folder, not a file (relative paths start at the deck's "
                        "folder)");
    return std::nullopt;
  }
  std::ifstream probe(path);
  if (!probe) {
    addProblem(key, "cannot open '" + path + "' (relative paths start at the deck's folder)");
    return std::nullopt;
  }
  // summary.json names the file wherever the run was started from.
  std::error_code absoluteError;
  const std::filesystem::path absolute = std::filesystem::absolute(path, absoluteError);
  record(key, key, absoluteError ? path : absolute.lexically_normal().string());
  return path;
}

std::string DeckSection::getFilePath(const std::string& key) {
  if (!has(key)) {
    deck_->readString(getKeyPath(key), true);  // "missing key"
    return {};
  }
  return getOptionalFilePath(key).value_or(std::string());
}

std::optional<CsvTable> DeckSection::readCsvTable(const std::string& key,
                                                  const std::vector<std::string>& requiredColumns,
                                                  bool required) {
  const std::optional<std::string> path =
      required ? std::optional<std::string>(getFilePath(key)) : getOptionalFilePath(key);
  if (!path || path->empty())
    return std::nullopt;
  try {
    return io::readCsvTable(*path, requiredColumns);
  } catch (const DeckError& e) {
    addProblem(key, e.what());
    return std::nullopt;
  }
}

std::optional<CsvTable> DeckSection::getCsvTable(const std::string& key,
                                                 const std::vector<std::string>& requiredColumns) {
  return readCsvTable(key, requiredColumns, true);
}

std::optional<CsvTable> DeckSection::getOptionalCsvTable(
    const std::string& key, const std::vector<std::string>& requiredColumns) {
  return readCsvTable(key, requiredColumns, false);
}

}  // namespace pistondyn::io
