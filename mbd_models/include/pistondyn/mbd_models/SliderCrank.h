#pragma once
/// \file
/// Closed-form slider-crank kinematics with pin and crank (desaxe) offsets, for a
/// piston held on the cylinder axis. Used to place the Simbody model at a given crank
/// angle, to locate TDC/BDC, and to compute the cylinder volume for imep. (The tests
/// check the Simbody model against their own, separately written closed form.)
///
/// Geometry: the pin axis moves on the line x = e = crankOffset + pinOffset. The crank
/// pin is at C = r(-sin phi, cos phi) where phi is the crank rotation about +z measured
/// from +y. Firing TDC (crank and rod collinear, pin highest) is at phi_TDC =
/// -asin(e / (L + r)); the crank angle theta used everywhere is theta = phi - phi_TDC.

#include "pistondyn/mbd_models/EngineDescription.h"

namespace pistondyn::mbd {

/// Closed-form slider-crank kinematics of a piston held on the cylinder axis (this file's
/// documentation gives the geometry and the angles).
class SliderCrank {
 public:
  /// Inputs: geometry (validated: r > 0, L > r + |e|).
  explicit SliderCrank(const CrankTrainGeometry& geometry);

  double crankRadius_m() const { return r_; }                ///< r [m]
  double conrodLength_m() const { return L_; }               ///< L [m]
  double pinLineX_m() const { return e_; }                   ///< x of the pin-axis line [m]
  double crankRotationAtTdc_rad() const { return phiTdc_; }  ///< phi_TDC [rad]
  double pinHeightAtTdc_m() const { return yTdc_; }         ///< pin height above the crank axis [m]
  double pinHeightAtBdc_m() const { return yBdc_; }         ///< pin height above the crank axis [m]
  double stroke_m() const { return yTdc_ - yBdc_; }         ///< slightly > 2r with offsets [m]
  double crankAngleAtBdc_rad() const { return thetaBdc_; }  ///< theta at BDC [rad]

  /// Pin-axis height above the crank axis and its first two derivatives with respect
  /// to the crank angle theta [m, m/rad, m/rad^2].
  struct PinHeight {
    double y_m;          ///< pin height [m]
    double dy_dtheta;    ///< [m/rad]
    double d2y_dtheta2;  ///< [m/rad^2]
  };
  PinHeight calcPinHeight(double crankAngle_rad) const;  ///< at crank angle theta [rad]

  /// Rod angle beta (sin beta = (e + r sin phi) / L, rod leaning with its top towards +x
  /// for beta > 0) and its first two derivatives with respect to theta.
  struct RodAngle {
    double beta_rad;        ///< rod angle [rad]
    double dbeta_dtheta;    ///< [-]
    double d2beta_dtheta2;  ///< [1/rad]
  };
  RodAngle calcRodAngle(double crankAngle_rad) const;  ///< at crank angle theta [rad]

 private:
  double r_, L_, e_, phiTdc_, yTdc_, yBdc_, thetaBdc_;
};

/// Cylinder volume [m^3] and dV/dtheta [m^3/rad] for a piston of the given bore and a
/// clearance volume V_c = V_d / (CR - 1), V_d = A * stroke.
struct CylinderVolume {
  /// Inputs: the kinematics (copied), bore [m] > 0, compression ratio > 1.
  CylinderVolume(const SliderCrank& kinematics, double bore_m, double compressionRatio);
  double displacement_m3() const { return displacement_m3_; }       ///< V_d [m^3]
  double clearance_m3() const { return clearance_m3_; }             ///< V_c [m^3]
  double pistonArea_m2() const { return area_m2_; }                 ///< A [m^2]
  double calcVolume_m3(double crankAngle_rad) const;                ///< V(theta) [m^3]
  double calcVolumeDerivative_m3prad(double crankAngle_rad) const;  ///< dV/dtheta [m^3/rad]

 private:
  SliderCrank kin_;  ///< small value type: copied, so no lifetime coupling
  double area_m2_, displacement_m3_, clearance_m3_;
};

}  // namespace pistondyn::mbd
