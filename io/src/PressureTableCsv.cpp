#include "pistondyn/io/PressureTableCsv.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "pistondyn/io/DeckError.h"

namespace pistondyn::io {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos)
    return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string f;
  while (std::getline(ss, f, ','))
    out.push_back(trim(f));
  if (!line.empty() && line.back() == ',')
    out.emplace_back();
  return out;
}

// A finite number filling the whole field. Underflow (e.g. 1e-400) reads as 0 or a
// subnormal and is accepted as that value; overflow, "nan" and "inf" are rejected.
bool parseDouble(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value)) return false;
  return errno != ERANGE || std::abs(value) < 1.0;  // ERANGE with |value| < 1 = underflow
}

}  // namespace

mbd::CylinderPressureCurve readPressureTableCsv(const std::string& filePath) {
  std::ifstream in(filePath);
  if (!in)
    throw DeckError(filePath + ": cannot open the cylinder-pressure table");
  static const std::map<std::string, double> kUnits = {
      {"pressure_Pa", 1.0}, {"pressure_kPa", 1e3}, {"pressure_bar", 1e5}, {"pressure_MPa", 1e6}};

  std::vector<double> angle, pressure;
  std::vector<int> lineOfRow;
  double toPa = 0.0;
  bool haveHeader = false;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (lineNo == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 BOM
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
      haveHeader = true;
      continue;
    }
    if (f.size() != 2) {
      throw DeckError(at + "expected 2 columns (crank angle, pressure), found " +
                      std::to_string(f.size()));
    }
    double a = 0.0, p = 0.0;
    if (!parseDouble(f[0], a))
      throw DeckError(at + "crank angle '" + f[0] + "' is not a number");
    if (!parseDouble(f[1], p))
      throw DeckError(at + "pressure '" + f[1] + "' is not a number");
    if (!angle.empty() && !(a > angle.back())) {
      throw DeckError(at + "crank angle " + f[0] + " deg is not greater than the previous row's (" +
                      std::to_string(angle.back()) + " deg); angles must increase");
    }
    if (!(p > 0.0)) {
      throw DeckError(at + "pressure " + f[1] + " must be positive (absolute pressure)");
    }
    angle.push_back(a);
    pressure.push_back(p * toPa);
    lineOfRow.push_back(lineNo);
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

}  // namespace pistondyn::io
