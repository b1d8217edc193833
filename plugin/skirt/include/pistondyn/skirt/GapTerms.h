#pragma once
/// \file
/// The seven terms of the piston-to-liner gap (thesis §2.1, eq. 1; docs/DESIGN.md §4),
///
///   h = h_rigid + h_skirtProfile + h_linerShape + h_pistonThermal + h_linerThermal
///       + h_pistonElastic + h_linerElastic,
///
/// each its own named nodal field, each switchable, positive terms open the gap. The inputs of
/// all of them, gathered for GapAssembly.

#include <limits>

#include "pistondyn/skirt/LinerShape.h"
#include "pistondyn/skirt/SkirtProfile.h"
#include "pistondyn/skirt/ThermalGrowth.h"

namespace pistondyn::skirt {

/// Which terms enter the gap (all on by default). A term switched off is not computed, reads 0
/// in GapFields and adds nothing (the elastic fields, which the caller writes, are then left as
/// written but not added). Switching h_rigid off also removes the clearance c0.
struct GapTermSwitches {
  bool rigid = true;          ///< h_rigid (and c0)
  bool skirtProfile = true;   ///< h_skirtProfile
  bool linerShape = true;     ///< h_linerShape
  bool pistonThermal = true;  ///< h_pistonThermal
  bool linerThermal = true;   ///< h_linerThermal
  bool pistonElastic = true;  ///< h_pistonElastic (the caller's field)
  bool linerElastic = true;   ///< h_linerElastic (the caller's field)
};

/// The range of the pin-axis height above the crank axis over the cycle (BDC to TDC) [m]: where
/// the hot running clearance is looked for along the liner.
struct PistonTravel {
  double lowestPinHeight_m = std::numeric_limits<double>::quiet_NaN();   ///< at BDC, required
  double highestPinHeight_m = std::numeric_limits<double>::quiet_NaN();  ///< at TDC, required
};

/// The data of all seven gap terms and their switches, for GapAssembly.
struct GapAssemblyParameters {
  /// c0: cold radial clearance at the profile's reference (zero-drop) point, centred piston,
  /// at referenceTemperature_degC [m], finite (required).
  double coldRadialClearance_m = std::numeric_limits<double>::quiet_NaN();
  /// Y_top: height of the liner top above the crank axis [m], finite; required when the bore
  /// distortion or the liner temperature is given (depths are measured from it).
  double linerTopHeight_m = std::numeric_limits<double>::quiet_NaN();
  /// T_ref: temperature of the cold data (clearance, profile, bore distortion) [degC],
  /// default 20.
  double referenceTemperature_degC = 20.0;
  PistonTravel travel;                    ///< required (hot running clearance)
  SkirtProfileParameters skirtProfile;    ///< h_skirtProfile; default cylindrical and round
  BoreDistortionParameters linerShape;    ///< h_linerShape; default ideal cylinder
  PistonThermalParameters pistonThermal;  ///< h_pistonThermal; default none
  LinerThermalParameters linerThermal;    ///< h_linerThermal; default none
  GapTermSwitches terms;                  ///< default all on
};

}  // namespace pistondyn::skirt
