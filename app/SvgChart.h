#pragma once
// Line charts as inline SVG for the design-loop report pages (DesignReport.cpp): no
// gnuplot, no script, no network; the page stays one self-contained file.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pistondyn::app {

struct ChartSeries {
  std::string label;
  std::vector<double> x, y;  // non-finite values break the line
  bool points = false;       // markers instead of a line
  bool dashed = false;
  int colour = 0;  // index into the palette
};

// A shaded band between two curves (the 5 % and 95 % bands of a propagation).
struct ChartBand {
  std::string label;
  std::vector<double> x, lower, upper;
  int colour = 0;
};

struct Chart {
  std::string title, xLabel, yLabel;
  std::vector<ChartSeries> series;
  std::vector<ChartBand> bands;
  std::optional<std::pair<double, double>> xRange;     // default: the data's
  std::vector<double> xMarks;                          // vertical guide lines (TDCs)
  std::vector<std::pair<double, std::string>> yMarks;  // horizontal guide lines, labelled
};

// The chart as an <svg> element `width` x `height` pixels; an empty chart says so.
std::string renderSvg(const Chart& chart, int width = 760, int height = 300);

// Round tick values covering [lo, hi], about `count` of them.
std::vector<double> niceTicks(double lo, double hi, int count = 6);

// Text for HTML (& < > " escaped).
std::string escapeHtml(const std::string& s);

}  // namespace pistondyn::app
