// SkirtSideGrid: node layout, the exact load weights and the loads on the piston.
// References: Gauss-Legendre quadrature of the bilinear hats times the weight functions (written
// here), closed-form integrals over the side of uniform and linear tractions, the symmetry of
// a thrust-side pressure, and the 3-D resultant of the traction vector integrated directly
// (r x t with Eigen's cross product, no hand-derived moment arms).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include <Eigen/Geometry>

#include "SkirtTestSupport.h"
#include "pistondyn/skirt/SkirtSideGrid.h"

namespace ps = pistondyn::skirt;
using ps::test::kPi;

namespace {

TEST(SkirtSideGrid, NodesFilmGridAndCylinderGridAgree) {
  for (ps::SkirtSide side : {ps::SkirtSide::Thrust, ps::SkirtSide::AntiThrust}) {
    ps::SkirtSideGridParameters p = ps::test::thrustSide(9, 7);
    p.side = side;
    p.axialClustering = 1.5;
    const ps::SkirtSideGrid g(p);
    const double c = side == ps::SkirtSide::Thrust ? 0.0 : kPi;
    EXPECT_EQ(g.getCentreAngle_rad(), c);
    EXPECT_NEAR(g.getPhiNodes_rad()[0], c - p.arcWidth_rad / 2, 1e-15);
    EXPECT_NEAR(g.getPhiNodes_rad()[8], c + p.arcWidth_rad / 2, 1e-15);
    EXPECT_NEAR(g.getSkirtBottomHeight_m(), -0.025, 1e-17);
    EXPECT_EQ(g.getSkirtTopHeight_m(), 0.015);
    // clustered: the first cell is the smallest
    EXPECT_LT(g.getYNodes_m()[1] - g.getYNodes_m()[0], g.getYNodes_m()[4] - g.getYNodes_m()[3]);
    const auto& fg = g.getFilmGrid();
    const auto& cg = g.getCylinderGrid();
    ASSERT_EQ(fg.nx(), 9);
    ASSERT_EQ(fg.ny(), 7);
    EXPECT_FALSE(fg.isPeriodicX());
    EXPECT_EQ(cg.radius_m(), p.radius_m);
    EXPECT_FALSE(cg.isClosed());
    for (int i = 0; i < 9; ++i) {
      EXPECT_NEAR(fg.x_m()[i], p.radius_m * (g.getPhiNodes_rad()[i] - c), 1e-17);
      EXPECT_EQ(cg.phi_rad()[i], g.getPhiNodes_rad()[i]);
      // exactly symmetric offsets about the centre line
      EXPECT_EQ(fg.x_m()[i], -fg.x_m()[8 - i]);
    }
    for (int j = 0; j < 7; ++j) {
      EXPECT_EQ(fg.y_m()[j], g.getYNodes_m()[j]);
      EXPECT_EQ(cg.y_m()[j], g.getYNodes_m()[j]);
    }
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 9; ++i) {
        const int k = i + 9 * j;
        EXPECT_EQ(g.nodeIndex(i, j), k);
        EXPECT_EQ(fg.nodeIndex(i, j), k);
        EXPECT_EQ(cg.index(i, j), k);
        EXPECT_EQ(g.getNodePhi_rad()[k], g.getPhiNodes_rad()[i]);
        EXPECT_EQ(g.getNodeY_m()[k], g.getYNodes_m()[j]);
        EXPECT_EQ(g.getNodeCosPhi()[k], std::cos(g.getPhiNodes_rad()[i]));
        EXPECT_EQ(g.getNodeSinPhi()[k], std::sin(g.getPhiNodes_rad()[i]));
      }
  }
}

// Reference weight of node k: integral of N_k f over its support cells, 12 x 12 Gauss points per
// cell (hat x cos/sin on cells up to 1.5 rad: error < 1e-20 relative), and the integral of
// N_k |f| as the scale.
struct Reference {
  double value = 0.0, scale = 0.0;
};
Reference referenceWeight(const ps::SkirtSideGrid& g, int i, int j,
                          const std::function<double(double, double)>& f) {
  const auto [gx, gw] = ps::test::gaussLegendre(12);
  const Eigen::VectorXd& phi = g.getPhiNodes_rad();
  const Eigen::VectorXd& y = g.getYNodes_m();
  Reference r;
  for (int ci = std::max(i - 1, 0); ci <= std::min(i, g.nPhi() - 2); ++ci)
    for (int cj = std::max(j - 1, 0); cj <= std::min(j, g.nY() - 2); ++cj) {
      const double a = phi[ci], b = phi[ci + 1], c = y[cj], d = y[cj + 1];
      for (int p = 0; p < 12; ++p)
        for (int q = 0; q < 12; ++q) {
          const double pp = 0.5 * (a + b) + 0.5 * (b - a) * gx[p];
          const double yy = 0.5 * (c + d) + 0.5 * (d - c) * gx[q];
          const double w = gw[p] * gw[q] * 0.25 * (b - a) * (d - c) * g.getRadius_m();
          const double n = ps::test::hat(phi, i, pp) * ps::test::hat(y, j, yy);
          r.value += w * n * f(pp, yy);
          r.scale += w * n * std::abs(f(pp, yy));
        }
    }
  return r;
}

TEST(SkirtSideGrid, WeightsEqualGaussQuadratureOfTheHats) {
  struct Case {
    ps::SkirtSide side;
    double arc;
    int nPhi, nY;
    double clustering, circumferentialClustering = 0.0;
  };
  // fine (small half-widths: series branch), coarse and wide (closed-form branch), anti-thrust;
  // centre-clustered angles (unequal cells around phi)
  for (const Case& cs : {Case{ps::SkirtSide::Thrust, kPi / 3, 24, 9, 0.0},
                         Case{ps::SkirtSide::AntiThrust, 1.2, 17, 6, 2.0},
                         Case{ps::SkirtSide::Thrust, 3.0, 3, 3, 0.0},
                         Case{ps::SkirtSide::AntiThrust, 2.9, 4, 5, 0.5},
                         Case{ps::SkirtSide::Thrust, 1.4, 33, 7, 0.0, 2.0},
                         Case{ps::SkirtSide::AntiThrust, 2.5, 8, 5, 1.0, 3.0}}) {
    ps::SkirtSideGridParameters p = ps::test::thrustSide(cs.nPhi, cs.nY);
    p.side = cs.side;
    p.arcWidth_rad = cs.arc;
    p.axialClustering = cs.clustering;
    p.circumferentialClustering = cs.circumferentialClustering;
    const ps::SkirtSideGrid g(p);
    const std::vector<std::pair<const Eigen::ArrayXd*, std::function<double(double, double)>>>
        families = {
            {&g.getAreaWeights_m2(), [](double, double) { return 1.0; }},
            {&g.getCosPhiWeights_m2(), [](double ph, double) { return std::cos(ph); }},
            {&g.getSinPhiWeights_m2(), [](double ph, double) { return std::sin(ph); }},
            {&g.getYCosPhiWeights_m3(), [](double ph, double yy) { return yy * std::cos(ph); }},
            {&g.getYSinPhiWeights_m3(), [](double ph, double yy) { return yy * std::sin(ph); }},
        };
    double worst = 0.0;
    for (const auto& [weights, f] : families)
      for (int j = 0; j < g.nY(); ++j)
        for (int i = 0; i < g.nPhi(); ++i) {
          const Reference r = referenceWeight(g, i, j, f);
          const double rel = std::abs((*weights)[g.nodeIndex(i, j)] - r.value) / r.scale;
          worst = std::max(worst, rel);
          EXPECT_LE(rel, 1e-13) << "node " << i << ", " << j;
        }
    std::printf("[ weights  ] arc %.2f rad, %d x %d: worst relative deviation %.2e\n", cs.arc,
                cs.nPhi, cs.nY, worst);
  }
}

// Circumferential clustering: phi = (Phi/2) sinh(b xi) / sinh(b) of xi uniform in [-1, 1]
// (closed form here), exactly antisymmetric about the centre line, the arc's ends kept; b = 2
// gives b / sinh(b) = 0.551 of the uniform spacing at the centre line.
TEST(SkirtSideGrid, CircumferentialClusteringFollowsTheSinhMapAndKeepsTheSymmetry) {
  for (ps::SkirtSide side : {ps::SkirtSide::Thrust, ps::SkirtSide::AntiThrust}) {
    ps::SkirtSideGridParameters p = ps::test::thrustSide(65, 5);
    p.side = side;
    p.arcWidth_rad = 1.4;
    p.circumferentialClustering = 2.0;
    const ps::SkirtSideGrid g(p);
    const Eigen::VectorXd& phi = g.getPhiNodes_rad();
    const double c = g.getCentreAngle_rad();
    for (int i = 0; i < 65; ++i) {
      const double xi = (2.0 * i - 64.0) / 64.0;
      EXPECT_NEAR(phi[i] - c, 0.7 * std::sinh(2.0 * xi) / std::sinh(2.0), 1e-15) << i;
      EXPECT_EQ(phi[i] - c, -(phi[64 - i] - c)) << i;
    }
    EXPECT_EQ(phi[32], c);
    // Cell sizes against the map's slope at the cells' middles: 0.551 and 2.01 x uniform.
    const double uniform = 1.4 / 64.0;
    auto slope = [](double xi) { return 2.0 * std::cosh(2.0 * xi) / std::sinh(2.0); };
    EXPECT_NEAR((phi[33] - phi[32]) / uniform, slope(1.0 / 64.0), 1e-4);
    EXPECT_NEAR((phi[64] - phi[63]) / uniform, slope(63.0 / 64.0), 1e-3);
  }
}

TEST(SkirtSideGrid, UniformPressureGivesTheClosedFormLoads) {
  for (ps::SkirtSide side : {ps::SkirtSide::Thrust, ps::SkirtSide::AntiThrust}) {
    ps::SkirtSideGridParameters p = ps::test::thrustSide(33, 21);
    p.side = side;
    p.arcWidth_rad = 1.1;
    p.axialClustering = 1.0;
    const ps::SkirtSideGrid g(p);
    const double pr = 2.5e5, R = p.radius_m;
    const double f1 = g.getPhiNodes_rad()[0], f2 = g.getPhiNodes_rad()[32];
    const double y1 = g.getSkirtBottomHeight_m(), y2 = g.getSkirtTopHeight_m(), L = y2 - y1;
    const ps::PistonLoads l = g.calcLoadsOnPiston(Eigen::ArrayXd::Constant(g.nodeCount(), pr));
    const double scale = pr * R * p.arcWidth_rad * L;  // |p| times the area
    // Integrals of -p e_r and of r x (-p e_r) over the side (SkirtSideGrid.h); the bilinear
    // interpolant of a constant is the constant, so they are exact up to rounding.
    EXPECT_NEAR(l.force_N.x(), -pr * R * L * (std::sin(f2) - std::sin(f1)), 1e-14 * scale);
    EXPECT_NEAR(l.force_N.y(), 0.0, 1e-14 * scale);
    EXPECT_NEAR(l.force_N.z(), pr * R * L * (std::cos(f2) - std::cos(f1)), 1e-14 * scale);
    const double ym = 0.5 * (y2 * y2 - y1 * y1);
    EXPECT_NEAR(l.moment_Nm.x(), -pr * R * ym * (std::cos(f1) - std::cos(f2)), 1e-14 * scale * L);
    EXPECT_NEAR(l.moment_Nm.y(), 0.0, 1e-14 * scale * L);
    EXPECT_NEAR(l.moment_Nm.z(), pr * R * ym * (std::sin(f2) - std::sin(f1)), 1e-14 * scale * L);
    EXPECT_NEAR(g.getAreaWeights_m2().sum(), R * p.arcWidth_rad * L, 1e-15 * R * L);
  }
}

TEST(SkirtSideGrid, PressureLinearInHeightGivesTheClosedFormTiltMoment) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(20, 15));
  const double p0 = 1e5, p1 = 4e6;  // p = p0 + p1 y [Pa]
  const Eigen::ArrayXd pr = p0 + p1 * g.getNodeY_m();
  const ps::PistonLoads l = g.calcLoadsOnPiston(pr);
  const double R = g.getRadius_m(), f1 = -kPi / 6, f2 = kPi / 6;
  const double y1 = g.getSkirtBottomHeight_m(), y2 = g.getSkirtTopHeight_m();
  // M_z = int p y cos phi dA = R (sin f2 - sin f1) int (p0 y + p1 y^2) dy (bilinear
  // interpolation of a linear field is exact)
  const double mz = R * (std::sin(f2) - std::sin(f1)) *
                    (p0 * (y2 * y2 - y1 * y1) / 2 + p1 * (y2 * y2 * y2 - y1 * y1 * y1) / 3);
  const double fx =
      -R * (std::sin(f2) - std::sin(f1)) * (p0 * (y2 - y1) + p1 * (y2 * y2 - y1 * y1) / 2);
  EXPECT_NEAR(l.moment_Nm.z(), mz, 1e-13 * std::abs(mz));
  EXPECT_NEAR(l.force_N.x(), fx, 1e-13 * std::abs(fx));
  std::printf("[ tilt     ] M_z = %.12e N m, closed form %.12e N m\n", l.moment_Nm.z(), mz);
}

TEST(SkirtSideGrid, ThrustSymmetricPressureHasNoPinAxisForceNorMomentAboutX) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(31, 12));
  Eigen::ArrayXd pr(g.nodeCount());
  for (int k = 0; k < g.nodeCount(); ++k) {
    const double ph = g.getNodePhi_rad()[k], y = g.getNodeY_m()[k];
    pr[k] = 3e5 * std::cos(2.0 * ph) * std::exp(-ph * ph) * (1.0 + 20.0 * y);  // even in phi
  }
  const ps::PistonLoads l = g.calcLoadsOnPiston(pr);
  const double scale = std::abs(l.force_N.x());
  EXPECT_GT(scale, 100.0);
  EXPECT_NEAR(l.force_N.z(), 0.0, 1e-14 * scale);
  EXPECT_NEAR(l.moment_Nm.x(), 0.0, 1e-14 * scale * 0.04);
  EXPECT_NEAR(l.moment_Nm.y(), 0.0, 1e-14 * scale * 0.04);
}

TEST(SkirtSideGrid, UniformShearsGiveTheClosedFormLoads) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(16, 11));
  const double R = g.getRadius_m(), f1 = -kPi / 6, f2 = kPi / 6, Phi = kPi / 3;
  const double y1 = g.getSkirtBottomHeight_m(), y2 = g.getSkirtTopHeight_m(), L = y2 - y1;
  const double ym = 0.5 * (y2 * y2 - y1 * y1);
  const Eigen::ArrayXd zero = Eigen::ArrayXd::Zero(g.nodeCount());
  const double tau = 120.0;  // [Pa]
  const Eigen::ArrayXd t = Eigen::ArrayXd::Constant(g.nodeCount(), tau);
  const double scale = tau * R * Phi * L;
  // axial shear tau_y e_y: F_y = tau A, M = R tau int (-sin, 0, cos) dA
  const ps::PistonLoads a = g.calcLoadsOnPiston(zero, t, zero);
  EXPECT_NEAR(a.force_N.y(), tau * R * Phi * L, 1e-14 * scale);
  EXPECT_NEAR(a.force_N.x(), 0.0, 1e-14 * scale);
  EXPECT_NEAR(a.moment_Nm.x(), -R * tau * R * L * (std::cos(f1) - std::cos(f2)), 1e-14 * scale * R);
  EXPECT_NEAR(a.moment_Nm.z(), R * tau * R * L * (std::sin(f2) - std::sin(f1)), 1e-14 * scale * R);
  // circumferential shear tau e_phi: F = tau R L (cos f1 - cos f2, 0, sin f2 - sin f1),
  // M = (tau int y cos, -R tau A, tau int y sin)
  const ps::PistonLoads c = g.calcLoadsOnPiston(zero, zero, t);
  EXPECT_NEAR(c.force_N.x(), -tau * R * L * (std::cos(f1) - std::cos(f2)), 1e-14 * scale);
  EXPECT_NEAR(c.force_N.z(), tau * R * L * (std::sin(f2) - std::sin(f1)), 1e-14 * scale);
  EXPECT_NEAR(c.moment_Nm.x(), tau * R * ym * (std::sin(f2) - std::sin(f1)), 1e-14 * scale * L);
  EXPECT_NEAR(c.moment_Nm.y(), -R * tau * R * Phi * L, 1e-14 * scale * R);
  EXPECT_NEAR(c.moment_Nm.z(), tau * R * ym * (std::cos(f1) - std::cos(f2)), 1e-14 * scale * L);
}

// Bilinear interpolant of a nodal field at (phi, y) inside cell (ci, cj).
double bilinear(const ps::SkirtSideGrid& g, const Eigen::ArrayXd& v, int ci, int cj, double ph,
                double y) {
  const Eigen::VectorXd& P = g.getPhiNodes_rad();
  const Eigen::VectorXd& Y = g.getYNodes_m();
  const double s = (ph - P[ci]) / (P[ci + 1] - P[ci]), t = (y - Y[cj]) / (Y[cj + 1] - Y[cj]);
  return (1 - s) * (1 - t) * v[g.nodeIndex(ci, cj)] + s * (1 - t) * v[g.nodeIndex(ci + 1, cj)] +
         (1 - s) * t * v[g.nodeIndex(ci, cj + 1)] + s * t * v[g.nodeIndex(ci + 1, cj + 1)];
}

TEST(SkirtSideGrid, LoadsEqualTheDirectlyIntegratedTractionResultant) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (ps::SkirtSide side : {ps::SkirtSide::Thrust, ps::SkirtSide::AntiThrust}) {
    ps::SkirtSideGridParameters p = ps::test::thrustSide(13, 9);
    p.side = side;
    p.axialClustering = 1.2;
    const ps::SkirtSideGrid g(p);
    const int n = g.nodeCount();
    Eigen::ArrayXd pr(n), ty(n), tp(n);
    for (int k = 0; k < n; ++k) {
      pr[k] = 2e5 * (1.0 + 0.8 * u(rng));
      ty[k] = 300.0 * u(rng);
      tp[k] = 200.0 * u(rng);
    }
    const ps::PistonLoads l = g.calcLoadsOnPiston(pr, ty, tp);
    // Reference: int t dA and int r x t dA with t = -p e_r + tau_y e_y + tau_phi e_phi built as
    // 3-D vectors, 10 x 10 Gauss points per cell.
    const auto [gx, gw] = ps::test::gaussLegendre(10);
    Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
    double absF = 0.0, absM = 0.0;
    const double R = g.getRadius_m();
    const Eigen::VectorXd& P = g.getPhiNodes_rad();
    const Eigen::VectorXd& Y = g.getYNodes_m();
    for (int ci = 0; ci + 1 < g.nPhi(); ++ci)
      for (int cj = 0; cj + 1 < g.nY(); ++cj)
        for (int a = 0; a < 10; ++a)
          for (int b = 0; b < 10; ++b) {
            const double ph = 0.5 * (P[ci] + P[ci + 1]) + 0.5 * (P[ci + 1] - P[ci]) * gx[a];
            const double y = 0.5 * (Y[cj] + Y[cj + 1]) + 0.5 * (Y[cj + 1] - Y[cj]) * gx[b];
            const double dA = gw[a] * gw[b] * 0.25 * (P[ci + 1] - P[ci]) * (Y[cj + 1] - Y[cj]) * R;
            const Eigen::Vector3d er(std::cos(ph), 0.0, std::sin(ph));
            const Eigen::Vector3d ephi(-std::sin(ph), 0.0, std::cos(ph));
            const Eigen::Vector3d r(R * std::cos(ph), y, R * std::sin(ph));
            const Eigen::Vector3d t = -bilinear(g, pr, ci, cj, ph, y) * er +
                                      bilinear(g, ty, ci, cj, ph, y) * Eigen::Vector3d::UnitY() +
                                      bilinear(g, tp, ci, cj, ph, y) * ephi;
            F += t * dA;
            M += r.cross(t) * dA;
            absF += t.norm() * dA;
            absM += r.norm() * t.norm() * dA;
          }
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(l.force_N[c], F[c], 1e-13 * absF) << "force " << c;
      EXPECT_NEAR(l.moment_Nm[c], M[c], 1e-13 * absM) << "moment " << c;
    }
  }
}

}  // namespace
