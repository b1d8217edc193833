#pragma once
/// \file
/// h_pistonThermal and h_linerThermal (thesis §2.1, h_4 and h_5): radial thermal growth of skirt
/// and bore from temperature fields and linear expansion coefficients,
///
///   h_pistonThermal = -R alpha_p (T_p(y) - T_ref)     (a hotter skirt grows: closes the gap)
///   h_linerThermal  = +R alpha_l (T_l(Y) - T_ref)     (a hotter bore grows: opens the gap)
///
/// R the nominal skirt radius (the radius the growth is taken on: the difference between skirt
/// and bore radius, ~c0, changes the growth by c0/R ~ 1e-3 of itself), T_ref the reference
/// temperature at which the cold clearance, the profile and the bore distortion are given
/// (GapAssemblyParameters::referenceTemperature_degC, default 20 degC). The growth is the free
/// linear expansion of each radius; thermal distortion that is not uniform around the
/// circumference belongs in the bore distortion or in the elastic/given displacement fields.
///
/// Temperature fields (all temperatures in degC, above absolute zero):
///   piston: a table of height above the pin axis [m] vs temperature (per zone: Linear; or
///           Pchip), or one temperature per skirt node (nodalTemperature_degC, overrides the
///           table);
///   liner:  a table of depth below the liner top [m] vs temperature (Linear or Pchip); a skirt
///           node at piston-frame height y sits at Y = Y_pin + y, depth = Y_top - Y.
/// Outside a table's range the end temperatures hold (constant extension). An empty table is
/// T = T_ref (no growth).
///
/// Rates at a skirt node: the piston term is fixed to the skirt (rate 0); the liner term moves
/// with the liner, so a skirt node sees d h_linerThermal/dt = R alpha_l (dT_l/dY) v_y
/// = -R alpha_l (dT_l/d depth) v_y (as for the bore distortion, LinerShape.h). With a Linear
/// table the rate jumps where a node crosses a table row (the slope of the interval below in
/// depth, i.e. the one towards the liner bottom, at the row itself).

#include <limits>

#include <Eigen/Core>

#include "pistondyn/skirt/InterpolatedTable.h"
#include "pistondyn/skirt/SkirtSideGrid.h"

namespace pistondyn::skirt {

/// The skirt's temperature field and expansion coefficient.
struct PistonThermalParameters {
  /// Linear expansion coefficient of the skirt alpha_p [1/K], >= 0 and finite; required when a
  /// temperature is given (default NaN = not set).
  double expansionCoefficient_perK = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd height_m;          ///< height above the pin axis [m], strictly increasing
  Eigen::VectorXd temperature_degC;  ///< skirt temperature [degC] at those heights
  Interpolation interpolation = Interpolation::Linear;  ///< default Linear (per zone)
  /// Optional: one temperature per skirt node [degC] (nodeCount() entries, k = i + nPhi j);
  /// overrides the table when not empty.
  Eigen::ArrayXd nodalTemperature_degC;
};

/// The bore wall's temperature along the depth and the liner's expansion coefficient.
struct LinerThermalParameters {
  /// Linear expansion coefficient of the liner alpha_l [1/K], >= 0 and finite; required when a
  /// temperature is given (default NaN = not set).
  double expansionCoefficient_perK = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd depth_m;           ///< depth below the liner top [m], strictly increasing
  Eigen::VectorXd temperature_degC;  ///< bore wall temperature [degC] at those depths
  Interpolation interpolation = Interpolation::Linear;  ///< default Linear (per zone)
};

/// The piston thermal gap term: -R alpha_p (T - T_ref) (the documentation of ThermalGrowth.h).
class PistonThermalGrowth {
 public:
  /// No growth.
  PistonThermalGrowth() = default;

  /// Inputs: the field, the side (for R and the node count) and T_ref [degC].
  /// Throws std::invalid_argument naming the member and row.
  PistonThermalGrowth(const PistonThermalParameters& parameters, const SkirtSideGrid& grid,
                      double referenceTemperature_degC);

  bool isActive() const { return active_; }           ///< a temperature was given
  bool isNodal() const { return nodal_.size() > 0; }  ///< per-node temperatures
  /// h_pistonThermal [m] at height y_m [m] from the table (0 without one).
  double calcGapFromTable_m(double y_m) const;
  /// h_pistonThermal at every node of the grid it was built for [m] (preallocated).
  void calcField(const SkirtSideGrid& grid, Eigen::Ref<Eigen::ArrayXd> gap_m) const;
  /// The nodal field as given (empty unless isNodal()).
  const Eigen::ArrayXd& getNodalTemperature_degC() const { return nodal_; }
  double getGrowthPerKelvin_m() const { return radiusAlpha_m_; }  ///< R alpha_p [m/K]
  double getReferenceTemperature_degC() const { return tRef_; }   ///< T_ref [degC]

 private:
  bool active_ = false;
  double radiusAlpha_m_ = 0.0, tRef_ = 20.0;
  InterpolatedTable table_;
  Eigen::ArrayXd nodal_;
};

/// Value and rate of the liner term at one bore height.
struct LinerThermalSample {
  double gap_m = 0.0;             ///< h_linerThermal [m]
  double dGap_dBoreHeight = 0.0;  ///< d h_linerThermal / dY [m/m]
};

/// The liner thermal gap term: R alpha_l (T(depth) - T_ref) (the documentation of ThermalGrowth.h).
class LinerThermalGrowth {
 public:
  /// No growth.
  LinerThermalGrowth() = default;

  /// Inputs: the field, the side (R, heights), Y_top [m] (finite when a table is given), T_ref.
  /// Throws std::invalid_argument naming the member and row.
  LinerThermalGrowth(const LinerThermalParameters& parameters, const SkirtSideGrid& grid,
                     double linerTopHeight_m, double referenceTemperature_degC);

  bool isActive() const { return active_; }  ///< a temperature table was given
  /// h_linerThermal and d/dY at bore height boreHeight_m [m].
  LinerThermalSample calcSample(double boreHeight_m) const;
  /// h_linerThermal and its rate at every node (preallocated, nodeCount() entries); the term is
  /// axisymmetric, so one value per grid row. Allocates nothing.
  void calcField(double pinHeight_m, double axialVelocity_mps, Eigen::Ref<Eigen::ArrayXd> gap_m,
                 Eigen::Ref<Eigen::ArrayXd> gapRate_mps) const;
  double getGrowthPerKelvin_m() const { return radiusAlpha_m_; }           ///< R alpha_l [m/K]
  double getLinerTopHeight_m() const { return linerTop_m_; }               ///< Y_top [m]
  const InterpolatedTable& getTemperatureTable() const { return table_; }  ///< against depth

 private:
  bool active_ = false;
  double radiusAlpha_m_ = 0.0, tRef_ = 20.0, linerTop_m_ = 0.0;
  int nPhi_ = 0;
  Eigen::VectorXd y_m_;
  InterpolatedTable table_;
};

}  // namespace pistondyn::skirt
