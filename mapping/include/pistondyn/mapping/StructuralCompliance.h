#pragma once
/// \file
/// The radial compliance of an elastic structure (piston skirt or liner band) on its coarse
/// structural grid, as read from a finite-element export (pistondyn::io::readStructuralCompliance,
/// examples/fe/README.md). Plain data: the reader validates it, the elastohydrodynamic coupling
/// (film pressure -> nodal forces by ForceMap -> displacements -> HermiteSurface -> gap) uses it.
///
/// Grid: a tensor grid phi_rad (nPhi angles) x y_m (nY heights), node (i, j) at
/// k = i + nPhi * j (phi fastest), the order of CylinderGrid and of every nodal field
/// (common/NodalField.h). `fullCircle` says whether the nodes go round the whole circle (then
/// build the grid with CylinderGrid::fullCircle, else CylinderGrid::sector). Angles from +x
/// (thrust) towards +z (pin axis); heights in the structure's own frame (piston frame: above
/// the pin axis; liner: above the crank axis) as the node table states.
///
/// Meaning of the entries (the definition the FE script uses, examples/fe/README.md):
///   u_m = compliance_m_per_N * f_N
/// u_m[k]: radial displacement of structural node k [m] (+ outward), f_N[k]: radial nodal force
/// at node k [N] (+ outward), the nodal force being the consistent load of the bilinear hat of
/// node k (what mapping::ForceMap produces) and the displacement its hat-weighted mean. So a
/// film pressure pushing the skirt inwards gives negative nodal forces on the skirt, positive
/// (outward) ones on the liner.
///
/// gasDisplacement_m_per_Pa: radial displacement of each node per unit cylinder (gauge)
/// pressure [m/Pa], to be scaled by the current pressure; empty when the export has none.

#include <Eigen/Core>

namespace pistondyn::mapping {

/// Radial compliance of a structure on its structural grid (the documentation of
/// StructuralCompliance.h gives the grid, the sign and the meaning of the entries).
struct StructuralCompliance {
  Eigen::VectorXd phi_rad;  ///< nPhi node angles, strictly increasing, in [0, 2 pi)
  Eigen::VectorXd y_m;      ///< nY node heights, strictly increasing [m]
  bool fullCircle = false;  ///< the angles close the ring (equal spacing over 2 pi)
  /// nodes x nodes, symmetric positive definite [m/N] (the reader symmetrises the file's
  /// matrix after checking it is symmetric to its stated tolerance).
  Eigen::MatrixXd compliance_m_per_N;
  Eigen::VectorXd gasDisplacement_m_per_Pa;  ///< nodes entries, or empty

  int nPhi() const { return static_cast<int>(phi_rad.size()); }  ///< node angles
  int nY() const { return static_cast<int>(y_m.size()); }        ///< node heights
  int nodeCount() const { return nPhi() * nY(); }                ///< nPhi * nY
  /// The export has a gas field.
  bool hasGasDisplacement() const { return gasDisplacement_m_per_Pa.size() > 0; }
};

}  // namespace pistondyn::mapping
