// Regime bounds (definition: boundary h/σ ≤ 1 < mixed ≤ 3 < hydrodynamic) and the bad
// inputs the issue lists: each must throw std::invalid_argument naming the argument.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "ExpectInvalidArgument.h"
#include "pistondyn/contact_forces/BoundaryFriction.h"
#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"
#include "pistondyn/contact_forces/PenaltyContactLaw.h"

namespace pc = pistondyn::contact_forces;
using pc::LubricationRegime;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

using pistondyn::test::expectInvalidArgument;
}  // namespace

TEST(Regime, BoundariesAtOneAndThree) {
  EXPECT_EQ(pc::classifyRegime(-2.0), LubricationRegime::Boundary);
  EXPECT_EQ(pc::classifyRegime(1.0), LubricationRegime::Boundary);
  EXPECT_EQ(pc::classifyRegime(std::nextafter(1.0, 2.0)), LubricationRegime::Mixed);
  EXPECT_EQ(pc::classifyRegime(3.0), LubricationRegime::Mixed);
  EXPECT_EQ(pc::classifyRegime(std::nextafter(3.0, 4.0)), LubricationRegime::Hydrodynamic);
  EXPECT_EQ(pc::classifyRegime(kInf), LubricationRegime::Hydrodynamic);
  EXPECT_EQ(pc::classifyRegime(-kInf), LubricationRegime::Boundary);
  EXPECT_STREQ(pc::toString(LubricationRegime::Mixed), "mixed");

  // Through a law: σ = 2^-21 m exactly (Rq2 = 0), so h = σ and h = 3σ are exact ratios.
  pc::GreenwoodTrippParameters p;
  p.roughnessSurface1_m = std::ldexp(1.0, -21);
  p.roughnessSurface2_m = 0.0;
  const pc::GreenwoodTrippLaw law(p);
  const double sigma = law.compositeSigma_m();
  EXPECT_EQ(sigma, std::ldexp(1.0, -21));
  EXPECT_EQ(law.calcNode(sigma).regime, LubricationRegime::Boundary);
  EXPECT_EQ(law.calcNode(std::nextafter(sigma, 1.0)).regime, LubricationRegime::Mixed);
  EXPECT_EQ(law.calcNode(3.0 * sigma).regime, LubricationRegime::Mixed);
  EXPECT_EQ(law.calcNode(std::nextafter(3.0 * sigma, 1.0)).regime, LubricationRegime::Hydrodynamic);
  EXPECT_EQ(law.classify(3.0 * sigma), LubricationRegime::Mixed);
}

TEST(BadInput, GreenwoodTrippParameters) {
  auto with = [](const std::function<void(pc::GreenwoodTrippParameters&)>& edit) {
    return [edit] {
      pc::GreenwoodTrippParameters p;
      edit(p);
      const pc::GreenwoodTrippLaw law(p);
    };
  };
  expectInvalidArgument(with([](auto& p) { p.roughnessSurface1_m = -1e-7; }),
                        "roughnessSurface1_m");
  expectInvalidArgument(with([](auto& p) { p.roughnessSurface2_m = kNaN; }), "roughnessSurface2_m");
  expectInvalidArgument(with([](auto& p) {
                          p.roughnessSurface1_m = 0.0;
                          p.roughnessSurface2_m = 0.0;
                        }),
                        "rq1_m^2 + rq2_m^2");
  expectInvalidArgument(with([](auto& p) { p.surface1.youngsModulus_Pa = -70e9; }),
                        "surface1.youngsModulus_Pa");
  expectInvalidArgument(with([](auto& p) { p.surface2.youngsModulus_Pa = 0.0; }),
                        "surface2.youngsModulus_Pa");
  for (double nu : {-1.0, 0.5, 0.7, -3.0, kNaN}) {
    expectInvalidArgument(with([nu](auto& p) { p.surface2.poissonRatio = nu; }),
                          "surface2.poissonRatio");
  }
  expectInvalidArgument(with([](auto& p) { p.roughnessParameter = 0.0; }), "roughnessParameter");
  expectInvalidArgument(with([](auto& p) { p.roughnessParameter = -0.04; }), "roughnessParameter");
  expectInvalidArgument(with([](auto& p) { p.sigmaOverBeta = 0.0; }), "sigmaOverBeta");
  expectInvalidArgument(with([](auto& p) { p.sigmaOverBeta = -1e-3; }), "sigmaOverBeta");
  expectInvalidArgument(with([](auto& p) {
                          p.tailModel = pc::TailIntegralModel::PowerLawFit;
                          p.powerLawF52.coefficient = -1.0;
                        }),
                        "powerLawF52.coefficient");
  // Valid edge values construct.
  EXPECT_NO_THROW(with([](auto& p) { p.surface1.poissonRatio = 0.4999; })());
  EXPECT_NO_THROW(with([](auto& p) { p.roughnessSurface2_m = 0.0; })());
}

TEST(BadInput, FreeFunctions) {
  expectInvalidArgument([] { pc::compositeRoughness_m(-1e-7, 1e-7); }, "rq1_m");
  expectInvalidArgument(
      [] {
        pc::effectiveModulus_Pa({200e9, 0.3}, {-1.0, 0.3});
      },
      "surface2.youngsModulus_Pa");
  expectInvalidArgument(
      [] {
        pc::reducedModulusHertz_Pa({200e9, 0.5}, {200e9, 0.3});
      },
      "surface1.poissonRatio");
  expectInvalidArgument([] { pc::greenwoodTrippCoefficient(0.04, 0.0); }, "sigmaOverBeta");
  expectInvalidArgument([] { pc::classifyRegime(kNaN); }, "filmRatio");
}

TEST(BadInput, NanGaps) {
  const pc::GreenwoodTrippLaw law;
  expectInvalidArgument([&] { law.calcPressure(kNaN); }, "gap_m");
  expectInvalidArgument([&] { law.calcPressureAndSlope(kNaN); }, "gap_m");
  expectInvalidArgument([&] { law.calcNode(-kInf); }, "gap_m");
  expectInvalidArgument([&] { law.classify(kNaN); }, "gap_m");
  // −inf is rejected by classify as by the pressure calls (it used to return "boundary"
  // while calcPressure threw).
  expectInvalidArgument([&] { law.classify(-kInf); }, "GreenwoodTripp::classify");
  EXPECT_EQ(law.classify(kInf), LubricationRegime::Hydrodynamic);
  Eigen::ArrayXXd gap = Eigen::ArrayXXd::Constant(4, 3, 1e-6);
  gap(2, 1) = kNaN;
  pc::ContactField field;
  expectInvalidArgument([&] { law.calcField(gap, field); }, "gap_m(2, 1)");
  const pc::PenaltyContactLaw penalty;
  expectInvalidArgument([&] { penalty.calcPressure(kNaN); }, "Penalty::calcPressure");
}

TEST(BadInput, PenaltyAndFrictionParameters) {
  auto penalty = [](const std::function<void(pc::PenaltyContactParameters&)>& edit) {
    return [edit] {
      pc::PenaltyContactParameters p;
      edit(p);
      const pc::PenaltyContactLaw law(p);
    };
  };
  expectInvalidArgument(penalty([](auto& p) { p.referencePressure_Pa = 0.0; }),
                        "referencePressure_Pa");
  expectInvalidArgument(penalty([](auto& p) { p.exponent = 0.5; }), "exponent");
  expectInvalidArgument(penalty([](auto& p) { p.transitionDepth_m = 0.0; }), "transitionDepth_m");
  expectInvalidArgument(penalty([](auto& p) { p.compositeRoughness_m = -1e-6; }),
                        "compositeRoughness_m");
  expectInvalidArgument(penalty([](auto& p) { p.onsetGap_m = kNaN; }), "onsetGap_m");

  auto friction = [](const std::function<void(pc::BoundaryFrictionParameters&)>& edit) {
    return [edit] {
      pc::BoundaryFrictionParameters p;
      edit(p);
      const pc::BoundaryFriction f(p);
    };
  };
  expectInvalidArgument(friction([](auto& p) { p.frictionCoefficient = -0.1; }),
                        "frictionCoefficient");
  expectInvalidArgument(friction([](auto& p) { p.regularisationSpeed_mps = 0.0; }),
                        "regularisationSpeed_mps");
  const pc::BoundaryFriction f;
  expectInvalidArgument([&] { f.calcShearStress_Pa(-1.0, Eigen::Vector2d(1, 0)); },
                        "contactPressure_Pa");
  expectInvalidArgument([&] { f.calcShearStress_Pa(1.0, Eigen::Vector2d(kNaN, 0)); },
                        "slidingVelocity_mps");
  Eigen::ArrayXXd p = Eigen::ArrayXXd::Constant(2, 2, 1e5);
  Eigen::ArrayXXd vx = Eigen::ArrayXXd::Zero(2, 2);
  Eigen::ArrayXXd vy = Eigen::ArrayXXd::Zero(2, 2);
  Eigen::ArrayXXd tx, ty;
  vy(1, 0) = kInf;
  expectInvalidArgument([&] { f.calcShearStressField(p, vx, vy, tx, ty); },
                        "slidingVelocityY_mps(1, 0)");
}

// Greenwood–Tripp at the edges of the double range (reference: the double range and the
// physical scale of surfaces). A denormal or sub-picometre σ is rejected at construction
// (it made h/σ = ±inf for ordinary gaps, hence p = inf in overlap); an overlap so deep
// that F_{5/2} overflows throws naming the gap (it returned p = inf); just inside the range
// the pressure is finite and follows the overlap asymptote F_{5/2}(λ) ≈ |λ|^{5/2} (1 + …).
TEST(BadInput, GreenwoodTrippOverflowAndDenormalSigma) {
  pc::GreenwoodTrippParameters p;
  p.roughnessSurface1_m = 1e-320;  // denormal
  p.roughnessSurface2_m = 0.0;
  expectInvalidArgument([&] { const pc::GreenwoodTrippLaw law(p); },
                        "roughnessSurface1_m^2 + roughnessSurface2_m^2");
  p.roughnessSurface1_m = 0.5e-12;
  expectInvalidArgument([&] { const pc::GreenwoodTrippLaw law(p); }, "1e-12 m");
  p.roughnessSurface1_m = 1e-12;
  EXPECT_NO_THROW(const pc::GreenwoodTrippLaw law(p));

  const pc::GreenwoodTrippLaw law;  // σ = 0.5 µm
  expectInvalidArgument([&] { law.calcPressure(-1e300); }, "gap_m");
  expectInvalidArgument([&] { law.calcPressureAndSlope(-1e300); }, "overflow");
  expectInvalidArgument([&] { law.calcNode(-1e300); }, "gap_m");
  const double deep = -1e100 * law.compositeSigma_m();  // λ = −1e100: F ≈ 1e250
  const double p52 = law.calcPressure(deep);
  EXPECT_TRUE(std::isfinite(p52));
  EXPECT_NEAR(p52 / (law.pressureScale_Pa() * 1e250), 1.0, 1e-12);
}
