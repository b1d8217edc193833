#include "DesignReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "SvgChart.h"
#include "pistondyn/design/Figures.h"
#include "pistondyn/io/ResultFolder.h"
#include "pistondyn/io/Version.h"

namespace pistondyn::app {
namespace {

std::string fmt(double v) {
  return displayNumber(v);
}

// The quantities a design is judged by, as cycle.csv names them.
struct Quantity {
  const char* title;
  std::vector<const char*> columns;
  const char* axis;
};

const std::vector<Quantity>& comparedQuantities() {
  static const std::vector<Quantity> q = {
      {"lateral displacement at the pin axis", {"u_lat_um"}, "u_lat [µm]"},
      {"tilt", {"tilt_mrad"}, "tilt [mrad]"},
      {"friction power", {"friction_power_W"}, "friction power [W]"},
      {"minimum film thickness, thrust side", {"min_film_thickness_thrust_um"}, "h_min [µm]"},
      {"minimum film thickness, anti-thrust side",
       {"min_film_thickness_antithrust_um"},
       "h_min [µm]"},
      {"side force", {"side_force_N"}, "side force [N]"},
  };
  return q;
}

}  // namespace

std::string displayNumber(double v) {
  if (!std::isfinite(v))
    return "";
  char t[32];
  std::snprintf(t, sizeof t, "%.6g", v);
  return t;
}

std::string beginReportPage(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
         escapeHtml(title) +
         "</title>\n<style>body{font-family:sans-serif;max-width:1000px;margin:1em auto;color:#222}"
         "table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #ccc;padding:2px "
         "8px;text-align:right}th{background:#f4f4f4}td.l,th.l{text-align:left}.note{color:#555;"
         "font-size:90%}.warn{color:#a00}</style></head><body>\n<h1>" +
         escapeHtml(title) + "</h1>\n";
}

std::string endReportPage() {
  return "<p class=\"note\">pistondyn " + escapeHtml(io::getVersion()) +
         "; crank angle 0&deg; = firing TDC.</p>\n</body></html>\n";
}

std::string makeRunComparisonCharts(const std::vector<NamedRun>& runs) {
  std::vector<io::ResultFolder> folders;
  std::vector<io::CycleWindow> windows;
  std::ostringstream html;
  for (const auto& r : runs) {
    try {
      folders.push_back(io::readResultFolder(r.folder));
      windows.push_back(io::selectLastCycle(folders.back().cycle));
    } catch (const std::exception& e) {
      html << "<p class=\"warn\">" << escapeHtml(r.label) << ": cannot read "
           << escapeHtml(r.folder) << ": " << escapeHtml(e.what()) << "</p>\n";
      return html.str();
    }
  }
  for (const auto& q : comparedQuantities()) {
    Chart chart;
    chart.title = q.title;
    chart.xLabel = "crank angle [°]";
    chart.yLabel = q.axis;
    chart.xRange = std::make_pair(0.0, 720.0);
    chart.xMarks = {360.0};
    for (std::size_t k = 0; k < runs.size(); ++k) {
      for (const char* column : q.columns) {
        const auto& table = folders[k].cycle;
        if (!table.hasColumn(column))
          continue;
        const std::size_t c = table.columnIndex(column);
        ChartSeries s;
        s.label = runs[k].label;
        s.colour = static_cast<int>(k);
        s.dashed = runs[k].dashed;
        s.x = windows[k].angle_deg;
        for (const std::size_t row : windows[k].rows)
          s.y.push_back(table.rows[row][c]);
        chart.series.push_back(std::move(s));
      }
    }
    if (!chart.series.empty())
      html << renderSvg(chart) << "\n";
  }
  return html.str();
}

std::string makeOptimizeReport(const design::OptimizeSpec& spec, const design::OptimizeOutcome& o) {
  const design::DesignStudy& s = spec.study;
  std::ostringstream html;
  html << beginReportPage("pistondyn optimize: " + (s.name.empty() ? s.deckPath : s.name));
  html << "<p>Study <code>" << escapeHtml(s.deckPath) << "</code>, base deck <code>"
       << escapeHtml(s.baseDeckPath) << "</code>; " << o.history.size()
       << " designs evaluated (history.csv); objective";
  for (std::size_t i = 0; i < spec.objective.size(); ++i)
    html << (i ? " +" : "") << " " << fmt(spec.objective[i].weight) << " &times; "
         << escapeHtml(spec.objective[i].figure);
  html << "; local method " << escapeHtml(spec.method.local) << " from the best "
       << spec.method.starts << " of " << spec.method.doeSamples << " Latin-hypercube points (seed "
       << spec.method.seed << ")"
       << (spec.method.global == "isres" ? ", after a global ISRES stage" : "") << ".</p>\n";
  const design::DesignPoint& base = o.history.front();
  if (!o.optimum) {
    html << "<p class=\"warn\">No feasible design was found: every evaluation violated a "
            "constraint or failed. The history lists each with its violation.</p>\n";
  }
  const design::DesignPoint* best = o.optimum ? &o.history[*o.optimum] : nullptr;
  // Variables.
  html << "<h2>Design variables</h2>\n<table><tr><th class=\"l\">variable</th><th>lower</th>"
          "<th>upper</th><th>baseline</th><th>optimum</th></tr>\n";
  for (std::size_t i = 0; i < s.variables.size(); ++i) {
    const auto& v = s.variables[i];
    html << "<tr><td class=\"l\">" << escapeHtml(v.key) << "</td><td>" << fmt(v.lower)
         << "</td><td>" << fmt(v.upper) << "</td><td>"
         << (v.baseline ? fmt(*v.baseline) : "deck's table") << "</td><td>"
         << (best ? fmt(best->x[i]) : "") << "</td></tr>\n";
  }
  html << "</table>\n";
  // Objective and constraints.
  html << "<h2>Objective and constraints</h2>\n<table><tr><th class=\"l\">figure</th><th>bound</th>"
          "<th>baseline</th><th>optimum</th><th>active at the optimum</th></tr>\n";
  auto figure = [](const design::DesignPoint* p, const std::string& name) {
    if (p == nullptr || !p->result.ok)
      return std::nan("");
    return design::RunFigures(p->result.summaryJson).get(name).value_or(std::nan(""));
  };
  html << "<tr><td class=\"l\">objective</td><td>minimised</td><td>"
       << (base.objective ? fmt(*base.objective) : "failed") << "</td><td>"
       << (best ? fmt(*best->objective) : "") << "</td><td></td></tr>\n";
  for (const auto& t : spec.objective) {
    html << "<tr><td class=\"l\">" << escapeHtml(t.figure) << " (weight " << fmt(t.weight)
         << ")</td><td></td><td>" << fmt(figure(&base, t.figure)) << "</td><td>"
         << fmt(figure(best, t.figure)) << "</td><td></td></tr>\n";
  }
  for (const auto& c : spec.constraints) {
    const double at = figure(best, c.figure);
    std::string bound, active;
    for (const auto& [isMin, b] : {std::pair{true, c.minimum}, std::pair{false, c.maximum}}) {
      if (!b)
        continue;
      bound += (bound.empty() ? "" : ", ") + std::string(isMin ? "&ge; " : "&le; ") + fmt(*b);
      const double scale = *b != 0.0 ? std::fabs(*b) : 1.0;
      if (std::isfinite(at) && std::fabs(at - *b) / scale <= kActiveConstraintShare)
        active = "active";
    }
    html << "<tr><td class=\"l\">" << escapeHtml(c.figure) << "</td><td>" << bound << "</td><td>"
         << fmt(figure(&base, c.figure)) << "</td><td>" << fmt(at) << "</td><td>" << active
         << "</td></tr>\n";
  }
  html << "</table>\n<p class=\"note\">A constraint is active when its figure lies within "
       << fmt(100 * kActiveConstraintShare)
       << " % of its bound at the optimum. Feasible: every constraint met within "
       << fmt(spec.method.constraintTolerance) << " of its bound (relative).</p>\n";
  // Convergence.
  Chart conv;
  conv.title = "convergence";
  conv.xLabel = "evaluation (history.csv number)";
  conv.yLabel = "objective";
  std::vector<std::string> stages;
  for (const auto& p : o.history) {
    if (p.stage != "baseline" && std::find(stages.begin(), stages.end(), p.stage) == stages.end())
      stages.push_back(p.stage);
  }
  for (std::size_t k = 0; k < stages.size(); ++k) {
    ChartSeries feasible;
    feasible.label = stages[k];
    feasible.points = true;
    feasible.colour = static_cast<int>(k) + 1;
    for (std::size_t i = 0; i < o.history.size(); ++i) {
      const auto& p = o.history[i];
      if (p.stage == stages[k] && p.feasible) {
        feasible.x.push_back(static_cast<double>(i + 1));
        feasible.y.push_back(*p.objective);
      }
    }
    conv.series.push_back(std::move(feasible));
  }
  ChartSeries bestSoFar;
  bestSoFar.label = "best feasible so far";
  double running = std::nan("");
  for (std::size_t i = 1; i < o.history.size(); ++i) {
    const auto& p = o.history[i];
    if (p.feasible && (!std::isfinite(running) || *p.objective < running))
      running = *p.objective;
    bestSoFar.x.push_back(static_cast<double>(i + 1));
    bestSoFar.y.push_back(running);
  }
  conv.series.push_back(std::move(bestSoFar));
  if (base.objective)
    conv.yMarks.emplace_back(*base.objective, "baseline");
  html << "<h2>Convergence</h2>\n<p class=\"note\">Feasible designs only (infeasible and "
          "failed ones are in history.csv).</p>\n"
       << renderSvg(conv) << "\n";
  // Searches.
  html << "<h2>Searches</h2>\n<table><tr><th class=\"l\">stage</th><th>NLopt evaluations</th>"
          "<th class=\"l\">stopped</th><th>best feasible objective</th></tr>\n";
  for (const auto& r : o.searches) {
    html << "<tr><td class=\"l\">" << escapeHtml(r.stage) << "</td><td>" << r.evaluations
         << "</td><td class=\"l\">" << escapeHtml(r.stopReason) << "</td><td>"
         << (r.best ? fmt(*o.history[*r.best].objective) : "none") << "</td></tr>\n";
  }
  html << "</table>\n";
  // Baseline against optimum.
  if (best != nullptr && base.result.ok) {
    html << "<h2>Baseline against optimum (last cycle)</h2>\n"
         << makeRunComparisonCharts(
                {{"baseline", base.result.folder, true}, {"optimum", best->result.folder, false}});
  }
  html << endReportPage();
  return html.str();
}

std::string makeFitReport(const design::FitSpec& spec, const design::FitOutcome& o) {
  const design::DesignStudy& s = spec.study;
  std::ostringstream html;
  html << beginReportPage("pistondyn fit: " + (s.name.empty() ? s.deckPath : s.name));
  html << "<p>Study <code>" << escapeHtml(s.deckPath) << "</code>, base deck <code>"
       << escapeHtml(s.baseDeckPath) << "</code>; " << o.points << " measured points in "
       << spec.traces.size() << " trace(s), " << s.variables.size()
       << " parameters; bounded Levenberg-Marquardt, " << escapeHtml(o.stopReason) << " after "
       << o.iterations.size() - 1 << " steps (history.csv). Sum of squares " << fmt(o.sumOfSquares)
       << ", residual standard deviation " << fmt(o.residualStd)
       << " (weighted units of the traces), Jacobian rank " << o.rank << " of "
       << s.variables.size() << ".</p>\n";
  html << "<h2>Fitted parameters</h2>\n<table><tr><th class=\"l\">parameter</th><th>lower</th>"
          "<th>upper</th><th>start</th><th>fitted</th><th>standard error</th><th class=\"l\">"
          "note</th></tr>\n";
  for (const auto& p : o.parameters) {
    const auto& v = *std::find_if(s.variables.begin(), s.variables.end(),
                                  [&](const design::DesignVariable& x) { return x.key == p.key; });
    html << "<tr><td class=\"l\">" << escapeHtml(p.key) << "</td><td>" << fmt(v.lower)
         << "</td><td>" << fmt(v.upper) << "</td><td>" << fmt(p.start) << "</td><td>"
         << (p.identifiable ? fmt(p.value) : "&mdash;") << "</td><td>"
         << (p.standardError ? fmt(*p.standardError) : "&mdash;") << "</td><td class=\"l\">"
         << escapeHtml(p.note) << (p.atBound ? " (at a bound)" : "") << "</td></tr>\n";
  }
  html << "</table>\n<p class=\"note\">Standard errors from the Jacobian at the optimum "
          "(central differences): covariance s&sup2; (J&#8242;J)<sup>&minus;1</sup>, s&sup2; = "
          "sum of squares / (points &minus; parameters). A parameter the traces cannot determine "
          "is reported without a value.</p>\n";
  html << "<h2>Correlation</h2>\n<table><tr><th></th>";
  for (const auto& p : o.parameters)
    html << "<th>" << escapeHtml(p.key) << "</th>";
  html << "</tr>\n";
  for (std::size_t i = 0; i < o.parameters.size(); ++i) {
    html << "<tr><th class=\"l\">" << escapeHtml(o.parameters[i].key) << "</th>";
    for (std::size_t j = 0; j < o.parameters.size(); ++j)
      html << "<td>" << (std::isfinite(o.correlation[i][j]) ? fmt(o.correlation[i][j]) : "&mdash;")
           << "</td>";
    html << "</tr>\n";
  }
  html << "</table>\n";
  for (std::size_t t = 0; t < spec.traces.size(); ++t) {
    const auto& tr = spec.traces[t];
    Chart fit;
    fit.title = "measured and fitted: " + tr.getLabel();
    fit.xLabel = "crank angle [°]";
    fit.yLabel = tr.getLabel();
    fit.xRange = std::make_pair(0.0, 720.0);
    fit.xMarks = {360.0};
    ChartSeries measured{"measured", tr.angle_deg, tr.value, true, false, 0};
    fit.series.push_back(measured);
    if (o.model.size() > t)
      fit.series.push_back({"fitted", tr.angle_deg, o.model[t], false, false, 1});
    Chart res;
    res.title = "residual (fitted - measured): " + tr.getLabel();
    res.xLabel = "crank angle [°]";
    res.yLabel = tr.getLabel();
    res.xRange = std::make_pair(0.0, 720.0);
    res.xMarks = {360.0};
    res.yMarks = {{0.0, ""}};
    if (o.model.size() > t) {
      std::vector<double> r;
      for (std::size_t i = 0; i < tr.value.size(); ++i)
        r.push_back(o.model[t][i] - tr.value[i]);
      res.series.push_back({"residual", tr.angle_deg, r, true, false, 2});
    }
    html << "<h2>Trace " << t + 1 << ": " << escapeHtml(tr.getLabel()) << "</h2>\n<p>"
         << escapeHtml(tr.file) << ", weight " << fmt(tr.weight) << ", " << tr.value.size()
         << " points";
    for (const auto& [from, to] : tr.windows_deg)
      html << " [" << fmt(from) << ", " << fmt(to) << "]&deg;";
    html << "</p>\n" << renderSvg(fit) << renderSvg(res, 760, 220);
  }
  Chart conv;
  conv.title = "sum of squares";
  conv.xLabel = "step (history.csv)";
  conv.yLabel = "sum of squares";
  ChartSeries tried{"tried", {}, {}, true, false, 3};
  ChartSeries accepted{"accepted", {}, {}, false, false, 0};
  for (const auto& it : o.iterations) {
    tried.x.push_back(it.number);
    tried.y.push_back(it.sumOfSquares);
    if (it.accepted) {
      accepted.x.push_back(it.number);
      accepted.y.push_back(it.sumOfSquares);
    }
  }
  conv.series = {tried, accepted};
  html << "<h2>Convergence</h2>\n" << renderSvg(conv, 760, 240);
  html << endReportPage();
  return html.str();
}

std::string makePropagateReport(const design::PropagateSpec& spec,
                                const design::PropagateOutcome& o) {
  const design::DesignStudy& s = spec.study;
  std::ostringstream html;
  html << beginReportPage("pistondyn propagate: " + (s.name.empty() ? s.deckPath : s.name));
  html << "<p>Study <code>" << escapeHtml(s.deckPath) << "</code>, base deck <code>"
       << escapeHtml(s.baseDeckPath) << "</code>: " << o.samples.size()
       << " Latin-hypercube samples (seed " << spec.seed << ") uniform over " << s.variables.size()
       << " inputs; " << o.samples.size() - static_cast<std::size_t>(o.failed) << " ran, "
       << o.failed << " failed (samples.csv).</p>\n";
  html << "<h2>Figures</h2>\n<table><tr><th class=\"l\">figure</th><th>5 %</th><th>50 %</th>"
          "<th>95 %</th><th>mean</th><th>standard deviation</th><th>samples</th><th>baseline"
          "</th></tr>\n";
  std::optional<design::RunFigures> base;
  if (o.baseline.ok)
    base.emplace(o.baseline.summaryJson);
  for (const auto& f : spec.figures) {
    const design::Band& b = o.figureBands.at(f);
    html << "<tr><td class=\"l\">" << escapeHtml(f) << "</td><td>" << fmt(b.p05) << "</td><td>"
         << fmt(b.p50) << "</td><td>" << fmt(b.p95) << "</td><td>" << fmt(b.mean) << "</td><td>"
         << fmt(b.std) << "</td><td>" << b.count << "</td><td>"
         << (base ? fmt(base->get(f).value_or(std::nan(""))) : "") << "</td></tr>\n";
  }
  html << "</table>\n<p class=\"note\">Percentiles of the samples that ran, linear between order "
          "statistics.</p>\n";
  for (const auto& c : spec.curves) {
    Chart chart;
    chart.title = c + ": 5 - 95 % band, median, baseline";
    chart.xLabel = "crank angle [°]";
    chart.yLabel = c;
    chart.xRange = std::make_pair(0.0, 720.0);
    chart.xMarks = {360.0};
    const auto& bands = o.curveBands.at(c);
    ChartBand band{"5 - 95 %", o.angle_deg, {}, {}, 0};
    ChartSeries median{"median", o.angle_deg, {}, false, false, 0};
    for (const auto& b : bands) {
      band.lower.push_back(b.p05);
      band.upper.push_back(b.p95);
      median.y.push_back(b.p50);
    }
    chart.bands.push_back(band);
    chart.series.push_back(median);
    const auto it = o.baselineCurves.find(c);
    if (it != o.baselineCurves.end())
      chart.series.push_back({"baseline", o.angle_deg, it->second, false, true, 1});
    html << renderSvg(chart) << "\n";
  }
  html << "<h2>Inputs</h2>\n<table><tr><th class=\"l\">input</th><th>lower</th><th>upper</th>"
          "<th>baseline</th><th class=\"l\">from</th></tr>\n";
  for (const auto& v : s.variables) {
    const bool est =
        std::find(spec.estKeys.begin(), spec.estKeys.end(), v.key) != spec.estKeys.end();
    html << "<tr><td class=\"l\">" << escapeHtml(v.key) << "</td><td>" << fmt(v.lower)
         << "</td><td>" << fmt(v.upper) << "</td><td>" << (v.baseline ? fmt(*v.baseline) : "")
         << "</td><td class=\"l\">" << (est ? "EST in the base deck" : "inputs") << "</td></tr>\n";
  }
  html << "</table>\n";
  if (!spec.estSkipped.empty()) {
    html << "<p class=\"note\">Marked EST but 0 in the base deck, so not varied by a share of "
            "their value (give them a range under inputs):";
    for (const auto& k : spec.estSkipped)
      html << " <code>" << escapeHtml(k) << "</code>";
    html << "</p>\n";
  }
  html << endReportPage();
  return html.str();
}

}  // namespace pistondyn::app
