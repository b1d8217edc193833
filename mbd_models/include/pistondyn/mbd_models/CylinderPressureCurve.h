#pragma once
/// \file
/// Cylinder gas pressure against crank angle, periodic over the 720 deg four-stroke
/// cycle, interpolated by a periodic cubic spline (C2, so the gas force the integrator
/// sees is smooth). Angles are crank angles from firing TDC in degrees; pressures are
/// absolute, in Pa. Reading the table from a file is the caller's business (edge code).

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "pistondyn/mbd_models/SliderCrank.h"

namespace pistondyn::mbd {

/// An unusable pressure table. row() is the 0-based index of the row the problem is at (also
/// named in the message), when there is one, so that a reader can translate it into its own
/// line numbers.
class PressureTableError : public std::invalid_argument {
 public:
  /// The message and the 0-based row it is about (if any).
  PressureTableError(const std::string& what, std::optional<std::size_t> row)
      : std::invalid_argument(what), row_(row) {}
  std::optional<std::size_t> row() const { return row_; }  ///< 0-based row, if any

 private:
  std::optional<std::size_t> row_;
};

/// Cylinder pressure over the 720 deg cycle as a periodic cubic spline (this file's
/// documentation).
class CylinderPressureCurve {
 public:
  static constexpr double kCycle_deg = 720.0;  ///< the four-stroke cycle [deg]

  /// Inputs:
  ///   crankAngle_deg  strictly increasing angles covering one cycle: either the last
  ///                   angle is first + 720 (its pressure must equal the first within
  ///                   0.5 % of the peak, and it is dropped as the periodic duplicate),
  ///                   or the gap from the last angle to first + 720 is no larger than
  ///                   the table's largest step. At least 4 distinct angles.
  ///   pressure_Pa     absolute pressure at each angle, > 0 and finite; the spline must
  ///                   stay > 0 between the knots too (a coarse table around a sharp
  ///                   peak can make it undershoot: rejected, naming the interval).
  /// Throws PressureTableError (a std::invalid_argument) naming the offending row otherwise.
  CylinderPressureCurve(std::vector<double> crankAngle_deg, std::vector<double> pressure_Pa);

  /// Pressure [Pa] at any crank angle (wrapped into the cycle).
  double calcPressure_Pa(double crankAngle_deg) const;
  /// dp/dtheta [Pa/deg].
  double calcPressureSlope_Paperdeg(double crankAngle_deg) const;

  double getPeakPressure_Pa() const { return peak_Pa_; }  ///< largest knot pressure [Pa]
  double getPeakPressureAngle_deg() const { return peakAngle_deg_; }   ///< its angle [deg]
  const std::vector<double>& getAngles_deg() const { return angle_; }  ///< the knots [deg]
  const std::vector<double>& getPressures_Pa() const { return p_; }    ///< knot values [Pa]

 private:
  /// Spline interval holding an angle: knots i, j (periodic), width h and the
  /// interpolation weights a (towards knot i) and b = 1 - a.
  struct Segment {
    std::size_t i, j;
    double h, a, b;
  };
  Segment locate(double crankAngle_deg) const;
  void requirePositiveBetweenKnots() const;  ///< throws if the spline undershoots to <= 0
  int findInterval(double wrappedAngle_deg) const;
  double wrap(double crankAngle_deg) const;

  std::vector<double> angle_;  ///< distinct knots, angle_[0] .. angle_[n-1] < angle_[0] + 720
  std::vector<double> p_;      ///< knot values
  std::vector<double> m_;      ///< knot second derivatives (periodic spline)
  double peak_Pa_ = 0.0, peakAngle_deg_ = 0.0;
};

/// Indicated mean effective pressure [Pa] of the 720 deg cycle: (closed integral of
/// p dV) / V_d, with V(theta) from the slider-crank kinematics. Net imep (includes the
/// gas-exchange loop). The integral is evaluated on the spline's own intervals, split
/// into sub-intervals of at most 1 deg, each with 8-point Gauss-Legendre (the
/// integrand is smooth there: a cubic times the smooth dV/dtheta).
double calcImep_Pa(const CylinderPressureCurve& pressure, const CylinderVolume& volume);

}  // namespace pistondyn::mbd
