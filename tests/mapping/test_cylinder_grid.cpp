// CylinderGrid: construction checks and the node areas (trapezoid weights).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "ExpectInvalidArgument.h"
#include "TestSupport.h"
#include "pistondyn/mapping/CylinderGrid.h"
#include "pistondyn/mapping/HatOverlap1D.h"

namespace pm = pistondyn::mapping;
using pistondyn::test::expectInvalidArgument;
using pm::test::kPi;

namespace {

Eigen::VectorXd vec(std::initializer_list<double> v) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(v.size()));
  int k = 0;
  for (double d : v)
    x[k++] = d;
  return x;
}

}  // namespace

TEST(CylinderGrid, RejectsBadNodesNamingTheArgument) {
  const Eigen::VectorXd y = vec({0.0, 0.01, 0.02});
  expectInvalidArgument(
      [&] {
        pm::CylinderGrid::sector(0.03, vec({0.0, 0.2, 0.1, 0.3}), y);
      },
      "phi_rad[2]");
  expectInvalidArgument(
      [&] {
        pm::CylinderGrid::sector(0.03, vec({0.0, 0.1}), vec({0.0, 0.0}));
      },
      "y_m[1]");
  expectInvalidArgument([&] { pm::CylinderGrid::sector(0.03, vec({0.0}), y); },
                        "phi_rad has 1 nodes");
  expectInvalidArgument(
      [&] {
        pm::CylinderGrid::sector(0.03, vec({0.0, 0.1}), vec({0.01}));
      },
      "y_m has 1 nodes");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectInvalidArgument(
      [&] {
        pm::CylinderGrid::sector(0.03, vec({0.0, 0.1}), vec({0.0, nan}));
      },
      "y_m[1]");
  expectInvalidArgument([&] { pm::CylinderGrid::sector(0.0, vec({0.0, 0.1}), y); }, "radius_m");
  expectInvalidArgument([&] { pm::CylinderGrid::sector(nan, vec({0.0, 0.1}), y); }, "radius_m");
  // A sector of 2*pi or more repeats a node: that is a full circle.
  expectInvalidArgument(
      [&] {
        pm::CylinderGrid::sector(0.03, vec({0.0, kPi, 2 * kPi}), y);
      },
      "phi_rad spans");
  expectInvalidArgument(
      [&] {
        pm::CylinderGrid::fullCircle(0.03, vec({0.0, kPi, 2 * kPi}), y);
      },
      "phi_rad spans");
  expectInvalidArgument(
      [&] {
        pm::CylinderGrid::fullCircle(0.03, vec({0.0, kPi}), y);
      },
      "phi_rad has 2 nodes");
  // The first node repeated at the end with rounding: a closing cell of 1e-13 rad (it
  // was accepted, giving dPhi ~ -2e13 in the Hermite surface). Reference: the 1 % rule
  // of CylinderGrid.h, checked on both sides of the threshold (the smallest other cell is
  // the one before the added node, 2*pi/12 minus the closing cell: 1 % of it is 5.19e-3 rad
  // for a 5e-3 closing cell and 5.18e-3 rad for 5.5e-3).
  {
    Eigen::VectorXd ring(13);
    ring.head(12) = pm::fullCircleNodes_rad(12);
    ring[12] = 2 * kPi - 1e-13;
    expectInvalidArgument([&] { pm::CylinderGrid::fullCircle(0.03, ring, y); }, "closing cell");
    pm::HatOverlap1D out;
    expectInvalidArgument(
        [&] {
          pm::calcHatOverlap1D(pm::fullCircleNodes_rad(8), true, ring, true, 2 * kPi, 0.0,
                               pm::LoadRule::Consistent, false, out);
        },
        "targetNodes[0]");
    ring[12] = 2 * kPi - 5.0e-3;  // 0.95 % of the smallest other cell
    expectInvalidArgument([&] { pm::CylinderGrid::fullCircle(0.03, ring, y); }, "closing cell");
    ring[12] = 2 * kPi - 5.5e-3;  // 1.05 %: a (strongly) graded ring, accepted
    EXPECT_NO_THROW(pm::CylinderGrid::fullCircle(0.03, ring, y));
  }
  expectInvalidArgument([] { pm::uniformNodes(0.0, 1.0, 1); }, "count");
  expectInvalidArgument([] { pm::fullCircleNodes_rad(2); }, "count");
}

// Independent reference: the grid's area in closed form, R * (angle range) * length;
// the node areas are the integrals of the shape functions, which sum to it.
TEST(CylinderGrid, NodeAreasSumToTheGridArea) {
  std::mt19937 rng(7);
  const double r = 0.0325;
  const Eigen::VectorXd phi = pm::test::randomNodes(rng, -0.7, 0.9, 11);
  const Eigen::VectorXd y = pm::test::randomNodes(rng, 0.001, 0.043, 17);
  const auto sector = pm::CylinderGrid::sector(r, phi, y);
  const double sectorArea = r * 1.6 * 0.042;
  EXPECT_NEAR(sector.nodeArea_m2().sum(), sectorArea, 1e-14 * sectorArea);

  const auto ring = pm::CylinderGrid::fullCircle(r, pm::test::randomNodes(rng, 0.3, 6.0, 13), y);
  const double ringArea = r * 2 * kPi * 0.042;
  EXPECT_NEAR(ring.nodeArea_m2().sum(), ringArea, 1e-14 * ringArea);
  EXPECT_EQ(ring.phiCellCount(), 13);
  EXPECT_EQ(sector.phiCellCount(), 10);
  EXPECT_DOUBLE_EQ(ring.phiEnd_rad(), 0.3 + 2 * kPi);
}
