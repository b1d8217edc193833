// CONVENTIONS.md: code that runs every force evaluation allocates nothing after setup.
// Reference: the allocation counter of tests/support (interposes malloc, calloc, realloc).
#include <gtest/gtest.h>

#include <cmath>

#include "AllocationCounter.h"
#include "SkirtTestSupport.h"
#include "pistondyn/skirt/GapAssembly.h"
#include "pistondyn/skirt/RigidGap.h"

namespace ps = pistondyn::skirt;

namespace {

// Every term on, with tables on every path (PCHIP and linear, nodal piston temperature).
ps::GapAssemblyParameters everyTerm(const ps::SkirtSideGrid& g) {
  ps::GapAssemblyParameters p;
  p.coldRadialClearance_m = 60e-6;
  p.linerTopHeight_m = 0.25;
  p.travel = {0.12, 0.20};
  p.skirtProfile.axial.height_m = Eigen::VectorXd::LinSpaced(9, -0.03, 0.03);
  p.skirtProfile.axial.radialDrop_m =
      p.skirtProfile.axial.height_m.unaryExpr([](double y) { return 0.04 * y * y; });
  p.skirtProfile.ovality.diametralOvality_m = 40e-6;
  for (int n = 0; n <= ps::kMaxBoreDistortionOrder; ++n) {
    ps::BoreDistortionOrder o;
    o.order = n;
    o.depth_m = Eigen::VectorXd::LinSpaced(7, 0.0, 0.18);
    o.amplitude_m = Eigen::VectorXd::Constant(7, 1e-6 / (1 + n)) + 1e-6 * o.depth_m;
    o.phase_rad = Eigen::VectorXd::Constant(7, 0.1 * n) + 2.0 * o.depth_m;
    p.linerShape.orders.push_back(o);
  }
  p.pistonThermal.expansionCoefficient_perK = 21e-6;
  p.pistonThermal.nodalTemperature_degC = Eigen::ArrayXd::Constant(g.nodeCount(), 50.0);
  p.linerThermal.expansionCoefficient_perK = 11e-6;
  p.linerThermal.depth_m = Eigen::Vector3d(0.0, 0.1, 0.3);
  p.linerThermal.temperature_degC = Eigen::Vector3d(110.0, 90.0, 60.0);
  p.linerThermal.interpolation = ps::Interpolation::Pchip;
  return p;
}

TEST(SkirtAllocation, CounterSeesTheSetup) {
  const auto count = pistondyn::test::allocationsDuring(
      [] { const ps::SkirtSideGrid g(ps::test::thrustSide(64, 48)); });
  EXPECT_GT(count, 0);
}

TEST(SkirtAllocation, PerCallFunctionsAllocateNothing) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(64, 48));  // the default grid size
  const ps::GapAssembly gap(g, everyTerm(g));
  ps::GapFields f = gap.makeFields();
  f.pistonElastic_m.setConstant(1e-7);
  Eigen::ArrayXd pressure = Eigen::ArrayXd::Constant(g.nodeCount(), 1e5);
  Eigen::ArrayXd tauY = Eigen::ArrayXd::Constant(g.nodeCount(), 50.0);
  Eigen::ArrayXd tauPhi = Eigen::ArrayXd::Constant(g.nodeCount(), 5.0);
  double sink = 0.0;
  const long count = pistondyn::test::allocationsDuring([&] {
    for (int call = 0; call < 20; ++call) {
      const double t = 1e-4 * call;
      gap.calc({10e-6 * std::sin(t), 1e-4 * call, 0.0}, {0.01, 0.5, 0.0}, 0.15 + t, 5.0, f);
      ps::calcRigidGap(g, 60e-6, {1e-6, 0, 0}, {}, f.rigid_m, f.rigidRate_mps, f.dGap_dPose,
                       f.squeezeBasis);
      sink += g.calcLoadsOnPiston(pressure, tauY, tauPhi).force_N.x();
      sink += g.calcLoadsOnPiston(pressure).moment_Nm.z();
    }
  });
  EXPECT_EQ(count, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
