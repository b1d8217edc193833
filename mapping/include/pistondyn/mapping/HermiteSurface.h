#pragma once
/// \file
/// Bicubic Hermite surface on a CylinderGrid (thesis eq. 9): a scalar field (skirt
/// profile, ovality, temperature, deformation, ...) known at the grid nodes becomes a C1
/// function of (phi, y) that can be read at any point, e.g. at the nodes of another
/// grid that moves relative to this one.
///
/// In every cell [phi_i, phi_i+1] x [y_j, y_j+1], with local coordinates
/// t = (phi - phi_i)/h_phi and u = (y - y_j)/h_y in [0, 1],
///
///   f(t, u) = g(t)^T G g(u),   g = [h00, h01, h10, h11] (cubic Hermite basis),
///   G = [ f00        f01        hy*fy00          hy*fy01        ]
///       [ f10        f11        hy*fy10          hy*fy11        ]
///       [ hphi*fp00  hphi*fp01  hphi*hy*fpy00    hphi*hy*fpy01  ]
///       [ hphi*fp10  hphi*fp11  hphi*hy*fpy10    hphi*hy*fpy11  ]
///
/// (f = value, fp = df/dphi, fy = df/dy, fpy = d2f/dphi dy at the cell corners, first
/// index the phi corner, second the y corner; the thesis' f, s, l, k). The surface stores
/// G per cell and evaluates eq. 9 in this Hermite form (not expanded into powers of t, u:
/// the Hermite form reproduces the nodal data exactly at cell edges, so neighbouring cells
/// agree to the last bit there, and it keeps derivatives better conditioned).
///
/// Nodal derivatives either come with the data (caller-supplied) or are taken from the
/// values by interpolating cubic splines along every grid line: not-a-knot on open lines
/// (>= 4 nodes; 3 nodes give the parabola, 2 the chord), periodic where the grid closes
/// the circle; the cross derivative is the phi-spline slope of the y-spline slopes. With
/// spline derivatives the surface is the tensor-product cubic spline interpolant: it
/// reproduces every bicubic polynomial exactly (sector grids with >= 4 nodes in each
/// direction), converges at fourth order on smooth data and is C1 everywhere, across the
/// periodic seam included (tests/mapping/test_hermite_surface.cpp).
///
/// Cost model (thesis §2.3.1): construction factorises the spline systems (they depend on
/// the node positions only) and computes every cell's C. Data that never change (profile,
/// ovality, temperatures) are built once. When the nodal values change (deformation),
/// updateValues() reuses the factorisations and recomputes slopes and C in O(nodes).
///
/// Thread safety: every const member function is safe to call concurrently; per-call
/// scratch of evaluateOnGrid() is the caller's HermiteGridWorkspace (one per thread).
/// updateValues() mutates the surface: do not call it while others evaluate.

#include <vector>

#include <Eigen/Core>

#include "pistondyn/mapping/CylinderGrid.h"
#include "pistondyn/mapping/detail/SplineSlopes.h"

namespace pistondyn::mapping {

/// Value and derivatives at one point. Derivatives are per radian and per metre; the
/// derivative along the developed arc length s = R*phi is dPhi / R.
struct HermiteSample {
  double value = 0.0;   ///< [unit of the field]
  double dPhi = 0.0;    ///< d value / d phi [unit/rad]
  double dY = 0.0;      ///< d value / d y [unit/m]
  double dPhiDY = 0.0;  ///< d2 value / (d phi d y) [unit/(rad m)]
};

/// What to do with a point outside the grid (only possible in y, and in phi for sectors).
/// Points within 1e-12 of the grid's extent outside an end are always clamped onto it.
enum class OutsidePolicy {
  Throw,           ///< std::invalid_argument naming the coordinate (default)
  ExtendEndCells,  ///< evaluate the end cell's bicubic polynomial beyond its edge
};

/// Caller-owned scratch for HermiteSurface::evaluateOnGrid (cell indices and Hermite basis
/// values at the local coordinates of the target nodes). Reused between calls: no allocation after
/// the first call at a given target size.
struct HermiteGridWorkspace {
  std::vector<int> phiCell;                            ///< phi cell of each target phi node
  std::vector<int> yCell;                              ///< y cell of each target y node
  Eigen::Matrix<double, 4, Eigen::Dynamic> phiBasis;   ///< Hermite basis in phi per node
  Eigen::Matrix<double, 4, Eigen::Dynamic> phiDBasis;  ///< its derivative
  Eigen::Matrix<double, 4, Eigen::Dynamic> yBasis;     ///< Hermite basis in y per node
  Eigen::Matrix<double, 4, Eigen::Dynamic> yDBasis;    ///< its derivative
};

/// Bicubic Hermite interpolation of nodal values on a CylinderGrid (thesis eq. 9; this
/// file's documentation): built once, values updated without refactorising.
class HermiteSurface {
 public:
  /// Surface from nodal values; derivatives from splines along the grid lines.
  /// Inputs:
  ///   grid    the grid the values live on (copied)
  ///   values  grid.nodeCount() finite nodal values, node (i, j) at i + nPhi*j
  /// Throws std::invalid_argument on wrong size or non-finite values.
  HermiteSurface(CylinderGrid grid, const Eigen::Ref<const Eigen::VectorXd>& values);

  /// Surface from nodal values and caller-supplied nodal derivatives (same layout):
  /// dPhi = d/dphi [unit/rad], dY = d/dy [unit/m], dPhiDY = d2/(dphi dy) [unit/(rad m)].
  HermiteSurface(CylinderGrid grid, const Eigen::Ref<const Eigen::VectorXd>& values,
                 const Eigen::Ref<const Eigen::VectorXd>& dPhi,
                 const Eigen::Ref<const Eigen::VectorXd>& dY,
                 const Eigen::Ref<const Eigen::VectorXd>& dPhiDY);

  /// New nodal values on the same grid (e.g. deformation of this step): spline slopes and
  /// cell coefficients are recomputed with the stored factorisations; no allocation.
  void updateValues(const Eigen::Ref<const Eigen::VectorXd>& values);
  /// New nodal values and derivatives (caller-supplied); no allocation.
  void updateValues(const Eigen::Ref<const Eigen::VectorXd>& values,
                    const Eigen::Ref<const Eigen::VectorXd>& dPhi,
                    const Eigen::Ref<const Eigen::VectorXd>& dY,
                    const Eigen::Ref<const Eigen::VectorXd>& dPhiDY);

  const CylinderGrid& grid() const { return grid_; }  ///< the grid the values live on
  /// Nodal data in use (flat, node (i, j) at i + nPhi*j).
  const Eigen::VectorXd& values() const { return values_; }
  const Eigen::VectorXd& dPhi() const { return dPhi_; }      ///< d/dphi [unit/rad]
  const Eigen::VectorXd& dY() const { return dY_; }          ///< d/dy [unit/m]
  const Eigen::VectorXd& dPhiDY() const { return dPhiDY_; }  ///< d2/(dphi dy) [unit/(rad m)]

  /// The matrix G of eq. 9 for cell (i, j): f(t, u) = g(t)^T G g(u).
  /// i in [0, grid().phiCellCount()), j in [0, grid().yCellCount()).
  Eigen::Matrix4d cellCoefficients(int i, int j) const;

  /// Value and derivatives at (phi_rad, y_m) of this grid's frame. phi is taken modulo
  /// 2*pi. Throws std::invalid_argument for non-finite coordinates, |phi_rad| above
  /// kMaxAbsAngle_rad (1e6 rad; the reduction modulo 2*pi would lose every digit, e.g. at
  /// 1e300), and for points outside the grid under OutsidePolicy::Throw. The same bound
  /// applies to evaluateOnGrid's offset.phi_rad.
  HermiteSample evaluate(double phi_rad, double y_m,
                         OutsidePolicy outside = OutsidePolicy::Throw) const;

  /// The polynomial of cell (i, j) at local coordinates (t, u) (t, u in [0, 1] inside the
  /// cell). No wrapping or clamping: this is eq. 9 of one cell, e.g. to compare both
  /// sides of a cell boundary.
  HermiteSample evaluateInCell(int i, int j, double t, double u) const;

  /// Values at every node of `points`, whose node (phi, y) lies at
  /// (phi + offset.phi_rad, y + offset.y_m) of this surface's frame. Outputs have
  /// points.nodeCount() entries (same layout). The derivative overload also returns
  /// d/dphi and d/dy (per rad, per m). Scratch lives in `ws`.
  void evaluateOnGrid(const CylinderGrid& points, GridOffset offset,
                      Eigen::Ref<Eigen::VectorXd> values, HermiteGridWorkspace& ws,
                      OutsidePolicy outside = OutsidePolicy::Throw) const;
  /// Values with their derivatives d/dphi [unit/rad] and d/dy [unit/m] (see above).
  void evaluateOnGrid(const CylinderGrid& points, GridOffset offset,
                      Eigen::Ref<Eigen::VectorXd> values, Eigen::Ref<Eigen::VectorXd> dPhi,
                      Eigen::Ref<Eigen::VectorXd> dY, HermiteGridWorkspace& ws,
                      OutsidePolicy outside = OutsidePolicy::Throw) const;

 private:
  /// Grid, factorisations and storage; values set by the public constructors.
  explicit HermiteSurface(CylinderGrid grid);
  void checkValues(const char* function, const Eigen::Ref<const Eigen::VectorXd>& values) const;
  void calcSplineSlopes();
  void calcCellCoefficients();
  /// Cell index and local coordinate of one coordinate (fn names the caller in errors).
  void locatePhi(const char* fn, double phi_rad, OutsidePolicy outside, int& cell, double& t) const;
  void locateY(const char* fn, double y_m, OutsidePolicy outside, int& cell, double& u) const;
  void prepareGrid(const char* fn, const CylinderGrid& points, GridOffset offset,
                   Eigen::Index outputSize, HermiteGridWorkspace& ws, OutsidePolicy outside) const;

  CylinderGrid grid_;
  detail::SplineSlopes phiSlopes_, ySlopes_;
  Eigen::VectorXd phiCellWidth_, yCellWidth_;
  Eigen::VectorXd values_, dPhi_, dY_, dPhiDY_;
  std::vector<double> coeff_;  ///< G of eq. 9, 16 per cell, cell (i, j) at i + phiCellCount*j
  Eigen::VectorXd phiLineScratch_, yLineScratch_;  ///< one entry per line (spline solves)
};

}  // namespace pistondyn::mapping
