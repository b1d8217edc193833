// skirt::ElasticCoupling against references written here, independently of the code under test:
//   1. a Hertzian pressure on an elastic half-space (flat strip: R = 1 m, a 18 mm square):
//      the coupling's displacement of the film grid against the closed-form Boussinesq
//      solution (Johnson, Contact Mechanics, eqs. 3.41a/b), with a compliance built here from
//      Love's uniform-patch integral;
//   2. a load symmetric about the side's centre line (local stiff film law, symmetric gap and
//      grids): the converged deformation is mirror-symmetric to round-off;
//   3. the gas field alone: minus the field's bicubic interpolant times the cylinder pressure;
//   4. bad input, each message naming the member.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "ElasticCouplingTestSupport.h"
#include "ExpectInvalidArgument.h"
#include "SkirtTestSupport.h"
#include "pistondyn/mapping/CylinderGrid.h"
#include "pistondyn/skirt/AitkenCoupling.h"
#include "pistondyn/skirt/ElasticCoupling.h"
#include "pistondyn/skirt/NewtonCoupling.h"

namespace ps = pistondyn::skirt;
namespace pm = pistondyn::mapping;
using pistondyn::test::expectInvalidArgument;
using ps::test::kPi;

namespace {

constexpr double kYoungs_Pa = 75e9, kPoisson = 0.33;  // Al-Si piston alloy

// ------------------------------------------------------------------------------------------
// 1. Hertzian pressure p = p0 sqrt(1 - r^2/a^2) on a half-space. Normal displacement
// (Johnson eq. 3.41a inside, 3.41b outside, with 1/E* -> (1 - nu^2)/E for one elastic body):
//   r <= a: w = (1 - nu^2)/E * pi p0 / (4 a) * (2 a^2 - r^2)
//   r >  a: w = (1 - nu^2)/E * p0 / (2 a) * [(2 a^2 - r^2) asin(a/r) + r a sqrt(1 - a^2/r^2)]
// Both give w(a) = (1 - nu^2)/E * pi p0 a / 4 (continuity, checked below).
double hertzDisplacement_m(double r, double a, double p0) {
  const double k = (1.0 - kPoisson * kPoisson) / kYoungs_Pa;
  if (r <= a)
    return k * kPi * p0 / (4.0 * a) * (2.0 * a * a - r * r);
  return k * p0 / (2.0 * a) *
         ((2.0 * a * a - r * r) * std::asin(a / r) + r * a * std::sqrt(1.0 - a * a / (r * r)));
}

TEST(ElasticCoupling, HertzPressureOnAHalfSpaceMatchesBoussinesq) {
  // Flat strip: radius 1 m, so the side is an 18 mm x 18 mm square of the developed surface.
  const double R = 1.0, half = 0.009, a = 0.003, p0 = 1e8;
  ps::SkirtSideGridParameters gp;
  gp.radius_m = R;
  gp.arcWidth_rad = 2.0 * half / R;
  gp.skirtTopHeight_m = half;
  gp.skirtLength_m = 2.0 * half;
  gp.nPhi = 73;  // 0.25 mm film cells
  gp.nY = 73;
  const ps::SkirtSideGrid side(gp);
  // Structural grid: 25 x 25 nodes, 0.75 mm = a/4 cells, over the same square.
  const Eigen::VectorXd phiS = pm::uniformNodes(-half / R, half / R, 25);
  const Eigen::VectorXd yS = pm::uniformNodes(-half, half, 25);
  const auto compliance = ps::test::halfSpaceCompliance(R, phiS, yS, kYoungs_Pa, kPoisson);

  const int n = side.nodeCount();
  Eigen::ArrayXd pressure(n);
  for (int k = 0; k < n; ++k) {
    const double s = R * side.getNodePhi_rad()[k], y = side.getNodeY_m()[k];
    const double r2 = s * s + y * y;
    pressure[k] = r2 < a * a ? p0 * std::sqrt(1.0 - r2 / (a * a)) : 0.0;
  }
  ps::AitkenCoupling coupling(side, compliance);
  int calls = 0;
  const ps::ElasticCouplingReport rep =
      coupling.solve([&](const Eigen::ArrayXd&, ps::FilmPressureEvaluation& out) {
        ++calls;
        out.normalPressure_Pa = pressure;  // a given load: the deformation does not change it
        out.minFilmThickness_m = 1e-6;
      });
  ASSERT_TRUE(rep.converged);
  EXPECT_EQ(rep.iterations, calls);

  // Check of the reference itself: both branches meet at r = a.
  EXPECT_NEAR(hertzDisplacement_m(a * (1 + 1e-12), a, p0), hertzDisplacement_m(a, a, p0),
              1e-9 * hertzDisplacement_m(0.0, a, p0));

  const double w0 = hertzDisplacement_m(0.0, a, p0);
  double worst = 0.0, centre = 0.0, worstR = 0.0;
  for (int k = 0; k < n; ++k) {
    const double s = R * side.getNodePhi_rad()[k], y = side.getNodeY_m()[k];
    const double r = std::hypot(s, y);
    const double err = std::abs(coupling.pistonElastic_m()[k] - hertzDisplacement_m(r, a, p0));
    if (err > worst) {
      worst = err;
      worstR = r;
    }
    if (r == 0.0)
      centre = coupling.pistonElastic_m()[k];
  }
  std::printf(
      "[ElasticCoupling] Hertz on a half-space: w(0) = %.4e m (closed form %.4e m, "
      "%+.2f %%), worst node error %.2f %% of w(0) at r = %.2f a, %d iterations\n",
      centre, w0, 100.0 * (centre / w0 - 1.0), 100.0 * worst / w0, worstR / a, rep.iterations);
  EXPECT_NEAR(centre, w0, 0.05 * w0);
  EXPECT_LT(worst, 0.05 * w0);
  // The total load: p0 * 2 pi a^2 / 3 (integral of the Hertz pressure), to the film grid's
  // resolution of the square-root edge.
  const double load = p0 * 2.0 * kPi * a * a / 3.0;
  EXPECT_NEAR(rep.pistonForce_N, load, 0.01 * load);
  EXPECT_NEAR(rep.structureForce_N, -rep.pistonForce_N, 1e-12 * load);
}

// ------------------------------------------------------------------------------------------
// A stiff local film law on a thrust side: p = p_ref(phi, y) (h_r / h_f)^3, h_f the smoothly
// clamped gap (h_c = 0.1 um) of h = h_r + h_el, h_r a centred round skirt with a barrel,
// p_ref a bump symmetric about phi = 0. dp/dh = -3 p / h: the stiffness of a squeeze film.
struct LocalFilm {
  Eigen::ArrayXd rigidGap_m, referencePressure_Pa;
  void operator()(const Eigen::ArrayXd& elastic_m, ps::FilmPressureEvaluation& out) const {
    out.normalPressure_Pa.resize(rigidGap_m.size());
    for (Eigen::Index k = 0; k < rigidGap_m.size(); ++k) {
      const double hf = ps::test::smoothClamp(rigidGap_m[k] + elastic_m[k], 1e-7);
      out.normalPressure_Pa[k] = referencePressure_Pa[k] * std::pow(rigidGap_m[k] / hf, 3);
    }
    out.minFilmThickness_m = (rigidGap_m + elastic_m).minCoeff();
  }
};

struct SymmetricCase {
  ps::SkirtSideGrid side;
  pm::StructuralCompliance compliance;
  LocalFilm film;
};

SymmetricCase symmetricCase() {
  ps::SkirtSideGridParameters gp = ps::test::thrustSide(48, 36);
  gp.arcWidth_rad = 1.0;
  const ps::SkirtSideGrid side(gp);
  const double R = gp.radius_m;
  // Structural sector, symmetric about phi = 0, covering the side.
  const Eigen::VectorXd phiS = pm::uniformNodes(-0.6, 0.6, 13);
  const Eigen::VectorXd yS = pm::uniformNodes(-0.025, 0.015, 9);
  LocalFilm film;
  const int n = side.nodeCount();
  film.rigidGap_m.resize(n);
  film.referencePressure_Pa.resize(n);
  const double yMid = -0.005, halfL = 0.02;
  for (int k = 0; k < n; ++k) {
    const double phi = side.getNodePhi_rad()[k], y = side.getNodeY_m()[k];
    // c0 = 30 um, e = 29 um: 1 um at the centre line; barrel 20 um at the edges.
    film.rigidGap_m[k] = 30e-6 - 29e-6 * std::cos(phi) + 20e-6 * std::pow((y - yMid) / halfL, 2);
    film.referencePressure_Pa[k] = 40e6 * std::exp(-std::pow(R * phi / 0.006, 2)) *
                                   std::max(0.0, 1.0 - std::pow((y - yMid) / halfL, 2));
  }
  return {side, ps::test::halfSpaceCompliance(R, phiS, yS, kYoungs_Pa, kPoisson), film};
}

TEST(ElasticCoupling, SymmetricLoadGivesASymmetricDeformation) {
  const SymmetricCase c = symmetricCase();
  ps::ElasticCouplingParameters p;
  p.absoluteTolerance_m = 1e-11;  // tight: symmetry is checked far below the tolerance anyway
  p.relativeTolerance = 0.0;
  ps::AitkenCoupling coupling(c.side, c.compliance, p);
  const ps::ElasticCouplingReport rep = coupling.solve(c.film);
  ASSERT_TRUE(rep.converged) << rep.iterations << " iterations, residual " << rep.residual_m;
  const Eigen::ArrayXd& d = coupling.pistonElastic_m();
  const int nPhi = c.side.nPhi(), nY = c.side.nY();
  double asym = 0.0;
  for (int j = 0; j < nY; ++j)
    for (int i = 0; i < nPhi; ++i)
      asym = std::max(asym, std::abs(d[i + nPhi * j] - d[(nPhi - 1 - i) + nPhi * j]));
  const double peak = d.abs().maxCoeff();
  std::printf(
      "[ElasticCoupling] symmetric load: peak deformation %.4e m, asymmetry %.2e of it, "
      "%d iterations, residual %.2e m, relaxation %.3f\n",
      peak, asym / peak, rep.iterations, rep.residual_m, rep.relaxation);
  EXPECT_GT(peak, 0.2e-6);  // the case is really coupled (vs a 2 um film)
  EXPECT_LT(asym, 1e-12 * peak);
  // The deformation opens the gap where the film presses (sign, ElasticCoupling.h).
  Eigen::Index kMax = 0;
  c.film.referencePressure_Pa.maxCoeff(&kMax);
  EXPECT_GT(d[kMax], 0.0);
}

// ------------------------------------------------------------------------------------------
// The gas field alone (no film pressure): the gap term is minus the field times the cylinder
// pressure, read on the film grid by the bicubic spline. A field that is a bicubic polynomial
// in (phi, y) is reproduced exactly by it (sector, >= 4 nodes per direction; mapping/README.md),
// so the film-grid values are known in closed form.
TEST(ElasticCoupling, GasFieldAloneGivesMinusItsScaledInterpolant) {
  SymmetricCase c = symmetricCase();
  const auto poly = [](double phi, double y) {  // [m/Pa], a bicubic polynomial
    const double t = phi / 0.6, u = (y + 0.005) / 0.02;
    return 1e-12 * (-3.0 + 0.5 * t - 2.0 * t * t + 0.3 * t * t * t * u + u * u * u - t * u);
  };
  const int ns = c.compliance.nodeCount(), np = c.compliance.nPhi();
  c.compliance.gasDisplacement_m_per_Pa.resize(ns);
  for (int k = 0; k < ns; ++k)
    c.compliance.gasDisplacement_m_per_Pa[k] =
        poly(c.compliance.phi_rad[k % np], c.compliance.y_m[k / np]);
  ps::AitkenCoupling coupling(c.side, c.compliance);
  const double pCyl = 5e6;
  const ps::ElasticCouplingReport rep = coupling.solve(
      [&](const Eigen::ArrayXd&, ps::FilmPressureEvaluation& out) {
        out.normalPressure_Pa = Eigen::ArrayXd::Zero(c.side.nodeCount());
        out.minFilmThickness_m = 1e-6;
      },
      pCyl);
  ASSERT_TRUE(rep.converged);
  double worst = 0.0, scale = 0.0;
  for (int k = 0; k < c.side.nodeCount(); ++k) {
    const double expected = -pCyl * poly(c.side.getNodePhi_rad()[k], c.side.getNodeY_m()[k]);
    worst = std::max(worst, std::abs(coupling.pistonElastic_m()[k] - expected));
    scale = std::max(scale, std::abs(expected));
  }
  std::printf(
      "[ElasticCoupling] gas field alone: largest term %.3e m, error %.1e of it, %d "
      "iterations\n",
      scale, worst / scale, rep.iterations);
  EXPECT_GT(scale, 1e-6);
  EXPECT_LT(worst, 1e-10 * scale);  // the residual tolerance is 1 nm: the last step is exact here
  EXPECT_EQ(rep.structureForce_N, 0.0);
}

// ------------------------------------------------------------------------------------------
// Bad input.
TEST(ElasticCouplingBadInput, NamesTheMember) {
  const SymmetricCase c = symmetricCase();
  {
    auto bad = c.compliance;
    bad.compliance_m_per_N.conservativeResize(bad.nodeCount() - 1, bad.nodeCount() - 1);
    expectInvalidArgument([&] { (void)ps::makeElasticCoupling(c.side, bad, {}); },
                          {"compliance_m_per_N is 116 x 116", "117 nodes"});
  }
  {
    auto bad = c.compliance;
    bad.compliance_m_per_N(3, 5) = std::numeric_limits<double>::quiet_NaN();
    expectInvalidArgument([&] { (void)ps::makeElasticCoupling(c.side, bad, {}); },
                          {"compliance_m_per_N(3, 5)", "finite"});
  }
  {
    auto bad = c.compliance;
    bad.gasDisplacement_m_per_Pa = Eigen::VectorXd::Zero(5);
    expectInvalidArgument([&] { (void)ps::makeElasticCoupling(c.side, bad, {}); },
                          {"gasDisplacement_m_per_Pa", "expected 117"});
  }
  {
    auto bad = c.compliance;
    bad.y_m = pm::uniformNodes(-0.020, 0.015, 9);  // the side reaches down to -0.025 m
    expectInvalidArgument([&] { (void)ps::makeElasticCoupling(c.side, bad, {}); },
                          {"outside the structural grid's heights"});
  }
  {
    auto bad = c.compliance;
    bad.phi_rad = pm::uniformNodes(-0.4, 0.4, 13);  // the side spans +-0.5 rad
    expectInvalidArgument([&] { (void)ps::makeElasticCoupling(c.side, bad, {}); },
                          {"outside the structural sector"});
  }
  {
    ps::ElasticCouplingParameters p;
    p.maxIterations = 0;
    expectInvalidArgument([&] { (void)ps::makeElasticCoupling(c.side, c.compliance, p); },
                          {"ElasticCouplingParameters", "maxIterations"});
    p = {};
    p.maxRelaxation = 1.5;
    expectInvalidArgument([&] { (void)ps::makeElasticCoupling(c.side, c.compliance, p); },
                          {"maxRelaxation", "(0, 1]"});
    p = {};
    p.absoluteTolerance_m = 0.0;
    p.relativeTolerance = 0.0;
    expectInvalidArgument([&] { (void)ps::makeElasticCoupling(c.side, c.compliance, p); }, {"both 0"});
    p = {};
    p.maxKrylovIterations = 0;
    expectInvalidArgument([&] { (void)ps::makeElasticCoupling(c.side, c.compliance, p); },
                          {"maxKrylovIterations = 0", "1 ... 50"});
    p = {};
    p.krylovTolerance = 1.0;
    expectInvalidArgument([&] { (void)ps::makeElasticCoupling(c.side, c.compliance, p); },
                          {"krylovTolerance", "(0, 1)"});
  }
  {
    // The Newton scheme needs the film's local stiffness with every evaluation.
    ps::ElasticCouplingParameters p;
    p.scheme = ps::ElasticCouplingScheme::Newton;
    ps::NewtonCoupling newton(c.side, c.compliance, p);
    const int n = c.side.nodeCount();
    expectInvalidArgument(
        [&] {
          (void)newton.solve([n](const Eigen::ArrayXd&, ps::FilmPressureEvaluation& out) {
            out.normalPressure_Pa = Eigen::ArrayXd::Constant(n, 1e5);
          });
        },
        {"Newton scheme needs", "pressureStiffness_Pa_per_m"});
  }
  ps::AitkenCoupling coupling(c.side, c.compliance);
  expectInvalidArgument(
      [&] {
        (void)coupling.solve([](const Eigen::ArrayXd&, ps::FilmPressureEvaluation& out) {
          out.normalPressure_Pa = Eigen::ArrayXd::Zero(7);
        });
      },
      {"normalPressure_Pa with 7 entries", "expected 1728"});
  expectInvalidArgument(
      [&] {
        (void)coupling.solve([&](const Eigen::ArrayXd&, ps::FilmPressureEvaluation& out) {
          out.normalPressure_Pa = Eigen::ArrayXd::Zero(c.side.nodeCount());
          out.normalPressure_Pa[10] = std::numeric_limits<double>::infinity();
        });
      },
      {"normalPressure_Pa[10]", "finite"});
  expectInvalidArgument(
      [&] { (void)coupling.solve(c.film, std::numeric_limits<double>::quiet_NaN()); },
      {"cylinderPressure_Pa"});
  expectInvalidArgument([&] { coupling.setStart(Eigen::VectorXd::Zero(3)); }, {"setStart", "117"});
}

}  // namespace
