#include "pistondyn/io/StudyComparison.h"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "CsvText.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/Version.h"

namespace pistondyn::io {

const std::vector<std::string> kComparisonFigures = {
    "fmep_kPa",
    "friction_power_mean_W",
    "asperity_friction_work_share",
    "min_h_over_sigma_thrust",
    "min_h_over_sigma_thrust_crank_angle_deg",
    "min_h_over_sigma_antithrust",
    "min_h_over_sigma_antithrust_crank_angle_deg",
    "min_film_thickness_thrust_um",
    "min_film_thickness_antithrust_um",
    "max_abs_u_lat_um",
    "max_abs_tilt_deg",
    "slap_energy_max_mJ",
    "side_force_max_N",
    "cycles_to_converge",
    "converged",
};

namespace {

using Json = nlohmann::json;

// The Markdown table's columns: a figure (or a figure with its crank angle) and its header.
struct MarkdownColumn {
  std::string figure, angleFigure, header;
};
const std::vector<MarkdownColumn>& markdownColumns() {
  static const std::vector<MarkdownColumn> columns = {
      {"fmep_kPa", "", "fmep (kPa)"},
      {"friction_power_mean_W", "", "mean friction power (W)"},
      {"asperity_friction_work_share", "", "asperity share of friction work"},
      {"min_h_over_sigma_thrust", "min_h_over_sigma_thrust_crank_angle_deg",
       "min h/σ thrust (at crank angle)"},
      {"min_h_over_sigma_antithrust", "min_h_over_sigma_antithrust_crank_angle_deg",
       "min h/σ anti-thrust (at crank angle)"},
      {"min_film_thickness_thrust_um", "", "min film thrust (µm)"},
      {"min_film_thickness_antithrust_um", "", "min film anti-thrust (µm)"},
      {"max_abs_u_lat_um", "", "max \\|u_lat\\| (µm)"},
      {"max_abs_tilt_deg", "", "max \\|tilt\\| (°)"},
      {"slap_energy_max_mJ", "", "largest slap energy (mJ)"},
      {"side_force_max_N", "", "max side force (N)"},
      {"cycles_to_converge", "", "cycles to converge"},
      {"converged", "", "converged"},
  };
  return columns;
}

std::size_t figureIndex(const std::string& figure) {
  for (std::size_t i = 0; i < kComparisonFigures.size(); ++i) {
    if (kComparisonFigures[i] == figure)
      return i;
  }
  throw std::logic_error("StudyComparison: no figure " + figure);
}

// A number to 4 significant digits for reading (the CSV keeps every digit).
std::string readable(const std::string& jsonText) {
  if (jsonText.empty() || jsonText == "true" || jsonText == "false")
    return jsonText;
  char* end = nullptr;
  const double v = std::strtod(jsonText.c_str(), &end);
  if (end == jsonText.c_str() || *end != '\0')
    return jsonText;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// Markdown cells hold no bare '|' and no line break.
std::string markdownCell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n' || c == '\r')
      out += ' ';
    else
      out += c;
  }
  return out;
}

std::string lastPart(const std::string& key) {
  const auto dot = key.find_last_of('.');
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

}  // namespace

StudyComparison makeStudyComparison(const SweepPlan& plan,
                                    const std::vector<SweepCaseResult>& results) {
  StudyComparison c;
  c.name = plan.name;
  c.studyDeckPath = plan.sweepDeckPath;
  c.baseDeckPath = plan.baseDeckPath;
  for (const auto& k : plan.sweptKeys)
    c.sweptKeys.push_back(k.key);
  std::map<int, const SweepCaseResult*> byIndex;
  for (const auto& r : results)
    byIndex[r.index] = &r;
  for (const SweepCase& sc : plan.cases) {
    StudyComparisonRow row;
    row.index = sc.index;
    row.folder = plan.getCaseFolderName(sc.index);
    for (const auto& k : plan.sweptKeys) {
      std::string value;
      for (const auto& a : sc.assignments) {
        if (a.key == k.key)
          value = a.value;
      }
      row.values.push_back(value);
    }
    row.figures.assign(kComparisonFigures.size(), "");
    const auto it = byIndex.find(sc.index);
    if (it == byIndex.end()) {
      row.message = "not run";
    } else if (!it->second->ok) {
      row.message = it->second->message;
    } else {
      row.ok = true;
      Json summary;
      try {
        summary = Json::parse(it->second->summaryJson);
      } catch (const std::exception& e) {
        throw std::runtime_error(plan.getCaseFolderName(sc.index) +
                                 "/summary.json: cannot be parsed: " + e.what());
      }
      const Json& res = summary.contains("results") ? summary["results"] : Json::object();
      for (std::size_t f = 0; f < kComparisonFigures.size(); ++f) {
        const auto v = res.find(kComparisonFigures[f]);
        if (v != res.end() && (v->is_number() || v->is_boolean()))
          row.figures[f] = v->dump();
      }
    }
    c.rows.push_back(std::move(row));
  }
  return c;
}

std::string makeComparisonCsv(const StudyComparison& c) {
  std::ostringstream out;
  out << "# pistondyn " << getVersion() << " study comparison"
      << (c.name.empty() ? std::string() : ": " + escapeForCommentLine(c.name)) << "\n";
  out << "# study deck " << escapeForCommentLine(c.studyDeckPath) << "; base deck "
      << escapeForCommentLine(c.baseDeckPath) << "\n";
  out << "# crank angle 0 deg = firing TDC; figures of the last simulated 720 deg cycle of "
         "each case (its summary.json); empty: the case has no such figure\n";
  out << "case";
  for (const auto& k : c.sweptKeys)
    out << ',' << detail::csvField(k);
  out << ",status";
  for (const auto& f : kComparisonFigures)
    out << ',' << f;
  out << ",message\n";
  for (const auto& r : c.rows) {
    out << r.index;
    for (const auto& v : r.values)
      out << ',' << detail::csvField(v);
    out << ',' << (r.ok ? "ok" : "failed");
    for (const auto& f : r.figures)
      out << ',' << f;
    out << ',' << detail::csvField(r.message) << '\n';
  }
  return out.str();
}

std::string makeComparisonMarkdown(const StudyComparison& c) {
  std::ostringstream out;
  out << "# " << (c.name.empty() ? std::string("Study") : markdownCell(c.name)) << "\n\n";
  out << "Study deck `" << c.studyDeckPath << "`, base deck `" << c.baseDeckPath
      << "`. Figures of the last simulated 720° cycle of each case (its `summary.json`); "
         "crank angle 0° = firing TDC; – where a case has no such figure.\n\n";
  out << "| case |";
  for (const auto& k : c.sweptKeys)
    out << " `" << markdownCell(k) << "` |";
  out << " status |";
  for (const auto& col : markdownColumns())
    out << ' ' << col.header << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < c.sweptKeys.size() + 1 + markdownColumns().size(); ++i)
    out << "---|";
  out << '\n';
  for (const auto& r : c.rows) {
    out << "| " << r.index << " |";
    for (const auto& v : r.values)
      out << ' ' << (v.empty() ? "–" : markdownCell(v)) << " |";
    out << ' ' << (r.ok ? "ok" : "failed: " + markdownCell(r.message)) << " |";
    for (const auto& col : markdownColumns()) {
      std::string text = readable(r.figures[figureIndex(col.figure)]);
      if (!text.empty() && !col.angleFigure.empty()) {
        const std::string angle = readable(r.figures[figureIndex(col.angleFigure)]);
        if (!angle.empty())
          text += " at " + angle + "°";
      }
      out << ' ' << (text.empty() ? "–" : text) << " |";
    }
    out << '\n';
  }
  return out.str();
}

std::string describeCase(const StudyComparison& c, const StudyComparisonRow& row) {
  std::string out;
  for (std::size_t i = 0; i < c.sweptKeys.size() && i < row.values.size(); ++i) {
    if (row.values[i].empty())
      continue;
    std::string name = lastPart(c.sweptKeys[i]);
    for (std::size_t j = 0; j < c.sweptKeys.size(); ++j) {
      if (j != i && lastPart(c.sweptKeys[j]) == name)
        name = c.sweptKeys[i];
    }
    out += (out.empty() ? "" : ", ") + name + "=" + row.values[i];
  }
  return "case " + std::to_string(row.index) + (out.empty() ? "" : ": " + out);
}

}  // namespace pistondyn::io
