// HermiteSurface (thesis eq. 9): exactness on bicubic polynomials, fourth-order
// convergence, C1 across the periodic seam, grid evaluation at an offset, bad input.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <random>
#include <vector>

#include "ExpectInvalidArgument.h"
#include "TestSupport.h"
#include "pistondyn/mapping/HermiteSurface.h"

namespace pm = pistondyn::mapping;
using pistondyn::test::expectInvalidArgument;
using pm::test::kPi;

namespace {

// f(phi, y) = sum_{a,b <= 3} c(a, b) phi^a (y/L)^b with its derivatives, evaluated
// directly: the independent reference for the exactness tests.
struct Bicubic {
  Eigen::Matrix4d c;
  double length;
  pm::HermiteSample at(double phi, double y) const {
    const double v = y / length;
    const Eigen::Vector4d p(1, phi, phi * phi, phi * phi * phi), dp(0, 1, 2 * phi, 3 * phi * phi);
    const Eigen::Vector4d q(1, v, v * v, v * v * v),
        dq = Eigen::Vector4d(0, 1, 2 * v, 3 * v * v) / length;
    return {p.dot(c * q), dp.dot(c * q), p.dot(c * dq), dp.dot(c * dq)};
  }
  Eigen::VectorXd nodal(const pm::CylinderGrid& g, double pm::HermiteSample::*member) const {
    Eigen::VectorXd f(g.nodeCount());
    for (int j = 0; j < g.nY(); ++j)
      for (int i = 0; i < g.nPhi(); ++i)
        f[g.index(i, j)] = at(g.phi_rad()[i], g.y_m()[j]).*member;
    return f;
  }
};

Bicubic randomBicubic(std::mt19937& rng, double length) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Bicubic b{Eigen::Matrix4d::Zero(), length};
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 4; ++k)
      b.c(a, k) = u(rng);
  return b;
}

// Largest |reference - computed| over samples, per quantity, and the largest |reference|
// (the scale of the relative tolerance).
struct MaxErrors {
  std::array<double, 4> error{}, scale{};
  void add(const pm::HermiteSample& ref, const pm::HermiteSample& got) {
    const double r[4] = {ref.value, ref.dPhi, ref.dY, ref.dPhiDY};
    const double g[4] = {got.value, got.dPhi, got.dY, got.dPhiDY};
    for (int q = 0; q < 4; ++q) {
      error[q] = std::max(error[q], std::abs(r[q] - g[q]));
      scale[q] = std::max(scale[q], std::abs(r[q]));
    }
  }
  void expectRelativeBelow(double tol, int quantities = 4) const {
    const char* names[4] = {"value", "dPhi", "dY", "dPhiDY"};
    for (int q = 0; q < quantities; ++q)
      EXPECT_LE(error[q], tol * scale[q]) << names[q] << " scale " << scale[q];
  }
};

pm::CylinderGrid gradedSector(std::mt19937& rng, int nPhi, int nY) {
  return pm::CylinderGrid::sector(0.0325, pm::test::randomNodes(rng, -0.6, 0.7, nPhi),
                                  pm::test::randomNodes(rng, 0.002, 0.041, nY));
}

// Errors of the surface against the bicubic at `count` random points of the graded
// sectors' domain [-0.6, 0.7] x [0.002, 0.041].
MaxErrors errorsAtRandomPoints(const Bicubic& f, const pm::HermiteSurface& surface,
                               std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> phi(-0.6, 0.7), y(0.002, 0.041);
  MaxErrors e;
  for (int s = 0; s < count; ++s) {
    const double p = phi(rng), q = y(rng);
    e.add(f.at(p, q), surface.evaluate(p, q));
  }
  return e;
}

}  // namespace

// Reference: the bicubic polynomial itself. The not-a-knot spline slopes are exact for
// cubics along every line, so the Hermite surface IS the polynomial; 1e-12 relative
// leaves room only for rounding (the spline solves amplify it by O(10)).
TEST(HermiteSurface, ReproducesBicubicPolynomialsExactlyWithSplineDerivatives) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 5; ++trial) {
    const pm::CylinderGrid grid = gradedSector(rng, 4 + 3 * trial, 5 + 4 * trial);
    const Bicubic f = randomBicubic(rng, 0.04);
    const pm::HermiteSurface surface(grid, f.nodal(grid, &pm::HermiteSample::value));
    errorsAtRandomPoints(f, surface, rng, 300).expectRelativeBelow(1e-12);
  }
}

// Reference: the bicubic polynomial; exact nodal derivatives supplied by the caller.
TEST(HermiteSurface, ReproducesBicubicPolynomialsExactlyWithSuppliedDerivatives) {
  std::mt19937 rng(2);
  const pm::CylinderGrid grid = gradedSector(rng, 3, 2);  // even the smallest grids
  const Bicubic f = randomBicubic(rng, 0.04);
  const pm::HermiteSurface surface(
      grid, f.nodal(grid, &pm::HermiteSample::value), f.nodal(grid, &pm::HermiteSample::dPhi),
      f.nodal(grid, &pm::HermiteSample::dY), f.nodal(grid, &pm::HermiteSample::dPhiDY));
  errorsAtRandomPoints(f, surface, rng, 300).expectRelativeBelow(1e-12);
}

// updateValues() keeps the grid's factorisations: a surface built for other data and then
// updated reproduces the new bicubic exactly (reference: the polynomial).
TEST(HermiteSurface, UpdateValuesReproducesTheNewData) {
  std::mt19937 rng(3);
  const pm::CylinderGrid grid = gradedSector(rng, 9, 12);
  pm::HermiteSurface surface(grid, Eigen::VectorXd::Zero(grid.nodeCount()));
  for (int step = 0; step < 3; ++step) {
    const Bicubic f = randomBicubic(rng, 0.04);
    surface.updateValues(f.nodal(grid, &pm::HermiteSample::value));
    errorsAtRandomPoints(f, surface, rng, 200).expectRelativeBelow(1e-12);
  }
}

// Reference: a smooth periodic closed-form field. Cubic spline interpolation converges at
// O(h^4) in the value; the observed order over three halvings of both spacings (graded
// grids, full circle, 48 x 32 up to 384 x 256 nodes) must be 4 within 0.25. Observed:
// 3.96, 4.16, 4.00; coarser grids (12 x 8, 24 x 16) are pre-asymptotic (4.77, 4.35).
TEST(HermiteSurface, ConvergesAtFourthOrderOnSmoothData) {
  const double length = 0.05;
  auto f = [&](double phi, double y) {
    return std::exp(std::sin(phi)) * std::cos(2 * kPi * y / length + 0.3) + std::cos(2 * phi);
  };
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> uPhi(0.0, 2 * kPi), uY(0.0, length);
  std::vector<std::pair<double, double>> samples(3000);
  for (auto& s : samples)
    s = {uPhi(rng), uY(rng)};

  std::vector<double> errors;
  for (int level = 2; level < 6; ++level) {
    const int nPhi = 12 << level, nY = 8 << level;
    Eigen::VectorXd phi(nPhi), y(nY);
    for (int i = 0; i < nPhi; ++i) {  // smoothly graded: spacing ratio up to ~1.9
      const double xi = double(i) / nPhi;
      phi[i] = 2 * kPi * (xi - 0.05 * std::sin(2 * kPi * xi));
    }
    for (int j = 0; j < nY; ++j) {
      const double xi = double(j) / (nY - 1);
      y[j] = length * (xi - 0.08 * std::sin(2 * kPi * xi));
    }
    const auto grid = pm::CylinderGrid::fullCircle(0.0325, phi, y);
    Eigen::VectorXd v(grid.nodeCount());
    for (int j = 0; j < nY; ++j)
      for (int i = 0; i < nPhi; ++i)
        v[grid.index(i, j)] = f(phi[i], y[j]);
    const pm::HermiteSurface surface(grid, v);
    double e = 0.0;
    for (const auto& [p, q] : samples)
      e = std::max(e, std::abs(surface.evaluate(p, q).value - f(p, q)));
    errors.push_back(e);
  }
  for (size_t r = 0; r + 1 < errors.size(); ++r) {
    const double order = std::log2(errors[r] / errors[r + 1]);
    EXPECT_NEAR(order, 4.0, 0.25) << "refinement " << r << ": " << errors[r] << " -> "
                                  << errors[r + 1];
  }
}

// The last cell (phi_{n-1} .. phi_0 + 2*pi) and the first cell meet at the seam: value
// and all derivatives must agree from both sides (reference: each other; both interpolate
// the same nodal data, so only rounding may differ: 1e-13 of the quantity's scale).
// Also: evaluating at phi and phi + 2*pi gives the same result.
// Note: C1 at the seam is true by construction (both cells take the same nodal value and
// slopes, and the Hermite basis reproduces them exactly at a cell edge), so this test
// guards the seam's bookkeeping (indices, closing-cell width, wrapping), not the slopes.
// That the slopes are right (the periodic spline's, across the seam too) is checked by
// ConvergesAtFourthOrderOnSmoothData (wrong seam slopes would drop the order to 1-2
// there) and by FourierModeErrorOnAFullCircleMatchesTheClosedForm.
TEST(HermiteSurface, IsC1AcrossThePeriodicSeam) {
  std::mt19937 rng(5);
  const Eigen::VectorXd phi = pm::test::randomNodes(rng, 0.4, 0.4 + 2 * kPi - 0.3, 17);
  const Eigen::VectorXd y = pm::test::randomNodes(rng, 0.0, 0.03, 9);
  const auto grid = pm::CylinderGrid::fullCircle(0.0325, phi, y);
  Eigen::VectorXd v(grid.nodeCount());
  for (int j = 0; j < grid.nY(); ++j)
    for (int i = 0; i < grid.nPhi(); ++i)
      v[grid.index(i, j)] = std::exp(std::cos(phi[i] - 1.0)) * (1.0 + 30.0 * y[j] * y[j]) +
                            0.3 * std::sin(3 * phi[i]);
  const pm::HermiteSurface surface(grid, v);
  const int last = grid.phiCellCount() - 1;
  MaxErrors seam;
  for (int j = 0; j < grid.yCellCount(); ++j)
    for (double u : {0.0, 0.25, 0.5, 0.9}) {
      seam.add(surface.evaluateInCell(0, j, 0.0, u), surface.evaluateInCell(last, j, 1.0, u));
    }
  seam.expectRelativeBelow(1e-13);
  // The seam slopes are not trivial (the test would be vacuous with zero derivatives).
  EXPECT_GT(seam.scale[1], 0.1);

  MaxErrors wrap;
  std::uniform_real_distribution<double> uPhi(0.0, 2 * kPi), uY(0.0, 0.03);
  for (int s = 0; s < 100; ++s) {
    const double p = uPhi(rng), q = uY(rng);
    wrap.add(surface.evaluate(p, q), surface.evaluate(p + 2 * kPi, q));
    wrap.add(surface.evaluate(p, q), surface.evaluate(p - 4 * kPi, q));
  }
  wrap.expectRelativeBelow(1e-13);
}

// Resolution of a full-circle grid for bore distortion (Fourier orders 0..12 along the
// circumference, docs/DESIGN.md §4). Reference: the closed form of the periodic cubic
// spline's error for one Fourier mode on n uniform nodes, derived by hand, sharing nothing
// with the library: the spline slopes of e^{ik phi} are m_j = c f_j with
// c h = 3 i sin(theta) / (2 + cos(theta)), theta = k h = 2 pi k / n, and at a cell
// midpoint the Hermite interpolant differs from e^{ik phi} by a factor of modulus
//   e(theta) = |1 - cos(theta/2) - 3 sin(theta) sin(theta/2) / (4 (2 + cos(theta)))|,
// the largest error over the cell. The complex mode is interpolated as two surfaces
// (cos, sin), so the error modulus is seen at every midpoint whatever the phase.
// Figures: 36 nodes: order 8 -> 1.55 %, order 12 -> 12.5 % of the amplitude; 72 nodes:
// order 12 -> 0.41 %; 1 % needs 4.94 nodes per wavelength (order 12: 60 nodes), 0.1 %
// needs 8.27 (order 12: 100 nodes). mapping/README.md gives the rule.
TEST(HermiteSurface, FourierModeErrorOnAFullCircleMatchesTheClosedForm) {
  const Eigen::VectorXd y = pm::uniformNodes(0.0, 0.1, 2);
  auto closedForm = [](double theta) {
    return std::abs(1.0 - std::cos(theta / 2) -
                    3.0 * std::sin(theta) * std::sin(theta / 2) / (4.0 * (2.0 + std::cos(theta))));
  };
  struct Case {
    int nodes, order;
    double expectedPercent;  // closed form, for the record
  };
  for (const Case c : {Case{36, 2, 0.0040}, Case{36, 8, 1.5536}, Case{36, 12, 12.5},
                       Case{72, 8, 0.0697}, Case{72, 12, 0.4071}, Case{144, 12, 0.0209}}) {
    const auto grid = pm::CylinderGrid::fullCircle(0.0325, pm::fullCircleNodes_rad(c.nodes), y);
    Eigen::VectorXd re(grid.nodeCount()), im(grid.nodeCount());
    for (int j = 0; j < grid.nY(); ++j)
      for (int i = 0; i < grid.nPhi(); ++i) {
        re[grid.index(i, j)] = std::cos(c.order * grid.phi_rad()[i]);
        im[grid.index(i, j)] = std::sin(c.order * grid.phi_rad()[i]);
      }
    const pm::HermiteSurface cosSurface(grid, re), sinSurface(grid, im);
    const double h = 2 * kPi / c.nodes;
    const double expected = closedForm(c.order * h);
    EXPECT_NEAR(100.0 * expected, c.expectedPercent, 5e-4)
        << c.nodes << " nodes, order " << c.order;
    double worstMid = 0.0, worstAnywhere = 0.0;
    for (int i = 0; i < c.nodes; ++i)
      for (double t : {0.1, 0.25, 0.4, 0.5, 0.6, 0.75, 0.9}) {
        const double phi = (i + t) * h;
        const std::complex<double> spline(cosSurface.evaluate(phi, 0.05).value,
                                          sinSurface.evaluate(phi, 0.05).value);
        const double error = std::abs(spline - std::polar(1.0, c.order * phi));
        worstAnywhere = std::max(worstAnywhere, error);
        if (t == 0.5)
          worstMid = std::max(worstMid, error);
      }
    // Rounding only (values O(1), 1e-12); the midpoint is the worst point of a cell.
    EXPECT_NEAR(worstMid, expected, 1e-12) << c.nodes << " nodes, order " << c.order;
    EXPECT_LE(worstAnywhere, expected + 1e-12) << c.nodes << " nodes, order " << c.order;
  }
}

// Reference: the bicubic polynomial at the target nodes. A 17 x 30 structural field read
// on a 64 x 48 contact grid placed at an offset inside it (grid path, with derivatives).
TEST(HermiteSurface, EvaluateOnGridAtAnOffsetReproducesBicubics) {
  std::mt19937 rng(6);
  const auto structural = pm::CylinderGrid::sector(
      0.0325, pm::test::randomNodes(rng, -1.0, 1.0, 17), pm::test::randomNodes(rng, 0.0, 0.04, 30));
  const auto contact = pm::CylinderGrid::sector(0.0325, pm::uniformNodes(-0.7, 0.7, 64),
                                                pm::uniformNodes(0.0, 0.03, 48));
  const pm::GridOffset offset{0.13, 0.004};
  const Bicubic f = randomBicubic(rng, 0.04);
  const pm::HermiteSurface surface(structural, f.nodal(structural, &pm::HermiteSample::value));
  Eigen::VectorXd value(contact.nodeCount()), dPhi(contact.nodeCount()), dY(contact.nodeCount()),
      valueOnly(contact.nodeCount());
  pm::HermiteGridWorkspace ws;
  surface.evaluateOnGrid(contact, offset, value, dPhi, dY, ws);
  surface.evaluateOnGrid(contact, offset, valueOnly, ws);
  MaxErrors e;
  for (int j = 0; j < contact.nY(); ++j)
    for (int i = 0; i < contact.nPhi(); ++i) {
      const int k = contact.index(i, j);
      const pm::HermiteSample ref =
          f.at(contact.phi_rad()[i] + offset.phi_rad, contact.y_m()[j] + offset.y_m);
      e.add(ref, {value[k], dPhi[k], dY[k], ref.dPhiDY});
      e.add(ref, {valueOnly[k], ref.dPhi, ref.dY, ref.dPhiDY});
    }
  e.expectRelativeBelow(1e-12, 3);
}

// Outside the grid: Throw names the coordinate; ExtendEndCells continues the end cell's
// polynomial, which for a reproduced bicubic is the bicubic itself (reference). Points
// within rounding of an edge are clamped, not rejected.
TEST(HermiteSurface, OutsidePointsThrowOrExtendTheEndCells) {
  std::mt19937 rng(8);
  const pm::CylinderGrid grid = gradedSector(rng, 8, 8);
  const Bicubic f = randomBicubic(rng, 0.04);
  const pm::HermiteSurface surface(grid, f.nodal(grid, &pm::HermiteSample::value));
  expectInvalidArgument([&] { surface.evaluate(0.0, 0.05); }, "y_m = 0.05");
  expectInvalidArgument([&] { surface.evaluate(0.8, 0.01); }, "phi_rad = 0.8");
  expectInvalidArgument([&] { surface.evaluate(-0.7, 0.01); }, "lies outside the sector");
  MaxErrors e;
  for (auto [p, q] : {std::pair{0.75, 0.01}, {-0.65, 0.02}, {0.1, 0.0}, {0.2, 0.045}, {0.8, 0.045}})
    e.add(f.at(p, q), surface.evaluate(p, q, pm::OutsidePolicy::ExtendEndCells));
  e.expectRelativeBelow(1e-12);
  const double yEnd = grid.y_m()[grid.nY() - 1];
  EXPECT_NO_THROW(surface.evaluate(0.7 + 1e-15, yEnd * (1 + 1e-15)));

  pm::HermiteGridWorkspace ws;
  Eigen::VectorXd out(grid.nodeCount());
  expectInvalidArgument([&] { surface.evaluateOnGrid(grid, {0.0, 0.001}, out, ws); }, "y_m");
}

TEST(HermiteSurface, RejectsBadInputNamingTheArgument) {
  std::mt19937 rng(9);
  const pm::CylinderGrid grid = gradedSector(rng, 5, 6);
  Eigen::VectorXd v = Eigen::VectorXd::Ones(grid.nodeCount());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectInvalidArgument([&] { pm::HermiteSurface(grid, Eigen::VectorXd::Ones(7)); },
                        "values has 7");
  v[5] = nan;
  expectInvalidArgument([&] { pm::HermiteSurface(grid, v); }, "values[5]");
  v[5] = 1.0;
  Eigen::VectorXd d = Eigen::VectorXd::Zero(grid.nodeCount());
  Eigen::VectorXd bad = d;
  bad[3] = std::numeric_limits<double>::infinity();
  expectInvalidArgument([&] { pm::HermiteSurface(grid, v, d, bad, d); }, "dY[3]");
  pm::HermiteSurface surface(grid, v);
  expectInvalidArgument([&] { surface.updateValues(Eigen::VectorXd::Ones(3)); }, "values has 3");
  expectInvalidArgument([&] { surface.evaluate(nan, 0.01); }, "phi_rad");
  // Absurd angles: the reduction modulo 2*pi of 1e300 keeps no digit (it used to return
  // garbage); within the bound it is exact to ~1e-10 rad (reference: the same point
  // given at its reduced angle, 159154 turns back).
  expectInvalidArgument([&] { surface.evaluate(1e300, 0.01); },
                        "HermiteSurface::evaluate: phi_rad");
  expectInvalidArgument([&] { surface.evaluate(-2e6, 0.01); }, "kMaxAbsAngle_rad");
  {
    Eigen::VectorXd w(grid.nodeCount());
    for (int k = 0; k < w.size(); ++k)
      w[k] = std::sin(0.7 * k);  // O(1) values, slopes O(10) per rad
    const pm::HermiteSurface varied(grid, w);
    const double turns = 159154.0, phi = 0.5 * (grid.phi_rad()[1] + grid.phi_rad()[2]);
    const double y = 0.5 * (grid.y_m()[1] + grid.y_m()[2]);
    const pm::HermiteSample far = varied.evaluate(phi + turns * 2.0 * kPi, y);
    const pm::HermiteSample near = varied.evaluate(phi, y);
    // 1e6 rad carries an ulp of 1.2e-10 rad and the reduction a few of them.
    EXPECT_NEAR(far.value, near.value, 1e-8);
  }
  expectInvalidArgument([&] { surface.evaluateInCell(99, 0, 0.5, 0.5); }, "cell (99, 0)");
  pm::HermiteGridWorkspace ws;
  Eigen::VectorXd out(3);
  expectInvalidArgument([&] { surface.evaluateOnGrid(grid, {}, out, ws); }, "output has 3");
  Eigen::VectorXd full(grid.nodeCount());
  expectInvalidArgument(
      [&] {
        surface.evaluateOnGrid(grid, {1e300, 0.0}, full, ws);
      },
      "offset.phi_rad");
}
