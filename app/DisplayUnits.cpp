#include "DisplayUnits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace pistondyn::app::units {
namespace {

// Every unit the result files, the deck's SI inputs and the displays use.
const Unit kUnits[] = {
    {"N", "force", 1.0, "N"},
    {"kN", "force", 1e3, "kN"},
    {"Nm", "moment", 1.0, "N·m"},
    {"m", "length", 1.0, "m"},
    {"mm", "length", 1e-3, "mm"},
    {"um", "length", 1e-6, "µm"},
    {"rad", "angle", 1.0, "rad"},
    {"mrad", "angle", 1e-3, "mrad"},
    {"deg", "angle", M_PI / 180.0, "°"},
    {"Pa", "pressure", 1.0, "Pa"},
    {"kPa", "pressure", 1e3, "kPa"},
    {"MPa", "pressure", 1e6, "MPa"},
    {"GPa", "pressure", 1e9, "GPa"},
    {"bar", "pressure", 1e5, "bar"},
    {"W", "power", 1.0, "W"},
    {"kW", "power", 1e3, "kW"},
    {"J", "energy", 1.0, "J"},
    {"mJ", "energy", 1e-3, "mJ"},
    {"", "dimensionless", 1.0, ""},
    {"%", "dimensionless", 1e-2, "%"},
    {"m3", "volume", 1.0, "m³"},
    {"cm3", "volume", 1e-6, "cm³"},
    {"mm3", "volume", 1e-9, "mm³"},
    {"s", "time", 1.0, "s"},
    {"kg", "mass", 1.0, "kg"},
    {"g", "mass", 1e-3, "g"},
    {"kg_m2", "inertia", 1.0, "kg·m²"},
    {"kg_mm2", "inertia", 1e-6, "kg·mm²"},
    {"mps", "speed", 1.0, "m/s"},
    {"mm_per_s", "speed", 1e-3, "mm/s"},
    {"um_per_h", "speed", 1e-6 / 3600.0, "µm/h"},
    {"mps2", "acceleration", 1.0, "m/s²"},
    {"m_per_s2", "acceleration", 1.0, "m/s²"},
    {"rad_per_s", "angular speed", 1.0, "rad/s"},
    {"rpm", "angular speed", 2.0 * M_PI / 60.0, "rpm"},
    {"Pas", "viscosity", 1.0, "Pa·s"},
    {"mPas", "viscosity", 1e-3, "mPa·s"},
    {"mm3ph", "volume rate", 1e-9 / 3600.0, "mm³/h"},
    {"N_per_m", "stiffness", 1.0, "N/m"},
    {"N_per_mm", "stiffness", 1e3, "N/mm"},
    {"kg_per_m3", "density", 1.0, "kg/m³"},
    {"per_K", "expansion", 1.0, "1/K"},
    {"m3_per_N_m", "wear coefficient", 1.0, "m³/(N·m)"},
    {"mm3_per_N_m", "wear coefficient", 1e-9, "mm³/(N·m)"},
    {"degC", "temperature", 1.0, "°C"},
};

// The default display unit of each written unit (the unit itself when not listed).
const std::pair<const char*, const char*> kDefaultDisplay[] = {
    {"m", "mm"},     {"Pa", "kPa"},       {"m3", "cm3"},   {"rad", "mrad"},
    {"kg", "g"},     {"kg_m2", "kg_mm2"}, {"rad_per_s", "rpm"}, {"Pas", "mPas"},
    {"m_per_s2", "mps2"}, {"mps", "mps"},
};

// Quantities shown in a unit of their own: a '*' at either end of the pattern matches any
// text. First match wins.
struct NamedRule {
  const char* pattern;  // the name without its unit
  const char* unit;
  int significant;
};
const NamedRule kNamedRules[] = {
    {"peak_cylinder_pressure", "bar", 3},
    {"cylinder_pressure", "bar", 3},
    {"crankcase_pressure", "bar", 3},
    {"displacement", "cm3", 4},
    {"film_pressure*", "MPa", 3},
    {"contact_pressure*", "MPa", 3},
    {"*youngs_modulus", "GPa", 3},
    {"gas_force", "kN", 3},
    {"conrod_force*", "kN", 3},
    {"indicated_power", "kW", 3},
    {"max_abs_tilt", "mrad", 3},
    {"*_share*", "%", 3},
    {"energy_balance_relative_error", "%", 3},
};

bool matches(const std::string& pattern, const std::string& name) {
  const bool head = !pattern.empty() && pattern.front() == '*';
  const bool tail = pattern.size() > 1 && pattern.back() == '*';
  const std::string core = pattern.substr(head ? 1 : 0, pattern.size() - head - tail);
  if (head && tail)
    return name.find(core) != std::string::npos;
  if (head)
    return name.size() >= core.size() && name.compare(name.size() - core.size(), core.size(), core) == 0;
  if (tail)
    return name.rfind(core, 0) == 0;
  return name == core;
}

}  // namespace

// A unit is not taken when what remains ends in "_per" (a compound unit not in the table,
// "damping_Ns_per_m" is not a length).
std::pair<std::string, std::string> splitUnit(const std::string& dotted) {
  const std::size_t dot = dotted.rfind('.');
  const std::string name = dot == std::string::npos ? dotted : dotted.substr(dot + 1);
  const Unit* best = nullptr;
  for (const Unit& u : kUnits) {
    const std::size_t n = std::strlen(u.code);
    if (n == 0 || name.size() <= n + 1 || name.compare(name.size() - n, n, u.code) != 0 ||
        name[name.size() - n - 1] != '_')
      continue;
    const std::string rest = name.substr(0, name.size() - n - 1);
    if (rest.size() >= 4 && rest.compare(rest.size() - 4, 4, "_per") == 0)
      continue;
    if (best == nullptr || n > std::strlen(best->code))
      best = &u;
  }
  if (best == nullptr)
    return {name, ""};
  return {name.substr(0, name.size() - std::strlen(best->code) - 1), best->code};
}

const Unit* findUnit(const std::string& code) {
  for (const Unit& u : kUnits) {
    if (code == u.code)
      return &u;
  }
  return nullptr;
}

std::optional<double> conversionFactor(const std::string& from, const std::string& to) {
  const Unit* a = findUnit(from);
  const Unit* b = findUnit(to);
  if (a == nullptr || b == nullptr || std::strcmp(a->quantity, b->quantity) != 0)
    return std::nullopt;
  return a->toSI / b->toSI;
}

std::string getUnitText(const std::string& code) {
  const Unit* u = findUnit(code);
  return u ? u->text : code;
}

DisplayFormat getDisplayFormat(const std::string& name) {
  const auto [bare, written] = splitUnit(name);
  DisplayFormat f;
  f.unit = written;
  for (const auto& [from, to] : kDefaultDisplay) {
    if (written == from)
      f.unit = to;
  }
  for (const NamedRule& rule : kNamedRules) {
    if (matches(rule.pattern, bare) && conversionFactor(written, rule.unit)) {
      f.unit = rule.unit;
      f.significant = rule.significant;
      break;
    }
  }
  f.factor = conversionFactor(written, f.unit).value_or(1.0);
  if (f.unit == "deg")
    f.maxDecimals = 1;  // crank angles: to the tenth of a degree, 717 rather than 717.0
  return f;
}

std::string formatSignificant(double value, int significant) {
  if (!std::isfinite(value))
    return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
  if (value == 0.0)
    return "0";
  const int digits = std::max(1, significant);
  // The exponent after rounding to `digits` (9.996 at 3 digits is 10.0, exponent 1).
  char probe[64];
  std::snprintf(probe, sizeof probe, "%.*e", digits - 1, value);
  const int exponent = std::atoi(std::strchr(probe, 'e') + 1);
  std::string text;
  if (exponent < -4) {
    text = probe;  // 1.23e-05
  } else {
    char fixed[400];
    std::snprintf(fixed, sizeof fixed, "%.*f", std::max(0, digits - 1 - exponent), value);
    text = fixed;
  }
  if (text.find_first_not_of("-0.") == std::string::npos || text.rfind("-0e", 0) == 0)
    return "0";
  return text;
}

std::string formatDecimals(double value, int decimals) {
  if (!std::isfinite(value))
    return formatSignificant(value, 1);
  char text[400];
  std::snprintf(text, sizeof text, "%.*f", std::max(0, decimals), value);
  std::string s = text;
  if (s.find('.') != std::string::npos) {
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.')
      s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

std::string formatDisplayNumber(const std::string& name, double value) {
  const DisplayFormat f = getDisplayFormat(name);
  const double v = value * f.factor;
  return f.maxDecimals ? formatDecimals(v, *f.maxDecimals) : formatSignificant(v, f.significant);
}

std::string formatDisplayValue(const std::string& name, double value) {
  const DisplayFormat f = getDisplayFormat(name);
  const std::string number = formatDisplayNumber(name, value);
  if (f.unit.empty())
    return number;
  if (f.unit == "deg")
    return number + "°";
  return number + " " + getUnitText(f.unit);
}

std::string getDisplayUnitText(const std::string& name) {
  return getUnitText(getDisplayFormat(name).unit);
}

std::string describeName(const std::string& name) {
  std::string s = splitUnit(name).first;
  const std::pair<const char*, const char*> words[] = {
      {"h_over_sigma", "h/σ"}, {"antithrust", "anti-thrust"}, {"max_abs_", "max |"}};
  for (const auto& [from, to] : words) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1))
      s.replace(at, std::strlen(from), to);
  }
  if (s.rfind("max |", 0) == 0)
    s += "|";
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

}  // namespace pistondyn::app::units
