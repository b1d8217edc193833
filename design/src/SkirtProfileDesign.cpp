#include "pistondyn/design/SkirtProfileDesign.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "pistondyn/common/Validation.h"

namespace pistondyn::design {
namespace {

using common::formatNumber;

void checkSkirt(const SkirtProfileShape& s, double bottom_mm, double top_mm) {
  const double ym = s.minClearanceHeight_mm;
  if (!(std::isfinite(bottom_mm) && std::isfinite(top_mm) && std::isfinite(ym) && bottom_mm < ym &&
        ym < top_mm)) {
    throw std::invalid_argument("skirt profile: the minimum-clearance height " + formatNumber(ym) +
                                " mm must lie inside the skirt, between its bottom edge " +
                                formatNumber(bottom_mm) + " mm and its top edge " +
                                formatNumber(top_mm) + " mm above the pin");
  }
  for (const double v : {s.topDrop_um, s.bottomDrop_um, s.curvature_um_per_mm2}) {
    if (!std::isfinite(v))
      throw std::invalid_argument("skirt profile: a drop or the curvature is not finite");
  }
}

}  // namespace

double calcProfileDrop_um(const SkirtProfileShape& shape, double bottom_mm, double top_mm,
                          double y_mm) {
  checkSkirt(shape, bottom_mm, top_mm);
  const double s = y_mm - shape.minClearanceHeight_mm;
  const bool above = s >= 0.0;
  const double length =
      above ? top_mm - shape.minClearanceHeight_mm : shape.minClearanceHeight_mm - bottom_mm;
  const double edge = above ? shape.topDrop_um : shape.bottomDrop_um;
  const double c = shape.curvature_um_per_mm2;
  const double q = s / length;
  return c * s * s + (edge - c * length * length) * q * q * q * q;
}

std::string makeProfileTable(const SkirtProfileShape& shape, double bottom_mm, double top_mm,
                             int rows) {
  checkSkirt(shape, bottom_mm, top_mm);
  if (rows < 5)
    throw std::invalid_argument("makeProfileTable: rows = " + std::to_string(rows) +
                                " must be at least 5");
  constexpr double kBeyond_mm = 0.5;
  const double first = bottom_mm - kBeyond_mm, last = top_mm + kBeyond_mm;
  std::vector<double> heights;
  for (int k = 0; k < rows; ++k)
    heights.push_back(first + (last - first) * k / (rows - 1));
  heights.back() = last;
  for (const double y : {bottom_mm, shape.minClearanceHeight_mm, top_mm})
    heights.push_back(y);
  std::sort(heights.begin(), heights.end());
  // Points closer than 1e-9 mm to another (an edge on the even spacing) are one row.
  std::vector<double> unique;
  for (const double y : heights) {
    if (unique.empty() || y - unique.back() > 1e-9)
      unique.push_back(y);
  }
  std::ostringstream out;
  out << "# skirt profile written by pistondyn's design loop (pistondyn/design/"
         "SkirtProfileDesign.h):\n"
      << "#   radial_drop_um = c s^2 + (d - c L^2) (s/L)^4, s = height - y_m, L = distance "
         "from y_m to the edge on that side\n"
      << "#   top_drop_um " << formatNumber(shape.topDrop_um) << ", bottom_drop_um "
      << formatNumber(shape.bottomDrop_um) << ", min_clearance_height_mm y_m "
      << formatNumber(shape.minClearanceHeight_mm) << ", curvature_um_per_mm2 c "
      << formatNumber(shape.curvature_um_per_mm2) << "\n"
      << "#   skirt from " << formatNumber(bottom_mm) << " to " << formatNumber(top_mm)
      << " mm above the pin (the formula continued " << formatNumber(kBeyond_mm)
      << " mm past each edge)\n"
      << "height_above_pin_mm,radial_drop_um\n";
  for (const double y : unique)
    out << formatNumber(y) << ',' << formatNumber(calcProfileDrop_um(shape, bottom_mm, top_mm, y))
        << '\n';
  return out.str();
}

}  // namespace pistondyn::design
