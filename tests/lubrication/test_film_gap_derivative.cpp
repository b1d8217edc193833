// Gap derivatives (FilmProblem::gapBasis -> FilmResult::dPressure_dGap): the static pressure-gap
// sensitivity on the final active set, against a closed form and against central differences
// of complete solves.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "FilmSystem.h"
#include "pistondyn/lubrication/GapFloor.h"
#include "test_film_support.h"

namespace pistondyn::lubrication {
namespace {

// Parallel plates of length B approaching at speed v (Hamrock et al., ch. 14):
// p = 6 eta v y (B - y) / h^3, so a uniform change of the gap at a fixed approach speed gives
// dp/dh = -3 p / h. The three-point balance is exact for the quadratic pressure, so the nodal
// derivative is too, up to the difference quotient's truncation and the solve tolerance. Two
// periodic widths take the solver's two ways: 3 nodes (not a multiple of 5: central differences
// per column, ~1e-8) and 5 nodes (the five coloured one-sided perturbations, ~1e-6).
void checkParallelPlates(int nx, double tolerance) {
  const double eta = 0.02, B = 0.01, h = 10e-6, v = 1e-3, width = 1e-3;
  const int ny = 41;
  const FilmGrid g = FilmGrid::uniform(nx, width, ny, B, true);
  FilmProblem pr;
  pr.gap_m.setConstant(g.nodeCount(), h);
  pr.gapRate_mps.setConstant(g.nodeCount(), -v);
  pr.gapBasis = Eigen::MatrixXd::Constant(g.nodeCount(), 1, 1.0);  // d(gap)/du: uniform
  pr.viscosity_Pas = eta;
  pr.cavitation = CavitationModel::Reynolds;
  for (FilmSolverType type :
       {FilmSolverType::FastActiveSet, FilmSolverType::ReferenceGaussSeidel}) {
    FilmSolver solver(test::tightOptions(type, 1e-12));
    const FilmResult r = solver.solve(g, pr);
    ASSERT_TRUE(r.converged);
    ASSERT_FALSE(r.derivativesFailed);
    ASSERT_EQ(r.dPressure_dGap.rows(), g.nodeCount());
    ASSERT_EQ(r.dPressure_dGap.cols(), 1);
    const double scale = 3.0 * 6.0 * eta * v * B * B / (4.0 * h * h * h * h);  // |dp/dh| peak
    double worst = 0.0;
    for (int j = 1; j + 1 < ny; ++j) {
      const double y = g.y_m()[j];
      const double exact = -3.0 * 6.0 * eta * v * y * (B - y) / (h * h * h * h);
      worst = std::max(worst, std::abs(r.dPressure_dGap(g.nodeIndex(1, j), 0) - exact) / scale);
    }
    test::reportFigure(std::string("gapDerivative.parallelPlates.nx") + std::to_string(nx) + "." +
                           (type == FilmSolverType::FastActiveSet ? "fast" : "reference"),
                       worst);
    EXPECT_LT(worst, tolerance);
    // Edge nodes are prescribed: no derivative.
    EXPECT_EQ(r.dPressure_dGap(g.nodeIndex(1, 0), 0), 0.0);
  }
}

TEST(FilmGapDerivative, ParallelPlatesMatchTheClosedForm) {
  checkParallelPlates(3, 1e-7);
  checkParallelPlates(5, 1e-5);
}

// Shapes on the skirt patch: uniform, a tilt-like ramp, and a circumferential cosine (a mode
// of the elastic skirt), each [m per unit].
Eigen::MatrixXd gapShapes(const test::SkirtPatch& sp, const FilmGrid& g) {
  Eigen::MatrixXd b(g.nodeCount(), 3);
  for (int j = 0; j < g.ny(); ++j)
    for (int i = 0; i < g.nx(); ++i) {
      const int k = g.nodeIndex(i, j);
      const double th = g.x_m()[i] / sp.radius_m;
      const double y = g.y_m()[j] / sp.length_m;
      b(k, 0) = 1.0;
      b(k, 1) = y - 0.4;
      b(k, 2) = std::cos(2.0 * th) * y;
    }
  return b;
}

// Each gap column of `base` (solved from pr) against a central difference of two complete
// solves that move the gap by +-step * b (and the gap rate by +-step * the rate basis, if pr
// has one), warm started from the base and required to keep its cavitation set. Figures
// "gapDerivative.<tag>.<column>", asserted 1e-5 of the column's size.
void expectCompleteSolveDerivatives(const FilmGrid& g, const FilmProblem& pr,
                                    const FilmResult& base, const std::string& tag) {
  const bool withRate = pr.gapRateBasis.size() > 0;
  for (Eigen::Index c = 0; c < pr.gapBasis.cols(); ++c) {
    const double step = 1e-5 * pr.gap_m.minCoeff() / pr.gapBasis.col(c).cwiseAbs().maxCoeff();
    FilmProblem plus = pr, minus = pr;
    for (FilmProblem* q : {&plus, &minus}) {
      q->squeezeBasis.resize(0, 0);
      q->gapBasis.resize(0, 0);
      q->gapRateBasis.resize(0, 0);
    }
    plus.gap_m += step * pr.gapBasis.col(c).array();
    minus.gap_m -= step * pr.gapBasis.col(c).array();
    if (withRate) {
      plus.gapRate_mps += step * pr.gapRateBasis.col(c).array();
      minus.gapRate_mps -= step * pr.gapRateBasis.col(c).array();
    }
    FilmSolver sp1(test::tightOptions(FilmSolverType::FastActiveSet, 1e-12));
    FilmSolver sm1(test::tightOptions(FilmSolverType::FastActiveSet, 1e-12));
    const FilmResult rp = sp1.solve(g, plus, &base.state);
    const FilmResult rm = sm1.solve(g, minus, &base.state);
    ASSERT_TRUE(rp.converged && rm.converged) << tag;
    ASSERT_EQ(rp.state.cavitated, base.state.cavitated) << tag << ": step changed the set";
    ASSERT_EQ(rm.state.cavitated, base.state.cavitated) << tag << ": step changed the set";
    const Eigen::ArrayXd fd = (rp.pressure_Pa() - rm.pressure_Pa()) / (2.0 * step);
    const double size = base.dPressure_dGap.col(c).cwiseAbs().maxCoeff();
    ASSERT_GT(size, 0.0) << tag;
    const double err = (fd - base.dPressure_dGap.col(c).array()).abs().maxCoeff() / size;
    test::reportFigure("gapDerivative." + tag + "." + std::to_string(c), err);
    EXPECT_LT(err, 1e-5) << tag << " column " << c;
  }
}

// The derivative is the one of the complete nonlinear solve for a fixed cavitation set: a
// central difference of two complete solves (1e-12, a step of 1e-5 of the thinnest gap, warm
// started from the base so that they keep its set) agrees to 1e-5 of the column's size (the
// difference quotient loses ~5 digits of the solve tolerance; its truncation is ~1e-10; the
// solver's coloured one-sided perturbations are good to ~2e-6).
// limitedFlux: mass-conserving, FillFractionFlux::LimitedSecondOrder, and a history whose fill
// fraction ramps from 0.4 at the bottom edge to 1 at mid-height, so that the explicit
// correction fluxes are non-zero on most faces (checked on the assembled system): the
// derivative then includes their dependence on the gaps (through the faces' Couette
// contents), with the limiter's factors frozen at the solve's so that the coloured Jacobian
// keeps five-point stencils (FilmSystem::freezeFillLimiter).
void checkAgainstCompleteSolves(CavitationModel model, const std::string& tag,
                                bool limitedFlux = false) {
  const test::SkirtPatch sp;
  const test::GaussianRoughFactors rough(0.8e-6);
  const FilmGrid g = sp.grid(36, 28);
  FilmProblem pr = sp.problem(g, model);
  pr.flowFactors = &rough;
  if (model == CavitationModel::MassConserving)
    test::SkirtPatch::setPartlyFilledHistory(g, 0.6, pr);
  if (limitedFlux) {
    pr.fillFractionFlux = FillFractionFlux::LimitedSecondOrder;
    const int half = g.ny() / 2;
    for (int j = 0; j < g.ny(); ++j)
      for (int i = 0; i < g.nx(); ++i)
        pr.history.last.fillFraction[g.nodeIndex(i, j)] = j >= half ? 1.0 : 0.4 + 0.6 * j / half;
    detail::FilmSystem assembled;
    assembled.assemble(g, pr);
    ASSERT_GT(assembled.fillCorrOut.abs().maxCoeff(), 0.0) << tag;
  }
  pr.squeezeBasis = sp.squeezeBasis(g);  // asked together with the gap columns
  pr.gapBasis = gapShapes(sp, g);
  FilmSolver solver(test::tightOptions(FilmSolverType::FastActiveSet, 1e-12));
  const FilmResult base = solver.solve(g, pr);
  ASSERT_TRUE(base.converged) << tag;
  ASSERT_FALSE(base.derivativesFailed) << tag;
  ASSERT_GT(base.cavitatedNodes, 0) << tag;
  ASSERT_EQ(base.dPressure_dGap.cols(), 3) << tag;
  ASSERT_EQ(base.dPressure_dVelocity.cols(), 2) << tag;

  // The squeeze columns are unchanged by the gap columns asked with them.
  FilmProblem squeezeOnly = pr;
  squeezeOnly.gapBasis.resize(0, 0);
  FilmSolver other(test::tightOptions(FilmSolverType::FastActiveSet, 1e-12));
  const FilmResult s = other.solve(g, squeezeOnly);
  EXPECT_EQ(s.dPressure_dGap.size(), 0) << tag;
  const double squeezeSize = s.dPressure_dVelocity.cwiseAbs().maxCoeff();
  EXPECT_LT((s.dPressure_dVelocity - base.dPressure_dVelocity).cwiseAbs().maxCoeff(),
            1e-6 * squeezeSize)
      << tag;
  expectCompleteSolveDerivatives(g, pr, base, tag);
}

TEST(FilmGapDerivative, MatchesCompleteSolvesReynolds) {
  checkAgainstCompleteSolves(CavitationModel::Reynolds, "reynolds");
}

TEST(FilmGapDerivative, MatchesCompleteSolvesMassConserving) {
  checkAgainstCompleteSolves(CavitationModel::MassConserving, "jfo");
}

TEST(FilmGapDerivative, MatchesCompleteSolvesWithTheLimitedFillFractionFlux) {
  checkAgainstCompleteSolves(CavitationModel::MassConserving, "jfoLimited", true);
}

// A coordinate that moves the gap and, backward Euler over a step dt, its rate
// (FilmProblem::gapRateBasis = gapBasis / dt): the derivative is that of complete solves with
// both moved, gap by step * b and rate by step * b / dt (mass-conserving skirt patch, all
// three shapes, dt = 1e-4 s so that both parts count).
TEST(FilmGapDerivative, WithTheRateMatchesCompleteSolves) {
  const test::SkirtPatch sp;
  const test::GaussianRoughFactors rough(0.8e-6);
  const FilmGrid g = sp.grid(36, 28);
  FilmProblem pr = sp.problem(g, CavitationModel::MassConserving);
  pr.flowFactors = &rough;
  pr.timeStep_s = 1e-4;
  pr.history.last.fillFraction.setOnes(g.nodeCount());
  const double dt_s = 1e-4;
  pr.gapBasis = gapShapes(sp, g);
  pr.gapRateBasis = pr.gapBasis / dt_s;
  FilmSolver solver(test::tightOptions(FilmSolverType::FastActiveSet, 1e-12));
  const FilmResult base = solver.solve(g, pr);
  ASSERT_TRUE(base.converged);
  ASSERT_GT(base.cavitatedNodes, 0);
  ASSERT_EQ(base.dPressure_dGap.cols(), 3);
  expectCompleteSolveDerivatives(g, pr, base, "withRate");
}

TEST(FilmGapDerivative, BadBasisNamesTheMember) {
  const test::SkirtPatch sp;
  const FilmGrid g = sp.grid(12, 10);
  FilmProblem pr = sp.problem(g, CavitationModel::Reynolds);
  FilmSolver solver;
  pr.gapBasis = Eigen::MatrixXd::Zero(g.nodeCount() - 1, 1);
  try {
    (void)solver.solve(g, pr);
    FAIL() << "a gap basis of the wrong size was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("problem.gapBasis"), std::string::npos) << e.what();
  }
  pr.gapBasis = Eigen::MatrixXd::Zero(g.nodeCount(), 1);
  pr.gapBasis(3, 0) = std::nan("");
  EXPECT_THROW((void)solver.solve(g, pr), std::invalid_argument);
  pr.gapBasis(3, 0) = 0.0;
  pr.gapRateBasis = Eigen::MatrixXd::Zero(g.nodeCount(), 2);  // columns differ
  try {
    (void)solver.solve(g, pr);
    FAIL() << "a gap-rate basis with other columns was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("problem.gapRateBasis"), std::string::npos) << e.what();
  }
}

// GapFloor.h: the floored gap's slope and curvature against central differences of the
// formula itself, across the knee (h from deep overlap to far above the floor h_c).
TEST(GapFloor, SlopeAndCurvatureMatchCentralDifferences) {
  const double hc = 5e-8;
  for (const double h : {-1e-6, -1e-7, -2e-8, 0.0, 3e-8, 5e-8, 8e-8, 2e-7, 2e-6}) {
    const FlooredGap f = calcFlooredGap(h, hc);
    const double d = 1e-4 * hc;
    const FlooredGap up = calcFlooredGap(h + d, hc), down = calcFlooredGap(h - d, hc);
    const double slope = (up.film_m - down.film_m) / (2.0 * d);
    const double curvature = (up.slope - down.slope) / (2.0 * d);
    EXPECT_NEAR(f.slope, slope, 1e-7) << "h = " << h;
    EXPECT_NEAR(f.curvature_per_m, curvature, 1e-6 * f.curvature_per_m + 1e-3) << "h = " << h;
    EXPECT_GT(f.curvature_per_m, 0.0);
  }
  // At the knee h = h_c: slope 1/2, curvature 1 / (2 h_c).
  EXPECT_DOUBLE_EQ(calcFlooredGap(hc, hc).slope, 0.5);
  EXPECT_NEAR(calcFlooredGap(hc, hc).curvature_per_m, 0.5 / hc, 1e-12 / hc);
}

}  // namespace
}  // namespace pistondyn::lubrication
