// Squeeze term and squeeze-velocity derivatives: a closed-form squeeze film, and the
// back-substituted derivatives d(load, moments)/d(velocity) against central finite differences
// of the full solve.
#include <gtest/gtest.h>

#include <cmath>

#include "test_film_support.h"

namespace pistondyn::lubrication {
namespace {

// Infinitely long parallel plates of length B approaching at speed v (dh/dt = -v), ambient
// pressure at both ends: (h^3/12 eta) p'' = dh/dt gives p = 6 eta v y (B - y) / h^3 and a load
// per unit length eta v B^3 / h^3 (Hamrock et al., ch. 14), linear in v, so dW'/dv = W'/v.
// The three-point balance is exact for this quadratic pressure, so the nodal pressures are
// exact and the trapezoid load is the closed form times (1 - 1/n^2) (n intervals: the chords of
// the concave parabola lie below it, int - T = B h^2 (-p'')/12).
TEST(FilmSqueeze, ParallelPlatesMatchClosedFormAndItsDerivative) {
  const double eta = 0.02, B = 0.01, h = 10e-6, v = 1e-3, width = 1e-3;
  const int ny = 41;
  const FilmGrid g = FilmGrid::uniform(3, width, ny, B, true);
  FilmProblem pr;
  pr.gap_m.setConstant(g.nodeCount(), h);
  pr.gapRate_mps.setConstant(g.nodeCount(), -v);
  pr.squeezeBasis = Eigen::MatrixXd::Constant(g.nodeCount(), 1, -1.0);  // d(dh/dt)/dv
  pr.viscosity_Pas = eta;
  pr.cavitation = CavitationModel::Reynolds;
  const double n = ny - 1;
  const double trapezoidLoad = eta * v * B * B * B / (h * h * h) * (1.0 - 1.0 / (n * n));
  for (FilmSolverType type :
       {FilmSolverType::FastActiveSet, FilmSolverType::ReferenceGaussSeidel}) {
    FilmSolver solver(test::tightOptions(type, 1e-12));
    const FilmResult r = solver.solve(g, pr);
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.load_N / width / trapezoidLoad, 1.0, 1e-9);
    EXPECT_NEAR(r.dLoad_dVelocity[0] / width / (trapezoidLoad / v), 1.0, 1e-9);
    for (int j = 0; j < ny; ++j) {
      const double y = g.y_m()[j];
      EXPECT_NEAR(r.pressure_Pa()[g.nodeIndex(1, j)], 6.0 * eta * v * y * (B - y) / (h * h * h),
                  1e-9 * 6.0 * eta * v * B * B / (h * h * h));
    }
  }
}

struct Derivs {
  Eigen::Vector3d value;              // load, first moments x, y
  Eigen::Matrix<double, 3, 2> deriv;  // d/d(lateral velocity), d/d(tilt rate)
  int cavitated;
};

Derivs solveWithDerivatives(const FilmGrid& g, const FilmProblem& pr, FilmSolverType type,
                            const FilmState* warm = nullptr) {
  FilmSolver solver(test::tightOptions(type, 1e-12));
  const FilmResult r = solver.solve(g, pr, warm);
  EXPECT_TRUE(r.converged);
  Derivs d;
  d.value = {r.load_N, r.firstMomentX_Nm, r.firstMomentY_Nm};
  d.cavitated = r.cavitatedNodes;
  if (r.dLoad_dVelocity.size() == 2) {
    d.deriv.row(0) = r.dLoad_dVelocity.transpose();
    d.deriv.row(1) = r.dFirstMomentX_dVelocity.transpose();
    d.deriv.row(2) = r.dFirstMomentY_dVelocity.transpose();
  }
  return d;
}

// For a fixed cavitation set the pressure is linear in the squeeze velocities, so a central
// difference with a step small enough to keep the set is exact up to the solve tolerance. The
// derivatives come from back-substitution with the final factorisation; the finite differences
// from two complete solves. Agreement to 1e-6 of the derivative's size (the solves are converged
// to 1e-12, the difference quotient loses ~4 digits).
void checkDerivatives(CavitationModel model, FilmSolverType type, const std::string& tag) {
  const test::SkirtPatch sp;
  const test::GaussianRoughFactors rough(0.8e-6);
  const FilmGrid g = sp.grid(36, 28);
  FilmProblem pr = sp.problem(g, model);
  pr.flowFactors = &rough;
  pr.momentPoint_m = {0.0, sp.pinHeight_m};
  if (model == CavitationModel::MassConserving) {
    // Full film in the converging upper half, partly filled history in the diverging lower half.
    pr.timeStep_s = 1e-4;
    pr.previousFillFraction.setOnes(g.nodeCount());
    for (int j = 0; j < g.ny() / 2; ++j)
      for (int i = 0; i < g.nx(); ++i)
        pr.previousFillFraction[g.nodeIndex(i, j)] = 0.6;
  }
  pr.squeezeBasis = sp.squeezeBasis(g);
  const Derivs base = solveWithDerivatives(g, pr, type);
  if (model != CavitationModel::None) {
    EXPECT_GT(base.cavitated, 0) << tag;
  }
  ASSERT_GT(base.deriv.cwiseAbs().maxCoeff(), 0.0) << tag;
  const Eigen::Vector2d step(1e-6, 1e-4);  // lateral [m/s], tilt rate [rad/s]
  for (int m = 0; m < 2; ++m) {
    FilmProblem plus = pr, minus = pr;
    plus.squeezeBasis.resize(0, 0);
    minus.squeezeBasis.resize(0, 0);
    plus.gapRate_mps += step[m] * pr.squeezeBasis.col(m).array();
    minus.gapRate_mps -= step[m] * pr.squeezeBasis.col(m).array();
    const Derivs dp = solveWithDerivatives(g, plus, type);
    const Derivs dm = solveWithDerivatives(g, minus, type);
    ASSERT_EQ(dp.cavitated, base.cavitated) << tag << ": step changed the cavitation set";
    ASSERT_EQ(dm.cavitated, base.cavitated) << tag << ": step changed the cavitation set";
    const Eigen::Vector3d fd = (dp.value - dm.value) / (2.0 * step[m]);
    const double size = base.deriv.col(m).cwiseAbs().maxCoeff();
    const double err = (fd - base.deriv.col(m)).cwiseAbs().maxCoeff() / size;
    test::reportFigure("squeezeDerivative." + tag + "." + std::to_string(m), err);
    EXPECT_LT(err, 1e-6) << tag << " velocity " << m;
  }
}

TEST(FilmSqueeze, DerivativesMatchFiniteDifferencesReynolds) {
  checkDerivatives(CavitationModel::Reynolds, FilmSolverType::FastActiveSet, "reynolds.fast");
  checkDerivatives(CavitationModel::Reynolds, FilmSolverType::ReferenceGaussSeidel,
                   "reynolds.reference");
}

TEST(FilmSqueeze, DerivativesMatchFiniteDifferencesFullSommerfeld) {
  checkDerivatives(CavitationModel::None, FilmSolverType::FastActiveSet, "none.fast");
}

TEST(FilmSqueeze, DerivativesMatchFiniteDifferencesMassConserving) {
  checkDerivatives(CavitationModel::MassConserving, FilmSolverType::FastActiveSet, "jfo.fast");
  checkDerivatives(CavitationModel::MassConserving, FilmSolverType::ReferenceGaussSeidel,
                   "jfo.reference");
}

}  // namespace
}  // namespace pistondyn::lubrication
