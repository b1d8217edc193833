#pragma once
/// \file
/// The "ideal liner": holds the piston exactly on the cylinder axis, upright, and at
/// zero tertiary displacement, by Simbody constraints (lateral position, tilt, and - when the
/// crank train has the tertiary mobility - the position along the pin axis). It applies no force of
/// its own; its reaction is the side force a rigid, frictionless, zero-clearance liner would carry.
/// Used to verify the crank train against closed forms and as the simplest liner for quick studies;
/// the lubricated skirt element replaces it.
///
/// Outputs (state realized through Stage::Acceleration):
///   side_force_N      lateral force the piston exerts on the liner, + towards thrust
///   guide_moment_Nm   moment the piston exerts on the liner about +z
///   guide_axial_N     force the piston exerts along the pin axis (tertiary), + along +z

#include "pistondyn/plugin/LinerElement.h"

namespace pistondyn::plugin {

/// The ideal liner guide: the piston held on the axis by constraints (this file's
/// documentation).
class IdealLinerGuide final : public LinerElement {
 public:
  std::string getName() const override { return "ideal_liner_guide"; }
  void addToModel(const ModelBuildContext& context) override;
  void calcForces(const SimTK::State&, AppliedForces&) const override {}
  ElementOutputs getOutputs() const override;
  /// Lateral force the piston exerts on the liner, + towards thrust [N] (Stage::Acceleration).
  double getSideForce_N(const SimTK::State& s) const override { return calcForceOnLiner(s)[1][0]; }

  /// Force [N] and moment about the piston-frame origin [N m], in ground, that the
  /// piston exerts on the liner through the three constraints (Stage::Acceleration).
  SimTK::SpatialVec calcForceOnLiner(const SimTK::State& s) const;

 private:
  const mbd::CrankTrain* crankTrain_ = nullptr;  ///< non-owning
  SimTK::Constraint lateral_, tilt_, transverse_;
};

}  // namespace pistondyn::plugin
