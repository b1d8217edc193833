#include "pistondyn/mbd_models/SingleZonePressureModel.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pistondyn::mbd {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kFine_deg = kSingleZoneFineStep_deg;
constexpr double kWiebeA = 6.908;  // 99.9 % burnt at the end of the duration
constexpr double kBlowDown_deg = 60.0;
constexpr double kIntakeBlendStart_deg = 370.0, kIntakeBlendEnd_deg = 400.0;

void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::invalid_argument("single-zone pressure model: " + what);
}

void checkCycle(const SingleZoneCycle& c) {
  require(c.polytropicExponent > 1.0 && std::isfinite(c.polytropicExponent),
          "polytropic exponent " + std::to_string(c.polytropicExponent) + " must be > 1");
  require(c.intakePressure_Pa > 0.0 && std::isfinite(c.intakePressure_Pa),
          "intake pressure must be positive");
  require(c.exhaustPressure_Pa > 0.0 && std::isfinite(c.exhaustPressure_Pa),
          "exhaust pressure must be positive");
  require(c.intakeValveClosing_deg >= kIntakeBlendEnd_deg && c.intakeValveClosing_deg < 720.0,
          "intake valve closing " + std::to_string(c.intakeValveClosing_deg) +
              " deg must be in [400, 720) deg (after the intake stroke's pressure blend)");
  require(c.exhaustValveOpening_deg > 0.0 &&
              c.exhaustValveOpening_deg + kBlowDown_deg <= kIntakeBlendStart_deg,
          "exhaust valve opening " + std::to_string(c.exhaustValveOpening_deg) +
              " deg must be in (0, 310] deg (the blow-down ends by 370 deg)");
  require(std::isfinite(c.combustionStart_deg) &&
              c.combustionStart_deg > c.intakeValveClosing_deg - 720.0 &&
              c.combustionStart_deg < c.exhaustValveOpening_deg,
          "start of combustion " + std::to_string(c.combustionStart_deg) +
              " deg must lie between intake valve closing (- 720) and exhaust valve opening");
  require(c.combustionDuration_deg > 0.0 && std::isfinite(c.combustionDuration_deg),
          "combustion duration must be positive");
}

double wiebeFraction(double theta_deg, const SingleZoneCycle& c) {
  if (theta_deg <= c.combustionStart_deg)
    return 0.0;
  const double x = (theta_deg - c.combustionStart_deg) / c.combustionDuration_deg;
  return 1.0 - std::exp(-kWiebeA * x * x * x);
}

// Cosine blend: 1 at a, 0 at b.
double blend(double theta_deg, double a, double b) {
  return 0.5 * (1.0 + std::cos(M_PI * (theta_deg - a) / (b - a)));
}

}  // namespace

std::vector<double> calcSingleZonePressure_Pa(const SingleZoneCycle& c,
                                              const CylinderVolume& vol,
                                              double heatReleased_J) {
  checkCycle(c);
  require(heatReleased_J >= 0.0 && std::isfinite(heatReleased_J),
          "heat released " + std::to_string(heatReleased_J) + " J must be >= 0");
  const int n = static_cast<int>(std::lround(720.0 / kFine_deg));
  std::vector<double> pr(n, 0.0);
  const double pInt = c.intakePressure_Pa, pExh = c.exhaustPressure_Pa, k = c.polytropicExponent;
  auto V = [&](double th) { return vol.calcVolume_m3(th * kDeg); };
  auto dV = [&](double th) {  // per deg
    return vol.calcVolumeDerivative_m3prad(th * kDeg) * kDeg;
  };
  // Heat release per degree; the burn is measured from firing TDC (theta may be < 0).
  auto dQ = [&](double th) {
    const double h = 1e-4;
    return heatReleased_J * (wiebeFraction(th + h, c) - wiebeFraction(th - h, c)) / (2 * h);
  };
  auto rhs = [&](double th, double pp) {
    return (k - 1.0) / V(th) * dQ(th - 720.0 * (th > 360.0)) - k * pp / V(th) * dV(th);
  };
  // Closed cycle from IVC (e.g. 580) to EVO + 720 (e.g. 860), RK4.
  double pp = pInt;
  const int iIvc = static_cast<int>(std::lround(c.intakeValveClosing_deg / kFine_deg));
  const int iEvo = static_cast<int>(std::lround((c.exhaustValveOpening_deg + 720.0) / kFine_deg));
  for (int i = iIvc; i <= iEvo; ++i) {
    pr[i % n] = pp;
    const double th = i * kFine_deg, h = kFine_deg;
    const double k1 = rhs(th, pp), k2 = rhs(th + h / 2, pp + h / 2 * k1);
    const double k3 = rhs(th + h / 2, pp + h / 2 * k2), k4 = rhs(th + h, pp + h * k3);
    pp += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  // Gas exchange: blow-down, exhaust stroke, blend to the intake pressure, intake stroke.
  const double pEvo = pr[iEvo % n];
  const double evo = c.exhaustValveOpening_deg;
  for (int i = (iEvo % n) + 1; i < iIvc; ++i) {
    const double th = i * kFine_deg;
    if (th < evo + kBlowDown_deg) {
      pr[i] = pExh + (pEvo - pExh) * blend(th, evo, evo + kBlowDown_deg);
    } else if (th < kIntakeBlendStart_deg) {
      pr[i] = pExh;
    } else if (th < kIntakeBlendEnd_deg) {
      pr[i] = pInt + (pExh - pInt) * blend(th, kIntakeBlendStart_deg, kIntakeBlendEnd_deg);
    } else {
      pr[i] = pInt;
    }
  }
  return pr;
}

double calcFineGridNetImep_Pa(const std::vector<double>& pr, const CylinderVolume& vol) {
  const int n = static_cast<int>(pr.size());
  double w = 0.0;
  for (int i = 0; i < n; ++i) {
    const double a = i * kFine_deg, b = (i + 1) * kFine_deg;
    w += 0.5 * (pr[i] + pr[(i + 1) % n]) *
         (vol.calcVolume_m3(b * kDeg) - vol.calcVolume_m3(a * kDeg));
  }
  return w / vol.displacement_m3();
}

SingleZonePressureTable makeSingleZonePressureTable(const SingleZoneCycle& c,
                                                    const CylinderVolume& vol,
                                                    std::optional<double> targetImep_Pa,
                                                    double tableStep_deg) {
  require(tableStep_deg >= kFine_deg && tableStep_deg <= 90.0,
          "table step " + std::to_string(tableStep_deg) + " deg must be in [0.01, 90] deg");
  require(!targetImep_Pa || std::isfinite(*targetImep_Pa), "the target imep must be finite");
  double q = 0.0;
  if (targetImep_Pa) {
    auto f = [&](double qq) {
      return calcFineGridNetImep_Pa(calcSingleZonePressure_Pa(c, vol, qq), vol) - *targetImep_Pa;
    };
    double q0 = 0.0, q1 = 1000.0 * vol.displacement_m3() * 1e3;  // ~ 1 kJ per litre
    double f0 = f(q0);
    require(f0 <= 0.0, "target imep " + std::to_string(*targetImep_Pa / 1e3) +
                           " kPa is below the motored cycle's " +
                           std::to_string((f0 + *targetImep_Pa) / 1e3) +
                           " kPa (it would need a negative heat release)");
    double f1 = f(q1);
    for (int it = 0; it < 50 && std::abs(f1) > 1e-6 && f1 != f0; ++it) {
      const double q2 = q1 - f1 * (q1 - q0) / (f1 - f0);
      q0 = q1;
      f0 = f1;
      q1 = std::max(q2, 0.0);
      f1 = f(q1);
    }
    // The imep is linear in Q_tot (the pressure is), so the secant lands in one or two
    // steps; anything else is a bug or a degenerate cycle.
    if (!(std::abs(f1) <= 1e-6 * std::max(1.0, std::abs(*targetImep_Pa))))
      throw std::runtime_error("single-zone pressure model: the heat release for imep " +
                               std::to_string(*targetImep_Pa / 1e3) + " kPa was not found");
    q = q1;
  }
  const std::vector<double> fine = calcSingleZonePressure_Pa(c, vol, q);
  SingleZonePressureTable table;
  table.heatReleased_J = q;
  table.netImep_Pa = calcFineGridNetImep_Pa(fine, vol);
  const auto stride =
      static_cast<std::size_t>(std::max(1L, std::lround(tableStep_deg / kFine_deg)));
  for (std::size_t i = 0; i < fine.size(); i += stride) {
    table.crankAngle_deg.push_back(static_cast<double>(i) * kFine_deg);
    table.pressure_Pa.push_back(fine[i]);
  }
  return table;
}

}  // namespace pistondyn::mbd
