#pragma once
// Comparison figures of the cases of a study or sweep on common axes, drawn by gnuplot
// into DIR/plots/ (`pistondyn study`, `pistondyn sweep`): one curve per case against the
// crank angle 0 ... 720 deg of each case's last cycle (firing TDC at 0 and 720 deg, the
// gas-exchange TDC at 360 deg marked), the legend naming each case by its overrides:
//
//   comparison_side_force.png        side force on the liner (N)
//   comparison_secondary_motion.png  lateral displacement at the pin axis (µm), tilt (mrad)
//   comparison_friction_power.png    skirt friction power (W)
//   comparison_film_thickness.png    minimum film thickness, thrust and anti-thrust (µm)
//   comparison_h_over_sigma.png      minimum h/σ, thrust and anti-thrust, h/σ = 1 and 3 marked
//
// each only when some case has the columns (all but the first need the lubricated skirt).

#include <string>
#include <vector>

#include "pistondyn/io/ResultFolder.h"

namespace pistondyn::app {

struct ComparisonCase {
  std::string label;  // the legend: "case 2: film_um=0.5"
  io::ResultFolder folder;
};

// The most cases one figure compares; a sweep with more draws none (its sweep.csv holds
// every case).
inline constexpr std::size_t kMaxComparedCases = 12;

// Writes the figures into <dir>/plots/ all-or-nothing (earlier comparison figures there
// are replaced, a figure no case has data for is removed); `title` heads every figure.
// Returns the paths written. Throws GnuplotMissing (Gnuplot.h) or std::runtime_error.
std::vector<std::string> writeComparisonPlots(const std::vector<ComparisonCase>& cases,
                                              const std::string& dir, const std::string& title);

}  // namespace pistondyn::app
