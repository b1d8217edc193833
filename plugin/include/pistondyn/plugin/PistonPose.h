#pragma once
/// \file
/// The piston's pose in the bore as the skirt-liner numerics see it (plain numbers, SI),
/// read from a Simbody State; and the bridge back: generalised forces and their
/// derivatives with respect to the pose, turned into Simbody mobility forces and the
/// mobility-space force Jacobian (ForceElement::addForceJacobian).
///
/// Pose coordinates p = (e, alpha, z_t) (CrankTrain.h, README "Frames and signs"):
///   e       lateral displacement of the piston-frame origin (piston axis at pin height)
///           from the cylinder axis, + towards thrust [m]
///   alpha   tilt, + when the crown leans towards thrust = rotation about -z [rad]
///   z_t     tertiary displacement along the pin axis (+z) [m]
/// Their rates are read from the piston's spatial velocity V = (omega, v) in ground:
///   de/dt = v_x, dalpha/dt = -omega_z, dz_t/dt = v_z,  i.e. pdot = P V.
/// Generalised forces conjugate to p, Q = (F_x [N], Q_alpha [N m], F_z [N]), with
/// Q_alpha = -M_z (virtual work F_x de + M_z d theta_z = F_x de - M_z d alpha), act on the
/// piston as the spatial force P^T Q at the piston-frame origin. With the frame Jacobian J
/// of that origin (V = J u, and dp = P J dq for mobilizers with qdot = u):
///   f_gen = J^T P^T Q,   d f_gen / d u = J^T P^T (dQ/dpdot) P J,
///   d f_gen / d q = J^T P^T (dQ/dp) P J   (the change of J with q is left out: it
///   multiplies Q, which is not stiff).

#include <Eigen/Core>

#include "pistondyn/mbd_models/CrankTrain.h"
#include "pistondyn/plugin/ForceElement.h"

namespace pistondyn::plugin {

/// The piston's pose and rates read from the State (the documentation of PistonPose.h gives the
/// frames and signs).
struct PistonPose {
  double lateral_m = 0.0;           ///< e
  double tilt_rad = 0.0;            ///< alpha
  double transverse_m = 0.0;        ///< z_t
  double lateralRate_mps = 0.0;     ///< de/dt
  double tiltRate_radps = 0.0;      ///< dalpha/dt
  double transverseRate_mps = 0.0;  ///< dz_t/dt
  double pinHeight_m = 0.0;         ///< height of the piston-frame origin above the crank axis
  double axialVelocity_mps = 0.0;   ///< piston velocity along +y (towards the head)
};

/// Pose and rates at a state realized through Stage::Velocity.
PistonPose calcPistonPose(const mbd::CrankTrain& crankTrain, const SimTK::State& s);

/// Applies the pose generalised forces Q = (F_x, Q_alpha, F_z) (see top) plus an axial
/// force F_y [N] along +y at the piston-frame origin and a moment about the x axis
/// M_x [N m] (tertiary tilt, not a pose coordinate), all in ground.
void applyPoseForces(const mbd::CrankTrain& crankTrain, const SimTK::State& s,
                     const Eigen::Vector3d& poseForces, double axialForce_N, double momentX_Nm,
                     AppliedForces& forces);

/// Adds J^T P^T dQ_dPose P J to jacobian.dfdq and J^T P^T dQ_dPoseRate P J to
/// jacobian.dfdu (state realized through Stage::Position).
/// Inputs:  dQ_dPose      3x3, row i = d Q_i / d (e, alpha, z_t)
///          dQ_dPoseRate  3x3, row i = d Q_i / d (de/dt, dalpha/dt, dz_t/dt)
void addPoseForceJacobian(const mbd::CrankTrain& crankTrain, const SimTK::State& s,
                          const Eigen::Matrix3d& dQ_dPose, const Eigen::Matrix3d& dQ_dPoseRate,
                          ForceJacobian& jacobian);

}  // namespace pistondyn::plugin
