#pragma once
/// \file
/// The nodal fields one GapAssembly::calc() fills: the total gap, its rate, each of the seven
/// terms (GapTerms.h) and the derivatives with respect to the pose and its rates. Nodal order
/// k = i + nPhi j (SkirtSideGrid.h). Make one with GapAssembly::makeFields() (sized, zeroed) and
/// reuse it every call: calc() writes in place and allocates nothing.
///
/// Inputs among the fields: the elastic terms. The caller writes pistonElastic_m,
/// linerElastic_m and their rates (zero after makeFields()) before calc(); calc() adds them to
/// the gap and the rate (when switched on) and never writes them. Their rates are the caller's:
/// the rate of a liner displacement at a skirt node includes its convection along the bore.

#include <Eigen/Core>

namespace pistondyn::skirt {

/// The nodal fields of one skirt side's gap (the documentation of GapFields.h).
struct GapFields {
  Eigen::ArrayXd gap_m;        ///< h, sum of the terms switched on [m]
  Eigen::ArrayXd gapRate_mps;  ///< dh/dt at the skirt node [m/s] (lubrication::FilmProblem)
  /// d/dy of the skirt surface's own terms (skirt profile with ovality, piston thermal, piston
  /// elastic; those switched on) [-]: the skirt surface's axial slope, r_s' = -slope. The film
  /// pressure on the skirt has the axial component -p slope per area (SkirtSideLubrication.h).
  Eigen::ArrayXd skirtGapSlope;

  /// The seven terms [m] (0 when switched off): h_rigid.
  Eigen::ArrayXd rigid_m;
  Eigen::ArrayXd skirtProfile_m;   ///< h_skirtProfile [m]
  Eigen::ArrayXd linerShape_m;     ///< h_linerShape [m]
  Eigen::ArrayXd pistonThermal_m;  ///< h_pistonThermal [m]
  Eigen::ArrayXd linerThermal_m;   ///< h_linerThermal [m]
  Eigen::ArrayXd pistonElastic_m;  ///< INPUT, written by the caller
  Eigen::ArrayXd linerElastic_m;   ///< INPUT, written by the caller

  /// Rates of the terms that change at a skirt node [m/s] (the skirt profile and the piston
  /// thermal term are fixed to the skirt: rate 0).
  Eigen::ArrayXd rigidRate_mps;
  Eigen::ArrayXd linerShapeRate_mps;     ///< convective, (d/dY) v_y
  Eigen::ArrayXd linerThermalRate_mps;   ///< convective, (d/dY) v_y
  Eigen::ArrayXd pistonElasticRate_mps;  ///< INPUT, written by the caller
  Eigen::ArrayXd linerElasticRate_mps;   ///< INPUT, written by the caller

  /// nodes x 3, columns lateral, tilt, tertiary (PoseCoordinate):
  Eigen::MatrixXd dGap_dPose;  ///< dh/de [-], dh/dalpha [m/rad], dh/dz_t [-]
  /// d(dh/dt)/d(de/dt, dalpha/dt, dz_t/dt): lubrication::FilmProblem::squeezeBasis
  Eigen::MatrixXd squeezeBasis;
};

}  // namespace pistondyn::skirt
