// PenaltyContactLaw against hand calculations, continuity checks at the onset and at the
// end of the ramp, and central differences.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "ExpectInvalidArgument.h"
#include "pistondyn/contact_forces/PenaltyContactLaw.h"

namespace pc = pistondyn::contact_forces;

// Past the onset ramp the law is p_ref·(δ/δ_ref)^e (hand calculation):
//   linear, p_ref = 10 MPa at 1 µm, onset 0.1 µm, gap −0.9 µm: δ = 1.0 µm → 10 MPa
//   e = 1.5, gap −3.9 µm: δ = 4 µm → 10 MPa · 4^1.5 = 80 MPa
// Inside the ramp (δ_s = 0.2 µm), gap 0 µm: δ = 0.1 µm, x = 0.5, S = 3·0.25 − 2·0.125 = 0.5
//   linear: 10 MPa · 0.1 · 0.5 = 0.5 MPa
TEST(PenaltyContact, MatchesHandCalculation) {
  pc::PenaltyContactParameters p;
  p.onsetGap_m = 0.1e-6;
  const pc::PenaltyContactLaw linear(p);
  EXPECT_NEAR(linear.calcPressure(-0.9e-6), 10.0e6, 1e-6);
  EXPECT_NEAR(linear.calcPressure(0.0), 0.5e6, 1e-6);
  EXPECT_EQ(linear.calcPressure(0.1e-6), 0.0);
  EXPECT_EQ(linear.calcPressure(5e-6), 0.0);
  EXPECT_NEAR(linear.calcNode(0.0).realAreaFraction, 0.5, 1e-12);
  p.exponent = 1.5;
  const pc::PenaltyContactLaw hertzian(p);
  EXPECT_NEAR(hertzian.calcPressure(-3.9e-6), 80.0e6, 1e-5);
}

// Pressure and slope are continuous at the onset (δ = 0) and at the end of the ramp
// (δ = δ_s): compare values just either side (property of the C¹ cubic step).
TEST(PenaltyContact, PressureAndSlopeContinuousAtOnsetAndRampEnd) {
  for (double exponent : {1.0, 1.5, 2.0}) {
    pc::PenaltyContactParameters p;
    p.exponent = exponent;
    const pc::PenaltyContactLaw law(p);
    const double e = 1e-15;  // m, far below every length in the law
    for (double kink : {p.onsetGap_m, p.onsetGap_m - p.transitionDepth_m}) {
      const pc::PressureAndSlope below = law.calcPressureAndSlope(kink - e);
      const pc::PressureAndSlope above = law.calcPressureAndSlope(kink + e);
      const double slopeScale = p.referencePressure_Pa / p.referencePenetration_m;
      EXPECT_NEAR(below.pressure_Pa, above.pressure_Pa, 1e-6 * p.referencePressure_Pa);
      EXPECT_NEAR(below.dPressure_dGap_PaPerM, above.dPressure_dGap_PaPerM, 1e-6 * slopeScale)
          << "exponent " << exponent << ", kink at " << kink;
    }
  }
}

// ∂p/∂h against a central difference of p (independent), across onset, ramp and beyond.
TEST(PenaltyContact, SlopeMatchesCentralDifference) {
  for (double exponent : {1.0, 1.5, 2.5}) {
    pc::PenaltyContactParameters p;
    p.exponent = exponent;
    const pc::PenaltyContactLaw law(p);
    for (double gap = -3e-6; gap < -1e-9; gap += 0.0137e-6) {
      const double step = 1e-12;
      const double difference =
          (law.calcPressure(gap + step) - law.calcPressure(gap - step)) / (2.0 * step);
      const double slope = law.calcPressureAndSlope(gap).dPressure_dGap_PaPerM;
      ASSERT_LT(slope, 0.0);
      ASSERT_NEAR(slope / difference, 1.0, 1e-6) << "exponent " << exponent << ", gap " << gap;
    }
  }
}

// Overflow (reference: the double range). (δ/δ_ref)^e overflows for a deep enough overlap;
// before the fix the law returned p = inf and, from inf · S'(1) = inf · 0, dp/dh = NaN.
// Now the slope term of the step is skipped where S = 1, and the base class reports a
// non-finite result as an error naming the gap. Just below the overflow the result is the
// plain power law, finite, slope −p_ref·e·(δ/δ_ref)^(e−1)/δ_ref (hand value).
TEST(PenaltyContact, OverflowingOverlapThrowsInsteadOfInfOrNan) {
  pc::PenaltyContactParameters p;  // 10 MPa at 1 µm, onset 0
  const pc::PenaltyContactLaw linear(p);
  const pc::PressureAndSlope big = linear.calcPressureAndSlope(-1e290);  // δ/δ_ref = 1e296
  EXPECT_NEAR(big.pressure_Pa / 1e303, 1.0, 1e-14);
  EXPECT_NEAR(big.dPressure_dGap_PaPerM / -1e13, 1.0, 1e-14);
  p.exponent = 1.5;
  const pc::PenaltyContactLaw hertzian(p);
  for (const pc::PenaltyContactLaw* law : {&linear, &hertzian}) {
    const double gap = law == &linear ? -1e300 : -1e200;  // (1e306)^1 · 1e7, (1e206)^1.5
    for (const auto& call : std::vector<std::function<void()>>{
             [&] { law->calcPressure(gap); }, [&] { law->calcPressureAndSlope(gap); },
             [&] { law->calcNode(gap); }}) {
      SCOPED_TRACE(gap);
      pistondyn::test::expectInvalidArgument(call, {"gap_m", "overflow"});
    }
    Eigen::ArrayXXd field = Eigen::ArrayXXd::Constant(3, 2, -1e-7);
    field(2, 1) = gap;
    pc::ContactField out;
    pistondyn::test::expectInvalidArgument([&] { law->calcField(field, out); }, {"gap_m(2, 1)"});
  }
}
