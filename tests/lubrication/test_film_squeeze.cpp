// Squeeze term and squeeze-velocity derivatives: a closed-form squeeze film, and the
// back-substituted derivatives d(load, moments)/d(velocity) against central finite differences
// of the full solve.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

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

// Central difference of (load, first moments) along squeeze column `column` of pr, from two
// complete solves without derivatives, and the cavitated counts of both.
struct CentralDifference {
  Eigen::Vector3d value;
  int cavitatedPlus, cavitatedMinus;
};
CentralDifference centralDifference(const FilmGrid& g, const FilmProblem& pr, int column,
                                    double step, FilmSolverType type) {
  FilmProblem plus = pr, minus = pr;
  plus.squeezeBasis.resize(0, 0);
  minus.squeezeBasis.resize(0, 0);
  plus.gapRate_mps += step * pr.squeezeBasis.col(column).array();
  minus.gapRate_mps -= step * pr.squeezeBasis.col(column).array();
  const Derivs dp = solveWithDerivatives(g, plus, type);
  const Derivs dm = solveWithDerivatives(g, minus, type);
  return {(dp.value - dm.value) / (2.0 * step), dp.cavitated, dm.cavitated};
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
    test::SkirtPatch::setPartlyFilledHistory(g, 0.6, pr);
  }
  pr.squeezeBasis = sp.squeezeBasis(g);
  const Derivs base = solveWithDerivatives(g, pr, type);
  if (model != CavitationModel::None) {
    EXPECT_GT(base.cavitated, 0) << tag;
  }
  ASSERT_GT(base.deriv.cwiseAbs().maxCoeff(), 0.0) << tag;
  const Eigen::Vector2d step(1e-6, 1e-4);  // lateral [m/s], tilt rate [rad/s]
  for (int m = 0; m < 2; ++m) {
    const CentralDifference cd = centralDifference(g, pr, m, step[m], type);
    ASSERT_EQ(cd.cavitatedPlus, base.cavitated) << tag << ": step changed the cavitation set";
    ASSERT_EQ(cd.cavitatedMinus, base.cavitated) << tag << ": step changed the cavitation set";
    const Eigen::Vector3d& fd = cd.value;
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

// Many squeeze columns from a warm start (an elastic skirt asks for one per deformation mode):
// the solver may then factorise the current Jacobian and back-substitute the remaining columns
// instead of a Krylov solve per column. Whichever path it takes, every column must still be the
// derivative of the full solve: central differences for the first, a middle and the last column,
// and the first two columns equal to those of the same warm step asked with two columns only.
void checkManyColumnsFromWarmStart(CavitationModel model, const std::string& tag) {
  const test::SkirtPatch sp;
  const test::GaussianRoughFactors rough(0.8e-6);
  const FilmGrid g = sp.grid(36, 28);  // below kMultigridMinNodes: the sparse-direct path
  auto problemAt = [&](double lateral_m, int columns) {
    test::SkirtPatch at = sp;
    at.lateral_m = lateral_m;
    FilmProblem pr = at.problem(g, model);
    pr.flowFactors = &rough;
    pr.momentPoint_m = {0.0, sp.pinHeight_m};
    if (model == CavitationModel::MassConserving) {
      pr.timeStep_s = 1e-4;
      pr.history.last.fillFraction.setOnes(g.nodeCount());
    }
    const Eigen::MatrixXd pose = sp.squeezeBasis(g);
    pr.squeezeBasis.resize(g.nodeCount(), columns);
    for (int c = 0; c < columns; ++c)
      for (int j = 0; j < g.ny(); ++j)
        for (int i = 0; i < g.nx(); ++i) {
          const int k = g.nodeIndex(i, j);
          const double th = g.x_m()[i] / sp.radius_m;
          const double y = g.y_m()[j] / sp.length_m;
          // Mode-like shapes: circumferential order c / 2, axial order c % 3.
          pr.squeezeBasis(k, c) = c < 2 ? pose(k, c)
                                        : -std::cos(0.5 * (c / 2) * th) * std::pow(y, c % 3);
        }
    return pr;
  };
  const int many = 12;
  auto warmRun = [&](const FilmProblem& pr) {
    FilmSolver solver(test::tightOptions(FilmSolverType::FastActiveSet, 1e-12));
    const FilmResult first = solver.solve(g, problemAt(13.9e-6, pr.squeezeBasis.cols()));
    FilmResult r = solver.solve(g, pr, &first.state);
    EXPECT_TRUE(r.converged) << tag;
    return r;
  };
  const FilmProblem pr = problemAt(14.0e-6, many);
  const FilmResult base = warmRun(pr);
  const FilmResult two = warmRun(problemAt(14.0e-6, 2));
  ASSERT_EQ(base.dLoad_dVelocity.size(), many) << tag;
  for (int c = 0; c < 2; ++c)
    EXPECT_NEAR(base.dLoad_dVelocity[c], two.dLoad_dVelocity[c],
                1e-9 * std::abs(two.dLoad_dVelocity[c]))
        << tag << " column " << c;
  // The step is small (13.9 -> 14 um): two columns stay on the lagged factorisation; twelve
  // make the current Jacobian's factorisation the cheaper path, so that path is under test.
  EXPECT_EQ(two.factorisations, 0) << tag;
  EXPECT_EQ(base.factorisations, 1) << tag;
  for (const int c : {0, many / 2, many - 1}) {
    const CentralDifference cd = centralDifference(g, pr, c, 1e-6, FilmSolverType::FastActiveSet);
    ASSERT_EQ(cd.cavitatedPlus, cd.cavitatedMinus) << tag << ": step changed the cavitation set";
    const double size = base.dLoad_dVelocity.cwiseAbs().maxCoeff();
    const double err = std::abs(cd.value[0] - base.dLoad_dVelocity[c]) / size;
    test::reportFigure("squeezeDerivative.manyColumns." + tag + "." + std::to_string(c), err);
    EXPECT_LT(err, 1e-6) << tag << " column " << c;
  }
}

TEST(FilmSqueeze, ManyColumnsFromAWarmStartMatchFiniteDifferences) {
  checkManyColumnsFromWarmStart(CavitationModel::Reynolds, "reynolds");
  checkManyColumnsFromWarmStart(CavitationModel::MassConserving, "jfo");
}


// A thin-film patch much smaller than its film region: an elliptic paraboloid gap
// h = h0 + x^2/(2 Rx) + y^2/(2 Ry) approaching a plane at V (dh/dt = -V). p = A / h^2 solves
// div(h^3 grad p) = 12 eta dh/dt exactly when A = 6 eta V / (1/Rx + 1/Ry) (grad p = -2 A grad h
// / h^3, and the Laplacian of h is 1/Rx + 1/Ry), so over the whole plane
//   F = integral A / h^2 dA = 12 pi eta V sqrt(Rx Ry) / ((1/Rx + 1/Ry) h0)
// (substitute x = sqrt(2 Rx) u, y = sqrt(2 Ry) v: integral du dv / (h0 + u^2 + v^2)^2 = pi / h0).
// For a circle it is the classical 6 pi eta R^2 V / h0 of a sphere squeezing a plane. The square
// +-L here cuts off about h0 / h(L) = (a / L)^2 = 1.3e-3 of it (a = sqrt(2 Rx h0), the patch
// radius). The patch spans 1.1 (65 nodes) and 2.3 (129 nodes) cells of radius: the face values
// of a linear gap (FaceValues::LinearGap) give +4.7 % and -0.12 %; the nodal means (the
// default) -41 % and -17 % (lubrication/README.md).
TEST(FilmSqueeze, SmallParaboloidPatchMatchesTheClosedFormOnACoarseGrid) {
  const double eta = 0.01, V = 1e-3, h0 = 1e-6, Rx = 1.0, Ry = 0.5, L = 0.04;
  const double closed = 12.0 * test::kPi * eta * V * std::sqrt(Rx * Ry) / ((1.0 / Rx + 1.0 / Ry) * h0);
  std::vector<double> linear, nodal;
  for (int nodes : {65, 129}) {
    const FilmGrid g = FilmGrid::uniform(nodes, 2.0 * L, nodes, 2.0 * L);
    FilmProblem pr;
    pr.gap_m.resize(g.nodeCount());
    pr.gapRate_mps.setConstant(g.nodeCount(), -V);
    for (int j = 0; j < nodes; ++j) {
      for (int i = 0; i < nodes; ++i) {
        const double x = g.x_m()[i] - L, y = g.y_m()[j] - L;
        pr.gap_m[g.nodeIndex(i, j)] = h0 + x * x / (2.0 * Rx) + y * y / (2.0 * Ry);
      }
    }
    pr.viscosity_Pas = eta;
    pr.cavitation = CavitationModel::Reynolds;
    for (FaceValues faces : {FaceValues::LinearGap, FaceValues::NodalMean}) {
      pr.faces = faces;
      FilmSolver solver(test::tightOptions(FilmSolverType::FastActiveSet, 1e-12));
      const FilmResult r = solver.solve(g, pr);
      ASSERT_TRUE(r.converged);
      const bool isLinear = faces == FaceValues::LinearGap;
      (isLinear ? linear : nodal).push_back(r.load_N / closed - 1.0);
      test::reportFigure("paraboloidSqueeze.nodes" + std::to_string(nodes) +
                             (isLinear ? ".linearGapFaces" : ".nodalMeanFaces") + ".loadRelError",
                         (isLinear ? linear : nodal).back());
    }
  }
  EXPECT_LT(std::abs(linear[0]), 0.06);  // the patch within about one cell
  EXPECT_LT(std::abs(linear[1]), 5e-3);  // two cells: within 4x the cut-off's share
  // The nodal means converge too, from far below (what LinearGap is for).
  EXPECT_LT(nodal[0], -0.2);
  EXPECT_LT(std::abs(nodal[1]), std::abs(nodal[0]));
}

}  // namespace
}  // namespace pistondyn::lubrication
