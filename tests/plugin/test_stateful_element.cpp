// Elements with history (ElementState.h): the example element WearingSpringLiner keeps a
// wear depth and an accepted-step counter in auto-update discrete variables and the
// dissipated energy in a continuous state. Checked here: only accepted steps advance the
// history, a State copy rewinds everything, two copies of a State give identical forces,
// and the continuous state integrates the dissipated energy exactly (energy balance).

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "WearingSpringLiner.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/GasForceElement.h"
#include "pistondyn/plugin/PistonAssemblyModel.h"

namespace {

using namespace pistondyn;
using examples::WearingSpringLiner;

mbd::EngineDescription testEngine() {
  mbd::EngineDescription e;
  e.name = "stateful";
  e.geometry.crankRadius_m = 0.04;
  e.geometry.conrodLength_m = 0.14;
  e.geometry.pinOffset_m = 0.0005;
  e.piston = {0.08, 0.03, 0.04, 0.01};
  e.mass.crank = {2, 0, -0.01, 3e-3};
  e.mass.conrod = {0.5, 0, 0.04, 2e-3};
  e.mass.pin = {0.06, 0, 0, 5e-6};
  e.mass.piston = {0.25, 0, 0.005, 2e-4};
  e.drive.speed_radps = 2000 * M_PI / 30;
  return e;
}

mbd::CylinderPressureCurve testPressure() {
  std::vector<double> a, p;
  for (int i = 0; i < 720; ++i) {
    a.push_back(i);
    const double d = std::min(std::abs(i - 10.0), std::abs(i - 730.0));
    p.push_back(1e5 + 40e5 * std::exp(-d * d / 900.0));
  }
  return mbd::CylinderPressureCurve(a, p);
}

// A model with gas and the wearing liner, at rest at the start angle with rates set.
struct Fixture {
  explicit Fixture(const WearingSpringLiner::Parameters& p = {},
                   const mbd::EngineDescription& e = testEngine())
      : model(e) {
    model.addElement(std::make_unique<plugin::GasForceElement>(testPressure(), 1e5));
    model.addElement(std::make_unique<WearingSpringLiner>(p));
    start = model.getDefaultState();
    model.getCrankTrain().setPose(start, 0.0);
    model.getCrankTrain().setRates(start, e.drive.speed_radps);
  }
  const WearingSpringLiner& liner() const {
    return model.getElementAs<WearingSpringLiner>("wearing_spring_liner");
  }
  plugin::PistonAssemblyModel model;
  SimTK::State start;
};

// Integrates with Runge-Kutta-Merson at a tight accuracy and a large first step, so the
// integrator rejects steps; the counter must count the accepted ones only.
TEST(StatefulElement, HistoryAdvancesOnlyOnAcceptedSteps) {
  Fixture f;
  SimTK::RungeKuttaMersonIntegrator integ(f.model.getSystem());
  integ.setAccuracy(1e-8);
  integ.setInitialStepSize(1e-3);  // far too large: the first attempts are rejected
  integ.initialize(f.start);
  const double tEnd = f.start.getTime() + 0.02;  // 240 deg at 2000 rpm
  while (integ.getTime() < tEnd)
    integ.stepTo(tEnd);
  const SimTK::State& s = integ.getState();
  const long accepted = integ.getNumStepsTaken();
  const long attempted = integ.getNumStepsAttempted();
  const long realizations = integ.getNumRealizations();
  const long counter = f.liner().getAcceptedUpdates(s);
  std::printf("  steps taken %ld, attempted %ld, realizations %ld, counter %ld\n", accepted,
              attempted, realizations, counter);
  ASSERT_GT(attempted, accepted) << "the test needs rejected steps to mean anything";
  ASSERT_GT(realizations, 2 * accepted);
  // Simbody swaps the update value in at initialize() and at the start of every step
  // (the value computed at the end of the step before), so after N accepted steps the
  // state holds N + 1. A counter in a mutable member would count the realizations.
  EXPECT_EQ(counter, accepted + 1);
  EXPECT_GT(f.liner().getWearDepth_m(s), 0.0);
}

// Rewinding is copying a State: continuing from a saved copy repeats the run bit for bit,
// history included; and two copies of a State give identical forces.
TEST(StatefulElement, CopiedStateRewindsHistoryAndGivesIdenticalForces) {
  Fixture f;
  const auto& system = f.model.getSystem();
  auto runFrom = [&](const SimTK::State& s0, double duration) {
    SimTK::RungeKuttaMersonIntegrator integ(system);
    integ.setAccuracy(1e-7);
    integ.initialize(s0);
    const double tEnd = s0.getTime() + duration;
    while (integ.getTime() < tEnd)
      integ.stepTo(tEnd);
    return integ.getState();
  };
  const SimTK::State mid = runFrom(f.start, 0.01);  // 120 deg: worn, energy dissipated
  ASSERT_GT(f.liner().getWearDepth_m(mid), 0.0);
  const SimTK::State savedCopy = mid;  // the rewind point
  const SimTK::State endA = runFrom(mid, 0.01);
  const SimTK::State endB = runFrom(savedCopy, 0.01);
  EXPECT_EQ(f.liner().getWearDepth_m(endA), f.liner().getWearDepth_m(endB));
  EXPECT_EQ(f.liner().getDissipatedEnergy_J(endA), f.liner().getDissipatedEnergy_J(endB));
  EXPECT_EQ(f.liner().getAcceptedUpdates(endA), f.liner().getAcceptedUpdates(endB));
  for (int i = 0; i < endA.getNQ(); ++i)
    EXPECT_EQ(endA.getQ()[i], endB.getQ()[i]);
  // The history advanced over the second half.
  EXPECT_GT(f.liner().getWearDepth_m(endA), f.liner().getWearDepth_m(mid));

  // Two copies of one state, realized independently and in either order.
  SimTK::State a = endA, b = endA;
  system.realize(b, SimTK::Stage::Dynamics);
  system.realize(a, SimTK::Stage::Dynamics);
  const auto& fa = system.getRigidBodyForces(a, SimTK::Stage::Dynamics);
  const auto& fb = system.getRigidBodyForces(b, SimTK::Stage::Dynamics);
  ASSERT_EQ(fa.size(), fb.size());
  for (int k = 0; k < fa.size(); ++k) {
    for (int c = 0; c < 2; ++c) {
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(fa[k][c][d], fb[k][c][d]);
    }
  }
}

// The continuous state integrates the damping power with the motion: for a free crank
// without gas, load or wear, kinetic + potential energy + dissipated energy is constant
// (to the integrator's accuracy), while the dissipated energy itself is not small.
TEST(StatefulElement, ContinuousStateClosesTheEnergyBalance) {
  mbd::EngineDescription e = testEngine();
  e.drive.mode = mbd::CrankDrive::Mode::Free;
  e.drive.flywheelInertia_kgm2 = 0.05;
  WearingSpringLiner::Parameters p;
  p.wearCoefficient_m2pN = 0.0;  // the wear changes the spring's rest point: no energy law
  plugin::PistonAssemblyModel m(e);
  m.addElement(std::make_unique<WearingSpringLiner>(p));
  SimTK::State s0 = m.getDefaultState();
  m.getCrankTrain().setPose(s0, 0.0, 40e-6);  // start off-centre: springs and dampers work
  m.getCrankTrain().setRates(s0, e.drive.speed_radps, 0.05);
  const auto& system = m.getSystem();
  const auto& liner = m.getElementAs<WearingSpringLiner>("wearing_spring_liner");
  auto total = [&](const SimTK::State& s) {
    system.realize(s, SimTK::Stage::Dynamics);
    return system.calcKineticEnergy(s) + system.calcPotentialEnergy(s) +
           *liner.getDissipatedEnergy_J(s);
  };
  SimTK::RungeKuttaMersonIntegrator integ(system);
  integ.setAccuracy(1e-10);
  integ.initialize(s0);
  const double e0 = total(integ.getState());
  double worst = 0.0;
  for (int k = 1; k <= 60; ++k) {
    integ.stepTo(s0.getTime() + k * 1e-3);
    worst = std::max(worst, std::abs(total(integ.getState()) - e0));
  }
  const double dissipated = *liner.getDissipatedEnergy_J(integ.getState());
  std::printf("  dissipated %.4e J, energy-balance defect %.3e J of %.3f J\n", dissipated, worst,
              e0);
  ASSERT_GT(dissipated, 1e-4);
  // Tolerance: the integrator's relative accuracy 1e-10 over 60 ms of a system whose
  // energy is e0; 1e-7 of e0 leaves a margin of 1000 and still resolves the dissipated
  // energy to better than 1e-3 of itself.
  EXPECT_LE(worst, 1e-7 * e0);
}

}  // namespace
