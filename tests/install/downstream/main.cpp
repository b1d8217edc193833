// Builds a crank-train model with the installed headers and libraries, swaps in a
// user-written element, runs one cycle and prints one number.
#include <cmath>
#include <cstdio>
#include <memory>

#include <pistondyn/mbd_models/SimbodyBuildCheck.h>
#include <pistondyn/plugin/CycleSimulation.h>
#include <pistondyn/plugin/GasForceElement.h>
#include <pistondyn/plugin/IdealLinerGuide.h>

int main() {
#ifdef NDEBUG
  std::puts("downstream: NDEBUG is defined in a TU including Simbody");
  return 1;
#endif
  using namespace pistondyn;
  mbd::EngineDescription e;
  e.name = "downstream";
  e.geometry.crankRadius_m = 0.04;
  e.geometry.conrodLength_m = 0.14;
  e.piston = {0.08, 0.03, 0.04, 0.01};
  e.mass.crank = {2, 0, 0, 3e-3};
  e.mass.conrod = {0.5, 0, 0.04, 2e-3};
  e.mass.pin = {0.06, 0, 0, 5e-6};
  e.mass.piston = {0.25, 0, 0.005, 2e-4};
  e.drive.speed_radps = 200.0;
  plugin::PistonAssemblyModel model(e);
  model.addElement(std::make_unique<plugin::GasForceElement>(
      mbd::CylinderPressureCurve({0, 180, 360, 540}, {2e5, 2e5, 2e5, 2e5}), 1e5));
  model.addElement(std::make_unique<plugin::IdealLinerGuide>());
  plugin::SimulationSettings s;
  s.outputStep_deg = 10.0;
  const auto table = plugin::CycleSimulation(model, s).run();
  const double side = table.column("side_force_N")[9];
  std::printf("downstream: side force at 90 deg = %.6f N, library NDEBUG = %d\n", side,
              static_cast<int>(mbd::libraryBuiltWithNDEBUG()));
  return (std::isfinite(side) && !mbd::libraryBuiltWithNDEBUG()) ? 0 : 1;
}
