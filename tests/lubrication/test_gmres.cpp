// lubrication::Gmres (Gmres.h) against independent references: Eigen's dense LU of the same
// small nonsymmetric systems, the Krylov property (convergence within the degree of the
// matrix's minimal polynomial, at most n), the true residual of the restarted max-norm stop
// computed here from the matrix, and the allocation counter of tests/support (no allocation
// per solve). Its own executable: the counter interposes malloc.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "AllocationCounter.h"
#include "pistondyn/lubrication/Gmres.h"

namespace pistondyn::lubrication {
namespace {

// A deterministic nonsymmetric n x n matrix: a diagonal from 2 to 4 plus an unsymmetric
// coupling (forward and backward neighbours of different weights, and a dense part of size
// 0.3 / n per entry), well conditioned and far from normal.
Eigen::MatrixXd testMatrix(int n) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    a(i, i) = 2.0 + 2.0 * i / (n - 1);
    if (i + 1 < n)
      a(i, i + 1) = -0.9;
    if (i > 0)
      a(i, i - 1) = 0.4;
    for (int j = 0; j < n; ++j)
      a(i, j) += 0.3 / n * std::sin(1.0 + 3.0 * i + 7.0 * j);
  }
  return a;
}

Eigen::VectorXd testRhs(int n) {
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i)
    b[i] = std::cos(0.5 + 1.3 * i);
  return b;
}

// y = A x, always given.
auto productWith(const Eigen::MatrixXd& a) {
  return [&a](const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& y) {
    y.noalias() = a * x;
    return true;
  };
}

// Jacobi: z = D^-1 r.
auto jacobiOf(const Eigen::MatrixXd& a) {
  return [&a](const Eigen::Ref<const Eigen::VectorXd>& r, Eigen::Ref<Eigen::VectorXd> z) {
    z = r.cwiseQuotient(a.diagonal());
  };
}

auto identity() {
  return [](const Eigen::Ref<const Eigen::VectorXd>& r, Eigen::Ref<Eigen::VectorXd> z) { z = r; };
}

// Relative error of x against the dense LU solution.
double errorAgainstLu(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                      const Eigen::VectorXd& x) {
  const Eigen::VectorXd exact = a.partialPivLu().solve(b);
  return (x - exact).lpNorm<Eigen::Infinity>() / exact.lpNorm<Eigen::Infinity>();
}

// Without a restart GMRES finds the exact solution within n steps (the Krylov space is then
// the whole space). The tolerance 1e-12 on the residual's reduction and 1e-10 on the solution
// leave room for the round-off of modified Gram-Schmidt on a matrix of condition ~10.
TEST(Gmres, MatchesDenseLuWithinNIterations) {
  const int n = 12;
  const Eigen::MatrixXd a = testMatrix(n);
  const Eigen::VectorXd b = testRhs(n);
  for (const bool flexible : {false, true}) {
    for (const bool jacobi : {false, true}) {
      Gmres gmres(GmresOptions{n, n, flexible, false}, n);
      GmresRelativeReduction stop(1e-12);
      const GmresReport r = jacobi ? gmres.solve(productWith(a), jacobiOf(a), b, stop)
                                   : gmres.solve(productWith(a), identity(), b, stop);
      EXPECT_TRUE(r.converged) << flexible << jacobi;
      EXPECT_LE(r.iterations, n);
      EXPECT_EQ(r.lastCycleDirections, r.iterations);
      EXPECT_LE(errorAgainstLu(a, b, gmres.solution()), 1e-10) << flexible << jacobi;
    }
  }
}

// A = I + u v^T + w z^T has the minimal polynomial (t - 1) q(t) with deg q <= 2: GMRES
// converges in at most 3 steps whatever n is.
TEST(Gmres, ConvergesWithinTheMinimalPolynomialsDegree) {
  const int n = 40;
  Eigen::VectorXd u(n), v(n), w(n), z(n);
  for (int i = 0; i < n; ++i) {
    u[i] = std::sin(0.3 * i);
    v[i] = std::cos(0.7 * i) / n;
    w[i] = 1.0 / (1.0 + i);
    z[i] = std::sin(1.1 * i + 0.2) / n;
  }
  const Eigen::MatrixXd a = Eigen::MatrixXd::Identity(n, n) + u * v.transpose() + w * z.transpose();
  const Eigen::VectorXd b = testRhs(n);
  Gmres gmres(GmresOptions{n, n, false, false}, n);
  GmresRelativeReduction stop(1e-13);
  const GmresReport r = gmres.solve(productWith(a), identity(), b, stop);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 3);
  EXPECT_LE(errorAgainstLu(a, b, gmres.solution()), 1e-11);
}

// Restarted, stopping on the max norm: with 3 directions per cycle the solve needs restarts;
// it ends only when the true residual b - A x, recomputed here from the matrix, meets the
// target in the max norm.
TEST(Gmres, RestartedMaxNormStopMeetsTheTargetOnTheTrueResidual) {
  const int n = 30;
  const Eigen::MatrixXd a = testMatrix(n);
  const Eigen::VectorXd b = testRhs(n);
  const double target = 1e-9 * b.lpNorm<Eigen::Infinity>();
  for (const bool flexible : {false, true}) {
    Gmres gmres(GmresOptions{3, 300, flexible, false}, n);
    GmresMaxNormTarget stop(target);
    const GmresReport r = gmres.solve(productWith(a), jacobiOf(a), b, stop);
    EXPECT_TRUE(r.converged) << flexible;
    EXPECT_GT(r.iterations, 3) << flexible;  // it did restart
    EXPECT_LE((b - a * gmres.solution()).lpNorm<Eigen::Infinity>(), target) << flexible;
  }
  // The same cap of iterations with too few of them: no convergence is reported.
  Gmres capped(GmresOptions{3, 4, false, false}, n);
  GmresMaxNormTarget stop(target);
  const GmresReport r = capped.solve(productWith(a), jacobiOf(a), b, stop);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 4);
}

// GmresRelativeReduction restarts from the true residual too (it is only not checked); the
// reduction it reaches is that of the last cycle's estimate, which the true residual confirms.
TEST(Gmres, RestartedRelativeReduction) {
  const int n = 30;
  const Eigen::MatrixXd a = testMatrix(n);
  const Eigen::VectorXd b = testRhs(n);
  Gmres gmres(GmresOptions{4, 200, true, false}, n);
  GmresRelativeReduction stop(1e-8);
  const GmresReport r = gmres.solve(productWith(a), jacobiOf(a), b, stop);
  EXPECT_TRUE(r.converged);
  EXPECT_GT(r.iterations, 4);
  // The estimate is exact in exact arithmetic: 1.01 allows for round-off.
  EXPECT_LE((b - a * gmres.solution()).norm(), 1.01e-8 * b.norm());
}

TEST(Gmres, ZeroRightHandSide) {
  const int n = 8;
  const Eigen::MatrixXd a = testMatrix(n);
  Gmres gmres(GmresOptions{n, n, false, false}, n);
  GmresMaxNormTarget maxNorm(0.0);
  const GmresReport r = gmres.solve(productWith(a), identity(), Eigen::VectorXd::Zero(n), maxNorm);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(gmres.solution().lpNorm<Eigen::Infinity>(), 0.0);
}

// An operator that refuses after two products (a budget of evaluations) ends the solve with the
// two directions it has: their least-squares combination, which is the exact minimiser of
// |b - A x|_2 over span{b, A b} (identity preconditioner), computed here by a dense QR.
TEST(Gmres, RefusedProductEndsTheSolveWithTheDirectionsSoFar) {
  const int n = 10;
  const Eigen::MatrixXd a = testMatrix(n);
  const Eigen::VectorXd b = testRhs(n);
  int products = 0;
  const auto budget = [&](const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& y) {
    if (products == 2)
      return false;
    ++products;
    y.noalias() = a * x;
    return true;
  };
  Gmres gmres(GmresOptions{n, n, true, true}, n);
  GmresRelativeReduction stop(1e-14);
  const GmresReport r = gmres.solve(budget, identity(), b, stop);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.lastCycleDirections, 2);
  Eigen::MatrixXd krylov(n, 2);
  krylov.col(0) = b;
  krylov.col(1) = a * b;
  const Eigen::VectorXd c = (a * krylov).colPivHouseholderQr().solve(b);
  const Eigen::VectorXd best = krylov * c;
  EXPECT_LE((gmres.solution() - best).lpNorm<Eigen::Infinity>(),
            1e-12 * best.lpNorm<Eigen::Infinity>());
}

// A product that adds nothing (A z = 0: a degenerate rotation) is left out when asked: no
// direction, no convergence, x = 0.
TEST(Gmres, DegenerateDirectionIsLeftOut) {
  const int n = 6;
  const auto zero = [](const Eigen::Ref<const Eigen::VectorXd>&, Eigen::VectorXd& y) {
    y.setZero();
    return true;
  };
  Gmres gmres(GmresOptions{n, n, true, true}, n);
  GmresRelativeReduction stop(0.1);
  const GmresReport r = gmres.solve(zero, identity(), testRhs(n), stop);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.lastCycleDirections, 0);
  EXPECT_EQ(gmres.solution().lpNorm<Eigen::Infinity>(), 0.0);
}

// CONVENTIONS.md: the workspace is sized once; a solve allocates nothing (both forms, with
// restarts, operator and preconditioner that allocate nothing themselves).
TEST(Gmres, SolveAllocatesNothing) {
  const int n = 30;
  const Eigen::MatrixXd a = testMatrix(n);
  const Eigen::VectorXd b = testRhs(n);
  for (const bool flexible : {false, true}) {
    Gmres gmres(GmresOptions{3, 300, flexible, false}, n);
    GmresMaxNormTarget stop(1e-9);
    GmresReport r;
    const long count = pistondyn::test::allocationsDuring(
        [&] { r = gmres.solve(productWith(a), jacobiOf(a), b, stop); });
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(count, 0) << flexible;
  }
}

}  // namespace
}  // namespace pistondyn::lubrication
