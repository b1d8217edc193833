// The force-element layer: registry rules, and that a user-written element plugged in
// through the public interface acts on the model exactly as a force should.

#include <gtest/gtest.h>

#include <cmath>

#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/GasForceElement.h"
#include "pistondyn/plugin/IdealLinerGuide.h"
#include "pistondyn/plugin/PistonAssemblyModel.h"

namespace {

using namespace pistondyn;

mbd::EngineDescription testEngine() {
  mbd::EngineDescription e;
  e.name = "test";
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

// A user-written element: a constant lateral push on the piston crown, + towards thrust.
class LateralPush final : public plugin::ForceElement {
 public:
  explicit LateralPush(double force_N) : force_N_(force_N) {}
  std::string getName() const override { return "lateral_push"; }
  void addToModel(const plugin::ModelBuildContext& c) override { ct_ = &c.crankTrain; }
  void calcForces(const SimTK::State& s, plugin::AppliedForces& f) const override {
    f.addForceAtStation(s, ct_->getPiston(), ct_->getCrownCentreInPiston(),
                        SimTK::Vec3(force_N_, 0, 0));
  }
  plugin::ElementOutputs getOutputs() const override {
    return {{"push", "N", "the constant push", [this](const SimTK::State&) { return force_N_; }}};
  }

 private:
  double force_N_;
  const mbd::CrankTrain* ct_ = nullptr;
};

TEST(ElementRegistry, AddReplaceRemoveAndFreeze) {
  plugin::PistonAssemblyModel m(testEngine());
  m.addElement(std::make_unique<plugin::GasForceElement>(testPressure(), 1e5));
  m.addElement(std::make_unique<plugin::IdealLinerGuide>());
  EXPECT_THROW(m.addElement(std::make_unique<plugin::IdealLinerGuide>()), std::invalid_argument);
  EXPECT_THROW(m.replaceElement("nope", std::make_unique<LateralPush>(1.0)), std::invalid_argument);
  m.replaceElement("gas_force", std::make_unique<LateralPush>(1.0));  // keeps the slot
  EXPECT_EQ(m.getElementNames(), (std::vector<std::string>{"lateral_push", "ideal_liner_guide"}));
  m.removeElement("lateral_push");
  EXPECT_FALSE(m.hasElement("lateral_push"));
  EXPECT_THROW(m.getElementAs<plugin::GasForceElement>("ideal_liner_guide"), std::invalid_argument);
  (void)m.getDefaultState();  // builds
  EXPECT_THROW(m.addElement(std::make_unique<LateralPush>(1.0)), std::logic_error);
  EXPECT_THROW(m.removeElement("ideal_liner_guide"), std::logic_error);
}

// A lateral force P on the piston, with the piston held by the ideal guide, changes
// nothing in the rod (its equations do not contain P) and so raises the force the
// piston puts on the liner by exactly P, at every crank angle (free-body balance).
TEST(UserElement, LateralPushAddsExactlyToTheGuideReaction) {
  auto run = [](double push) {
    plugin::PistonAssemblyModel m(testEngine());
    m.addElement(std::make_unique<plugin::GasForceElement>(testPressure(), 1e5));
    m.addElement(std::make_unique<plugin::IdealLinerGuide>());
    m.addElement(std::make_unique<LateralPush>(push));
    plugin::SimulationSettings s;
    s.outputStep_deg = 5.0;
    return plugin::CycleSimulation(m, s).run();
  };
  const auto base = run(0.0), pushed = run(250.0);
  const auto s0 = base.column("side_force_N"), s1 = pushed.column("side_force_N");
  const auto r0 = base.column("conrod_force_N"), r1 = pushed.column("conrod_force_N");
  ASSERT_EQ(s0.size(), s1.size());
  for (std::size_t i = 0; i < s0.size(); ++i) {
    EXPECT_NEAR(s1[i] - s0[i], 250.0, 1e-6);
    EXPECT_NEAR(r1[i], r0[i], 1e-6 * std::max(1.0, std::abs(r0[i])));
  }
  EXPECT_EQ(pushed.column("push_N").front(), 250.0);
}

// The gas element's cached results are per state: two states at different crank
// angles keep their own values (nothing shared between states).
TEST(ElementCache, ResultsArePerState) {
  plugin::PistonAssemblyModel m(testEngine());
  m.addElement(std::make_unique<plugin::GasForceElement>(testPressure(), 1e5));
  m.addElement(std::make_unique<plugin::IdealLinerGuide>());
  SimTK::State a = m.getDefaultState(), b = m.getDefaultState();
  m.getCrankTrain().setPose(a, 10.0 * M_PI / 180.0);
  m.getCrankTrain().setPose(b, 200.0 * M_PI / 180.0);
  m.getSystem().realize(a, SimTK::Stage::Position);
  m.getSystem().realize(b, SimTK::Stage::Position);
  const auto& gas = m.getElementAs<plugin::GasForceElement>("gas_force");
  const double pa = gas.getResults(a).cylinderPressure_Pa;
  const double pb = gas.getResults(b).cylinderPressure_Pa;
  EXPECT_NEAR(pa, testPressure().calcPressure_Pa(10.0), 1e-6);
  EXPECT_NEAR(pb, testPressure().calcPressure_Pa(200.0), 1e-6);
  EXPECT_NEAR(gas.getResults(a).cylinderPressure_Pa, pa, 0.0);
}

// A copy of a realized state, moved to another time and crank angle, must not keep the
// copied cache values (Simbody 3.7 copies cache entries with the state; ElementCache.h).
// The stepper does exactly this: it copies the accepted, realized state and moves the copy.
TEST(ElementCache, CopyOfARealizedStateRecomputesAfterItMoves) {
  plugin::PistonAssemblyModel m(testEngine());
  m.addElement(std::make_unique<plugin::GasForceElement>(testPressure(), 1e5));
  m.addElement(std::make_unique<LateralPush>(0.0));
  const auto& gas = m.getElementAs<plugin::GasForceElement>("gas_force");
  const auto& system = m.getSystem();
  SimTK::State a = m.getDefaultState();
  m.getCrankTrain().setPose(a, 10.0 * M_PI / 180.0);
  system.prescribe(a);
  system.realize(a, SimTK::Stage::Acceleration);
  ASSERT_NEAR(gas.getResults(a).cylinderPressure_Pa, testPressure().calcPressure_Pa(10.0), 1e-6);
  for (double angle : {11.0, 12.0, 200.0}) {
    SimTK::State b = a;  // copy of the realized state
    SimTK::State c = b;  // and a copy of the copy, as the stepper makes them
    m.getCrankTrain().setPose(c, angle * M_PI / 180.0);
    system.prescribe(c);
    system.realize(c, SimTK::Stage::Acceleration);
    EXPECT_NEAR(gas.getResults(c).cylinderPressure_Pa, testPressure().calcPressure_Pa(angle), 1e-6)
        << "stale cache value at " << angle << " deg";
  }
}

// A free crank with a flywheel and no load: with the ideal guide doing no work and
// no load torque, the total mechanical energy changes only by the gas work; check
// energy conservation with the gas force removed (pure flywheel + inertia + gravity).
TEST(FreeCrank, ConservesEnergyWithoutGasOrLoad) {
  mbd::EngineDescription e = testEngine();
  e.drive.mode = mbd::CrankDrive::Mode::Free;
  e.drive.flywheelInertia_kgm2 = 0.05;
  plugin::PistonAssemblyModel m(e);
  m.addElement(std::make_unique<plugin::IdealLinerGuide>());
  std::vector<double> energy;
  plugin::SimulationSettings s;
  s.outputStep_deg = 10.0;
  s.accuracy = 1e-10;
  const auto& system = m.getSystem();
  auto observe = [&](const SimTK::State& st) {
    energy.push_back(system.calcKineticEnergy(st) + system.calcPotentialEnergy(st));
  };
  const auto table = plugin::CycleSimulation(m, s).run({}, observe);
  const auto speed = table.column("crank_speed_rpm");
  double worst = 0;
  for (double E : energy)
    worst = std::max(worst, std::abs(E - energy.front()));
  std::printf("  energy drift %.3e J of %.3f J; speed %.2f..%.2f rpm\n", worst, energy.front(),
              *std::min_element(speed.begin(), speed.end()),
              *std::max_element(speed.begin(), speed.end()));
  EXPECT_LE(worst, 1e-7 * energy.front());
  // The speed does fluctuate (the reciprocating inertia), so the crank really is free.
  EXPECT_GT(
      *std::max_element(speed.begin(), speed.end()) - *std::min_element(speed.begin(), speed.end()),
      0.1);
}

}  // namespace
