#include "pistondyn/io/PressureTableCsv.h"

#include "MessageText.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <vector>

#include "CsvText.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/io/DeckError.h"

namespace pistondyn::io {

using detail::parseDouble;
using detail::splitCsv;
using detail::trim;

namespace {

// Row problems reported at once, as the rest of the deck's are; a table of garbage stops
// at this many lines.
constexpr std::size_t kMaxProblemLines = 20;

}  // namespace

mbd::CylinderPressureCurve readPressureTableCsv(const std::string& filePath,
                                                std::string* pressureUnit) {
  if (detail::isFolder(filePath))
    throw DeckError(filePath + ": is a folder, not a cylinder-pressure table file");
  std::ifstream in(filePath);
  if (!in)
    throw DeckError(filePath + ": cannot open the cylinder-pressure table");
  static const std::map<std::string, double> kUnits = {
      {"pressure_Pa", 1.0}, {"pressure_kPa", 1e3}, {"pressure_bar", 1e5}, {"pressure_MPa", 1e6}};

  std::vector<double> angle, pressure;
  std::vector<int> lineOfRow;
  std::vector<std::string> problems;
  double toPa = 0.0;
  bool haveHeader = false;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (lineNo == 1)
      detail::stripBom(line);
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#')
      continue;
    const std::vector<std::string> f = splitCsv(t);
    const std::string at = filePath + ":" + std::to_string(lineNo) + ": ";
    if (!haveHeader) {
      if (f.size() != 2 || f[0] != "crank_angle_deg" || kUnits.count(f[1]) == 0) {
        throw DeckError(at +
                        "expected the header 'crank_angle_deg,pressure_<unit>' with unit "
                        "Pa, kPa, bar or MPa (absolute), found '" +
                        t + "'");
      }
      toPa = kUnits.at(f[1]);
      if (pressureUnit != nullptr)
        *pressureUnit = f[1].substr(std::string("pressure_").size());
      haveHeader = true;
      continue;
    }
    if (f.size() != 2) {
      problems.push_back(at + "expected 2 columns (crank angle, pressure), found " +
                         std::to_string(f.size()));
      continue;
    }
    double a = 0.0, p = 0.0;
    const bool angleOk = parseDouble(f[0], a), pressureOk = parseDouble(f[1], p);
    if (!angleOk)
      problems.push_back(at + "crank angle " + detail::quoteValue(f[0]) + " is not a number");
    if (!pressureOk)
      problems.push_back(at + "pressure " + detail::quoteValue(f[1]) + " is not a number");
    if (!angleOk || !pressureOk)
      continue;
    // Compared with the last good row, so one bad row gives one message.
    if (!angle.empty() && !(a > angle.back())) {
      problems.push_back(at + "crank angle " + f[0] +
                         " deg is not greater than the previous row's (" +
                         common::formatNumber(angle.back()) + " deg); angles must increase");
      continue;
    }
    if (!(p > 0.0)) {
      problems.push_back(at + "pressure " + f[1] + " must be positive (absolute pressure)");
      continue;
    }
    if (!std::isfinite(p * toPa)) {
      problems.push_back(at + "pressure " + f[1] + " overflows when converted to Pa");
      continue;
    }
    angle.push_back(a);
    pressure.push_back(p * toPa);
    lineOfRow.push_back(lineNo);
  }
  if (!problems.empty()) {
    std::string all;
    for (std::size_t i = 0; i < problems.size() && i < kMaxProblemLines; ++i)
      all += (i == 0 ? "" : "\n") + problems[i];
    if (problems.size() > kMaxProblemLines)
      all += "\n... and " + std::to_string(problems.size() - kMaxProblemLines) + " more problems";
    throw DeckError(all);
  }
  if (!haveHeader)
    throw DeckError(filePath + ": empty table (no header line)");
  try {
    return mbd::CylinderPressureCurve(std::move(angle), std::move(pressure));
  } catch (const mbd::PressureTableError& e) {
    // The curve counts 0-based data rows; name this file's line instead.
    if (e.row() && *e.row() < lineOfRow.size())
      throw DeckError(filePath + ":" + std::to_string(lineOfRow[*e.row()]) + ": " + e.what());
    throw DeckError(filePath + ": " + e.what());
  }
}

std::string formatPressureTableCsv(const std::vector<double>& crankAngle_deg,
                                   const std::vector<double>& pressure_Pa,
                                   const std::vector<std::string>& commentLines) {
  if (crankAngle_deg.size() != pressure_Pa.size())
    throw std::invalid_argument("formatPressureTableCsv: " + std::to_string(crankAngle_deg.size()) +
                                " angles but " + std::to_string(pressure_Pa.size()) +
                                " pressures");
  std::string text;
  for (const std::string& line : commentLines)
    text += "# " + line + "\n";
  text += "crank_angle_deg,pressure_bar\n";
  char row[64];
  for (std::size_t i = 0; i < crankAngle_deg.size(); ++i) {
    std::snprintf(row, sizeof row, "%.10g,%.8g\n", crankAngle_deg[i], pressure_Pa[i] / 1e5);
    text += row;
  }
  return text;
}

}  // namespace pistondyn::io
