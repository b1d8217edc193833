// h_skirtProfile: axial profile (barrel) and ovality.
// References: the closed-form elliptic law and the exact ellipse radius; the closed-form
// parabola of a barrel profile, exact at the table rows and within the derived PCHIP bound
// between them (slope error <= f'' h, Hermite basis: value error <= f'' h^2 / 4); the mirror
// identity drop_mirrored(y) = parabola(-y); symmetry of a tabulated ovality about both axes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "SkirtTestSupport.h"
#include "pistondyn/skirt/SkirtProfile.h"

namespace ps = pistondyn::skirt;
using ps::test::kPi;

namespace {

TEST(Ovality, EllipticLawGivesHalfTheOvalityOnThePinAxisAndNothingOnTheThrustAxis) {
  ps::OvalityParameters p;
  p.diametralOvality_m = 40e-6;
  const ps::Ovality ov(p, kPi / 6);
  EXPECT_EQ(ov.calcDrop_m(0.0), 0.0);
  EXPECT_NEAR(ov.calcDrop_m(kPi / 2), 20e-6, 1e-20);
  EXPECT_NEAR(ov.calcDrop_m(-kPi / 2), 20e-6, 1e-20);
  EXPECT_NEAR(ov.calcDrop_m(kPi), 0.0, 1e-20);  // anti-thrust axis
  EXPECT_NEAR(ov.calcDrop_m(kPi / 4), 10e-6, 1e-20);
  EXPECT_NEAR(ov.calcDrop_m(kPi + kPi / 6), 40e-6 / 4 * 0.5, 1e-20);
  // Against the exact ellipse with diameters D (thrust) and D - Ov (pin): to first order in
  // Ov / D the same; the difference is O(Ov^2 / D) (2.2e-8 m here).
  const double D = 0.074, a = D / 2, b = (D - 40e-6) / 2;
  for (int s = 0; s <= 90; s += 5) {
    const double ph = s * kPi / 180;
    const double r = a * b / std::hypot(b * std::cos(ph), a * std::sin(ph));
    EXPECT_NEAR(ov.calcDrop_m(ph), a - r, 40e-6 * 40e-6 / D) << s << " deg";
  }
}

TEST(Ovality, Cos4CoefficientChangesTheFlanksOnly) {
  for (double k : {-0.5, -0.2, 0.3, 0.5}) {
    ps::OvalityParameters p;
    p.diametralOvality_m = 30e-6;
    p.cos4Coefficient = k;
    const ps::Ovality ov(p, 0.5);
    EXPECT_NEAR(ov.calcDrop_m(0.0), 0.0, 1e-21);
    EXPECT_NEAR(ov.calcDrop_m(kPi / 2), 15e-6, 1e-20);                // Ov/2 for every k
    EXPECT_NEAR(ov.calcDrop_m(kPi / 4), (1 + k) * 30e-6 / 4, 1e-20);  // (1 + k) Ov/4
    double previous = -1.0;
    for (int s = 0; s <= 900; ++s) {  // monotone from the thrust axis to the pin axis
      const double d = ov.calcDrop_m(s * kPi / 1800);
      EXPECT_GE(d, previous - 1e-21) << "k = " << k << " at " << s / 10.0 << " deg";
      previous = d;
    }
  }
}

TEST(Ovality, TableIsSymmetricAboutBothAxesAndExactAtItsRows) {
  // The elliptic law sampled at 10 rows over one quadrant.
  const double ov = 40e-6;
  Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(10, 0.0, kPi / 2), d(10);
  for (int r = 0; r < 10; ++r)
    d[r] = ov / 4 * (1 - std::cos(2 * a[r]));
  d[0] = 0.0;
  ps::OvalityParameters p;
  p.model = ps::OvalityModel::Table;
  p.tableAngle_rad = a;
  p.tableRadialDrop_m = d;
  const ps::Ovality t(p, kPi / 3);
  for (int r = 0; r < 10; ++r)
    EXPECT_NEAR(t.calcDrop_m(a[r]), d[r], 1e-21) << r;
  for (double ph : {0.05, 0.3, 0.77, 1.2, 1.5}) {
    const double v = t.calcDrop_m(ph);
    EXPECT_EQ(t.calcDrop_m(-ph), v);  // about the thrust axis
    // about the pin axis (anti-thrust side); pi - ph is rounded: a few ulps
    EXPECT_NEAR(t.calcDrop_m(kPi - ph), v, 1e-14 * ov);
    // PCHIP of the sampled law: slope error <= f'' h with f'' <= 2 Ov, h = pi/18; value
    // error <= f'' h^2 / 4
    const double h = kPi / 18;
    EXPECT_NEAR(v, ov / 4 * (1 - std::cos(2 * ph)), 2 * ov * h * h / 4) << ph;
  }
  // zero slope on the thrust axis (the reflected table): drop(eps) = O(eps^2)
  EXPECT_LT(t.calcDrop_m(1e-4), 1e-6 * ov);
}

// Barrel profile: drop = c (y - y0)^2 tabulated every 5 mm over [-30, 30] mm.
struct Barrel {
  double c = 0.04, y0 = -0.004;  // [1/m], [m]: 16 um drop at 20 mm from the vertex
  Eigen::VectorXd rows = Eigen::VectorXd::LinSpaced(13, -0.03, 0.03);
  double drop(double y) const { return c * (y - y0) * (y - y0); }
  ps::AxialProfileParameters parameters(bool mirrored) const {
    ps::AxialProfileParameters p;
    p.height_m = rows;
    p.radialDrop_m = rows.unaryExpr([this](double y) { return drop(y); });
    p.mirrored = mirrored;
    return p;
  }
  double bound() const { return 2 * c * 0.005 * 0.005 / 4; }  // f'' h^2 / 4
};

TEST(AxialProfile, BarrelIsExactAtTheRowsAndWithinPchipAccuracyBetween) {
  const Barrel b;
  const ps::AxialProfile prof(b.parameters(false), -0.025, 0.015);
  for (Eigen::Index r = 0; r < b.rows.size(); ++r)
    EXPECT_EQ(prof.calcDrop_m(b.rows[r]), b.drop(b.rows[r])) << r;
  double worst = 0.0;
  for (int s = 0; s <= 400; ++s) {
    const double y = -0.025 + 0.04 * s / 400;
    worst = std::max(worst, std::abs(prof.calcDrop_m(y) - b.drop(y)));
  }
  EXPECT_LE(worst, b.bound());
  std::printf("[ barrel   ] PCHIP vs parabola: worst %.3e m, bound f'' h^2/4 = %.3e m\n", worst,
              b.bound());
}

TEST(AxialProfile, MirrorReadsTheProfileAtMinusY) {
  const Barrel b;
  const ps::AxialProfile mirrored(b.parameters(true), -0.025, 0.015);
  EXPECT_TRUE(mirrored.isMirrored());
  for (Eigen::Index r = 0; r < b.rows.size(); ++r)
    EXPECT_EQ(mirrored.calcDrop_m(-b.rows[r]), b.drop(b.rows[r])) << r;
  for (int s = 0; s <= 100; ++s) {
    const double y = -0.025 + 0.04 * s / 100;
    EXPECT_NEAR(mirrored.calcDrop_m(y), b.drop(-y), b.bound()) << y;
  }
  // the minimum-clearance point moves from y0 = -4 mm (below the pin) to +4 mm (above)
  EXPECT_LT(mirrored.calcDrop_m(0.004), mirrored.calcDrop_m(-0.004));
}

TEST(SkirtProfile, FieldIsProfilePlusOvalityAtEveryNode) {
  const Barrel b;
  for (ps::SkirtSide side : {ps::SkirtSide::Thrust, ps::SkirtSide::AntiThrust}) {
    ps::SkirtSideGridParameters gp = ps::test::thrustSide(11, 17);
    gp.side = side;
    const ps::SkirtSideGrid g(gp);
    ps::SkirtProfileParameters p;
    p.axial = b.parameters(false);
    p.ovality.diametralOvality_m = 50e-6;
    const ps::SkirtProfile prof(p, g);
    Eigen::ArrayXd field(g.nodeCount());
    prof.calcField(g, field);
    for (int k = 0; k < g.nodeCount(); ++k) {
      const double ph = g.getNodePhi_rad()[k], y = g.getNodeY_m()[k];
      const double expected = b.drop(y) + 50e-6 / 4 * (1 - std::cos(2 * ph));
      EXPECT_NEAR(field[k], expected, b.bound() + 1e-20) << k;
    }
  }
}

}  // namespace
