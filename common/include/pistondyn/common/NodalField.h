#pragma once
/// \file
/// The one storage convention for nodal fields, shared by every pistondyn module, and zero-copy
/// views between its forms (docs/CONVENTIONS.md, "Nodal fields").
///
/// A nodal field on a structured grid of nA x nB nodes is a flat Eigen::ArrayXd of size nA*nB
/// with node (i, j), i in [0, nA), j in [0, nB), at k = i + nA*j: the first grid index runs
/// fastest. That is exactly the storage of a column-major nA x nB Eigen::ArrayXXd, so the flat
/// field, the 2-D array and a column vector share one block of memory and convert without a
/// copy. In pistondyn:
///   lubrication::FilmGrid     nA = nx (x, circumferential), nB = ny (y, axial), k = i + nx*j
///   mapping::CylinderGrid     nA = nPhi, nB = nY, k = i + nPhi*j
///   skirt::SkirtSideGrid      nA = nPhi, nB = nY, k = i + nPhi*j
///   contact_forces            Eigen::ArrayXXd fields, rows i and columns j of the same grid
///
/// Header-only (target pistondyn::common). The views do not own memory: they stay valid as long
/// as the field they view is neither resized nor destroyed (views of temporaries do not compile).

#include <stdexcept>

#include <Eigen/Core>

#include "pistondyn/common/Validation.h"

namespace pistondyn::common {

/// Flat index of node (i, j) on a grid with nA nodes along its first direction.
inline Eigen::Index nodeIndex(Eigen::Index i, Eigen::Index j, Eigen::Index nA) {
  return i + nA * j;
}

namespace detail {

/// Throws std::invalid_argument unless nA, nB >= 0 and size == nA * nB.
inline void requireGridShape(const char* function, Eigen::Index size, int nA, int nB) {
  if (nA < 0 || nB < 0) {
    throwInvalidArgument(function, message("grid shape nA x nB = ", nA, " x ", nB,
                                           " must have non-negative node counts"));
  }
  const Eigen::Index expected = static_cast<Eigen::Index>(nA) * static_cast<Eigen::Index>(nB);
  if (size != expected) {
    throwInvalidArgument(
        function, message("field has ", size, " entries, expected nA * nB = ", nA, " * ", nB, " = ",
                          expected, " (node (i, j) at k = i + nA*j)"));
  }
}

}  // namespace detail

/// The flat field as an nA x nB array: entry (i, j) is field[i + nA*j]. No copy.
/// Inputs:  field  nodal field of size nA*nB;  nA, nB  node counts along the grid's first and
///          second direction, >= 0
/// Outputs: a view of field's memory
/// Throws std::invalid_argument for negative counts or field.size() != nA*nB.
inline Eigen::Map<const Eigen::ArrayXXd> asGrid(const Eigen::ArrayXd& field, int nA, int nB) {
  detail::requireGridShape("pistondyn::common::asGrid", field.size(), nA, nB);
  return Eigen::Map<const Eigen::ArrayXXd>(field.data(), nA, nB);
}

/// Writable form of asGrid: writing entry (i, j) writes field[i + nA*j].
inline Eigen::Map<Eigen::ArrayXXd> asGrid(Eigen::ArrayXd& field, int nA, int nB) {
  detail::requireGridShape("pistondyn::common::asGrid", field.size(), nA, nB);
  return Eigen::Map<Eigen::ArrayXXd>(field.data(), nA, nB);
}

/// The same for a field passed on as an Eigen::Ref (contiguous, as every Ref<ArrayXd> is), e.g.
/// an output argument Eigen::Ref<Eigen::ArrayXd> gap_m: a view of the memory the Ref refers to.
inline Eigen::Map<const Eigen::ArrayXXd> asGrid(const Eigen::Ref<const Eigen::ArrayXd>& field,
                                                int nA, int nB) {
  detail::requireGridShape("pistondyn::common::asGrid", field.size(), nA, nB);
  return Eigen::Map<const Eigen::ArrayXXd>(field.data(), nA, nB);
}

/// Writable form of the Eigen::Ref view.
inline Eigen::Map<Eigen::ArrayXXd> asGrid(Eigen::Ref<Eigen::ArrayXd> field, int nA, int nB) {
  detail::requireGridShape("pistondyn::common::asGrid", field.size(), nA, nB);
  return Eigen::Map<Eigen::ArrayXXd>(field.data(), nA, nB);
}

/// The flat field as a column vector (linear algebra on nodal values, e.g. a sparse map
/// applied to a pressure field). No copy, no size condition.
inline Eigen::Map<const Eigen::VectorXd> asColumnVector(const Eigen::ArrayXd& field) {
  return Eigen::Map<const Eigen::VectorXd>(field.data(), field.size());
}

/// Writable form of asColumnVector(const Eigen::ArrayXd&).
inline Eigen::Map<Eigen::VectorXd> asColumnVector(Eigen::ArrayXd& field) {
  return Eigen::Map<Eigen::VectorXd>(field.data(), field.size());
}

/// The same for a field of a grid of nA x nB nodes, with the size checked as in asGrid.
inline Eigen::Map<const Eigen::VectorXd> asColumnVector(const Eigen::ArrayXd& field, int nA,
                                                        int nB) {
  detail::requireGridShape("pistondyn::common::asColumnVector", field.size(), nA, nB);
  return asColumnVector(field);
}

/// Writable form, size checked.
inline Eigen::Map<Eigen::VectorXd> asColumnVector(Eigen::ArrayXd& field, int nA, int nB) {
  detail::requireGridShape("pistondyn::common::asColumnVector", field.size(), nA, nB);
  return asColumnVector(field);
}

/// A column-major nA x nB array (e.g. a contact_forces field) as the flat column vector of the
/// same nodes, k = i + nA*j. No copy.
inline Eigen::Map<const Eigen::VectorXd> asColumnVector(const Eigen::ArrayXXd& grid) {
  return Eigen::Map<const Eigen::VectorXd>(grid.data(), grid.size());
}

/// Writable form of asColumnVector(const Eigen::ArrayXXd&).
inline Eigen::Map<Eigen::VectorXd> asColumnVector(Eigen::ArrayXXd& grid) {
  return Eigen::Map<Eigen::VectorXd>(grid.data(), grid.size());
}

/// A view of a temporary would dangle: not allowed.
Eigen::Map<const Eigen::ArrayXXd> asGrid(Eigen::ArrayXd&& field, int nA, int nB) = delete;
Eigen::Map<const Eigen::VectorXd> asColumnVector(Eigen::ArrayXd&& field) = delete;
Eigen::Map<const Eigen::VectorXd> asColumnVector(Eigen::ArrayXd&& field, int nA, int nB) = delete;
Eigen::Map<const Eigen::VectorXd> asColumnVector(Eigen::ArrayXXd&& grid) = delete;

}  // namespace pistondyn::common
