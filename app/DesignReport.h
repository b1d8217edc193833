#pragma once
// The report pages of the design loop (DIR/report.html): one self-contained HTML file with
// inline SVG charts (SvgChart.h), no gnuplot and no network.
//   optimize   the optimum against the baseline (variables, objective, constraints and
//              which are active, secondary motion, friction, films), the convergence
//   fit        fitted values with standard errors or "not identifiable", correlations,
//              measured against fitted traces, residuals against the crank angle
//   propagate  5 / 50 / 95 % of the figures, bands of the curves

#include <string>

#include "pistondyn/design/Fit.h"
#include "pistondyn/design/Optimize.h"
#include "pistondyn/design/Propagate.h"

namespace pistondyn::app {

// A constraint is reported active when its figure lies within this share of its bound
// (relative; 1 %) at the optimum.
inline constexpr double kActiveConstraintShare = 0.01;

std::string makeOptimizeReport(const design::OptimizeSpec& spec,
                               const design::OptimizeOutcome& outcome);

std::string makeFitReport(const design::FitSpec& spec, const design::FitOutcome& outcome);

std::string makePropagateReport(const design::PropagateSpec& spec,
                                const design::PropagateOutcome& outcome);

// The shared page frame.
std::string beginReportPage(const std::string& title);
std::string endReportPage();
// A number to 6 significant digits ("" for NaN).
std::string displayNumber(double v);

// Secondary motion, friction and films of runs on common axes (the last cycle of each
// run folder; columns missing in a run are left out): one chart per quantity.
struct NamedRun {
  std::string label;
  std::string folder;
  bool dashed = false;
};
std::string makeRunComparisonCharts(const std::vector<NamedRun>& runs);

}  // namespace pistondyn::app
