// common::wrapCrankAngle_deg against hand-computed angles of the 720 deg cycle.
#include <gtest/gtest.h>

#include <cmath>

#include "pistondyn/common/CrankAngle.h"

namespace pc = pistondyn::common;

TEST(CrankAngle, WrapsIntoTheCycle) {
  EXPECT_EQ(pc::wrapCrankAngle_deg(0.0), 0.0);
  EXPECT_EQ(pc::wrapCrankAngle_deg(719.5), 719.5);
  EXPECT_EQ(pc::wrapCrankAngle_deg(720.0), 0.0);
  EXPECT_EQ(pc::wrapCrankAngle_deg(1440.0 + 65.0), 65.0);  // third cycle
  EXPECT_EQ(pc::wrapCrankAngle_deg(-10.0), 710.0);         // before the start
  EXPECT_EQ(pc::wrapCrankAngle_deg(-1440.0), 0.0);
  // A tiny negative angle: fmod gives -1e-14, + 720 rounds to 720, which is the cycle's 0.
  const double a = pc::wrapCrankAngle_deg(-1e-14);
  EXPECT_GE(a, 0.0);
  EXPECT_LT(a, 720.0);
}

// A table over the cycle (the skirt's supply film, the oil-control ring's film): its points
// exactly, linear between them, and the segment from the last point across 720 deg back to
// the first (hand-computed: 600 -> 100 deg spans 220 deg).
TEST(CrankAngle, ATableOverTheCycleIsLinearAndWrapsFromItsLastPointToItsFirst) {
  const std::vector<double> angle = {100.0, 300.0, 600.0}, value = {1.0, 3.0, 5.0};
  EXPECT_EQ(pc::interpolateOverCycle(angle, value, 100.0), 1.0);
  EXPECT_EQ(pc::interpolateOverCycle(angle, value, 300.0), 3.0);
  EXPECT_DOUBLE_EQ(pc::interpolateOverCycle(angle, value, 200.0), 2.0);
  EXPECT_DOUBLE_EQ(pc::interpolateOverCycle(angle, value, 650.0), 5.0 - 4.0 * 50.0 / 220.0);
  EXPECT_DOUBLE_EQ(pc::interpolateOverCycle(angle, value, 50.0), 5.0 - 4.0 * 170.0 / 220.0);
  EXPECT_DOUBLE_EQ(pc::interpolateOverCycle(angle, value, 50.0 + 1440.0),
                   pc::interpolateOverCycle(angle, value, 50.0));
}
