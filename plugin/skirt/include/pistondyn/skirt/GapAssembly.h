#pragma once
/// \file
/// The piston-to-liner gap of one skirt side, assembled from the seven terms (thesis §2.1;
/// GapTerms.h) for a pose, every force evaluation.
///
/// Built once from the side's grid and the term parameters: everything that does not depend on
/// the pose is evaluated then (skirt profile + ovality and piston thermal growth per node, the
/// bore distortion's cos(n phi) / sin(n phi) per grid angle, the tables' slopes), and the hot
/// running clearance is computed and checked (HotRunningClearance.h: a negative one is
/// rejected). Per call, calc() fills a preallocated GapFields in place: h_rigid and its
/// derivatives from the pose, the liner terms at the bore heights the skirt rows reach
/// (Y = Y_pin + y) with their convective rates, the caller's elastic fields, and the sums.
///
/// Rates: gapRate_mps is dh/dt at a fixed skirt node (the film grid moves with the skirt):
///   rigid: -(de/dt + y cos alpha dalpha/dt) cos phi - dz_t/dt sin phi;
///   liner shape and liner thermal: (d/dY) v_y (convective; LinerShape.h, ThermalGrowth.h);
///   elastic: the caller's rates; skirt profile, piston thermal: 0.
/// dGap_dPose and squeezeBasis come from h_rigid only (the other terms do not depend on the
/// secondary pose in this linear model; RigidGap.h lists what is neglected).
///
/// Immutable after construction; calc() is const, keeps no state and allocates nothing, so one
/// GapAssembly may serve several threads, each with its own GapFields.

#include "pistondyn/skirt/GapFields.h"
#include "pistondyn/skirt/GapTerms.h"
#include "pistondyn/skirt/HotRunningClearance.h"
#include "pistondyn/skirt/LinerShape.h"
#include "pistondyn/skirt/PistonPose.h"
#include "pistondyn/skirt/SkirtSideGrid.h"
#include "pistondyn/skirt/ThermalGrowth.h"

namespace pistondyn::skirt {

/// The seven gap terms of one skirt side assembled per force evaluation (this file's
/// documentation).
class GapAssembly {
 public:
  /// Inputs:
  ///   grid        the skirt side (copied: the assembly keeps its own)
  ///   parameters  the terms' data and switches (GapTerms.h)
  /// Throws std::invalid_argument naming the member for bad data, or when the hot running
  /// clearance is negative (with its value and where).
  GapAssembly(const SkirtSideGrid& grid, const GapAssemblyParameters& parameters);

  const SkirtSideGrid& getGrid() const { return grid_; }            ///< the side (own copy)
  const GapTermSwitches& getSwitches() const { return switches_; }  ///< terms switched on
  double getColdRadialClearance_m() const { return c0_; }           ///< c0 [m]
  const HotRunningClearance& getHotRunningClearance() const { return hot_; }  ///< as computed
  /// Pose-independent terms as evaluated at construction (whether switched on or not) [m].
  const Eigen::ArrayXd& getSkirtProfile_m() const { return skirtProfile_; }
  const Eigen::ArrayXd& getPistonThermal_m() const { return pistonThermal_; }  ///< see above
  const SkirtProfile& getSkirtProfile() const { return profile_; }  ///< profile + ovality
  const LinerShape& getLinerShape() const { return linerShape_; }   ///< bore distortion
  const LinerThermalGrowth& getLinerThermalGrowth() const { return linerThermal_; }  ///< liner

  /// Fields sized for this side, all zero (the elastic inputs included).
  GapFields makeFields() const;

  /// Fills the gap fields for a pose.
  /// Inputs:
  ///   pose, rate         secondary/tertiary pose of the piston and its rates (finite)
  ///   pinHeight_m        Y_pin, pin-axis height above the crank axis [m] (finite)
  ///   axialVelocity_mps  v_y = dY_pin/dt [m/s] (finite)
  ///   out                fields from makeFields(); its elastic members are read (inputs)
  /// Outputs: every other member of out (see GapFields.h).
  /// Allocates nothing. Throws std::invalid_argument for a non-finite input or fields of the
  /// wrong size (naming the member).
  void calc(const PistonPose& pose, const PistonPoseRate& rate, double pinHeight_m,
            double axialVelocity_mps, GapFields& out) const;

 private:
  SkirtSideGrid grid_;
  GapTermSwitches switches_;
  double c0_;
  SkirtProfile profile_;
  LinerShape linerShape_;
  PistonThermalGrowth pistonThermalGrowth_;
  LinerThermalGrowth linerThermal_;
  Eigen::ArrayXd skirtProfile_, pistonThermal_;
  Eigen::ArrayXd fixedSkirtSlope_;  // d/dy of the switched-on profile and piston thermal terms
  HotRunningClearance hot_;
};

}  // namespace pistondyn::skirt
