// The film solver with the real Patir & Cheng flow-factor model, against an independent
// 1-D quadrature of the same average Reynolds equation.
//
// Infinitely wide inclined slider: x periodic (no side leakage), gap linear in y, surface 1
// (the liner) sliding along +y into the converging gap, p = 0 at both ends. In 1-D the
// average Reynolds equation says the flux is constant:
//   q = -K(y) p'(y) + (U/2) C(y),   K = phi_y h^3 / (12 eta),   C = hT + sigma phiS,
// so p' = ((U/2) C - q) / K with q fixed by p(L) = 0:  q = (U/2) int(C/K) / int(1/K).
// Load per unit width = int p dy. The test integrates this with composite Gauss-Legendre
// (thousands of panels, exact to ~1e-12) using the same model's factors; the solver must
// reproduce it with its own finite-volume discretisation (second order in the spacing).
// Unequal roughness makes the shear-flow term matter; swapping the surfaces flips it.

#include <gtest/gtest.h>

#include <cmath>

#include "pistondyn/lubrication/FilmSolver.h"
#include "pistondyn/lubrication/PatirChengFlowFactors.h"

namespace {

using namespace pistondyn::lubrication;

constexpr double kL = 5e-3, kU = 10.0, kEta = 0.01;
constexpr double kHin = 3.0e-6, kHout = 0.8e-6;  // h/sigma from 6 down to 1.6 (sigma 0.5 um)

double gapAt(double y) {
  return kHin + (kHout - kHin) * y / kL;
}

// Load per unit width from the 1-D ODE.
double referenceLoadPerWidth(const FlowFactorModel& model) {
  static constexpr double xg[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                   0.9602898564975363};
  static constexpr double wg[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                   0.1012285362903763};
  auto K = [&](double y) {
    const double h = gapAt(y);
    return model.calcFactors(h).phiPressureSliding * h * h * h / (12.0 * kEta);
  };
  auto C = [&](double y) {
    const NodeFlowFactors f = model.calcFactors(gapAt(y));
    return f.expectedGap_m + f.sigmaPhiS_m;
  };
  const int panels = 4000;
  const double dy = kL / panels;
  auto integrate = [&](auto&& f, double a, double b) {
    double sum = 0.0;
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    for (int k = 0; k < 4; ++k)
      sum += wg[k] * half * (f(mid - half * xg[k]) + f(mid + half * xg[k]));
    return sum;
  };
  double intCK = 0.0, intInvK = 0.0;
  for (int i = 0; i < panels; ++i) {
    intCK += integrate([&](double y) { return C(y) / K(y); }, i * dy, (i + 1) * dy);
    intInvK += integrate([&](double y) { return 1.0 / K(y); }, i * dy, (i + 1) * dy);
  }
  const double q = 0.5 * kU * intCK / intInvK;
  // p(y) by accumulating panel integrals of p'; load by Gauss on each panel using
  // p at the Gauss points (integral of p' from the panel start).
  double p0 = 0.0, load = 0.0;
  auto dp = [&](double y) { return (0.5 * kU * C(y) - q) / K(y); };
  for (int i = 0; i < panels; ++i) {
    const double a = i * dy, b = a + dy;
    load += integrate([&](double y) { return p0 + integrate(dp, a, y); }, a, b);
    p0 += integrate(dp, a, b);
  }
  EXPECT_NEAR(p0, 0.0, 1e-9 * std::abs(load / kL)) << "reference p(L) must vanish";
  return load;
}

double solverLoadPerWidth(const FlowFactorModel& model, int ny) {
  const int nx = 4;
  const double width = 1e-3;
  const FilmGrid grid = FilmGrid::uniform(nx, width, ny, kL, /*periodicX=*/true);
  FilmProblem problem;
  problem.gap_m.resize(nx * ny);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i)
      problem.gap_m[i + nx * j] = gapAt(kL * j / (ny - 1));
  }
  problem.slidingVelocity_mps = Eigen::Vector2d(0.0, kU);
  problem.viscosity_Pas = kEta;
  problem.flowFactors = &model;
  problem.cavitation = CavitationModel::None;
  FilmSolver solver;
  const FilmResult r = solver.solve(grid, problem);
  EXPECT_TRUE(r.converged);
  return r.load_N / width;
}

PatirChengParameters roughness(double rq1, double rq2) {
  PatirChengParameters p;
  p.rq1_m = rq1;
  p.rq2_m = rq2;
  return p;
}

TEST(FilmWithPatirCheng, InclinedSliderMatchesOneDimensionalQuadrature) {
  for (const auto& [rq1, rq2] : {std::pair{0.3e-6, 0.4e-6}, std::pair{0.4e-6, 0.3e-6}}) {
    const PatirChengFlowFactors model(roughness(rq1, rq2));
    const double ref = referenceLoadPerWidth(model);
    const double coarse = solverLoadPerWidth(model, 201), fine = solverLoadPerWidth(model, 401);
    const double order = std::log2(std::abs(coarse - ref) / std::abs(fine - ref));
    std::printf(
        "  Rq1 %.1f um, Rq2 %.1f um: reference %.6f N/m, solver %.6f (ny 201), %.6f "
        "(ny 401), rel. error %.2e, order %.2f\n",
        rq1 * 1e6, rq2 * 1e6, ref, coarse, fine, (fine - ref) / ref, order);
    EXPECT_NEAR(fine, ref, 2e-4 * ref);  // second-order FV error at 401 nodes (order checked)
    EXPECT_NEAR(order, 2.0, 0.2);
  }
}

// The shear-flow term really enters: swapping which surface is rougher changes the load,
// in the solver exactly as in the reference.
TEST(FilmWithPatirCheng, ShearFlowSignFollowsTheMovingSurface) {
  const PatirChengFlowFactors linerRougher(roughness(0.4e-6, 0.3e-6));
  const PatirChengFlowFactors skirtRougher(roughness(0.3e-6, 0.4e-6));
  const double refDiff = referenceLoadPerWidth(linerRougher) - referenceLoadPerWidth(skirtRougher);
  const double solDiff =
      solverLoadPerWidth(linerRougher, 401) - solverLoadPerWidth(skirtRougher, 401);
  std::printf("  load(liner rougher) - load(skirt rougher): reference %.6f, solver %.6f N/m\n",
              refDiff, solDiff);
  EXPECT_GT(std::abs(refDiff), 1e-3 * referenceLoadPerWidth(linerRougher));
  EXPECT_NEAR(solDiff, refDiff, 2e-3 * std::abs(refDiff));
}

// With h/sigma in the thousands every factor is smooth, so the rough model must give the
// plain Reynolds answer (the average equation reduces to the Reynolds equation).
TEST(FilmWithPatirCheng, LargeGapOverSigmaGivesPlainReynolds) {
  const PatirChengFlowFactors model(roughness(0.5e-9, 0.5e-9));
  const SmoothFlowFactors smooth;
  const double rough = solverLoadPerWidth(model, 201), plain = solverLoadPerWidth(smooth, 201);
  EXPECT_NEAR(rough, plain, 1e-6 * plain);
}

}  // namespace
