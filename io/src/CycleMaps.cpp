#include "CycleMaps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <stdexcept>

#include "pistondyn/common/CrankAngle.h"
#include "pistondyn/common/Validation.h"

namespace pistondyn::io::detail {
namespace {

// Which fields are mapped and how a row of nodes is reduced over the arc: the extreme that
// matters for each (the thinnest film, the highest pressure) and the mean for the fill.
struct MapRule {
  const char* field;
  const char* reduction;  // also the column's infix
};
const MapRule kMapRules[] = {{"gap", "min"},           {"h_over_sigma", "min"},
                             {"film_pressure", "max"}, {"fill_fraction", "mean"},
                             {"contact_pressure", "max"}, {"wear_depth_rate", "max"}};
const char* const kFramedFields[] = {"film_pressure", "fill_fraction", "contact_pressure"};

// 4 significant digits; "0" for zero of either sign.
std::string fieldText(double v) {
  if (v == 0.0)
    return "0";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

std::string coordinateText(double v) {
  const double rounded = std::round(v * 1e6) / 1e6;
  return common::formatNumber(rounded == 0.0 ? 0.0 : rounded);
}

// Node indices 0, s, 2s, ... and the last, s the smallest stride leaving at most `most`.
std::vector<int> decimate(int n, int most) {
  const int stride = std::max(1, (n + most - 2) / std::max(1, most - 1));
  std::vector<int> kept;
  for (int i = 0; i < n; i += stride)
    kept.push_back(i);
  if (kept.back() != n - 1)
    kept.push_back(n - 1);
  return kept;
}

void writeLine(std::ostream& out, const std::vector<std::string>& cells) {
  for (std::size_t c = 0; c < cells.size(); ++c)
    out << (c ? "," : "") << cells[c];
  out << '\n';
}

// Writes `rows` (blocks of `blockSize` values, each a line of `width` values whose first is
// the crank angle) ordered by angle: the last cycle may start anywhere in [0, 720).
void writeBlocksByAngle(std::ostream& out, const std::vector<double>& rows, std::size_t width,
                        std::size_t blockLines, std::size_t coordinates) {
  const std::size_t blockSize = width * blockLines;
  std::vector<std::size_t> order(rows.size() / blockSize);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return rows[a * blockSize] < rows[b * blockSize];
  });
  std::vector<std::string> cells(width);
  for (const std::size_t b : order) {
    for (std::size_t line = 0; line < blockLines; ++line) {
      const double* v = &rows[b * blockSize + line * width];
      for (std::size_t c = 0; c < width; ++c)
        cells[c] = c < coordinates ? coordinateText(v[c]) : fieldText(v[c]);
      writeLine(out, cells);
    }
  }
}
}  // namespace

std::string CycleMapSink::mapFileName(const std::string& region) {
  return "cycle_map_" + region + ".csv";
}

std::string CycleMapSink::frameFileName(const std::string& region) {
  return "field_frames_" + region + ".csv";
}

CycleMapSink::CycleMapSink(const plugin::NodalFieldSource& source, long rowsPerCycle,
                           std::vector<std::string> commentLines, ResultFileSet& files)
    : source_(source),
      files_(files),
      perCycle_(rowsPerCycle),
      frameStride_(std::max(1L, std::lround(kFrameStep_deg * rowsPerCycle / 720.0))),
      comments_(std::move(commentLines)) {}

void CycleMapSink::beginRun(const std::vector<std::string>&) {
  const std::vector<plugin::NodalFieldDeclaration> declared = source_.getNodalFieldDeclarations();
  auto find = [&](const std::string& name) {
    for (std::size_t k = 0; k < declared.size(); ++k) {
      if (declared[k].name == name)
        return static_cast<int>(k);
    }
    return -1;
  };
  mapped_.clear();
  for (const MapRule& rule : kMapRules) {
    const int k = find(rule.field);
    if (k < 0)
      continue;
    const std::string& unit = declared[static_cast<std::size_t>(k)].unit;
    const std::string r = rule.reduction;
    mapped_.push_back({k, r == "min" ? Reduction::Min : r == "max" ? Reduction::Max : Reduction::Mean,
                       std::string(rule.field) + "_" + r + (unit == "1" ? "" : "_" + unit)});
  }
  framed_.clear();
  for (const char* name : kFramedFields) {
    if (const int k = find(name); k >= 0)
      framed_.emplace_back(k, declared[static_cast<std::size_t>(k)].getColumnName());
  }
  regions_.clear();
  if (mapped_.empty())
    return;
  for (const plugin::NodalFieldRegion& nodes : source_.getNodalFieldRegions()) {
    Region r;
    r.nodes = nodes;
    // Trapezoidal weights along phi, row by row (a row may be clustered).
    r.arcWeights = Eigen::MatrixXd::Zero(nodes.nPhi, nodes.nY);
    for (int j = 0; j < nodes.nY; ++j) {
      const int base = j * nodes.nPhi;
      for (int i = 0; i < nodes.nPhi; ++i) {
        const double left = nodes.phi_rad[base + std::max(0, i - 1)];
        const double right = nodes.phi_rad[base + std::min(nodes.nPhi - 1, i + 1)];
        r.arcWeights(i, j) = 0.5 * (right - left);
      }
      const double total = r.arcWeights.col(j).sum();
      if (total > 0.0)
        r.arcWeights.col(j) /= total;
      else
        r.arcWeights.col(j).setConstant(1.0 / nodes.nPhi);  // one node around
    }
    for (const int j : decimate(nodes.nY, kFrameNodesAlong)) {
      for (const int i : decimate(nodes.nPhi, kFrameNodesAround))
        r.frameNodes.push_back(i + nodes.nPhi * j);
    }
    r.mapPath = files_.stage(mapFileName(nodes.name));
    if (!framed_.empty())
      r.framePath = files_.stage(frameFileName(nodes.name));
    regions_.push_back(std::move(r));
  }
}

void CycleMapSink::beginCycle(int) {
  rowInCycle_ = 0;
  discardRows();
}

void CycleMapSink::discardRows() {
  rowsKept_ = 0;
  for (Region& r : regions_) {
    r.mapRows.clear();
    r.frameRows.clear();
  }
}

void CycleMapSink::consumeRow(const SimTK::State& state, const std::vector<double>& values) {
  if (rowInCycle_ < 0 || regions_.empty())
    return;
  const long k = rowInCycle_++;
  if (k >= perCycle_)
    return;  // the row closing the cycle is the next cycle's first
  const double angle_deg = common::wrapCrankAngle_deg(values.at(1));  // crank_angle_deg
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    try {
      source_.calcNodalFields(state, static_cast<int>(r), values_);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("cycle maps at " + common::formatNumber(angle_deg) +
                               " deg: " + e.what());
    }
    keepRow(r, values_, angle_deg, k % frameStride_ == 0);
  }
  ++rowsKept_;
}

void CycleMapSink::keepRow(std::size_t r, const Eigen::MatrixXd& values, double angle_deg,
                           bool frame) {
  Region& region = regions_[r];
  const plugin::NodalFieldRegion& nodes = region.nodes;
  if (values.rows() != static_cast<Eigen::Index>(nodes.nPhi) * nodes.nY)
    throw std::runtime_error("cycle maps: region " + nodes.name + " has " +
                             std::to_string(values.rows()) + " nodal values, not nPhi x nY");
  if (!values.allFinite())
    throw std::runtime_error("cycle maps at " + common::formatNumber(angle_deg) + " deg, region " +
                             nodes.name + ": a non-finite nodal value");
  for (int j = 0; j < nodes.nY; ++j) {
    region.mapRows.push_back(angle_deg);
    region.mapRows.push_back(nodes.y_m[j * nodes.nPhi] * 1e3);
    for (const Mapped& m : mapped_) {
      const auto row = values.col(m.field).segment(j * nodes.nPhi, nodes.nPhi);
      region.mapRows.push_back(m.reduction == Reduction::Min   ? row.minCoeff()
                               : m.reduction == Reduction::Max ? row.maxCoeff()
                                                               : row.dot(region.arcWeights.col(j)));
    }
  }
  if (!frame || framed_.empty())
    return;
  for (const int k : region.frameNodes) {
    region.frameRows.push_back(angle_deg);
    region.frameRows.push_back(nodes.phi_rad[k] * 180.0 / M_PI);
    region.frameRows.push_back(nodes.y_m[k] * 1e3);
    for (const auto& [field, column] : framed_)
      region.frameRows.push_back(values(k, field));
  }
}

void CycleMapSink::endRun() {
  if (regions_.empty())
    return;
  if (rowsKept_ != perCycle_) {
    throw std::runtime_error("cycle maps: the last cycle has " + std::to_string(rowsKept_) +
                             " output rows, a whole cycle " + std::to_string(perCycle_));
  }
  for (const Region& r : regions_) {
    writeMap(r);
    if (!r.framePath.empty())
      writeFrames(r);
  }
}


void CycleMapSink::writeMap(const Region& region) const {
  std::ofstream out(region.mapPath, std::ios::binary | std::ios::trunc);
  std::vector<std::string> columns{"crank_angle_deg", "y_mm"};
  for (const Mapped& m : mapped_)
    columns.push_back(m.column);
  std::vector<std::string> comments = comments_;
  comments.push_back("nodal fields of the liner element over the last cycle, " +
                     region.nodes.name + " region, reduced over the arc at each height: min, "
                     "max or trapezoidal mean in phi as the column says; 4 significant digits");
  comments.push_back("y above the pin axis (piston frame); one line per output row and height, "
                     "heights fastest; pressures gauge");
  writeCsvHeader(out, columns, comments);
  writeBlocksByAngle(out, region.mapRows, columns.size(),
                     static_cast<std::size_t>(region.nodes.nY), 2);
  out.close();
  if (!out)
    throw std::runtime_error(region.mapPath + ": write failed");
}

void CycleMapSink::writeFrames(const Region& region) const {
  std::ofstream out(region.framePath, std::ios::binary | std::ios::trunc);
  std::vector<std::string> columns{"crank_angle_deg", "phi_deg", "y_mm"};
  for (const auto& [field, column] : framed_)
    columns.push_back(column);
  std::vector<std::string> comments = comments_;
  comments.push_back("nodal fields of the liner element, " + region.nodes.name +
                     " region, every " + common::formatNumber(kFrameStep_deg * 1.0) +
                     " deg of the last cycle on every k-th node (at most " +
                     std::to_string(kFrameNodesAround) + " x " + std::to_string(kFrameNodesAlong) +
                     "); 4 significant digits");
  comments.push_back("phi from +x (thrust) towards +z (pin axis), y above the pin axis (piston "
                     "frame); phi fastest, then y, then the crank angle; pressures gauge");
  writeCsvHeader(out, columns, comments);
  writeBlocksByAngle(out, region.frameRows, columns.size(), region.frameNodes.size(), 3);
  out.close();
  if (!out)
    throw std::runtime_error(region.framePath + ": write failed");
}

}  // namespace pistondyn::io::detail
