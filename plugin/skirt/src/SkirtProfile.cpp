#include "pistondyn/skirt/SkirtProfile.h"

#include "OutputChecks.h"
#include "pistondyn/common/NodalField.h"

namespace pistondyn::skirt {

SkirtProfile::SkirtProfile(const SkirtProfileParameters& parameters, const SkirtSideGrid& grid)
    : axial_(parameters.axial, grid.getSkirtBottomHeight_m(), grid.getSkirtTopHeight_m()),
      ovality_(parameters.ovality, 0.5 * grid.getArcWidth_rad()) {}

void SkirtProfile::calcField(const SkirtSideGrid& grid, Eigen::Ref<Eigen::ArrayXd> gap_m) const {
  detail::requireNodalSize("SkirtProfile::calcField", "gap_m", gap_m.size(), grid.nodeCount());
  const Eigen::VectorXd& phi = grid.getPhiNodes_rad();
  const Eigen::VectorXd& y = grid.getYNodes_m();
  const Eigen::ArrayXd ovality = phi.unaryExpr([this](double p) { return ovality_.calcDrop_m(p); });
  auto rows = common::asGrid(gap_m, grid.nPhi(), grid.nY());
  for (int j = 0; j < grid.nY(); ++j)
    rows.col(j) = ovality + axial_.calcDrop_m(y[j]);
}

}  // namespace pistondyn::skirt
