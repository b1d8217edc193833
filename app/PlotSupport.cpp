#include "PlotSupport.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "DisplayUnits.h"
#include "Gnuplot.h"
#include "pistondyn/io/ResultFolder.h"
#include "pistondyn/io/ResultWriters.h"

namespace pistondyn::app::plot {
namespace {

namespace fs = std::filesystem;

// The written unit if column `c` is output `name` in some unit ("" for no unit).
std::optional<std::string> unitOfOutput(const std::string& c, const std::string& name) {
  if (c == name)
    return std::string();
  if (c.rfind(name + "_", 0) == 0 && io::getColumnUnit(c) == c.substr(name.size() + 1))
    return c.substr(name.size() + 1);
  return std::nullopt;
}

}  // namespace

std::optional<double> conversionFactor(const std::string& from, const std::string& to) {
  return units::conversionFactor(from, to);
}

std::string displayUnit(const std::string& unit) {
  return unit.empty() ? "–" : units::getUnitText(unit);
}

std::string axisUnit(const std::string& name) {
  return units::getDisplayFormat(name).unit;
}

std::optional<Column> findOutput(const io::CsvTable& t, const std::string& name,
                                 const std::string& unit) {
  for (std::size_t j = 0; j < t.columns.size(); ++j) {
    const std::optional<std::string> written = unitOfOutput(t.columns[j], name);
    if (!written)
      continue;
    if (const auto f = conversionFactor(*written, unit))
      return Column{j, *f};
    spdlog::warn("plot: column {} is not in a unit convertible to '{}'; left out", t.columns[j],
                 unit);
    return std::nullopt;
  }
  return std::nullopt;
}

bool hasOutput(const io::CsvTable& t, const std::string& name) {
  return std::any_of(t.columns.begin(), t.columns.end(),
                     [&](const std::string& c) { return unitOfOutput(c, name).has_value(); });
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string quotedLines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) {
    if (line.empty())
      continue;
    const std::string q = quoted(line);
    text += (text.empty() ? "" : "\\n") + q.substr(1, q.size() - 2);
  }
  return "\"" + text + "\"";
}

std::string twoLines(const std::string& first, const std::string& second) {
  return quotedLines({first, second});
}

std::string number(double v) {
  return io::formatNumber(v);
}

const char* getCaseColour(std::size_t k) {
  static const char* const colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                        "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return colours[k % (sizeof colours / sizeof colours[0])];
}

double chooseColourTop(std::vector<double>& positive, double largest) {
  if (positive.empty())
    return largest;
  const std::size_t k = (positive.size() - 1) * 99 / 100;
  std::nth_element(positive.begin(), positive.begin() + static_cast<std::ptrdiff_t>(k),
                   positive.end());
  return std::min(largest, positive[k]);
}

void writeTdcMarks(std::ostream& gp) {
  gp << "set xrange [0:720]\nset xtics 0,90,720 nomirror\nset mxtics 3\n"
        "set x2range [0:720]\n"
        "set x2tics (\"firing TDC\" 0, \"gas-exchange TDC\" 360, \"firing TDC\" 720) "
        "nomirror scale 0\n"
        "unset arrow\n";
  for (int a : {0, 360, 720}) {
    gp << "set arrow from first " << a << ", graph 0 to first " << a
       << ", graph 1 nohead dt 2 lw 1.2 lc rgb 'gray30'\n";
  }
  gp << "set xlabel \"crank angle (°), 0° = firing TDC\"\n";
}

const char* getScriptPreamble() {
  return "set encoding utf8\nset grid xtics ytics lc rgb 'gray85' lt 1\n"
         "set key outside right top vertical Left reverse\nset lmargin 12\n";
}

std::string getStagedPath(const io::ResultFileSet& files, const std::string& name) {
  return (fs::path(files.getDirectory()) / ("." + name + ".partial")).string();
}

void stageFigure(io::ResultFileSet& files, const std::string& name) {
  if (files.stage(name) != getStagedPath(files, name))
    throw std::logic_error("stageFigure: the staged name differs from ResultFileSet's");
}

std::vector<std::string> drawAndCommit(const std::string& gnuplot, const fs::path& script,
                                       const fs::path& workDir, io::ResultFileSet& files,
                                       const std::vector<std::string>& names,
                                       const std::string& prefix) {
  spdlog::debug("plot: running {} {}", gnuplot, script.string());
  runGnuplot(gnuplot, script.string(), (workDir / "gnuplot.log").string());
  files.commit();
  const fs::path dir(files.getDirectory());
  const std::set<std::string> keep(names.begin(), names.end());
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (e.path().extension() == ".png" && n.rfind(prefix, 0) == 0 && !keep.count(n))
      fs::remove(e.path());
  }
  std::vector<std::string> paths;
  for (const auto& n : names)
    paths.push_back((dir / n).string());
  return paths;
}

TempDir::TempDir() {
  std::string tmpl = (fs::temp_directory_path() / "pistondyn_plot_XXXXXX").string();
  if (::mkdtemp(tmpl.data()) == nullptr)
    throw std::runtime_error("cannot create a temporary folder for gnuplot's data");
  path = tmpl;
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path, ec);
}

}  // namespace pistondyn::app::plot
