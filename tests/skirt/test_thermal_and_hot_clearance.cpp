// h_pistonThermal, h_linerThermal and the hot running clearance.
// References: closed forms of uniform temperatures (Delta R = R alpha Delta T on piston and
// liner; hot clearance c0 + R (alpha_l - alpha_p) Delta T), the closed-form minimum of a
// parabolic barrel plus a linear piston temperature, the coldest bore height the skirt reaches
// for a liner temperature falling with depth, and the closed-form slope of a linear liner
// temperature for its convective rate.
#include <gtest/gtest.h>

#include <cmath>

#include "ExpectInvalidArgument.h"
#include "SkirtTestSupport.h"
#include "pistondyn/skirt/GapAssembly.h"
#include "pistondyn/skirt/HotRunningClearance.h"
#include "pistondyn/skirt/ThermalGrowth.h"

namespace ps = pistondyn::skirt;

namespace {

constexpr double kAlphaPiston = 21e-6;  // aluminium piston alloy [1/K]
constexpr double kAlphaLiner = 11e-6;   // grey cast iron [1/K]
constexpr double kC0 = 30e-6;           // [m]

ps::GapAssemblyParameters baseParameters() {
  ps::GapAssemblyParameters p;
  p.coldRadialClearance_m = kC0;
  p.linerTopHeight_m = 0.25;
  p.travel = {0.12, 0.20};  // pin height at BDC and TDC above the crank axis
  return p;
}

TEST(ThermalGrowth, UniformTemperaturesGrowBothRadiiByRAlphaDeltaT) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(7, 5));
  const double R = g.getRadius_m(), dT = 150.0;
  ps::PistonThermalParameters pp;
  pp.expansionCoefficient_perK = kAlphaPiston;
  pp.height_m = Eigen::VectorXd::Constant(1, 0.0);
  pp.temperature_degC = Eigen::VectorXd::Constant(1, 20.0 + dT);
  const ps::PistonThermalGrowth piston(pp, g, 20.0);
  Eigen::ArrayXd h(g.nodeCount());
  piston.calcField(g, h);
  EXPECT_NEAR(h.maxCoeff(), -R * kAlphaPiston * dT, 1e-20);
  EXPECT_NEAR(h.minCoeff(), -R * kAlphaPiston * dT, 1e-20);
  // the same per node
  pp.nodalTemperature_degC = Eigen::ArrayXd::Constant(g.nodeCount(), 20.0 + dT);
  const ps::PistonThermalGrowth nodal(pp, g, 20.0);
  nodal.calcField(g, h);
  EXPECT_NEAR((h + R * kAlphaPiston * dT).abs().maxCoeff(), 0.0, 1e-20);

  ps::LinerThermalParameters lp;
  lp.expansionCoefficient_perK = kAlphaLiner;
  lp.depth_m = Eigen::Vector2d(0.0, 0.2);
  lp.temperature_degC = Eigen::Vector2d(20.0 + dT, 20.0 + dT);
  const ps::LinerThermalGrowth liner(lp, g, 0.25, 20.0);
  Eigen::ArrayXd hl(g.nodeCount()), rate(g.nodeCount());
  liner.calcField(0.18, 12.0, hl, rate);
  EXPECT_NEAR(hl.maxCoeff(), R * kAlphaLiner * dT, 1e-20);
  EXPECT_NEAR(hl.minCoeff(), R * kAlphaLiner * dT, 1e-20);
  EXPECT_EQ(rate.abs().maxCoeff(), 0.0);
}

TEST(HotRunningClearance, UniformTemperatureGivesC0PlusRDeltaAlphaDeltaT) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(9, 7));
  const double R = g.getRadius_m(), dT = -60.0;  // a cold start below T_ref: liner-in-piston
  // c0 + R (alpha_l - alpha_p) dT: the piston shrinks more than the bore -> larger clearance
  ps::GapAssemblyParameters p = baseParameters();
  p.pistonThermal.expansionCoefficient_perK = kAlphaPiston;
  p.pistonThermal.height_m = Eigen::VectorXd::Constant(1, 0.0);
  p.pistonThermal.temperature_degC = Eigen::VectorXd::Constant(1, 20.0 + dT);
  p.linerThermal.expansionCoefficient_perK = kAlphaLiner;
  p.linerThermal.depth_m = Eigen::VectorXd::Constant(1, 0.0);
  p.linerThermal.temperature_degC = Eigen::VectorXd::Constant(1, 20.0 + dT);
  const ps::HotRunningClearance hot = ps::calcHotRunningClearance(g, p);
  EXPECT_NEAR(hot.clearance_m, kC0 + R * (kAlphaLiner - kAlphaPiston) * dT, 1e-19);
  // Hot: 50 K on both (an aluminium piston in an iron bore loses 18.5 um of its 30 um)
  for (double t : {70.0}) {
    p.pistonThermal.temperature_degC[0] = t;
    p.linerThermal.temperature_degC[0] = t;
    const ps::HotRunningClearance h2 = ps::calcHotRunningClearance(g, p);
    EXPECT_NEAR(h2.clearance_m, kC0 + R * (kAlphaLiner - kAlphaPiston) * (t - 20.0), 1e-19);
    std::printf("[ hot      ] uniform 50 K: c_hot = %.6e m, closed form %.6e m\n", h2.clearance_m,
                kC0 + R * (kAlphaLiner - kAlphaPiston) * 50.0);
    const ps::GapAssembly assembly(g, p);
    EXPECT_EQ(assembly.getHotRunningClearance().clearance_m, h2.clearance_m);
  }
}

TEST(HotRunningClearance, BarrelAndLinearPistonTemperatureGiveTheClosedFormMinimum) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(9, 11));  // y in [-25, 15] mm
  const double R = g.getRadius_m();
  const double c = 0.05, y0 = -0.008;   // drop = c (y - y0)^2, rows every 2.5 mm
  const double T0 = 180.0, T1 = 800.0;  // piston temperature T0 + T1 y [degC], hotter above
  ps::GapAssemblyParameters p = baseParameters();
  p.skirtProfile.axial.height_m = Eigen::VectorXd::LinSpaced(25, -0.03, 0.03);
  p.skirtProfile.axial.radialDrop_m =
      p.skirtProfile.axial.height_m.unaryExpr([&](double y) { return c * (y - y0) * (y - y0); });
  p.pistonThermal.expansionCoefficient_perK = kAlphaPiston;
  p.pistonThermal.height_m = Eigen::Vector2d(-0.03, 0.03);
  p.pistonThermal.temperature_degC = Eigen::Vector2d(T0 - 0.03 * T1, T0 + 0.03 * T1);
  p.coldRadialClearance_m = 150e-6;
  const ps::HotRunningClearance hot = ps::calcHotRunningClearance(g, p);
  // f(y) = c0 + c (y - y0)^2 - R alpha (T0 + T1 y - 20): minimum at y* = y0 + R alpha T1/(2c)
  const double k = R * kAlphaPiston * T1;
  const double yStar = y0 + k / (2 * c);
  const double fStar =
      150e-6 + c * (yStar - y0) * (yStar - y0) - R * kAlphaPiston * (T0 + T1 * yStar - 20.0);
  // PCHIP of the parabola: within f'' h^2 / 4 = 2c (2.5 mm)^2 / 4
  const double bound = 2 * c * 0.0025 * 0.0025 / 4;
  EXPECT_NEAR(hot.clearance_m, fStar, bound);
  EXPECT_NEAR(hot.skirtHeight_m, yStar, 0.0025);
  std::printf("[ hot      ] barrel: c_hot = %.6e m at y = %.4e m; closed form %.6e m at %.4e m\n",
              hot.clearance_m, hot.skirtHeight_m, fStar, yStar);
}

TEST(HotRunningClearance, IsAtTheColdestBoreHeightTheSkirtReaches) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(9, 7));  // y in [-25, 15] mm
  const double R = g.getRadius_m();
  ps::GapAssemblyParameters p = baseParameters();  // liner top 0.25 m, pin 0.12..0.20 m
  p.pistonThermal.expansionCoefficient_perK = kAlphaPiston;
  p.pistonThermal.height_m = Eigen::VectorXd::Constant(1, 0.0);
  p.pistonThermal.temperature_degC = Eigen::VectorXd::Constant(1, 170.0);
  // liner 160 degC at the top, falling 500 K/m with depth (linear)
  p.linerThermal.expansionCoefficient_perK = kAlphaLiner;
  p.linerThermal.depth_m = Eigen::Vector2d(0.0, 0.3);
  p.linerThermal.temperature_degC = Eigen::Vector2d(160.0, 160.0 - 150.0);
  const ps::HotRunningClearance hot = ps::calcHotRunningClearance(g, p);
  // deepest point reached: skirt bottom (y = -25 mm) at BDC (Y_pin = 0.12): depth 0.155 m
  const double depth = 0.25 - (0.12 - 0.025);
  const double expected =
      kC0 - R * kAlphaPiston * 150.0 + R * kAlphaLiner * (160.0 - 500.0 * depth - 20.0);
  EXPECT_NEAR(hot.clearance_m, expected, 1e-19);
  EXPECT_NEAR(hot.skirtHeight_m, -0.025, 1e-15);
  EXPECT_NEAR(hot.pinHeight_m, 0.12, 1e-15);
}

TEST(HotRunningClearance, NegativeIsRejectedWithItsValueAndPlace) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(9, 7));
  ps::GapAssemblyParameters p = baseParameters();
  p.coldRadialClearance_m = 10e-6;
  p.pistonThermal.expansionCoefficient_perK = kAlphaPiston;
  p.pistonThermal.height_m = Eigen::VectorXd::Constant(1, 0.0);
  p.pistonThermal.temperature_degC = Eigen::VectorXd::Constant(1, 220.0);  // -155 um growth
  pistondyn::test::expectInvalidArgument(
      [&] { ps::GapAssembly a(g, p); },
      {"GapAssembly", "hot running clearance is -", "thrust side", "skirt height", "Y_pin"});
  // switched off, the piston growth no longer counts
  p.terms.pistonThermal = false;
  EXPECT_NO_THROW(ps::GapAssembly(g, p));
}

TEST(ThermalGrowth, LinearLinerTemperatureHasTheClosedFormConvectiveRate) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(5, 6));
  ps::LinerThermalParameters lp;
  lp.expansionCoefficient_perK = kAlphaLiner;
  lp.depth_m = Eigen::Vector2d(0.0, 0.3);
  lp.temperature_degC = Eigen::Vector2d(160.0, 10.0);  // dT/d depth = -500 K/m
  const ps::LinerThermalGrowth liner(lp, g, 0.25, 20.0);
  Eigen::ArrayXd h(g.nodeCount()), rate(g.nodeCount());
  const double vy = 6.0;
  liner.calcField(0.18, vy, h, rate);
  // rate = R alpha (dT/dY) v_y = R alpha (+500 K/m) v_y (hotter upwards, moving up: opens)
  const double expected = g.getRadius_m() * kAlphaLiner * 500.0 * vy;
  EXPECT_NEAR(rate.minCoeff(), expected, 1e-18);
  EXPECT_NEAR(rate.maxCoeff(), expected, 1e-18);
  for (int j = 0; j < g.nY(); ++j) {
    const double depth = 0.25 - (0.18 + g.getYNodes_m()[j]);
    EXPECT_NEAR(h[g.nodeIndex(2, j)],
                g.getRadius_m() * kAlphaLiner * (160.0 - 500.0 * depth - 20.0), 1e-19);
  }
}

}  // namespace
