#include "pistondyn/skirt/RigidGap.h"

#include <cmath>
#include <string>

#include "Checks.h"
#include "OutputChecks.h"

namespace pistondyn::skirt {

void calcRigidGap(const SkirtSideGrid& grid, double coldRadialClearance_m, const PistonPose& pose,
                  const PistonPoseRate& rate, Eigen::Ref<Eigen::ArrayXd> gap_m,
                  Eigen::Ref<Eigen::ArrayXd> gapRate_mps, Eigen::Ref<Eigen::MatrixXd> dGap_dPose,
                  Eigen::Ref<Eigen::MatrixXd> squeezeBasis) {
  const char* fn = "calcRigidGap";
  detail::requireFinite(fn, "coldRadialClearance_m", coldRadialClearance_m, "m");
  detail::requirePose(fn, pose, rate);
  const Eigen::Index n = grid.nodeCount();
  detail::requireNodalSize(fn, "gap_m", gap_m.size(), n);
  detail::requireNodalSize(fn, "gapRate_mps", gapRate_mps.size(), n);
  detail::requireNodalMatrix(fn, "dGap_dPose", dGap_dPose.rows(), dGap_dPose.cols(), n);
  detail::requireNodalMatrix(fn, "squeezeBasis", squeezeBasis.rows(), squeezeBasis.cols(), n);

  const Eigen::ArrayXd& c = grid.getNodeCosPhi();
  const Eigen::ArrayXd& s = grid.getNodeSinPhi();
  const Eigen::ArrayXd& y = grid.getNodeY_m();
  const double sinA = std::sin(pose.tilt_rad), cosA = std::cos(pose.tilt_rad);
  gap_m = coldRadialClearance_m - (pose.lateral_m + y * sinA) * c - pose.tertiary_m * s;
  dGap_dPose.col(kLateral).array() = -c;
  dGap_dPose.col(kTilt).array() = -cosA * y * c;
  dGap_dPose.col(kTertiary).array() = -s;
  squeezeBasis = dGap_dPose;  // the rigid gap rate is linear in the pose rates
  gapRate_mps = rate.lateral_mps * dGap_dPose.col(kLateral).array() +
                rate.tilt_radps * dGap_dPose.col(kTilt).array() +
                rate.tertiary_mps * dGap_dPose.col(kTertiary).array();
}

}  // namespace pistondyn::skirt
