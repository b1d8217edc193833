#include "HtmlReport.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/Version.h"

namespace pistondyn::app {
namespace {

namespace fs = std::filesystem;

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error(path + ": cannot read");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string prettyUnit(const std::string& u) {
  static const std::pair<const char*, const char*> names[] = {
      {"um", "µm"},       {"Nm", "N·m"},          {"deg", "°"},        {"mps", "m/s"},
      {"mps2", "m/s²"},   {"m_per_s2", "m/s²"},   {"rad_per_s", "rad/s"}, {"kg_m2", "kg·m²"},
      {"m3", "m³"},       {"m2", "m²"},           {"mm3", "mm³"},      {"mm3ph", "mm³/h"},
      {"degC", "°C"},     {"Pas", "Pa·s"},        {"per_K", "1/K"},    {"kg_per_m3", "kg/m³"}};
  for (const auto& [a, b] : names) {
    if (u == a)
      return b;
  }
  return u.empty() ? "–" : u;
}

// "results.min_film_thickness_thrust_um" -> ("min film thickness thrust", "µm").
std::pair<std::string, std::string> describeKey(const std::string& key, const std::string& prefix) {
  std::string name = key.substr(prefix.size());
  const std::string last = name.substr(name.rfind('.') == std::string::npos ? 0 : name.rfind('.') + 1);
  const std::string unit = io::getColumnUnit(last);
  if (!unit.empty())
    name.erase(name.size() - unit.size() - 1);
  std::replace(name.begin(), name.end(), '_', ' ');
  return {name, prettyUnit(unit)};
}

// Numbers to 6 significant digits for reading (summary.json keeps every digit).
std::string displayValue(const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || end != v.c_str() + v.size() || !std::isfinite(x))
    return v;
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

void summaryTable(std::ostream& html, const io::ResultFolder& f, const std::string& prefix,
                  const std::vector<std::string>& skip) {
  html << "<table class=\"summary\"><thead><tr><th>quantity</th><th>value</th><th>unit</th>"
          "</tr></thead><tbody>\n";
  for (const auto& e : f.summary) {
    if (e.key.rfind(prefix, 0) != 0 ||
        std::find(skip.begin(), skip.end(), e.key) != skip.end())
      continue;
    const auto [name, unit] = describeKey(e.key, prefix);
    html << "<tr><td>" << escape(name) << "</td><td class=\"num\">" << escape(displayValue(e.value))
         << "</td><td>" << escape(unit) << "</td></tr>\n";
  }
  html << "</tbody></table>\n";
}

double summaryNumber(const io::ResultFolder& f, const std::string& key, double fallback) {
  const std::string v = f.getSummaryValue(key);
  if (v.empty())
    return fallback;
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  return end != v.c_str() && std::isfinite(x) ? x : fallback;
}

// The animation's data (last cycle) as JSON, and its drawing.
void animation(std::ostream& html, const io::ResultFolder& f) {
  const io::CsvTable& t = f.cycle;
  const io::CycleWindow w = io::selectLastCycle(t);
  for (const char* c : {"piston_y_m", "u_lat_um", "tilt_mrad"}) {
    if (!t.hasColumn(c)) {
      html << "<p>No animation: cycle.csv has no column " << c << ".</p>\n";
      return;
    }
  }
  const std::size_t iy = t.columnIndex("piston_y_m"), iu = t.columnIndex("u_lat_um"),
                    ia = t.columnIndex("tilt_mrad");
  const double bore_mm = 1e3 * summaryNumber(f, "inputs.geometry.bore_m", 0.08);
  const double height_mm = 1e3 * summaryNumber(f, "inputs.piston.compression_height_m", 0.3 * bore_mm * 1e-3);
  const double skirtTop_mm = 1e3 * summaryNumber(f, "inputs.piston.skirt_top_above_pin_m", 0.0);
  const double skirtLength_mm = 1e3 * summaryNumber(f, "inputs.piston.skirt_length_m", 0.4 * bore_mm * 1e-3);
  const std::string hot = f.getSummaryValue("results.hot_clearance_um");
  const bool knownClearance = !hot.empty();
  const double clearance_mm = knownClearance ? summaryNumber(f, "results.hot_clearance_um", 0) * 1e-3
                                             : 5e-4 * bore_mm;
  const double factor = chooseExaggeration(bore_mm * 1e-3, std::max(clearance_mm * 1e-3, 1e-7));
  double yMin = INFINITY, yMax = -INFINITY, uMax = 0.0;
  std::ostringstream angle, y, u, tilt;
  for (std::size_t k = 0; k < w.rows.size(); ++k) {
    const auto& r = t.rows[w.rows[k]];
    const char* sep = k ? "," : "";
    angle << sep << io::formatNumber(w.angle_deg[k]);
    y << sep << io::formatNumber(r[iy] * 1e3);
    u << sep << io::formatNumber(r[iu]);
    tilt << sep << io::formatNumber(r[ia]);
    yMin = std::min(yMin, r[iy] * 1e3);
    yMax = std::max(yMax, r[iy] * 1e3);
    uMax = std::max(uMax, std::abs(r[iu]));
  }
  const double top = yMax + height_mm + 0.1 * bore_mm;
  const double bottom = yMin + skirtTop_mm - skirtLength_mm - 0.1 * bore_mm;
  const double half = bore_mm / 2.0, pistonHalf = half - clearance_mm * factor;
  const double left = -0.8 * bore_mm, width = 1.6 * bore_mm;
  auto n = [](double v) { return io::formatNumber(std::round(v * 1e4) / 1e4); };
  html << "<p>The piston in the bore over the last cycle (crank angle 0° = firing TDC). "
          "Vertical motion and the piston's outline to scale; <strong>lateral displacement, "
          "radial clearance and tilt exaggerated × "
       << io::formatNumber(factor) << "</strong>"
       << (knownClearance ? " (the drawn gap is the hot running clearance at the profile's "
                            "zero-drop point)"
                          : " (no clearance in the results: the drawn gap is schematic)")
       << (f.getSummaryValue("inputs.liner.model") == "ideal_guide"
               ? "; the ideal guide holds the piston on the bore axis (|u_lat| at most " +
                     io::formatNumber(uMax) + " um)"
               : "")
       << ". Thrust side on the right.</p>\n";
  html << "<div class=\"anim\"><svg id=\"bore\" xmlns=\"http://www.w3.org/2000/svg\" width=\"380\" "
          "height=\""
       << std::lround(380.0 * (top - bottom) / width) << "\" viewBox=\"" << n(left) << " "
       << n(-top) << " " << n(width) << " " << n(top - bottom) << "\">\n"
       << "<g transform=\"scale(1,-1)\">\n"
       << "<rect x=\"" << n(-half - 0.15 * bore_mm) << "\" y=\"" << n(bottom) << "\" width=\""
       << n(0.15 * bore_mm) << "\" height=\"" << n(top - bottom) << "\" fill=\"#bbb\"/>\n"
       << "<rect x=\"" << n(half) << "\" y=\"" << n(bottom) << "\" width=\"" << n(0.15 * bore_mm)
       << "\" height=\"" << n(top - bottom) << "\" fill=\"#bbb\"/>\n"
       << "<g id=\"piston\">\n"
       << "<rect x=\"" << n(-pistonHalf * 0.98) << "\" y=\"" << n(skirtTop_mm) << "\" width=\""
       << n(2 * pistonHalf * 0.98) << "\" height=\"" << n(height_mm - skirtTop_mm)
       << "\" fill=\"#9aa7b8\" stroke=\"#333\" stroke-width=\"0.3\"/>\n"
       << "<rect x=\"" << n(-pistonHalf) << "\" y=\"" << n(skirtTop_mm - skirtLength_mm)
       << "\" width=\"" << n(2 * pistonHalf) << "\" height=\"" << n(skirtLength_mm)
       << "\" fill=\"#4f79a8\" stroke=\"#333\" stroke-width=\"0.3\"/>\n"
       << "<circle cx=\"0\" cy=\"0\" r=\"" << n(0.12 * bore_mm)
       << "\" fill=\"#eee\" stroke=\"#333\" stroke-width=\"0.3\"/>\n"
       << "<line x1=\"0\" y1=\"" << n(skirtTop_mm - skirtLength_mm) << "\" x2=\"0\" y2=\""
       << n(height_mm) << "\" stroke=\"#c00\" stroke-width=\"0.3\" stroke-dasharray=\"1,1\"/>\n"
       << "</g>\n</g>\n"
       << "<text x=\"" << n(left + 0.02 * bore_mm) << "\" y=\"" << n(-top + 0.06 * bore_mm)
       << "\" font-size=\"" << n(0.05 * bore_mm) << "\">anti-thrust</text>\n"
       << "<text x=\"" << n(left + width - 0.02 * bore_mm) << "\" y=\"" << n(-top + 0.06 * bore_mm)
       << "\" font-size=\"" << n(0.05 * bore_mm) << "\" text-anchor=\"end\">thrust</text>\n"
       << "</svg>\n<div><p id=\"animation-status\"></p>\n"
       << "<button id=\"animation-play\" type=\"button\">pause</button> "
       << "<input id=\"animation-slider\" type=\"range\" min=\"0\" value=\"0\" "
          "aria-label=\"crank angle\"></div></div>\n";
  html << "<script type=\"application/json\" id=\"motion-data\">{\"factor\":"
       << io::formatNumber(factor) << ",\"angle_deg\":[" << angle.str() << "],\"y_mm\":[" << y.str()
       << "],\"u_lat_um\":[" << u.str() << "],\"tilt_mrad\":[" << tilt.str() << "]}</script>\n";
}

const char* kStyle = R"(body{font-family:sans-serif;max-width:1250px;margin:1em auto;padding:0 1em;color:#222}
table.summary{border-collapse:collapse;margin:0.5em 0}
table.summary td,table.summary th{border:1px solid #ccc;padding:2px 8px;text-align:left}
td.num{font-family:monospace;text-align:right}
figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd}
pre{background:#f6f6f6;padding:0.6em;overflow:auto;font-size:90%}
.anim{display:flex;gap:1.5em;align-items:flex-start}
#animation-status{font-family:monospace;min-width:32em})";

const char* kScript = R"(window.addEventListener('error', function (e) {
  document.body.setAttribute('data-js-error', String(e.message));
});
(function () {
  var node = document.getElementById('motion-data');
  if (!node) { return; }
  var d = JSON.parse(node.textContent);
  var piston = document.getElementById('piston');
  var status = document.getElementById('animation-status');
  var slider = document.getElementById('animation-slider');
  var button = document.getElementById('animation-play');
  var n = d.angle_deg.length, i = 0, playing = true;
  function draw(k) {
    i = k;
    var x = d.u_lat_um[k] * 1e-3 * d.factor;                        // mm, exaggerated
    var a = -d.tilt_mrad[k] * 1e-3 * d.factor * 180 / Math.PI;      // tilt > 0: crown to thrust
    piston.setAttribute('transform', 'translate(' + x + ' ' + d.y_mm[k] + ') rotate(' + a + ')');
    status.textContent = 'crank angle ' + d.angle_deg[k].toFixed(1) + ' deg   u_lat ' +
        d.u_lat_um[k].toFixed(2) + ' um   tilt ' + d.tilt_mrad[k].toFixed(3) + ' mrad';
    slider.value = String(k);
  }
  slider.max = String(n - 1);
  slider.addEventListener('input', function () {
    playing = false; button.textContent = 'play'; draw(Number(slider.value));
  });
  button.addEventListener('click', function () {
    playing = !playing; button.textContent = playing ? 'pause' : 'play';
  });
  setInterval(function () { if (playing) { draw((i + 1) % n); } }, 40);
  draw(0);
  document.body.setAttribute('data-animation', 'ready');
})();
window.addEventListener('load', function () {
  var shown = 0, imgs = document.querySelectorAll('figure img');
  for (var k = 0; k < imgs.length; ++k) { if (imgs[k].complete && imgs[k].naturalWidth > 0) { ++shown; } }
  document.body.setAttribute('data-images-shown', String(shown));
});)";

}  // namespace

std::string encodeBase64(const std::string& bytes) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += abc[v >> 18];
    out += abc[(v >> 12) & 63];
    out += abc[(v >> 6) & 63];
    out += abc[v & 63];
  }
  if (i < bytes.size()) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size())
      v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += abc[v >> 18];
    out += abc[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? abc[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

double chooseExaggeration(double bore_m, double clearance_m) {
  const double wanted = 0.08 * bore_m / clearance_m;
  const double decade = std::pow(10.0, std::floor(std::log10(wanted)));
  double best = decade;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * decade <= wanted)
      best = m * decade;
  }
  return std::max(1.0, best);
}

std::string makeHtmlReport(const io::ResultFolder& f, const std::vector<std::string>& pngPaths,
                           const std::string& plotNote) {
  std::ostringstream html;
  const std::string engine = f.getSummaryValue("inputs.engine.name");
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>pistondyn "
          "report: "
       << escape(engine) << "</title>\n<style>" << kStyle << "</style></head>\n<body>\n";
  html << "<h1>pistondyn report: " << escape(engine) << "</h1>\n";
  html << "<p>Results folder <code>" << escape(fs::absolute(f.directory).string())
       << "</code>, deck <code>" << escape(f.getSummaryValue("deck_file")) << "</code>, pistondyn "
       << escape(f.getSummaryValue("pistondyn_version")) << " (report by pistondyn "
       << escape(io::getVersion()) << "). "
       << escape(f.getSummaryValue("crank_angle_convention")) << "; "
       << escape(f.getSummaryValue("frame_convention")) << ".</p>\n";
  html << "<h2>Summary</h2>\n<p>" << escape(f.getSummaryValue("results.note"))
       << " (6 significant digits; summary.json holds every digit).</p>\n";
  summaryTable(html, f, "results.", {"results.note"});
  html << "<h2>Secondary motion in the bore</h2>\n";
  animation(html, f);
  html << "<h2>Plots</h2>\n";
  if (pngPaths.empty())
    html << "<p class=\"noplots\">" << escape(plotNote) << "</p>\n";
  for (const auto& p : pngPaths) {
    const std::string name = fs::path(p).stem().string();
    html << "<figure><img alt=\"" << escape(name) << "\" src=\"data:image/png;base64,"
         << encodeBase64(readBytes(p)) << "\"><figcaption>" << escape(name)
         << ".png</figcaption></figure>\n";
  }
  html << "<h2>Inputs</h2>\n";
  const std::string deck = f.getSummaryValue("deck_file");
  std::error_code ec;
  if (!deck.empty() && fs::is_regular_file(deck, ec)) {
    html << "<h3>Deck <code>" << escape(deck) << "</code></h3>\n<pre id=\"deck\">"
         << escape(readBytes(deck)) << "</pre>\n";
  } else {
    html << "<p>The deck file <code>" << escape(deck)
         << "</code> is not readable from here; the resolved inputs follow.</p>\n";
  }
  const std::string overrides = f.getSummaryValue("overrides");
  html << "<p>Overrides (--set): <code>" << escape(overrides.empty() ? "[]" : overrides)
       << "</code></p>\n<h3>Resolved inputs (SI, from summary.json)</h3>\n";
  summaryTable(html, f, "inputs.", {});
  html << "<script>" << kScript << "</script>\n</body></html>\n";
  return html.str();
}

}  // namespace pistondyn::app
