#pragma once
// Internal to pistondyn::mapping (used by HermiteSurface); not part of the public API.
// Slopes (first derivatives at the nodes) of the interpolating cubic spline along one
// grid direction, for many lines at once. The linear system depends only on the node
// positions, so it is factorised once at construction and reused for every update of
// the nodal values.
//
//   open lines, n >= 4: not-a-knot end conditions (de Boor, "A Practical Guide to
//                       Splines", ch. IV; the same equations as MATLAB's spline.m), so
//                       every cubic polynomial is reproduced exactly;
//   open lines, n == 3: slopes of the interpolating parabola (not-a-knot is singular);
//   open lines, n == 2: slope of the chord;
//   closed lines, n >= 3: periodic spline (C2 across the seam), cyclic tridiagonal
//                       system solved by Sherman-Morrison on a Thomas factorisation.

#include <vector>

#include <Eigen/Core>

namespace pistondyn::mapping::detail {

class SplineSlopes {
 public:
  SplineSlopes() = default;
  // x: strictly increasing nodes; closed: the line closes with a cell of width
  // x[0] + period - x[n-1].
  SplineSlopes(const Eigen::VectorXd& x, bool closed, double period);

  // f: n x lines (one line per column); slopes: n x lines, same shape as f.
  void calcSlopes(const Eigen::Ref<const Eigen::MatrixXd>& f,
                  Eigen::Ref<Eigen::MatrixXd> slopes) const;

 private:
  void rhs(const double* f, double* b) const;
  void solveTridiagonal(double* d) const;  // in place, factors of the (modified) matrix

  int n_ = 0;
  bool closed_ = false;
  std::vector<double> h_;      // cell widths (n-1 open, n closed)
  std::vector<double> lower_;  // Thomas multipliers l_i = a_i / piv_{i-1}
  std::vector<double> pivot_;  // Thomas pivots
  std::vector<double> upper_;  // super-diagonal c_i
  std::vector<double> smZ_;    // Sherman-Morrison: solution z of T' z = u
  double smBetaOverGamma_ = 0.0;
  double smDenominator_ = 1.0;  // 1 + v.z
};

}  // namespace pistondyn::mapping::detail
