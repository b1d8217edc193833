#include "pistondyn/io/Units.h"

#include <cmath>

namespace pistondyn::io {
namespace {

using Q = Quantity;

const std::vector<UnitSuffix>& allUnits() {
  static const std::vector<UnitSuffix> kUnits = {
      {"m", Q::Length, 1.0, "m"},
      {"cm", Q::Length, 1e-2, "m"},
      {"mm", Q::Length, 1e-3, "m"},
      {"um", Q::Length, 1e-6, "m"},
      {"nm", Q::Length, 1e-9, "m"},
      {"m2", Q::Area, 1.0, "m2"},
      {"cm2", Q::Area, 1e-4, "m2"},
      {"mm2", Q::Area, 1e-6, "m2"},
      {"um2", Q::Area, 1e-12, "m2"},
      {"m3", Q::Volume, 1.0, "m3"},
      {"l", Q::Volume, 1e-3, "m3"},
      {"cm3", Q::Volume, 1e-6, "m3"},
      {"mm3", Q::Volume, 1e-9, "m3"},
      {"kg", Q::Mass, 1.0, "kg"},
      {"g", Q::Mass, 1e-3, "kg"},
      {"s", Q::Time, 1.0, "s"},
      {"ms", Q::Time, 1e-3, "s"},
      {"us", Q::Time, 1e-6, "s"},
      {"rad", Q::Angle, 1.0, "rad"},
      {"mrad", Q::Angle, 1e-3, "rad"},
      {"urad", Q::Angle, 1e-6, "rad"},
      {"deg", Q::Angle, M_PI / 180.0, "rad"},
      {"rad_per_s", Q::AngularSpeed, 1.0, "rad_per_s"},
      {"radps", Q::AngularSpeed, 1.0, "rad_per_s"},
      {"rpm", Q::AngularSpeed, M_PI / 30.0, "rad_per_s"},
      {"Hz", Q::Frequency, 1.0, "Hz"},
      {"per_s", Q::Frequency, 1.0, "Hz"},
      {"mps", Q::Speed, 1.0, "mps"},
      {"m_per_s", Q::Speed, 1.0, "mps"},
      {"mm_per_s", Q::Speed, 1e-3, "mps"},
      {"mps2", Q::Acceleration, 1.0, "mps2"},
      {"m_per_s2", Q::Acceleration, 1.0, "mps2"},
      {"N", Q::Force, 1.0, "N"},
      {"kN", Q::Force, 1e3, "N"},
      {"mN", Q::Force, 1e-3, "N"},
      {"Nm", Q::Moment, 1.0, "Nm"},
      {"N_m", Q::Moment, 1.0, "Nm"},
      {"kNm", Q::Moment, 1e3, "Nm"},
      {"Nmm", Q::Moment, 1e-3, "Nm"},
      {"Pa", Q::Pressure, 1.0, "Pa"},
      {"kPa", Q::Pressure, 1e3, "Pa"},
      {"MPa", Q::Pressure, 1e6, "Pa"},
      {"GPa", Q::Pressure, 1e9, "Pa"},
      {"bar", Q::Pressure, 1e5, "Pa"},
      {"mbar", Q::Pressure, 1e2, "Pa"},
      {"Pas", Q::DynamicViscosity, 1.0, "Pas"},
      {"mPas", Q::DynamicViscosity, 1e-3, "Pas"},
      {"cP", Q::DynamicViscosity, 1e-3, "Pas"},
      {"m2_per_s", Q::KinematicViscosity, 1.0, "m2_per_s"},
      {"mm2_per_s", Q::KinematicViscosity, 1e-6, "m2_per_s"},
      {"cSt", Q::KinematicViscosity, 1e-6, "m2_per_s"},
      {"kg_per_m3", Q::Density, 1.0, "kg_per_m3"},
      {"kg_m3", Q::Density, 1.0, "kg_per_m3"},
      {"g_per_cm3", Q::Density, 1e3, "kg_per_m3"},
      {"kg_m2", Q::Inertia, 1.0, "kg_m2"},
      {"kg_mm2", Q::Inertia, 1e-6, "kg_m2"},
      {"g_mm2", Q::Inertia, 1e-9, "kg_m2"},
      {"N_per_m", Q::Stiffness, 1.0, "N_per_m"},
      {"Npm", Q::Stiffness, 1.0, "N_per_m"},
      {"N_per_mm", Q::Stiffness, 1e3, "N_per_m"},
      {"N_per_um", Q::Stiffness, 1e6, "N_per_m"},
      {"kN_per_mm", Q::Stiffness, 1e6, "N_per_m"},
      {"Ns_per_m", Q::Damping, 1.0, "Ns_per_m"},
      {"Nspm", Q::Damping, 1.0, "Ns_per_m"},
      {"Ns_per_mm", Q::Damping, 1e3, "Ns_per_m"},
      {"Nm_per_rad", Q::RotationalStiffness, 1.0, "Nm_per_rad"},
      {"Nmprad", Q::RotationalStiffness, 1.0, "Nm_per_rad"},
      {"Nm_per_deg", Q::RotationalStiffness, 180.0 / M_PI, "Nm_per_rad"},
      {"Nms_per_rad", Q::RotationalDamping, 1.0, "Nms_per_rad"},
      {"Nmsprad", Q::RotationalDamping, 1.0, "Nms_per_rad"},
      {"W", Q::Power, 1.0, "W"},
      {"kW", Q::Power, 1e3, "W"},
      {"J", Q::Energy, 1.0, "J"},
      {"kJ", Q::Energy, 1e3, "J"},
      {"mJ", Q::Energy, 1e-3, "J"},
      {"K", Q::Temperature, 1.0, "K"},
      {"degC", Q::Temperature, 1.0, "K", 273.15},
      {"per_K", Q::ThermalExpansion, 1.0, "per_K"},
      {"um_per_m_K", Q::ThermalExpansion, 1e-6, "per_K"},
      {"m3_per_N_m", Q::WearCoefficient, 1.0, "m3_per_N_m"},
      {"mm3_per_N_m", Q::WearCoefficient, 1e-9, "m3_per_N_m"},
  };
  return kUnits;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

std::vector<UnitSuffix> getUnits(Quantity quantity) {
  std::vector<UnitSuffix> out;
  for (const auto& u : allUnits()) {
    if (u.quantity == quantity)
      out.push_back(u);
  }
  return out;
}

std::string getQuantityName(Quantity quantity) {
  switch (quantity) {
    case Q::Length:
      return "length";
    case Q::Area:
      return "area";
    case Q::Volume:
      return "volume";
    case Q::Mass:
      return "mass";
    case Q::Time:
      return "time";
    case Q::Angle:
      return "angle";
    case Q::AngularSpeed:
      return "angular speed";
    case Q::Frequency:
      return "frequency";
    case Q::Speed:
      return "speed";
    case Q::Acceleration:
      return "acceleration";
    case Q::Force:
      return "force";
    case Q::Moment:
      return "moment";
    case Q::Pressure:
      return "pressure";
    case Q::DynamicViscosity:
      return "dynamic viscosity";
    case Q::KinematicViscosity:
      return "kinematic viscosity";
    case Q::Density:
      return "density";
    case Q::Inertia:
      return "moment of inertia";
    case Q::Stiffness:
      return "stiffness";
    case Q::Damping:
      return "damping";
    case Q::RotationalStiffness:
      return "rotational stiffness";
    case Q::RotationalDamping:
      return "rotational damping";
    case Q::Power:
      return "power";
    case Q::Energy:
      return "energy";
    case Q::Temperature:
      return "temperature";
    case Q::ThermalExpansion:
      return "thermal expansion coefficient";
    case Q::WearCoefficient:
      return "wear coefficient";
  }
  return "quantity";
}

std::optional<UnitSuffix> findUnitSuffix(const std::string& key, Quantity quantity) {
  std::optional<UnitSuffix> best;
  for (const auto& u : allUnits()) {
    if (u.quantity != quantity || !endsWith(key, "_" + u.suffix) ||
        key.size() == u.suffix.size() + 1) {
      continue;
    }
    if (!best || u.suffix.size() > best->suffix.size())
      best = u;
  }
  return best;
}

std::string toSIKey(const std::string& key, const UnitSuffix& unit) {
  return key.substr(0, key.size() - unit.suffix.size()) + unit.siSuffix;
}

}  // namespace pistondyn::io
