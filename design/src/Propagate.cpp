#include "pistondyn/design/Propagate.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "StudyDeckReader.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/design/Figures.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/ResultFolder.h"
#include "pistondyn/io/SweepDeck.h"
#include "pistondyn/plugin/CycleSimulation.h"

namespace pistondyn::design {
namespace {

using Json = nlohmann::ordered_json;
using common::formatNumber;

std::optional<std::vector<std::string>> readNames(detail::StudyDeckReader& r,
                                                  const YAML::Node& node,
                                                  const std::string& where) {
  if (!node.IsSequence() || node.size() == 0) {
    r.problem(node, where, "expected a list of names, e.g. [fmep_kPa, min_h_over_sigma]");
    return std::nullopt;
  }
  std::vector<std::string> out;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const auto t = r.text(node[i], where + "[" + std::to_string(i + 1) + "]");
    if (!t)
      return std::nullopt;
    if (std::find(out.begin(), out.end(), *t) != out.end()) {
      r.problem(node[i], where, "'" + *t + "' is listed twice");
      return std::nullopt;
    }
    out.push_back(*t);
  }
  return out;
}

Json describe(const PropagateSpec& spec, bool forFingerprint) {
  const DesignStudy& s = spec.study;
  Json j;
  if (!forFingerprint) {
    j["deck"] = s.deckPath;
    j["name"] = s.name;
    j["base_deck"] = s.baseDeckPath;
  }
  j["context_sha256"] = s.contextSha256;
  j["fixed_overrides"] = s.fixedOverrides;
  Json vars = Json::array();
  for (const auto& v : s.variables)
    vars.push_back({{"key", v.key}, {"lower", v.lower}, {"upper", v.upper}});
  j["inputs"] = vars;
  j["samples"] = spec.samples;
  j["seed"] = spec.seed;
  j["figures"] = spec.figures;
  j["curves"] = spec.curves;
  return j;
}

std::vector<double> columnOfLastCycle(const io::ResultFolder& f, const io::CycleWindow& w,
                                      const std::string& column) {
  const std::size_t c = f.cycle.columnIndex(column);
  std::vector<double> out;
  for (const std::size_t row : w.rows)
    out.push_back(f.cycle.rows[row][c]);
  return out;
}

}  // namespace

std::vector<std::pair<std::string, double>> findEstimatedKeys(const std::string& deckPath) {
  std::ifstream in(deckPath);
  std::vector<std::pair<std::string, double>> out;
  std::vector<std::pair<std::size_t, std::string>> stack;  // indentation, section name
  static const std::regex line(R"(^( *)([A-Za-z0-9_]+):[ \t]*([^#]*?)[ \t]*(#.*)?$)");
  static const std::regex est(R"((^|[^A-Za-z])EST([^A-Za-z]|$))");
  std::string text;
  while (std::getline(in, text)) {
    std::smatch m;
    if (!std::regex_match(text, m, line))
      continue;
    const std::size_t indent = m[1].length();
    while (!stack.empty() && stack.back().first >= indent)
      stack.pop_back();
    const std::string key = m[2].str(), value = m[3].str(), comment = m[4].str();
    if (value.empty()) {
      stack.emplace_back(indent, key);
      continue;
    }
    if (!std::regex_search(comment, est))
      continue;
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (end != value.c_str() + value.size() || !std::isfinite(v))
      continue;
    std::string path;
    for (const auto& s : stack)
      path += s.second + ".";
    out.emplace_back(path + key, v);
  }
  return out;
}

double calcQuantile(std::vector<double> values, double p) {
  if (values.empty())
    return std::nan("");
  std::sort(values.begin(), values.end());
  const double h = (static_cast<double>(values.size()) - 1.0) * p;
  const auto k = static_cast<std::size_t>(std::floor(h));
  if (k + 1 >= values.size())
    return values.back();
  return values[k] + (h - static_cast<double>(k)) * (values[k + 1] - values[k]);
}

Band calcBand(const std::vector<double>& v) {
  Band b;
  b.count = static_cast<int>(v.size());
  if (v.empty()) {
    b.p05 = b.p50 = b.p95 = b.mean = b.std = b.min = b.max = std::nan("");
    return b;
  }
  b.p05 = calcQuantile(v, 0.05);
  b.p50 = calcQuantile(v, 0.5);
  b.p95 = calcQuantile(v, 0.95);
  double sum = 0.0;
  for (const double x : v)
    sum += x;
  b.mean = sum / static_cast<double>(v.size());
  double ss = 0.0;
  for (const double x : v)
    ss += (x - b.mean) * (x - b.mean);
  b.std = v.size() > 1 ? std::sqrt(ss / static_cast<double>(v.size() - 1)) : 0.0;
  b.min = *std::min_element(v.begin(), v.end());
  b.max = *std::max_element(v.begin(), v.end());
  return b;
}

PropagateSpec loadPropagateDeck(const std::string& path,
                                const std::vector<std::string>& commandLineOverrides,
                                const io::LinerRegistry& registry) {
  detail::StudyDeckReader r(path, "propagate");
  PropagateSpec spec;
  spec.figures = {"fmep_kPa", "min_h_over_sigma", "slap_energy_max_mJ"};
  spec.curves = {"u_lat_um", "tilt_mrad"};
  std::optional<double> estShare;  // set once est_inputs is read and valid
  YAML::Node estNode, curvesNode;
  bool sawInputs = false;
  for (const auto& [key, value] : r.open()) {
    if (key == "inputs")
      sawInputs = true;
    if (r.readCommon(key, value, "inputs", false))
      continue;
    if (key == "est_inputs") {
      estNode.reset(value);
      const auto share = r.number(value, key);
      if (share && !(*share > 0.0 && *share < 1.0))
        r.problem(value, key, "expected the relative half-range, a number in (0, 1), e.g. 0.1");
      else if (share)
        estShare.emplace(*share);
    } else if (key == "samples") {
      if (const auto n = r.wholeNumber(value, key, 2, 100000))
        spec.samples = *n;
    } else if (key == "seed") {
      if (const auto n = r.wholeNumber(value, key, 0, 9007199254740992L))
        spec.seed = static_cast<std::uint64_t>(*n);
    } else if (key == "figures") {
      if (const auto names = readNames(r, value, key)) {
        spec.figures = *names;
        for (std::size_t i = 0; i < names->size(); ++i) {
          if (!isKnownFigure((*names)[i]))
            r.problem(value[i], key,
                      "'" + (*names)[i] + "' is not a figure the design loop knows (one of: " +
                          listKnownFigures() + ")");
        }
      }
    } else if (key == "curves") {
      curvesNode.reset(value);
      if (const auto names = readNames(r, value, key))
        spec.curves = *names;
    } else {
      r.problem(value, key,
                "unknown key (a propagation deck has name, base_deck, set, inputs, est_inputs, "
                "profile, samples, seed, figures, curves)");
    }
  }
  // The inputs the base deck marks EST, +-share of their value.
  if (estShare) {
    const double share = *estShare;
    if (const auto base = r.getBaseDeckPath()) {
      for (const auto& estimated : findEstimatedKeys(*base)) {
        // Plain variables, not a structured binding: clang 14 (the sanitizer build) cannot
        // capture a binding in the lambda below.
        const std::string key = estimated.first;
        const double value = estimated.second;
        // A key the study lists, sets, or the command line fixes keeps that.
        const bool fixedHere =
            std::any_of(commandLineOverrides.begin(), commandLineOverrides.end(),
                        [&](const std::string& o) { return o.rfind(key + "=", 0) == 0; });
        if (r.hasVariable(key) || r.isSet(key) || fixedHere)
          continue;
        if (value == 0.0) {
          spec.estSkipped.push_back(key);
          continue;
        }
        DesignVariable v;
        v.key = key;
        v.lower = std::min(value * (1 - share), value * (1 + share));
        v.upper = std::max(value * (1 - share), value * (1 + share));
        v.origin = r.at(estNode, "est_inputs") + " (" + key + ", marked EST in the base deck)";
        r.addVariable(v);
        spec.estKeys.push_back(key);
      }
    }
  }
  if (!sawInputs && estShare)
    r.setVariablesBlockOptional();  // est_inputs alone
  r.throwIfProblems();
  const auto base = r.finishCommon(spec.study, commandLineOverrides, registry);
  // The curves are columns the run writes.
  std::vector<std::string> columns;
  try {
    auto model = io::buildModel(*base);
    columns = plugin::CycleSimulation(*model, base->simulation).getColumns();
  } catch (const std::exception& e) {
    r.problem(r.getPath() + ": base_deck: the model cannot be built: " + e.what());
  }
  for (const auto& c : spec.curves) {
    if (std::find(columns.begin(), columns.end(), c) == columns.end()) {
      std::string list;
      for (const auto& x : columns)
        list += (list.empty() ? "" : ", ") + x;
      r.problem((curvesNode.IsDefined() ? r.at(curvesNode, "curves") : r.getPath() + ": curves") +
                ": the run writes no column " + c + " (its columns: " + list + ")");
    }
  }
  if (spec.study.variables.empty())
    r.problem(r.getPath() + ": inputs: no inputs to vary (list some, or est_inputs)");
  r.throwIfProblems();
  spec.description = describe(spec, false).dump();
  spec.fingerprint = hashText("propagate\n" + describe(spec, true).dump());
  return spec;
}

PropagateOutcome runPropagation(const PropagateSpec& spec, Executor& executor,
                                const PropagateProgress& progress) {
  PropagateOutcome out;
  out.samples = io::makeLatinHypercube(spec.study.getBounds(), spec.samples, spec.seed);
  std::vector<EvaluationRequest> requests = {spec.study.makeBaselineRequest()};
  std::vector<std::optional<std::string>> unbuildable;
  for (const auto& x : out.samples) {
    try {
      requests.push_back(spec.study.makeRequest(x));
      unbuildable.emplace_back();
    } catch (const std::exception& e) {
      unbuildable.emplace_back(e.what());
    }
  }
  if (progress)
    progress("evaluating the baseline and " + std::to_string(out.samples.size()) +
             " Latin-hypercube samples");
  const auto results = executor.evaluate(requests);
  out.baseline = results[0];
  std::size_t next = 1;
  for (const auto& why : unbuildable) {
    EvaluationResult r;
    if (why)
      r.message = *why;
    else
      r = results[next++];
    out.runs.push_back(r);
  }
  // Figures.
  std::vector<std::vector<double>> perFigure(spec.figures.size());
  for (const auto& run : out.runs) {
    std::vector<std::optional<double>> values(spec.figures.size());
    if (run.ok) {
      const RunFigures f(run.summaryJson);
      for (std::size_t k = 0; k < spec.figures.size(); ++k) {
        values[k] = f.get(spec.figures[k]);
        if (values[k])
          perFigure[k].push_back(*values[k]);
      }
    } else {
      ++out.failed;
    }
    out.figureValues.push_back(values);
  }
  for (std::size_t k = 0; k < spec.figures.size(); ++k)
    out.figureBands[spec.figures[k]] = calcBand(perFigure[k]);
  // Curves at every output angle of the last cycle (the runs share the deck's angles).
  std::vector<std::vector<std::vector<double>>> curves(spec.curves.size());
  for (const auto& run : out.runs) {
    if (!run.ok)
      continue;
    const io::ResultFolder f = io::readResultFolder(run.folder);
    const io::CycleWindow w = io::selectLastCycle(f.cycle);
    if (out.angle_deg.empty())
      out.angle_deg = w.angle_deg;
    if (w.angle_deg != out.angle_deg)
      throw std::runtime_error(run.folder +
                               ": its crank angles differ from the other samples' "
                               "(a varied input changes the output step?)");
    for (std::size_t k = 0; k < spec.curves.size(); ++k)
      curves[k].push_back(columnOfLastCycle(f, w, spec.curves[k]));
  }
  for (std::size_t k = 0; k < spec.curves.size(); ++k) {
    std::vector<Band> bands;
    for (std::size_t i = 0; i < out.angle_deg.size(); ++i) {
      std::vector<double> v;
      for (const auto& sample : curves[k])
        v.push_back(sample[i]);
      bands.push_back(calcBand(v));
    }
    out.curveBands[spec.curves[k]] = bands;
  }
  if (out.baseline.ok) {
    const io::ResultFolder f = io::readResultFolder(out.baseline.folder);
    const io::CycleWindow w = io::selectLastCycle(f.cycle);
    if (w.angle_deg == out.angle_deg) {
      for (const auto& c : spec.curves)
        out.baselineCurves[c] = columnOfLastCycle(f, w, c);
    }
  }
  if (progress)
    progress(std::to_string(out.runs.size() - static_cast<std::size_t>(out.failed)) + " of " +
             std::to_string(out.runs.size()) + " samples ran");
  return out;
}

std::string makeSamplesCsv(const PropagateSpec& spec, const PropagateOutcome& o) {
  std::ostringstream out;
  out << "# pistondyn propagate: the Latin-hypercube samples (uniform over the inputs' ranges, "
         "seed "
      << spec.seed << ") and their figures; evaluation: the run folder under evaluations/\n";
  out << "sample";
  for (const auto& v : spec.study.variables)
    out << ',' << v.key;
  out << ",status";
  for (const auto& f : spec.figures)
    out << ',' << f;
  out << ",evaluation,message\n";
  for (std::size_t i = 0; i < o.samples.size(); ++i) {
    out << i + 1;
    for (const double x : o.samples[i])
      out << ',' << formatNumber(x);
    out << ',' << (o.runs[i].ok ? "ok" : "failed");
    for (const auto& v : o.figureValues[i])
      out << ',' << (v ? formatNumber(*v) : "");
    std::string m = o.runs[i].message;
    std::replace(m.begin(), m.end(), '"', '\'');
    out << ',' << o.runs[i].id << ',' << (m.empty() ? "" : "\"" + m + "\"") << '\n';
  }
  return out.str();
}

std::string makeBandsCsv(const PropagateSpec& spec, const PropagateOutcome& o) {
  std::ostringstream out;
  out << "# pistondyn propagate: 5, 50 and 95 % of the samples' curves at every output crank "
         "angle of the last cycle (0 deg = firing TDC), and the baseline's\n";
  out << "crank_angle_deg";
  for (const auto& c : spec.curves)
    out << ',' << c << "_p05," << c << "_p50," << c << "_p95," << c << "_baseline";
  out << '\n';
  for (std::size_t i = 0; i < o.angle_deg.size(); ++i) {
    out << formatNumber(o.angle_deg[i]);
    for (const auto& c : spec.curves) {
      const Band& b = o.curveBands.at(c)[i];
      const auto base = o.baselineCurves.find(c);
      out << ',' << formatNumber(b.p05) << ',' << formatNumber(b.p50) << ',' << formatNumber(b.p95)
          << ',' << (base != o.baselineCurves.end() ? formatNumber(base->second[i]) : "");
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace pistondyn::design
