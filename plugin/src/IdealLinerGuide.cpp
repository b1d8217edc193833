#include "pistondyn/plugin/IdealLinerGuide.h"

namespace pistondyn::plugin {

void IdealLinerGuide::addToModel(const ModelBuildContext& context) {
  crankTrain_ = &context.crankTrain;
  SimTK::MobilizedBody& ground = context.matter.updGround();
  SimTK::MobilizedBody& piston =
      context.matter.updMobilizedBody(crankTrain_->getPiston().getMobilizedBodyIndex());
  const double axisX = crankTrain_->getEngine().geometry.crankOffset_m;
  // Piston-frame origin (on the piston axis) stays on the plane x = cylinder axis.
  lateral_ = SimTK::Constraint::PointInPlane(ground, SimTK::UnitVec3(SimTK::XAxis), axisX, piston,
                                             SimTK::Vec3(0));
  // Piston y axis stays perpendicular to ground x: no tilt.
  tilt_ = SimTK::Constraint::ConstantAngle(ground, SimTK::UnitVec3(SimTK::XAxis), piston,
                                           SimTK::UnitVec3(SimTK::YAxis));
  // Piston-frame origin stays on the plane z = 0: no tertiary motion (a train built without
  // the tertiary mobility needs no constraint for it).
  if (crankTrain_->getEngine().tertiaryMotion) {
    transverse_ = SimTK::Constraint::PointInPlane(ground, SimTK::UnitVec3(SimTK::ZAxis), 0.0,
                                                  piston, SimTK::Vec3(0));
  }
}

SimTK::SpatialVec IdealLinerGuide::calcForceOnLiner(const SimTK::State& s) const {
  const SimTK::MobilizedBody& piston = crankTrain_->getPiston();
  SimTK::SpatialVec total(SimTK::Vec3(0), SimTK::Vec3(0));
  for (const SimTK::Constraint* c : {&lateral_, &tilt_, &transverse_}) {
    if (c->isEmptyHandle())
      continue;
    // Simbody reports constraint forces with the opposite sign of applied forces
    // (they sit on the left-hand side of its equations of motion), so these are
    // already the forces the piston exerts on the constraint, i.e. on the liner.
    const SimTK::Vector_<SimTK::SpatialVec> f = c->getConstrainedBodyForcesAsVector(s);
    for (SimTK::ConstrainedBodyIndex b(0); b < c->getNumConstrainedBodies(); ++b) {
      if (c->getMobilizedBodyFromConstrainedBody(b).getMobilizedBodyIndex() !=
          piston.getMobilizedBodyIndex()) {
        continue;
      }
      // Body forces are given at the body origin, in ground.
      total[0] += f[b][0];
      total[1] += f[b][1];
    }
  }
  return total;
}

ElementOutputs IdealLinerGuide::getOutputs() const {
  return {{"side_force", "N", "lateral force the piston exerts on the liner, + towards thrust",
           [this](const SimTK::State& s) { return getSideForce_N(s); }},
          {"guide_moment", "Nm",
           "moment the piston exerts on the liner about +z, about the piston-frame origin",
           [this](const SimTK::State& s) { return calcForceOnLiner(s)[0][2]; }},
          {"guide_axial", "N", "force the piston exerts on the liner along the pin axis (+z)",
           [this](const SimTK::State& s) { return calcForceOnLiner(s)[1][2]; }}};
}

}  // namespace pistondyn::plugin
