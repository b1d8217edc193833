// ForceMap / TensorForceMap on the developed surface (s = R*phi, y): static equivalence,
// uniform pressure, consistent versus half-cell (lumped) loads, partial overlap, the
// tensor-product update path, bad input.
//
// The independent reference throughout is a direct integration written here: every
// source cell, placed in the target frame and clipped to the target grid's rectangle, is
// integrated with a 3 x 3 Gauss rule of the cell's own bilinear interpolant (exact: the
// integrands are at most quadratic per direction). It shares no code with the library's
// overlap sweep.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "ExpectInvalidArgument.h"
#include "TestSupport.h"
#include "pistondyn/mapping/ForceMap.h"

namespace pm = pistondyn::mapping;
using pistondyn::test::expectInvalidArgument;
using pm::test::kPi;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Integrals of p_h * {1, s, y} (s = R_source * phi in the target frame) over the part of
// the source inside [phiLo, phiHi] x [yLo, yHi] (target frame). The source is a sector
// that the tests place so that no 2*pi aliasing occurs.
struct Integrals {
  double force = 0.0, momentS = 0.0, momentY = 0.0;
};

Integrals integrateSource(const pm::CylinderGrid& src, const Eigen::VectorXd& p, pm::GridOffset off,
                          double phiLo, double phiHi, double yLo, double yHi) {
  const double r = src.radius_m();
  Integrals out;
  pm::test::forEachClippedCell(
      src.phi_rad(), src.y_m(), off.phi_rad, off.y_m, phiLo, phiHi, yLo, yHi,
      [&](int i, int j, std::array<double, 4> cell, std::array<double, 4> clip) {
        const double a = cell[0], b = cell[1], c = cell[2], d = cell[3];
        const double lo = clip[0], hi = clip[1], ylo = clip[2], yhi = clip[3];
        const double f00 = p[src.index(i, j)], f10 = p[src.index(i + 1, j)],
                     f01 = p[src.index(i, j + 1)], f11 = p[src.index(i + 1, j + 1)];
        auto ph = [&](double x, double y) {
          return pm::test::bilinear(a, b, c, d, f00, f10, f01, f11, x, y);
        };
        out.force += r * pm::test::integrateRectangle(lo, hi, ylo, yhi, 3, 3, ph);
        out.momentS +=
            r * pm::test::integrateRectangle(lo, hi, ylo, yhi, 3, 3,
                                             [&](double x, double y) { return r * x * ph(x, y); });
        out.momentY +=
            r * pm::test::integrateRectangle(lo, hi, ylo, yhi, 3, 3,
                                             [&](double x, double y) { return y * ph(x, y); });
      });
  return out;
}

// Target-side sums: sum F_J, sum s_J F_J, sum y_J F_J, with s_J = R_source * phi_J taken
// on the turn nearest to `phiCentre` (for a full-circle target, whose node angles are
// only defined modulo 2*pi).
Integrals sumTarget(const pm::CylinderGrid& tgt, const Eigen::VectorXd& f, double rSource,
                    double phiCentre) {
  Integrals out;
  for (int j = 0; j < tgt.nY(); ++j)
    for (int i = 0; i < tgt.nPhi(); ++i) {
      double phi = tgt.phi_rad()[i];
      if (tgt.isClosed())
        phi += 2 * kPi * std::round((phiCentre - phi) / (2 * kPi));
      const double fj = f[tgt.index(i, j)];
      out.force += fj;
      out.momentS += rSource * phi * fj;
      out.momentY += tgt.y_m()[j] * fj;
    }
  return out;
}

// One random source/target pair with an offset.
struct Pair {
  pm::CylinderGrid source, target;
  pm::GridOffset offset;
};

Pair randomPair(std::mt19937& rng, bool closedTarget) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const double r = 0.0325;
  const double sw = 0.2 + u(rng), s0 = -0.5 * sw + 0.4 * (u(rng) - 0.5);
  const double sl = 0.01 + 0.03 * u(rng);
  const pm::CylinderGrid src =
      pm::CylinderGrid::sector(r, pm::test::randomNodes(rng, s0, s0 + sw, pick(2, 64)),
                               pm::test::randomNodes(rng, 0.0, sl, pick(2, 48)));
  if (closedTarget) {
    const double phi0 = -kPi + 2 * kPi * u(rng);
    const int n = pick(6, 40);
    const pm::CylinderGrid tgt = pm::CylinderGrid::fullCircle(
        r, pm::test::randomNodes(rng, phi0, phi0 + 2 * kPi * (1.0 - 0.5 / n), n),
        pm::test::randomNodes(rng, -0.02, 0.12, pick(2, 100)));
    return {src, tgt, {1.6 * (u(rng) - 0.5), -0.04 + 0.15 * u(rng)}};
  }
  const double tw = 0.3 + 1.7 * u(rng), t0 = -0.5 * tw + (u(rng) - 0.5);
  const double ty0 = -0.01 + 0.02 * u(rng), ty1 = ty0 + 0.01 + 0.04 * u(rng);
  const pm::CylinderGrid tgt =
      pm::CylinderGrid::sector(r, pm::test::randomNodes(rng, t0, t0 + tw, pick(2, 20)),
                               pm::test::randomNodes(rng, ty0, ty1, pick(2, 30)));
  return {src, tgt, {1.6 * (u(rng) - 0.5), -0.02 + 0.05 * u(rng)}};
}

// Target rectangle for the reference integration (a full circle does not clip phi).
std::array<double, 4> targetRectangle(const pm::CylinderGrid& t) {
  const double phiLo = t.isClosed() ? -kInf : t.phi_rad()[0];
  const double phiHi = t.isClosed() ? kInf : t.phiEnd_rad();
  return {phiLo, phiHi, t.y_m()[0], t.y_m()[t.nY() - 1]};
}

Eigen::VectorXd absolute(const Eigen::VectorXd& v) {
  return v.cwiseAbs();
}

}  // namespace

// Static equivalence on the developed surface. A traction (normal t_n, circumferential
// t_s, axial t_y) is mapped component by component; forces F = (F_s, F_y, F_n) and the
// moments about the target frame's origin
//   M_s = int y t_n,  M_y = -int s t_n,  M_n = int (s t_y - y t_s)
// must agree between the target nodal forces and the source field over the overlapped
// region, to 1e-12 of the magnitude scale (the same integrals of |t|, times the largest
// |s| or |y| of the source for moments: rounding is relative to the summed magnitudes,
// not to a possibly cancelling result). 60 random pairs: sizes 2..64 x 2..48 onto 2..20 x 2..30
// sectors or 6..40 x 2..100 full circles, graded up to 1:3, offsets giving full and partial
// overlaps.
TEST(ForceMap, StaticEquivalenceOnRandomGridPairs) {
  std::mt19937 rng(11);
  int partial = 0, full = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Pair pr = randomPair(rng, trial % 2 == 1);
    const pm::CylinderGrid& src = pr.source;
    const pm::CylinderGrid& tgt = pr.target;
    const int ns = src.nodeCount();
    const Eigen::VectorXd tn = pm::test::randomVector(rng, ns, 0.0, 2e6);  // pressure >= 0
    const Eigen::VectorXd ts = pm::test::randomVector(rng, ns, -3e4, 3e4);
    const Eigen::VectorXd ty = pm::test::randomVector(rng, ns, -3e4, 3e4);

    const pm::ForceMap map(src, tgt, pr.offset);
    Eigen::VectorXd fn(tgt.nodeCount()), fs(tgt.nodeCount()), fy(tgt.nodeCount());
    const pm::LoadBalance bn = map.apply(tn, fn);
    const pm::LoadBalance bs = map.apply(ts, fs);
    const pm::LoadBalance by = map.apply(ty, fy);

    const std::array<double, 4> rect = targetRectangle(tgt);
    const double phiLo = rect[0], phiHi = rect[1], yLo = rect[2], yHi = rect[3];
    auto inside = [&](const Eigen::VectorXd& p) {
      return integrateSource(src, p, pr.offset, phiLo, phiHi, yLo, yHi);
    };
    auto whole = [&](const Eigen::VectorXd& p) {
      return integrateSource(src, p, pr.offset, -kInf, kInf, -kInf, kInf);
    };
    const Integrals rn = inside(tn), rs = inside(ts), ry = inside(ty);
    const Integrals an = inside(absolute(tn)), as = inside(absolute(ts)), ay = inside(absolute(ty));
    const double centre = 0.5 * (src.phi_rad()[0] + src.phiEnd_rad()) + pr.offset.phi_rad;
    const double r = src.radius_m();
    const Integrals gn = sumTarget(tgt, fn, r, centre), gs = sumTarget(tgt, fs, r, centre),
                    gy = sumTarget(tgt, fy, r, centre);
    // Largest |s| and |y| of the source in the target frame: the moment arms.
    const double lever = std::max({std::abs(r * (src.phi_rad()[0] + pr.offset.phi_rad)),
                                   std::abs(r * (src.phiEnd_rad() + pr.offset.phi_rad)),
                                   std::abs(src.y_m()[0] + pr.offset.y_m),
                                   std::abs(src.y_m()[src.nY() - 1] + pr.offset.y_m)});

    const Integrals wn = whole(tn);
    const double wholeScaleN = whole(absolute(tn)).force, wholeScaleS = whole(absolute(ts)).force,
                 wholeScaleY = whole(absolute(ty)).force;
    (wn.force > rn.force * (1 + 1e-9) ? partial : full)++;
    SCOPED_TRACE(::testing::Message()
                 << "trial " << trial << " source " << src.nPhi() << "x" << src.nY() << " target "
                 << tgt.nPhi() << "x" << tgt.nY() << (tgt.isClosed() ? " closed" : " sector"));
    // Forces.
    EXPECT_NEAR(gn.force, rn.force, 1e-12 * an.force);
    EXPECT_NEAR(gs.force, rs.force, 1e-12 * as.force);
    EXPECT_NEAR(gy.force, ry.force, 1e-12 * ay.force);
    // Moments about the three axes of the developed frame.
    EXPECT_NEAR(gn.momentY, rn.momentY, 1e-12 * an.force * lever);    // M_s
    EXPECT_NEAR(-gn.momentS, -rn.momentS, 1e-12 * an.force * lever);  // M_y
    EXPECT_NEAR(gy.momentS - gs.momentY, ry.momentS - rs.momentY,     // M_n
                1e-12 * (ay.force + as.force) * lever);
    // Bookkeeping: whole source = mapped + unmapped, each against the reference.
    EXPECT_NEAR(bn.sourceTotal_N, wn.force, 1e-12 * wholeScaleN);
    EXPECT_NEAR(bn.unmapped_N, wn.force - rn.force, 1e-12 * wholeScaleN);
    EXPECT_NEAR(bn.mapped_N(), gn.force, 1e-12 * wholeScaleN);
    EXPECT_NEAR(bs.mapped_N(), gs.force, 1e-12 * wholeScaleS);
    EXPECT_NEAR(by.mapped_N(), gy.force, 1e-12 * wholeScaleY);
  }
  // Both kinds of overlap really occurred.
  EXPECT_GE(partial, 10);
  EXPECT_GE(full, 10);
}

// A uniform pressure maps to exactly its area integral (closed form R * dphi * dy of the
// overlap), and, where the source covers the target, every target node receives p times
// its shape function's integral (the trapezoid weights, closed form here).
TEST(ForceMap, UniformPressureMapsToItsAreaIntegral) {
  std::mt19937 rng(12);
  const double r = 0.0325, p = 2.5e5;
  const auto src = pm::CylinderGrid::sector(r, pm::test::randomNodes(rng, -0.8, 0.8, 64),
                                            pm::test::randomNodes(rng, 0.0, 0.04, 48));
  // Target fully covered: 17 x 30 structural grid inside the contact grid.
  const Eigen::VectorXd tPhi = pm::test::randomNodes(rng, -0.5, 0.6, 17);
  const Eigen::VectorXd tY = pm::test::randomNodes(rng, 0.0, 0.03, 30);
  const auto tgt = pm::CylinderGrid::sector(r, tPhi, tY);
  const pm::GridOffset off{0.1, -0.005};  // source covers [-0.7, 0.9] x [-0.005, 0.035]
  const pm::ForceMap map(src, tgt, off);
  Eigen::VectorXd f(tgt.nodeCount());
  const pm::LoadBalance b = map.apply(Eigen::VectorXd::Constant(src.nodeCount(), p), f);
  const double overlap = r * 1.1 * 0.03;
  EXPECT_NEAR(f.sum(), p * overlap, 1e-13 * p * overlap);
  EXPECT_NEAR(b.sourceTotal_N, p * r * 1.6 * 0.04, 1e-13 * p * r * 1.6 * 0.04);
  for (int j = 0; j < tgt.nY(); ++j)
    for (int i = 0; i < tgt.nPhi(); ++i) {
      const double wPhi = 0.5 * ((i > 0 ? tPhi[i] - tPhi[i - 1] : 0.0) +
                                 (i + 1 < tgt.nPhi() ? tPhi[i + 1] - tPhi[i] : 0.0));
      const double wY =
          0.5 * ((j > 0 ? tY[j] - tY[j - 1] : 0.0) + (j + 1 < tgt.nY() ? tY[j + 1] - tY[j] : 0.0));
      EXPECT_NEAR(f[tgt.index(i, j)], p * r * wPhi * wY, 1e-13 * p * r * wPhi * wY);
    }
}

namespace {
// 1-D consistent mass matrix of hat functions, assembled from the element matrices
// h/6 [[2, 1], [1, 2]] (closed: the ring's last element joins node n-1 to node 0).
Eigen::MatrixXd massMatrix1D(const Eigen::VectorXd& x, bool closed) {
  const int n = static_cast<int>(x.size());
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  const int cells = closed ? n : n - 1;
  for (int c = 0; c < cells; ++c) {
    const int a = c, b = (c + 1) % n;
    const double h = (c + 1 < n ? x[c + 1] : x[0] + 2 * kPi) - x[c];
    m(a, a) += h / 3;
    m(b, b) += h / 3;
    m(a, b) += h / 6;
    m(b, a) += h / 6;
  }
  return m;
}

// 2-D consistent mass matrix R * kron(M_y, M_phi), applied to p.
Eigen::VectorXd consistentLoads(const pm::CylinderGrid& g, const Eigen::VectorXd& p) {
  const Eigen::MatrixXd mPhi = massMatrix1D(g.phi_rad(), g.isClosed());
  const Eigen::MatrixXd mY = massMatrix1D(g.y_m(), false);
  const Eigen::Map<const Eigen::MatrixXd> pm_(p.data(), g.nPhi(), g.nY());
  const Eigen::MatrixXd f = g.radius_m() * mPhi * pm_ * mY.transpose();
  return Eigen::Map<const Eigen::VectorXd>(f.data(), f.size());
}
}  // namespace

// Mapping onto the same grid gives the consistent loads: the consistent mass matrix
// (assembled here from element matrices) times the nodal pressures. Sector and full circle.
TEST(ForceMap, SameGridGivesTheConsistentLoad) {
  std::mt19937 rng(13);
  const double r = 0.0325;
  const std::array<pm::CylinderGrid, 2> grids = {
      pm::CylinderGrid::sector(r, pm::test::randomNodes(rng, -0.6, 0.7, 23),
                               pm::test::randomNodes(rng, 0.0, 0.03, 19)),
      pm::CylinderGrid::fullCircle(r, pm::test::randomNodes(rng, 0.2, 6.0, 29),
                                   pm::test::randomNodes(rng, 0.0, 0.1, 41))};
  for (const auto& g : grids) {
    const Eigen::VectorXd p = pm::test::randomVector(rng, g.nodeCount(), 0.0, 1e6);
    const pm::ForceMap map(g, g, {});
    Eigen::VectorXd f(g.nodeCount());
    const pm::LoadBalance b = map.apply(p, f);
    const Eigen::VectorXd expected = consistentLoads(g, p);
    EXPECT_LE((f - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
    EXPECT_EQ(b.unmapped_N, 0.0);
  }
}

// The thesis' "half grid near the node" read literally (LoadRule::HalfCell: integrate
// p_h over each target node's tributary half-cells) is a lumped load. For a pressure
// linear in s and y on a graded grid (same grid as source and target):
// - uniform pressure: identical to the consistent load (both p * trapezoid weight);
// - total force: exact (reference: closed-form integral of the linear pressure);
// - moment int s p dA: the consistent load is exact, the half-cell load is off by exactly
//   sum_J int_{D_J} (s_J - s) p dA over the half-cell rectangles D_J (reference: that sum
//   by Gauss quadrature, exact for the quadratic integrand), which is not small.
TEST(ForceMap, HalfCellLoadConservesForceButNotMoment) {
  std::mt19937 rng(14);
  const double r = 0.0325;
  const Eigen::VectorXd phi = pm::test::randomNodes(rng, -0.5, 0.5, 9);
  const Eigen::VectorXd y = pm::test::randomNodes(rng, 0.0, 0.03, 7);
  const auto g = pm::CylinderGrid::sector(r, phi, y);
  const double a = 3e5, bs = 4e7, cy = -1e7;  // p = a + bs*s + cy*y [Pa], s = r*phi
  Eigen::VectorXd p(g.nodeCount());
  for (int j = 0; j < g.nY(); ++j)
    for (int i = 0; i < g.nPhi(); ++i)
      p[g.index(i, j)] = a + bs * r * phi[i] + cy * y[j];

  const pm::ForceMap consistent(g, g, {}), halfCell(g, g, {}, pm::LoadRule::HalfCell);
  Eigen::VectorXd fc(g.nodeCount()), fh(g.nodeCount());
  Eigen::VectorXd uniform = Eigen::VectorXd::Constant(g.nodeCount(), a);
  (void)consistent.apply(uniform, fc);
  (void)halfCell.apply(uniform, fh);
  EXPECT_LE((fc - fh).cwiseAbs().maxCoeff(), 1e-13 * fc.cwiseAbs().maxCoeff());

  (void)consistent.apply(p, fc);
  (void)halfCell.apply(p, fh);
  auto pAt = [&](double s, double yy) { return a + bs * s + cy * yy; };
  const double s0 = r * phi[0], s1 = r * phi[g.nPhi() - 1], y0 = y[0], y1 = y[g.nY() - 1];
  const double force = pm::test::integrateRectangle(s0, s1, y0, y1, 2, 2, pAt);
  const double momentS = pm::test::integrateRectangle(
      s0, s1, y0, y1, 2, 2, [&](double s, double yy) { return s * pAt(s, yy); });
  EXPECT_NEAR(fc.sum(), force, 1e-13 * force);
  EXPECT_NEAR(fh.sum(), force, 1e-13 * force);
  double mc = 0.0, mh = 0.0, halfCellError = 0.0;
  for (int j = 0; j < g.nY(); ++j)
    for (int i = 0; i < g.nPhi(); ++i) {
      const double sJ = r * phi[i];
      mc += sJ * fc[g.index(i, j)];
      mh += sJ * fh[g.index(i, j)];
      const double dl = r * (i > 0 ? 0.5 * (phi[i - 1] + phi[i]) : phi[0]);
      const double dr = r * (i + 1 < g.nPhi() ? 0.5 * (phi[i] + phi[i + 1]) : phi[i]);
      const double yl = j > 0 ? 0.5 * (y[j - 1] + y[j]) : y[0];
      const double yr = j + 1 < g.nY() ? 0.5 * (y[j] + y[j + 1]) : y[j];
      halfCellError += pm::test::integrateRectangle(
          dl, dr, yl, yr, 2, 2, [&](double s, double yy) { return (sJ - s) * pAt(s, yy); });
    }
  const double scale = std::abs(momentS);
  EXPECT_NEAR(mc, momentS, 1e-12 * scale);
  EXPECT_NEAR(mh - momentS, halfCellError, 1e-12 * scale);
  EXPECT_GT(std::abs(halfCellError), 1e-4 * scale);  // a real, not a rounding, difference
}

// Source regions outside the target are reported, not dropped: closed-form areas of a
// uniform pressure with partial overlap in both phi and y; the per-node unmapped areas sum
// to the outside area; the tensor path reports the same.
TEST(ForceMap, PartialOverlapReportsTheUnmappedForce) {
  const double r = 0.0325, p = 1.0e6;
  const auto src =
      pm::CylinderGrid::sector(r, pm::uniformNodes(-0.3, 0.3, 13), pm::uniformNodes(0.0, 0.03, 11));
  const auto tgt =
      pm::CylinderGrid::sector(r, pm::uniformNodes(-0.5, 0.1, 7), pm::uniformNodes(0.01, 0.05, 9));
  const double whole = r * 0.6 * 0.03, overlap = r * 0.4 * 0.02;
  const pm::ForceMap map(src, tgt, {});
  Eigen::VectorXd f(tgt.nodeCount());
  const pm::LoadBalance b = map.apply(Eigen::VectorXd::Constant(src.nodeCount(), p), f);
  EXPECT_NEAR(b.sourceTotal_N, p * whole, 1e-13 * p * whole);
  EXPECT_NEAR(b.unmapped_N, p * (whole - overlap), 1e-13 * p * whole);
  EXPECT_NEAR(f.sum(), p * overlap, 1e-13 * p * whole);
  EXPECT_NEAR(map.unmappedArea_m2().sum(), whole - overlap, 1e-13 * whole);
  EXPECT_NEAR(map.sourceArea_m2().sum(), whole, 1e-13 * whole);

  const pm::TensorForceMap tensor(src, tgt, 0.0);
  pm::TensorForceMap::Workspace ws;
  tensor.setAxialOffset(0.0, ws);
  Eigen::VectorXd ft(tgt.nodeCount());
  const pm::LoadBalance bt = tensor.apply(ws, Eigen::VectorXd::Constant(src.nodeCount(), p), ft);
  EXPECT_NEAR(bt.unmapped_N, b.unmapped_N, 1e-13 * p * whole);
  EXPECT_NEAR(bt.sourceTotal_N, b.sourceTotal_N, 1e-13 * p * whole);

  // Entirely outside: everything unmapped, nothing mapped.
  const pm::ForceMap away(src, tgt, {0.0, 0.2});
  const pm::LoadBalance ba = away.apply(Eigen::VectorXd::Constant(src.nodeCount(), p), f);
  EXPECT_EQ(f.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_NEAR(ba.unmapped_N, p * whole, 1e-13 * p * whole);
}

// The liner path: a 64 x 48 contact field onto a 36 x 400 full-circle liner while the
// piston moves (partly beyond both liner ends at the extremes). Updating only the axial
// factor in one reused workspace must give the same forces and balance as a ForceMap
// rebuilt from scratch at every offset, to 1e-13.
// What this does and does not check: the ForceMap is assembled from the same
// TensorForceMap / calcHatOverlap1D factors (as kron(A_y, A_phi)), so the reference is not
// independent of the 1-D integrals. It checks the Kronecker assembly against the tensor
// application and the reuse of one workspace across offsets (no stale state). The 1-D
// integrals themselves are checked independently, against Gauss integration of the
// clipped source cells, by ForceMap.StaticEquivalenceOnRandomGridPairs and the other
// tests of this file.
TEST(TensorForceMap, AxialUpdateEqualsFullRebuild) {
  std::mt19937 rng(15);
  const double r = 0.0325;
  const auto contact = pm::CylinderGrid::sector(r, pm::uniformNodes(-0.7, 0.7, 64),
                                                pm::test::randomNodes(rng, 0.0, 0.03, 48, 1.5));
  const auto liner = pm::CylinderGrid::fullCircle(r, pm::fullCircleNodes_rad(36, -0.05),
                                                  pm::uniformNodes(0.0, 0.12, 400));
  const Eigen::VectorXd p = pm::test::randomVector(rng, contact.nodeCount(), 0.0, 2e6);
  const double phiOffset = 0.05;
  const pm::TensorForceMap tensor(contact, liner, phiOffset);
  pm::TensorForceMap::Workspace ws;
  Eigen::VectorXd ft(liner.nodeCount()), ff(liner.nodeCount());
  for (int step = 0; step <= 24; ++step) {
    const double yOffset = -0.01 + 0.11 * step / 24.0;  // 0.1 + 0.03 > 0.12: beyond the top
    tensor.setAxialOffset(yOffset, ws);
    const pm::LoadBalance bt = tensor.apply(ws, p, ft);
    const pm::ForceMap full(contact, liner, {phiOffset, yOffset});
    const pm::LoadBalance bf = full.apply(p, ff);
    const double scale = ff.cwiseAbs().maxCoeff();
    EXPECT_LE((ft - ff).cwiseAbs().maxCoeff(), 1e-13 * scale) << "step " << step;
    EXPECT_NEAR(bt.sourceTotal_N, bf.sourceTotal_N, 1e-13 * bf.sourceTotal_N);
    EXPECT_NEAR(bt.unmapped_N, bf.unmapped_N, 1e-13 * bf.sourceTotal_N);
  }
}

// Windowed paths (issue 5's liner step): accumulate() and accumulateTraction() add into
// full-size liner vectors and touch only the rows ws.rows. Two skirt sides (thrust at
// phi = 0.05, anti-thrust at phi = pi + 0.05) add into one load vector over 25 piston
// positions, partly beyond both liner ends at the extremes. References:
// - scalar: ForceMap rebuilt at every offset (independent sparse assembly), 1e-13;
// - traction: the full applyTraction (checked against direct Gauss integration of the
//   3-D traction in test_force_map_cylinder.cpp), 1e-13 of the largest nodal force;
// - entries outside the window: bit-for-bit untouched (sentinel values); the full paths
//   are exactly 0 there, so the window holds every non-zero load; its first and last rows
//   carry load (the window is tight).
TEST(TensorForceMap, WindowedAccumulateEqualsFullPath) {
  std::mt19937 rng(16);
  const double r = 0.0325;
  const auto contact = pm::CylinderGrid::sector(r, pm::uniformNodes(-0.7, 0.7, 64),
                                                pm::test::randomNodes(rng, 0.0, 0.03, 48, 1.5));
  const auto liner = pm::CylinderGrid::fullCircle(r, pm::fullCircleNodes_rad(36, -0.05),
                                                  pm::uniformNodes(0.0, 0.12, 400));
  const int ns = contact.nodeCount(), nt = liner.nodeCount(), ntPhi = liner.nPhi();
  std::vector<Eigen::VectorXd> pn, ps, py;
  for (int side = 0; side < 2; ++side) {
    pn.push_back(pm::test::randomVector(rng, ns, 1e5, 2e6));  // > 0: every row is loaded
    ps.push_back(pm::test::randomVector(rng, ns, -2e4, 2e4));
    py.push_back(pm::test::randomVector(rng, ns, -1e5, 1e5));
  }
  const pm::TensorForceMap thrust(contact, liner, 0.05), antiThrust(contact, liner, kPi + 0.05);
  const pm::TensorForceMap* sides[2] = {&thrust, &antiThrust};
  pm::TensorForceMap::Workspace ws[2];
  const Eigen::VectorXd sentinel = pm::test::randomVector(rng, nt, -1e3, 1e3);
  for (int step = 0; step <= 24; ++step) {
    const double yOffset = -0.01 + 0.11 * step / 24.0;
    Eigen::VectorXd full = Eigen::VectorXd::Zero(nt), fx = full, fy = full, fz = full;
    Eigen::VectorXd acc = sentinel, ax = sentinel, ay = sentinel, az = sentinel;
    Eigen::VectorXd one(nt), ox(nt), oy(nt), oz(nt);
    for (int k = 0; k < 2; ++k) {
      sides[k]->setAxialOffset(yOffset, ws[k]);
      const pm::ForceMap rebuilt(contact, liner, {sides[k]->phiOffset_rad(), yOffset});
      const pm::LoadBalance bFull = rebuilt.apply(pn[k], one);
      full += one;
      const pm::CartesianLoadBalance tFull =
          sides[k]->applyTraction(ws[k], pn[k], ps[k], py[k], ox, oy, oz);
      fx += ox;
      fy += oy;
      fz += oz;
      // The full paths are exactly zero outside the window.
      const pm::TensorForceMap::RowWindow w = ws[k].rows;
      ASSERT_GT(w.count, 0) << "step " << step;
      for (int j = 0; j < liner.nY(); ++j) {
        const bool inside = j >= w.first && j < w.end();
        const double rowMax = std::max({one.segment(ntPhi * j, ntPhi).cwiseAbs().maxCoeff(),
                                        ox.segment(ntPhi * j, ntPhi).cwiseAbs().maxCoeff(),
                                        oy.segment(ntPhi * j, ntPhi).cwiseAbs().maxCoeff()});
        if (!inside) {
          ASSERT_EQ(rowMax, 0.0) << "step " << step << " row " << j;
        } else if (j == w.first || j == w.end() - 1) {
          EXPECT_GT(rowMax, 0.0) << "window not tight: step " << step << " row " << j;
        }
      }
      const pm::LoadBalance bAcc = sides[k]->accumulate(ws[k], pn[k], acc);
      const pm::CartesianLoadBalance tAcc =
          sides[k]->accumulateTraction(ws[k], pn[k], ps[k], py[k], ax, ay, az);
      EXPECT_NEAR(bAcc.sourceTotal_N, bFull.sourceTotal_N, 1e-13 * bFull.sourceTotal_N);
      EXPECT_NEAR(bAcc.unmapped_N, bFull.unmapped_N, 1e-13 * bFull.sourceTotal_N);
      EXPECT_EQ(tAcc.sourceTotal_N, tFull.sourceTotal_N);
      EXPECT_EQ(tAcc.unmapped_N, tFull.unmapped_N);
    }
    // Rows neither side reaches keep their sentinel values bit for bit.
    auto touched = [&](int j) {
      for (const auto& w : ws)
        if (j >= w.rows.first && j < w.rows.end())
          return true;
      return false;
    };
    for (int j = 0; j < liner.nY(); ++j)
      if (!touched(j))
        for (int i = 0; i < ntPhi; ++i) {
          const int n = i + ntPhi * j;
          ASSERT_EQ(acc[n], sentinel[n]);
          ASSERT_EQ(ax[n], sentinel[n]);
          ASSERT_EQ(ay[n], sentinel[n]);
          ASSERT_EQ(az[n], sentinel[n]);
        }
    const double scale = full.cwiseAbs().maxCoeff();
    EXPECT_LE((acc - sentinel - full).cwiseAbs().maxCoeff(), 1e-13 * scale) << "step " << step;
    EXPECT_LE((ax - sentinel - fx).cwiseAbs().maxCoeff(), 1e-13 * scale) << "step " << step;
    EXPECT_LE((ay - sentinel - fy).cwiseAbs().maxCoeff(), 1e-13 * scale) << "step " << step;
    EXPECT_LE((az - sentinel - fz).cwiseAbs().maxCoeff(), 1e-13 * scale) << "step " << step;
  }
  // No overlap at all: an empty window, nothing written, everything unmapped.
  pm::TensorForceMap::Workspace far;
  thrust.setAxialOffset(0.5, far);
  EXPECT_EQ(far.rows.count, 0);
  Eigen::VectorXd untouched = sentinel;
  const pm::LoadBalance b = thrust.accumulate(far, pn[0], untouched);
  EXPECT_EQ(untouched, sentinel);
  EXPECT_NEAR(b.unmapped_N, b.sourceTotal_N, 1e-13 * b.sourceTotal_N);
}

// A workspace carries the axial factor of the map that filled it. Used with a map whose
// target has the same sizes but other axial nodes it used to be accepted silently (the
// forces were those of the wrong axial factor); now it throws naming `ws`. A map with the
// same axial nodes and rule (here the other skirt side, another phi offset) builds the same
// A_y and may share it: reference, its own freshly set workspace (bit-identical result).
TEST(TensorForceMap, WorkspaceOfAnotherMapIsRejected) {
  const double r = 0.0325;
  const auto src =
      pm::CylinderGrid::sector(r, pm::uniformNodes(-0.3, 0.3, 5), pm::uniformNodes(0.0, 0.03, 4));
  const auto tgtA =
      pm::CylinderGrid::sector(r, pm::uniformNodes(-0.5, 0.5, 3), pm::uniformNodes(0.0, 0.05, 3));
  const auto tgtB = pm::CylinderGrid::sector(r, pm::uniformNodes(-0.5, 0.5, 3),
                                             pm::uniformNodes(0.04, 0.09, 3));  // same sizes
  const pm::TensorForceMap mapA(src, tgtA, 0.0), mapB(src, tgtB, 0.0), mapA2(src, tgtA, 0.1);
  const Eigen::VectorXd p = Eigen::VectorXd::Ones(src.nodeCount());
  Eigen::VectorXd f(tgtA.nodeCount()), f2(tgtA.nodeCount());
  pm::TensorForceMap::Workspace wsA;
  mapA.setAxialOffset(0.0, wsA);
  expectInvalidArgument([&] { (void)mapB.apply(wsA, p, f); },
                        "ws holds the axial factor of another map");
  expectInvalidArgument([&] { (void)mapB.accumulate(wsA, p, f); },
                        "TensorForceMap::accumulate: ws");
  expectInvalidArgument([&] { (void)mapB.applyTraction(wsA, p, p, p, f, f, f); },
                        "applyTraction: ws");
  // Other load rule, same nodes: another A_y, rejected too.
  const pm::TensorForceMap halfCell(src, tgtA, 0.0, pm::LoadRule::HalfCell);
  expectInvalidArgument([&] { (void)halfCell.apply(wsA, p, f); }, "ws");
  // Same axial nodes and rule: shared legitimately.
  pm::TensorForceMap::Workspace ws2;
  mapA2.setAxialOffset(0.0, ws2);
  (void)mapA2.apply(wsA, p, f);
  (void)mapA2.apply(ws2, p, f2);
  EXPECT_EQ(f, f2);
}

TEST(ForceMap, RejectsBadInputNamingTheArgument) {
  const double r = 0.0325;
  const auto src =
      pm::CylinderGrid::sector(r, pm::uniformNodes(-0.3, 0.3, 5), pm::uniformNodes(0.0, 0.03, 4));
  const auto tgt =
      pm::CylinderGrid::sector(r, pm::uniformNodes(-0.5, 0.5, 3), pm::uniformNodes(0.0, 0.05, 3));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectInvalidArgument([&] { pm::ForceMap(src, tgt, {nan, 0.0}); }, "sourceInTarget.phi_rad");
  expectInvalidArgument([&] { pm::ForceMap(src, tgt, {0.0, nan}); }, "sourceInTarget.y_m");
  const pm::ForceMap map(src, tgt, {});
  Eigen::VectorXd p = Eigen::VectorXd::Ones(src.nodeCount()), f(tgt.nodeCount());
  p[7] = nan;
  expectInvalidArgument([&] { (void)map.apply(p, f); }, "sourcePressure_Pa[7]");
  expectInvalidArgument([&] { (void)map.apply(Eigen::VectorXd::Ones(3), f); },
                        "sourcePressure_Pa has 3");
  Eigen::VectorXd wrong(4);
  expectInvalidArgument([&] { (void)map.apply(Eigen::VectorXd::Ones(src.nodeCount()), wrong); },
                        "targetForce_N has 4");

  const pm::TensorForceMap tensor(src, tgt, 0.0);
  pm::TensorForceMap::Workspace ws;
  expectInvalidArgument([&] { (void)tensor.apply(ws, Eigen::VectorXd::Ones(src.nodeCount()), f); },
                        "setAxialOffset");
  expectInvalidArgument([&] { tensor.setAxialOffset(nan, ws); }, "yOffset_m");
  expectInvalidArgument([&] { pm::TensorForceMap(src, tgt, nan); }, "phiOffset_rad");
  // Absurd angles throw (reducing 1e300 modulo 2*pi keeps no digit).
  expectInvalidArgument([&] { pm::TensorForceMap(src, tgt, 1e300); }, "phiOffset_rad");
  expectInvalidArgument([&] { pm::ForceMap(src, tgt, {-1e300, 0.0}); }, "sourceInTarget.phi_rad");
}

// The 1-D building block checks its own arguments (it is public).
TEST(HatOverlap1D, RejectsBadNodesNamingTheArgument) {
  pm::HatOverlap1D out;
  Eigen::VectorXd good = pm::uniformNodes(0.0, 1.0, 5), bad = good;
  bad[3] = bad[2];
  expectInvalidArgument(
      [&] {
        pm::calcHatOverlap1D(bad, false, good, false, 0.0, 0.0, pm::LoadRule::Consistent, false,
                             out);
      },
      "sourceNodes[3]");
  expectInvalidArgument(
      [&] {
        pm::calcHatOverlap1D(good, false, Eigen::VectorXd::Zero(1), false, 0.0, 0.0,
                             pm::LoadRule::Consistent, false, out);
      },
      "targetNodes has 1 nodes");
  expectInvalidArgument(
      [&] {
        pm::calcHatOverlap1D(good, true, good, false, 0.0, 0.0, pm::LoadRule::Consistent, false,
                             out);
      },
      "period");
  expectInvalidArgument(
      [&] {
        pm::calcHatOverlap1D(pm::uniformNodes(0.0, 0.4, 3), false, good, true, 0.5, 0.0,
                             pm::LoadRule::Consistent, false, out);
      },
      "targetNodes spans");
}
