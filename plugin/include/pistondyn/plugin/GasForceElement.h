#pragma once
/// \file
/// Gas force on the piston crown: (p_cylinder(theta) - p_crankcase) * A_bore, acting at
/// the crown centre along the piston axis (a body-fixed direction, so it follows the
/// tilt: pressure acts normal to the crown). Periodic cylinder-pressure curve over 720
/// deg; crank angle from the crank train's state.
///
/// Outputs: cylinder_pressure [Pa], gas_force [N] (positive = pushing the piston down,
/// towards the crank).

#include "pistondyn/mbd_models/CylinderPressureCurve.h"
#include "pistondyn/plugin/ElementCache.h"
#include "pistondyn/plugin/ForceElement.h"

namespace pistondyn::plugin {

/// The gas force on the crown (the documentation of GasForceElement.h).
class GasForceElement final : public ForceElement {
 public:
  /// crankcasePressure_Pa: absolute pressure under the piston [Pa], >= 0.
  GasForceElement(mbd::CylinderPressureCurve cylinderPressure, double crankcasePressure_Pa);

  std::string getName() const override { return "gas_force"; }
  void addToModel(const ModelBuildContext& context) override;
  void realizeTopology(SimTK::State& s, ElementStateAllocator& alloc) const override;
  void calcForces(const SimTK::State& s, AppliedForces& forces) const override;
  bool dependsOnlyOnPositions() const override { return true; }
  ElementOutputs getOutputs() const override;

  const mbd::CylinderPressureCurve& getCylinderPressure() const { return pressure_; }  ///< p(theta)
  double getCrankcasePressure_Pa() const { return crankcase_Pa_; }  ///< absolute [Pa]

  /// The element's results at one state.
  struct Results {
    double cylinderPressure_Pa = 0.0;  ///< absolute, from the table [Pa]
    double gasForce_N = 0.0;           ///< along -y of the piston frame
  };
  /// Requires Stage::Position.
  const Results& getResults(const SimTK::State& s) const;

 private:
  mbd::CylinderPressureCurve pressure_;
  double crankcase_Pa_;
  const mbd::CrankTrain* crankTrain_ = nullptr;  ///< non-owning; the model owns both
  double area_m2_ = 0.0;
  ElementCache<Results> cache_;
};

}  // namespace pistondyn::plugin
