#include "pistondyn/io/YamlDeck.h"

#include "MessageText.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "pistondyn/common/Validation.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/DeckKeys.h"
#include "pistondyn/io/DeckSection.h"

#include "FileBytes.h"

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

// Counts document starts and keeps the second one's position; builds nothing.
class DocumentCounter final : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++count_ == 2)
      secondStart_ = mark;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}

  int getCount() const { return count_; }
  const YAML::Mark& getSecondStart() const { return secondStart_; }

 private:
  int count_ = 0;
  YAML::Mark secondStart_;
};

// Whether the text holds a second document, and where it starts. Not YAML::LoadAll:
// yaml-cpp 0.7 (Debian 12) loops for ever, allocating, when a document's first token is
// one its parser does not consume (a lone ',': yaml-cpp issue #1040, fixed upstream in
// PR #1319). Here at most two documents are parsed, so every input ends.
std::optional<YAML::Mark> secondDocumentStart(const std::string& text) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentCounter counter;
  for (int i = 0; i < 2 && parser.HandleNextDocument(counter); ++i) {
  }
  if (counter.getCount() < 2)
    return std::nullopt;
  return counter.getSecondStart();
}

}  // namespace

struct YamlDeck::Impl {
  std::string filePath;
  YAML::Node root;
  std::set<std::string> known;        // every key path a getter asked for (and its parents)
  std::set<std::string> ignored;      // sections whose keys are never reported as unknown
  std::set<std::string> overridden;   // key paths set by --set
  std::set<std::string> fileIgnored;  // sections whose keys from the file are not checked
  std::map<std::string, std::string> fileValues;  // plain values --set replaced, as in the file
  std::vector<std::string> problems;
  std::vector<ResolvedInput> resolved;
  std::set<std::string> allowImplausible;  // checks.allow_implausible

  YAML::Node lookup(const std::string& path) const;                 // invalid node if absent
  // True if a section above `path` holds a value or a list instead (`drive: [1, 2]`): its
  // keys are not "missing", the section is the problem (reported by getSection()).
  bool isBelowAValue(const std::string& path) const {
    for (auto dot = path.find('.'); dot != std::string::npos; dot = path.find('.', dot + 1)) {
      const YAML::Node n = lookup(path.substr(0, dot));
      if (n.IsDefined() && !n.IsNull() && !n.IsMap())
        return true;
    }
    return false;
  }
  std::string overridingAssignment(const std::string& path) const;  // "" if from the file
  void collectUnknown(const YAML::Node& node, const std::string& prefix);
  bool isBelowFileIgnored(const std::string& path) const {
    for (const auto& section : fileIgnored) {
      if (path.rfind(section + ".", 0) == 0)
        return true;
    }
    return false;
  }
};

YamlDeck::~YamlDeck() = default;
YamlDeck::YamlDeck(YamlDeck&&) noexcept = default;
YamlDeck& YamlDeck::operator=(YamlDeck&&) noexcept = default;

YamlDeck::YamlDeck(std::string filePath) : impl_(std::make_unique<Impl>()) {
  std::string& filePath_ = impl_->filePath;
  YAML::Node& root_ = impl_->root;
  filePath_ = std::move(filePath);
  // Before yaml-cpp sees it: a folder opens as a stream that fails on the first read,
  // and yaml-cpp leaks its scanner when that read throws.
  std::error_code ec;
  if (std::filesystem::is_directory(filePath_, ec))
    throw DeckError(filePath_ + ": is a folder, not a deck file");
  // The bytes first: yaml-cpp stops at a NUL byte (the rest of the file would be silently
  // missing) and reads every document of a multi-document file.
  const std::optional<std::string> text = detail::readFileBytes(filePath_);
  if (!text)
    throw DeckError(filePath_ + ": cannot open the deck file");
  if (const auto nul = text->find('\0'); nul != std::string::npos) {
    const auto line = 1 + std::count(text->begin(), text->begin() + nul, '\n');
    throw DeckError(filePath_ + ":" + std::to_string(line) +
                    ": holds a NUL byte: a deck is UTF-8 text (a binary file, or saved as "
                    "UTF-16?)");
  }
  std::optional<YAML::Mark> secondDocument;
  try {
    root_ = YAML::Load(*text);  // the first document only
    if (root_.IsMap())
      secondDocument = secondDocumentStart(*text);
  } catch (const YAML::ParserException& e) {
    // yaml-cpp's depth guard (YAML::DeepRecursion, 2000 levels) says only "bad file".
    if (e.msg == YAML::ErrorMsg::BAD_FILE) {
      throw DeckError(filePath_ + lineText(e.mark) +
                      ": nested deeper than the YAML reader takes (2000 levels of lists or "
                      "sections); a deck is a mapping of sections a few levels deep");
    }
    throw DeckError(filePath_ + lineText(e.mark) + ": not valid YAML: " + e.msg);
  } catch (const std::exception& e) {
    throw DeckError(filePath_ + ": cannot read the deck file: " + e.what());
  }
  if (secondDocument) {
    throw DeckError(filePath_ + lineText(*secondDocument) +
                    ": a second YAML document (after '---'): a deck is one document, and "
                    "nothing after the first would be read; remove the '---' line or merge "
                    "the documents");
  }
  if (!root_.IsMap()) {
    throw DeckError(filePath_ +
                    ": the deck must be a YAML mapping of sections (engine:, "
                    "geometry:, ...)");
  }
}

const std::string& YamlDeck::getFilePath() const {
  return impl_->filePath;
}

std::string YamlDeck::getDirectory() const {
  const std::string& f = impl_->filePath;
  const auto slash = f.find_last_of('/');
  return slash == std::string::npos ? std::string() : f.substr(0, slash + 1);
}

std::string YamlDeck::resolvePath(const std::string& path) const {
  return (!path.empty() && path[0] == '/') ? path : getDirectory() + path;
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
    if (part.empty())
      throw DeckError("--set " + path + ": empty key in the path");
  }
  YAML::Node value;
  try {
    value = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw DeckError("--set " + path + ": value '" + text + "' is not valid YAML: " + e.msg);
  }
  // What the file said, for getFileValue() (the first --set of a key replaces the file's).
  if (impl_->overridden.count(path) == 0 && impl_->overridingAssignment(path).empty()) {
    const YAML::Node old = impl_->lookup(path);
    if (old.IsDefined() && old.IsScalar() && old.Mark().line >= 0)
      impl_->fileValues.emplace(path, old.Scalar());
  }
  // yaml-cpp nodes are handles: walk with a copy and assign into the last map.
  YAML::Node node = impl_->root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node child = node[parts[i]];
    if (child.IsDefined() && !child.IsMap()) {
      throw DeckError("--set " + path + ": '" + parts[i] + "' is a value, not a section");
    }
    if (!child.IsDefined())
      node[parts[i]] = YAML::Node(YAML::NodeType::Map);
    node.reset(node[parts[i]]);
  }
  // A value for a whole section would drop every key of it ("--set geometry=5" then
  // reports each as missing): name the mistake instead. A section for a section, or null
  // (removes the section, as for a key), is fine.
  const YAML::Node replaced = impl_->lookup(path);
  if (replaced.IsDefined() && replaced.IsMap() && !value.IsMap() && !value.IsNull()) {
    std::string example;
    for (const auto& kv : replaced) {
      if (kv.first.IsScalar()) {
        example = " (e.g. --set " + path + "." + kv.first.Scalar() + "=...)";
        break;
      }
    }
    throw DeckError("--set " + path + ": '" + path +
                    "' is a section of the deck, not a value: set one of its keys" + example);
  }
  node[parts.back()] = value;
  impl_->overridden.insert(path);
}

YAML::Node YamlDeck::Impl::lookup(const std::string& path) const {
  // Walk through const references so a missing key is never inserted.
  YAML::Node cur = root;
  if (path.empty())
    return cur;
  for (const std::string& p : splitPath(path)) {
    if (!cur.IsMap())
      return YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node next = static_cast<const YAML::Node&>(cur)[p];
    if (!next.IsDefined())
      return YAML::Node(YAML::NodeType::Undefined);
    cur.reset(next);
  }
  return cur;
}

bool YamlDeck::has(const std::string& path) const {
  const YAML::Node n = impl_->lookup(path);
  return n.IsDefined() && !n.IsNull();
}

std::string YamlDeck::Impl::overridingAssignment(const std::string& path) const {
  // The key itself, or a section above it, set on the command line.
  for (std::string p = path;;) {
    if (overridden.count(p) != 0)
      return p;
    const auto dot = p.find_last_of('.');
    if (dot == std::string::npos)
      return {};
    p = p.substr(0, dot);
  }
}

std::string YamlDeck::where(const std::string& path) const {
  const std::string set = impl_->overridingAssignment(path);
  if (!set.empty())
    return set == path ? "--set " + path : "--set " + set + ": " + path;
  // The key's own line, else (a missing key) the line of its nearest section.
  for (std::string p = path;;) {
    const YAML::Node n = impl_->lookup(p);
    if (n.IsDefined() && n.Mark().line >= 0)
      return impl_->filePath + lineText(n.Mark()) + ": " + path;
    const auto dot = p.find_last_of('.');
    if (dot == std::string::npos)
      return impl_->filePath + ": " + path;
    p = p.substr(0, dot);
  }
}

void YamlDeck::addProblem(const std::string& path, const std::string& message) {
  impl_->problems.push_back(where(path) + ": " + message);
}

bool YamlDeck::hasProblems() const {
  return !impl_->problems.empty();
}

void YamlDeck::Impl::collectUnknown(const YAML::Node& node, const std::string& prefix) {
  std::set<std::string> seen;
  for (const auto& kv : node) {
    const std::string at = filePath + lineText(kv.first.Mark()) + ": ";
    if (!kv.first.IsScalar()) {
      problems.push_back(at + (prefix.empty() ? std::string() : prefix + ": ") +
                         "keys must be plain names, not lists or sections");
      continue;
    }
    const std::string key = kv.first.Scalar();
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    if (!seen.insert(key).second) {
      problems.push_back(at + path + ": duplicate key (YAML would keep only one of them)");
      continue;
    }
    const bool fromFile = kv.first.Mark().line >= 0 && overridingAssignment(path).empty();
    if (known.count(path) == 0 && fromFile && isBelowFileIgnored(path)) {
      if (kv.second.IsMap())
        collectUnknown(kv.second, path);  // keys a --set added below it are still checked
      continue;
    }
    if (known.count(path) == 0) {
      // From the file, from a --set of this key or a section above it, or a section
      // that exists only because a --set below it created it.
      std::string origin = at + path;
      if (!overridingAssignment(path).empty()) {
        const std::string set = overridingAssignment(path);
        origin = set == path ? "--set " + path : "--set " + set + ": " + path;
      } else if (kv.first.Mark().line < 0) {
        for (const auto& o : overridden) {
          if (o.rfind(path + ".", 0) == 0)
            origin = "--set " + o;
        }
      }
      problems.push_back(origin +
                         ": unknown key (misspelt, or a unit the key does not take? "
                         "`pistondyn keys` lists every key)");
    } else if (kv.second.IsMap() && ignored.count(path) == 0) {
      collectUnknown(kv.second, path);
    }
  }
}

void YamlDeck::markKnown(const std::string& path) {
  // The key and every section above it are part of the schema.
  for (std::size_t pos = path.find('.'); pos != std::string::npos; pos = path.find('.', pos + 1)) {
    impl_->known.insert(path.substr(0, pos));
  }
  impl_->known.insert(path);
}

void YamlDeck::ignoreFileKeys(const std::string& path) {
  impl_->fileIgnored.insert(path);
}

std::optional<std::string> YamlDeck::getFileValue(const std::string& path) const {
  const auto it = impl_->fileValues.find(path);
  if (it == impl_->fileValues.end())
    return std::nullopt;
  return it->second;
}

void YamlDeck::ignoreSection(const std::string& path) {
  markKnown(path);
  impl_->ignored.insert(path);
}

const std::vector<ResolvedInput>& YamlDeck::getResolvedInputs() const {
  return impl_->resolved;
}

void YamlDeck::recordInput(ResolvedInput input) {
  // A value resolved again (a default the deck then replaces) takes the earlier one's place.
  for (ResolvedInput& r : impl_->resolved) {
    if (r.path == input.path) {
      r = std::move(input);
      return;
    }
  }
  impl_->resolved.push_back(std::move(input));
}

namespace {

// "found a section" / "found a list" for a non-scalar node.
std::string foundKind(const YAML::Node& n) {
  return std::string(n.IsMap() ? "section" : "list");
}

// Numbers in messages: the shortest text that reads back to the same double.
std::string formatBound(double v) {
  return common::formatNumber(v);
}

// The problem with a number outside `bounds`, in the words the deck has always used.
std::string boundsMessage(const Bounds& b, const std::string& given, const std::string& unit) {
  // The value as written (a number of 100,000 digits is still one line).
  const std::string text = detail::shortenValue(given);
  const bool lower = std::isfinite(b.minimum), upper = std::isfinite(b.maximum);
  const std::string u = unit.empty() ? std::string() : " " + unit;
  if (lower && !upper && b.minimum == 0.0)
    return (b.excludeMinimum ? "must be positive (got " : "must not be negative (got ") + text +
           ")";
  if (lower && upper && (b.excludeMinimum || b.excludeMaximum)) {
    return std::string(b.excludeMinimum ? "must be above " : "must be at least ") +
           formatBound(b.minimum) + u + (b.excludeMaximum ? " and below " : " and at most ") +
           formatBound(b.maximum) + u + " (got " + text + ")";
  }
  if (lower && upper) {
    return "must be between " + formatBound(b.minimum) + " and " + formatBound(b.maximum) + u +
           " (got " + text + ")";
  }
  if (lower) {
    return std::string(b.excludeMinimum ? "must be greater than " : "must be at least ") +
           formatBound(b.minimum) + u + " (got " + text + ")";
  }
  return std::string(b.excludeMaximum ? "must be below " : "must be at most ") +
         formatBound(b.maximum) + u + " (got " + text + ")";
}

// A finite double from a scalar node, or the problem with it.
std::optional<double> scalarToNumber(const YAML::Node& n, std::string& problem) {
  double v = 0.0;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    problem = detail::quoteValue(n.Scalar()) + " is not a number";
    return std::nullopt;
  }
  if (!std::isfinite(v)) {
    problem = detail::quoteValue(n.Scalar()) + " is not a finite number";
    return std::nullopt;
  }
  return v;
}

Bounds boundsOf(YamlDeck::Sign sign) {
  switch (sign) {
    case YamlDeck::Sign::Positive:
      return Bounds::positive();
    case YamlDeck::Sign::NonNegative:
      return Bounds::nonNegative();
    case YamlDeck::Sign::Any:
    default:
      return Bounds::any();
  }
}

}  // namespace

std::optional<double> YamlDeck::readNumber(const std::string& path, const Bounds& bounds,
                                           bool required, const std::string& unit) {
  markKnown(path);
  const YAML::Node n = impl_->lookup(path);
  if (!n.IsDefined() || n.IsNull()) {
    if (required && !impl_->isBelowAValue(path))
      addProblem(path, "missing key (a number is required)");
    return std::nullopt;
  }
  if (!n.IsScalar()) {
    addProblem(path, "expected a number, found a " + foundKind(n));
    return std::nullopt;
  }
  std::string problem;
  const std::optional<double> v = scalarToNumber(n, problem);
  if (!v) {
    addProblem(path, problem);
    return std::nullopt;
  }
  if (!bounds.contains(*v)) {
    // Sign checks quote the value as written, range checks as read (as they always have).
    const bool signOnly = !std::isfinite(bounds.maximum) && bounds.minimum == 0.0;
    addProblem(path, boundsMessage(bounds, signOnly ? n.Scalar() : formatBound(*v), unit));
    return std::nullopt;
  }
  return v;
}

std::optional<std::vector<double>> YamlDeck::readNumberList(const std::string& path,
                                                            const Bounds& bounds, bool required,
                                                            const std::string& unit) {
  markKnown(path);
  const YAML::Node n = impl_->lookup(path);
  if (!n.IsDefined() || n.IsNull()) {
    if (required && !impl_->isBelowAValue(path))
      addProblem(path, "missing key (a list of numbers is required, e.g. [1, 2, 3])");
    return std::nullopt;
  }
  if (!n.IsSequence()) {
    addProblem(path, "expected a list of numbers, e.g. [1, 2, 3], found a " +
                         std::string(n.IsMap() ? "section" : "single value"));
    return std::nullopt;
  }
  std::vector<double> out;
  bool ok = true;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const YAML::Node item = n[i];
    const std::string which = "item " + std::to_string(i + 1) + ": ";
    if (!item.IsScalar()) {
      addProblem(path, which + "expected a number, found a " + foundKind(item));
      ok = false;
      continue;
    }
    std::string problem;
    const std::optional<double> v = scalarToNumber(item, problem);
    if (!v) {
      addProblem(path, which + problem);
      ok = false;
    } else if (!bounds.contains(*v)) {
      addProblem(path, which + boundsMessage(bounds, item.Scalar(), unit));
      ok = false;
    } else {
      out.push_back(*v);
    }
  }
  if (!ok)
    return std::nullopt;
  return out;
}

std::optional<bool> YamlDeck::readBool(const std::string& path, bool required) {
  markKnown(path);
  const YAML::Node n = impl_->lookup(path);
  if (!n.IsDefined() || n.IsNull()) {
    if (required && !impl_->isBelowAValue(path))
      addProblem(path, "missing key (true or false is required)");
    return std::nullopt;
  }
  if (n.IsScalar()) {
    const std::string& t = n.Scalar();
    if (t == "true" || t == "True" || t == "TRUE")
      return true;
    if (t == "false" || t == "False" || t == "FALSE")
      return false;
    addProblem(path, "expected true or false, found " + detail::quoteValue(t));
  } else {
    addProblem(path, "expected true or false, found a " + foundKind(n));
  }
  return std::nullopt;
}

std::optional<std::string> YamlDeck::readString(const std::string& path, bool required) {
  markKnown(path);
  const YAML::Node n = impl_->lookup(path);
  if (!n.IsDefined() || n.IsNull()) {
    if (required && !impl_->isBelowAValue(path))
      addProblem(path, "missing key (text is required)");
    return std::nullopt;
  }
  if (!n.IsScalar()) {
    addProblem(path, "expected text, found a " + foundKind(n));
    return std::nullopt;
  }
  return n.Scalar();
}

double YamlDeck::getNumber(const std::string& path, Sign sign) {
  return readNumber(path, boundsOf(sign), true).value_or(1.0);
}

std::optional<double> YamlDeck::getOptionalNumber(const std::string& path, Sign sign) {
  return readNumber(path, boundsOf(sign), false);
}

double YamlDeck::getNumberOr(const std::string& path, double fallback, Sign sign) {
  return readNumber(path, boundsOf(sign), false).value_or(fallback);
}

long YamlDeck::getIntegerOr(const std::string& path, long fallback, long minimum, long maximum) {
  const std::optional<double> v = readNumber(path, Bounds::any(), false);
  if (!v)
    return fallback;
  // Range before the cast: the comparison is exact for doubles far outside long's range.
  if (*v != std::floor(*v) || *v < static_cast<double>(minimum) ||
      *v > static_cast<double>(maximum)) {
    addProblem(path, "must be a whole number from " + std::to_string(minimum) + " to " +
                         std::to_string(maximum));
    return fallback;
  }
  return static_cast<long>(*v);
}

std::optional<double> YamlDeck::readKeyNumber(const DeckKey& key) {
  const std::optional<UnitSuffix> unitSuffix = key.getUnit();
  const std::string unit = unitSuffix ? unitSuffix->suffix : std::string();
  const bool present = has(key.path);
  const std::optional<double> v = readNumber(key.path, Bounds::any(), key.required, unit);
  if (!v)
    return present ? std::nullopt : key.defaultValue;
  const std::string slip = describeUnitSlip(key, *v);
  const std::string hint = slip.empty() ? std::string() : "; " + slip;
  if (key.kind == DeckValueKind::WholeNumber) {
    if (*v != std::floor(*v) || !key.valid.contains(*v)) {
      addProblem(key.path, "must be a whole number from " + formatBound(key.valid.minimum) +
                               " to " + formatBound(key.valid.maximum) + " (got " +
                               formatBound(*v) + ")");
      return std::nullopt;
    }
  } else if (!key.valid.contains(*v)) {
    const std::string reason = key.rangeReason.empty() ? std::string() : ": " + key.rangeReason;
    addProblem(key.path, boundsMessage(key.valid, formatBound(*v), unit) + reason + hint);
    return std::nullopt;
  }
  if (key.plausible && !key.plausible->contains(*v) && !isImplausibleAllowed(key.path)) {
    const std::string u = unit.empty() ? std::string() : " " + unit;
    addProblem(key.path, formatBound(*v) + u + " is outside the plausible range [" +
                             formatBound(key.plausible->minimum) + ", " +
                             formatBound(key.plausible->maximum) + "]" + u +
                             " of the engines pistondyn is for" + hint +
                             " (if the value is right, list the key under " +
                             kAllowImplausibleKey + ")");
    return std::nullopt;
  }
  return v;
}

void YamlDeck::readAllowedImplausible(const std::vector<const DeckKeyTable*>& tables) {
  markKnown(kAllowImplausibleKey);
  const YAML::Node n = impl_->lookup(kAllowImplausibleKey);
  if (!n.IsDefined() || n.IsNull())
    return;
  if (!n.IsSequence()) {
    addProblem(kAllowImplausibleKey, "expected a list of key paths, e.g. [geometry.bore_mm]");
    return;
  }
  for (std::size_t i = 0; i < n.size(); ++i) {
    const YAML::Node item = n[i];
    const std::string which = "item " + std::to_string(i + 1) + ": ";
    if (!item.IsScalar()) {
      addProblem(kAllowImplausibleKey, which + "expected a key path, found a " + foundKind(item));
      continue;
    }
    const DeckKey* key = nullptr;
    for (const DeckKeyTable* t : tables)
      key = key != nullptr ? key : t->find(item.Scalar());
    if (key == nullptr || !key->plausible) {
      addProblem(kAllowImplausibleKey,
                 which + detail::quoteValue(item.Scalar()) +
                     " is not a key with a plausible range (`pistondyn keys` lists them)");
      continue;
    }
    impl_->allowImplausible.insert(item.Scalar());
  }
}

bool YamlDeck::isImplausibleAllowed(const std::string& path) const {
  return impl_->allowImplausible.count(path) != 0;
}

std::vector<std::string> YamlDeck::getKnownKeys() const {
  return {impl_->known.begin(), impl_->known.end()};
}

std::optional<double> YamlDeck::getNumberInRange(const std::string& path, bool required,
                                                 double minimum, double maximum,
                                                 const std::string& unit) {
  return readNumber(path, Bounds::between(minimum, maximum), required, unit);
}

std::string YamlDeck::getString(const std::string& path) {
  return readString(path, true).value_or(std::string());
}

std::string YamlDeck::getChoiceOr(const std::string& path, const std::vector<std::string>& choices,
                                  const std::string& fallback) {
  if (!has(path)) {
    markKnown(path);
    return fallback;
  }
  const std::string v = getString(path);
  for (const auto& c : choices) {
    if (v == c)
      return v;
  }
  std::string list;
  for (const auto& c : choices)
    list += (list.empty() ? "" : ", ") + c;
  addProblem(path, detail::quoteValue(v) + " is not one of: " + list);
  return fallback;
}

DeckSection YamlDeck::getSection(const std::string& path) {
  if (!path.empty()) {
    markKnown(path);
    const YAML::Node n = impl_->lookup(path);
    if (n.IsDefined() && !n.IsNull() && !n.IsMap()) {
      addProblem(path, "expected a section (indented 'key: value' lines), found a " +
                           std::string(n.IsSequence() ? "list" : "value"));
    }
  }
  return DeckSection(*this, path);
}

void YamlDeck::finish() {
  impl_->collectUnknown(impl_->root, "");
  if (impl_->problems.empty())
    return;
  std::string all;
  for (const auto& p : impl_->problems)
    all += p + "\n";
  all.pop_back();
  throw DeckError(all);
}

}  // namespace pistondyn::io
