#include "FieldDumps.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "pistondyn/common/CrankAngle.h"
#include "pistondyn/common/Validation.h"

namespace pistondyn::io::detail {
namespace {

constexpr double kAngleTolerance_deg = 1e-6;  // rows carry omega t in deg: rounding only

}  // namespace

std::string FieldDumpSink::fileName(double angle_deg, const std::string& region) {
  return "field_dump_" + common::formatNumber(angle_deg) + "deg_" + region + ".csv";
}

FieldDumpSink::FieldDumpSink(const plugin::NodalFieldSource& source,
                             std::vector<double> angles_deg, long rowsPerCycle,
                             std::vector<std::string> commentLines, ResultFileSet& files)
    : source_(source),
      files_(files),
      angles_deg_(std::move(angles_deg)),
      perCycle_(rowsPerCycle),
      comments_(std::move(commentLines)),
      written_(angles_deg_.size(), false) {}

void FieldDumpSink::beginRun(const std::vector<std::string>&) {
  // The regions exist once the element is in a built model.
  regions_ = source_.getNodalFieldRegions();
  columns_ = {"phi_deg", "y_mm"};
  for (const plugin::NodalFieldDeclaration& d : source_.getNodalFieldDeclarations())
    columns_.push_back(d.getColumnName());
  paths_.clear();
  for (const double a : angles_deg_) {
    for (const plugin::NodalFieldRegion& region : regions_)
      paths_.push_back(files_.stage(fileName(a, region.name)));
  }
}

void FieldDumpSink::beginCycle(int) {
  rowInCycle_ = 0;
  written_.assign(angles_deg_.size(), false);
}

void FieldDumpSink::discardRows() {
  written_.assign(angles_deg_.size(), false);
}

void FieldDumpSink::consumeRow(const SimTK::State& state, const std::vector<double>& values) {
  if (rowInCycle_ < 0)
    return;
  const long k = rowInCycle_++;
  if (k >= perCycle_)
    return;  // the row closing the cycle is the next cycle's first
  const double angle = common::wrapCrankAngle_deg(values.at(1));  // crank_angle_deg
  for (std::size_t i = 0; i < angles_deg_.size(); ++i) {
    const double d = std::abs(angle - angles_deg_[i]);
    if (d <= kAngleTolerance_deg || std::abs(d - 720.0) <= kAngleTolerance_deg)
      write(state, i, values.at(0));
  }
}

void FieldDumpSink::write(const SimTK::State& state, std::size_t a, double time_s) {
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    const plugin::NodalFieldRegion& region = regions_[r];
    try {
      source_.calcNodalFields(state, static_cast<int>(r), values_);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("field dump at " + common::formatNumber(angles_deg_[a]) +
                               " deg: " + e.what());
    }
    const std::string& path = paths_[regions_.size() * a + r];
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    std::vector<std::string> comments = comments_;
    comments.push_back("nodal fields of the liner element, " + region.name +
                       " region, at crank angle " + common::formatNumber(angles_deg_[a]) +
                       " deg of the last cycle (time " + common::formatNumber(time_s) + " s)");
    comments.push_back(
        "phi from +x (thrust) towards +z (pin axis), y above the pin axis (piston frame); one "
        "row per node, phi fastest; gap_um = sum of the seven terms, film_gap_um its clamped "
        "film value; pressures gauge");
    writeCsvHeader(out, columns_, comments);
    const Eigen::Index n = values_.rows();
    std::vector<double> row(columns_.size());
    for (Eigen::Index k = 0; k < n; ++k) {
      row[0] = region.phi_rad[k] * 180.0 / M_PI;
      row[1] = region.y_m[k] * 1e3;
      for (Eigen::Index c = 0; c < values_.cols(); ++c)
        row[static_cast<std::size_t>(c) + 2] = values_(k, c);
      for (double v : row) {
        if (!std::isfinite(v))
          throw std::runtime_error("field dump at " + common::formatNumber(angles_deg_[a]) +
                                   " deg: a non-finite nodal value");
      }
      writeCsvRow(out, row);
    }
    out.close();
    if (!out)
      throw std::runtime_error(path + ": write failed");
  }
  written_[a] = true;
}

void FieldDumpSink::endRun() {
  for (std::size_t i = 0; i < angles_deg_.size(); ++i) {
    if (!written_[i]) {
      throw std::runtime_error("field dump: no output row of the last cycle at crank angle " +
                               common::formatNumber(angles_deg_[i]) + " deg");
    }
  }
}

}  // namespace pistondyn::io::detail
