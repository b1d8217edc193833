#pragma once
/// \file
/// The piston's pose in the bore and its rates: what the skirt gap needs from the multibody
/// state (the lubricated skirt element reads these from the Simbody State).
///
/// Bore frame: cylinder axis y (towards the head), x towards the thrust side, z along the pin
/// axis. Piston frame: see SkirtSideGrid.h (origin on the piston axis at the pin-axis height).
///
///   lateral_m   e    displacement of the piston-frame origin from the cylinder axis along +x
///   tilt_rad    alpha  rotation of the piston about -z: alpha > 0 leans the crown towards the
///                   thrust side (a piston-frame point at height y > 0 on the axis moves to +x)
///   tertiary_m  z_t  displacement of the piston-frame origin along +z (pin axis)
/// and their time derivatives. The axial position is the pin-axis height above the crank axis,
/// Y_pin [m], and its rate the axial velocity v_y = dY_pin/dt [m/s]; a skirt node at
/// piston-frame height y is at bore height Y = Y_pin + y.

namespace pistondyn::skirt {

/// The piston's pose in the bore (the documentation of PistonPose.h gives the frames and signs).
struct PistonPose {
  double lateral_m = 0.0;   ///< e [m], + towards thrust
  double tilt_rad = 0.0;    ///< alpha [rad], + crown towards thrust (rotation about -z)
  double tertiary_m = 0.0;  ///< z_t [m], + along the pin axis (+z)
};

/// The time derivatives of the pose.
struct PistonPoseRate {
  double lateral_mps = 0.0;   ///< de/dt [m/s]
  double tilt_radps = 0.0;    ///< dalpha/dt [rad/s]
  double tertiary_mps = 0.0;  ///< dz_t/dt [m/s]
};

/// Column order of every derivative with respect to the pose (dGap_dPose) or its rates
/// (squeezeBasis): 0 = lateral, 1 = tilt, 2 = tertiary.
enum PoseCoordinate : int { kLateral = 0, kTilt = 1, kTertiary = 2 };

}  // namespace pistondyn::skirt
