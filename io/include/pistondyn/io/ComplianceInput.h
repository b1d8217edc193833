#pragma once
/// \file
/// Reading a structural compliance (skirt or liner) exported by a finite-element program: a
/// Matrix Market matrix (MatrixMarket.h) and its node table (CSV), checked and converted to SI
/// in a mapping::StructuralCompliance. The files examples/fe/make_compliance.py writes are
/// of this form (examples/fe/README.md).
///
/// Node table (CsvTable.h rules: '#' comments, a header line of names with units):
///
///   node,phi_deg,y_mm[,gas_u_r_um_per_MPa]
///   1,0.0,-18
///   2,11.25,-18
///   ...
///
///   node      1, 2, ..., n in this order: row/column k of the matrix is node k
///   phi_*     node angle (any angle unit: phi_deg, phi_rad), from +x (thrust) towards +z (pin
///             axis), in [0, 360 deg)
///   y_*       node height (any length unit: y_mm, y_m) in the structure's frame
///   gas_u_r_um_per_MPa or gas_u_r_m_per_Pa (optional): radial displacement (+ outward) per
///             unit cylinder pressure
/// The nodes must form a tensor grid, phi fastest: nPhi angles, strictly increasing, repeated in
/// every row; nY heights, strictly increasing, constant within a row (to 1e-9 of the range).
/// The grid is a full circle when the angles are equally spaced over 360 deg (to 1e-9 rad),
/// else a sector.
///
/// Checks (each failure throws DeckError naming the file, and the line or entry):
///   matrix n x n with n = number of nodes; every entry finite (MatrixMarket.h);
///   symmetric: max |C_ij - C_ji| <= symmetryTolerance * max_k C_kk (Maxwell-Betti);
///   diagonal > 0; positive definite (Cholesky of the symmetrised matrix succeeds).
/// The result holds the symmetrised matrix (C + C^T) / 2 [m/N].

#include <string>

#include "pistondyn/mapping/StructuralCompliance.h"

namespace pistondyn::io {

/// How the compliance files are read.
struct ComplianceReadOptions {
  /// The compliance file's unit: entries times this factor give m/N (default: the file is in
  /// m/N, as make_compliance.py writes; 1e-3 for a file in mm/N).
  double matrixToSI = 1.0;
  /// Allowed asymmetry, relative to the largest diagonal entry. The default 1e-5 is far above
  /// the rounding of an 8-digit export and of a direct FE solve, and far below any modelling
  /// error (a wrong node order or a transposed block shows at the 1e-2 level).
  double symmetryTolerance = 1.0e-5;
};

/// Reads and checks a compliance (Matrix Market) and its node table (this file's
/// documentation); throws DeckError naming the file and the line or entry.
mapping::StructuralCompliance readStructuralCompliance(const std::string& matrixPath,
                                                       const std::string& nodeTablePath,
                                                       const ComplianceReadOptions& options = {});

}  // namespace pistondyn::io
