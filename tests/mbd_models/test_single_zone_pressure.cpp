// The single-zone pressure model (make_pressure_curve, pistondyn new) against closed forms:
// the motored closed cycle is the polytropic p V^k = const, the fired one releases the
// Wiebe heat by the first law, a target imep is met by the independent spline integral of
// CylinderPressureCurve, and bad parameters are refused naming them.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "pistondyn/mbd_models/CylinderPressureCurve.h"
#include "pistondyn/mbd_models/SingleZonePressureModel.h"

namespace {

namespace mbd = pistondyn::mbd;

constexpr double kDeg = M_PI / 180.0;
constexpr double kFine = mbd::kSingleZoneFineStep_deg;

// The gasoline example's geometry (74.5 x 80 mm, 140 mm rod, CR 10, pin offset 0.5 mm).
struct Gasoline {
  mbd::CrankTrainGeometry geometry() const {
    mbd::CrankTrainGeometry g;
    g.crankRadius_m = 0.040;
    g.conrodLength_m = 0.140;
    g.pinOffset_m = 0.0005;
    return g;
  }
  mbd::SliderCrank kin{geometry()};
  mbd::CylinderVolume vol{kin, 0.0745, 10.0};
};

double volumeAt(const mbd::CylinderVolume& vol, long i) {
  return vol.calcVolume_m3(static_cast<double>(i) * kFine * kDeg);
}

TEST(SingleZonePressure, MotoredClosedCycleIsPolytropic) {
  const Gasoline e;
  mbd::SingleZoneCycle c;  // k 1.30, IVC 580, EVO 140
  const std::vector<double> p = mbd::calcSingleZonePressure_Pa(c, e.vol, 0.0);
  ASSERT_EQ(p.size(), 72000u);
  const long iIvc = 58000, iEvo = 86000;  // 580 deg .. 140 + 720 deg
  const double invariant = c.intakePressure_Pa * std::pow(volumeAt(e.vol, iIvc), 1.30);
  double worst = 0.0;
  for (long i = iIvc; i <= iEvo; ++i) {
    const double pv = p[static_cast<std::size_t>(i % 72000)] * std::pow(volumeAt(e.vol, i), 1.30);
    worst = std::max(worst, std::abs(pv / invariant - 1.0));
  }
  EXPECT_LT(worst, 1e-12) << "p V^k drifts by " << worst;
  // Gas exchange: exhaust stroke at the exhaust pressure, intake stroke at the intake one.
  EXPECT_DOUBLE_EQ(p[30000], c.exhaustPressure_Pa);  // 300 deg
  EXPECT_DOUBLE_EQ(p[50000], c.intakePressure_Pa);   // 500 deg
}

// First law over the closed cycle: the heat released from IVC to EVO is
// integral (V dp + k p dV) / (k - 1), here by the trapezoid rule on the fine grid; the
// Wiebe law has burnt 1 - exp(-6.908 ((EVO - SOC)/duration)^3) of Q_tot by EVO.
TEST(SingleZonePressure, FiredClosedCycleReleasesTheWiebeHeat) {
  const Gasoline e;
  mbd::SingleZoneCycle c;
  const double q = 450.0, k = c.polytropicExponent;
  const std::vector<double> p = mbd::calcSingleZonePressure_Pa(c, e.vol, q);
  double heat = 0.0;
  for (long i = 58000; i < 86000; ++i) {
    const double p0 = p[static_cast<std::size_t>(i % 72000)];
    const double p1 = p[static_cast<std::size_t>((i + 1) % 72000)];
    const double v0 = volumeAt(e.vol, i), v1 = volumeAt(e.vol, i + 1);
    heat += (0.5 * (v0 + v1) * (p1 - p0) + k * 0.5 * (p0 + p1) * (v1 - v0)) / (k - 1.0);
  }
  const double x = (c.exhaustValveOpening_deg - c.combustionStart_deg) / c.combustionDuration_deg;
  const double burnt = q * (1.0 - std::exp(-6.908 * x * x * x));
  EXPECT_NEAR(heat, burnt, 1e-7 * q) << "heat " << heat << " J, Wiebe " << burnt << " J";
}

// The table's imep by CylinderPressureCurve's spline integral (Gauss-Legendre, not the
// generator's trapezoid) meets the target; the motored table's imep is negative (pumping).
TEST(SingleZonePressure, TargetImepIsMetByTheSplineIntegral) {
  const Gasoline e;
  mbd::SingleZoneCycle c;
  c.intakePressure_Pa = 0.60e5;
  const auto fired = mbd::makeSingleZonePressureTable(c, e.vol, 598e3, 0.5);
  ASSERT_EQ(fired.crankAngle_deg.size(), 1440u);
  EXPECT_DOUBLE_EQ(fired.crankAngle_deg[1], 0.5);
  EXPECT_NEAR(fired.netImep_Pa, 598e3, 1e-6);
  const mbd::CylinderPressureCurve curve(fired.crankAngle_deg, fired.pressure_Pa);
  EXPECT_NEAR(mbd::calcImep_Pa(curve, e.vol), 598e3, 1e-5 * 598e3);
  EXPECT_GT(fired.heatReleased_J, 0.0);

  const auto motored = mbd::makeSingleZonePressureTable(c, e.vol, std::nullopt, 1.0);
  EXPECT_EQ(motored.heatReleased_J, 0.0);
  EXPECT_EQ(motored.crankAngle_deg.size(), 720u);
  EXPECT_LT(motored.netImep_Pa, 0.0);
  const mbd::CylinderPressureCurve motoredCurve(motored.crankAngle_deg, motored.pressure_Pa);
  EXPECT_NEAR(mbd::calcImep_Pa(motoredCurve, e.vol), motored.netImep_Pa,
              1e-5 * std::abs(motored.netImep_Pa));
}

std::string rejection(const mbd::SingleZoneCycle& c, std::optional<double> target = {},
                      double step = 0.5) {
  const Gasoline e;
  try {
    mbd::makeSingleZonePressureTable(c, e.vol, target, step);
  } catch (const std::invalid_argument& ex) {
    return ex.what();
  }
  return "";
}

TEST(SingleZonePressure, RefusesBadParametersNamingThem) {
  mbd::SingleZoneCycle c;
  c.polytropicExponent = 1.0;
  EXPECT_NE(rejection(c).find("polytropic exponent"), std::string::npos);
  c = {};
  c.intakeValveClosing_deg = 380;
  EXPECT_NE(rejection(c).find("intake valve closing"), std::string::npos);
  c = {};
  c.exhaustValveOpening_deg = 320;
  EXPECT_NE(rejection(c).find("exhaust valve opening"), std::string::npos);
  c = {};
  c.combustionDuration_deg = 0;
  EXPECT_NE(rejection(c).find("combustion duration"), std::string::npos);
  c = {};
  c.intakePressure_Pa = -1;
  EXPECT_NE(rejection(c).find("intake pressure"), std::string::npos);
  EXPECT_NE(rejection({}, std::nullopt, 0.001).find("table step"), std::string::npos);
  // A target below the motored cycle's imep would need a negative heat release.
  EXPECT_NE(rejection({}, -200e3).find("below the motored cycle"), std::string::npos);
}

}  // namespace
