#pragma once
// A numeric CSV file the program wrote (cycle.csv, a field dump) read back for a test:
// '#' lines skipped, the header's column names, then every row's numbers (strtod, exact
// for the shortest round-trip text the writers use). Independent of io::CsvTable, the
// reader under test elsewhere.

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace pistondyn::test {

struct NumericCsv {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  // Index of a column; std::out_of_range if there is none.
  std::size_t col(const std::string& name) const {
    const auto it = std::find(columns.begin(), columns.end(), name);
    if (it == columns.end())
      throw std::out_of_range(name);
    return static_cast<std::size_t>(it - columns.begin());
  }
  // A whole column; std::out_of_range if there is none.
  std::vector<double> column(const std::string& name) const {
    const std::size_t c = col(name);
    std::vector<double> out;
    for (const auto& r : rows)
      out.push_back(r.at(c));
    return out;
  }
};

inline NumericCsv readNumericCsv(const std::filesystem::path& p) {
  NumericCsv c;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    std::stringstream ss(line);
    std::string f;
    if (c.columns.empty()) {
      while (std::getline(ss, f, ','))
        c.columns.push_back(f);
      continue;
    }
    c.rows.emplace_back();
    while (std::getline(ss, f, ','))
      c.rows.back().push_back(std::strtod(f.c_str(), nullptr));
  }
  return c;
}

}  // namespace pistondyn::test
