// CylinderPressureCurve (periodic cubic spline) and calcImep_Pa against closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "pistondyn/mbd_models/CylinderPressureCurve.h"

namespace {

using pistondyn::mbd::calcImep_Pa;
using pistondyn::mbd::CrankTrainGeometry;
using pistondyn::mbd::CylinderPressureCurve;
using pistondyn::mbd::CylinderVolume;
using pistondyn::mbd::SliderCrank;

// A smooth 720-periodic test function and its exact values.
double smoothPressure(double deg) {
  const double t = deg * M_PI / 360.0;  // period 720 deg -> 2 pi
  return 2e5 + 1e5 * std::sin(t) + 5e4 * std::cos(3 * t) + 2e4 * std::sin(5 * t + 0.3);
}

CylinderPressureCurve sampled(double step_deg, double start_deg = 0.0) {
  std::vector<double> a, p;
  for (double x = start_deg; x < start_deg + 720.0 - 1e-9; x += step_deg) {
    a.push_back(x);
    p.push_back(smoothPressure(x));
  }
  return CylinderPressureCurve(a, p);
}

double maxError(const CylinderPressureCurve& c) {
  double worst = 0;
  for (double x = -720.0; x < 1440.0; x += 0.37) {
    worst = std::max(worst, std::abs(c.calcPressure_Pa(x) - smoothPressure(x)));
  }
  return worst;
}

TEST(CylinderPressureCurve, InterpolatesKnotsExactlyAndWrapsPeriodically) {
  const CylinderPressureCurve c = sampled(10.0, -30.0);
  for (double x = -30.0; x < 690.0; x += 10.0) {
    EXPECT_NEAR(c.calcPressure_Pa(x), smoothPressure(x), 1e-9 * 2e5);
    EXPECT_NEAR(c.calcPressure_Pa(x + 720.0), smoothPressure(x), 1e-9 * 2e5);
    EXPECT_NEAR(c.calcPressure_Pa(x - 1440.0), smoothPressure(x), 1e-9 * 2e5);
  }
}

// A periodic cubic spline converges at fourth order on a smooth periodic function.
TEST(CylinderPressureCurve, ConvergesAtFourthOrder) {
  const double e1 = maxError(sampled(20.0)), e2 = maxError(sampled(10.0)),
               e3 = maxError(sampled(5.0));
  const double order1 = std::log2(e1 / e2), order2 = std::log2(e2 / e3);
  std::printf("  spline errors %.3e %.3e %.3e Pa, orders %.2f %.2f\n", e1, e2, e3, order1, order2);
  EXPECT_NEAR(order1, 4.0, 0.3);
  EXPECT_NEAR(order2, 4.0, 0.3);
}

// The spline is C2 across the cycle seam: slopes from both sides of the first knot agree.
TEST(CylinderPressureCurve, SlopeIsContinuousAcrossTheSeam) {
  const CylinderPressureCurve c = sampled(15.0);
  const double h = 1e-6;
  const double left = c.calcPressureSlope_Paperdeg(720.0 - h);
  const double right = c.calcPressureSlope_Paperdeg(0.0 + h);
  EXPECT_NEAR(left, right, 1e-3);
  // And the analytic slope matches a central difference of the values.
  const double fd = (c.calcPressure_Pa(123.4 + 1e-4) - c.calcPressure_Pa(123.4 - 1e-4)) / 2e-4;
  EXPECT_NEAR(c.calcPressureSlope_Paperdeg(123.4), fd, 1e-4 * std::abs(fd) + 1e-3);
}

TEST(CylinderPressureCurve, AcceptsAClosedTableWithTheDuplicateEndpoint) {
  std::vector<double> a, p;
  for (double x = 0; x <= 720.0 + 1e-9; x += 30.0) {
    a.push_back(x);
    p.push_back(smoothPressure(x));
  }
  const CylinderPressureCurve c(a, p);
  EXPECT_EQ(c.getAngles_deg().size(), 24u);
}

// imep closed form: with p = p0 + p1 sin(theta) and no offsets, dV/dtheta =
// A r (sin theta + (r/L) sin theta cos theta / sqrt(1 - (r/L)^2 sin^2 theta)); the second
// term integrates to zero against sin(theta) over [0, 4 pi] (odd about pi), so the closed
// integral of p dV is 2 pi p1 A r per cycle and imep = 2 pi p1 A r / (2 r A) = pi p1.
TEST(Imep, SinusoidalPressureGivesPiTimesAmplitude) {
  CrankTrainGeometry g;
  g.crankRadius_m = 0.04;
  g.conrodLength_m = 0.13;
  g.compressionRatio = 10.0;
  const SliderCrank kin(g);
  const CylinderVolume vol(kin, 0.08, g.compressionRatio);
  const double p0 = 5e5, p1 = 2e5;
  std::vector<double> a, p;
  for (double x = 0; x < 720.0; x += 0.5) {
    a.push_back(x);
    p.push_back(p0 + p1 * std::sin(x * M_PI / 180.0));
  }
  const double imep = calcImep_Pa(CylinderPressureCurve(a, p), vol);
  EXPECT_NEAR(imep, M_PI * p1, 1e-9 * M_PI * p1);
}

// A constant pressure does no net work over a closed cycle.
TEST(Imep, ConstantPressureGivesZero) {
  CrankTrainGeometry g;
  g.crankRadius_m = 0.03;
  g.conrodLength_m = 0.1;
  g.pinOffset_m = 0.001;
  g.crankOffset_m = 0.002;
  const SliderCrank kin(g);
  const CylinderVolume vol(kin, 0.07, 8.0);
  const CylinderPressureCurve c({0, 180, 360, 540}, {1e5, 1e5, 1e5, 1e5});
  EXPECT_NEAR(calcImep_Pa(c, vol), 0.0, 1e-9);
}

TEST(CylinderPressureCurve, RejectsBadTablesNamingTheRow) {
  auto message = [](std::vector<double> a, std::vector<double> p) -> std::string {
    try {
      CylinderPressureCurve c(std::move(a), std::move(p));
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_NE(message({0, 90, 90, 400}, {1, 2, 3, 4}).find("row 2"), std::string::npos);
  EXPECT_NE(message({0, 90, 80, 400}, {1, 2, 3, 4}).find("not increasing"), std::string::npos);
  EXPECT_NE(message({0, 90, 180, 270}, {1, 2, 3, 4}).find("does not cover"), std::string::npos);
  EXPECT_NE(message({0, 200, 400, 800}, {1, 2, 3, 4}).find("more than one"), std::string::npos);
  EXPECT_NE(message({0, 240, 480, 720}, {1, 2, 3, 4}).find("not periodic"), std::string::npos);
  EXPECT_NE(message({0, 240, 480}, {1, 2, 3}).find("at least 4"), std::string::npos);
  EXPECT_NE(message({0, 180, 360, 540}, {1, -2, 3, 4}).find("row 1"), std::string::npos);
  EXPECT_NE(message({0, 180, 360, 540}, {1, NAN, 3, 4}).find("positive and finite"),
            std::string::npos);
  EXPECT_NE(message({0, 180}, {1, 2, 3}).find("differ in length"), std::string::npos);
}

}  // namespace
