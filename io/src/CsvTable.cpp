#include "pistondyn/io/CsvTable.h"

#include <cmath>
#include <fstream>
#include <set>
#include <stdexcept>

#include "CsvText.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/io/DeckError.h"

namespace pistondyn::io {

bool CsvTable::hasColumn(const std::string& name) const {
  for (const auto& c : columns) {
    if (c == name)
      return true;
  }
  return false;
}

std::size_t CsvTable::columnIndex(const std::string& name) const {
  for (std::size_t j = 0; j < columns.size(); ++j) {
    if (columns[j] == name)
      return j;
  }
  std::string list;
  for (const auto& c : columns)
    list += (list.empty() ? "" : ", ") + c;
  throw DeckError(filePath + ": no column '" + name + "' (columns: " + list + ")");
}

std::vector<double> CsvTable::getColumn(const std::string& name) const {
  const std::size_t j = columnIndex(name);
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& r : rows)
    out.push_back(r[j]);
  return out;
}

std::vector<double> CsvTable::getColumnSI(const std::string& name, Quantity quantity) const {
  const auto unit = findUnitSuffix(name, quantity);
  if (!unit) {
    throw std::logic_error("CsvTable::getColumnSI: column '" + name + "' does not end with a " +
                           getQuantityName(quantity) + " unit");
  }
  std::vector<double> out = getColumn(name);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double si = out[i] * unit->factor + unit->offset;
    // A finite value as written can overflow in SI (1e306 kN): never pass on an inf.
    if (!std::isfinite(si)) {
      throw DeckError(where(i) + ": " + name + " " + common::formatNumber(out[i]) +
                      " is too large: it overflows when converted to " + unit->siSuffix);
    }
    out[i] = si;
  }
  return out;
}

std::string CsvTable::where(std::size_t row) const {
  return row < rowLines.size() ? filePath + ":" + std::to_string(rowLines[row]) : filePath;
}

CsvTable readCsvTable(const std::string& filePath,
                      const std::vector<std::string>& requiredColumns) {
  if (detail::isFolder(filePath))
    throw DeckError(filePath + ": is a folder, not a table file");
  std::ifstream in(filePath);
  if (!in)
    throw DeckError(filePath + ": cannot open the table");
  CsvTable table;
  table.filePath = filePath;
  bool haveHeader = false;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (lineNo == 1)
      detail::stripBom(line);
    const std::string t = detail::trim(line);
    if (t.empty() || t[0] == '#')
      continue;
    const std::vector<std::string> f = detail::splitCsv(t);
    const std::string at = filePath + ":" + std::to_string(lineNo) + ": ";
    if (!haveHeader) {
      std::set<std::string> seen;
      for (const auto& name : f) {
        double ignored = 0.0;
        if (name.empty() || detail::parseDouble(name, ignored)) {
          throw DeckError(at +
                          "expected a header of column names with units (e.g. "
                          "axial_position_mm,radial_drop_um), found '" +
                          t + "'");
        }
        if (!seen.insert(name).second)
          throw DeckError(at + "column '" + name + "' appears twice in the header");
      }
      table.columns = f;
      haveHeader = true;
      continue;
    }
    if (f.size() != table.columns.size()) {
      throw DeckError(at + "expected " + std::to_string(table.columns.size()) +
                      " columns as in the header, found " + std::to_string(f.size()));
    }
    std::vector<double> row(f.size());
    for (std::size_t j = 0; j < f.size(); ++j) {
      if (!detail::parseDouble(f[j], row[j])) {
        throw DeckError(at + table.columns[j] + " '" + f[j] + "' is not a finite number");
      }
    }
    table.rows.push_back(std::move(row));
    table.rowLines.push_back(lineNo);
  }
  if (!haveHeader)
    throw DeckError(filePath + ": empty table (no header line)");
  for (const auto& name : requiredColumns) {
    if (!table.hasColumn(name)) {
      std::string list;
      for (const auto& c : table.columns)
        list += (list.empty() ? "" : ", ") + c;
      throw DeckError(filePath + ": the table needs a column '" + name + "' (header: " + list +
                      ")");
    }
  }
  return table;
}

}  // namespace pistondyn::io
