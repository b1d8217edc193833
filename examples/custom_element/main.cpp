// Example: a user-written force element swapped in for a built-in one.
//
// SpringLinerGuide is a compliant liner: linear springs and dampers on the piston's
// lateral displacement, tilt and transverse displacement (a crude stand-in for a skirt
// with clearance, the way a user might prototype a new force law). It implements
// pistondyn::plugin::ForceElement and replaces the "ideal_liner_guide" of a model built
// from an example deck - nothing else in the model changes.
//
// Run: custom_element_example [DECK.yaml]   (default: the gasoline example engine)

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/LinerElement.h"

namespace {

using namespace pistondyn;

class SpringLinerGuide final : public plugin::LinerElement {
 public:
  struct Parameters {
    double lateralStiffness_Npm = 2e7;  // [N/m]
    double lateralDamping_Nspm = 2e3;   // [N s/m]
    double tiltStiffness_Nmprad = 2e4;  // [N m/rad]
    double tiltDamping_Nmsprad = 2.0;   // [N m s/rad]
    double axialStiffness_Npm = 2e7;    // along the pin axis [N/m]
    double axialDamping_Nspm = 2e3;     // [N s/m]
  };
  explicit SpringLinerGuide(Parameters p) : p_(p) {}

  std::string getName() const override { return "spring_liner_guide"; }
  void addToModel(const plugin::ModelBuildContext& context) override {
    crankTrain_ = &context.crankTrain;
  }
  void calcForces(const SimTK::State& s, plugin::AppliedForces& forces) const override {
    const SimTK::MobilizedBody& piston = crankTrain_->getPiston();
    const SimTK::Vec3 v = piston.getBodyOriginVelocity(s);
    const double fx = -p_.lateralStiffness_Npm * crankTrain_->getLateralDisplacement_m(s) -
                      p_.lateralDamping_Nspm * v[0];
    const double fz = -p_.axialStiffness_Npm * crankTrain_->getTransverseDisplacement_m(s) -
                      p_.axialDamping_Nspm * v[2];
    // Tilt is a rotation about -z; the restoring moment about +z is +k * tilt.
    const double tiltRate = -piston.getBodyAngularVelocity(s)[2];
    const double mz =
        p_.tiltStiffness_Nmprad * crankTrain_->getTilt_rad(s) + p_.tiltDamping_Nmsprad * tiltRate;
    forces.addForceAtStation(s, piston, SimTK::Vec3(0), SimTK::Vec3(fx, 0, fz));
    forces.addTorque(s, piston, SimTK::Vec3(0, 0, mz));
  }
  // The liner role (LinerElement.h): the force the piston puts on the liner.
  double getSideForce_N(const SimTK::State& s) const override {
    const double x = crankTrain_->getLateralDisplacement_m(s);
    const double vx = crankTrain_->getPiston().getBodyOriginVelocity(s)[0];
    return p_.lateralStiffness_Npm * x + p_.lateralDamping_Nspm * vx;
  }
  plugin::ElementOutputs getOutputs() const override {
    return {{"side_force", "N", "lateral force the piston exerts on the springs, + towards thrust",
             [this](const SimTK::State& s) { return getSideForce_N(s); }}};
  }

 private:
  Parameters p_;
  const mbd::CrankTrain* crankTrain_ = nullptr;
};

}  // namespace

int main(int argc, char** argv) {
  const std::string deckPath = argc > 1 ? argv[1]
                                        : std::string(PISTONDYN_SOURCE_DIR) +
                                              "/examples/engines/gasoline_1400_2000rpm/engine.yaml";
  const io::EngineDeck deck = io::loadEngineDeck(deckPath, {});
  plugin::SimulationSettings settings = deck.simulation;
  settings.cycles = 2;  // let the compliant piston settle, compare the last cycle
  settings.outputStep_deg = 1.0;

  auto ideal = io::buildModel(deck);
  const auto reference = plugin::CycleSimulation(*ideal, settings).run();

  auto compliant = io::buildModel(deck);
  compliant->replaceElement("ideal_liner_guide",
                            std::make_unique<SpringLinerGuide>(SpringLinerGuide::Parameters{}));
  plugin::CycleSimulation sim(*compliant, settings);
  const auto swapped = sim.run();

  const auto a = reference.column("side_force_N"), b = swapped.column("side_force_N");
  const auto u = swapped.column("u_lat_um");
  double peak = 0, diff = 0, uMax = 0;
  for (std::size_t i = a.size() / 2; i < a.size(); ++i) {
    peak = std::max(peak, std::abs(a[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
    uMax = std::max(uMax, std::abs(u[i]));
  }
  std::printf("custom element: elements %s + %s\n", compliant->getElementNames()[0].c_str(),
              compliant->getElementNames()[1].c_str());
  std::printf(
      "  last cycle: peak ideal side force %.1f N, max difference %.1f N, "
      "max lateral displacement %.2f um, %ld steps in %.3f s\n",
      peak, diff, uMax, sim.getStats().integratorSteps, sim.getStats().wallTime_s);
  // The springs carry the same load as the ideal guide up to their dynamics.
  return diff < 0.2 * peak ? 0 : 1;
}
