#pragma once
/// \file
/// Reading back the result folder `pistondyn run` writes (RunDeck.h): cycle.csv, summary.json
/// and the lubricated skirt's field dumps. Used by `pistondyn plot` and `pistondyn report`,
/// and by anyone comparing runs (sweeps, studies). Columns are found by their names, which
/// carry their units (ElementOutput.h: name + "_" + unit), never by position.
///
///   const io::ResultFolder r = io::readResultFolder("results/gasoline");
///   const io::CycleWindow w = io::selectLastCycle(r.cycle);
///   for (std::size_t i = 0; i < w.rows.size(); ++i)
///     use(w.angle_deg[i], r.cycle.rows[w.rows[i]][r.cycle.columnIndex("side_force_N")]);

#include <stdexcept>
#include <string>
#include <vector>

#include "pistondyn/io/CsvTable.h"

namespace pistondyn::io {

/// One field-dump file (liner.field_dumps.crank_angles_deg): the crank angle of the last
/// cycle it was taken at, the skirt side and its path.
struct FieldDumpFile {
  double crankAngle_deg = 0.0;  ///< in [0, 720) [deg]
  std::string side;             ///< "thrust" or "antithrust"
  std::string path;             ///< the file
};

/// A file of one region of the liner element's nodal fields over the last cycle
/// (cycle_map_<region>.csv, field_frames_<region>.csv; their columns are described in
/// README.md, "Result files").
struct RegionFile {
  std::string region;  ///< e.g. "thrust", "antithrust"
  std::string path;    ///< the file
};

/// A flattened entry of summary.json: "results.fmep_kPa", "inputs.geometry.bore_m", ...;
/// `value` is the JSON text of a number, boolean or string (strings without quotes), or of
/// an array of numbers ("[2.37, 2.41]").
struct SummaryEntry {
  std::string key;    ///< dotted path
  std::string value;  ///< JSON text of the value
};

/// A result folder read back (what `pistondyn plot` and `report` read).
struct ResultFolder {
  std::string directory;                   ///< the folder
  CsvTable cycle;                          ///< cycle.csv
  std::vector<std::string> cycleComments;  ///< its '#' lines, without the '#'
  std::string summaryJson;                 ///< summary.json as written
  std::vector<SummaryEntry> summary;       ///< ... flattened, in file order
  std::vector<FieldDumpFile> fieldDumps;   ///< by angle, thrust before anti-thrust
  /// cycle_map_<region>.csv and field_frames_<region>.csv: thrust, anti-thrust, then any
  /// other region by name.
  ///@{
  std::vector<RegionFile> cycleMaps, fieldFrames;
  ///@}

  /// The flattened summary value of `key`, or "" if absent.
  std::string getSummaryValue(const std::string& key) const;
};

/// A folder that is not a result folder of `pistondyn run`, or a file in it that is not as
/// run writes it (the message names the file and what is wrong).
class ResultFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads DIR/cycle.csv and DIR/summary.json (both required) and lists DIR's field dumps,
/// cycle maps and field frames.
/// summary.json must be a JSON object with a "results" object whose figures are numbers
/// (or true / false, null, a list of numbers; "note" is text), its inputs whose key names a
/// unit numbers, and wall_time_s and integrator_steps numbers. Throws ResultFolderError
/// naming the file and what is wrong (DeckError for a malformed cycle.csv, naming its line).
ResultFolder readResultFolder(const std::string& directory);

/// The rows of the last 720 deg cycle of a cycle table (see selectLastCycle()).
struct CycleWindow {
  std::vector<std::size_t> rows;  ///< indices into table.rows
  std::vector<double> angle_deg;  ///< the mapped crank angle of each
};
/// The rows of the last 720 deg cycle of a cycle table, for plotting against a crank-angle
/// axis 0 ... 720 deg: the crank angle of each row mapped into [0, 720] (720 only for the
/// row closing a cycle that starts at a multiple of 720 deg), rows ordered by that angle,
/// one row per angle. Needs a crank_angle_deg column; throws std::runtime_error if it is
/// missing or the table is empty.
CycleWindow selectLastCycle(const CsvTable& table);

/// The unit suffix of a column name as the project writes them ("side_force_N" -> "N",
/// "tilt_mrad" -> "mrad", "crank_speed_rpm" -> "rpm"); "" for a dimensionless column
/// ("min_h_over_sigma_thrust"). Only the suffixes the result files use are known.
std::string getColumnUnit(const std::string& column);

}  // namespace pistondyn::io
