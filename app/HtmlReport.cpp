#include "HtmlReport.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "DisplayUnits.h"
#include "FileText.h"
#include "ReportInputs.h"
#include "ReportSummary.h"
#include "SvgChart.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/Version.h"

namespace pistondyn::app {
namespace {

namespace fs = std::filesystem;

std::string escape(const std::string& s) {
  return escapeHtml(s);
}

// The results table: every figure of summary.json's `results` in its display unit.
void summaryTable(std::ostream& html, const io::ResultFolder& f) {
  html << "<table class=\"summary\" id=\"summary\"><thead><tr><th>quantity</th><th>value</th>"
          "<th>unit</th></tr></thead><tbody>\n";
  const std::string prefix = "results.";
  for (const auto& e : f.summary) {
    if (e.key.rfind(prefix, 0) != 0 || e.key == "results.note")
      continue;
    const std::string key = e.key.substr(prefix.size());
    const bool number = e.value != "null" && e.value != "true" && e.value != "false";
    html << "<tr><td>" << escape(units::describeName(key)) << "</td><td class=\"num\">"
         << escape(formatSummaryValue(key, e.value)) << "</td><td>"
         << escape(number ? units::getDisplayUnitText(key) : "") << "</td></tr>\n";
  }
  html << "</tbody></table>\n";
}

// The headline: the figures a run is judged by, each with what it is.
void headline(std::ostream& html, const io::ResultFolder& f) {
  html << "<section id=\"headline\"><h2>Headline</h2>\n<table class=\"headline\"><tbody>\n";
  for (const HeadlineItem& item : makeHeadline(f)) {
    html << "<tr><th>" << escape(item.label) << "</th><td class=\"num\">" << escape(item.value)
         << "</td><td class=\"note\">" << escape(item.note) << "</td></tr>\n";
  }
  html << "</tbody></table></section>\n";
}

// The comment block a deck opens with (its title and the legend of its source marks).
std::string getLeadingComment(const std::string& deckText) {
  std::istringstream in(deckText);
  std::string line, block;
  while (std::getline(in, line) && !line.empty() && line.front() == '#')
    block += line + "\n";
  return block;
}

// The inputs: a row per input in its deck unit with its source (the deck's marks), then the
// deck's text.
void inputsTable(std::ostream& html, const io::ResultFolder& f, const std::string& deckText) {
  const std::vector<InputRow> rows = makeInputRows(f.summaryJson, deckText);
  std::size_t estimated = 0;
  for (const InputRow& r : rows)
    estimated += r.estimated;
  html << "<p>" << rows.size() << " inputs, " << estimated
       << " of them marked EST in the deck (engineering estimates: replace them with your "
          "engine's data). Source: the marks of the deck's comment on the key's line (the "
          "deck's legend below), <em>deck</em> for a value the deck sets without a mark, "
          "<code>--set</code> for an override, <em>default</em> for a "
          "key the deck leaves out, <em>derived</em> for a figure the program computed from "
          "the inputs.</p>\n";
  const std::string legend = getLeadingComment(deckText);
  if (!legend.empty())
    html << "<pre class=\"legend\">" << escape(legend) << "</pre>\n";
  html       << "<table class=\"summary inputs\" id=\"inputs\"><thead><tr><th>key</th><th>value</th>"
          "<th>unit</th><th>source</th><th>note</th></tr></thead><tbody>\n";
  std::string section;
  for (const InputRow& r : rows) {
    if (r.section != section) {
      section = r.section;
      html << "<tr class=\"section\"><th colspan=\"5\">" << escape(section) << "</th></tr>\n";
    }
    html << "<tr" << (r.estimated ? " class=\"est\"" : "") << "><td><code>" << escape(r.key)
         << "</code></td><td class=\"num\">" << escape(r.value) << "</td><td>"
         << escape(r.unit) << "</td><td>" << escape(r.source) << "</td><td class=\"note\">"
         << escape(r.note) << "</td></tr>\n";
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

// The animated map of the skirt's film: each side's skirt unwrapped, the fields of the
// decimated frames (FieldAnimation.h) drawn by the page's script at the frame nearest the
// piston animation's crank angle. Nothing when the run wrote no field frames.
void fieldMap(std::ostream& html, const io::ResultFolder& f, const std::string& json) {
  if (json.empty())
    return;
  html << "<h3>The skirt's film, following the animation</h3>\n"
          "<p>Each side of the skirt unwrapped as seen from the liner: the angle around the "
          "bore across (thrust side centred on 0°, anti-thrust on 180°), the height on the skirt "
          "up; a cell per node of a decimated grid, a frame every 10° of crank angle of the last "
          "cycle - the frame nearest the crank angle of the animation above. One colour scale "
          "per field for both sides; values above its top are drawn in the top colour.</p>\n"
          "<p><label>field <select id=\"field-map-field\"></select></label> "
          "<span id=\"field-map-status\"></span></p>\n"
          "<div class=\"fieldmap\" id=\"field-map\" data-bore-mm=\""
       << io::formatNumber(1e3 * summaryNumber(f, "inputs.geometry.bore_m", 0.08))
       << "\"></div>\n"
       << "<script type=\"application/json\" id=\"field-frames\">" << json << "</script>\n";
}

const char* kStyle = R"(body{font-family:sans-serif;max-width:1250px;margin:1em auto;padding:0 1em;color:#222}
table.summary{border-collapse:collapse;margin:0.5em 0}
table.summary td,table.summary th{border:1px solid #ccc;padding:2px 8px;text-align:left}
td.num{font-family:monospace;text-align:right}
figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd}
pre{background:#f6f6f6;padding:0.6em;overflow:auto;font-size:90%}
.anim{display:flex;gap:1.5em;align-items:flex-start}
#animation-status{font-family:monospace;min-width:32em}
table.headline{border-collapse:collapse;margin:0.5em 0;font-size:105%}
table.headline th{text-align:left;padding:3px 12px 3px 0;font-weight:normal}
table.headline td.num{font-weight:bold;text-align:left;padding:3px 12px}
td.note{color:#555;font-size:90%}
tr.est td{background:#fff4d6}tr.section th{background:#eef2f7;text-align:left}
pre.legend{font-size:85%}
.fieldmap{display:flex;gap:1.5em;align-items:flex-end;flex-wrap:wrap}
.fieldmap figure{margin:0}.fieldmap canvas{border:1px solid #999}
#field-map-status{font-family:monospace})";

const char* kScript = R"(window.addEventListener('error', function (e) {
  document.body.setAttribute('data-js-error', String(e.message));
});
// The animated field map: window.pistondynShowFieldFrame(angle) draws the frame nearest a
// crank angle (the motion's loop below calls it).
(function () {
  var node = document.getElementById('field-frames');
  if (!node) { return; }
  var d = JSON.parse(node.textContent);
  var box = document.getElementById('field-map');
  var select = document.getElementById('field-map-field');
  var status = document.getElementById('field-map-status');
  var bore = Number(box.getAttribute('data-bore-mm'));
  function decode(s) {
    var b = atob(s), a = new Uint8Array(b.length);
    for (var i = 0; i < b.length; ++i) { a[i] = b.charCodeAt(i); }
    return a;
  }
  var bytes = d.fields.map(function (f) { return f.data.map(decode); });
  function palette(stops) {
    var p = [];
    for (var k = 0; k < 256; ++k) {
      var t = k / 255 * (stops.length - 1), i = Math.min(Math.floor(t), stops.length - 2), u = t - i;
      p.push('rgb(' + [0, 1, 2].map(function (j) {
        return Math.round(stops[i][j] + u * (stops[i + 1][j] - stops[i][j]));
      }).join(',') + ')');
    }
    return p;
  }
  // The colours of the cycle maps (cycle_maps.png): magma, blues for the fill fraction.
  var magma = palette([[0, 0, 4], [59, 15, 112], [140, 41, 129], [222, 73, 104], [254, 159, 109], [252, 253, 191]]);
  var blues = palette([[255, 255, 255], [198, 219, 239], [107, 174, 214], [8, 81, 156]]);
  // A cell per node reaching halfway to its neighbours, in pixels of a physical scale.
  function edges(v) {
    var e = [v[0]];
    for (var i = 1; i < v.length; ++i) { e.push((v[i - 1] + v[i]) / 2); }
    e.push(v[v.length - 1]);
    return e;
  }
  var maps = d.regions.map(function (g) {
    var arc = (g.phi_deg[g.phi_deg.length - 1] - g.phi_deg[0]) * Math.PI / 180 * bore / 2;
    var height = g.y_mm[g.y_mm.length - 1] - g.y_mm[0];
    var scale = 260 / Math.max(arc, height, 1e-9);
    var fig = document.createElement('figure');
    var c = document.createElement('canvas');
    c.width = Math.max(20, Math.round(arc * scale));
    c.height = Math.max(20, Math.round(height * scale));
    c.className = 'field-map';
    var cap = document.createElement('figcaption');
    cap.textContent = g.title + ': φ ' + g.phi_deg[0] + '…' + g.phi_deg[g.phi_deg.length - 1] +
        '°, y ' + g.y_mm[0] + '…' + g.y_mm[g.y_mm.length - 1] + ' mm';
    fig.appendChild(c); fig.appendChild(cap); box.appendChild(fig);
    var ex = edges(g.phi_deg), ey = edges(g.y_mm);
    function px(v, e, n) { return (v - e[0]) / Math.max(e[e.length - 1] - e[0], 1e-12) * n; }
    return {c: c, nx: g.phi_deg.length, ny: g.y_mm.length,
            x: ex.map(function (v) { return px(v, ex, c.width); }),
            y: ey.map(function (v) { return c.height - px(v, ey, c.height); })};
  });
  var bar = document.createElement('figure');
  var bc = document.createElement('canvas');
  bc.width = 18; bc.height = 200; bc.className = 'field-map-bar';
  var bt = document.createElement('figcaption');
  bar.appendChild(bc); bar.appendChild(bt); box.appendChild(bar);
  d.fields.forEach(function (f, k) {
    var o = document.createElement('option');
    o.value = String(k); o.textContent = f.label + (f.unit ? ' [' + f.unit + ']' : '');
    select.appendChild(o);
  });
  var field = 0, frame = 0, angle = d.frames_deg[0];
  function draw() {
    var f = d.fields[field], pal = f.blues ? blues : magma;
    maps.forEach(function (m, r) {
      var ctx = m.c.getContext('2d'), data = bytes[field][r], n = m.nx * m.ny;
      ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, m.c.width, m.c.height);
      if (data.length < (frame + 1) * n) { return; }  // this side has no such field
      for (var j = 0; j < m.ny; ++j) {
        for (var i = 0; i < m.nx; ++i) {
          ctx.fillStyle = pal[data[frame * n + j * m.nx + i]];
          ctx.fillRect(m.x[i], m.y[j + 1], m.x[i + 1] - m.x[i] + 0.5, m.y[j] - m.y[j + 1] + 0.5);
        }
      }
    });
    var b = bc.getContext('2d');
    for (var k = 0; k < 256; ++k) {
      b.fillStyle = pal[k];
      b.fillRect(0, bc.height * (1 - (k + 1) / 256), bc.width, bc.height / 256 + 1);
    }
    bt.textContent = f.lo + ' … ' + f.top + ' ' + f.unit + ' (bottom to top)' +
        (f.peak !== f.top ? ' (peak ' + f.peak + ')' : '');
    status.textContent = 'crank angle ' + angle.toFixed(1) + ' deg: frame of ' +
        d.frames_deg[frame].toFixed(0) + ' deg';
  }
  select.addEventListener('change', function () { field = Number(select.value); draw(); });
  window.pistondynShowFieldFrame = function (a) {
    var best = 0, bestGap = Infinity;
    for (var k = 0; k < d.frames_deg.length; ++k) {
      var t = ((a - d.frames_deg[k]) % 720 + 720) % 720, gap = Math.min(t, 720 - t);
      if (gap < bestGap) { bestGap = gap; best = k; }  // nearest over the periodic cycle
    }
    angle = a; frame = best; draw();
  };
  window.pistondynShowFieldFrame(d.frames_deg[0]);
  document.body.setAttribute('data-field-map', 'ready');
})();
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
    if (window.pistondynShowFieldFrame) { window.pistondynShowFieldFrame(d.angle_deg[k]); }
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
                           const std::string& plotNote, const std::string& fieldFramesJson) {
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
  headline(html, f);
  html << "<h2>Secondary motion in the bore</h2>\n";
  animation(html, f);
  fieldMap(html, f, fieldFramesJson);
  html << "<h2>Summary</h2>\n<p>" << escape(f.getSummaryValue("results.note"))
       << ", each in the unit an engine engineer reads it in and to the digits that mean "
          "something (summary.json holds every digit, in the units its keys name).</p>\n";
  summaryTable(html, f);
  html << "<h2>Plots</h2>\n";
  writeEmbeddedFigures(html, pngPaths, plotNote);
  html << "<h2>Inputs</h2>\n";
  const std::string deck = f.getSummaryValue("deck_file");
  std::error_code ec;
  const bool deckReadable = !deck.empty() && fs::is_regular_file(deck, ec);
  const std::string deckText = deckReadable ? readWholeFile(deck) : "";
  if (!deckReadable) {
    html << "<p>The deck file <code>" << escape(deck)
         << "</code> is not readable from here: the inputs follow without their sources.</p>\n";
  }
  const std::string overrides = f.getSummaryValue("overrides");
  html << "<p>Overrides (--set): <code>" << escape(overrides.empty() ? "[]" : overrides)
       << "</code></p>\n";
  inputsTable(html, f, deckText);
  if (deckReadable) {
    html << "<details><summary>The deck <code>" << escape(deck)
         << "</code> as written</summary>\n<pre id=\"deck\">" << escape(deckText)
         << "</pre></details>\n";
  }
  html << "<script>" << kScript << "</script>\n</body></html>\n";
  return html.str();
}

void writeEmbeddedFigures(std::ostream& html, const std::vector<std::string>& pngPaths,
                          const std::string& plotNote) {
  if (pngPaths.empty())
    html << "<p class=\"noplots\">" << escape(plotNote) << "</p>\n";
  for (const auto& p : pngPaths) {
    const std::string name = fs::path(p).stem().string();
    html << "<figure><img alt=\"" << escape(name) << "\" src=\"data:image/png;base64,"
         << encodeBase64(readWholeFile(p)) << "\"><figcaption>" << escape(name)
         << ".png</figcaption></figure>\n";
  }
}

}  // namespace pistondyn::app
