// CONVENTIONS.md: code that runs every force evaluation allocates nothing after the first
// call at a given size. Reference: the allocation counter of tests/support, which interposes
// glibc's malloc, calloc and realloc.

#include <gtest/gtest.h>

#include <vector>

#include "AllocationCounter.h"
#include "pistondyn/mapping/ForceMap.h"
#include "pistondyn/mapping/HermiteSurface.h"

namespace pm = pistondyn::mapping;

namespace {
using pistondyn::test::allocationsDuring;

const double kR = 0.0325;
pm::CylinderGrid contactGrid() {
  return pm::CylinderGrid::sector(kR, pm::uniformNodes(-0.7, 0.7, 64),
                                  pm::uniformNodes(0.0, 0.03, 48));
}
}  // namespace

TEST(MappingAllocation, PerStepCallsDoNotAllocate) {
  // The counter sees Eigen's and the standard library's allocations (otherwise the
  // zeros below would prove nothing); the volatile sink keeps them from being elided.
  volatile double sink = 0.0;
  EXPECT_GT(allocationsDuring([&] {
              Eigen::VectorXd big = Eigen::VectorXd::Ones(1000);
              sink = sink + big[999];
            }),
            0);
  EXPECT_GT(allocationsDuring([&] {
              std::vector<double> v(1000, 1.0);
              sink = sink + v[999];
            }),
            0);

  const auto contact = contactGrid();
  const auto structural = pm::CylinderGrid::sector(kR, pm::uniformNodes(-1.0, 1.0, 17),
                                                   pm::uniformNodes(-0.002, 0.034, 30));
  const auto liner = pm::CylinderGrid::fullCircle(kR, pm::fullCircleNodes_rad(36),
                                                  pm::uniformNodes(0.0, 0.12, 400));
  const Eigen::VectorXd p = Eigen::VectorXd::LinSpaced(contact.nodeCount(), 1e5, 2e6);
  Eigen::VectorXd fs(structural.nodeCount()), fl(liner.nodeCount()), fx(liner.nodeCount()),
      fy(liner.nodeCount()), fz(liner.nodeCount());

  const pm::ForceMap toStructure(contact, structural, {});
  EXPECT_EQ(allocationsDuring([&] { (void)toStructure.apply(p, fs); }), 0);

  const pm::TensorForceMap toLiner(contact, liner, 0.0);
  pm::TensorForceMap::Workspace ws;
  toLiner.setAxialOffset(0.0, ws);  // first call at this size: may allocate
  (void)toLiner.apply(ws, p, fl);
  (void)toLiner.applyTraction(ws, p, p, p, fx, fy, fz);
  EXPECT_EQ(allocationsDuring([&] {
              for (int step = 0; step < 50; ++step) {
                toLiner.setAxialOffset(0.0017 * step, ws);
                (void)toLiner.apply(ws, p, fl);
                (void)toLiner.applyTraction(ws, p, p, p, fx, fy, fz);
                (void)toLiner.accumulate(ws, p, fl);
                (void)toLiner.accumulateTraction(ws, p, p, p, fx, fy, fz);
              }
            }),
            0);

  Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(structural.nodeCount(), 0.0, 1e-5);
  pm::HermiteSurface surface(structural, v);
  pm::HermiteGridWorkspace hws;
  Eigen::VectorXd out(contact.nodeCount()), dPhi(contact.nodeCount()), dY(contact.nodeCount());
  surface.evaluateOnGrid(contact, {}, out, hws);
  EXPECT_EQ(allocationsDuring([&] {
              v *= 1.01;
              surface.updateValues(v);
              surface.evaluateOnGrid(contact, {0.01, 0.001}, out, hws);
              surface.evaluateOnGrid(contact, {0.01, 0.001}, out, dPhi, dY, hws);
              (void)surface.evaluate(0.1, 0.01);
            }),
            0);
}
