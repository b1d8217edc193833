#include "pistondyn/io/YamlDeck.h"

#include <cmath>
#include <sstream>

#include "pistondyn/io/DeckError.h"

namespace pistondyn::io {
namespace {

// Splits "a.b.c"; keeps empty segments so that "a..b" or "a.b." can be rejected.
std::vector<std::string> splitPath(const std::string& path) {
  std::vector<std::string> parts(1);
  for (const char c : path) {
    if (c == '.') {
      parts.emplace_back();
    } else {
      parts.back() += c;
    }
  }
  return parts;
}

// ":<line>" for a node read from the file; "" for one created by --set (no position).
std::string lineText(const YAML::Mark& mark) {
  return mark.line >= 0 ? ":" + std::to_string(mark.line + 1) : std::string();
}

}  // namespace

YamlDeck::YamlDeck(std::string filePath) : filePath_(std::move(filePath)) {
  try {
    root_ = YAML::LoadFile(filePath_);
  } catch (const YAML::BadFile&) {
    throw DeckError(filePath_ + ": cannot open the deck file");
  } catch (const YAML::ParserException& e) {
    throw DeckError(filePath_ + lineText(e.mark) + ": not valid YAML: " + e.msg);
  } catch (const std::exception& e) {
    // e.g. the path is a directory (std::ios_base::failure)
    throw DeckError(filePath_ + ": cannot read the deck file: " + e.what());
  }
  if (!root_.IsMap()) {
    throw DeckError(filePath_ + ": the deck must be a YAML mapping of sections (engine:, "
                                "geometry:, ...)");
  }
}

std::string YamlDeck::getDirectory() const {
  const auto slash = filePath_.find_last_of('/');
  return slash == std::string::npos ? std::string() : filePath_.substr(0, slash + 1);
}

void YamlDeck::applyOverride(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw DeckError("--set " + assignment + ": expected key.path=value");
  }
  const std::string path = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  const std::vector<std::string> parts = splitPath(path);
  for (const auto& part : parts) {
    if (part.empty()) throw DeckError("--set " + path + ": empty key in the path");
  }
  YAML::Node value;
  try {
    value = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw DeckError("--set " + path + ": value '" + text + "' is not valid YAML: " + e.msg);
  }
  // yaml-cpp nodes are handles: walk with a copy and assign into the last map.
  YAML::Node node = root_;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node child = node[parts[i]];
    if (child.IsDefined() && !child.IsMap()) {
      throw DeckError("--set " + path + ": '" + parts[i] + "' is a value, not a section");
    }
    if (!child.IsDefined()) node[parts[i]] = YAML::Node(YAML::NodeType::Map);
    node.reset(node[parts[i]]);
  }
  node[parts.back()] = value;
  overridden_.insert(path);
}

YAML::Node YamlDeck::lookup(const std::string& path) const {
  // Walk through const references so a missing key is never inserted.
  YAML::Node cur = root_;
  for (const std::string& p : splitPath(path)) {
    if (!cur.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node next = static_cast<const YAML::Node&>(cur)[p];
    if (!next.IsDefined()) return YAML::Node(YAML::NodeType::Undefined);
    cur.reset(next);
  }
  return cur;
}

bool YamlDeck::has(const std::string& path) const {
  const YAML::Node n = lookup(path);
  return n.IsDefined() && !n.IsNull();
}

std::string YamlDeck::overridingAssignment(const std::string& path) const {
  // The key itself, or a section above it, set on the command line.
  for (std::string p = path;;) {
    if (overridden_.count(p) != 0) return p;
    const auto dot = p.find_last_of('.');
    if (dot == std::string::npos) return {};
    p = p.substr(0, dot);
  }
}

std::string YamlDeck::where(const std::string& path) const {
  const std::string set = overridingAssignment(path);
  if (!set.empty()) return set == path ? "--set " + path : "--set " + set + ": " + path;
  // The key's own line, else (a missing key) the line of its nearest section.
  for (std::string p = path;;) {
    const YAML::Node n = lookup(p);
    if (n.IsDefined() && n.Mark().line >= 0) return filePath_ + lineText(n.Mark()) + ": " + path;
    const auto dot = p.find_last_of('.');
    if (dot == std::string::npos) return filePath_ + ": " + path;
    p = p.substr(0, dot);
  }
}

void YamlDeck::addProblem(const std::string& path, const std::string& message) {
  problems_.push_back(where(path) + ": " + message);
}

void YamlDeck::collectUnknown(const YAML::Node& node, const std::string& prefix) {
  std::set<std::string> seen;
  for (const auto& kv : node) {
    const std::string at = filePath_ + lineText(kv.first.Mark()) + ": ";
    if (!kv.first.IsScalar()) {
      problems_.push_back(at + (prefix.empty() ? std::string() : prefix + ": ") +
                          "keys must be plain names, not lists or sections");
      continue;
    }
    const std::string key = kv.first.Scalar();
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    if (!seen.insert(key).second) {
      problems_.push_back(at + path + ": duplicate key (YAML would keep only one of them)");
      continue;
    }
    if (known_.count(path) == 0) {
      // From the file, from a --set of this key or a section above it, or a section
      // that exists only because a --set below it created it.
      std::string origin = at + path;
      if (!overridingAssignment(path).empty()) {
        origin = where(path);
      } else if (kv.first.Mark().line < 0) {
        for (const auto& o : overridden_) {
          if (o.rfind(path + ".", 0) == 0) origin = "--set " + o;
        }
      }
      problems_.push_back(origin + ": unknown key (misspelt, or a unit the key does not take? see the "
                          "deck reference in README.md)");
    } else if (kv.second.IsMap()) {
      collectUnknown(kv.second, path);
    }
  }
}

void YamlDeck::markKnown(const std::string& path) {
  // The key and every section above it are part of the schema.
  for (std::size_t pos = path.find('.'); pos != std::string::npos; pos = path.find('.', pos + 1)) {
    known_.insert(path.substr(0, pos));
  }
  known_.insert(path);
}

std::optional<double> YamlDeck::readNumber(const std::string& path, Sign sign, bool required) {
  markKnown(path);
  const YAML::Node n = lookup(path);
  if (!n.IsDefined() || n.IsNull()) {
    if (required) addProblem(path, "missing key (a number is required)");
    return std::nullopt;
  }
  if (!n.IsScalar()) {
    addProblem(path, "expected a number, found a " + std::string(n.IsMap() ? "section" : "list"));
    return std::nullopt;
  }
  double v = 0.0;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    addProblem(path, "'" + n.Scalar() + "' is not a number");
    return std::nullopt;
  }
  if (!std::isfinite(v)) {
    addProblem(path, "'" + n.Scalar() + "' is not a finite number");
    return std::nullopt;
  }
  if (sign == Sign::Positive && !(v > 0.0)) {
    addProblem(path, "must be positive (got " + n.Scalar() + ")");
    return std::nullopt;
  }
  if (sign == Sign::NonNegative && v < 0.0) {
    addProblem(path, "must not be negative (got " + n.Scalar() + ")");
    return std::nullopt;
  }
  return v;
}

double YamlDeck::getNumber(const std::string& path, Sign sign) {
  return readNumber(path, sign, true).value_or(1.0);
}

std::optional<double> YamlDeck::getOptionalNumber(const std::string& path, Sign sign) {
  return readNumber(path, sign, false);
}

double YamlDeck::getNumberOr(const std::string& path, double fallback, Sign sign) {
  return readNumber(path, sign, false).value_or(fallback);
}

long YamlDeck::getIntegerOr(const std::string& path, long fallback, long minimum, long maximum) {
  const std::optional<double> v = readNumber(path, Sign::Any, false);
  if (!v) return fallback;
  // Range before the cast: the comparison is exact for doubles far outside long's range.
  if (*v != std::floor(*v) || *v < static_cast<double>(minimum) ||
      *v > static_cast<double>(maximum)) {
    addProblem(path, "must be a whole number from " + std::to_string(minimum) + " to " +
                         std::to_string(maximum));
    return fallback;
  }
  return static_cast<long>(*v);
}

std::optional<double> YamlDeck::getNumberInRange(const std::string& path, bool required,
                                                 double minimum, double maximum,
                                                 const std::string& unit) {
  const std::optional<double> v = readNumber(path, Sign::Any, required);
  if (v && !(*v >= minimum && *v <= maximum)) {
    std::ostringstream m;
    m << "must be between " << minimum << " and " << maximum << " " << unit << " (got " << *v
      << ")";
    addProblem(path, m.str());
    return std::nullopt;
  }
  return v;
}

std::string YamlDeck::getString(const std::string& path) {
  markKnown(path);
  const YAML::Node n = lookup(path);
  if (!n.IsDefined() || n.IsNull()) {
    addProblem(path, "missing key (text is required)");
    return {};
  }
  if (!n.IsScalar()) {
    addProblem(path, "expected text, found a " + std::string(n.IsMap() ? "section" : "list"));
    return {};
  }
  return n.Scalar();
}

std::string YamlDeck::getChoiceOr(const std::string& path, const std::vector<std::string>& choices,
                                  const std::string& fallback) {
  if (!has(path)) {
    markKnown(path);
    return fallback;
  }
  const std::string v = getString(path);
  for (const auto& c : choices) {
    if (v == c) return v;
  }
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  addProblem(path, "'" + v + "' is not one of: " + list);
  return fallback;
}

void YamlDeck::finish() {
  collectUnknown(root_, "");
  if (problems_.empty()) return;
  std::string all;
  for (const auto& p : problems_) all += p + "\n";
  all.pop_back();
  throw DeckError(all);
}

}  // namespace pistondyn::io
