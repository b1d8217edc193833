#include "pistondyn/mbd_models/SliderCrank.h"

#include <cmath>
#include <stdexcept>

namespace pistondyn::mbd {

SliderCrank::SliderCrank(const CrankTrainGeometry& g)
    : r_(g.crankRadius_m), L_(g.conrodLength_m), e_(g.crankOffset_m + g.pinOffset_m) {
  if (!(r_ > 0.0) || !(L_ > r_ + std::abs(e_))) {
    throw std::invalid_argument(
        "SliderCrank: need crankRadius_m > 0 and conrodLength_m > crankRadius_m + |offset|");
  }
  // TDC: crank pin on the segment from the crank axis to the pin, |P| = L + r.
  phiTdc_ = -std::asin(e_ / (L_ + r_));
  yTdc_ = std::sqrt((L_ + r_) * (L_ + r_) - e_ * e_);
  // BDC: crank pin opposite the pin, |P| = L - r; sin(phi) = e/(L-r), cos(phi) < 0.
  yBdc_ = std::sqrt((L_ - r_) * (L_ - r_) - e_ * e_);
  const double phiBdc = M_PI - std::asin(e_ / (L_ - r_));
  thetaBdc_ = phiBdc - phiTdc_;
}

SliderCrank::RodAngle SliderCrank::calcRodAngle(double theta) const {
  const double phi = theta + phiTdc_;
  const double s = std::sin(phi), c = std::cos(phi);
  const double sinb = (e_ + r_ * s) / L_;
  const double cosb = std::sqrt(1.0 - sinb * sinb);
  RodAngle a;
  a.beta_rad = std::asin(sinb);
  // L sin(beta) = e + r sin(phi)  differentiated twice in theta (dphi/dtheta = 1).
  a.dbeta_dtheta = r_ * c / (L_ * cosb);
  a.d2beta_dtheta2 = (-r_ * s + L_ * sinb * a.dbeta_dtheta * a.dbeta_dtheta) / (L_ * cosb);
  return a;
}

SliderCrank::PinHeight SliderCrank::calcPinHeight(double theta) const {
  const double phi = theta + phiTdc_;
  const double s = std::sin(phi), c = std::cos(phi);
  const RodAngle b = calcRodAngle(theta);
  const double sb = std::sin(b.beta_rad), cb = std::cos(b.beta_rad);
  PinHeight h;
  h.y_m = r_ * c + L_ * cb;
  h.dy_dtheta = -r_ * s - L_ * sb * b.dbeta_dtheta;
  h.d2y_dtheta2 = -r_ * c - L_ * cb * b.dbeta_dtheta * b.dbeta_dtheta - L_ * sb * b.d2beta_dtheta2;
  return h;
}

CylinderVolume::CylinderVolume(const SliderCrank& kinematics, double bore_m,
                               double compressionRatio)
    : kin_(kinematics) {
  if (!(bore_m > 0.0) || !(compressionRatio > 1.0)) {
    throw std::invalid_argument("CylinderVolume: need bore_m > 0 and compressionRatio > 1");
  }
  area_m2_ = 0.25 * M_PI * bore_m * bore_m;
  displacement_m3_ = area_m2_ * kin_.stroke_m();
  clearance_m3_ = displacement_m3_ / (compressionRatio - 1.0);
}

double CylinderVolume::calcVolume_m3(double theta) const {
  return clearance_m3_ + area_m2_ * (kin_.pinHeightAtTdc_m() - kin_.calcPinHeight(theta).y_m);
}

double CylinderVolume::calcVolumeDerivative_m3prad(double theta) const {
  return -area_m2_ * kin_.calcPinHeight(theta).dy_dtheta;
}

}  // namespace pistondyn::mbd
