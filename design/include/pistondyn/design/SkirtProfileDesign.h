#pragma once
/// @file
/// The parametric skirt profile of the design loop: the cold radial drop of the skirt below
/// its reference diameter against the height above the pin axis, from four numbers, written
/// as the table `liner.skirt_profile.axial_profile_file` reads (CSV `height_above_pin_mm,
/// radial_drop_um`), so that profile optimisation needs no hand-made tables.
///
/// With y the height above the pin [mm], y_m the minimum-clearance point, s = y - y_m and L
/// the distance from y_m to the skirt edge on the side of y (top edge y_t above, bottom
/// edge y_b below):
///
/// ~~~
///   drop(y) = c s^2 + (d - c L^2) (s / L)^4        d = top_drop_um above y_m,
///                                                    bottom_drop_um below it
/// ~~~
///
/// so drop(y_m) = 0 (the cold clearance is the clearance there), drop'(y_m) = 0, drop'' =
/// 2c at y_m (c = curvature_um_per_mm2: the parabola c s^2 of a plain barrel, which the
/// quartic term bends to reach the edge drop d exactly at the edge). With c = 0.12 and the
/// edge drops of 0.12 L^2 it is the examples' parabolic barrel. The drop rises monotonically
/// from y_m to each edge when d >= c L^2 / 2 on that side (below that the profile turns back
/// towards the edge; it is written as the formula gives it).

#include <string>

namespace pistondyn::design {

/// The four numbers of the parametric skirt profile (this file's formula), in the deck's
/// units.
struct SkirtProfileShape {
  double topDrop_um = 0.0;             ///< radial drop at the skirt's top edge [um]
  double bottomDrop_um = 0.0;          ///< ... at its bottom edge [um]
  double minClearanceHeight_mm = 0.0;  ///< y_m, above the pin axis [mm]
  double curvature_um_per_mm2 = 0.0;   ///< c [um/mm^2]
};

/// The drop [um] at height y_mm of a skirt from bottom_mm to top_mm (heights above the pin).
/// Throws std::invalid_argument unless bottom_mm < minClearanceHeight_mm < top_mm.
double calcProfileDrop_um(const SkirtProfileShape& shape, double bottom_mm, double top_mm,
                          double y_mm);

/// The profile table's text: '#' lines (the formula and the four numbers), the header, then
/// `rows` rows evenly spaced from bottom_mm - 0.5 to top_mm + 0.5 (the formula continued
/// half a millimetre past each edge, so the table covers the skirt whatever rounding its
/// height takes in SI) with y_m and both edges among them. Numbers in the shortest text
/// that reads back to the same double. Throws std::invalid_argument as above or for rows < 5.
std::string makeProfileTable(const SkirtProfileShape& shape, double bottom_mm, double top_mm,
                             int rows = 41);

}  // namespace pistondyn::design
