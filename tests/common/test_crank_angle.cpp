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
