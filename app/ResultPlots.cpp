#include "ResultPlots.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>


#include "DisplayUnits.h"
#include "Gnuplot.h"
#include "PlotSupport.h"
#include "pistondyn/io/ResultWriters.h"

namespace pistondyn::app {
namespace {

namespace fs = std::filesystem;
using namespace plot;

// ---- figure descriptions ----------------------------------------------------------

// Which runs a figure or series belongs to: every run, runs with a liner element (the
// summary has side-force figures), or runs of one liner model (inputs.liner.model). A run
// it belongs to must have its columns (checkResultPlotColumns).
constexpr const char* kEveryRun = "";
constexpr const char* kRunsWithALiner = "a liner element";
constexpr const char* kSkirt = "lubricated_skirt";

struct Series {
  std::string output;  // output name without unit
  std::string title;
  std::string colour;
  int dashType = 1;
  std::string belongsTo = kEveryRun;
};
struct ReferenceLine {
  double value;
  std::string title;
};
struct Panel {
  std::string quantity;  // axis label without unit
  std::string unit;      // the unit the axis is in
  std::vector<Series> series;
  std::vector<ReferenceLine> lines;
  int stacked = 0;  // the first `stacked` series are drawn as stacked filled areas
  std::string yrange;
};
struct Figure {
  std::string name;      // file stem
  std::string title;
  std::string requiredOutput;  // the figure is drawn only if this output exists
  std::vector<Panel> panels;
  std::string belongsTo = kEveryRun;
};

std::vector<Figure> describeFigures(const io::ResultFolder& f) {
  std::vector<Figure> figures;
  figures.push_back(
      {"crank_train_forces",
       "Crank-train forces",
       "",
       {{"force",
         axisUnit("gas_force_N"),
         {{"gas_force", "gas force on the crown (+ down)", kBlue},
          {"conrod_force", "conrod force (+ compression)", kOrange},
          {"crank_train_side_force", "crank-train side force, from the rod (+ thrust)", kPurple},
          {"side_force", "side force on the liner (+ thrust)", kGreen, 2, kRunsWithALiner}},
         {},
         0,
         ""},
        {"torque",
         axisUnit("crank_torque_Nm"),
         {{"crank_torque", "crank torque (indicated)", kBlue},
          {"drive_torque", "drive torque", kRed, 2}},
         {},
         0,
         ""}}});
  figures.push_back(
      {"side_force",
       "Side force",
       "side_force",
       {{"force",
         axisUnit("side_force_N"),
         {{"side_force", "side force on the liner (+ thrust)", "black"},
          {"hydrodynamic_normal_force_thrust", "film, thrust side", kBlue, 1, kSkirt},
          {"hydrodynamic_normal_force_antithrust", "film, anti-thrust side", kOrange, 1, kSkirt},
          {"asperity_normal_force_thrust", "asperities, thrust side", kBlue, 2, kSkirt},
          {"asperity_normal_force_antithrust", "asperities, anti-thrust side", kOrange, 2,
           kSkirt}},
         {},
         0,
         ""},
        {"moment on the liner about +z",
         axisUnit("liner_moment_Nm"),
         {{"guide_moment", "guide moment (about the pin axis)", kPurple, 1, "ideal_guide"},
          {"liner_moment", "skirt moment (about the pin axis)", kPurple, 1, kSkirt}},
         {},
         0,
         ""}},
       kRunsWithALiner});
  std::vector<ReferenceLine> clearance;
  const std::string lateral = axisUnit("u_lat_um");
  const std::string hot = f.getSummaryValue("results.hot_clearance_um");
  if (!hot.empty()) {
    const double c = std::strtod(hot.c_str(), nullptr) * *conversionFactor("um", lateral);
    clearance = {{c, "± hot clearance (zero-drop point)"}, {-c, ""}};
  }
  figures.push_back({"secondary_motion",
                     "Secondary motion (+ towards thrust; tilt > 0: crown towards thrust)",
                     "u_lat_skirt_top",
                     {{"lateral displacement",
                       lateral,
                       {{"u_lat_skirt_top", "at the skirt top", kBlue},
                        {"u_lat", "at the pin axis", "black", 2},
                        {"u_lat_skirt_bottom", "at the skirt bottom", kOrange}},
                       clearance,
                       0,
                       ""},
                      {"tilt", axisUnit("tilt_mrad"), {{"tilt", "tilt", kGreen}}, {}, 0, ""}},
                     kSkirt});
  figures.push_back({"friction",
                     "Skirt friction",
                     "friction_force",
                     {{"friction force on the piston along +y",
                       axisUnit("friction_force_N"),
                       {{"friction_force", "total", "black"},
                        {"hydrodynamic_friction", "film shear", kBlue},
                        {"asperity_friction", "asperity (boundary)", kRed}},
                       {},
                       0,
                       ""},
                      {"friction power", axisUnit("friction_power_W"),
                       {{"friction_power", "friction power", kPurple}}, {},
                       0, ""}},
                     kSkirt});
  figures.push_back(
      {"film_thickness",
       "Minimum film thickness and h/σ",
       "min_film_thickness_thrust",
       {{"minimum film thickness",
         axisUnit("min_film_thickness_thrust_um"),
         {{"min_film_thickness_thrust", "thrust side", kBlue},
          {"min_film_thickness_antithrust", "anti-thrust side", kOrange}},
         {{0.0, ""}},
         0,
         ""},
        {"minimum h/σ",
         axisUnit("min_h_over_sigma_thrust"),
         {{"min_h_over_sigma_thrust", "thrust side", kBlue},
          {"min_h_over_sigma_antithrust", "anti-thrust side", kOrange}},
         {{1.0, "h/σ = 1 and 3 (regime limits)"}, {3.0, ""}},
         0,
         ""}},
       kSkirt});
  const std::string share = axisUnit("hydrodynamic_share_thrust");
  Figure regimes{"regime_shares", "Lubrication regimes: area shares of each skirt side",
                 "hydrodynamic_share_thrust", {}, kSkirt};
  for (const auto& [side, label] : {std::pair<std::string, std::string>{"thrust", "thrust side"},
                                    {"antithrust", "anti-thrust side"}}) {
    regimes.panels.push_back({"area share, " + label,
                              share,
                              {{"boundary_share_" + side, "boundary (h/σ ≤ 1)", kRed},
                               {"mixed_share_" + side, "mixed (1 < h/σ ≤ 3)", kOrange},
                               {"hydrodynamic_share_" + side, "hydrodynamic (h/σ > 3)", kBlue},
                               {"wetted_share_" + side, "wetted (fill fraction > 0)", "black"}},
                              {},
                              3,
                              "[0:" + number(1.05 * *conversionFactor("", share)) + "]"});
  }
  figures.push_back(regimes);
  return figures;
}

// ---- writing data and scripts ---------------------------------------------------------

// One crank-angle figure: its data file and its part of the script.
bool writeFigure(const Figure& fig, const io::ResultFolder& folder, const io::CycleWindow& w,
                 const fs::path& work, const std::string& pngPath, std::ostream& gp) {
  const io::CsvTable& t = folder.cycle;
  if (!fig.requiredOutput.empty() && !hasOutput(t, fig.requiredOutput))
    return false;
  // Columns of the data file: angle, then every series found, panel by panel.
  std::vector<Column> columns;
  std::vector<std::vector<std::pair<const Series*, int>>> present(fig.panels.size());
  for (std::size_t p = 0; p < fig.panels.size(); ++p) {
    for (const Series& s : fig.panels[p].series) {
      if (const auto c = findOutput(t, s.output, fig.panels[p].unit)) {
        columns.push_back(*c);
        present[p].push_back({&s, static_cast<int>(columns.size()) + 1});
      }
    }
  }
  std::vector<std::size_t> panels;
  for (std::size_t p = 0; p < fig.panels.size(); ++p) {
    const bool complete =
        fig.panels[p].stacked == 0 ||
        static_cast<int>(present[p].size()) == static_cast<int>(fig.panels[p].series.size());
    if (!present[p].empty() && complete)
      panels.push_back(p);
  }
  if (panels.empty())
    return false;
  const fs::path data = work / (fig.name + ".dat");
  {
    std::ofstream out(data);
    for (std::size_t i = 0; i < w.rows.size(); ++i) {
      out << number(w.angle_deg[i]);
      for (const Column& c : columns)
        out << ' ' << number(t.rows[w.rows[i]][c.index] * c.factor);
      out << '\n';
    }
    if (!out)
      throw std::runtime_error(data.string() + ": write failed");
  }
  const int height = 110 + 360 * static_cast<int>(panels.size());
  gp << "\nset terminal pngcairo size 1200," << height << " noenhanced font 'Sans,11'\n"
     << "set output " << quoted(pngPath) << "\n";
  const std::string engine = folder.getSummaryValue("inputs.engine.name");
  gp << "set multiplot layout " << panels.size() << ",1 title "
     << twoLines(fig.title + "   (last cycle)", engine) << " font 'Sans,13'\n";
  for (std::size_t p : panels) {
    const Panel& panel = fig.panels[p];
    writeTdcMarks(gp);
    gp << "set ylabel " << quoted(panel.quantity + " (" + displayUnit(panel.unit) + ")") << "\n";
    gp << "set yrange " << (panel.yrange.empty() ? "[*:*]" : panel.yrange) << "\n";
    std::string plot;
    auto add = [&](const std::string& item) { plot += (plot.empty() ? "plot " : ", \\\n  ") + item; };
    const std::string file = quoted(data.string());
    std::string below = "0";
    int k = 0;
    for (const auto& [s, col] : present[p]) {
      const std::string style = "lc rgb '" + s->colour + "'";
      if (k++ < panel.stacked) {
        const std::string top = below + "+$" + std::to_string(col);
        add(file + " using 1:(" + below + "):(" + top + ") with filledcurves fs solid 0.45 " +
            style + " title " + quoted(s->title));
        below = top;
      } else {
        add(file + " using 1:" + std::to_string(col) + " with lines lw 2 dt " +
            std::to_string(s->dashType) + " " + style + " title " + quoted(s->title));
      }
    }
    for (const ReferenceLine& l : panel.lines) {
      add(number(l.value) + " with lines dt 3 lw 1.2 lc rgb 'gray40' " +
          (l.title.empty() ? std::string("notitle") : "title " + quoted(l.title)));
    }
    gp << plot << "\n";
  }
  gp << "unset multiplot\nunset output\n";
  return true;
}

// A field-dump map: film pressure, fill fraction and gap, thrust and anti-thrust side.
void writeFieldMap(double angle_deg, const std::vector<const io::FieldDumpFile*>& sides,
                   const std::string& engine, const fs::path& work, const std::string& pngPath,
                   std::ostream& gp) {
  struct Field {
    const char* output;
    const char* label;
    std::string unit;
  };
  const Field fields[] = {{"film_pressure", "film pressure (gauge)", axisUnit("film_pressure_Pa")},
                          {"fill_fraction", "fill fraction", axisUnit("fill_fraction")},
                          {"gap", "gap (nominal, all seven terms)", axisUnit("gap_um")}};
  std::vector<fs::path> data;
  std::vector<double> lo(3, INFINITY), hi(3, -INFINITY);
  for (const io::FieldDumpFile* d : sides) {
    const io::CsvTable t = io::readCsvTable(d->path, {"phi_deg", "y_mm"});
    std::vector<Column> cols;
    for (const Field& fld : fields) {
      const auto c = findOutput(t, fld.output, fld.unit);
      if (!c)
        throw std::runtime_error(d->path + ": no column for " + fld.output);
      cols.push_back(*c);
    }
    const std::size_t phi = t.columnIndex("phi_deg"), y = t.columnIndex("y_mm");
    data.push_back(work / ("field_" + number(angle_deg) + "_" + d->side + ".dat"));
    std::ofstream out(data.back());
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      // pm3d reads one scan per height: phi runs fastest, a blank line between heights.
      if (i > 0 && t.rows[i][y] != t.rows[i - 1][y])
        out << '\n';
      out << number(t.rows[i][phi]) << ' ' << number(t.rows[i][y]);
      for (std::size_t k = 0; k < cols.size(); ++k) {
        const double v = t.rows[i][cols[k].index] * cols[k].factor;
        lo[k] = std::min(lo[k], v);
        hi[k] = std::max(hi[k], v);
        out << ' ' << number(v);
      }
      out << '\n';
    }
  }
  gp << "\nset terminal pngcairo size 1200,1250 noenhanced font 'Sans,11'\n"
     << "set output " << quoted(pngPath) << "\n"
     << "unset arrow\nunset x2tics\nset xtics autofreq mirror\nset mxtics default\n"
     << "set xrange [*:*]\nset yrange [*:*]\nset autoscale xfix\nset autoscale yfix\n"
     << "set view map\nset pm3d map corners2color mean\nunset key\n"
     << "set multiplot layout 3," << sides.size() << " title "
     << twoLines("Skirt fields at crank angle " + number(angle_deg) +
                     "° of the last cycle (0° = firing TDC), unwrapped skirt",
                 engine)
     << " font 'Sans,13'\n";
  for (std::size_t k = 0; k < 3; ++k) {
    // One colour scale for both sides, so that they compare.
    const double span = hi[k] - lo[k];
    const double a = lo[k], b = span > 0 ? hi[k] : lo[k] + 1.0;
    gp << (k == 1 ? "set palette defined (0 '#ffffff', 1 '#c6dbef', 2 '#6baed6', 3 '#08519c')\n"
                  : "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', "
                    "4 '#fde725')\n");
    gp << "set cbrange [" << number(a) << ":" << number(b) << "]\n";
    for (std::size_t s = 0; s < sides.size(); ++s) {
      const std::string side = sides[s]->side == "thrust" ? "thrust side" : "anti-thrust side";
      gp << "set title " << quoted(std::string(fields[k].label) + ", " + side) << "\n"
         << "set xlabel \"circumferential angle φ from the thrust axis (°)\"\n"
         << "set ylabel \"height above the pin axis (mm)\"\n"
         << "set cblabel " << quoted(std::string(fields[k].label) + " (" +
                                     displayUnit(fields[k].unit) + ")") << "\n"
         << "splot " << quoted(data[s].string()) << " using 1:2:" << (3 + k) << " with pm3d\n";
    }
  }
  gp << "unset multiplot\nunset output\nunset view\nunset pm3d\nunset title\nunset cblabel\n"
     << "set key\n";
}

// ---- cycle maps (cycle_map_<region>.csv) ------------------------------------------------

// How a mapped field is drawn; a field of the files not listed is drawn with its name as the
// label (a region added later needs no code here).
struct MapStyle {
  const char* field;  // column without unit
  const char* label;
  bool blues;         // a fill fraction: white to blue; else dark to bright
  double colourTop;   // the top of the colour scale at most (h/σ: the regimes lie below 3)
};
const MapStyle kMapStyles[] = {
    {"film_pressure_max", "largest film pressure (gauge) around the arc", false, INFINITY},
    {"fill_fraction_mean", "mean fill fraction around the arc", true, INFINITY},
    {"contact_pressure_max", "largest asperity pressure around the arc", false, INFINITY},
    {"wear_depth_rate_max", "largest Archard wear depth rate around the arc", false, INFINITY},
    {"h_over_sigma_min", "smallest h/σ around the arc", false, 6.0},
};
// Not drawn: the smallest gap is h/σ times the composite roughness, drawn above.
const char* const kMapsNotDrawn[] = {"gap_min"};

// The height axis of a region's map: its file's second column.
std::string describeHeight(const std::string& column) {
  const auto [name, unit] = units::splitUnit(column);
  const std::string what = name == "y" ? "height above the pin axis" : units::describeName(name);
  return what + " (" + displayUnit(unit) + ")";
}

std::string describeRegion(const std::string& region) {
  if (region == "thrust")
    return "thrust side";
  if (region == "antithrust")
    return "anti-thrust side";
  std::string s = region;
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

struct MapPanelField {
  std::string field;  // column without unit
  std::string unit;   // the colour bar's unit
  MapStyle style;
  int dataColumn = 0;                    // in the data files (gnuplot's, from 1)
  double lo = INFINITY, hi = -INFINITY;  // over every region, in `unit`
  std::vector<double> positive;          // the values > 0, for the colour scale's top
};

// The top of a field's colour scale (chooseColourTop), at most the style's colourTop.
double colourTop(MapPanelField& f) {
  return std::min(chooseColourTop(f.positive, f.hi), f.style.colourTop);
}

// Reads the maps' files; per region a data file (angle, height, then one column per entry of
// `fields`, NaN where the region lacks it; a blank line between angles: pm3d's scans).
std::vector<MapPanelField> writeMapData(const std::vector<io::RegionFile>& maps,
                                        const fs::path& work, std::vector<fs::path>& data,
                                        std::vector<std::string>& heights) {
  std::vector<MapPanelField> fields;
  std::vector<io::CsvTable> tables;
  for (const io::RegionFile& m : maps) {
    tables.push_back(io::readCsvTable(m.path, {"crank_angle_deg"}));
    const io::CsvTable& t = tables.back();
    heights.push_back(describeHeight(t.columns.at(1)));
    for (std::size_t c = 2; c < t.columns.size(); ++c) {
      const std::string name = units::splitUnit(t.columns[c]).first;
      if (std::find(std::begin(kMapsNotDrawn), std::end(kMapsNotDrawn), name) != std::end(kMapsNotDrawn) ||
          std::any_of(fields.begin(), fields.end(), [&](const MapPanelField& f) { return f.field == name; }))
        continue;
      MapStyle style{nullptr, nullptr, false, INFINITY};
      for (const MapStyle& s : kMapStyles) {
        if (name == s.field)
          style = s;
      }
      MapPanelField f;
      f.field = name;
      f.unit = axisUnit(t.columns[c]);
      f.style = style;
      fields.push_back(std::move(f));
    }
  }
  // The listed fields first, in the table's order.
  auto rank = [](const MapPanelField& f) {
    for (std::size_t k = 0; k < std::size(kMapStyles); ++k) {
      if (f.field == kMapStyles[k].field)
        return k;
    }
    return std::size(kMapStyles);
  };
  std::stable_sort(fields.begin(), fields.end(),
                   [&](const MapPanelField& a, const MapPanelField& b) { return rank(a) < rank(b); });
  for (std::size_t k = 0; k < fields.size(); ++k)
    fields[k].dataColumn = 3 + static_cast<int>(k);
  for (std::size_t r = 0; r < maps.size(); ++r) {
    const io::CsvTable& t = tables[r];
    std::vector<std::optional<Column>> columns;
    for (const MapPanelField& f : fields)
      columns.push_back(findOutput(t, f.field, f.unit));
    data.push_back(work / ("cycle_map_" + maps[r].region + ".dat"));
    std::ofstream out(data.back());
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      if (i > 0 && t.rows[i][0] != t.rows[i - 1][0])
        out << '\n';
      out << number(t.rows[i][0]) << ' ' << number(t.rows[i][1]);
      for (std::size_t k = 0; k < fields.size(); ++k) {
        if (!columns[k]) {
          out << " NaN";
          continue;
        }
        const double v = t.rows[i][columns[k]->index] * columns[k]->factor;
        fields[k].lo = std::min(fields[k].lo, v);
        fields[k].hi = std::max(fields[k].hi, v);
        if (v > 0.0)
          fields[k].positive.push_back(v);
        out << ' ' << number(v);
      }
      out << '\n';
    }
    if (!out)
      throw std::runtime_error(data.back().string() + ": write failed");
  }
  return fields;
}

// cycle_maps.png: one column per region, one row per field that is not zero everywhere, crank
// angle across and height up; one colour scale per field, shared by the regions. Returns
// false when there is nothing to draw.
bool writeCycleMaps(const io::ResultFolder& folder, const fs::path& work,
                    const std::string& pngPath, std::ostream& gp) {
  if (folder.cycleMaps.empty())
    return false;
  std::vector<fs::path> data;
  std::vector<std::string> heights;
  std::vector<MapPanelField> all = writeMapData(folder.cycleMaps, work, data, heights);
  std::vector<MapPanelField> fields;
  std::string zero;
  for (const MapPanelField& f : all) {
    if (f.lo == 0.0 && f.hi == 0.0)
      zero += (zero.empty() ? "" : ", ") +
              (f.style.label ? std::string(f.style.label) : units::describeName(f.field));
    else if (f.lo <= f.hi)
      fields.push_back(f);
  }
  if (fields.empty())
    return false;
  const std::size_t nRegions = folder.cycleMaps.size();
  gp << "\nset terminal pngcairo size 1200," << 110 + 330 * fields.size()
     << " noenhanced font 'Sans,10'\n"
     << "set output " << quoted(pngPath) << "\n"
     << "unset arrow\nunset x2tics\nset xtics 0,90,720 mirror\nset mxtics 3\n"
     << "set xrange [0:720]\nset yrange [*:*]\nset autoscale yfix\n"
     << "set view map\nset pm3d map corners2color c1\nunset key\n"
     << "set multiplot layout " << fields.size() << "," << nRegions << " title "
     // The fields that are zero throughout on a line of their own (on one line with the rest
     // they ran past the page's width).
     << quotedLines({"Over the last cycle, crank angle across (0° and 720° firing TDC, 360° "
                     "gas-exchange TDC), height up",
                     zero.empty() ? std::string() : "zero throughout: " + zero,
                     folder.getSummaryValue("inputs.engine.name")})
     << " font 'Sans,12'\n";
  for (MapPanelField& f : fields) {
    // Values beyond the colour scale are drawn in its end colours.
    const double top = std::max(colourTop(f), f.lo + 1e-12 * std::max(1.0, std::abs(f.lo)));
    const std::string label = f.style.label ? f.style.label : units::describeName(f.field);
    std::string note;
    if (top < f.hi) {
      const std::string unit = f.unit.empty() ? "" : " " + displayUnit(f.unit);
      note = (f.hi > f.style.colourTop ? "above " + number(top)
                                       : "peaks up to " + units::formatSignificant(f.hi, 3)) +
             unit + " in the top colour";
    }
    gp << (f.style.blues ? "set palette defined (0 '#ffffff', 1 '#c6dbef', 2 '#6baed6', 3 '#08519c')\n"
                         : "set palette defined (0 '#000004', 1 '#3b0f70', 2 '#8c2981', 3 "
                           "'#de4968', 4 '#fe9f6d', 5 '#fcfdbf')\n")
       << "set cbrange [" << number(f.lo) << ":" << number(top) << "]\n"
       << "set cblabel " << quoted(f.unit.empty() ? "" : displayUnit(f.unit)) << "\n";
    for (std::size_t r = 0; r < nRegions; ++r) {
      gp << "set title " << twoLines(describeRegion(folder.cycleMaps[r].region) + ": " + label, note)
         << "\nset xlabel \"crank angle (°)\"\nset ylabel " << quoted(heights[r]) << "\n"
         << "splot " << quoted(data[r].string()) << " using 1:2:" << f.dataColumn
         << " with pm3d\n";
    }
  }
  gp << "unset multiplot\nunset output\nunset view\nunset pm3d\nunset title\nunset cblabel\n"
     << "set key\n";
  return true;
}

// The liner's oil film along the bore over the last cycle (liner_film.csv, written with the
// liner oil transport): crank angle x bore height maps, thrust and anti-thrust side, on a
// logarithmic colour scale from 0.1 um, so that the ring's micrometre shows beside the
// flooded region's tens (films below it, the dry liner and the skirt's path stay white).
void writeLinerFilmMap(const std::string& csvPath, const std::string& engine,
                       const fs::path& work, const std::string& pngPath, std::ostream& gp) {
  const io::CsvTable t = io::readCsvTable(
      csvPath, {"crank_angle_deg", "height_above_crank_mm", "film_thrust_um", "film_antithrust_um"});
  const std::size_t a = t.columnIndex("crank_angle_deg");
  const std::size_t h = t.columnIndex("height_above_crank_mm");
  const std::size_t ft = t.columnIndex("film_thrust_um"), fa = t.columnIndex("film_antithrust_um");
  // pm3d reads one scan per crank angle, in order: the heights run fastest, a blank line
  // between angles (a run that starts elsewhere than 0 deg wraps within the cycle).
  std::vector<std::size_t> order(t.rows.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return t.rows[x][a] < t.rows[y][a]; });
  const fs::path data = work / "liner_film.dat";
  double top = 1.0;
  {
    std::ofstream out(data);
    for (std::size_t n = 0; n < order.size(); ++n) {
      const auto& row = t.rows[order[n]];
      if (n > 0 && row[a] != t.rows[order[n - 1]][a])
        out << '\n';
      out << number(row[a]) << ' ' << number(row[h]) << ' ' << number(row[ft]) << ' '
          << number(row[fa]) << '\n';
      top = std::max({top, row[ft], row[fa]});
    }
  }
  gp << "\nset terminal pngcairo size 1200,900 noenhanced font 'Sans,11'\n"
     << "set output " << quoted(pngPath) << "\n"
     << "unset arrow\nunset x2tics\nset xtics 90 mirror\nset mxtics default\n"
     << "set xrange [*:*]\nset yrange [*:*]\nset autoscale xfix\nset autoscale yfix\n"
     << "set view map\nset pm3d map corners2color mean\nunset key\n"
     << "set palette defined (0 '#ffffff', 1 '#c6dbef', 2 '#6baed6', 3 '#08519c', 4 '#08306b')\n"
     << "set logscale cb\nset cbrange [0.1:" << number(top) << "]\n"
     << "set multiplot layout 2,1 title "
     << twoLines("Oil film on the liner along the bore over the last cycle (0° = firing TDC; "
                 "white where the skirt covers it or the film is below 0.1 µm)",
                 engine)
     << " font 'Sans,13'\n";
  for (int side = 0; side < 2; ++side) {
    gp << "set title " << quoted(side == 0 ? "thrust side" : "anti-thrust side") << "\n"
       << "set xlabel \"crank angle (°)\"\n"
       << "set ylabel \"bore height above the crank axis (mm)\"\n"
       << "set cblabel \"liner film, mean over the arc (µm)\"\n"
       << "splot " << quoted(data.string()) << " using 1:2:" << (3 + side) << " with pm3d\n";
  }
  gp << "unset multiplot\nunset output\nunset view\nunset pm3d\nunset title\nunset cblabel\n"
     << "unset logscale cb\nset xtics autofreq\nset key\n";
}

}  // namespace

void checkResultPlotColumns(const io::ResultFolder& folder) {
  const std::string model = folder.getSummaryValue("inputs.liner.model");
  const bool hasLiner = !folder.getSummaryValue("results.side_force_max_N").empty();
  auto belongs = [&](const std::string& to) {
    return to == kEveryRun || (to == kRunsWithALiner && hasLiner) || to == model;
  };
  const std::string csv = (fs::path(folder.directory) / "cycle.csv").string();
  auto run = [&](const std::string& to) {
    return to == kEveryRun ? std::string("every run")
           : to == kRunsWithALiner ? "a run with a liner element"
                                   : "a run of liner model " + to;
  };
  for (const Figure& fig : describeFigures(folder)) {
    if (!belongs(fig.belongsTo))
      continue;
    for (const Panel& panel : fig.panels) {
      for (const Series& s : panel.series) {
        if (!belongs(s.belongsTo))
          continue;
        const std::string what = "the figure " + fig.name + ".png (" + panel.quantity +
                                 ") of " + run(s.belongsTo.empty() ? fig.belongsTo : s.belongsTo);
        if (!hasOutput(folder.cycle, s.output)) {
          throw io::ResultFolderError(csv + ": no column " + s.output + "_<unit>, which " + what +
                                      " needs; nothing was drawn");
        }
        if (!findOutput(folder.cycle, s.output, panel.unit)) {
          throw io::ResultFolderError(csv + ": the column of " + s.output +
                                      " is not in a unit of " + displayUnit(panel.unit) +
                                      "'s kind, which " + what + " needs; nothing was drawn");
        }
      }
    }
  }
  // The maps of the field dumps: their node coordinates and the three fields.
  for (const io::FieldDumpFile& d : folder.fieldDumps) {
    const io::CsvTable t = io::readCsvTable(d.path, {"phi_deg", "y_mm"});
    for (const auto& [output, unit] : {std::pair<const char*, const char*>{"film_pressure", "MPa"},
                                       {"fill_fraction", ""},
                                       {"gap", "um"}}) {
      if (!findOutput(t, output, unit)) {
        throw io::ResultFolderError(d.path + ": no column " + output +
                                    "_<unit> (or not in a unit of its kind), which its field map "
                                    "needs; nothing was drawn");
      }
    }
  }
}

std::vector<std::string> writeResultPlots(const io::ResultFolder& folder) {
  checkResultPlotColumns(folder);
  const std::string gnuplot = findGnuplot();
  const io::CycleWindow window = io::selectLastCycle(folder.cycle);
  const fs::path plotDir = fs::path(folder.directory) / "plots";
  TempDir work;
  io::ResultFileSet files(plotDir.string());
  std::vector<std::string> names;
  const fs::path script = work.path / "plots.gp";
  {
    std::ofstream gp(script);
    gp << getScriptPreamble() << "set rmargin 40\n";
    for (const Figure& fig : describeFigures(folder)) {
      const std::string name = fig.name + ".png";
      std::ostringstream part;
      if (writeFigure(fig, folder, window, work.path, getStagedPath(files, name), part)) {
        stageFigure(files, name);
        names.push_back(name);
        gp << part.str();
      }
    }
    std::vector<double> angles;
    for (const auto& d : folder.fieldDumps) {
      if (angles.empty() || angles.back() != d.crankAngle_deg)
        angles.push_back(d.crankAngle_deg);
    }
    {
      const std::string name = "cycle_maps.png";
      std::ostringstream part;
      part << "set lmargin -1\nset rmargin -1\n";
      if (writeCycleMaps(folder, work.path, getStagedPath(files, name), part)) {
        stageFigure(files, name);
        names.push_back(name);
        gp << part.str();
      }
    }
    for (double a : angles) {
      std::vector<const io::FieldDumpFile*> sides;
      for (const auto& d : folder.fieldDumps) {
        if (d.crankAngle_deg == a)
          sides.push_back(&d);
      }
      const std::string name = "field_map_" + number(a) + "deg.png";
      const std::string staged = files.stage(name);
      names.push_back(name);
      gp << "set lmargin -1\nset rmargin -1\n";
      writeFieldMap(a, sides, folder.getSummaryValue("inputs.engine.name"), work.path, staged, gp);
    }
    const fs::path linerFilm = fs::path(folder.directory) / "liner_film.csv";
    if (fs::exists(linerFilm)) {
      const std::string name = "liner_film.png";
      const std::string staged = files.stage(name);
      names.push_back(name);
      gp << "set lmargin -1\nset rmargin -1\n";
      writeLinerFilmMap(linerFilm.string(), folder.getSummaryValue("inputs.engine.name"),
                        work.path, staged, gp);
    }
    if (!gp)
      throw std::runtime_error(script.string() + ": write failed");
  }
  // The folder holds this run's figures only.
  return drawAndCommit(gnuplot, script, work.path, files, names, "");
}

}  // namespace pistondyn::app
