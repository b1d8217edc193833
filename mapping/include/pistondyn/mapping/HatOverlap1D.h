#pragma once
/// \file
/// One-dimensional building block of the force mapping: the exact integrals of the
/// products of two families of 1-D piecewise-linear "hat" functions,
///
///   A[j, k] = integral a_k(x) b_j(x) w(x) dx,
///
/// a_k the source node k's hat (1 at its node, 0 at the neighbours), b_j the target node
/// j's basis (its hat for LoadRule::Consistent, the indicator of its half-cells for
/// LoadRule::HalfCell), w = 1, cos x or sin x (x = angle in the target frame). The
/// bilinear shape functions of a CylinderGrid are products of a phi-hat and a y-hat, so
/// the 2-D consistent-load matrix is R * kron(A_y, A_phi) (see ForceMap.h).
///
/// The integrand is quadratic (times cos/sin) on every overlap of a source cell with a
/// target cell; it is integrated in closed form there: the product of two linear
/// functions by L/6 (2 u0 v0 + u0 v1 + u1 v0 + 2 u1 v1), the trigonometric weights by
/// moments of theta^k cos/sin theta about the interval midpoint (series below 1 rad
/// half-width, where the closed forms would cancel). No quadrature error.
///
/// Angles are periodic with `period` = 2*pi: a source cell overlaps every 2*pi-shifted
/// copy of the target's angular range. For y (period 0) nothing wraps.

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace pistondyn::mapping {

/// What a target node collects (docs/DESIGN.md §4, thesis eq. 10 and Fig. 3).
enum class LoadRule {
  /// F_J = integral p_h * N_J dA with N_J the target's bilinear shape function: the
  /// consistent load. Conserves total force AND the first moments (default).
  Consistent,
  /// F_J = integral of p_h over the target node's half-cells (tributary area, the
  /// thesis' "half grid near the node" read literally): a lumped load. Conserves total
  /// force, but not the moments (see mapping/README.md).
  HalfCell,
};

/// Sparse target x source matrices (compressed by source column) and per-source-node
/// integrals. Reused between builds: storage only grows.
struct HatOverlap1D {
  int targetCount = 0;           ///< target nodes (rows)
  int sourceCount = 0;           ///< source nodes (columns)
  bool withTrig = false;         ///< the cos/sin-weighted integrals were built
  std::vector<int> outer;        ///< column starts, sourceCount + 1
  std::vector<int> inner;        ///< target node of each entry (sorted within a column)
  std::vector<double> value;     ///< integral a_k b_j dx
  std::vector<double> valueCos;  ///< integral a_k b_j cos x dx (withTrig only)
  std::vector<double> valueSin;  ///< integral a_k b_j sin x dx (withTrig only)
  /// Per source node k, columns (1, cos x, sin x) (the last two withTrig only):
  Eigen::MatrixX3d sourceIntegral;   ///< integral of a_k * w over its whole support
  Eigen::MatrixX3d insideIntegral;   ///< ... over the part inside the target range
  Eigen::MatrixX3d outsideIntegral;  ///< ... over the part outside the target range

  /// Views of the matrices as Eigen sparse matrices (valid until the next build).
  Eigen::Map<const Eigen::SparseMatrix<double>> matrix() const { return view(value); }
  /// The cos-weighted matrix (withTrig only).
  Eigen::Map<const Eigen::SparseMatrix<double>> matrixCos() const { return view(valueCos); }
  /// The sin-weighted matrix (withTrig only).
  Eigen::Map<const Eigen::SparseMatrix<double>> matrixSin() const { return view(valueSin); }

  /// Build scratch (one source column's entries before merging).
  struct Entry {
    int row;      ///< target node
    double v[3];  ///< plain, cos- and sin-weighted integral
  };
  std::vector<Entry> columnScratch;  ///< build scratch

 private:
  Eigen::Map<const Eigen::SparseMatrix<double>> view(const std::vector<double>& v) const;
};

/// Builds `out` (reusing its storage).
/// Inputs:
///   sourceNodes, sourceClosed  source node coordinates (strictly increasing) and whether
///                              they close a ring of length `period`
///   targetNodes, targetClosed  the same for the target
///   period                     2*pi for angles [rad], 0 for axial coordinates
///   offset                     a source point x lies at x + offset in the target frame
///   rule                       target basis (hat or half-cell indicator)
///   withTrig                   also compute the cos/sin-weighted integrals (angles only)
/// Throws std::invalid_argument naming the argument: nodes not finite or not strictly
/// increasing, fewer than 2 (3 when closed), spanning a period or more, a closing cell of a
/// closed grid below 1 % of its smallest other cell; non-finite offset or period;
/// period <= 0 with a closed grid.
void calcHatOverlap1D(const Eigen::VectorXd& sourceNodes, bool sourceClosed,
                      const Eigen::VectorXd& targetNodes, bool targetClosed, double period,
                      double offset, LoadRule rule, bool withTrig, HatOverlap1D& out);

}  // namespace pistondyn::mapping
