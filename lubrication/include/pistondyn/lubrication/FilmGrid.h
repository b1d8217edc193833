#pragma once
/// \file
/// Structured vertex-centred grid of one film region (a skirt side, a full-circle liner band,
/// a journal bearing): circumferential coordinate x (arc length, m) times axial coordinate y (m),
/// uniform or graded, optionally periodic in x.
///
/// Node (i, j) sits at (x[i], y[j]); its flat index is k = i + nx * j (x runs fastest). Every
/// nodal field the film solver takes or returns uses that order.
///
/// The pressure is the bilinear interpolant of the nodal values, so
///   * areaWeights_m2()[k]  = integral of node k's bilinear shape function = the area of its
///     vertex-centred control volume (tensor-product trapezoid weights); sum_k w_k p_k is the
///     exact integral of the interpolant;
///   * xFirstMomentWeights_m3()[k] = integral of x * N_k dA and yFirstMomentWeights_m3()[k]
///     the same with y, so first moments of the interpolant are exact too.
/// With a periodic x the cell between the last node and the first one closes the circle; the
/// first node is then at x[0] on its right-hand half-cell and at x[0] + period on its left-hand
/// half-cell (the moment weights integrate over [x[0], x[0] + period)).

#include <Eigen/Core>

namespace pistondyn::lubrication {

/// Structured vertex-centred grid of one film region with exact area and first-moment
/// weights (the documentation of FilmGrid.h gives the node order and the weights' meaning).
class FilmGrid {
 public:
  /// Uniform grid. Open x: nx nodes from x0_m to x0_m + lengthX_m (both edges are nodes).
  /// Periodic x: nx nodes spaced lengthX_m / nx starting at x0_m, period lengthX_m.
  /// y: ny nodes from y0_m to y0_m + lengthY_m.
  /// Throws std::invalid_argument when nx < 3, ny < 3 or a length is not positive and finite.
  static FilmGrid uniform(int nx, double lengthX_m, int ny, double lengthY_m,
                          bool periodicX = false, double x0_m = 0.0, double y0_m = 0.0);

  /// Graded grid from strictly increasing node coordinates (at least 3 each, finite).
  /// periodicX: x nodes lie in one period, periodX_m > x.back() - x.front().
  static FilmGrid fromCoordinates(Eigen::VectorXd x_m, Eigen::VectorXd y_m, bool periodicX = false,
                                  double periodX_m = 0.0);

  /// n coordinates from a to b clustered towards both ends (tanh stretching; clustering >= 0,
  /// 0 gives uniform spacing, 2..3 is a strong clustering). Useful to resolve open edges.
  static Eigen::VectorXd clusteredCoordinates(int n, double a, double b, double clustering);

  int nx() const { return static_cast<int>(x_.size()); }      ///< nodes along x
  int ny() const { return static_cast<int>(y_.size()); }      ///< nodes along y
  int nodeCount() const { return nx() * ny(); }               ///< nx * ny
  int nodeIndex(int i, int j) const { return i + nx() * j; }  ///< k = i + nx * j

  const Eigen::VectorXd& x_m() const { return x_; }  ///< node coordinates along x [m]
  const Eigen::VectorXd& y_m() const { return y_; }  ///< node coordinates along y [m]
  bool isPeriodicX() const { return periodicX_; }    ///< x closes on itself
  double periodX_m() const { return periodX_; }      ///< period along x [m]; 0 for an open x

  /// Distance from node i to node i+1 along x (wraps to the first node when periodic; 0 for
  /// the last node of an open x), and from j to j+1 along y (0 for the last row).
  double dxEast_m(int i) const;
  /// See dxEast_m.
  double dyNorth_m(int j) const { return j + 1 < ny() ? y_[j + 1] - y_[j] : 0.0; }

  /// One-dimensional trapezoid weights along x (integral of the 1-D hat of node i) [m].
  const Eigen::VectorXd& xWeights_m() const { return wx_; }
  /// One-dimensional trapezoid weights along y [m].
  const Eigen::VectorXd& yWeights_m() const { return wy_; }
  /// Exact one-dimensional first-moment weights along x, integral of x times the hat [m²].
  const Eigen::VectorXd& xFirstMomentWeights_m2() const { return mx_; }
  /// Exact one-dimensional first-moment weights along y [m²].
  const Eigen::VectorXd& yFirstMomentWeights_m2() const { return my_; }

  /// Tensor-product nodal area weights (size nodeCount(), k = i + nx*j) [m²].
  const Eigen::ArrayXd& areaWeights_m2() const { return area_; }
  /// Nodal weights of the first moment in x, integral of x N_k dA [m³].
  const Eigen::ArrayXd& xFirstMomentWeights_m3() const { return areaMx_; }
  /// Nodal weights of the first moment in y, integral of y N_k dA [m³].
  const Eigen::ArrayXd& yFirstMomentWeights_m3() const { return areaMy_; }

  /// Total area of the film region (sum of areaWeights_m2()).
  double area_m2() const { return area_.sum(); }

 private:
  FilmGrid() = default;
  void computeWeights();

  Eigen::VectorXd x_, y_;
  bool periodicX_ = false;
  double periodX_ = 0.0;
  Eigen::VectorXd wx_, wy_, mx_, my_;
  Eigen::ArrayXd area_, areaMx_, areaMy_;
};

}  // namespace pistondyn::lubrication
