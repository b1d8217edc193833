#pragma once
/// \file
/// Reading a dense real matrix from a Matrix Market file (NIST Matrix Market exchange format,
/// https://math.nist.gov/MatrixMarket/formats.html), the format Abaqus, Nastran, CalculiX and
/// SciPy export. Supported banner (keywords case-insensitive):
///
///   %%MatrixMarket matrix coordinate|array real|integer|double general|symmetric
///
/// then '%' comment lines (blank lines ignored), the size line ("M N NNZ" for coordinate,
/// "M N" for array) and the entries: coordinate "i j value" (1-based; symmetric: lower
/// triangle i >= j only, the upper one is filled by symmetry; entries not given are 0, an entry
/// given twice is an error); array: values column by column (symmetric: the lower triangle
/// column by column, M == N). Every value must be a finite number.
///
/// Pattern, complex, hermitian and skew-symmetric matrices are rejected. Errors throw
/// DeckError "<file>:<line>: <what is wrong and what is expected>".

#include <string>

#include <Eigen/Core>

namespace pistondyn::io {

/// Reads the whole matrix into a dense Eigen matrix (as the file states it; no checks beyond
/// the format: the caller checks symmetry, definiteness). A size line beyond 20000 rows or
/// columns is refused before anything is allocated. expectedSize >= 0: the matrix must be
/// expectedSize x expectedSize, checked on the size line before the matrix is allocated (a
/// header that claims 20000 x 20000 costs nothing); the DeckError says
/// "<file>: R x C matrix, expected n x n<sizeReason>".
Eigen::MatrixXd readMatrixMarketDense(const std::string& filePath, Eigen::Index expectedSize = -1,
                                      const std::string& sizeReason = "");

}  // namespace pistondyn::io
