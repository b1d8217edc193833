#pragma once
// A flat nodal field (k = i + nPhi j, SkirtSideGrid.h) viewed as an nPhi x nY column-major array
// without copying: column j is grid row j. Local helper until the common
// pistondyn/common/NodalField.h (another branch) lands; then use that one.

#include <Eigen/Core>

namespace pistondyn::skirt::detail {

inline Eigen::Map<Eigen::ArrayXXd> asNodeMatrix(Eigen::Ref<Eigen::ArrayXd> field, Eigen::Index nPhi,
                                                Eigen::Index nY) {
  return Eigen::Map<Eigen::ArrayXXd>(field.data(), nPhi, nY);
}

}  // namespace pistondyn::skirt::detail
