#pragma once
// How the program shows a number to a person (report pages, figure axes): the units it knows,
// one table of display units per quantity, and significant digits that mean something
// (31.0 bar, 348.7 cm³, 80.0 mm, fmep 2.81 kPa, min film 1.23 µm).
//
// A value is named as the result files name it: a summary key or a column, its unit as the
// suffix ("peak_cylinder_pressure_Pa", "fmep_kPa", "film_pressure_max_Pa", "u_lat_um",
// "inputs.gas.crankcase_pressure_Pa"; only the last dotted part counts). Its display format:
// the first named rule (DisplayUnits.cpp, kNamedRules) whose pattern matches the name without
// its unit - a peak cylinder pressure in bar, film pressures in MPa, shares in % - else the
// default for the unit it is written in (Pa in kPa, m in mm, um in µm, m3 in cm³, rad in
// mrad, kg in g). The same format serves the summary table, the headline and the axes of the
// figures, so that a quantity reads the same everywhere.

#include <optional>
#include <string>
#include <utility>

namespace pistondyn::app::units {

// A unit as names write it ("um"), what it measures, its factor to SI and how it is shown.
struct Unit {
  const char* code;
  const char* quantity;
  double toSI;
  const char* text;
};
// nullptr if unknown.
const Unit* findUnit(const std::string& code);
// The factor from unit `from` to unit `to` of the same quantity ("um" -> "mm": 1e-3);
// nullopt if either is unknown or they measure different quantities.
std::optional<double> conversionFactor(const std::string& from, const std::string& to);
// How a unit is written for a person ("um" -> "µm", "m3" -> "m³", "" -> "").
std::string getUnitText(const std::string& code);

struct DisplayFormat {
  std::string unit;                 // code of the unit shown ("bar"; "" dimensionless; "%")
  double factor = 1.0;              // from the unit the name is written in to `unit`
  int significant = 3;              // significant digits shown ...
  std::optional<int> maxDecimals;   // ... or at most this many decimals (crank angles: 1)
};
// The display format of a named value (this file's top comment). A name whose unit is not
// known is shown as written, 3 significant digits.
DisplayFormat getDisplayFormat(const std::string& name);

// `value` to `significant` significant digits without an exponent where that stays readable
// (12340 for 12340.28 at 3 digits: the integer part is never rounded away; 0.000123), with an
// exponent below 1e-4 (1.23e-05); "0" for zero, no "-0".
std::string formatSignificant(double value, int significant);
// `value` with at most `decimals` decimals, trailing zeros dropped (382.5, 717).
std::string formatDecimals(double value, int decimals);

// The number of a named value in its display unit: formatDisplayNumber("peak_cylinder_
// pressure_Pa", 3101484.2) == "31.0".
std::string formatDisplayNumber(const std::string& name, double value);
// ... with its unit: "31.0 bar", "717°", "28.9 %", "2.81 kPa", "0.820" (dimensionless).
std::string formatDisplayValue(const std::string& name, double value);
// The text of the display unit of a named value ("bar", "µm", "" for none).
std::string getDisplayUnitText(const std::string& name);

// The last dotted part of a name split into the name and its unit: the longest unit of the
// table it ends with after an underscore ("film_pressure_max_Pa" -> {"film_pressure_max",
// "Pa"}; {"fill_fraction_mean", ""} when none).
std::pair<std::string, std::string> splitUnit(const std::string& name);

// A name for a person: "min_h_over_sigma_antithrust_um" -> "min h/σ anti-thrust" (the unit
// suffix dropped, underscores as spaces, h_over_sigma as h/σ, antithrust as anti-thrust).
std::string describeName(const std::string& name);

}  // namespace pistondyn::app::units
