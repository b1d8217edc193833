#include "pistondyn/io/SweepDeck.h"

#include "MessageText.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "Sha256.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/EngineDeck.h"

namespace pistondyn::io {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using common::formatNumber;

// At most this many distinct problems are listed (a key misspelt in a sweep of 10,000
// cases is one problem, reported once with the number of cases it affects).
constexpr std::size_t kMaxProblemLines = 50;
// Seeds are whole numbers a double holds exactly (YAML reads them as numbers).
constexpr double kMaxSeed = 9007199254740992.0;  // 2^53

std::string lineText(const YAML::Mark& mark) {
  return mark.line >= 0 ? ":" + std::to_string(mark.line + 1) : std::string();
}

std::string joinLines(const std::vector<std::string>& lines) {
  std::string all;
  for (const auto& l : lines)
    all += (all.empty() ? "" : "\n") + l;
  return all;
}

// One block's contribution to the cases: a list of partial assignments.
struct Assignment {
  std::string key, value;
  std::string origin;  // "<file>:<line>: <block>.<key>"
};
using PartialCase = std::vector<Assignment>;

class SweepDeckReader {
 public:
  explicit SweepDeckReader(std::string path) : path_(std::move(path)) {}

  SweepPlan read(const std::vector<std::string>& commandLineOverrides,
                 const LinerRegistry& registry);

 private:
  std::string at(const YAML::Node& node, const std::string& keyPath) const {
    return path_ + lineText(node.Mark()) + ": " + keyPath;
  }
  void problem(const YAML::Node& node, const std::string& keyPath, const std::string& what) {
    problems_.push_back(at(node, keyPath) + ": " + what);
  }
  // The keys of a mapping, each once; problems for duplicates and non-scalar keys.
  std::vector<std::pair<std::string, YAML::Node>> entries(const YAML::Node& map,
                                                          const std::string& prefix);
  bool checkKeyPath(const YAML::Node& keyNode, const std::string& key, const std::string& where);
  std::optional<std::string> valueText(const YAML::Node& value, const std::string& where);
  void claimKey(const std::string& key, const std::string& origin);

  void readSet(const YAML::Node& node);
  std::optional<std::vector<PartialCase>> readCartesian(const YAML::Node& node);
  std::optional<std::vector<PartialCase>> readCases(const YAML::Node& node);
  std::optional<std::vector<PartialCase>> readLatinHypercube(const YAML::Node& node);
  void checkCases(SweepPlan& plan, const std::vector<std::vector<std::string>>& origins,
                  const LinerRegistry& registry);

  std::string path_;
  std::vector<std::string> problems_;
  std::vector<std::string> fixedOverrides_;
  std::map<std::string, std::string> claimed_;  // key -> where the sweep deck sets it
  std::vector<SweepKey> sweptKeys_;
};

std::vector<std::pair<std::string, YAML::Node>> SweepDeckReader::entries(
    const YAML::Node& map, const std::string& prefix) {
  std::vector<std::pair<std::string, YAML::Node>> out;
  std::set<std::string> seen;
  for (const auto& kv : map) {
    if (!kv.first.IsScalar()) {
      problem(kv.first, prefix, "keys must be plain names, not lists or sections");
      continue;
    }
    const std::string key = kv.first.Scalar();
    const std::string where = prefix.empty() ? key : prefix + "." + key;
    if (!seen.insert(key).second) {
      problem(kv.first, where, "duplicate key (YAML would keep only one of them)");
      continue;
    }
    out.emplace_back(key, kv.second);
  }
  return out;
}

// A deck key path as --set takes it: sections and a key, "geometry.pin_offset_mm".
bool SweepDeckReader::checkKeyPath(const YAML::Node& keyNode, const std::string& key,
                                   const std::string& where) {
  bool ok = key.find('.') != std::string::npos && key.front() != '.' && key.back() != '.' &&
            key.find("..") == std::string::npos;
  for (const char c : key) {
    if (c == '=' || c == ' ' || c == '\t' || c == '\n')
      ok = false;
  }
  if (!ok) {
    problem(keyNode, where,
            "expected an engine-deck key path with its section, as --set takes it "
            "(e.g. geometry.pin_offset_mm)");
  }
  return ok;
}

// The value as --set is given it. Plain numbers become the shortest text that reads back
// to the same double (0.50 and 5e-1 are the same case); other plain text is kept as
// written, quoted text stays quoted, lists and sections are written in flow style.
std::optional<std::string> SweepDeckReader::valueText(const YAML::Node& value,
                                                      const std::string& where) {
  if (!value.IsDefined()) {
    problems_.push_back(path_ + lineText(value.Mark()) + ": " + where + ": a value is required");
    return std::nullopt;
  }
  // null (written `null` or `~`) removes the key from the base deck, as --set key=null does
  // (e.g. film_um when a case sets oil_supply.fully_flooded: true).
  if (value.IsNull())
    return std::string("null");
  if (value.IsScalar()) {
    if (value.Tag() != "!") {  // plain (unquoted)
      double v = 0.0;
      if (YAML::convert<double>::decode(value, v) && std::isfinite(v))
        return formatNumber(v);
      return value.Scalar();
    }
    YAML::Emitter e;
    e << YAML::DoubleQuoted << value.Scalar();
    return std::string(e.c_str());
  }
  YAML::Emitter e;
  e << YAML::Flow << value;
  return std::string(e.c_str());
}

void SweepDeckReader::claimKey(const std::string& key, const std::string& origin) {
  const auto [it, inserted] = claimed_.emplace(key, origin);
  if (!inserted && it->second != origin) {
    problems_.push_back(origin + ": the key is also set at " + it->second +
                        " (a key belongs to one block of the sweep deck)");
  }
}

void SweepDeckReader::readSet(const YAML::Node& node) {
  if (!node.IsMap()) {
    problem(node, "set", "expected a section of key: value overrides every case shares");
    return;
  }
  for (const auto& [key, value] : entries(node, "set")) {
    const std::string where = "set." + key;
    if (!checkKeyPath(value, key, where))
      continue;
    const auto text = valueText(value, where);
    if (!text)
      continue;
    claimKey(key, at(value, where));
    fixedOverrides_.push_back(key + "=" + *text);
  }
}

std::optional<std::vector<PartialCase>> SweepDeckReader::readCartesian(const YAML::Node& node) {
  if (!node.IsMap() || node.size() == 0) {
    problem(node, "cartesian",
            "expected a section of key: [value, value, ...] lists, e.g. "
            "geometry.pin_offset_mm: [-0.5, 0, 0.5]");
    return std::nullopt;
  }
  std::vector<PartialCase> grid(1);
  bool ok = true;
  for (const auto& [key, values] : entries(node, "cartesian")) {
    const std::string where = "cartesian." + key;
    if (!checkKeyPath(values, key, where)) {
      ok = false;
      continue;
    }
    const std::string origin = at(values, where);
    if (!values.IsSequence()) {
      problem(values, where,
              "expected a list of values, e.g. [1, 2, 3] (a value every case shares "
              "belongs under set:)");
      ok = false;
      continue;
    }
    if (values.size() == 0) {
      problem(values, where, "empty list: give at least one value");
      ok = false;
      continue;
    }
    std::vector<std::string> texts;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const auto text = valueText(values[i], where + " item " + std::to_string(i + 1));
      if (!text) {
        ok = false;
        continue;
      }
      if (std::find(texts.begin(), texts.end(), *text) != texts.end()) {
        problem(values[i], where,
                "item " + std::to_string(i + 1) + ": " + *text +
                    " is listed twice (it would run the same case twice)");
        ok = false;
        continue;
      }
      texts.push_back(*text);
    }
    claimKey(key, origin);
    sweptKeys_.push_back({key, origin});
    if (!ok)
      continue;
    if (static_cast<double>(grid.size()) * static_cast<double>(texts.size()) >
        static_cast<double>(SweepPlan::kMaxCases)) {
      problem(values, where,
              "the grid grows beyond " + std::to_string(SweepPlan::kMaxCases) + " cases");
      return std::nullopt;
    }
    // Earlier keys vary slowest: each existing point is followed by this key's values.
    std::vector<PartialCase> next;
    next.reserve(grid.size() * texts.size());
    for (const auto& point : grid) {
      for (const auto& t : texts) {
        next.push_back(point);
        next.back().push_back({key, t, origin});
      }
    }
    grid = std::move(next);
  }
  if (!ok)
    return std::nullopt;
  return grid;
}

std::optional<std::vector<PartialCase>> SweepDeckReader::readCases(const YAML::Node& node) {
  if (!node.IsSequence() || node.size() == 0) {
    problem(node, "cases",
            node.IsSequence() ? "empty list: give at least one case"
                              : "expected a list of cases, each a section of key: value "
                                "overrides, e.g. - {geometry.pin_offset_mm: 0.5}");
    return std::nullopt;
  }
  std::vector<PartialCase> out;
  bool ok = true;
  std::set<std::string> keysHere;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    const std::string prefix = "cases[" + std::to_string(i + 1) + "]";
    if (!item.IsMap() || item.size() == 0) {
      problem(item, prefix,
              "expected a section of key: value overrides, e.g. {geometry.pin_offset_mm: 0.5}");
      ok = false;
      continue;
    }
    PartialCase c;
    for (const auto& [key, value] : entries(item, prefix)) {
      const std::string where = prefix + "." + key;
      if (!checkKeyPath(value, key, where)) {
        ok = false;
        continue;
      }
      const auto text = valueText(value, where);
      if (!text) {
        ok = false;
        continue;
      }
      const std::string origin = at(value, where);
      if (keysHere.insert(key).second) {
        claimKey(key, origin);
        sweptKeys_.push_back({key, origin});
      }
      c.push_back({key, *text, origin});
    }
    out.push_back(std::move(c));
  }
  if (!ok)
    return std::nullopt;
  return out;
}

std::optional<std::vector<PartialCase>> SweepDeckReader::readLatinHypercube(
    const YAML::Node& node) {
  if (!node.IsMap()) {
    problem(node, "latin_hypercube", "expected a section with samples, seed and ranges");
    return std::nullopt;
  }
  bool ok = true;
  long samples = 0;
  std::uint64_t seed = 1;
  YAML::Node ranges;
  bool haveSamples = false;
  for (const auto& [key, value] : entries(node, "latin_hypercube")) {
    const std::string where = "latin_hypercube." + key;
    if (key == "samples" || key == "seed") {
      double v = 0.0;
      const bool number = value.IsScalar() && YAML::convert<double>::decode(value, v);
      const double maximum =
          key == "samples" ? static_cast<double>(SweepPlan::kMaxCases) : kMaxSeed;
      const double minimum = key == "samples" ? 1.0 : 0.0;
      if (!number || !std::isfinite(v) || v != std::floor(v) || v < minimum || v > maximum) {
        problem(value, where,
                "expected a whole number between " +
                    std::to_string(static_cast<long long>(minimum)) + " and " +
                    std::to_string(static_cast<long long>(maximum)) +
                    (value.IsScalar() ? " (got " + detail::shortenValue(value.Scalar()) + ")"
                                      : std::string()) +
                    (key == "samples" && number && v == 0.0
                         ? ": a Latin hypercube needs at least one sample"
                         : ""));
        ok = false;
      } else if (key == "samples") {
        samples = static_cast<long>(v);
        haveSamples = true;
      } else {
        seed = static_cast<std::uint64_t>(v);
      }
    } else if (key == "ranges") {
      ranges = value;
    } else {
      problem(value, where, "unknown key (expected samples, seed, ranges)");
      ok = false;
    }
  }
  if (!haveSamples && ok) {
    problem(node, "latin_hypercube.samples", "missing key (the number of samples is required)");
    ok = false;
  }
  if (!ranges.IsDefined() || !ranges.IsMap() || ranges.size() == 0) {
    problem(ranges.IsDefined() ? ranges : node, "latin_hypercube.ranges",
            ranges.IsDefined() ? "expected a section of key: [minimum, maximum] ranges"
                               : "missing key (a section of key: [minimum, maximum] ranges)");
    return std::nullopt;
  }
  std::vector<std::pair<double, double>> box;
  std::vector<std::string> keys, origins;
  for (const auto& [key, range] : entries(ranges, "latin_hypercube.ranges")) {
    const std::string where = "latin_hypercube.ranges." + key;
    if (!checkKeyPath(range, key, where)) {
      ok = false;
      continue;
    }
    const std::string origin = at(range, where);
    double lo = 0.0, hi = 0.0;
    const bool pair = range.IsSequence() && range.size() == 2 && range[0].IsScalar() &&
                      range[1].IsScalar() && YAML::convert<double>::decode(range[0], lo) &&
                      YAML::convert<double>::decode(range[1], hi) && std::isfinite(lo) &&
                      std::isfinite(hi);
    if (!pair) {
      problem(range, where, "expected [minimum, maximum], two numbers in the key's unit");
      ok = false;
      continue;
    }
    if (!(lo < hi)) {
      problem(range, where,
              "empty range [" + formatNumber(lo) + ", " + formatNumber(hi) +
                  "]: the minimum must be less than the maximum");
      ok = false;
      continue;
    }
    claimKey(key, origin);
    sweptKeys_.push_back({key, origin});
    box.emplace_back(lo, hi);
    keys.push_back(key);
    origins.push_back(origin);
  }
  if (!ok)
    return std::nullopt;
  const auto points = makeLatinHypercube(box, samples, seed);
  std::vector<PartialCase> out;
  out.reserve(points.size());
  for (const auto& p : points) {
    PartialCase c;
    for (std::size_t k = 0; k < keys.size(); ++k)
      c.push_back({keys[k], formatNumber(p[k]), origins[k]});
    out.push_back(std::move(c));
  }
  return out;
}

// The problems of loading case `caseIndex`'s deck, one per line. A line about one of the
// case's overrides ("--set KEY: ...") is given the place the sweep deck sets KEY.
struct CaseProblem {
  std::string origin;      // "<file>:<line>: <block>.<key>" or "" (base deck, command line)
  std::string assignment;  // "KEY=VALUE" of the first case with this problem
  std::string text;        // what is wrong
  int firstCase = 0;
  long count = 0;
};

void SweepDeckReader::checkCases(SweepPlan& plan,
                                 const std::vector<std::vector<std::string>>& origins,
                                 const LinerRegistry& registry) {
  std::vector<CaseProblem> found;
  std::map<std::pair<std::string, std::string>, std::size_t> byText;
  std::set<std::string> files;
  auto add = [&](const std::string& origin, const std::string& assignment, const std::string& text,
                 int index) {
    const auto [it, inserted] = byText.emplace(std::make_pair(origin, text), found.size());
    if (inserted)
      found.push_back({origin, assignment, text, index, 0});
    ++found[it->second].count;
  };
  for (std::size_t ci = 0; ci < plan.cases.size(); ++ci) {
    const SweepCase& c = plan.cases[ci];
    std::string message;
    try {
      const EngineDeck deck = loadEngineDeck(plan.baseDeckPath, plan.getOverrides(c), registry);
      files.insert(deck.cylinderPressureFile);
      for (const auto& in : deck.linerInputs) {
        const auto* text = std::get_if<std::string>(&in.value);
        if (text != nullptr && in.path.size() > 5 &&
            in.path.compare(in.path.size() - 5, 5, "_file") == 0)
          files.insert(*text);
      }
      continue;
    } catch (const DeckError& e) {
      message = e.what();
    } catch (const std::exception& e) {
      message = plan.baseDeckPath + ": the deck could not be read: " + e.what();
    }
    std::size_t begin = 0;
    while (begin <= message.size()) {
      const std::size_t end = std::min(message.find('\n', begin), message.size());
      const std::string line = message.substr(begin, end - begin);
      begin = end + 1;
      if (line.empty())
        continue;
      // The longest of the case's keys the line is about ("--set KEY: ..." or
      // "--set KEY" at its end).
      std::size_t best = c.assignments.size();
      for (std::size_t k = 0; k < c.assignments.size(); ++k) {
        const std::string head = "--set " + c.assignments[k].key;
        if (line.compare(0, head.size(), head) == 0 &&
            (line.size() == head.size() || line[head.size()] == ':') &&
            (best == c.assignments.size() ||
             c.assignments[k].key.size() > c.assignments[best].key.size()))
          best = k;
      }
      if (best < c.assignments.size()) {
        const SweepAssignment& a = c.assignments[best];
        const std::size_t head = std::string("--set ").size() + a.key.size();
        std::string rest = line.substr(head);
        if (rest.rfind(": ", 0) == 0)
          rest.erase(0, 2);
        add(origins[ci][best], a.key + "=" + a.value, rest, c.index);
        continue;
      }
      // A shared override from the sweep deck's `set`: give its line too.
      std::string origin;
      for (const auto& o : plan.fixedOverrides) {
        const std::string key = o.substr(0, o.find('='));
        const std::string head = "--set " + key;
        const auto claim = claimed_.find(key);
        if (claim != claimed_.end() && line.compare(0, head.size(), head) == 0 &&
            (line.size() == head.size() || line[head.size()] == ':')) {
          origin = claim->second;
          std::string rest = line.substr(head.size());
          if (rest.rfind(": ", 0) == 0)
            rest.erase(0, 2);
          add(origin, "", rest, c.index);
          break;
        }
      }
      if (origin.empty())
        add("", "", line, c.index);
    }
  }
  const long total = static_cast<long>(plan.cases.size());
  for (std::size_t i = 0; i < found.size() && i < kMaxProblemLines; ++i) {
    const CaseProblem& p = found[i];
    std::string cases;
    if (p.count == total && total > 1) {
      cases = "every case";
    } else {
      cases = "case " + std::to_string(p.firstCase);
      if (!p.assignment.empty())
        cases += " (" + p.assignment + ")";
      if (p.count > 1)
        cases += " and " + std::to_string(p.count - 1) + " other case" + (p.count > 2 ? "s" : "");
    }
    problems_.push_back((p.origin.empty() ? cases : p.origin + ": " + cases) + ": " + p.text);
  }
  if (found.size() > kMaxProblemLines) {
    problems_.push_back("... and " + std::to_string(found.size() - kMaxProblemLines) +
                        " more problems");
  }
  if (!problems_.empty())
    return;
  // The files the cases read, by content (the same table under two names counts once).
  std::map<std::string, std::string> bySha;
  for (const auto& f : files) {
    const auto sha = detail::sha256HexOfFile(f);
    if (!sha) {
      problems_.push_back(f + ": cannot read the file (a case's deck names it)");
      continue;
    }
    bySha.emplace(*sha, f);
  }
  for (const auto& [sha, path] : bySha)
    plan.inputFiles.push_back({path, sha});
}

Json fingerprintContent(const SweepPlan& plan) {
  Json j;
  j["format"] = "pistondyn sweep 1";
  j["base_deck_sha256"] = plan.baseDeckSha256;
  Json files = Json::array();
  for (const auto& f : plan.inputFiles)
    files.push_back(f.sha256);
  j["input_files_sha256"] = files;
  j["fixed_overrides"] = plan.fixedOverrides;
  Json keys = Json::array();
  for (const auto& k : plan.sweptKeys)
    keys.push_back(k.key);
  j["swept_keys"] = keys;
  Json cases = Json::array();
  for (const auto& c : plan.cases) {
    Json one = Json::array();
    for (const auto& a : c.assignments)
      one.push_back(a.key + "=" + a.value);
    cases.push_back(one);
  }
  j["cases"] = cases;
  return j;
}

SweepPlan SweepDeckReader::read(const std::vector<std::string>& commandLineOverrides,
                                const LinerRegistry& registry) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path_);
  } catch (const YAML::BadFile&) {
    throw DeckError(path_ + ": cannot open the sweep deck");
  } catch (const YAML::ParserException& e) {
    throw DeckError(path_ + lineText(e.mark) + ": not valid YAML: " + e.msg);
  } catch (const std::exception& e) {
    throw DeckError(path_ + ": cannot read the sweep deck: " + e.what());
  }
  if (!root.IsMap()) {
    throw DeckError(path_ +
                    ": a sweep deck is a YAML mapping (base_deck:, set:, cartesian:, cases:, "
                    "latin_hypercube:; see README.md, Design sweeps)");
  }
  SweepPlan plan;
  plan.sweepDeckPath = path_;
  std::optional<std::vector<PartialCase>> listed, grid, hypercube;
  bool blocksOk = true;
  YAML::Node baseNode;
  for (const auto& [key, value] : entries(root, "")) {
    if (key == "name") {
      if (value.IsScalar())
        plan.name = value.Scalar();
      else
        problem(value, key, "expected text");
    } else if (key == "base_deck") {
      baseNode = value;
    } else if (key == "set") {
      readSet(value);
    } else if (key == "cartesian") {
      grid = readCartesian(value);
      blocksOk = blocksOk && grid.has_value();
    } else if (key == "cases") {
      listed = readCases(value);
      blocksOk = blocksOk && listed.has_value();
    } else if (key == "latin_hypercube") {
      hypercube = readLatinHypercube(value);
      blocksOk = blocksOk && hypercube.has_value();
    } else {
      problem(value, key,
              "unknown key (a sweep deck has name, base_deck, set, cartesian, cases, "
              "latin_hypercube)");
    }
  }
  // The base deck, relative to the sweep deck's folder.
  if (!baseNode.IsDefined() || baseNode.IsNull()) {
    problems_.push_back(path_ + ": base_deck: missing key (the engine deck the cases start from)");
  } else if (!baseNode.IsScalar() || baseNode.Scalar().empty()) {
    problem(baseNode, "base_deck", "expected the path of an engine deck");
  } else {
    fs::path base(baseNode.Scalar());
    if (base.is_relative())
      base = fs::path(path_).parent_path() / base;
    std::error_code ec;
    const fs::path absolute = fs::absolute(base, ec).lexically_normal();
    plan.baseDeckPath = ec ? base.string() : absolute.string();
    const auto sha = detail::sha256HexOfFile(plan.baseDeckPath);
    if (!sha || fs::is_directory(plan.baseDeckPath, ec)) {
      problem(baseNode, "base_deck",
              "cannot open '" + plan.baseDeckPath +
                  "' (relative paths start at the sweep "
                  "deck's folder)");
    } else {
      plan.baseDeckSha256 = *sha;
    }
  }
  if (blocksOk && !listed && !grid && !hypercube) {
    problems_.push_back(path_ +
                        ": no cases: give cartesian:, cases: or latin_hypercube: (README.md, "
                        "Design sweeps)");
  }
  // Overrides from the command line, shared by every case after the deck's own.
  for (const auto& o : commandLineOverrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos || eq == 0) {
      problems_.push_back("--set " + o + ": expected key.path=value");
      continue;
    }
    const std::string key = o.substr(0, eq);
    const auto claim = claimed_.find(key);
    if (claim != claimed_.end() &&
        std::none_of(fixedOverrides_.begin(), fixedOverrides_.end(),
                     [&](const std::string& f) { return f.rfind(key + "=", 0) == 0; })) {
      problems_.push_back("--set " + key + ": the sweep varies this key (" + claim->second +
                          "); a --set cannot fix it");
      continue;
    }
    fixedOverrides_.push_back(o);
  }
  if (!problems_.empty())
    throw DeckError(joinLines(problems_));

  // The product of the blocks present: listed cases, then samples, then grid points.
  std::vector<PartialCase> product(1);
  for (const auto* block : {&listed, &hypercube, &grid}) {
    if (!*block)
      continue;
    if (static_cast<double>(product.size()) * static_cast<double>((*block)->size()) >
        static_cast<double>(SweepPlan::kMaxCases)) {
      throw DeckError(path_ + ": the sweep has more than " + std::to_string(SweepPlan::kMaxCases) +
                      " cases (the blocks multiply)");
    }
    std::vector<PartialCase> next;
    next.reserve(product.size() * (*block)->size());
    for (const auto& p : product) {
      for (const auto& q : **block) {
        next.push_back(p);
        next.back().insert(next.back().end(), q.begin(), q.end());
      }
    }
    product = std::move(next);
  }
  plan.fixedOverrides = fixedOverrides_;
  plan.sweptKeys = sweptKeys_;
  // Assignments in column order (a listed case need not set every key).
  std::map<std::string, std::size_t> column;
  for (std::size_t k = 0; k < sweptKeys_.size(); ++k)
    column.emplace(sweptKeys_[k].key, k);
  std::vector<std::vector<std::string>> origins;
  origins.reserve(product.size());
  for (std::size_t i = 0; i < product.size(); ++i) {
    PartialCase p = product[i];
    std::stable_sort(p.begin(), p.end(), [&](const Assignment& a, const Assignment& b) {
      return column.at(a.key) < column.at(b.key);
    });
    SweepCase c;
    c.index = static_cast<int>(i + 1);
    std::vector<std::string> o;
    for (const auto& a : p) {
      c.assignments.push_back({a.key, a.value});
      o.push_back(a.origin);
    }
    plan.cases.push_back(std::move(c));
    origins.push_back(std::move(o));
  }

  checkCases(plan, origins, registry);
  if (!problems_.empty())
    throw DeckError(joinLines(problems_));
  plan.fingerprint = detail::sha256Hex(fingerprintContent(plan).dump());
  return plan;
}

// Uniform in [0, n) without the bias of a plain modulo (n > 0).
std::uint64_t uniformIndex(std::mt19937_64& rng, std::uint64_t n) {
  const std::uint64_t limit = std::mt19937_64::max() - std::mt19937_64::max() % n;
  std::uint64_t x = rng();
  while (x >= limit)
    x = rng();
  return x % n;
}

// Uniform in (0, 1): the top 52 bits, centred in their cell (exact in a double, so
// neither 0 nor 1 can come out).
double uniformOpen(std::mt19937_64& rng) {
  return (static_cast<double>(rng() >> 12) + 0.5) * 0x1.0p-52;
}

}  // namespace

std::vector<std::string> SweepPlan::getOverrides(const SweepCase& c) const {
  std::vector<std::string> out = fixedOverrides;
  for (const auto& a : c.assignments)
    out.push_back(a.key + "=" + a.value);
  return out;
}

std::string SweepPlan::getCaseFolderName(int index) const {
  std::string digits = std::to_string(index);
  const std::size_t width = std::max<std::size_t>(4, std::to_string(cases.size()).size());
  if (digits.size() < width)
    digits.insert(0, width - digits.size(), '0');
  return "case_" + digits;
}

const SweepCase& SweepPlan::getCase(int index) const {
  if (index < 1 || index > static_cast<int>(cases.size()))
    throw std::out_of_range("SweepPlan::getCase: no case " + std::to_string(index));
  return cases[static_cast<std::size_t>(index - 1)];
}

SweepPlan loadSweepDeck(const std::string& sweepDeckPath,
                        const std::vector<std::string>& commandLineOverrides,
                        const LinerRegistry& registry) {
  return SweepDeckReader(sweepDeckPath).read(commandLineOverrides, registry);
}

std::vector<std::vector<double>> makeLatinHypercube(
    const std::vector<std::pair<double, double>>& ranges, long samples, std::uint64_t seed) {
  if (samples < 1)
    throw std::invalid_argument("makeLatinHypercube: samples = " + std::to_string(samples) +
                                " must be at least 1");
  for (const auto& [lo, hi] : ranges) {
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi))
      throw std::invalid_argument("makeLatinHypercube: range [" + formatNumber(lo) + ", " +
                                  formatNumber(hi) + "] must be finite with minimum < maximum");
  }
  const auto n = static_cast<std::size_t>(samples);
  std::vector<std::vector<double>> out(n, std::vector<double>(ranges.size()));
  std::mt19937_64 rng(seed);
  std::vector<std::size_t> stratum(n);
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    // Plain variables, not a structured binding: clang 14 (the sanitizer and fuzz build)
    // cannot capture a binding in the lambda below.
    const double lo = ranges[k].first, hi = ranges[k].second;
    std::iota(stratum.begin(), stratum.end(), std::size_t{0});
    for (std::size_t i = n - 1; i > 0; --i)  // Fisher-Yates
      std::swap(stratum[i], stratum[uniformIndex(rng, i + 1)]);
    const double width = hi - lo;
    for (std::size_t i = 0; i < n; ++i) {
      const double s = static_cast<double>(stratum[i]);
      double v = lo + (s + uniformOpen(rng)) / static_cast<double>(n) * width;
      // Rounding may put a value that lies within one ulp of its interval's edge into the
      // neighbour: step it back inside, so the documented stratum test holds exactly.
      const double centre = lo + (s + 0.5) / static_cast<double>(n) * width;
      auto interval = [&](double x) {
        return std::floor((x - lo) / width * static_cast<double>(n));
      };
      while (interval(v) != s)
        v = std::nextafter(v, centre);
      out[i][k] = v;
    }
  }
  return out;
}

std::string makeSweepJson(const SweepPlan& plan) {
  Json j;
  j["format"] = "pistondyn sweep 1";
  j["fingerprint"] = plan.fingerprint;
  j["sweep_deck"] = plan.sweepDeckPath;
  j["name"] = plan.name;
  j["base_deck"] = plan.baseDeckPath;
  j["base_deck_sha256"] = plan.baseDeckSha256;
  Json files = Json::array();
  for (const auto& f : plan.inputFiles)
    files.push_back({{"path", f.path}, {"sha256", f.sha256}});
  j["input_files"] = files;
  j["fixed_overrides"] = plan.fixedOverrides;
  Json keys = Json::array();
  for (const auto& k : plan.sweptKeys)
    keys.push_back({{"key", k.key}, {"origin", k.origin}});
  j["swept_keys"] = keys;
  Json cases = Json::array();
  for (const auto& c : plan.cases) {
    Json set = Json::object();
    for (const auto& a : c.assignments)
      set[a.key] = a.value;
    cases.push_back({{"case", c.index}, {"folder", plan.getCaseFolderName(c.index)}, {"set", set}});
  }
  j["cases"] = cases;
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

SweepPlan parseSweepJson(const std::string& text) {
  SweepPlan plan;
  try {
    const Json j = Json::parse(text);
    if (j.at("format").get<std::string>() != "pistondyn sweep 1")
      throw std::runtime_error("unknown format " + j.at("format").dump());
    plan.fingerprint = j.at("fingerprint").get<std::string>();
    plan.sweepDeckPath = j.at("sweep_deck").get<std::string>();
    plan.name = j.at("name").get<std::string>();
    plan.baseDeckPath = j.at("base_deck").get<std::string>();
    plan.baseDeckSha256 = j.at("base_deck_sha256").get<std::string>();
    for (const auto& f : j.at("input_files"))
      plan.inputFiles.push_back(
          {f.at("path").get<std::string>(), f.at("sha256").get<std::string>()});
    plan.fixedOverrides = j.at("fixed_overrides").get<std::vector<std::string>>();
    for (const auto& k : j.at("swept_keys"))
      plan.sweptKeys.push_back({k.at("key").get<std::string>(), k.at("origin").get<std::string>()});
    for (const auto& c : j.at("cases")) {
      SweepCase one;
      one.index = c.at("case").get<int>();
      if (one.index != static_cast<int>(plan.cases.size()) + 1)
        throw std::runtime_error("cases out of order at case " + std::to_string(one.index));
      for (const auto& [key, value] : c.at("set").items())
        one.assignments.push_back({key, value.get<std::string>()});
      plan.cases.push_back(std::move(one));
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("not a sweep description: ") + e.what());
  }
  return plan;
}

}  // namespace pistondyn::io
