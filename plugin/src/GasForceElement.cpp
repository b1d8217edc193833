#include "pistondyn/plugin/GasForceElement.h"

#include <cmath>
#include <stdexcept>

namespace pistondyn::plugin {

GasForceElement::GasForceElement(mbd::CylinderPressureCurve cylinderPressure,
                                 double crankcasePressure_Pa)
    : pressure_(std::move(cylinderPressure)), crankcase_Pa_(crankcasePressure_Pa) {
  if (!std::isfinite(crankcasePressure_Pa) || crankcasePressure_Pa < 0.0) {
    throw std::invalid_argument(
        "GasForceElement: crankcasePressure_Pa must be a non-negative absolute pressure");
  }
}

void GasForceElement::addToModel(const ModelBuildContext& context) {
  crankTrain_ = &context.crankTrain;
  const double bore = crankTrain_->getEngine().piston.bore_m;
  area_m2_ = 0.25 * M_PI * bore * bore;
}

void GasForceElement::realizeTopology(SimTK::State&, ElementStateAllocator& alloc) const {
  cache_.allocate(alloc, SimTK::Stage::Position);
}

const GasForceElement::Results& GasForceElement::getResults(const SimTK::State& s) const {
  return cache_.getOrCalc(s, [&](Results& r) {
    const double theta_deg = crankTrain_->getCrankAngle_rad(s) * 180.0 / M_PI;
    r.cylinderPressure_Pa = pressure_.calcPressure_Pa(theta_deg);
    r.gasForce_N = (r.cylinderPressure_Pa - crankcase_Pa_) * area_m2_;
  });
}

void GasForceElement::calcForces(const SimTK::State& s, AppliedForces& forces) const {
  const Results& r = getResults(s);
  const SimTK::MobilizedBody& piston = crankTrain_->getPiston();
  const SimTK::Vec3 forceInGround = piston.getBodyRotation(s) * SimTK::Vec3(0, -r.gasForce_N, 0);
  forces.addForceAtStation(s, piston, crankTrain_->getCrownCentreInPiston(), forceInGround);
}

ElementOutputs GasForceElement::getOutputs() const {
  return {{"cylinder_pressure", "Pa", "absolute cylinder pressure from the pressure table",
           [this](const SimTK::State& s) { return getResults(s).cylinderPressure_Pa; }},
          {"gas_force", "N",
           "(cylinder - crankcase pressure) x bore area, + pushing the piston towards the crank",
           [this](const SimTK::State& s) { return getResults(s).gasForce_N; }}};
}

}  // namespace pistondyn::plugin
