// GreenwoodTrippLaw against hand calculations, the Hertz-based derivation of the modulus
// convention, central finite differences, and its own per-node calls.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <thread>
#include <vector>

#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"
#include "pistondyn/contact_forces/PenaltyContactLaw.h"

namespace pc = pistondyn::contact_forces;

namespace {
constexpr double kPi = 3.14159265358979323846;

pc::GreenwoodTrippParameters publishedSet() {
  // ηβσ = 0.04 and σ/β = 0.001: the roughness set of many ring-pack papers (the one the
  // issue names). Surface 1 = cast-iron liner E = 115 GPa, ν = 0.26, Rq 0.3 µm; surface 2 =
  // aluminium skirt E = 75 GPa, ν = 0.33, Rq 0.4 µm (SurfacePair.h; the law is symmetric).
  pc::GreenwoodTrippParameters p;
  p.roughnessSurface1_m = 0.3e-6;
  p.roughnessSurface2_m = 0.4e-6;
  p.surface1 = {115.0e9, 0.26};
  p.surface2 = {75.0e9, 0.33};
  p.roughnessParameter = 0.04;
  p.sigmaOverBeta = 0.001;
  return p;
}
}  // namespace

// Hand calculation (independent of the code path; the F values are the parabolic-cylinder
// closed form evaluated to 25 digits, which the quadrature test confirms):
//   σ  = √(0.4² + 0.3²) µm = 0.5 µm
//   K  = (8√2/15)·π·0.04²·√0.001 = 0.754247·3.141593·0.0016·0.0316228 = 1.198901714e-4
//   Σ  = (1 − 0.33²)/75e9 + (1 − 0.26²)/115e9 = 1.18813e-11 + 8.10783e-12 = 1.998915942e-11 /Pa
//   E′ = 2/Σ = 1.000542323e11 Pa,  K·E′ = 1.199551906e7 Pa
//   h = 0.5 µm (λ = 1): F_5/2(1) = 0.08056233557, F_2(1) = 0.07533978334, F_3/2(1) = 0.07566817739
//     p_c  = 1.199551906e7 · 0.08056233557 = 9.663870319e5 Pa  (0.966 MPa)
//     A/A0 = π²·0.04²·0.07533978334 = 1.189718172e-3
//     dp/dh = −2.5 · 1.199551906e7 · 0.07566817739 / 0.5e-6 = −4.538395e12 Pa/m
//   h = 1.0 µm (λ = 2): p_c = 1.199551906e7 · 0.005423705197 = 6.506015907e4 Pa
//   h = 0 (λ = 0):      p_c = 1.199551906e7 · 0.6166342190 = 7.396847527e6 Pa
TEST(GreenwoodTripp, PublishedParameterSetMatchesHandCalculation) {
  const pc::GreenwoodTrippLaw law(publishedSet());
  // Hand values carry 10 significant digits; σ = hypot(0.4, 0.3) µm is 0.5 µm to 1 ulp.
  const double tol = 1e-9;
  EXPECT_NEAR(law.compositeSigma_m() / 0.5e-6, 1.0, 1e-15);
  EXPECT_NEAR(law.coefficientK() / 1.198901714e-4, 1.0, tol);
  EXPECT_NEAR(law.effectiveModulus_Pa() / 1.000542323e11, 1.0, tol);
  EXPECT_NEAR(law.pressureScale_Pa() / 1.199551906e7, 1.0, tol);

  const pc::ContactNodeState at1 = law.calcNode(0.5e-6);
  EXPECT_NEAR(at1.pressure_Pa / 9.663870319e5, 1.0, tol);
  EXPECT_NEAR(at1.realAreaFraction / 1.189718172e-3, 1.0, tol);
  EXPECT_NEAR(at1.dPressure_dGap_PaPerM / -4.538395e12, 1.0, 1e-6);  // 7 digits written
  EXPECT_NEAR(at1.filmRatio, 1.0, 1e-15);
  EXPECT_EQ(at1.regime, pc::LubricationRegime::Boundary);
  EXPECT_NEAR(law.calcPressure(1.0e-6) / 6.506015907e4, 1.0, tol);
  EXPECT_NEAR(law.calcPressure(0.0) / 7.396847527e6, 1.0, tol);
}

// The convention: K(8√2/15)·E′ with E′ = 2E* equals Greenwood & Tripp's Hertz-based
// (16√2/15)·π·(ηβσ)²·√(σ/β)·E* (derivation in GreenwoodTrippLaw.h), E* computed here.
TEST(GreenwoodTripp, ModulusConventionEqualsHertzBasedCoefficient) {
  const pc::GreenwoodTrippParameters p = publishedSet();
  const pc::GreenwoodTrippLaw law(p);
  const double hertzReduced = 1.0 / ((1.0 - 0.33 * 0.33) / 75.0e9 + (1.0 - 0.26 * 0.26) / 115.0e9);
  EXPECT_NEAR(pc::reducedModulusHertz_Pa(p.surface1, p.surface2) / hertzReduced, 1.0, 1e-15);
  EXPECT_NEAR(law.effectiveModulus_Pa() / (2.0 * hertzReduced), 1.0, 1e-15);
  const double greenwoodTripp =
      16.0 * std::sqrt(2.0) / 15.0 * kPi * 0.04 * 0.04 * std::sqrt(0.001) * hertzReduced;
  EXPECT_NEAR(law.pressureScale_Pa() / greenwoodTripp, 1.0, 1e-14);
}

// ∂p/∂h against a central difference of p (independent of the F_{3/2} identity), exact and
// both fits; relative step 1e-5·σ: truncation ~1e-10·λ², rounding ~1e-11, bound 1e-6.
TEST(GreenwoodTripp, SlopeMatchesCentralDifference) {
  for (pc::TailIntegralModel model :
       {pc::TailIntegralModel::Exact, pc::TailIntegralModel::PowerLawFit,
        pc::TailIntegralModel::PolynomialFit}) {
    pc::GreenwoodTrippParameters p = publishedSet();
    p.tailModel = model;
    const pc::GreenwoodTrippLaw law(p);
    const double sigma = law.compositeSigma_m();
    const double upper = model == pc::TailIntegralModel::PolynomialFit ? 1.85 : 3.9;
    for (double lambda = -3.0; lambda <= upper; lambda += 0.0625) {
      const double h = lambda * sigma;
      const double step = 1e-5 * sigma;
      const double difference =
          (law.calcPressure(h + step) - law.calcPressure(h - step)) / (2.0 * step);
      const pc::PressureAndSlope ps = law.calcPressureAndSlope(h);
      EXPECT_DOUBLE_EQ(ps.pressure_Pa, law.calcPressure(h));
      ASSERT_LT(ps.dPressure_dGap_PaPerM, 0.0);
      ASSERT_NEAR(ps.dPressure_dGap_PaPerM / difference, 1.0, 1e-6)
          << "model " << static_cast<int>(model) << ", lambda = " << lambda;
    }
  }
}

// Fit modes reproduce the fits they name (checks the switch, not the fits).
TEST(GreenwoodTripp, FitModesUseTheSelectedFits) {
  pc::GreenwoodTrippParameters p = publishedSet();
  const pc::GreenwoodTrippLaw exact(p);
  p.tailModel = pc::TailIntegralModel::PowerLawFit;
  const pc::GreenwoodTrippLaw power(p);
  p.tailModel = pc::TailIntegralModel::PolynomialFit;
  const pc::GreenwoodTrippLaw poly(p);
  const double sigma = exact.compositeSigma_m();
  for (double lambda : {0.0, 1.0, 1.5, 3.0}) {
    const double h = lambda * sigma;
    EXPECT_NEAR(
        power.calcPressure(h) / (exact.pressureScale_Pa() * pc::kPowerLawFitF52.value(lambda)), 1.0,
        1e-14);
    EXPECT_NEAR(power.calcNode(h).realAreaFraction,
                kPi * kPi * 0.04 * 0.04 * pc::kPowerLawQuotedF2.value(lambda), 1e-17);
    EXPECT_NEAR(poly.calcPressure(h),
                exact.pressureScale_Pa() * pc::kPolynomialFitF52.value(lambda),
                1e-14 * exact.pressureScale_Pa());
  }
}

// calcField on a 2-D grid equals the per-node calls, keeps its storage on the second call
// (no reallocation) and takes a column vector too.
TEST(GreenwoodTripp, FieldMatchesNodeCallsAndReusesStorage) {
  const pc::GreenwoodTrippLaw law(publishedSet());
  Eigen::ArrayXXd gap(7, 5);
  for (Eigen::Index j = 0; j < gap.cols(); ++j) {
    for (Eigen::Index i = 0; i < gap.rows(); ++i) {
      gap(i, j) = (-1.0 + 0.2 * static_cast<double>(i + 7 * j)) * 0.5e-6;
    }
  }
  pc::ContactField field;
  law.calcField(gap, field);
  const double* storage = field.pressure_Pa.data();
  law.calcField(gap, field);
  EXPECT_EQ(storage, field.pressure_Pa.data());
  for (Eigen::Index j = 0; j < gap.cols(); ++j) {
    for (Eigen::Index i = 0; i < gap.rows(); ++i) {
      const pc::ContactNodeState node = law.calcNode(gap(i, j));
      EXPECT_EQ(field.pressure_Pa(i, j), node.pressure_Pa);
      EXPECT_EQ(field.dPressure_dGap_PaPerM(i, j), node.dPressure_dGap_PaPerM);
      EXPECT_EQ(field.realAreaFraction(i, j), node.realAreaFraction);
      EXPECT_EQ(field.filmRatio(i, j), node.filmRatio);
      EXPECT_EQ(field.regime(i, j), node.regime);
    }
  }
  const Eigen::ArrayXd column = gap.col(2);
  law.calcField(column, field);
  EXPECT_EQ(field.pressure_Pa.rows(), 7);
  EXPECT_EQ(field.pressure_Pa.cols(), 1);
  EXPECT_EQ(field.pressure_Pa(3, 0), law.calcPressure(column(3)));
}

// Far apart (+inf) is no contact; deep overlap stays finite, positive and capped in area.
TEST(GreenwoodTripp, LimitsOfTheGap) {
  const pc::GreenwoodTrippLaw law(publishedSet());
  const pc::ContactNodeState far = law.calcNode(std::numeric_limits<double>::infinity());
  EXPECT_EQ(far.pressure_Pa, 0.0);
  EXPECT_EQ(far.dPressure_dGap_PaPerM, 0.0);
  EXPECT_EQ(far.regime, pc::LubricationRegime::Hydrodynamic);
  const pc::ContactNodeState deep = law.calcNode(-50.0 * law.compositeSigma_m());
  EXPECT_TRUE(std::isfinite(deep.pressure_Pa));
  EXPECT_GT(deep.pressure_Pa, law.calcPressure(-49.0 * law.compositeSigma_m()));
  EXPECT_EQ(deep.realAreaFraction, 1.0);
}

// Swapping laws through the interface: the same client code integrates a load with either
// law, and one law object is shared by two threads with identical results (immutability).
TEST(ContactLawInterface, LawsAreSwappableAndShareableAcrossThreads) {
  auto totalLoad = [](const pc::AsperityContactLaw& law,
                      const Eigen::Ref<const Eigen::ArrayXXd>& gap) {
    pc::ContactField field;
    law.calcField(gap, field);
    return field.pressure_Pa.sum();
  };
  const Eigen::ArrayXd gap = Eigen::ArrayXd::LinSpaced(200, -1e-6, 2e-6);
  const std::vector<std::shared_ptr<const pc::AsperityContactLaw>> laws = {
      std::make_shared<const pc::GreenwoodTrippLaw>(publishedSet()),
      std::make_shared<const pc::PenaltyContactLaw>()};
  for (const auto& law : laws) {
    double load1 = 0.0;
    double load2 = 0.0;
    std::thread t1([&] { load1 = totalLoad(*law, gap); });
    std::thread t2([&] { load2 = totalLoad(*law, gap); });
    t1.join();
    t2.join();
    EXPECT_GT(load1, 0.0) << law->name();
    EXPECT_EQ(load1, load2) << law->name();
  }
}
