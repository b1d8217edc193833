#include "ComparisonPlots.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "Gnuplot.h"
#include "PlotSupport.h"
#include "pistondyn/io/ResultWriters.h"

namespace pistondyn::app {
namespace {

namespace fs = std::filesystem;
using namespace plot;

struct ComparedPanel {
  std::string output;                                 // output name without unit
  std::string quantity;                               // axis label without unit
  std::string unit;                                   // the axis' unit
  std::vector<std::pair<double, std::string>> lines;  // reference lines and their titles
};
struct ComparedFigure {
  std::string name;  // file stem
  std::string title;
  std::vector<ComparedPanel> panels;
  // Drawn only if some case has this output (the ideal guide's u_lat and tilt are its
  // constraints' zeros, not a secondary motion).
  std::string requiredOutput;
};

std::vector<ComparedFigure> describeFigures() {
  const std::vector<std::pair<double, std::string>> regimes = {
      {1.0, "h/σ = 1 and 3 (regime limits)"}, {3.0, ""}};
  const std::string film = axisUnit("min_film_thickness_thrust_um");
  const std::string ratio = axisUnit("min_h_over_sigma_thrust");
  return {
      {"comparison_side_force",
       "Side force on the liner (+ thrust)",
       {{"side_force", "side force", axisUnit("side_force_N"), {}}},
       ""},
      {"comparison_secondary_motion",
       "Secondary motion (+ towards thrust; tilt > 0: crown towards thrust)",
       {{"u_lat", "lateral displacement at the pin axis", axisUnit("u_lat_um"), {}},
        {"tilt", "tilt", axisUnit("tilt_mrad"), {}}},
       "u_lat_skirt_top"},
      {"comparison_friction_power",
       "Skirt friction power",
       {{"friction_power", "friction power", axisUnit("friction_power_W"), {}}},
       ""},
      {"comparison_film_thickness",
       "Minimum film thickness",
       {{"min_film_thickness_thrust", "minimum film, thrust side", film, {{0.0, ""}}},
        {"min_film_thickness_antithrust", "minimum film, anti-thrust side", film, {{0.0, ""}}}},
       ""},
      {"comparison_h_over_sigma",
       "Minimum h/σ",
       {{"min_h_over_sigma_thrust", "minimum h/σ, thrust side", ratio, regimes},
        {"min_h_over_sigma_antithrust", "minimum h/σ, anti-thrust side", ratio, regimes}},
       ""},
  };
}

// The legend of a case, in lines of at most kLegendWidth characters (gnuplot drops a key that
// does not fit beside the panels into the plot area, over the curves): the label's
// "key=value" items, a value that is a path shortened to its file name, wrapped at the items.
constexpr std::size_t kLegendWidth = 52;

std::vector<std::string> legendLines(const std::string& label) {
  const std::size_t colon = label.find(": ");
  if (colon == std::string::npos)
    return {label};
  std::vector<std::string> items;
  for (std::size_t at = colon + 2; at < label.size();) {
    std::size_t end = label.find(", ", at);
    if (end == std::string::npos)
      end = label.size();
    std::string item = label.substr(at, end - at);
    const std::size_t eq = item.find('='), slash = item.rfind('/');
    if (eq != std::string::npos && slash != std::string::npos && slash > eq)
      item = item.substr(0, eq + 1) + item.substr(slash + 1);
    items.push_back(item);
    at = end + 2;
  }
  std::vector<std::string> lines{label.substr(0, colon + 1)};
  for (const std::string& item : items) {
    const bool first = lines.size() == 1 && lines[0].size() == colon + 1;
    if (!first && lines.back().size() + 2 + item.size() > kLegendWidth)
      lines.push_back("  " + item);
    else
      lines.back() += (first ? " " : ", ") + item;
  }
  return lines;
}

// One figure: a data file per case (angle, then the figure's panels) and its script.
bool writeFigure(const ComparedFigure& fig, const std::vector<ComparisonCase>& cases,
                 const std::vector<io::CycleWindow>& windows, const fs::path& work,
                 const std::string& title, const std::string& pngPath, int rightMargin,
                 std::ostream& gp) {
  // Panels some case has, and per case the data file's column of each (0: absent).
  if (!fig.requiredOutput.empty() &&
      std::none_of(cases.begin(), cases.end(), [&](const ComparisonCase& c) {
        return hasOutput(c.folder.cycle, fig.requiredOutput);
      }))
    return false;
  std::vector<std::size_t> panels;
  for (std::size_t p = 0; p < fig.panels.size(); ++p) {
    for (const auto& c : cases) {
      if (hasOutput(c.folder.cycle, fig.panels[p].output)) {
        panels.push_back(p);
        break;
      }
    }
  }
  if (panels.empty())
    return false;
  std::vector<std::vector<int>> columnOf(cases.size(), std::vector<int>(fig.panels.size(), 0));
  std::vector<fs::path> data(cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const io::CsvTable& t = cases[k].folder.cycle;
    std::vector<Column> columns;
    for (std::size_t p : panels) {
      if (const auto c = findOutput(t, fig.panels[p].output, fig.panels[p].unit)) {
        columns.push_back(*c);
        columnOf[k][p] = static_cast<int>(columns.size()) + 1;
      }
    }
    data[k] = work / (fig.name + "_" + std::to_string(k) + ".dat");
    std::ofstream out(data[k]);
    const io::CycleWindow& w = windows[k];
    for (std::size_t i = 0; i < w.rows.size(); ++i) {
      out << number(w.angle_deg[i]);
      for (const Column& c : columns)
        out << ' ' << number(t.rows[w.rows[i]][c.index] * c.factor);
      out << '\n';
    }
    if (!out)
      throw std::runtime_error(data[k].string() + ": write failed");
  }
  std::vector<std::vector<std::string>> legend;
  for (const ComparisonCase& c : cases)
    legend.push_back(legendLines(c.label));
  const int height = 110 + 360 * static_cast<int>(panels.size());
  gp << "\nset terminal pngcairo size " << 900 + 8 * rightMargin << "," << height
     << " noenhanced font 'Sans,11'\n"
     << "set output " << quoted(pngPath) << "\n"
     << "set rmargin " << rightMargin << "\n"
     << "set multiplot layout " << panels.size() << ",1 title "
     << twoLines(fig.title + "   (last cycle of each case)", title) << " font 'Sans,13'\n";
  for (std::size_t p : panels) {
    const ComparedPanel& panel = fig.panels[p];
    writeTdcMarks(gp);
    gp << "set ylabel " << quoted(panel.quantity + " (" + displayUnit(panel.unit) + ")") << "\n"
       << "set yrange [*:*]\n";
    std::string plot;
    auto add = [&](const std::string& item) {
      plot += (plot.empty() ? "plot " : ", \\\n  ") + item;
    };
    for (std::size_t k = 0; k < cases.size(); ++k) {
      if (columnOf[k][p] == 0)
        continue;
      add(quoted(data[k].string()) + " using 1:" + std::to_string(columnOf[k][p]) +
          " with lines lw 2 dt " + std::to_string(1 + static_cast<int>(k / 10)) + " lc rgb '" +
          getCaseColour(k) + "' title " + quoted(std::as_const(legend[k]).front()));
      // The legend's further lines as text-only key entries (a title with line breaks would
      // overlap the next entry).
      for (std::size_t l = 1; l < legend[k].size(); ++l)
        add("keyentry with lines lt nodraw title " + quoted(std::as_const(legend[k])[l]));
    }
    for (const auto& [value, lineTitle] : panel.lines) {
      add(number(value) + " with lines dt 3 lw 1.2 lc rgb 'gray40' " +
          (lineTitle.empty() ? std::string("notitle") : "title " + quoted(lineTitle)));
    }
    gp << plot << "\n";
  }
  gp << "unset multiplot\nunset output\n";
  return true;
}

}  // namespace

std::vector<std::string> writeComparisonPlots(const std::vector<ComparisonCase>& cases,
                                              const std::string& dir, const std::string& title) {
  if (cases.empty())
    throw std::runtime_error("no case to compare (no case finished)");
  if (cases.size() > kMaxComparedCases) {
    throw std::runtime_error(std::to_string(cases.size()) + " cases: more than the " +
                             std::to_string(kMaxComparedCases) + " curves a figure can tell apart");
  }
  const std::string gnuplot = findGnuplot();
  std::vector<io::CycleWindow> windows;
  std::size_t longest = 0;
  for (const auto& c : cases) {
    windows.push_back(io::selectLastCycle(c.folder.cycle));
    for (const std::string& line : legendLines(c.label))
      longest = std::max(longest, line.size());
  }
  // Room for the legend beside the panels (characters).
  const int rightMargin =
      static_cast<int>(std::min<std::size_t>(90, std::max<std::size_t>(36, longest + 8)));
  const fs::path plotDir = fs::path(dir) / "plots";
  TempDir work;
  io::ResultFileSet files(plotDir.string());
  std::vector<std::string> names;
  const fs::path script = work.path / "comparison.gp";
  {
    std::ofstream gp(script);
    gp << getScriptPreamble();
    for (const ComparedFigure& fig : describeFigures()) {
      const std::string name = fig.name + ".png";
      std::ostringstream part;
      if (writeFigure(fig, cases, windows, work.path, title, getStagedPath(files, name),
                      rightMargin, part)) {
        stageFigure(files, name);
        names.push_back(name);
        gp << part.str();
      }
    }
    if (!gp)
      throw std::runtime_error(script.string() + ": write failed");
  }
  // The folder holds this comparison's figures only (a run's own figures are in the case
  // folders, so every comparison_*.png here is ours).
  return drawAndCommit(gnuplot, script, work.path, files, names, "comparison_");
}

}  // namespace pistondyn::app
