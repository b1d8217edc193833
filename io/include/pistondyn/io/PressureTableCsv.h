#pragma once
/// \file
/// Reads a cylinder-pressure table: CSV, '#' comment lines allowed, a header naming the
/// two columns with their units, then one row per crank angle:
///
///   # any comment
///   crank_angle_deg,pressure_bar
///   0,41.3
///   0.5,41.9
///
/// The pressure column may be pressure_Pa, pressure_kPa, pressure_bar or pressure_MPa
/// (absolute). Angles: crank angle from firing TDC, strictly increasing, covering 720
/// deg (see mbd::CylinderPressureCurve). Errors name the file and line; the rows' problems
/// are reported together (up to 20 lines, then how many more).

#include <string>
#include <vector>

#include "pistondyn/mbd_models/CylinderPressureCurve.h"

namespace pistondyn::io {

/// Throws DeckError "<file>:<line>: ..." on any problem. `pressureUnit`, if given, receives
/// the unit the header names ("bar" of pressure_bar).
mbd::CylinderPressureCurve readPressureTableCsv(const std::string& filePath,
                                                std::string* pressureUnit = nullptr);

/// The text of a table readPressureTableCsv reads back: each of `commentLines` as a "# "
/// line, the header crank_angle_deg,pressure_bar, then one row per angle ("%.10g,%.8g": the
/// angle to 10 and the pressure in bar to 8 significant digits). `pressure_Pa` absolute,
/// as long as `crankAngle_deg` (std::invalid_argument otherwise).
std::string formatPressureTableCsv(const std::vector<double>& crankAngle_deg,
                                   const std::vector<double>& pressure_Pa,
                                   const std::vector<std::string>& commentLines);

}  // namespace pistondyn::io
