#pragma once
/// \file
/// A numeric CSV table as decks reference them (skirt profiles, ovality, temperature
/// fields, ...): '#' comment lines allowed anywhere, one header line of column names that
/// carry their units, then one row of numbers per line:
///
///   # measured axial profile, piston 3 of batch 7
///   axial_position_mm,radial_drop_um
///   0.0,12.5
///   2.0,8.1
///
/// Every field must be a finite number and every row as wide as the header. Errors name
/// the file and line. Column values convert to SI by the unit in their name
/// (getColumnSI, Units.h), like deck keys.

#include <cstddef>
#include <string>
#include <vector>

#include "pistondyn/io/Units.h"

namespace pistondyn::io {

/// A CSV table as read: header, numeric rows and their file lines.
struct CsvTable {
  std::string filePath;                   ///< the file it was read from
  std::vector<std::string> columns;       ///< header names, in file order
  std::vector<std::vector<double>> rows;  ///< rows[i][j] = value of columns[j] in row i
  std::vector<int> rowLines;              ///< file line (1-based) of each row

  bool hasColumn(const std::string& name) const;  ///< the header names it
  /// Throws DeckError "<file>: no column '<name>' (columns: ...)" if absent.
  std::size_t columnIndex(const std::string& name) const;
  /// The values of one column, as written.
  std::vector<double> getColumn(const std::string& name) const;
  /// The values of one column in SI, by the unit its name ends with; throws
  /// std::logic_error if the name has no unit of `quantity` (as DeckSection::getSI), and
  /// DeckError "<file>:<line>: ..." if a value overflows in SI (1e306 kN).
  std::vector<double> getColumnSI(const std::string& name, Quantity quantity) const;
  /// "<file>:<line>" of row i, for messages about a value (e.g. not increasing).
  std::string where(std::size_t row) const;
};

/// Reads a table; `requiredColumns` must appear in the header. Throws DeckError
/// "<file>[:<line>]: ..." on any problem.
CsvTable readCsvTable(const std::string& filePath,
                      const std::vector<std::string>& requiredColumns = {});

}  // namespace pistondyn::io
