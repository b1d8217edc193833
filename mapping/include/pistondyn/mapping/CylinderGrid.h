#pragma once
/// \file
/// Structured grid on a cylinder surface: circumferential angle phi [rad] x axial
/// coordinate y [m], vertex-centred (values live at the nodes), graded spacing allowed.
///
/// A grid is either a *sector* (nodes phi_0 < ... < phi_{n-1}, n-1 cells, the ends are
/// open) or a *full circle* (same nodes, n cells: the last cell closes the ring from
/// phi_{n-1} to phi_0 + 2*pi, so the grid is periodic in phi). The developed (unrolled)
/// surface coordinate is the arc length s = R * phi.
///
/// Node ordering of every nodal field in pistondyn::mapping: node (i, j) with
/// i = 0..nPhi()-1 along phi and j = 0..nY()-1 along y is entry k = i + nPhi() * j
/// (phi fastest), i.e. an Eigen column-major nPhi x nY matrix stored flat.
///
/// Grids are immutable values; copying one copies two short vectors.

#include <utility>

#include <Eigen/Core>

namespace pistondyn::mapping {

/// Largest |angle| accepted anywhere in pistondyn::mapping (node angles, offsets, evaluation
/// points) [rad]: 1e6 rad, about 159,000 turns. Reducing such an angle modulo 2*pi costs at
/// most ~2e-10 rad of accuracy; far beyond it the reduction returns garbage (at 1e300 every
/// digit is lost), so larger angles throw std::invalid_argument naming the argument.
inline constexpr double kMaxAbsAngle_rad = 1e6;

/// Position of one grid's coordinate origin in another grid's frame: a node at
/// (phi, y) of the moving grid lies at (phi + phi_rad, y + y_m) of the fixed grid.
struct GridOffset {
  double phi_rad = 0.0;  ///< circumferential offset [rad], default 0
  double y_m = 0.0;      ///< axial offset [m], default 0
};

/// Structured vertex-centred grid on a cylinder surface, a sector or a full circle (this
/// file's documentation gives the node order).
class CylinderGrid {
 public:
  /// A sector grid (open in phi).
  /// Inputs:
  ///   radius_m  surface radius R [m], > 0 and finite
  ///   phi_rad   node angles [rad], >= 2 entries, finite, |phi| <= kMaxAbsAngle_rad,
  ///             strictly increasing,
  ///             phi_rad[last] - phi_rad[0] < 2*pi (use fullCircle() for a closed ring)
  ///   y_m       axial node positions [m], >= 2 entries, finite, strictly increasing
  /// Throws std::invalid_argument naming the offending argument.
  static CylinderGrid sector(double radius_m, const Eigen::VectorXd& phi_rad,
                             const Eigen::VectorXd& y_m);

  /// A full-circle grid (periodic in phi): like sector(), but phi_rad needs >= 3 entries
  /// and the ring is closed by the cell from phi_rad[last] to phi_rad[0] + 2*pi, so the
  /// node at phi_rad[0] + 2*pi must NOT be repeated (phi_rad[last] < phi_rad[0] + 2*pi).
  /// That closing cell must be at least 1 % of the smallest other phi cell: a first node
  /// repeated at the end with rounding (2*pi - 1e-13) throws instead of creating a cell
  /// 1e-13 rad wide.
  static CylinderGrid fullCircle(double radius_m, const Eigen::VectorXd& phi_rad,
                                 const Eigen::VectorXd& y_m);

  double radius_m() const { return radius_m_; }                ///< surface radius R [m]
  const Eigen::VectorXd& phi_rad() const { return phi_rad_; }  ///< node angles [rad]
  const Eigen::VectorXd& y_m() const { return y_m_; }          ///< axial node positions [m]
  bool isClosed() const { return closed_; }                    ///< a full circle

  int nPhi() const { return static_cast<int>(phi_rad_.size()); }  ///< nodes along phi
  int nY() const { return static_cast<int>(y_m_.size()); }        ///< nodes along y
  int nodeCount() const { return nPhi() * nY(); }                 ///< nPhi * nY
  int index(int i, int j) const { return i + nPhi() * j; }        ///< k = i + nPhi * j

  /// Cells along phi: nPhi() for a full circle, nPhi() - 1 for a sector.
  int phiCellCount() const { return closed_ ? nPhi() : nPhi() - 1; }
  int yCellCount() const { return nY() - 1; }  ///< cells along y: nY() - 1
  /// Angle where the phi range ends: phi_rad[0] + 2*pi (full circle) or phi_rad[last].
  double phiEnd_rad() const;
  /// Node angle with the closing node of a full circle: phiNode_rad(nPhi()) = phi_0 + 2*pi.
  double phiNode_rad(int i) const { return i < nPhi() ? phi_rad_[i] : phiEnd_rad(); }

  /// Integral of each node's bilinear shape function over the developed surface,
  /// R * (trapezoid weight in phi) * (trapezoid weight in y) [m^2]; sums to the grid area.
  Eigen::VectorXd nodeArea_m2() const;

 private:
  CylinderGrid(double radius_m, Eigen::VectorXd phi_rad, Eigen::VectorXd y_m, bool closed)
      : radius_m_(radius_m), phi_rad_(std::move(phi_rad)), y_m_(std::move(y_m)), closed_(closed) {}

  double radius_m_;
  Eigen::VectorXd phi_rad_;
  Eigen::VectorXd y_m_;
  bool closed_;
};

/// count equally spaced nodes from first to last (both included), count >= 2.
Eigen::VectorXd uniformNodes(double first, double last, int count);

/// count equally spaced angles phi0 + 2*pi*i/count, i = 0..count-1, for fullCircle().
Eigen::VectorXd fullCircleNodes_rad(int count, double phi0_rad = 0.0);

}  // namespace pistondyn::mapping
