#include "SvgChart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace pistondyn::app {
namespace {

const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                          "#9467bd", "#8c564b", "#e377c2", "#17becf"};

const char* colour(int i) {
  return kPalette[static_cast<std::size_t>(std::abs(i)) % (sizeof kPalette / sizeof *kPalette)];
}

std::string num(double v) {
  char t[32];
  std::snprintf(t, sizeof t, "%.2f", v);
  return t;
}

std::string label(double v) {
  char t[32];
  std::snprintf(t, sizeof t, "%.6g", std::fabs(v) < 1e-12 ? 0.0 : v);
  return t;
}

}  // namespace

std::string escapeHtml(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::vector<double> niceTicks(double lo, double hi, int count) {
  if (!(std::isfinite(lo) && std::isfinite(hi)) || hi <= lo)
    return {lo};
  const double raw = (hi - lo) / std::max(1, count);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (const double f : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    step = f * magnitude;
    if (step >= raw)
      break;
  }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step)
    ticks.push_back(t);
  return ticks;
}

std::string renderSvg(const Chart& chart, int width, int height) {
  // Data extent.
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  auto takeX = [&](double v) {
    if (std::isfinite(v)) {
      x0 = std::min(x0, v);
      x1 = std::max(x1, v);
    }
  };
  auto takeY = [&](double v) {
    if (std::isfinite(v)) {
      y0 = std::min(y0, v);
      y1 = std::max(y1, v);
    }
  };
  for (const auto& s : chart.series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (std::isfinite(s.y[i])) {
        takeX(s.x[i]);
        takeY(s.y[i]);
      }
    }
  }
  for (const auto& b : chart.bands) {
    for (std::size_t i = 0; i < b.x.size(); ++i) {
      takeX(b.x[i]);
      takeY(b.lower[i]);
      takeY(b.upper[i]);
    }
  }
  for (const auto& m : chart.yMarks)
    takeY(m.first);
  if (chart.xRange) {
    x0 = chart.xRange->first;
    x1 = chart.xRange->second;
  }
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  svg << "<text x=\"" << width / 2 << "\" y=\"14\" text-anchor=\"middle\" font-size=\"13\">"
      << escapeHtml(chart.title) << "</text>\n";
  if (!(x0 < x1) && std::isfinite(x0)) {
    x0 -= 0.5;
    x1 += 0.5;
  }
  if (!(y0 < y1) && std::isfinite(y0)) {
    const double pad = y0 == 0.0 ? 1.0 : 0.05 * std::fabs(y0);
    y0 -= pad;
    y1 += pad;
  }
  if (!std::isfinite(x0) || !std::isfinite(y0)) {
    svg << "<text x=\"" << width / 2 << "\" y=\"" << height / 2
        << "\" text-anchor=\"middle\">no data</text>\n</svg>\n";
    return svg.str();
  }
  const double pad = 0.04 * (y1 - y0);
  y0 -= pad;
  y1 += pad;
  const double left = 70, right = width - 160.0, top = 24, bottom = height - 38.0;
  auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * (right - left); };
  auto py = [&](double y) { return bottom - (y - y0) / (y1 - y0) * (bottom - top); };
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << right - left << "\" height=\""
      << bottom - top << "\" fill=\"none\" stroke=\"#888\"/>\n";
  for (const double t : niceTicks(x0, x1, 8)) {
    svg << "<line x1=\"" << num(px(t)) << "\" y1=\"" << bottom << "\" x2=\"" << num(px(t))
        << "\" y2=\"" << top << "\" stroke=\"#eee\"/>"
        << "<text x=\"" << num(px(t)) << "\" y=\"" << bottom + 14 << "\" text-anchor=\"middle\">"
        << label(t) << "</text>\n";
  }
  for (const double t : niceTicks(y0, y1, 6)) {
    svg << "<line x1=\"" << left << "\" y1=\"" << num(py(t)) << "\" x2=\"" << right << "\" y2=\""
        << num(py(t)) << "\" stroke=\"#eee\"/>"
        << "<text x=\"" << left - 4 << "\" y=\"" << num(py(t) + 4) << "\" text-anchor=\"end\">"
        << label(t) << "</text>\n";
  }
  svg << "<text x=\"" << (left + right) / 2 << "\" y=\"" << height - 6
      << "\" text-anchor=\"middle\">" << escapeHtml(chart.xLabel) << "</text>\n";
  svg << "<text x=\"14\" y=\"" << (top + bottom) / 2
      << "\" text-anchor=\"middle\" transform=\"rotate(-90 14 " << (top + bottom) / 2 << ")\">"
      << escapeHtml(chart.yLabel) << "</text>\n";
  for (const double m : chart.xMarks) {
    if (m >= x0 && m <= x1)
      svg << "<line x1=\"" << num(px(m)) << "\" y1=\"" << top << "\" x2=\"" << num(px(m))
          << "\" y2=\"" << bottom << "\" stroke=\"#999\" stroke-dasharray=\"2,3\"/>\n";
  }
  for (const auto& [y, text] : chart.yMarks) {
    svg << "<line x1=\"" << left << "\" y1=\"" << num(py(y)) << "\" x2=\"" << right << "\" y2=\""
        << num(py(y)) << "\" stroke=\"#555\" stroke-dasharray=\"6,3\"/><text x=\"" << right - 4
        << "\" y=\"" << num(py(y) - 3) << "\" text-anchor=\"end\" fill=\"#555\">"
        << escapeHtml(text) << "</text>\n";
  }
  int legend = 0;
  auto legendEntry = [&](const std::string& text, const char* c,
                         int kind) {  // 0 line, 1 box, 2 dot
    const double y = top + 6 + 16.0 * legend++;
    if (kind == 2)
      svg << "<circle cx=\"" << right + 17 << "\" cy=\"" << y << "\" r=\"3\" fill=\"" << c
          << "\"/>";
    else if (kind == 1)
      svg << "<rect x=\"" << right + 10 << "\" y=\"" << y - 5
          << "\" width=\"14\" height=\"10\" fill=\"" << c << "\" fill-opacity=\"0.3\"/>";
    else
      svg << "<line x1=\"" << right + 10 << "\" y1=\"" << y << "\" x2=\"" << right + 24
          << "\" y2=\"" << y << "\" stroke=\"" << c << "\" stroke-width=\"2\"/>";
    svg << "<text x=\"" << right + 28 << "\" y=\"" << y + 4 << "\">" << escapeHtml(text)
        << "</text>\n";
  };
  for (const auto& b : chart.bands) {
    std::ostringstream path;
    bool first = true;
    for (std::size_t i = 0; i < b.x.size(); ++i) {
      path << (first ? "M" : "L") << num(px(b.x[i])) << ',' << num(py(b.upper[i])) << ' ';
      first = false;
    }
    for (std::size_t i = b.x.size(); i-- > 0;)
      path << 'L' << num(px(b.x[i])) << ',' << num(py(b.lower[i])) << ' ';
    svg << "<path d=\"" << path.str() << "Z\" fill=\"" << colour(b.colour)
        << "\" fill-opacity=\"0.25\" stroke=\"none\"/>\n";
    legendEntry(b.label, colour(b.colour), 1);
  }
  for (const auto& s : chart.series) {
    const char* c = colour(s.colour);
    if (s.points) {
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
        if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
          svg << "<circle cx=\"" << num(px(s.x[i])) << "\" cy=\"" << num(py(s.y[i]))
              << "\" r=\"2.5\" fill=\"" << c << "\"/>";
      }
      svg << "\n";
    } else {
      std::ostringstream path;
      bool pen = false;
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
        if (!std::isfinite(s.y[i]) || !std::isfinite(s.x[i])) {
          pen = false;
          continue;
        }
        path << (pen ? "L" : "M") << num(px(s.x[i])) << ',' << num(py(s.y[i])) << ' ';
        pen = true;
      }
      svg << "<path d=\"" << path.str() << "\" fill=\"none\" stroke=\"" << c
          << "\" stroke-width=\"1.5\"" << (s.dashed ? " stroke-dasharray=\"5,3\"" : "") << "/>\n";
    }
    if (!s.label.empty())
      legendEntry(s.label, c, s.points ? 2 : 0);
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace pistondyn::app
