#pragma once
// The figures of a run's result folder, drawn by gnuplot (pngcairo) into DIR/plots/:
//
//   crank_train_forces.png  gas, conrod force, the crank train's side force (from the rod)
//                           and the side force on the liner; crank and drive torque
//   side_force.png          side force (and, for the lubricated skirt, film and asperity
//                           normal forces per side); the liner's moment
//   secondary_motion.png    lateral displacement at skirt top, pin and skirt bottom; tilt
//   friction.png            friction force (film and asperity parts) and friction power
//   film_thickness.png      minimum film thickness and minimum h/sigma per side
//   regime_shares.png       hydrodynamic / mixed / boundary and wetted area shares per side
//   field_map_<a>deg.png    film pressure, fill fraction and gap over the unwrapped skirt,
//                           both sides, at each crank angle a with field dumps
//
// The last four and the maps only when the run has those columns (the lubricated skirt).
// Columns are chosen by output name, their unit read from the column name and converted
// to the unit the axis states. Crank-angle axes run 0 ... 720 deg over the last cycle,
// with firing TDC (0 and 720 deg, the README's convention) and the gas-exchange TDC marked.

#include <string>
#include <vector>

#include "pistondyn/io/ResultFolder.h"

namespace pistondyn::app {

// Checks that the folder has every column its figures need: the crank-train and gas
// columns of every run, the side force of a run with a liner element (results has side-
// force figures), the ideal guide's moment, the lubricated skirt's columns of the figures
// above (inputs.liner.model), and the field dumps' coordinates and fields - each in a unit
// the axis can convert. Throws io::ResultFolderError naming the file and the column (a
// figure is never dropped silently because a column is missing).
void checkResultPlotColumns(const io::ResultFolder& folder);

// Writes the figures into <folder.directory>/plots/ all-or-nothing (earlier PNGs there are
// replaced; figures this run has no data for are removed). Returns the paths written, in
// the order above. Throws io::ResultFolderError (checkResultPlotColumns), GnuplotMissing
// (Gnuplot.h) or std::runtime_error.
std::vector<std::string> writeResultPlots(const io::ResultFolder& folder);

}  // namespace pistondyn::app
