#include "SkirtFieldDumps.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "pistondyn/common/CrankAngle.h"
#include "pistondyn/common/Validation.h"

namespace pistondyn::io::detail {
namespace {

constexpr double kAngleTolerance_deg = 1e-6;  // rows carry omega t in deg: rounding only

const char* sideName(plugin::SkirtSide side) {
  return side == plugin::SkirtSide::Thrust ? "thrust" : "antithrust";
}

const std::vector<std::string>& columns() {
  static const std::vector<std::string> c = {"phi_deg",
                                             "y_mm",
                                             "gap_um",
                                             "rigid_um",
                                             "skirt_profile_um",
                                             "liner_shape_um",
                                             "piston_thermal_um",
                                             "liner_thermal_um",
                                             "piston_elastic_um",
                                             "liner_elastic_um",
                                             "film_gap_um",
                                             "h_over_sigma",
                                             "film_pressure_Pa",
                                             "fill_fraction",
                                             "contact_pressure_Pa"};
  return c;
}

}  // namespace

std::string SkirtFieldDumpSink::fileName(double angle_deg, plugin::SkirtSide side) {
  return "field_dump_" + common::formatNumber(angle_deg) + "deg_" + sideName(side) + ".csv";
}

SkirtFieldDumpSink::SkirtFieldDumpSink(const plugin::LubricatedSkirtElement& skirt,
                                       std::vector<double> angles_deg, long rowsPerCycle,
                                       std::vector<std::string> commentLines, ResultFileSet& files)
    : skirt_(skirt),
      angles_deg_(std::move(angles_deg)),
      perCycle_(rowsPerCycle),
      comments_(std::move(commentLines)),
      written_(angles_deg_.size(), false) {
  for (const double a : angles_deg_) {
    for (const auto side : {plugin::SkirtSide::Thrust, plugin::SkirtSide::AntiThrust})
      paths_.push_back(files.stage(fileName(a, side)));
  }
}

void SkirtFieldDumpSink::beginCycle(int) {
  rowInCycle_ = 0;
  written_.assign(angles_deg_.size(), false);
}

void SkirtFieldDumpSink::discardRows() {
  written_.assign(angles_deg_.size(), false);
}

void SkirtFieldDumpSink::consumeRow(const SimTK::State& state, const std::vector<double>& values) {
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

void SkirtFieldDumpSink::write(const SimTK::State& state, std::size_t a, double time_s) {
  const plugin::LubricatedSkirtResults& cached = skirt_.getResults(state);
  int s = 0;
  for (const auto side : {plugin::SkirtSide::Thrust, plugin::SkirtSide::AntiThrust}) {
    const skirt::GapFields& gap = skirt_.getLastGapFields(side);
    const skirt::SkirtSideResults& r = skirt_.getLastSideResults(side);
    const skirt::SkirtSideGrid& grid = skirt_.getGapAssembly(side).getGrid();
    // The element keeps the fields of its last evaluation: they must be this row's.
    const auto& figures = cached.sides[static_cast<std::size_t>(s)];
    if (r.minFilmThickness_m != figures.minFilmThickness_m ||
        r.hydrodynamicNormalForce_N != figures.hydrodynamicNormalForce_N) {
      throw std::runtime_error(
          "field dump at " + common::formatNumber(angles_deg_[a]) +
          " deg: the lubricated skirt's last fields are not those of this row's state");
    }
    const std::string& path = paths_[2 * a + static_cast<std::size_t>(s)];
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    std::vector<std::string> comments = comments_;
    comments.push_back("lubricated skirt nodal fields, " + std::string(sideName(side)) +
                       " side, at crank angle " + common::formatNumber(angles_deg_[a]) +
                       " deg of the last cycle (time " + common::formatNumber(time_s) + " s)");
    comments.push_back(
        "phi from +x (thrust) towards +z (pin axis), y above the pin axis (piston frame); one "
        "row per node, phi fastest; gap_um = sum of the seven terms, film_gap_um its clamped "
        "film value; pressures gauge");
    writeCsvHeader(out, columns(), comments);
    const int n = grid.nodeCount();
    const double* contact = r.contact.pressure_Pa.data();
    const double* ratio = r.contact.filmRatio.data();
    std::vector<double> row(columns().size());
    for (int k = 0; k < n; ++k) {
      row = {grid.getNodePhi_rad()[k] * 180.0 / M_PI,
             grid.getNodeY_m()[k] * 1e3,
             gap.gap_m[k] * 1e6,
             gap.rigid_m[k] * 1e6,
             gap.skirtProfile_m[k] * 1e6,
             gap.linerShape_m[k] * 1e6,
             gap.pistonThermal_m[k] * 1e6,
             gap.linerThermal_m[k] * 1e6,
             gap.pistonElastic_m[k] * 1e6,
             gap.linerElastic_m[k] * 1e6,
             r.filmGap_m[k] * 1e6,
             ratio[k],
             r.film.pressure_Pa()[k],
             r.film.fillFraction()[k],
             contact[k]};
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
    ++s;
  }
  written_[a] = true;
}

void SkirtFieldDumpSink::endRun() {
  for (std::size_t i = 0; i < angles_deg_.size(); ++i) {
    if (!written_[i]) {
      throw std::runtime_error("field dump: no output row of the last cycle at crank angle " +
                               common::formatNumber(angles_deg_[i]) + " deg");
    }
  }
}

}  // namespace pistondyn::io::detail
