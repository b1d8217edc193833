#pragma once
/// \file
/// Force mapping by analytical integration (thesis eq. 10, docs/DESIGN.md §4): a pressure (or
/// any force per area) known at the nodes of a source grid, read as its bilinear
/// interpolant p_h, becomes nodal forces on a target grid,
///
///   F_J = integral p_h(phi, y) * N_J(phi, y) dA,   dA = R_source dphi dy,
///
/// with N_J the target's bilinear shape function (LoadRule::Consistent) or the indicator
/// of its half-cells (LoadRule::HalfCell). The integral is exact (see HatOverlap1D.h).
/// Both grids are tensor grids on the same cylinder axis, so the map factorises:
///
///   F = R_source * kron(A_y, A_phi) * p,   i.e.   F_mat = R * A_phi * P_mat * A_y^T
///
/// (P_mat, F_mat the nPhi x nY node matrices). ForceMap assembles the sparse matrix once
/// for a fixed pair of grids and offset; TensorForceMap keeps the factors so that a new
/// axial offset (the piston moving in the liner) rebuilds only the 1-D axial factor.
///
/// Static equivalence, Consistent rule (tests/mapping/test_force_map.cpp and
/// test_force_map_cylinder.cpp; details in mapping/README.md):
/// - developed surface (s = R phi, y), any traction component mapped by the same matrix:
///   total force and the first moments int s p_h dA, int y p_h dA are exact over the
///   overlapped region, hence all three forces and all three moments of a traction
///   vector (normal, circumferential, axial components). HalfCell conserves the total
///   force only.
/// - curved cylinder, TensorForceMap::applyTraction (exact n(phi), t(phi) in the
///   integrand): the total 3-D force is exact; the moments about the x and z axes
///   through any point on the cylinder axis are exact for the normal and
///   circumferential components; the axial component's x/z moments and the moment
///   about the cylinder axis are not exact (errors bounded in mapping/README.md).
///
/// REQUIREMENT for force elements (plugin/): the tilt moments of the friction (axial
/// traction) and the moment about the cylinder axis are NOT preserved by the mapping on
/// the curved cylinder (on a 36-node liner the friction tilt moment is off by up to
/// R h^2/8 of the friction force magnitude, h = 10 deg). A force element must therefore
/// take the piston's resultant force and moments from the contact (film) grid directly,
/// integrating the traction there (e.g. with the film solver's exact load and moment
/// weights); use these maps only to load the liner and the structural (compliance) grids,
/// never to compute the forces and moments applied to the piston body.
///
/// Partial overlap: source cells (parts of cells) outside the target grid cannot be
/// mapped; their force is reported in LoadBalance::unmapped_N, never dropped silently.
///
/// Thread safety: ForceMap and TensorForceMap are immutable after construction and can be
/// shared between threads; TensorForceMap's per-step state and scratch live in the
/// caller's TensorForceMap::Workspace (one per thread).

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "pistondyn/mapping/CylinderGrid.h"
#include "pistondyn/mapping/HatOverlap1D.h"

namespace pistondyn::mapping {

/// Force bookkeeping of one scalar mapping.
struct LoadBalance {
  double sourceTotal_N = 0.0;  ///< integral of p_h over the whole source grid [N]
  double unmapped_N = 0.0;     ///< part of it on source regions outside the target grid [N]
  /// The mapped target forces sum to sourceTotal_N - unmapped_N (exactly, up to rounding).
  double mapped_N() const { return sourceTotal_N - unmapped_N; }
};

/// Force bookkeeping of a 3-D traction mapping, components in the target frame [N].
struct CartesianLoadBalance {
  Eigen::Vector3d sourceTotal_N = Eigen::Vector3d::Zero();  ///< integral of f over the source [N]
  Eigen::Vector3d unmapped_N = Eigen::Vector3d::Zero();     ///< part outside the target grid [N]
};

class TensorForceMap;

/// Force mapping between a fixed pair of grids by analytical integration (this file's
/// documentation): the assembled sparse map from source nodal pressures to target nodal
/// forces, built once and applied many times.
class ForceMap {
 public:
  /// Inputs:
  ///   source         grid of the nodal pressures (e.g. the fine contact grid)
  ///   target         grid receiving nodal forces (structural or liner grid)
  ///   sourceInTarget a source node (phi, y) lies at (phi + phi_rad, y + y_m) of the target
  ///   rule           Consistent (default) or HalfCell
  /// Throws std::invalid_argument for non-finite offsets.
  ForceMap(const CylinderGrid& source, const CylinderGrid& target, GridOffset sourceInTarget,
           LoadRule rule = LoadRule::Consistent);

  /// targetForce_N = matrix() * sourcePressure_Pa (nodal forces [N] from nodal pressures
  /// [Pa]); entries are areas [m^2]. Row = target node, column = source node.
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& matrix() const { return matrix_; }
  /// Per source node: integral of its shape function over the whole source grid [m^2]
  /// (= source.nodeArea_m2()), and over the part outside the target grid [m^2]. The
  /// unmapped nodal loads are unmappedArea_m2().cwiseProduct(p).
  const Eigen::VectorXd& sourceArea_m2() const { return sourceArea_m2_; }
  const Eigen::VectorXd& unmappedArea_m2() const { return unmappedArea_m2_; }  ///< see above

  /// Maps nodal pressures [Pa] (source.nodeCount()) to nodal forces [N]
  /// (target.nodeCount(), overwritten). Throws std::invalid_argument on wrong sizes or
  /// non-finite pressures. No allocation.
  [[nodiscard]] LoadBalance apply(const Eigen::Ref<const Eigen::VectorXd>& sourcePressure_Pa,
                                  Eigen::Ref<Eigen::VectorXd> targetForce_N) const;

 private:
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix_;
  Eigen::VectorXd sourceArea_m2_, unmappedArea_m2_;
};

/// Force mapping onto a grid the source moves along axially (the skirt onto the liner): the
/// map R A_phi P A_y^T kept as its two 1-D factors, only the axial one rebuilt per offset.
class TensorForceMap {
 public:
  /// Target rows (axial node indices j of the target) that the source overlaps at the
  /// current axial offset: j in [first, first + count). count = 0 when nothing overlaps.
  struct RowWindow {
    int first = 0;                             ///< first target row
    int count = 0;                             ///< number of target rows
    int end() const { return first + count; }  ///< one past the last target row
  };

  /// Per-caller state: the axial factor for the current axial offset, and scratch.
  /// A workspace belongs to the map whose setAxialOffset() filled it, or to any map with
  /// the same source and target axial nodes and load rule (they build the same A_y: e.g.
  /// the thrust- and anti-thrust-side maps of one skirt onto one liner may share it).
  /// Using it with any other map throws std::invalid_argument naming `ws` (checked by a
  /// fingerprint of those inputs, so a workspace of another map with the same sizes is not
  /// used silently).
  struct Workspace {
    HatOverlap1D axial;          ///< A_y for the offset set last
    double yOffset_m = 0.0;      ///< that offset
    bool ready = false;          ///< setAxialOffset() was called
    std::uint64_t axialKey = 0;  ///< fingerprint of the axial inputs A_y was built from
    RowWindow rows;              ///< target rows A_y reaches at that offset
    /// R A_phi P products on the reached target phi nodes (row-major: rows are written):
    /// plain, cos- and sin-weighted.
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> q0;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> q1;  ///< see q0
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> q2;  ///< see q0
    Eigen::RowVectorXd columnSums;  ///< column sums of one product, for the load balance
  };

  /// Builds the circumferential factors (plain, and cos/sin-weighted for applyTraction);
  /// a source node (phi, y) lies at phi + phiOffset_rad of the target frame.
  TensorForceMap(const CylinderGrid& source, const CylinderGrid& target, double phiOffset_rad,
                 LoadRule rule = LoadRule::Consistent);

  /// New axial offset (source node y lies at y + yOffset_m of the target): rebuilds the
  /// 1-D axial factor only, O(source nY + target nodes it touches), and sets ws.rows, the
  /// target rows it reaches; no allocation once the workspace has seen a similar overlap.
  void setAxialOffset(double yOffset_m, Workspace& ws) const;

  /// Same result as ForceMap(source, target, {phiOffset, ws.yOffset_m}, rule).apply(...),
  /// computed as R * A_phi * P * A_y^T. Throws std::invalid_argument on wrong sizes,
  /// non-finite pressures or a workspace without setAxialOffset().
  [[nodiscard]] LoadBalance apply(Workspace& ws,
                                  const Eigen::Ref<const Eigen::VectorXd>& sourcePressure_Pa,
                                  Eigen::Ref<Eigen::VectorXd> targetForce_N) const;

  /// 3-D nodal forces on the curved cylinder. The source carries a force per area [Pa]
  ///   f = normal * n(phi) + circumferential * t(phi) + axial * e_y,
  ///   n = (cos phi, 0, sin phi) (outward), t = (-sin phi, 0, cos phi), e_y = (0, 1, 0),
  /// in the target frame (x = thrust side at phi = 0, y = cylinder axis, z = pin axis at
  /// phi = pi/2). Target nodal forces F_J = integral f N_J dA with n, t exact in the
  /// integrand. E.g. film pressure p pushing the liner outwards: normal = +p on the liner.
  [[nodiscard]] CartesianLoadBalance applyTraction(
      Workspace& ws, const Eigen::Ref<const Eigen::VectorXd>& normal_Pa,
      const Eigen::Ref<const Eigen::VectorXd>& circumferential_Pa,
      const Eigen::Ref<const Eigen::VectorXd>& axial_Pa, Eigen::Ref<Eigen::VectorXd> forceX_N,
      Eigen::Ref<Eigen::VectorXd> forceY_N, Eigen::Ref<Eigen::VectorXd> forceZ_N) const;

  /// Windowed paths: their cost scales with the source (contact) grid, not the target.
  /// They ADD the mapped forces into full-size target vectors and touch only the target
  /// rows ws.rows (all target phi nodes of those rows); every other entry is left as it
  /// was. The full paths above write (zero) every target entry, which for the 36 x 400
  /// liner is most of their cost. Typical use per step, with one or several source grids
  /// (e.g. thrust and anti-thrust skirt sides) adding into one liner load vector:
  ///   zero the rows the previous step wrote (its ws.rows), setAxialOffset(), then
  ///   accumulate*(); ws.rows says which rows now hold loads.
  /// Results equal the full paths (same operations on the window; tested to 1e-13 of the
  /// largest nodal force). Same checks and throws as apply()/applyTraction().
  [[nodiscard]] LoadBalance accumulate(Workspace& ws,
                                       const Eigen::Ref<const Eigen::VectorXd>& sourcePressure_Pa,
                                       Eigen::Ref<Eigen::VectorXd> targetForce_N) const;
  /// The windowed form of applyTraction() (see accumulate()).
  [[nodiscard]] CartesianLoadBalance accumulateTraction(
      Workspace& ws, const Eigen::Ref<const Eigen::VectorXd>& normal_Pa,
      const Eigen::Ref<const Eigen::VectorXd>& circumferential_Pa,
      const Eigen::Ref<const Eigen::VectorXd>& axial_Pa, Eigen::Ref<Eigen::VectorXd> forceX_N,
      Eigen::Ref<Eigen::VectorXd> forceY_N, Eigen::Ref<Eigen::VectorXd> forceZ_N) const;

  const CylinderGrid& source() const { return source_; }   ///< the source grid
  const CylinderGrid& target() const { return target_; }   ///< the target grid
  double phiOffset_rad() const { return phiOffset_rad_; }  ///< source phi in the target [rad]
  LoadRule rule() const { return rule_; }                  ///< the load rule
  /// The circumferential factor A_phi (target nPhi x source nPhi, [rad]).
  const HatOverlap1D& circumferentialFactor() const { return phi_; }

  /// Run of consecutive reached target phi nodes: target nodes [target, target + length)
  /// are rows [compact, compact + length) of the compact products (implementation detail).
  struct PhiRun {
    int target;   ///< first target phi node of the run
    int compact;  ///< its row in the compact products
    int length;   ///< nodes in the run
  };

 private:
  friend class ForceMap;
  void checkWorkspace(const char* fn, const Workspace& ws) const;
  LoadBalance mapScalar(const char* fn, Workspace& ws,
                        const Eigen::Ref<const Eigen::VectorXd>& sourcePressure_Pa,
                        Eigen::Ref<Eigen::VectorXd> targetForce_N, bool overwrite) const;
  CartesianLoadBalance mapTraction(const char* fn, Workspace& ws,
                                   const Eigen::Ref<const Eigen::VectorXd>& normal_Pa,
                                   const Eigen::Ref<const Eigen::VectorXd>& circumferential_Pa,
                                   const Eigen::Ref<const Eigen::VectorXd>& axial_Pa,
                                   Eigen::Ref<Eigen::VectorXd> forceX_N,
                                   Eigen::Ref<Eigen::VectorXd> forceY_N,
                                   Eigen::Ref<Eigen::VectorXd> forceZ_N, bool overwrite) const;

  CylinderGrid source_, target_;
  double phiOffset_rad_;
  LoadRule rule_;
  HatOverlap1D phi_;  ///< with cos/sin weights
  /// The target phi nodes A_phi reaches (increasing) and R * A_phi on those rows, dense and
  /// row-major (nWin x source nPhi): plain, cos- and sin-weighted; per row the band of
  /// source nodes [begin, begin + length) holding its non-zeros.
  struct PhiBand {
    int begin, length;
  };
  using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  std::vector<int> phiRows_;
  std::vector<PhiBand> phiBands_;
  RowMajorMatrix phiPlain_, phiCos_, phiSin_;
  std::vector<PhiRun> phiRuns_;  ///< phiRows_ as runs of consecutive target phi nodes
  bool phiHasOutside_ = false;   ///< part of the source lies outside a sector target in phi
  std::uint64_t axialKey_ = 0;   ///< fingerprint of source y, target y, rule (see Workspace)
};

}  // namespace pistondyn::mapping
