#pragma once
// What the program's figures share (ResultPlots.cpp: one run; ComparisonPlots.cpp: the
// cases of a study or sweep on common axes): columns found by output name and converted
// to the unit an axis states, gnuplot strings, the crank-angle axis with its TDC marks, a
// palette, and a temporary folder for gnuplot's data.

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

#include <vector>

#include "pistondyn/io/CsvTable.h"
#include "pistondyn/io/ResultWriters.h"

namespace pistondyn::app::plot {

// The factor from a column's unit to an axis' unit of the same quantity ("um" -> "mm":
// 1e-3); nullopt if either is unknown or they measure different quantities
// (units::conversionFactor, DisplayUnits.h).
std::optional<double> conversionFactor(const std::string& from, const std::string& to);
// How an axis label writes a unit ("um" -> "µm", "" -> "–").
std::string displayUnit(const std::string& unit);
// The unit an axis shows the named quantity in (DisplayUnits.h: "gas_force_N" -> "kN",
// "film_pressure_Pa" -> "MPa", "u_lat_um" -> "um"): every figure shows a quantity in the unit
// the report's tables use.
std::string axisUnit(const std::string& name);

// The column of output `name` in whatever unit it was written ("side_force" finds
// side_force_N), with the factor to `unit`; nullopt if absent or not convertible (the
// latter logged as a warning).
struct Column {
  std::size_t index;
  double factor;
};
std::optional<Column> findOutput(const io::CsvTable& t, const std::string& name,
                                 const std::string& unit);
bool hasOutput(const io::CsvTable& t, const std::string& name);

// A gnuplot string literal; one of several lines (empty lines are left out: twoLines' second
// may be empty).
std::string quoted(const std::string& s);
std::string quotedLines(const std::vector<std::string>& lines);
std::string twoLines(const std::string& first, const std::string& second);
// The shortest text that reads back to the same double.
std::string number(double v);

inline const char* const kBlue = "#1f77b4";
inline const char* const kOrange = "#ff7f0e";
inline const char* const kGreen = "#2ca02c";
inline const char* const kRed = "#d62728";
inline const char* const kPurple = "#9467bd";
// Colour of curve k of a comparison (ten distinguishable colours, then again).
const char* getCaseColour(std::size_t k);

// The top of a colour scale for values whose largest is `largest`: that, unless a few peaks
// would leave the rest of a map in one colour - then the 99th percentile of the positive
// values (`positive`, reordered). The maps draw values above it in the top colour and say so.
double chooseColourTop(std::vector<double>& positive, double largest);

// The crank-angle x axis 0 ... 720 deg with firing TDC (0, 720) and gas-exchange TDC (360)
// marked on the top axis and by dashed lines.
void writeTdcMarks(std::ostream& gp);

// The script lines every figure file starts with (UTF-8, grid, key beside the panels).
const char* getScriptPreamble();

// Where `files` stages figure `name` (ResultFileSet::stage's path, known before a figure is
// written, so that a figure with no data is never staged), and its staging once it is
// written (checked against that path).
std::string getStagedPath(const io::ResultFileSet& files, const std::string& name);
void stageFigure(io::ResultFileSet& files, const std::string& name);

// Runs gnuplot on the script, commits the staged figures `names` and removes the other PNGs
// of the folder whose names start with `prefix` ("" = every PNG): the folder then holds
// these figures of that kind only. Returns the paths of `names`. Throws as runGnuplot() and
// ResultFileSet::commit().
std::vector<std::string> drawAndCommit(const std::string& gnuplot,
                                       const std::filesystem::path& script,
                                       const std::filesystem::path& workDir,
                                       io::ResultFileSet& files,
                                       const std::vector<std::string>& names,
                                       const std::string& prefix);

// A folder under the system's temporary folder, removed with everything in it.
struct TempDir {
  std::filesystem::path path;
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

}  // namespace pistondyn::app::plot
