// SliderCrank (closed-form helper of the library) against independent checks:
// TDC/BDC as the extrema of the pin height found numerically, derivatives against
// finite differences, and EngineDescription validation.

#include <gtest/gtest.h>

#include <cmath>

#include "ExpectInvalidArgument.h"
#include "pistondyn/mbd_models/EngineDescription.h"
#include "pistondyn/mbd_models/SliderCrank.h"

namespace {

using pistondyn::mbd::CrankTrainGeometry;
using pistondyn::mbd::SliderCrank;

CrankTrainGeometry offsetGeometry() {
  CrankTrainGeometry g;
  g.crankRadius_m = 0.04;
  g.conrodLength_m = 0.14;
  g.pinOffset_m = 0.0008;
  g.crankOffset_m = 0.0015;
  return g;
}

TEST(SliderCrank, TdcAndBdcAreTheExtremaOfThePinHeight) {
  const SliderCrank k(offsetGeometry());
  // Brute-force scan of the height over the crank angle (independent of the formulas).
  double yMax = -1, yMin = 1, thMax = 0, thMin = 0;
  for (double th = -0.2; th < 2 * M_PI - 0.2; th += 1e-5) {
    const double y = k.calcPinHeight(th).y_m;
    if (y > yMax)
      yMax = y, thMax = th;
    if (y < yMin)
      yMin = y, thMin = th;
  }
  EXPECT_NEAR(thMax, 0.0, 2e-5);  // theta = 0 is TDC
  EXPECT_NEAR(yMax, k.pinHeightAtTdc_m(), 1e-12);
  EXPECT_NEAR(thMin, k.crankAngleAtBdc_rad(), 2e-5);
  EXPECT_NEAR(yMin, k.pinHeightAtBdc_m(), 1e-12);
  // With an offset the stroke exceeds 2r and BDC is not at 180 deg.
  EXPECT_GT(k.stroke_m(), 2 * 0.04);
  EXPECT_GT(std::abs(k.crankAngleAtBdc_rad() - M_PI), 1e-3);
}

TEST(SliderCrank, DerivativesMatchFiniteDifferences) {
  const SliderCrank k(offsetGeometry());
  const double h = 1e-5;
  for (double th = 0.1; th < 4 * M_PI; th += 0.37) {
    const auto c = k.calcPinHeight(th), p = k.calcPinHeight(th + h), m = k.calcPinHeight(th - h);
    EXPECT_NEAR(c.dy_dtheta, (p.y_m - m.y_m) / (2 * h), 1e-9);
    EXPECT_NEAR(c.d2y_dtheta2, (p.dy_dtheta - m.dy_dtheta) / (2 * h), 1e-8);
    const auto bc = k.calcRodAngle(th), bp = k.calcRodAngle(th + h), bm = k.calcRodAngle(th - h);
    EXPECT_NEAR(bc.dbeta_dtheta, (bp.beta_rad - bm.beta_rad) / (2 * h), 1e-8);
    EXPECT_NEAR(bc.d2beta_dtheta2, (bp.dbeta_dtheta - bm.dbeta_dtheta) / (2 * h), 1e-7);
  }
}

TEST(SliderCrank, VolumeSpansClearanceToClearancePlusDisplacement) {
  const SliderCrank k(offsetGeometry());
  const pistondyn::mbd::CylinderVolume v(k, 0.08, 10.0);
  EXPECT_NEAR(v.calcVolume_m3(0.0), v.clearance_m3(), 1e-15);
  EXPECT_NEAR(v.calcVolume_m3(k.crankAngleAtBdc_rad()), v.clearance_m3() + v.displacement_m3(),
              1e-15);
  EXPECT_NEAR((v.clearance_m3() + v.displacement_m3()) / v.clearance_m3(), 10.0, 1e-12);
}

TEST(EngineDescription, ValidationNamesTheMember) {
  pistondyn::mbd::EngineDescription e;
  e.geometry = offsetGeometry();
  e.piston = {0.08, 0.03, 0.04, 0.01};
  e.mass.crank = {1, 0, 0, 1e-3};
  e.mass.conrod = {0.4, 0, 0.04, 1e-3};
  e.mass.pin = {0.05, 0, 0, 1e-6};
  e.mass.piston = {0.2, 0, 0.005, 1e-4};
  e.drive.speed_radps = 200;
  EXPECT_NO_THROW(validate(e));
  auto fails = [&](auto mutate, const char* member) {
    pistondyn::mbd::EngineDescription bad = e;
    mutate(bad);
    pistondyn::test::expectInvalidArgument([&] { validate(bad); }, {member});
  };
  fails([](auto& b) { b.geometry.crankRadius_m = -0.01; }, "crankRadius_m");
  fails([](auto& b) { b.geometry.conrodLength_m = 0.041; }, "conrodLength_m");
  fails([](auto& b) { b.geometry.compressionRatio = 1.0; }, "compressionRatio");
  fails([](auto& b) { b.piston.bore_m = 0.0; }, "bore_m");
  fails([](auto& b) { b.mass.piston.mass_kg = 0.0; }, "mass.piston.mass_kg");
  fails([](auto& b) { b.mass.conrod.inertiaZZ_kgm2 = -1.0; }, "mass.conrod.inertiaZZ_kgm2");
  fails([](auto& b) { b.drive.speed_radps = NAN; }, "speed_radps");
  fails([](auto& b) { b.piston.skirtTopAbovePin_m = 0.05; }, "skirtTopAbovePin_m");
}

}  // namespace
