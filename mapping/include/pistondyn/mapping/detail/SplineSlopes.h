#pragma once
/// \file
/// Internal to pistondyn::mapping (used by HermiteSurface); not part of the public API.
/// Slopes (first derivatives at the nodes) of the interpolating cubic spline along one
/// grid direction, for many lines at once. The linear system depends only on the node
/// positions, so it is factorised once at construction and reused for every update of
/// the nodal values.
///
///   open lines, n >= 4: not-a-knot end conditions (de Boor, "A Practical Guide to
///                       Splines", ch. IV; the same equations as MATLAB's spline.m), so
///                       every cubic polynomial is reproduced exactly;
///   open lines, n == 3: slopes of the interpolating parabola (not-a-knot is singular);
///   open lines, n == 2: slope of the chord;
///   closed lines, n >= 3: periodic spline (C2 across the seam), cyclic tridiagonal
///                       system solved by Sherman-Morrison on a Thomas factorisation.
///
/// All lines are processed together, one node position at a time (vector operations over
/// the lines), so the serial recurrences of the Thomas algorithm are vectorised.

#include <vector>

#include <Eigen/Core>

namespace pistondyn::mapping::detail {

/// Slopes of the interpolating cubic spline along one grid direction for many lines at once
/// (the documentation of SplineSlopes.h); factorised once per node set.
class SplineSlopes {
 public:
  /// How the lines lie in the matrices passed to calcSlopes().
  enum class Lines {
    InColumns,  ///< node index = row, one line per column
    InRows,     ///< node index = column, one line per row
  };

  SplineSlopes() = default;
  /// x: strictly increasing nodes; closed: the line closes with a cell of width
  /// x[0] + period - x[n-1].
  SplineSlopes(const Eigen::VectorXd& x, bool closed, double period);

  /// slopes (same shape as f) of every line of f. `scratch` (caller-owned, resized to the
  /// number of lines if needed) is used for closed lines only.
  void calcSlopes(const Eigen::Ref<const Eigen::MatrixXd>& f, Eigen::Ref<Eigen::MatrixXd> slopes,
                  Lines lines, Eigen::VectorXd& scratch) const;

 private:
  template <class Node>
  void run(const Eigen::Ref<const Eigen::MatrixXd>& f, Eigen::Ref<Eigen::MatrixXd>& m, Node node,
           Eigen::VectorXd& scratch) const;

  int n_ = 0;
  bool closed_ = false;
  bool solve_ = false;  ///< false: the stencil gives the slopes directly (open, n <= 3)
  /// Right-hand side b_i = sum_s coeff_[3i+s] * f[index_[3i+s]] (3-point stencils).
  std::vector<int> index_;
  std::vector<double> coeff_;
  std::vector<double> lower_;     ///< Thomas multipliers l_i = a_i / piv_{i-1}
  std::vector<double> invPivot_;  ///< 1 / piv_i
  std::vector<double> upper_;     ///< super-diagonal c_i
  std::vector<double> smZ_;       ///< Sherman-Morrison: solution z of T' z = u
  double smBetaOverGamma_ = 0.0;
  double smInvDenominator_ = 1.0;  ///< 1 / (1 + v.z)
};

}  // namespace pistondyn::mapping::detail
