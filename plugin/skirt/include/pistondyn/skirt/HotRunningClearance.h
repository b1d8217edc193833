#pragma once
/// \file
/// The hot running clearance of a skirt side.
///
/// Definition: the radial clearance between skirt and bore on the thrust axis (phi = phi_c, the
/// side's centre line, where the ovality drop is 0), for the centred, untilted piston, with the
/// skirt profile and both thermal growths (the terms switched on in
/// GapAssemblyParameters::terms), at the skirt's minimum-clearance line, minimised over the
/// piston's travel along the liner:
///
///   c_hot = min over y in [y_bottom, y_top], Y_pin in [Y_BDC, Y_TDC] of
///           c0 + drop(y) + h_pistonThermal(y) + h_linerThermal(Y_pin + y).
///
/// It excludes the bore distortion and the elastic terms: it is the design clearance of the hot,
/// unloaded piston in the hot, round bore. A negative value is an interference of the hot
/// piston (GapAssembly rejects it).
///
/// How it is found: for each height y the liner term's minimum over the bore heights
/// [Y_BDC + y, Y_TDC + y] is exact (the liner temperature is linear or monotone PCHIP between its
/// rows, so the minimum is at an end or a row). The minimum over y is taken over the grid rows,
/// the profile and temperature rows inside the skirt and 256 uniformly spaced heights, then
/// refined by golden-section search between the neighbours of the best candidate (to 1e-9 of the
/// skirt length). With a nodal piston temperature the piston term on the centre line is the
/// linear interpolant between the two node columns nearest it, known at the grid rows only, so
/// the search is over the grid rows.

#include "pistondyn/skirt/GapTerms.h"
#include "pistondyn/skirt/SkirtSideGrid.h"

namespace pistondyn::skirt {

/// The hot running clearance of a skirt side and where it occurs (definition above).
struct HotRunningClearance {
  double clearance_m = 0.0;    ///< c_hot [m]
  double skirtHeight_m = 0.0;  ///< y of the minimum-clearance line, piston frame [m]
  double pinHeight_m = 0.0;    ///< Y_pin at which the minimum occurs [m]
};

/// Inputs: the side and the gap parameters (coldRadialClearance_m, travel, profile, thermal
/// fields, switches; linerTopHeight_m when a liner temperature is given).
/// Output: the hot running clearance and where it occurs.
/// Throws std::invalid_argument naming the member for bad parameters (not for a negative
/// clearance: see requireNonNegativeHotClearance).
HotRunningClearance calcHotRunningClearance(const SkirtSideGrid& grid,
                                            const GapAssemblyParameters& parameters);

/// Throws std::invalid_argument with the value and where it occurs if hot.clearance_m < 0.
void requireNonNegativeHotClearance(const HotRunningClearance& hot, const SkirtSideGrid& grid);

}  // namespace pistondyn::skirt
