#pragma once
/// \file
/// h_rigid: the gap of a rigid, round skirt of radius R in a round bore of radius R + c0, for the
/// piston's pose (thesis §2.1, h_1). Positive opens the gap.
///
///   h_rigid = c0 - (e + y sin alpha) cos phi - z_t sin phi
///
/// at a skirt node (phi, y) (conventions: SkirtSideGrid.h, PistonPose.h), c0 = the cold radial
/// clearance at the profile's reference (zero-drop) point. Its rate at the skirt node and the
/// derivatives the film solver and the implicit integrator need:
///
///   dh/dt       = -(de/dt + y cos alpha dalpha/dt) cos phi - dz_t/dt sin phi
///   dh/de = -cos phi,  dh/dalpha = -y cos alpha cos phi,  dh/dz_t = -sin phi
///   d(dh/dt)/d(de/dt, dalpha/dt, dz_t/dt) = the same three columns (the "squeeze basis",
///   lubrication::FilmProblem::squeezeBasis, one column per generalised velocity).
///
/// Derivation and what the linear form neglects. A skirt point r = (R cos phi, y, R sin phi)
/// of the posed piston lies in the bore frame at
///   X = e + R cos phi cos alpha + y sin alpha,  Z = z_t + R sin phi,
///   Y = Y_pin + y cos alpha - R cos phi sin alpha,
/// at the distance rho = sqrt(X^2 + Z^2) from the cylinder axis, and the gap is
/// (R + c0) - rho. With u = e + y sin alpha, expanding rho to second order:
///   rho = R + u cos phi + z_t sin phi + (u sin phi - z_t cos phi)^2 / (2R) -
///           R (1 - cos alpha) cos^2 phi + ...
/// The linear form drops
///   * the lateral curvature term (u sin phi - z_t cos phi)^2 / (2R), e.g. e^2 sin^2 phi / (2R):
///     e = 50 um, R = 37 mm: 0.034 um at sin phi = 1, 0.008 um at the edge of a 60 deg side;
///   * the tilt term R (1 - cos alpha) cos^2 phi (the tilted circle's elliptic section):
///     alpha = 1 mrad, R = 37 mm: 0.019 um;
///   * the factor cos alpha on u cos phi (u (1 - cos alpha) = 2.5e-5 um for u = 50 um);
/// all small against the roughness (sigma ~ 0.3..1 um) and the clearance (10..50 um), and
///   * the axial shift -R cos phi sin alpha of the node in the bore (37 um at 1 mrad), which
///     only moves the height where the liner terms are read (their gradients along the bore
///     are ~1 um per 10 mm: an error ~0.004 um).
/// tests/skirt/test_rigid_gap.cpp checks the linear form against the exact distance with these
/// bounds.

#include <Eigen/Core>

#include "pistondyn/skirt/PistonPose.h"
#include "pistondyn/skirt/SkirtSideGrid.h"

namespace pistondyn::skirt {

/// Fills the rigid gap of every node of grid.
/// Inputs:
///   grid                   the skirt side
///   coldRadialClearance_m  c0 [m], finite (a negative value is a cold interference)
///   pose, rate             the piston's pose and its rates (finite)
/// Outputs (preallocated; sizes nodeCount() and nodeCount() x 3):
///   gap_m         h_rigid [m]
///   gapRate_mps   dh_rigid/dt at the skirt node [m/s]
///   dGap_dPose    columns dh/de [m/m], dh/dalpha [m/rad], dh/dz_t [m/m]
///   squeezeBasis  columns d(dh/dt)/d(de/dt) [-], d(dh/dt)/d(dalpha/dt) [m/rad],
///                 d(dh/dt)/d(dz_t/dt) [-]
/// Allocates nothing. Throws std::invalid_argument for a wrong output size or a non-finite
/// input.
void calcRigidGap(const SkirtSideGrid& grid, double coldRadialClearance_m, const PistonPose& pose,
                  const PistonPoseRate& rate, Eigen::Ref<Eigen::ArrayXd> gap_m,
                  Eigen::Ref<Eigen::ArrayXd> gapRate_mps, Eigen::Ref<Eigen::MatrixXd> dGap_dPose,
                  Eigen::Ref<Eigen::MatrixXd> squeezeBasis);

}  // namespace pistondyn::skirt
