#pragma once
/// \file
/// Results of a cycle simulation held in memory: column names (units in the names) and one
/// row of values per output crank angle. Plain data, no Simbody: programs that only read
/// or write results need nothing else. Long runs stream their rows to a RowSink
/// (CycleSimulation.h) instead of holding them here.

#include <cstddef>
#include <string>
#include <vector>

namespace pistondyn::plugin {

/// Column names and rows of a simulation held in memory.
struct ResultTable {
  std::vector<std::string> columns;       ///< column names, units in the names
  std::vector<std::vector<double>> rows;  ///< rows[i][j] = value of columns[j] at row i

  /// Index of a column; throws std::out_of_range naming it if absent.
  std::size_t columnIndex(const std::string& name) const;
  bool hasColumn(const std::string& name) const;  ///< a column of that name exists
  /// The values of one column, row by row; throws std::out_of_range naming it if absent.
  std::vector<double> column(const std::string& name) const;
};

}  // namespace pistondyn::plugin
