#include "pistondyn/plugin/PistonPose.h"

#include <Eigen/Dense>

namespace pistondyn::plugin {

PistonPose calcPistonPose(const mbd::CrankTrain& ct, const SimTK::State& s) {
  const SimTK::MobilizedBody& piston = ct.getPiston();
  const SimTK::Vec3 v = piston.getBodyOriginVelocity(s);
  const SimTK::Vec3 w = piston.getBodyAngularVelocity(s);
  PistonPose p;
  p.lateral_m = ct.getLateralDisplacement_m(s);
  p.tilt_rad = ct.getTilt_rad(s);
  p.transverse_m = ct.getTransverseDisplacement_m(s);
  p.lateralRate_mps = v[0];
  p.tiltRate_radps = -w[2];
  p.transverseRate_mps = v[2];
  p.pinHeight_m = ct.getPistonHeight_m(s);
  p.axialVelocity_mps = v[1];
  return p;
}

void applyPoseForces(const mbd::CrankTrain& ct, const SimTK::State& s, const Eigen::Vector3d& Q,
                     double axialForce_N, double momentX_Nm, AppliedForces& forces) {
  const SimTK::MobilizedBody& piston = ct.getPiston();
  forces.addForceAtStation(s, piston, SimTK::Vec3(0), SimTK::Vec3(Q[0], axialForce_N, Q[2]));
  forces.addTorque(s, piston, SimTK::Vec3(momentX_Nm, 0, -Q[1]));
}

void addPoseForceJacobian(const mbd::CrankTrain& ct, const SimTK::State& s,
                          const Eigen::Matrix3d& dQ_dPose, const Eigen::Matrix3d& dQ_dPoseRate,
                          ForceJacobian& jacobian) {
  const SimTK::MobilizedBody& piston = ct.getPiston();
  const auto& matter = piston.getMatterSubsystem();
  SimTK::RowVector_<SimTK::SpatialVec> jf;
  matter.calcFrameJacobian(s, piston.getMobilizedBodyIndex(), SimTK::Vec3(0), jf);
  const int nu = jf.size();
  Eigen::MatrixXd PJ(3, nu);  // d pose / d u
  for (int j = 0; j < nu; ++j) {
    PJ(0, j) = jf[j][1][0];
    PJ(1, j) = -jf[j][0][2];
    PJ(2, j) = jf[j][1][2];
  }
  const Eigen::MatrixXd dq = PJ.transpose() * dQ_dPose * PJ;
  const Eigen::MatrixXd du = PJ.transpose() * dQ_dPoseRate * PJ;
  // Mobilizers with qdot = u: q and u share the index order (LinearlyImplicitStepper.h).
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nu; ++j) {
      jacobian.dfdq(i, j) += dq(i, j);
      jacobian.dfdu(i, j) += du(i, j);
    }
  }
}

}  // namespace pistondyn::plugin
