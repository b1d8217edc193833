#include "StudyDeckReader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <variant>

#include <nlohmann/json.hpp>

#include "Sha256.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/Units.h"

namespace pistondyn::design {

const std::array<const char*, 4> ProfileSpec::kNames = {
    "top_drop_um", "bottom_drop_um", "min_clearance_height_mm", "curvature_um_per_mm2"};

namespace detail {
namespace {

namespace fs = std::filesystem;
using common::formatNumber;

std::string lineText(const YAML::Mark& mark) {
  return mark.line >= 0 ? ":" + std::to_string(mark.line + 1) : std::string();
}

// The value of a resolved input in the unit of its deck key (inputs are kept in SI).
std::optional<double> inDeckUnit(const io::ResolvedInput& in) {
  const double* si = std::get_if<double>(&in.value);
  if (si == nullptr)
    return std::nullopt;
  if (in.path == in.siPath)
    return *si;
  for (int q = 0; q <= static_cast<int>(io::Quantity::WearCoefficient); ++q) {
    const auto unit = io::findUnitSuffix(in.path, static_cast<io::Quantity>(q));
    if (unit && io::toSIKey(in.path, *unit) == in.siPath)
      return (*si - unit->offset) / unit->factor;
  }
  return std::nullopt;
}

const char* kindOf(const io::ResolvedInput::Value& v) {
  if (std::holds_alternative<double>(v))
    return "a number";
  if (std::holds_alternative<long>(v))
    return "a whole number (a design variable must vary continuously)";
  if (std::holds_alternative<bool>(v))
    return "a switch (true / false)";
  if (std::holds_alternative<std::string>(v))
    return "text or a file";
  return "a list";
}

// Each line of a deck error after `head`.
std::string indent(const std::string& message) {
  std::string out;
  for (std::size_t b = 0; b <= message.size();) {
    const std::size_t end = std::min(message.find('\n', b), message.size());
    if (end > b)
      out += "\n    " + message.substr(b, end - b);
    b = end + 1;
  }
  return out;
}

}  // namespace

std::string assignment(const std::string& key, double value) {
  return key + "=" + formatNumber(value);
}

StudyDeckReader::StudyDeckReader(std::string path, std::string kind)
    : path_(std::move(path)), kind_(std::move(kind)) {}

std::string StudyDeckReader::at(const YAML::Node& node, const std::string& keyPath) const {
  return path_ + lineText(node.Mark()) + ": " + keyPath;
}

void StudyDeckReader::problem(const YAML::Node& node, const std::string& keyPath,
                              const std::string& what) {
  problems_.push_back(at(node, keyPath) + ": " + what);
}

void StudyDeckReader::throwIfProblems() const {
  if (problems_.empty())
    return;
  std::string all;
  for (const auto& p : problems_)
    all += (all.empty() ? "" : "\n") + p;
  throw io::DeckError(all);
}

std::string StudyDeckReader::resolve(const std::string& path) const {
  fs::path p(path);
  if (p.is_relative())
    p = fs::path(path_).parent_path() / p;
  std::error_code ec;
  const fs::path a = fs::absolute(p, ec);
  return ec ? p.string() : a.lexically_normal().string();
}

std::vector<std::pair<std::string, YAML::Node>> StudyDeckReader::open() {
  try {
    root_ = YAML::LoadFile(path_);
  } catch (const YAML::BadFile&) {
    throw io::DeckError(path_ + ": cannot open the " + kind_ + " deck");
  } catch (const YAML::ParserException& e) {
    throw io::DeckError(path_ + lineText(e.mark) + ": not valid YAML: " + e.msg);
  } catch (const std::exception& e) {
    throw io::DeckError(path_ + ": cannot read the " + kind_ + " deck: " + e.what());
  }
  if (!root_.IsMap())
    throw io::DeckError(path_ + ": a " + kind_ +
                        " deck is a YAML mapping (base_deck:, set:, ...; README.md, The design "
                        "loop)");
  return entries(root_, "");
}

std::vector<std::pair<std::string, YAML::Node>> StudyDeckReader::entries(
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

std::optional<double> StudyDeckReader::number(const YAML::Node& node, const std::string& where) {
  double v = 0.0;
  if (node.IsScalar() && node.Tag() != "!" && YAML::convert<double>::decode(node, v) &&
      std::isfinite(v))
    return v;
  problem(node, where,
          "expected a finite number" +
              (node.IsScalar() ? " (got '" + node.Scalar() + "')" : std::string()));
  return std::nullopt;
}

std::optional<long> StudyDeckReader::wholeNumber(const YAML::Node& node, const std::string& where,
                                                 long minimum, long maximum) {
  double v = 0.0;
  if (node.IsScalar() && YAML::convert<double>::decode(node, v) && std::isfinite(v) &&
      v == std::floor(v) && v >= static_cast<double>(minimum) && v <= static_cast<double>(maximum))
    return static_cast<long>(v);
  problem(node, where,
          "expected a whole number from " + std::to_string(minimum) + " to " +
              std::to_string(maximum) +
              (node.IsScalar() ? " (got '" + node.Scalar() + "')" : std::string()));
  return std::nullopt;
}

std::optional<std::string> StudyDeckReader::text(const YAML::Node& node, const std::string& where) {
  if (node.IsScalar() && !node.Scalar().empty())
    return node.Scalar();
  problem(node, where, "expected text");
  return std::nullopt;
}

std::optional<std::pair<double, double>> StudyDeckReader::range(const YAML::Node& node,
                                                                const std::string& where) {
  double lo = 0.0, hi = 0.0;
  const bool pair = node.IsSequence() && node.size() == 2 && node[0].IsScalar() &&
                    node[1].IsScalar() && YAML::convert<double>::decode(node[0], lo) &&
                    YAML::convert<double>::decode(node[1], hi) && std::isfinite(lo) &&
                    std::isfinite(hi);
  if (!pair) {
    problem(node, where, "expected [lower, upper], two finite numbers in the key's unit");
    return std::nullopt;
  }
  if (!(lo < hi)) {
    problem(node, where,
            "bounds [" + formatNumber(lo) + ", " + formatNumber(hi) +
                "]: the lower bound must be less than the upper bound");
    return std::nullopt;
  }
  return std::make_pair(lo, hi);
}

std::optional<std::string> StudyDeckReader::getBaseDeckPath() const {
  if (!baseNode_.IsDefined() || !baseNode_.IsScalar() || baseNode_.Scalar().empty())
    return std::nullopt;
  return resolve(baseNode_.Scalar());
}

void StudyDeckReader::addVariable(const DesignVariable& v) {
  if (!hasVariable(v.key))
    variables_.push_back(v);
}

bool StudyDeckReader::hasVariable(const std::string& key) const {
  return std::any_of(variables_.begin(), variables_.end(),
                     [&](const DesignVariable& v) { return v.key == key; });
}

bool StudyDeckReader::isSet(const std::string& key) const {
  return std::any_of(setOrigins_.begin(), setOrigins_.end(),
                     [&](const auto& s) { return s.first == key; });
}

bool StudyDeckReader::checkKeyPath(const YAML::Node& node, const std::string& key,
                                   const std::string& where) {
  bool ok = key.find('.') != std::string::npos && key.front() != '.' && key.back() != '.' &&
            key.find("..") == std::string::npos;
  for (const char c : key)
    ok = ok && c != '=' && c != ' ' && c != '\t';
  if (!ok)
    problem(node, where,
            "expected an engine-deck key path with its section, as --set takes it (e.g. "
            "geometry.pin_offset_mm)");
  return ok;
}

bool StudyDeckReader::readCommon(const std::string& key, const YAML::Node& value,
                                 const std::string& variablesBlock, bool withStart) {
  variablesBlock_ = variablesBlock;
  if (key == "name") {
    if (const auto t = text(value, key))
      name_ = *t;
  } else if (key == "base_deck") {
    baseNode_.reset(value);
  } else if (key == "set") {
    readSet(value);
  } else if (key == variablesBlock) {
    sawVariables_ = true;
    readVariables(value, variablesBlock, withStart);
  } else if (key == "profile") {
    readProfile(value);
  } else {
    return false;
  }
  return true;
}

void StudyDeckReader::readSet(const YAML::Node& node) {
  if (!node.IsMap()) {
    problem(node, "set", "expected a section of key: value overrides every evaluation shares");
    return;
  }
  for (const auto& [key, value] : entries(node, "set")) {
    const std::string where = "set." + key;
    if (!checkKeyPath(value, key, where))
      continue;
    std::string text;
    if (value.IsNull()) {
      text = "null";
    } else if (value.IsScalar()) {
      double v = 0.0;
      text = value.Tag() != "!" && YAML::convert<double>::decode(value, v) && std::isfinite(v)
                 ? formatNumber(v)
                 : value.Scalar();
    } else {
      YAML::Emitter e;
      e << YAML::Flow << value;
      text = e.c_str();
    }
    setOverrides_.push_back(key + "=" + text);
    setOrigins_.emplace_back(key, at(value, where));
  }
}

void StudyDeckReader::readVariables(const YAML::Node& node, const std::string& block,
                                    bool withStart) {
  if (!node.IsMap() || node.size() == 0) {
    problem(node, block,
            std::string("expected a section of key: [lower, upper]") +
                (withStart ? " or key: {bounds: [lower, upper], start: value}" : "") +
                " entries, e.g. geometry.pin_offset_mm: [-1, 1]");
    return;
  }
  for (const auto& [key, value] : entries(node, block)) {
    const std::string where = block + "." + key;
    if (!checkKeyPath(value, key, where))
      continue;
    DesignVariable v;
    v.key = key;
    v.origin = at(value, where);
    // reset() rebinds a YAML::Node; operator= would write into the node it refers to.
    YAML::Node bounds;
    bounds.reset(value);
    if (withStart && value.IsMap()) {
      bounds.reset(YAML::Node());
      for (const auto& [k, x] : entries(value, where)) {
        if (k == "bounds")
          bounds.reset(x);
        else if (k == "start")
          v.start = number(x, where + ".start");
        else
          problem(x, where + "." + k, "unknown key (expected bounds, start)");
      }
      if (!bounds.IsDefined()) {
        problem(value, where + ".bounds", "missing key ([lower, upper] in the key's unit)");
        continue;
      }
    }
    const auto r = range(bounds, where);
    if (!r)
      continue;
    v.lower = r->first;
    v.upper = r->second;
    if (v.start && !(*v.start >= v.lower && *v.start <= v.upper)) {
      problem(value, where + ".start",
              formatNumber(*v.start) + " lies outside the bounds [" + formatNumber(v.lower) + ", " +
                  formatNumber(v.upper) + "]");
      continue;
    }
    variables_.push_back(v);
  }
}

void StudyDeckReader::readProfile(const YAML::Node& node) {
  if (!node.IsMap()) {
    problem(node, "profile",
            "expected a section with top_drop_um, bottom_drop_um, min_clearance_height_mm, "
            "curvature_um_per_mm2 (each a number, or [lower, upper] to vary it) and rows");
    return;
  }
  profile_.enabled = true;
  std::array<bool, 4> given{};
  for (const auto& [key, value] : entries(node, "profile")) {
    const std::string where = "profile." + key;
    if (key == "rows") {
      if (const auto n = wholeNumber(value, where, 5, 10000))
        profile_.rows = static_cast<int>(*n);
      continue;
    }
    const std::string name = key;  // a binding cannot be captured by clang 14's lambdas
    const auto it = std::find_if(ProfileSpec::kNames.begin(), ProfileSpec::kNames.end(),
                                 [&](const char* n) { return name == n; });
    if (it == ProfileSpec::kNames.end()) {
      problem(value, where,
              "unknown key (expected top_drop_um, bottom_drop_um, min_clearance_height_mm, "
              "curvature_um_per_mm2, rows)");
      continue;
    }
    const auto i = static_cast<std::size_t>(it - ProfileSpec::kNames.begin());
    given[i] = true;
    // Drops and curvature within what the profile table's reader accepts.
    const double limit = i == 3 ? 100.0 : 2000.0;
    if (value.IsSequence()) {
      const auto r = range(value, where);
      if (!r)
        continue;
      if (i != 2 && (r->first < -limit || r->second > limit)) {
        problem(
            value, where,
            "bounds must lie within [-" + formatNumber(limit) + ", " + formatNumber(limit) + "]");
        continue;
      }
      DesignVariable v;
      v.key = "profile." + key;
      v.lower = r->first;
      v.upper = r->second;
      v.origin = at(value, where);
      variables_.push_back(v);
    } else if (const auto x = number(value, where)) {
      if (i != 2 && std::fabs(*x) > limit) {
        problem(value, where,
                "must lie within [-" + formatNumber(limit) + ", " + formatNumber(limit) + "]");
        continue;
      }
      profile_.fixed[i] = *x;
    }
  }
  for (std::size_t i = 0; i < given.size(); ++i) {
    if (!given[i])
      problem(node, std::string("profile.") + ProfileSpec::kNames[i],
              "missing key (a number, or [lower, upper] to vary it)");
  }
}

std::optional<io::EngineDeck> StudyDeckReader::finishCommon(
    DesignStudy& study, const std::vector<std::string>& commandLineOverrides,
    const io::LinerRegistry& registry) {
  study.kind = kind_;
  study.deckPath = path_;
  study.name = name_;
  if (!sawVariables_)
    problems_.push_back(path_ + ": " + variablesBlock_ +
                        ": missing key (a section of key: " + "[lower, upper] entries" + ")");
  if (!baseNode_.IsDefined() || baseNode_.IsNull()) {
    problems_.push_back(path_ +
                        ": base_deck: missing key (the engine deck every evaluation "
                        "starts from, relative to this file)");
  } else if (!baseNode_.IsScalar() || baseNode_.Scalar().empty()) {
    problem(baseNode_, "base_deck", "expected the path of an engine deck");
  } else {
    study.baseDeckPath = resolve(baseNode_.Scalar());
    std::error_code ec;
    const auto sha = io::detail::sha256HexOfFile(study.baseDeckPath);
    if (!sha || fs::is_directory(study.baseDeckPath, ec))
      problem(baseNode_, "base_deck",
              "cannot open '" + study.baseDeckPath + "' (relative paths start at the folder of " +
                  path_ + ")");
    else
      study.baseDeckSha256 = *sha;
  }
  // A key is either varied or fixed.
  std::map<std::string, std::string> varied;
  for (const auto& v : variables_) {
    if (!v.isProfile())
      varied.emplace(v.key, v.origin);
  }
  for (const auto& [key, origin] : setOrigins_) {
    if (varied.count(key))
      problems_.push_back(origin + ": the key is also a variable (" + varied[key] +
                          "); a key is either varied or set");
    if (profile_.enabled && key.rfind("liner.skirt_profile.", 0) == 0 &&
        (key == "liner.skirt_profile.axial_profile_file" || key == "liner.skirt_profile.mirrored"))
      problems_.push_back(origin + ": the parametric profile writes this key per design");
  }
  study.fixedOverrides = setOverrides_;
  for (const auto& o : commandLineOverrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos || eq == 0) {
      problems_.push_back("--set " + o + ": expected key.path=value");
      continue;
    }
    const std::string key = o.substr(0, eq);
    if (varied.count(key)) {
      problems_.push_back("--set " + key + ": the study varies this key (" + varied[key] +
                          "); a --set cannot fix it");
      continue;
    }
    study.fixedOverrides.push_back(o);
  }
  if (profile_.enabled) {
    // The generated table replaces the deck's; it is written unmirrored.
    study.fixedOverrides.push_back("liner.skirt_profile.mirrored=false");
  }
  throwIfProblems();

  // The base deck with the shared overrides.
  std::optional<io::EngineDeck> base;
  try {
    base.emplace(io::loadEngineDeck(study.baseDeckPath, study.fixedOverrides, registry));
  } catch (const io::DeckError& e) {
    problem(
        baseNode_, "base_deck",
        "the base deck with the shared overrides (set:, --set) is rejected:" + indent(e.what()));
  }
  throwIfProblems();

  // Each deck-key variable: read as a number by the base deck, both bounds accepted.
  for (auto& v : variables_) {
    if (v.isProfile())
      continue;
    bool read = false;
    for (const auto& in : base->inputs) {
      if (in.path != v.key)
        continue;
      read = true;
      if (!std::holds_alternative<double>(in.value))
        problems_.push_back(v.origin + ": not a numeric deck key: the base deck reads it as " +
                            kindOf(in.value));
      else
        v.baseline = inDeckUnit(in);
    }
    bool boundsOk = true;
    for (const auto& [which, bound] : {std::pair{"lower", v.lower}, std::pair{"upper", v.upper}}) {
      std::vector<std::string> overrides = study.fixedOverrides;
      overrides.push_back(assignment(v.key, bound));
      try {
        const io::EngineDeck d = io::loadEngineDeck(study.baseDeckPath, overrides, registry);
        if (!read) {
          for (const auto& in : d.inputs)
            read = read || in.path == v.key;
        }
      } catch (const io::DeckError& e) {
        boundsOk = false;
        problems_.push_back(v.origin + ": the " + which + " bound " + formatNumber(bound) +
                            " is rejected by the base deck:" + indent(e.what()));
      }
    }
    if (!read && boundsOk)
      problems_.push_back(v.origin +
                          ": not a deck key the base deck's readers read (liner keys "
                          "depend on liner.model, now '" +
                          base->linerModel + "')");
  }

  // The profile: the lubricated skirt, its minimum-clearance point inside the skirt.
  study.profile = profile_;
  if (profile_.enabled) {
    const YAML::Node node = root_["profile"];
    if (base->linerModel != "lubricated_skirt") {
      problem(node, "profile",
              "the parametric skirt profile needs liner.model: lubricated_skirt (the base "
              "deck's is " +
                  base->linerModel + ")");
    }
    study.skirtTop_mm = base->engine.piston.skirtTopAbovePin_m * 1e3;
    study.skirtBottom_mm =
        (base->engine.piston.skirtTopAbovePin_m - base->engine.piston.skirtLength_m) * 1e3;
    const bool skirtVaried =
        varied.count("piston.skirt_length_mm") || varied.count("piston.skirt_top_above_pin_mm");
    double lo = 0.0, hi = 0.0;
    std::string origin = at(node["min_clearance_height_mm"], "profile.min_clearance_height_mm");
    if (profile_.fixed[2]) {
      lo = hi = *profile_.fixed[2];
    } else {
      for (const auto& v : variables_) {
        if (v.key == "profile.min_clearance_height_mm") {
          lo = v.lower;
          hi = v.upper;
        }
      }
    }
    if (!skirtVaried && !(lo > study.skirtBottom_mm && hi < study.skirtTop_mm)) {
      problems_.push_back(
          origin + ": the minimum-clearance height must lie inside the skirt, (" +
          formatNumber(study.skirtBottom_mm) + ", " + formatNumber(study.skirtTop_mm) +
          ") mm above the pin (piston.skirt_top_above_pin_mm, "
          "piston.skirt_length_mm); given " +
          (lo == hi ? formatNumber(lo) : "[" + formatNumber(lo) + ", " + formatNumber(hi) + "]"));
    }
  }
  // Deck keys first (deck order), then the profile's (their order in ProfileSpec).
  std::stable_partition(variables_.begin(), variables_.end(),
                        [](const DesignVariable& v) { return !v.isProfile(); });
  std::stable_sort(variables_.begin(), variables_.end(),
                   [](const DesignVariable& a, const DesignVariable& b) {
                     if (a.isProfile() != b.isProfile() || !a.isProfile())
                       return false;
                     auto rank = [](const DesignVariable& v) {
                       for (std::size_t i = 0; i < ProfileSpec::kNames.size(); ++i)
                         if (v.key == std::string("profile.") + ProfileSpec::kNames[i])
                           return i;
                       return ProfileSpec::kNames.size();
                     };
                     return rank(a) < rank(b);
                   });
  study.variables = variables_;

  // The tables the evaluations read, by content.
  std::map<std::string, std::string> bySha;
  std::vector<std::string> files = {base->cylinderPressureFile};
  for (const auto& in : base->linerInputs) {
    const auto* t = std::get_if<std::string>(&in.value);
    if (t != nullptr && in.path.size() > 5 && in.path.compare(in.path.size() - 5, 5, "_file") == 0)
      files.push_back(*t);
  }
  for (const auto& f : files) {
    if (const auto sha = io::detail::sha256HexOfFile(f))
      bySha.emplace(*sha, f);
    else
      problems_.push_back(f + ": cannot read the file (the base deck names it)");
  }
  for (const auto& [sha, path] : bySha)
    study.inputFiles.push_back({path, sha});
  throwIfProblems();

  nlohmann::ordered_json context;
  context["base_deck_sha256"] = study.baseDeckSha256;
  nlohmann::ordered_json shas = nlohmann::ordered_json::array();
  for (const auto& f : study.inputFiles)
    shas.push_back(f.sha256);
  context["input_files_sha256"] = shas;
  context["fixed_overrides"] = study.fixedOverrides;
  study.contextSha256 = io::detail::sha256Hex(context.dump());
  return base;
}

}  // namespace detail

// ---- DesignStudy -------------------------------------------------------------------------

std::vector<std::string> DesignStudy::getOverrides(const std::vector<double>& x) const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < variables.size(); ++i) {
    if (!variables[i].isProfile())
      out.push_back(detail::assignment(variables[i].key, x.at(i)));
  }
  return out;
}

std::vector<std::pair<double, double>> DesignStudy::getBounds() const {
  std::vector<std::pair<double, double>> out;
  for (const auto& v : variables)
    out.emplace_back(v.lower, v.upper);
  return out;
}

EvaluationRequest DesignStudy::makeRequest(const std::vector<double>& x) const {
  if (x.size() != variables.size())
    throw std::invalid_argument("DesignStudy::makeRequest: " + std::to_string(x.size()) +
                                " values for " + std::to_string(variables.size()) + " variables");
  EvaluationRequest r;
  r.overrides = getOverrides(x);
  if (!profile.enabled)
    return r;
  std::array<double, 4> p{};
  double top = skirtTop_mm, length = skirtTop_mm - skirtBottom_mm;
  for (std::size_t i = 0; i < variables.size(); ++i) {
    if (variables[i].key == "piston.skirt_top_above_pin_mm")
      top = x[i];
    if (variables[i].key == "piston.skirt_length_mm")
      length = x[i];
  }
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (profile.fixed[k]) {
      p[k] = *profile.fixed[k];
      continue;
    }
    for (std::size_t i = 0; i < variables.size(); ++i) {
      if (variables[i].key == std::string("profile.") + ProfileSpec::kNames[k])
        p[k] = x[i];
    }
  }
  const SkirtProfileShape shape{p[0], p[1], p[2], p[3]};
  // A minimum-clearance height outside this design's skirt throws: the evaluation fails
  // with the message (the caller turns it into a failed result).
  r.files.emplace_back("skirt_profile.csv",
                       makeProfileTable(shape, top - length, top, profile.rows));
  r.fileKey = "liner.skirt_profile.axial_profile_file";
  return r;
}

std::string hashText(const std::string& text) {
  return io::detail::sha256Hex(text);
}

}  // namespace pistondyn::design
