#pragma once
/// \file
/// A one-dimensional table f(x), read either as its piecewise-linear interpolant or as the
/// monotone piecewise cubic Hermite interpolant (PCHIP), with the first derivative.
///
/// PCHIP (Fritsch & Carlson, "Monotone piecewise cubic interpolation", SIAM J. Numer. Anal.
/// 17(2), 1980, 238-246; slopes by the weighted harmonic mean of Fritsch & Butland, SIAM J. Sci.
/// Stat. Comput. 5(2), 1984, 300-304 - the form used by MATLAB's pchip and SciPy's
/// PchipInterpolator):
///   * node slopes d_k: 0 where the secants delta_{k-1}, delta_k differ in sign or one is 0,
///     else 1/d_k = (w1/delta_{k-1} + w2/delta_k)/(w1 + w2), w1 = 2h_k + h_{k-1},
///     w2 = h_k + 2h_{k-1}; end slopes by the shape-preserving three-point formula (set to 0
///     if its sign differs from the end secant, limited to 3x the end secant when the first
///     two secants differ in sign);
///   * the result is C1, passes through every row exactly, is monotone on every interval
///     (no overshoot: the interpolant stays between the two rows of each interval), and
///     reproduces linear data exactly. Its extrema are therefore at table rows or at the ends.
///   * a 2-row table is the straight line; a 1-row table is the constant.
///
/// Linear: the derivative at an interior row is the slope of the interval to its right.
///
/// Outside [x_first, x_last] every table extends its end values as constants (derivative 0; at
/// the end rows themselves the derivative is that of the end interval); callers that need the
/// table to cover a range check it themselves.

#include <string>

#include <Eigen/Core>

namespace pistondyn::skirt {

/// How a table is interpolated between its rows.
enum class Interpolation {
  Linear,  ///< piecewise linear (C0)
  Pchip,   ///< monotone piecewise cubic Hermite (C1, no overshoot)
};

/// Value of a table and its derivative with respect to the abscissa at one point.
struct TableSample {
  double value = 0.0;       ///< f(x), unit of the table values
  double derivative = 0.0;  ///< df/dx, table value unit per abscissa unit
};

/// A one-dimensional table interpolated linearly or by PCHIP, constant beyond its ends.
class InterpolatedTable {
 public:
  /// The empty table: value 0 and derivative 0 everywhere.
  InterpolatedTable() = default;

  /// Inputs:
  ///   x_m, f       abscissae (strictly increasing, finite, >= 1 row) and values (finite, same
  ///                length); the names below say what they are in messages
  ///   method       Linear or Pchip
  ///   where        who is building the table, e.g. "AxialProfileParameters"
  ///   xName/xUnit, fName/fUnit   member names and units for messages
  /// Throws std::invalid_argument naming the member and the row.
  InterpolatedTable(Eigen::VectorXd x, Eigen::VectorXd f, Interpolation method,
                    const std::string& where, const std::string& xName, const std::string& xUnit,
                    const std::string& fName, const std::string& fUnit);

  /// Value and derivative at x (finite); constant extension outside the table.
  TableSample evaluate(double x) const;
  double value(double x) const { return evaluate(x).value; }  ///< value at x only

  bool empty() const { return x_.size() == 0; }              ///< the empty table
  int rows() const { return static_cast<int>(x_.size()); }   ///< number of rows
  double firstAbscissa() const { return x_[0]; }             ///< smallest x (not empty)
  double lastAbscissa() const { return x_[x_.size() - 1]; }  ///< largest x (not empty)
  const Eigen::VectorXd& abscissae() const { return x_; }    ///< the rows' x
  const Eigen::VectorXd& values() const { return f_; }       ///< the rows' values
  /// Node slopes d_k (PCHIP) or interval secants (Linear, one fewer).
  const Eigen::VectorXd& slopes() const { return d_; }
  Interpolation method() const { return method_; }  ///< Linear or Pchip

 private:
  Eigen::VectorXd x_, f_, d_;
  Interpolation method_ = Interpolation::Linear;
};

}  // namespace pistondyn::skirt
