#pragma once
/// \file
/// Units written in deck keys and table headers ("bore_mm", "speed_rpm", "pressure_bar")
/// and their conversion to SI. A key carries its unit as its last underscore-separated
/// part(s); DeckSection::getSI() reads such a key as a physical quantity and returns it in
/// SI, so a factory never multiplies by 1e-3 by hand.
///
/// The caller names the quantity it expects (a length, a pressure, ...): only that
/// quantity's units are matched against the key, so a key whose unit is not in the
/// table ("damping_Ns_per_mm" read as a Damping) is a programming error reported at once,
/// never silently converted by a shorter suffix that happens to match ("_mm").

#include <optional>
#include <string>
#include <vector>

namespace pistondyn::io {

/// The physical quantity a deck key's unit belongs to, with the units known for it.
enum class Quantity {
  Length,               ///< m, mm, um, nm, cm
  Area,                 ///< m2, cm2, mm2, um2
  Volume,               ///< m3, l, cm3, mm3
  Mass,                 ///< kg, g
  Time,                 ///< s, ms, us
  Angle,                ///< rad, mrad, urad, deg
  AngularSpeed,         ///< rad_per_s, radps, rpm
  Frequency,            ///< Hz, per_s
  Speed,                ///< mps, m_per_s, mm_per_s
  Acceleration,         ///< mps2, m_per_s2
  Force,                ///< N, kN, mN
  Moment,               ///< Nm, N_m, kNm, Nmm
  Pressure,             ///< Pa, kPa, MPa, GPa, bar, mbar
  DynamicViscosity,     ///< Pas, mPas, cP
  KinematicViscosity,   ///< m2_per_s, mm2_per_s, cSt
  Density,              ///< kg_per_m3, kg_m3, g_per_cm3
  Inertia,              ///< kg_m2, kg_mm2, g_mm2
  Stiffness,            ///< N_per_m, Npm, N_per_mm, N_per_um, kN_per_mm
  Damping,              ///< Ns_per_m, Nspm, Ns_per_mm
  RotationalStiffness,  ///< Nm_per_rad, Nmprad, Nm_per_deg
  RotationalDamping,    ///< Nms_per_rad, Nmsprad
  Power,                ///< W, kW
  Energy,               ///< J, kJ, mJ
  Temperature,          ///< K, degC (converted to K)
  ThermalExpansion,     ///< per_K, um_per_m_K
  WearCoefficient,      ///< m3_per_N_m, mm3_per_N_m (Archard k/H: volume per load and distance)
};

/// One unit a key may end with: "_" + suffix. SI value = value * factor + offset.
struct UnitSuffix {
  std::string suffix;    ///< as written at the end of a key, e.g. "mm"
  Quantity quantity;     ///< the quantity it measures
  double factor;         ///< to the SI unit
  std::string siSuffix;  ///< the SI unit as the project writes it, e.g. "m"
  double offset = 0.0;   ///< only for degC -> K
};

/// Every unit known for `quantity` (first entry: the SI unit itself).
std::vector<UnitSuffix> getUnits(Quantity quantity);
/// Human-readable name of a quantity ("length", "pressure", ...), for messages.
std::string getQuantityName(Quantity quantity);

/// The unit `key` ends with among the units of `quantity` (the longest that matches, after
/// an underscore), or nullopt if it ends with none of them.
std::optional<UnitSuffix> findUnitSuffix(const std::string& key, Quantity quantity);

/// `key` with its unit replaced by the SI one: ("clearance_um", um) -> "clearance_m".
std::string toSIKey(const std::string& key, const UnitSuffix& unit);

}  // namespace pistondyn::io
