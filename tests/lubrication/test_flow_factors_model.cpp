// PatirChengFlowFactors: how the single-surface factors are combined for two rough
// surfaces (Patir & Cheng 1979: Phi_s = Vr1 Phi_s(gamma1) - Vr2 Phi_s(gamma2), with
// Vr_i = Rq_i^2 / sigma^2, the same for phi_fs), the cross-flow relation
// phi_y(gamma) = phi_x(1/gamma) (Patir & Cheng 1978), the smooth limits, and bad input.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "ExpectInvalidArgument.h"
#include "pistondyn/lubrication/FlowFactorModel.h"
#include "pistondyn/lubrication/PatirChengExpectedGap.h"
#include "pistondyn/lubrication/PatirChengFactors.h"
#include "pistondyn/lubrication/PatirChengFlowFactors.h"

using namespace pistondyn::lubrication;
namespace pc = pistondyn::lubrication::patir_cheng;

namespace {

PatirChengParameters skirtAndLiner() {
  PatirChengParameters p;
  p.rq1_m = 0.3e-6;  // surface 1: the liner (moves at U relative to the grid)
  p.rq2_m =
      0.4e-6;  // surface 2: the skirt (carries the grid); sigma = 0.5 um, Vr1 = 0.36, Vr2 = 0.64
  return p;
}

}  // namespace

TEST(PatirChengFlowFactors, CompositeSigmaAndVarianceRatios) {
  const PatirChengFlowFactors model(skirtAndLiner());
  EXPECT_NEAR(model.compositeSigma_m(), 0.5e-6, 1e-18);
  const double sigma = 0.5e-6;
  for (const double H : {0.4, 1.0, 2.0, 4.0, 6.0}) {
    const NodeFlowFactors f = model.calcFactors(H * sigma);
    // [PC79]: sigma Phi_s = sigma (Vr1 - Vr2) Phi_s(H, 1) for equal gamma.
    EXPECT_NEAR(f.sigmaPhiS_m, sigma * (0.36 - 0.64) * pc::calcShearFlowFactor(H, 1.0), 1e-20) << H;
    EXPECT_NEAR(f.phiFs, (0.36 - 0.64) * pc::calcShearStressFactorFs(H, 1.0), 1e-14) << H;
    EXPECT_NEAR(f.phiPressureSliding, pc::calcPressureFlowFactor(H, 1.0), 1e-15);
    EXPECT_NEAR(f.phiPressureCross, pc::calcPressureFlowFactor(H, 1.0), 1e-15);
    EXPECT_NEAR(f.phiF, pc::calcShearStressFactorF(H), 1e-15);
    EXPECT_NEAR(f.phiFp, pc::calcShearStressFactorFp(H, 1.0), 1e-15);
    const ExpectedGap g = calcExpectedGap(H * sigma, sigma, ExpectedGapForm::kGaussian);
    EXPECT_DOUBLE_EQ(f.expectedGap_m, g.value_m);
    EXPECT_DOUBLE_EQ(f.dExpectedGap_dh, g.dValue_dh);
  }
}

// Which surface is rough decides the sign of the shear flow: a rough moving surface
// (surface 1) over a smooth one gives +Phi_s, the reverse -Phi_s [PC79], and equal
// roughness on both gives none.
TEST(PatirChengFlowFactors, ShearFlowSignFollowsTheRoughSurface) {
  const double rq = 0.5e-6;
  const double H = 1.5;
  PatirChengParameters movingRough;
  movingRough.rq1_m = rq;
  PatirChengParameters stationaryRough;
  stationaryRough.rq2_m = rq;
  PatirChengParameters bothEqual;
  bothEqual.rq1_m = bothEqual.rq2_m = rq;

  const double phiS = pc::calcShearFlowFactor(H, 1.0);
  EXPECT_NEAR(PatirChengFlowFactors(movingRough).calcFactors(H * rq).sigmaPhiS_m, rq * phiS, 1e-20);
  EXPECT_NEAR(PatirChengFlowFactors(stationaryRough).calcFactors(H * rq).sigmaPhiS_m, -rq * phiS,
              1e-20);
  const double sigmaBoth = std::sqrt(2.0) * rq;
  EXPECT_EQ(PatirChengFlowFactors(bothEqual).calcFactors(1.5 * sigmaBoth).sigmaPhiS_m, 0.0);
  EXPECT_EQ(PatirChengFlowFactors(bothEqual).calcFactors(1.5 * sigmaBoth).phiFs, 0.0);
}

// Per-surface Peklenik numbers for Phi_s and phi_fs, composite one for phi_x, phi_y, phi_fp.
TEST(PatirChengFlowFactors, PerSurfaceAndCompositePeklenik) {
  PatirChengParameters p = skirtAndLiner();
  p.peklenik1 = 1.0 / 3.0;
  p.peklenik2 = 6.0;
  p.peklenikComposite = 3.0;
  const PatirChengFlowFactors model(p);
  const double sigma = 0.5e-6;
  const double H = 2.2;
  const NodeFlowFactors f = model.calcFactors(H * sigma);
  EXPECT_NEAR(f.sigmaPhiS_m,
              sigma * (0.36 * pc::calcShearFlowFactor(H, 1.0 / 3.0) -
                       0.64 * pc::calcShearFlowFactor(H, 6.0)),
              1e-20);
  EXPECT_NEAR(
      f.phiFs,
      0.36 * pc::calcShearStressFactorFs(H, 1.0 / 3.0) - 0.64 * pc::calcShearStressFactorFs(H, 6.0),
      1e-14);
  EXPECT_NEAR(f.phiPressureSliding, pc::calcPressureFlowFactor(H, 3.0), 1e-15);
  EXPECT_NEAR(f.phiFp, pc::calcShearStressFactorFp(H, 3.0), 1e-15);
  EXPECT_DOUBLE_EQ(model.getCompositePeklenik(), 3.0);
}

// [PC78]: phi_y(H, gamma) = phi_x(H, 1/gamma), for the table interpolation and for the
// docs/DESIGN.md fit, at tabulated and intermediate gamma.
TEST(PatirChengFlowFactors, CrossFactorIsSlidingFactorOfInverseGamma) {
  for (const auto model :
       {pc::PressureFlowGammaModel::kTableLogGamma, pc::PressureFlowGammaModel::kDesignNoteFit}) {
    for (const double gamma : {1.0 / 9.0, 0.25, 1.0, 2.0, 6.0, 9.0}) {
      PatirChengParameters a = skirtAndLiner();
      a.peklenik1 = a.peklenik2 = gamma;
      a.pressureFlowGammaModel = model;
      PatirChengParameters b = a;
      b.peklenik1 = b.peklenik2 = 1.0 / gamma;
      const PatirChengFlowFactors ma(a);
      const PatirChengFlowFactors mb(b);
      for (const double H : {0.3, 0.9, 2.0, 5.0}) {
        const double h = H * 0.5e-6;
        EXPECT_NEAR(ma.calcFactors(h).phiPressureCross, mb.calcFactors(h).phiPressureSliding, 1e-14)
            << "gamma " << gamma << " H " << H;
        EXPECT_NEAR(ma.calcFactors(h).phiPressureCross,
                    pc::calcPressureFlowFactor(H, 1.0 / gamma, model), 1e-14);
      }
    }
  }
}

// Far from contact the average Reynolds equation becomes the plain one.
TEST(PatirChengFlowFactors, LargeGapGivesPlainReynolds) {
  PatirChengParameters p = skirtAndLiner();
  p.peklenik1 = p.peklenik2 = 9.0;  // slowest approach to 1 (H^-1.5)
  const PatirChengFlowFactors model(p);
  const double h = 1e6 * 0.5e-6;
  const NodeFlowFactors f = model.calcFactors(h);
  EXPECT_NEAR(f.phiPressureSliding, 1.0, 1e-8);
  EXPECT_NEAR(f.phiPressureCross, 1.0, 1e-8);
  EXPECT_NEAR(f.sigmaPhiS_m, 0.0, 1e-30);
  EXPECT_NEAR(f.expectedGap_m, h, 1e-15 * h);
  EXPECT_NEAR(f.dExpectedGap_dh, 1.0, 1e-15);
  EXPECT_NEAR(f.phiF, 1.0, 1e-11);
  EXPECT_EQ(f.phiFs, 0.0);
  EXPECT_NEAR(f.phiFp, 1.0, 1e-12);
}

TEST(PatirChengFlowFactors, SmoothSurfacesGiveSmoothFactors) {
  const PatirChengFlowFactors model(PatirChengParameters{});
  EXPECT_EQ(model.compositeSigma_m(), 0.0);
  const NodeFlowFactors f = model.calcFactors(3e-6);
  const NodeFlowFactors s = SmoothFlowFactors().calcFactors(3e-6);
  EXPECT_EQ(f.phiPressureSliding, s.phiPressureSliding);
  EXPECT_EQ(f.phiPressureCross, s.phiPressureCross);
  EXPECT_EQ(f.sigmaPhiS_m, s.sigmaPhiS_m);
  EXPECT_EQ(f.expectedGap_m, s.expectedGap_m);
  EXPECT_EQ(f.dExpectedGap_dh, s.dExpectedGap_dh);
  EXPECT_EQ(f.phiF, s.phiF);
  EXPECT_EQ(f.phiFs, s.phiFs);
  EXPECT_EQ(f.phiFp, s.phiFp);
}

// Deep in asperity contact (H down to 1e-3) every factor stays finite and the flow
// coefficients stay positive.
TEST(PatirChengFlowFactors, AsperityContactGivesFiniteFactors) {
  PatirChengParameters p = skirtAndLiner();
  for (const double gamma : {1.0 / 9.0, 1.0, 9.0}) {
    p.peklenik1 = p.peklenik2 = gamma;
    const PatirChengFlowFactors model(p);
    for (const double H : {1e-3, 0.05, 0.2, 0.49}) {
      const NodeFlowFactors f = model.calcFactors(H * 0.5e-6);
      EXPECT_GT(f.phiPressureSliding, 0.0);
      EXPECT_GT(f.phiPressureCross, 0.0);
      EXPECT_GT(f.phiFp, 0.0);
      EXPECT_GT(f.phiF, 0.0);
      EXPECT_GT(f.expectedGap_m, 0.0);
      EXPECT_TRUE(std::isfinite(f.sigmaPhiS_m) && std::isfinite(f.phiFs));
    }
  }
}

TEST(PatirChengFlowFactors, BadInputThrowsNamingTheArgument) {
  const auto expectThrowMentioning = [](const PatirChengParameters& p, const std::string& word) {
    pistondyn::test::expectInvalidArgument([&] { PatirChengFlowFactors model(p); }, word);
  };
  PatirChengParameters p = skirtAndLiner();
  p.rq1_m = -1e-7;
  expectThrowMentioning(p, "rq1_m");
  p = skirtAndLiner();
  p.rq2_m = std::nan("");
  expectThrowMentioning(p, "rq2_m");
  p = skirtAndLiner();
  p.peklenik1 = 0.0;
  expectThrowMentioning(p, "peklenik1");
  p = skirtAndLiner();
  p.peklenik2 = -3.0;
  expectThrowMentioning(p, "peklenik2");
  p = skirtAndLiner();
  p.peklenikComposite = 0.0;
  expectThrowMentioning(p, "peklenikComposite");
  p = skirtAndLiner();
  p.peklenik1 = 3.0;  // differs from peklenik2 = 1 and no composite given
  expectThrowMentioning(p, "peklenikComposite");

  const PatirChengFlowFactors model(skirtAndLiner());
  for (const double h : {0.0, -1e-6, std::nan(""), HUGE_VAL}) {
    SCOPED_TRACE(h);
    pistondyn::test::expectInvalidArgument([&] { model.calcFactors(h); }, {"h_m"});
  }
}

// The phi_f cut-off reaches the model (reference: the single-surface function with the
// same eps*), and a bad one is rejected naming the member.
TEST(PatirChengFlowFactors, PhiFCutoffIsPassedThrough) {
  PatirChengParameters p = skirtAndLiner();
  EXPECT_EQ(p.phiFCutoff, 1.0 / 300.0);
  p.phiFCutoff = 0.01;
  const PatirChengFlowFactors model(p);
  const double sigma = model.compositeSigma_m();
  for (const double H : {0.3, 1.0, 2.5, 4.0})
    EXPECT_EQ(model.calcFactors(H * sigma).phiF, pc::calcShearStressFactorF(H, 0.01)) << H;
  for (const double bad : {0.0, 0.5, std::nan("")}) {
    p.phiFCutoff = bad;
    SCOPED_TRACE(bad);
    pistondyn::test::expectInvalidArgument([&] { const PatirChengFlowFactors m(p); },
                                           {"phiFCutoff"});
  }
}

// sigma and the variance ratios at the ends of the double range (reference: hypot and the
// ratios Rq_i / sigma, and the single-surface factors). sqrt(Rq1^2 + Rq2^2) underflowed to
// 0 for Rq ~ 1e-170 (the model then silently returned smooth-surface factors) and
// overflowed for Rq ~ 1e200.
TEST(PatirChengFlowFactors, SigmaIsRobustForTinyAndHugeRoughness) {
  for (const double scale : {1e-170, 1e-300, 1e200}) {
    PatirChengParameters p;
    p.rq1_m = 0.6 * scale;  // Vr1 = 0.36
    p.rq2_m = 0.8 * scale;  // Vr2 = 0.64
    const PatirChengFlowFactors model(p);
    const double sigma = std::hypot(0.6 * scale, 0.8 * scale);
    ASSERT_GT(sigma, 0.0);
    ASSERT_TRUE(std::isfinite(sigma));
    EXPECT_NEAR(model.compositeSigma_m() / sigma, 1.0, 1e-15) << scale;
    const NodeFlowFactors f = model.calcFactors(1.5 * sigma);
    EXPECT_NEAR(f.phiFs, (0.36 - 0.64) * pc::calcShearStressFactorFs(1.5, 1.0), 1e-14) << scale;
    EXPECT_NEAR(f.phiPressureSliding, pc::calcPressureFlowFactor(1.5, 1.0), 1e-14) << scale;
    EXPECT_NEAR(f.sigmaPhiS_m / sigma, (0.36 - 0.64) * pc::calcShearFlowFactor(1.5, 1.0), 1e-14)
        << scale;
  }
}
