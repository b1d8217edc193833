#include "pistondyn/io/ResultFolder.h"

#include "FileBytes.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace pistondyn::io {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

std::string readText(const fs::path& p) {
  std::optional<std::string> bytes = detail::readFileBytes(p.string());
  if (!bytes)
    throw ResultFolderError(p.string() + ": cannot open (is this a pistondyn run's folder?)");
  return std::move(*bytes);
}

void flatten(const Json& j, const std::string& prefix, std::vector<SummaryEntry>& out) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      flatten(it.value(), prefix.empty() ? it.key() : prefix + "." + it.key(), out);
  } else if (j.is_string()) {
    out.push_back({prefix, j.get<std::string>()});
  } else if (j.is_array()) {
    std::string text = "[";
    for (const auto& e : j)
      text += (text.size() > 1 ? ", " : "") + (e.is_string() ? e.get<std::string>() : e.dump());
    out.push_back({prefix, text + "]"});
  } else {
    out.push_back({prefix, j.dump()});
  }
}

// What a JSON value is, for messages ("the text \"abc\"", "an array", ...).
std::string describe(const Json& j) {
  if (j.is_string()) {
    std::string text = j.get<std::string>();
    if (text.size() > 40)
      text = text.substr(0, 40) + "...";
    return "the text \"" + text + "\"";
  }
  if (j.is_array())
    return "an array";
  if (j.is_object())
    return "an object";
  if (j.is_boolean())
    return j.get<bool>() ? "true" : "false";
  return j.dump();
}

bool isNumberOrNull(const Json& j) {
  return j.is_number() || j.is_null();
}

bool isNumberList(const Json& j) {
  return j.is_array() &&
         std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_number(); });
}

// The shape summary.json has when `pistondyn run` wrote it, as far as the figures and the
// report read it: an object with a "results" object whose figures are numbers (true or
// false, null, or a list of numbers; "note" is text), inputs whose SI key names a unit
// holding numbers, and the run's own counts. The first departure, as "what: found what".
void checkSummaryShape(const Json& j, const std::string& file) {
  auto fail = [&](const std::string& what) {
    throw ResultFolderError(file + ": " + what + " (not a summary.json that pistondyn run wrote)");
  };
  if (!j.is_object())
    fail("expected a JSON object, found " + describe(j));
  if (!j.contains("results"))
    fail("no \"results\" object");
  const Json& results = j.at("results");
  if (!results.is_object())
    fail("\"results\" is " + describe(results) + ", expected an object");
  // Figures, and groups of figures (results.last_cycles: mean and spread) of the same shape.
  std::vector<std::pair<std::string, const Json*>> groups{{"results", &results}};
  while (!groups.empty()) {
    const auto [path, group] = groups.back();
    groups.pop_back();
    for (auto it = group->begin(); it != group->end(); ++it) {
      const Json& v = it.value();
      const std::string key = path + "." + it.key();
      if (v.is_object() && (path == "results" || path == "results.last_cycles"))
        groups.emplace_back(key, &v);
      else if (it.key() == "note" ? !v.is_string()
                                  : !(isNumberOrNull(v) || v.is_boolean() || isNumberList(v)))
        fail(key + ": expected " + (it.key() == "note" ? "text" : "a number") + ", found " +
             describe(v));
    }
  }
  for (const char* key : {"wall_time_s", "integrator_steps"}) {
    if (j.contains(key) && !isNumberOrNull(j.at(key)))
      fail(std::string(key) + ": expected a number, found " + describe(j.at(key)));
  }
  if (!j.contains("inputs"))
    return;
  if (!j.at("inputs").is_object())
    fail("\"inputs\" is " + describe(j.at("inputs")) + ", expected an object");
  // A key with a unit in its name (bore_m, speed_rad_per_s, crank_angles_deg) holds numbers.
  std::vector<std::pair<std::string, const Json*>> todo{{"inputs", &j.at("inputs")}};
  while (!todo.empty()) {
    const auto [path, node] = todo.back();
    todo.pop_back();
    for (auto it = node->begin(); it != node->end(); ++it) {
      const std::string key = path + "." + it.key();
      if (it.value().is_object())
        todo.emplace_back(key, &it.value());
      else if (!getColumnUnit(it.key()).empty() &&
               !(isNumberOrNull(it.value()) || isNumberList(it.value())))
        fail(key + ": expected a number, found " + describe(it.value()));
    }
  }
}

std::vector<std::string> commentLines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
    const std::size_t start = line.find_first_not_of("# ");
    lines.push_back(start == std::string::npos ? "" : line.substr(start));
  }
  return lines;
}

}  // namespace

std::string ResultFolder::getSummaryValue(const std::string& key) const {
  for (const auto& e : summary) {
    if (e.key == key)
      return e.value;
  }
  return "";
}

ResultFolder readResultFolder(const std::string& directory) {
  const fs::path dir(directory);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw ResultFolderError(directory + ": not a folder (give the --out folder of a run)");
  ResultFolder r;
  r.directory = directory;
  const fs::path csv = dir / "cycle.csv", json = dir / "summary.json";
  if (!fs::exists(csv, ec))
    throw ResultFolderError(csv.string() + ": missing (is this a pistondyn run's folder?)");
  r.cycle = readCsvTable(csv.string(), {"time_s", "crank_angle_deg"});
  r.cycleComments = commentLines(csv);
  r.summaryJson = readText(json);
  Json parsed;
  try {
    parsed = Json::parse(r.summaryJson);
  } catch (const Json::exception& e) {
    throw ResultFolderError(json.string() + ": not valid JSON: " + e.what());
  }
  checkSummaryShape(parsed, json.string());
  flatten(parsed, "", r.summary);
  // field_dump_<angle>deg_<side>.csv, the names SkirtFieldDumpSink writes.
  const std::regex name(R"(field_dump_([0-9.eE+-]+)deg_(thrust|antithrust)\.csv)");
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (entry.is_regular_file() && std::regex_match(file, m, name))
      r.fieldDumps.push_back({std::stod(m[1].str()), m[2].str(), entry.path().string()});
  }
  // cycle_map_<region>.csv and field_frames_<region>.csv (CycleMaps.h).
  const std::regex map(R"(cycle_map_([A-Za-z0-9_]+)\.csv)"), frames(R"(field_frames_([A-Za-z0-9_]+)\.csv)");
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (!entry.is_regular_file())
      continue;
    if (std::regex_match(file, m, map))
      r.cycleMaps.push_back({m[1].str(), entry.path().string()});
    else if (std::regex_match(file, m, frames))
      r.fieldFrames.push_back({m[1].str(), entry.path().string()});
  }
  auto byRegion = [](const RegionFile& a, const RegionFile& b) {
    auto rank = [](const std::string& region) {
      return region == "thrust" ? 0 : region == "antithrust" ? 1 : 2;
    };
    return rank(a.region) != rank(b.region) ? rank(a.region) < rank(b.region) : a.region < b.region;
  };
  std::sort(r.cycleMaps.begin(), r.cycleMaps.end(), byRegion);
  std::sort(r.fieldFrames.begin(), r.fieldFrames.end(), byRegion);
  std::sort(r.fieldDumps.begin(), r.fieldDumps.end(),
            [](const FieldDumpFile& a, const FieldDumpFile& b) {
              return a.crankAngle_deg != b.crankAngle_deg ? a.crankAngle_deg < b.crankAngle_deg
                                                          : a.side == "thrust" && b.side != "thrust";
            });
  return r;
}

CycleWindow selectLastCycle(const CsvTable& table) {
  if (!table.hasColumn("crank_angle_deg"))
    throw std::runtime_error(table.filePath + ": no column crank_angle_deg");
  if (table.rows.empty())
    throw std::runtime_error(table.filePath + ": no rows");
  const std::size_t a = table.columnIndex("crank_angle_deg");
  const double end = table.rows.back()[a];
  const double begin = end - 720.0;
  // Angles are start + k step as written: a tolerance far below any output step.
  const double tol = 1e-9 * std::max(1.0, std::abs(end));
  const bool closesAtTdc = std::abs(end / 720.0 - std::round(end / 720.0)) * 720.0 <= tol;
  std::vector<std::pair<double, std::size_t>> picked;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const double angle = table.rows[i][a];
    if (angle < begin - tol)
      continue;
    double x = angle - 720.0 * std::floor((angle + tol) / 720.0);
    if (closesAtTdc) {
      x = angle - begin;  // 0 ... 720 with both ends
    } else if (angle <= begin + tol) {
      continue;  // the same cycle angle as the last row
    }
    picked.emplace_back(std::max(0.0, std::min(720.0, x)), i);
  }
  std::stable_sort(picked.begin(), picked.end(),
                   [](const auto& p, const auto& q) { return p.first < q.first; });
  CycleWindow w;
  for (const auto& [x, i] : picked) {
    w.angle_deg.push_back(x);
    w.rows.push_back(i);
  }
  return w;
}

std::string getColumnUnit(const std::string& column) {
  // Longest first, so that "_mps2" wins over "_mps" and "_kg_m2" over "_m2".
  static const char* kUnits[] = {"um_per_h", "m_per_s2", "rad_per_s", "kg_per_m3", "kg_m2", "kg_mm2",
                                 "mm3ph", "per_K", "mps2", "mrad", "degC", "mps", "mm3",
                                 "kPa", "MPa", "bar", "rpm", "deg", "rad", "Pas", "mJ",
                                 "Nm", "um", "mm", "m3", "m2", "Pa", "kg", "N", "W",
                                 "J", "m", "s", "g"};
  for (const char* u : kUnits) {
    const std::string suffix = std::string("_") + u;
    if (column.size() > suffix.size() &&
        column.compare(column.size() - suffix.size(), suffix.size(), suffix) == 0)
      return u;
  }
  return "";
}

}  // namespace pistondyn::io
