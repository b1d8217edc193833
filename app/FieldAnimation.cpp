#include "FieldAnimation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "DisplayUnits.h"
#include "HtmlReport.h"
#include "PlotSupport.h"
#include "pistondyn/io/CsvTable.h"
#include "pistondyn/io/ResultWriters.h"

namespace pistondyn::app {
namespace {

struct FieldStyle {
  const char* name;
  const char* label;
  bool blues;
};
const FieldStyle kStyles[] = {{"film_pressure", "film pressure (gauge)", false},
                              {"fill_fraction", "fill fraction", true},
                              {"contact_pressure", "asperity pressure", false}};

// One region's frames on its grid: values[field][(frame * nY + j) * nPhi + i].
struct RegionFrames {
  std::vector<double> phi_deg, y_mm, frames_deg;
  std::vector<std::string> fields;  // columns
  std::vector<std::vector<double>> values;
};

std::vector<double> distinct(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

std::size_t indexOf(const std::vector<double>& sorted, double v) {
  return static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), v) -
                                   sorted.begin());
}

RegionFrames readFrames(const io::RegionFile& file) {
  const io::CsvTable t = io::readCsvTable(file.path, {"crank_angle_deg", "phi_deg", "y_mm"});
  RegionFrames r;
  const std::size_t ia = t.columnIndex("crank_angle_deg"), ip = t.columnIndex("phi_deg"),
                    iy = t.columnIndex("y_mm");
  r.frames_deg = distinct(t.getColumn("crank_angle_deg"));
  r.phi_deg = distinct(t.getColumn("phi_deg"));
  r.y_mm = distinct(t.getColumn("y_mm"));
  if (t.rows.empty())
    throw io::ResultFolderError(file.path + ": no frames (a header and no rows)");
  const std::size_t cells = r.phi_deg.size() * r.y_mm.size();
  if (t.rows.size() != r.frames_deg.size() * cells) {
    throw io::ResultFolderError(file.path + ": " + std::to_string(t.rows.size()) +
                                " rows, not one per frame and node (" +
                                std::to_string(r.frames_deg.size()) + " frames x " +
                                std::to_string(cells) + " nodes)");
  }
  std::vector<std::size_t> columns;
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    if (c != ia && c != ip && c != iy) {
      columns.push_back(c);
      r.fields.push_back(t.columns[c]);
    }
  }
  r.values.assign(columns.size(), std::vector<double>(t.rows.size(), NAN));
  for (const auto& row : t.rows) {
    const std::size_t k = (indexOf(r.frames_deg, row[ia]) * r.y_mm.size() + indexOf(r.y_mm, row[iy])) *
                              r.phi_deg.size() +
                          indexOf(r.phi_deg, row[ip]);
    for (std::size_t f = 0; f < columns.size(); ++f)
      r.values[f][k] = row[columns[f]];
  }
  // Every cell filled (no node twice, none missing) and every value a number the colour
  // scale can place.
  for (const auto& v : r.values) {
    if (std::any_of(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }))
      throw io::ResultFolderError(file.path +
                                  ": a node is missing from a frame, or a value is not finite");
  }
  return r;
}

std::string list(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t k = 0; k < v.size(); ++k)
    s += (k ? "," : "") + io::formatNumber(std::round(v[k] * 1e4) / 1e4);
  return s + "]";
}

// A JSON string that can stand inside the page's <script> element: '<' escaped so that no
// "</script>" in a region's name ends it, control characters escaped.
std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '<' || static_cast<unsigned char>(c) < 0x20) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", static_cast<unsigned char>(c));
      out += code;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

std::string makeFieldAnimationJson(const io::ResultFolder& folder) {
  if (folder.fieldFrames.empty())
    return "";
  std::vector<RegionFrames> regions;
  for (const io::RegionFile& f : folder.fieldFrames) {
    regions.push_back(readFrames(f));
    if (regions.back().frames_deg != regions.front().frames_deg)
      throw io::ResultFolderError(f.path + ": its frames are not those of " +
                                  folder.fieldFrames.front().path);
  }
  std::string json = "{\"frames_deg\":" + list(regions.front().frames_deg) + ",\"regions\":[";
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const std::string& name = folder.fieldFrames[r].region;
    const std::string title = name == "thrust"       ? "thrust side"
                              : name == "antithrust" ? "anti-thrust side"
                                                     : name;
    json += std::string(r ? "," : "") + "{\"name\":" + jsonString(name) +
            ",\"title\":" + jsonString(title) + ",\"phi_deg\":" + list(regions[r].phi_deg) +
            ",\"y_mm\":" + list(regions[r].y_mm) + "}";
  }
  json += "],\"fields\":[";
  // The fields of the first region, the styled ones first; a region lacking one is drawn
  // blank for it.
  std::vector<std::string> fields = regions.front().fields;
  auto rank = [](const std::string& column) {
    const std::string name = units::splitUnit(column).first;
    for (std::size_t k = 0; k < std::size(kStyles); ++k) {
      if (name == kStyles[k].name)
        return k;
    }
    return std::size(kStyles);
  };
  std::stable_sort(fields.begin(), fields.end(),
                   [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
  bool first = true;
  for (const std::string& column : fields) {
    const std::string name = units::splitUnit(column).first;
    const units::DisplayFormat display = units::getDisplayFormat(column);
    double lo = INFINITY, hi = -INFINITY;
    std::vector<double> positive;
    for (const RegionFrames& r : regions) {
      const auto at = std::find(r.fields.begin(), r.fields.end(), column);
      if (at == r.fields.end())
        continue;
      for (const double v : r.values[static_cast<std::size_t>(at - r.fields.begin())]) {
        lo = std::min(lo, v * display.factor);
        hi = std::max(hi, v * display.factor);
        if (v > 0.0)
          positive.push_back(v * display.factor);
      }
    }
    const double top = std::max(plot::chooseColourTop(positive, hi), lo + 1e-12);
    std::string data;
    for (std::size_t r = 0; r < regions.size(); ++r) {
      const auto at = std::find(regions[r].fields.begin(), regions[r].fields.end(), column);
      std::string bytes;
      if (at != regions[r].fields.end()) {
        for (const double v : regions[r].values[static_cast<std::size_t>(at - regions[r].fields.begin())]) {
          const double q = std::round(255.0 * (v * display.factor - lo) / (top - lo));
          bytes += static_cast<char>(static_cast<unsigned char>(std::clamp(q, 0.0, 255.0)));
        }
      }
      data += std::string(r ? "," : "") + "\"" + encodeBase64(bytes) + "\"";
    }
    std::string label = units::describeName(column);
    bool blues = false;
    for (const FieldStyle& s : kStyles) {
      if (name == s.name) {
        label = s.label;
        blues = s.blues;
      }
    }
    json += std::string(first ? "" : ",") + "{\"name\":" + jsonString(name) +
            ",\"label\":" + jsonString(label) +
            ",\"unit\":" + jsonString(units::getUnitText(display.unit)) +
            ",\"lo\":" + jsonString(units::formatSignificant(lo, 3)) +
            ",\"top\":" + jsonString(units::formatSignificant(top, 3)) +
            ",\"peak\":" + jsonString(units::formatSignificant(hi, 3)) +
            ",\"blues\":" + (blues ? "true" : "false") + ",\"data\":[" + data + "]}";
    first = false;
  }
  return json + "]}";
}

}  // namespace pistondyn::app
