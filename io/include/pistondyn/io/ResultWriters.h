#pragma once
/// \file
/// Result files. Numbers are written in the shortest form that reads back to the
/// identical double (std::to_chars), so a position in metres keeps every bit.
///
/// All-or-nothing: results are written under temporary names inside the output folder
/// (ResultFileSet::stage) and renamed into place together (commit) only when every file
/// is complete; if anything fails, the folder is left as it was, earlier results
/// included, and no file that looks like a result remains.

#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "pistondyn/plugin/CycleSimulation.h"

namespace pistondyn::io {

/// The shortest text that reads back to exactly `value` (common::formatNumber), as every
/// result file writes numbers.
std::string formatNumber(double value);

/// `text` made fit for one '#' comment line of a result file: a control character (a newline
/// in a deck's path, a tab, ...) written as a C escape (`\n`, `\r`, `\t`, `\xNN`) and a
/// backslash as `\\`, so that the line ends where it should and the text can be read back
/// exactly.
std::string escapeForCommentLine(const std::string& text);

/// '#'-prefixed comment lines (escapeForCommentLine), then a header of column names (with
/// units), then rows.
void writeCsv(std::ostream& out, const plugin::ResultTable& table,
              const std::vector<std::string>& commentLines);
/// The two parts of writeCsv, for writers that stream rows.
void writeCsvHeader(std::ostream& out, const std::vector<std::string>& columns,
                    const std::vector<std::string>& commentLines);
void writeCsvRow(std::ostream& out, const std::vector<double>& values);  ///< one row

/// Streams the rows of a run to a CSV file as the simulation produces them (the same
/// text as writeCsv of the whole table). The file is created at beginRun(); endRun()
/// flushes and closes it; discardRows() (a run to periodic steady state dropping an
/// earlier cycle) starts the file again after its header. Throws std::runtime_error naming
/// the file when it cannot be written. Give it a path from ResultFileSet::stage() for
/// all-or-nothing results.
class CsvRowSink final : public plugin::RowSink {
 public:
  /// The file to write and the '#' comment lines above its header.
  CsvRowSink(std::string filePath, std::vector<std::string> commentLines);
  void beginRun(const std::vector<std::string>& columns) override;  ///< creates the file
  /// Writes the row.
  void consumeRow(const SimTK::State& state, const std::vector<double>& values) override;
  void discardRows() override;  ///< starts the file again after its header
  void endRun() override;       ///< flushes and closes the file
  const std::string& getFilePath() const { return filePath_; }  ///< the file
  long getRowCount() const { return rows_; }                    ///< rows written

 private:
  void fail(const std::string& what) const;
  std::string filePath_;
  std::vector<std::string> comments_;
  std::vector<std::string> columns_;
  std::ofstream out_;
  long rows_ = 0;
};

/// Result files that appear in a folder together or not at all.
///
/// \code
///   ResultFileSet files(outDir);               // creates outDir (and parents) if needed
///   CsvRowSink csv(files.stage("cycle.csv"), comments);
///   sim.run({&csv});                           // a throw here: the destructor cleans up
///   std::ofstream(files.stage("summary.json")) << json;
///   files.commit();                            // both renamed into place
/// \endcode
class ResultFileSet {
 public:
  /// Creates `dir` and missing parents; throws std::runtime_error if it cannot.
  explicit ResultFileSet(std::string dir);
  /// Not committed: removes every staged file, and the folders this object created if
  /// they are empty. Never throws.
  ~ResultFileSet();
  ResultFileSet(const ResultFileSet&) = delete;
  ResultFileSet& operator=(const ResultFileSet&) = delete;

  const std::string& getDirectory() const { return dir_; }  ///< the folder
  /// The temporary path to write result `name` to: `DIR/.NAME.partial`.
  std::string stage(const std::string& name);
  /// Stages result `name` with the whole of `text`; throws std::runtime_error ("DIR/NAME: write
  /// failed") if it cannot be written.
  void stageText(const std::string& name, const std::string& text);
  /// Renames every staged file to its name, replacing earlier results of that name. On
  /// any failure the folder is restored as it was (old results back, no new or temporary
  /// files) and std::runtime_error is thrown.
  void commit();

 private:
  std::string dir_;
  std::vector<std::string> names_;    ///< staged, in order
  std::vector<std::string> created_;  ///< folders this object created, deepest first
  bool committed_ = false;
};

/// Writes files into `dir` all-or-nothing (a ResultFileSet of complete texts). Creates
/// `dir` (and parents) if needed. Throws std::runtime_error on I/O failure, leaving no
/// partial result files.
void writeFilesAtomically(const std::string& dir,
                          const std::vector<std::pair<std::string, std::string>>& nameAndContent);

}  // namespace pistondyn::io
