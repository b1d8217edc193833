#pragma once
/// \file
/// A synthetic cylinder-pressure cycle from a single-zone model, for decks that have no
/// measured trace: the generator behind `make_pressure_curve` and `pistondyn new`.
///
/// Model (single zone, crank angle 0 = firing TDC, 720 deg cycle):
///   closed cycle IVC -> EVO + 720:  dp/dtheta = (k-1)/V dQ/dtheta - k p/V dV/dtheta, RK4 on
///       a 0.01 deg grid from p(IVC) = intake pressure, with a Wiebe heat release
///       Q = Q_tot (1 - exp(-6.908 ((theta - theta_s)/dtheta)^3)) (a = 6.908: 99.9 % burnt at
///       theta_s + dtheta; m = 2); Q_tot = 0 is the motored cycle. k is an effective
///       polytropic exponent (heat loss lumped in).
///   blow-down EVO -> EVO + 60: cosine blend from p(EVO) to the exhaust pressure;
///   exhaust stroke at the exhaust pressure; 370 -> 400 deg cosine blend to the intake
///   pressure; intake stroke at the intake pressure until IVC.
/// The net imep is the closed integral of p dV over V_d by the trapezoid rule on the same
/// 0.01 deg grid. For a target imep, Q_tot is found by the secant method.
///
/// Pure numerics: no files, no printing (io/PressureTableCsv.h writes the table).

#include <optional>
#include <vector>

#include "pistondyn/mbd_models/SliderCrank.h"

namespace pistondyn::mbd {

/// The model's parameters (SI pressures, angles in degrees from firing TDC). The defaults
/// are make_pressure_curve's.
struct SingleZoneCycle {
  double polytropicExponent = 1.30;        ///< k, > 1 (heat loss lumped in)
  double intakePressure_Pa = 1.0e5;        ///< > 0, absolute
  double exhaustPressure_Pa = 1.05e5;      ///< > 0, absolute
  double intakeValveClosing_deg = 580.0;   ///< IVC, in [400, 720) (after the intake blend)
  double exhaustValveOpening_deg = 140.0;  ///< EVO, in (0, 310] (blow-down ends by 370)
  double combustionStart_deg = -15.0;      ///< start of combustion, finite, before EVO
  double combustionDuration_deg = 50.0;    ///< Wiebe duration (99.9 % burnt), > 0
};

/// Integration step of the closed cycle and of the imep integral [deg].
inline constexpr double kSingleZoneFineStep_deg = 0.01;

/// A generated table: rows every tableStep_deg from 0 to below 720 deg.
struct SingleZonePressureTable {
  std::vector<double> crankAngle_deg;  ///< 0, step, 2 step, ... < 720 [deg]
  std::vector<double> pressure_Pa;     ///< absolute [Pa]
  double heatReleased_J = 0.0;         ///< Q_tot per cycle [J]; 0 = motored
  double netImep_Pa = 0.0;             ///< of the fine-grid cycle (trapezoid, 0.01 deg) [Pa]
};

/// The cycle's pressure [Pa] on the fine grid theta_i = i * 0.01 deg, i = 0 .. 71999, with
/// `heatReleased_J` released per cycle (0: motored). Throws std::invalid_argument naming
/// the parameter if `cycle` breaks its documented ranges or the heat is negative.
std::vector<double> calcSingleZonePressure_Pa(const SingleZoneCycle& cycle,
                                              const CylinderVolume& volume,
                                              double heatReleased_J);

/// Net imep [Pa] of a fine-grid cycle (calcSingleZonePressure_Pa's grid): the trapezoid
/// rule on the 0.01 deg grid, closed over 720 deg.
double calcFineGridNetImep_Pa(const std::vector<double>& finePressure_Pa,
                              const CylinderVolume& volume);

/// The table: rows every `tableStep_deg` (a multiple of 0.01 deg, at least 0.01; rounded to
/// the nearest multiple) of the cycle with no heat release (`targetImep_Pa` empty: motored)
/// or with the heat release whose net imep is `targetImep_Pa` (secant method to 1e-6 Pa).
/// Throws std::invalid_argument for bad parameters or a target below the motored cycle's
/// imep (it would need a negative heat release), std::runtime_error if the secant method
/// does not reach the target.
SingleZonePressureTable makeSingleZonePressureTable(const SingleZoneCycle& cycle,
                                                    const CylinderVolume& volume,
                                                    std::optional<double> targetImep_Pa,
                                                    double tableStep_deg);

}  // namespace pistondyn::mbd
