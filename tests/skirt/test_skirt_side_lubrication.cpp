// skirt::SkirtSideLubrication (one skirt side's film, asperity contact, friction and loads per
// force evaluation) against references written here, independently of the code under test:
//   1. lateral and tilt squeeze of a centred round skirt: the short-bearing (Ocvirk) closed form
//      and the exact Fourier-series solution of the same rectangle (derived below);
//   2. axial sliding with a small tilt: the infinitely wide inclined slider on every phi-line,
//      integrated over the arc by Gauss quadrature here;
//   3. Couette friction eta U A / h, its sign and its power; boundary friction f g(|U|) W;
//   4. the derivatives against central finite differences of the code's own loads;
//   5. the asperity quadrature of an edge contact against a quadrature of p_c(h) with the exact
//      gap, under grid refinement; and the nodal result where no cell is near contact;
//   6. no allocation after the first call (malloc counter, tests/support);
//   7. bad input;
//   8. the mass-conserving (JFO) model: the oil balance closes; flooded steady = Reynolds.
// Every gap field is built here from its closed form (the rigid gap of a round skirt,
// h = c0 - (e + y alpha) cos phi - z_t sin phi, linear in the pose), not by GapAssembly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "AllocationCounter.h"
#include "ExpectInvalidArgument.h"
#include "SkirtTestSupport.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/contact_forces/BoundaryFriction.h"
#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"
#include "pistondyn/lubrication/FlowFactorModel.h"
#include "pistondyn/lubrication/PatirChengFlowFactors.h"
#include "pistondyn/skirt/PistonPose.h"
#include "pistondyn/skirt/SkirtSideLubrication.h"

namespace ps = pistondyn::skirt;
namespace lub = pistondyn::lubrication;
namespace cf = pistondyn::contact_forces;
using pistondyn::test::expectInvalidArgument;
using ps::test::kPi;

namespace {

using Loads6 = Eigen::Matrix<double, 6, 1>;

Loads6 stack(const ps::PistonLoads& l) {
  Loads6 v;
  v << l.force_N, l.moment_Nm;
  return v;
}

// A side of radius R, arc Phi, length L, top edge at yTop (piston frame), nPhi x nY nodes.
ps::SkirtSideGrid makeGrid(double arc_rad, double length_m, double top_m, int nPhi = 64,
                           int nY = 48, ps::SkirtSide side = ps::SkirtSide::Thrust,
                           double radius_m = 0.037) {
  ps::SkirtSideGridParameters p;
  p.side = side;
  p.radius_m = radius_m;
  p.arcWidth_rad = arc_rad;
  p.nPhi = nPhi;
  p.nY = nY;
  p.skirtTopHeight_m = top_m;
  p.skirtLength_m = length_m;
  return ps::SkirtSideGrid(p);
}

struct Pose {
  double e = 0.0, alpha = 0.0, z = 0.0;           // [m], [rad], [m]
  double eDot = 0.0, alphaDot = 0.0, zDot = 0.0;  // [m/s], [rad/s], [m/s]
};

// Rigid gap of a round skirt in a round bore, linear in the pose (the closed form of
// RigidGap.h with sin alpha -> alpha, cos alpha -> 1, so that dGap_dPose is its exact
// derivative): h = c0 - (e + y alpha) cos phi - z sin phi, plus an optional extra term
// extra(phi, y) fixed to the skirt (a profile: no rate, no pose derivative).
ps::GapFields rigidFields(const ps::SkirtSideGrid& g, double c0_m, const Pose& q,
                          const std::function<double(double, double)>& extra = {}) {
  const int n = g.nodeCount();
  ps::GapFields f;
  f.gap_m.resize(n);
  f.gapRate_mps.resize(n);
  f.dGap_dPose.resize(n, 3);
  f.squeezeBasis.resize(n, 3);
  for (int k = 0; k < n; ++k) {
    const double phi = g.getNodePhi_rad()[k], y = g.getNodeY_m()[k];
    const double c = std::cos(phi), s = std::sin(phi);
    f.gap_m[k] = c0_m - (q.e + y * q.alpha) * c - q.z * s + (extra ? extra(phi, y) : 0.0);
    f.gapRate_mps[k] = -(q.eDot + y * q.alphaDot) * c - q.zDot * s;
    f.dGap_dPose(k, 0) = -c;
    f.dGap_dPose(k, 1) = -y * c;
    f.dGap_dPose(k, 2) = -s;
  }
  f.squeezeBasis = f.dGap_dPose;
  return f;
}

std::shared_ptr<const cf::GreenwoodTrippLaw> gtLaw(double rq1 = 0.3e-6, double rq2 = 0.4e-6) {
  cf::GreenwoodTrippParameters p;
  p.roughnessSurface1_m = rq1;
  p.roughnessSurface2_m = rq2;
  return std::make_shared<const cf::GreenwoodTrippLaw>(p);
}

std::shared_ptr<const lub::FlowFactorModel> patirCheng(double rq1 = 0.3e-6, double rq2 = 0.4e-6) {
  lub::PatirChengParameters p;
  p.rq1_m = rq1;
  p.rq2_m = rq2;
  return std::make_shared<const lub::PatirChengFlowFactors>(p);
}

std::shared_ptr<const lub::FlowFactorModel> smooth() {
  return std::make_shared<const lub::SmoothFlowFactors>();
}

ps::SkirtLubricationParameters tightSolver(
    lub::CavitationModel model = lub::CavitationModel::Reynolds, double tolerance = 1e-11) {
  ps::SkirtLubricationParameters p;
  p.cavitation = model;
  p.solver.tolerance = tolerance;
  p.solver.derivativeTolerance = tolerance;  // the squeeze derivatives are checked too
  return p;
}

ps::SkirtSideLubrication makeLubrication(
    const ps::SkirtSideGrid& g, std::shared_ptr<const lub::FlowFactorModel> ff,
    const ps::SkirtLubricationParameters& p = tightSolver(),
    std::shared_ptr<const cf::AsperityContactLaw> law = gtLaw(),
    const cf::BoundaryFrictionParameters& fp = {}) {
  return ps::SkirtSideLubrication(g, std::move(ff), std::move(law), cf::BoundaryFriction(fp), p);
}

ps::SkirtSideInputs inputs(double eta_Pas, double uAxial_mps = 0.0, double uCirc_mps = 0.0) {
  ps::SkirtSideInputs in;
  in.viscosity_Pas = eta_Pas;
  in.slidingVelocityAxial_mps = uAxial_mps;
  in.slidingVelocityCircumferential_mps = uCirc_mps;
  in.squeezeColumns = 3;
  return in;
}

double relErr(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

// ------------------------------------------------------------------------------------------
// 1. Squeeze of a centred round skirt.
//
// Gap h = c0 uniform, gap rate dh/dt = -v(y) cos phi with v(y) = de/dt + y dalpha/dt (lateral
// and tilt rate), no sliding, smooth surfaces. On the film grid x = R phi (phi_c = 0), y, the
// Reynolds equation is (c0^3 / (12 eta)) (p_xx + p_yy) = dh/dt = -v(y) cos(x/R) on
// |x| <= a = R Phi/2, y_b <= y <= y_b + L, p = 0 on all four edges.
//
// Short bearing (Ocvirk: the circumferential pressure flow dropped, p_yy only). With
// y = y_m + y' (y_m the mid-height), p_yy = -(12 eta / c0^3) (de/dt + dalpha/dt (y_m + y'))
// cos phi, p(y' = +-L/2) = 0:
//   p = (6 eta cos phi / c0^3) (L^2/4 - y'^2) [de/dt + dalpha/dt (y_m + y'/3)]
// (check: d^2/dy'^2 of (L^2/4 - y'^2) is -2, of (L^2/4 - y'^2) y'/3 is -2 y'). With
//   int_{-L/2}^{L/2} (L^2/4 - y'^2) dy' = L^3/6,  int (L^2/4 - y'^2) y'^2 dy' = L^5/120,
//   int_{-Phi/2}^{Phi/2} cos^2 phi dphi = (Phi + sin Phi)/2,  dA = R dphi dy,
// the loads F_x = -int p cos phi dA and M_z = +int p y cos phi dA (SkirtSideGrid.h) are
//   F_x = -(eta R L^3 / c0^3) (Phi + sin Phi)/2 (de/dt + y_m dalpha/dt)
//   M_z = +(eta R / c0^3) (Phi + sin Phi)/2 [y_m L^3 de/dt + (y_m^2 L^3 + L^5/60) dalpha/dt]
// (M_z's tilt part: (y_m + y'/3)(y_m + y') = y_m^2 + (4/3) y_m y' + y'^2/3, so the y'
// integral is y_m^2 L^3/6 + L^5/360, times 6). The short bearing neglects
// the circumferential flow to the arc's ends, an error that shrinks with L / (R Phi).
//
// Exact solution of the same rectangle (to separate the grid's error from the short-bearing
// one). With s = y - y_b and k_n = n pi / L, expand v(y) = sum_n v_n sin(k_n s),
//   v_n = (2/L) [(de/dt + y_b dalpha/dt) J0_n + dalpha/dt J1_n],
//   J0_n = int_0^L sin(k_n s) ds = (1 - (-1)^n)/k_n,  J1_n = int_0^L s sin(k_n s) ds =
//   -L (-1)^n / k_n.
// Then p = sum_n sin(k_n s) f_n(x) with f_n'' - k_n^2 f_n = -S v_n cos(x/R), S = 12 eta/c0^3,
// f_n(+-a) = 0:
//   f_n = A_n [cos(x/R) - cos(a/R) cosh(k_n x)/cosh(k_n a)],  A_n = S v_n / (k_n^2 + 1/R^2).
// With Ic = int_{-a}^{a} cos^2(x/R) dx = a + (R/2) sin(2a/R) and
//   Ich_n = int_{-a}^{a} cosh(k x) cos(x/R) dx / cosh(k a)
//         = 2 [k tanh(k a) cos(a/R) + sin(a/R)/R] / (k^2 + 1/R^2)
// (the antiderivative [k sinh(kx) cos(bx) + b cosh(kx) sin(bx)]/(k^2 + b^2), b = 1/R):
//   F_x = -sum_n J0_n A_n (Ic - cos(a/R) Ich_n),
//   M_z = +sum_n (y_b J0_n + J1_n) A_n (Ic - cos(a/R) Ich_n).
// The terms fall like n^-4; 20000 terms leave < 1e-12.
struct SqueezeLoads {
  double fx, mz;
};

SqueezeLoads shortBearingSqueeze(double R, double arc, double L, double yMid, double c0, double eta,
                                 double eDot, double alphaDot) {
  const double arcFactor = 0.5 * (arc + std::sin(arc)), c3 = c0 * c0 * c0;
  const double L3 = L * L * L, L5 = L3 * L * L;
  return {
      -eta * R * L3 / c3 * arcFactor * (eDot + yMid * alphaDot),
      eta * R / c3 * arcFactor * (yMid * L3 * eDot + (yMid * yMid * L3 + L5 / 60.0) * alphaDot)};
}

SqueezeLoads exactRectangleSqueeze(double R, double arc, double L, double yBottom, double c0,
                                   double eta, double eDot, double alphaDot) {
  const double a = 0.5 * R * arc, b = 1.0 / R, S = 12.0 * eta / (c0 * c0 * c0);
  const double Ic = a + 0.5 * R * std::sin(2.0 * a / R);
  double fx = 0.0, mz = 0.0;
  for (int n = 20000; n >= 1; --n) {                                // small terms first
    const double k = n * kPi / L, sgn = (n % 2 == 0) ? 1.0 : -1.0;  // (-1)^n
    const double J0 = (1.0 - sgn) / k, J1 = -L * sgn / k;
    const double vn = 2.0 / L * ((eDot + yBottom * alphaDot) * J0 + alphaDot * J1);
    const double An = S * vn / (k * k + b * b);
    const double Ich =
        2.0 * (k * std::tanh(k * a) * std::cos(a * b) + b * std::sin(a * b)) / (k * k + b * b);
    const double line = An * (Ic - std::cos(a * b) * Ich);
    fx -= J0 * line;
    mz += (yBottom * J0 + J1) * line;
  }
  return {fx, mz};
}

TEST(SkirtSideLubrication, LateralSqueezeApproachesTheShortBearingAsTheSkirtShortens) {
  const double R = 0.037, arc = 2.6, c0 = 30e-6, eta = 0.01, eDot = 0.01, yMid = -0.005;
  const double lengths[] = {0.04, 0.02, 0.01, 0.005};
  std::printf(
      "  L/(R Phi)   F_x code [N]   short bearing   exact series   |code-SB|/SB   "
      "|code-exact|/exact\n");
  double previousShortBearingError = 1e300;
  for (double L : lengths) {
    const ps::SkirtSideGrid g = makeGrid(arc, L, yMid + 0.5 * L);
    ps::SkirtSideLubrication lub = makeLubrication(g, smooth());
    Pose q;
    q.eDot = eDot;
    const ps::GapFields f = rigidFields(g, c0, q);
    ps::SkirtSideResults out;
    lub.solve(f, inputs(eta), out);
    ASSERT_EQ(out.film.cavitatedNodes, 0);  // p > 0 on the whole arc: nothing cut
    const SqueezeLoads sb = shortBearingSqueeze(R, arc, L, yMid, c0, eta, eDot, 0.0);
    const SqueezeLoads ex = exactRectangleSqueeze(R, arc, L, yMid - 0.5 * L, c0, eta, eDot, 0.0);
    // The closed forms are the pressure's loads; the film's Poiseuille shear adds to F_x
    // (checked below), so the pressure part is split off with the grid's exact weights.
    const Eigen::ArrayXd pFilm = out.film.pressure_Pa();
    const ps::PistonLoads pl = g.calcLoadsOnPiston(pFilm);
    const double fx = pl.force_N.x();
    const double errSB = relErr(fx, sb.fx), errExact = relErr(fx, ex.fx);
    std::printf("  %9.4f   %12.6g   %13.6g   %12.6g   %12.3e   %12.3e\n", L / (R * arc), fx, sb.fx,
                ex.fx, errSB, errExact);
    // The grid's own error (64 x 48, second order): 0.2 % covers it at every length (the
    // cosh edge layer of width L/pi is resolved by ~1 cell at the shortest skirt).
    EXPECT_LT(errExact, 2e-3) << "L = " << L;
    // The short-bearing error shrinks with L / (R Phi) ...
    EXPECT_LT(errSB, previousShortBearingError) << "L = " << L;
    previousShortBearingError = errSB;
    // Symmetry of the thrust side: no z force, no x or y moment.
    EXPECT_LT(std::abs(out.totalLoads.force_N.z()), 1e-9 * std::abs(fx));
    EXPECT_LT(std::abs(out.totalLoads.moment_Nm.x()), 1e-9 * std::abs(fx) * R);
    EXPECT_LT(std::abs(out.totalLoads.moment_Nm.y()), 1e-9 * std::abs(fx) * R);
    // The M_z of the lateral squeeze (the moment arm y_m of the mid-height).
    EXPECT_LT(relErr(pl.moment_Nm.z(), ex.mz), 2e-3) << "L = " << L;
    // The circumferential Poiseuille shear on the skirt, tau_phi = -(h/2) dp/dx, gives
    // F_x = -int tau_phi sin phi dA = -(h / (2R)) int p cos phi dA (by parts, p = 0 at the
    // arc's ends): (h / 2R) = 4e-4 of the pressure's F_x, same sign. Its discrete form
    // (one-sided gradients at the arc's ends, where the edge layer of width L/pi is ~1 cell
    // at the shortest skirt) within 5 % of that.
    const double shearFx = out.totalLoads.force_N.x() - fx;
    EXPECT_LT(relErr(shearFx, c0 / (2.0 * R) * fx), 0.05) << "L = " << L;
    // The squeeze derivative's lateral column: the film is linear in the squeeze velocity.
    EXPECT_LT(relErr(out.dLoads_dPoseRate(0, ps::kLateral), ex.fx / eDot), 2e-3);
    EXPECT_LT(relErr(out.dLoads_dPoseRate(5, ps::kLateral), ex.mz / eDot), 2e-3);
    EXPECT_LT(relErr(out.dLoads_dPoseRate(0, ps::kLateral), fx / eDot), 1e-8);
    EXPECT_LT(relErr(out.dLoads_dPoseRate(5, ps::kLateral), pl.moment_Nm.z() / eDot), 1e-8);
  }
  // ... and is within 2 % at the shortest skirt (L / (R Phi) = 0.052) at the default grid.
  EXPECT_LT(previousShortBearingError, 0.02);
}

TEST(SkirtSideLubrication, TiltSqueezeDerivativeMatchesTheClosedForms) {
  // The tilt column of dLoads_dPoseRate (a pure tilt-rate squeeze, dh/dt = -y dalpha/dt cos
  // phi, changes sign at y = 0: it is taken with the full-film active set of a lateral squeeze,
  // de/dt > 0, alpha-dot = 0, where nothing cavitates) against the short-bearing and exact
  // closed forms above, with the reciprocity dF_x/d(alpha-dot) = -dM_z/d(e-dot) of a symmetric
  // damping matrix in the pose forces (F_x, -M_z).
  const double R = 0.037, arc = 2.6, c0 = 30e-6, eta = 0.01, yMid = -0.005;
  std::printf(
      "  L/(R Phi)  dFx/dadot code  short bearing  exact   dMz/dadot code  short bearing  "
      "exact\n");
  double previous = 1e300, errSB = 0.0;
  for (double L : {0.04, 0.02, 0.01, 0.005}) {
    const ps::SkirtSideGrid g = makeGrid(arc, L, yMid + 0.5 * L);
    ps::SkirtSideLubrication lub = makeLubrication(g, smooth());
    Pose q;
    q.eDot = 0.01;
    ps::SkirtSideResults out;
    lub.solve(rigidFields(g, c0, q), inputs(eta), out);
    ASSERT_EQ(out.film.cavitatedNodes, 0);
    const SqueezeLoads sb = shortBearingSqueeze(R, arc, L, yMid, c0, eta, 0.0, 1.0);
    const SqueezeLoads ex = exactRectangleSqueeze(R, arc, L, yMid - 0.5 * L, c0, eta, 0.0, 1.0);
    const double dFx = out.dLoads_dPoseRate(0, ps::kTilt), dMz = out.dLoads_dPoseRate(5, ps::kTilt);
    std::printf("  %8.4f  %14.6g  %13.6g  %12.6g  %14.6g  %13.6g  %12.6g\n", L / (R * arc), dFx,
                sb.fx, ex.fx, dMz, sb.mz, ex.mz);
    EXPECT_LT(relErr(dFx, ex.fx), 2e-3) << "L = " << L;  // grid error, as above
    EXPECT_LT(relErr(dMz, ex.mz), 2e-3) << "L = " << L;
    errSB = std::max(relErr(dFx, sb.fx), relErr(dMz, sb.mz));
    EXPECT_LT(errSB, previous);
    previous = errSB;
    // Reciprocity (the discrete Reynolds operator is symmetric and the load weights are the
    // squeeze basis' own: exact up to the solver tolerance).
    EXPECT_LT(relErr(dFx, -out.dLoads_dPoseRate(5, ps::kLateral)), 1e-6);
  }
  EXPECT_LT(errSB, 0.02);
}

TEST(SkirtSideLubrication, ClampedGapSqueezesWithTheClampsSlope) {
  // A nominal gap h at the clamp (h = 2 h_c, mixed contact) squeezing laterally: the film
  // sees the clamped gap h_f = (h + h_c + sqrt((h - h_c)^2 + h_c^2)) / 2 and its rate
  // dh_f/dt = (dh_f/dh) dh/dt, dh_f/dh = (1 + (h - h_c)/sqrt((h - h_c)^2 + h_c^2)) / 2 (the
  // header's clamp), both the gap rate and the squeeze basis. So the film's F_x and its
  // lateral squeeze derivative are the exact rectangle solution above with c0 -> h_f and
  // de/dt -> (dh_f/dh) de/dt (grid error 2e-3, as above). h_c = max(0.1 sigma, 10 nm): with
  // the contact law's sigma when the flow factors are smooth (0.05 um here), and the floor
  // 10 nm for a composite roughness of 16.7 nm.
  const double R = 0.037, arc = 2.6, L = 0.01, yMid = -0.005, eta = 0.01, eDot = 1e-6;
  for (double rq : {0.3e-6, 0.01e-6}) {  // liner Rq; skirt 4/3 of it: sigma 0.5 um, 16.7 nm
    const auto law = gtLaw(rq, rq * 4.0 / 3.0);
    const double sigma = law->compositeSigma_m();
    const double hc = std::max(0.1 * sigma, 1e-8);
    const ps::SkirtSideGrid g = makeGrid(arc, L, yMid + 0.5 * L);
    ps::SkirtSideLubrication lub = makeLubrication(g, smooth(), tightSolver(), law);
    EXPECT_DOUBLE_EQ(lub.getClampGap_m(), hc);
    const double h = 2.0 * hc, root = std::sqrt((h - hc) * (h - hc) + hc * hc);
    const double hf = 0.5 * (h + hc + root), slope = 0.5 * (1.0 + (h - hc) / root);
    Pose q;
    q.eDot = eDot;
    ps::SkirtSideResults out;
    lub.solve(rigidFields(g, h, q), inputs(eta), out);
    EXPECT_NEAR(out.filmGap_m.maxCoeff(), hf, 1e-15 * hf);
    const Eigen::ArrayXd p = out.film.pressure_Pa();
    const double fx = g.calcLoadsOnPiston(p).force_N.x();
    const SqueezeLoads ex =
        exactRectangleSqueeze(R, arc, L, yMid - 0.5 * L, hf, eta, slope * eDot, 0.0);
    std::printf("  sigma %.3g m: h_c %.3g m, h_f %.4g m, slope %.4f; F_x %.6g N vs %.6g N\n", sigma,
                hc, hf, slope, fx, ex.fx);
    EXPECT_LT(relErr(fx, ex.fx), 2e-3);
    EXPECT_LT(relErr(out.dLoads_dPoseRate(0, ps::kLateral), ex.fx / eDot), 2e-3);
  }
}

// ------------------------------------------------------------------------------------------
// 2. Axial sliding U (liner relative to skirt along +y) with a small tilt alpha > 0, e = 0:
// every phi-line has the linear gap h(y) = c0 - y alpha cos phi, decreasing along +y: a
// convergent slider with the inlet at the skirt's bottom edge y_b (h_in = c0 - y_b alpha cos
// phi) and the outlet at its top y_t (h_out). With side leakage neglected (a wide arc), each
// line is the infinitely wide inclined slider: d/dy(h^3 p') = 6 eta U h', p(y_b) = p(y_t) = 0,
// i.e. h^3 p' / (12 eta) = U (h - h*)/2, h* = 2 h_in h_out / (h_in + h_out), integrated:
//   p = 6 eta U L (h_in - h)(h - h_out) / (h^2 (h_in^2 - h_out^2)),  L = y_t - y_b
// (positive between the ends: the Reynolds condition cuts nothing). The loads
//   F_x = -int p cos phi R dphi dy,   M_z = int p y cos phi R dphi dy
// are integrated here by Gauss-Legendre quadrature of that closed form (the integrand is
// smooth: 48 x 200 points are exact to ~1e-12).
struct SliderLoads {
  double fx, mz;
};

SliderLoads inclinedSliderLoads(double R, double arc, double yB, double yT, double c0, double alpha,
                                double eta, double U) {
  const auto [xp, wp] = ps::test::gaussLegendre(200);
  const auto [xy, wy] = ps::test::gaussLegendre(48);
  const double L = yT - yB;
  double fx = 0.0, mz = 0.0;
  for (std::size_t a = 0; a < xp.size(); ++a) {
    const double phi = 0.5 * arc * xp[a], c = std::cos(phi);
    const double hin = c0 - yB * alpha * c, hout = c0 - yT * alpha * c;
    for (std::size_t b = 0; b < xy.size(); ++b) {
      const double y = 0.5 * (yB + yT) + 0.5 * L * xy[b];
      const double h = c0 - y * alpha * c;
      const double p =
          6.0 * eta * U * L * (hin - h) * (h - hout) / (h * h * (hin * hin - hout * hout));
      const double w = 0.5 * arc * wp[a] * 0.5 * L * wy[b] * R;
      fx -= p * c * w;
      mz += p * y * c * w;
    }
  }
  return {fx, mz};
}

TEST(SkirtSideLubrication, TiltedSlidingApproachesTheInclinedSliderAsTheArcWidens) {
  const double R = 0.037, c0 = 20e-6, eta = 0.01, U = 8.0, L = 0.01, yT = 0.005, yB = yT - L;
  // h_in / h_out = 2 on the centre line: alpha (2 y_t - y_b) = c0.
  const double alpha = c0 / (2.0 * yT - yB);
  std::printf(
      "  arc [rad]  F_x code [N]  slider [N]   err F_x    M_z code [Nm]  slider [Nm]  err M_z\n");
  double previous = 1e300, err = 0.0;
  for (double arc : {0.5, 1.0, 2.0, 3.0}) {
    const ps::SkirtSideGrid g = makeGrid(arc, L, yT);
    ps::SkirtSideLubrication lub = makeLubrication(g, smooth());
    Pose q;
    q.alpha = alpha;
    ps::SkirtSideResults out;
    lub.solve(rigidFields(g, c0, q), inputs(eta, U), out);
    EXPECT_EQ(out.film.cavitatedNodes, 0);  // convergent everywhere
    // Pressure loads alone (the slider's closed form is the pressure's; the film shear adds
    // -(h/2) p_y to tau_y, which moves M_z by R int tau_y cos: computed separately).
    Eigen::ArrayXd p = out.film.pressure_Pa();
    const ps::PistonLoads pl = g.calcLoadsOnPiston(p);
    const SliderLoads ref = inclinedSliderLoads(R, arc, yB, yT, c0, alpha, eta, U);
    const double eF = relErr(pl.force_N.x(), ref.fx), eM = relErr(pl.moment_Nm.z(), ref.mz);
    std::printf("  %8.2f  %12.6g  %10.6g  %9.3e  %12.6g  %12.6g  %9.3e\n", arc, pl.force_N.x(),
                ref.fx, eF, pl.moment_Nm.z(), ref.mz, eM);
    err = std::max(eF, eM);
    EXPECT_LT(err, previous) << "arc = " << arc;  // side leakage shrinks as the arc widens
    previous = err;
  }
  EXPECT_LT(err, 0.02);  // within 2 % for the widest arc (3 rad), 64 x 48 nodes
}

// ------------------------------------------------------------------------------------------
// 3. Friction.
//
// Uniform gap h, smooth surfaces (plain Reynolds: phi_f = 1, phi_fs = 0), sliding U = (U_x
// circumferential, U_y axial) of the liner relative to the skirt: pure Couette flow (no
// pressure: the Couette flux U h / 2 is divergence-free). The liner drags the skirt along U
// with tau = eta U / h (FilmResult: +eta U/h on surface 2), so over the side (area A = R Phi L,
// int cos phi dA = 2 R L sin(Phi/2), int sin phi dA = 0 on the thrust side):
//   F_y = eta U_y A / h,  M_y = -R int tau_phi dA = -R eta U_x A / h,
//   F_z = int tau_phi cos phi dA = eta U_x 2 R L sin(Phi/2) / h,  F_x = 0,
//   power U . int tau dA = eta |U|^2 A / h > 0.
TEST(SkirtSideLubrication, CouetteFrictionIsEtaUAOverHAlongTheLinerVelocity) {
  const double R = 0.037, arc = 1.0, L = 0.03, c0 = 20e-6, eta = 0.008;
  for (ps::SkirtSide side : {ps::SkirtSide::Thrust, ps::SkirtSide::AntiThrust}) {
    for (double uy : {8.0, -5.0}) {
      const double ux = 0.3;
      const ps::SkirtSideGrid g = makeGrid(arc, L, 0.01, 64, 48, side);
      // Both smooth forms: SmoothFlowFactors, and Patir & Cheng with zero roughness.
      for (auto ff : {smooth(), patirCheng(0.0, 0.0)}) {
        ps::SkirtSideLubrication lub = makeLubrication(g, ff);
        ps::SkirtSideResults out;
        lub.solve(rigidFields(g, c0, Pose()), inputs(eta, uy, ux), out);
        // The film gap is the header's smooth clamp of c0 (h_c = 0.1 sigma of the contact law,
        // the flow factors being smooth): c0 + h_c^2 / (4 (c0 - h_c)) + ...
        const double hc = lub.getClampGap_m();
        const double hf = 0.5 * (c0 + hc + std::sqrt((c0 - hc) * (c0 - hc) + hc * hc));
        EXPECT_NEAR(out.filmGap_m.minCoeff(), hf, 1e-18);
        EXPECT_NEAR(out.filmGap_m.maxCoeff(), hf, 1e-18);
        const double A = R * arc * L, sideSign = side == ps::SkirtSide::Thrust ? 1.0 : -1.0;
        const double tol = 1e-9;  // exact weights of a uniform field; p ~ solver tolerance
        EXPECT_LT(relErr(out.totalLoads.force_N.y(), eta * uy * A / hf), tol);
        EXPECT_LT(relErr(out.hydrodynamicFrictionAxial_N, eta * uy * A / hf), tol);
        EXPECT_EQ(std::signbit(out.hydrodynamicFrictionAxial_N), std::signbit(uy));  // along U
        EXPECT_LT(relErr(out.totalLoads.moment_Nm.y(), -R * eta * ux * A / hf), tol);
        // On the anti-thrust side e_phi = -z: the same shear gives -F_z.
        EXPECT_LT(relErr(out.totalLoads.force_N.z(),
                         sideSign * eta * ux * 2.0 * R * L * std::sin(0.5 * arc) / hf),
                  tol);
        EXPECT_LT(std::abs(out.totalLoads.force_N.x()), tol * eta * std::abs(ux) * A / hf);
        const double power = eta * (ux * ux + uy * uy) * A / hf;
        EXPECT_LT(relErr(out.frictionPower_W, power), tol);
        EXPECT_LT(relErr(out.hydrodynamicFrictionPower_W, power), tol);
        // h / sigma = 40: F_{5/2} is exactly 0 from lambda = 37 (GaussianTailIntegrals.h).
        EXPECT_EQ(out.asperityFrictionPower_W, 0.0);
        // Power = U . F from the loads themselves: int tau_y dA = F_y, int tau_phi = -M_y / R.
        EXPECT_LT(relErr(out.frictionPower_W,
                         uy * out.totalLoads.force_N.y() - ux * out.totalLoads.moment_Nm.y() / R),
                  1e-12);
        EXPECT_NEAR(out.hydrodynamicShare, 1.0, 1e-12);  // area sums: rounding only
        EXPECT_NEAR(out.wettedShare, 1.0, 1e-12);
      }
    }
  }
}

// Boundary friction on a uniform gap h in contact (h/sigma = 1.2 and 0.8): p_c uniform, the
// asperity normal load W = p_c A, the boundary shear on the skirt f p_c U / sqrt(|U|^2 +
// v_eps^2) along U (BoundaryFriction.h: Algebraic regularisation, skirt velocity -U), so
//   asperityFrictionAxial_N = f g(|U|) W sign(U_y) for U_x = 0, g(s) = s / sqrt(s^2 + v_eps^2),
//   asperity power = f g(|U|) |U| W, and the film's Couette power eta U^2 A / h_f with the
// clamped gap h_f = (h + h_c + sqrt((h - h_c)^2 + h_c^2)) / 2, h_c = 0.1 sigma (the header's
// clamp; smooth flow factors take the contact law's sigma). The split adds up to the total.
TEST(SkirtSideLubrication, BoundaryFrictionIsFGTimesTheAsperityLoadAndThePowerSplitAddsUp) {
  const double R = 0.037, arc = 1.0, L = 0.03, eta = 0.008, f = 0.12, vEps = 1e-3;
  const auto law = gtLaw();
  const double sigma = law->compositeSigma_m();
  cf::BoundaryFrictionParameters fp;
  fp.frictionCoefficient = f;
  fp.regularisationSpeed_mps = vEps;
  const ps::SkirtSideGrid g = makeGrid(arc, L, 0.01);
  const double A = R * arc * L;
  for (double ratio : {1.2, 0.8}) {
    for (double uy : {5.0, -0.5e-3}) {
      ps::SkirtLubricationParameters lp = tightSolver();
      lp.wearCoefficient_m2pN = 2e-17;
      ps::SkirtSideLubrication lub = makeLubrication(g, smooth(), lp, law, fp);
      const double h = ratio * sigma;
      ps::SkirtSideResults out;
      lub.solve(rigidFields(g, h, Pose()), inputs(eta, uy), out);
      const double pc = law->calcPressure(h), W = pc * A;
      ASSERT_GT(pc, 0.0);
      const double g_ = std::abs(uy) / std::sqrt(uy * uy + vEps * vEps);
      EXPECT_LT(relErr(out.asperityFrictionAxial_N, f * g_ * W * (uy > 0 ? 1.0 : -1.0)), 1e-12);
      EXPECT_LT(relErr(out.asperityLoads.force_N.y(), out.asperityFrictionAxial_N), 1e-12);
      EXPECT_LT(relErr(out.asperityNormalForce_N, pc * 2.0 * R * L * std::sin(0.5 * arc)), 1e-12);
      EXPECT_LT(relErr(out.asperityFrictionPower_W, f * g_ * std::abs(uy) * W), 1e-12);
      const double hc = 0.1 * sigma;
      EXPECT_DOUBLE_EQ(lub.getClampGap_m(), hc);
      const double hf = 0.5 * (h + hc + std::sqrt((h - hc) * (h - hc) + hc * hc));
      EXPECT_LT(relErr(out.hydrodynamicFrictionPower_W, eta * uy * uy * A / hf), 1e-9);
      EXPECT_LT(std::abs(out.frictionPower_W -
                         (out.hydrodynamicFrictionPower_W + out.asperityFrictionPower_W)),
                1e-14 * out.frictionPower_W);
      EXPECT_GT(out.asperityFrictionPower_W, 0.0);  // friction dissipates
      // Regime of the nominal gap: 1 < 1.2 <= 3 mixed, 0.8 <= 1 boundary.
      EXPECT_NEAR(ratio > 1.0 ? out.mixedShare : out.boundaryShare, 1.0, 1e-12);
      EXPECT_NEAR(out.hydrodynamicShare + out.mixedShare + out.boundaryShare, 1.0, 1e-12);
      // Archard: k/H W |U| and k/H p_c |U|.
      EXPECT_LT(relErr(out.wearRate_m3ps, 2e-17 * W * std::abs(uy)), 1e-12);
      EXPECT_LT(relErr(out.maxWearDepthRate_mps, 2e-17 * pc * std::abs(uy)), 1e-12);
      EXPECT_DOUBLE_EQ(out.minGapOverSigma, ratio);
    }
  }
}

// ------------------------------------------------------------------------------------------
// 4. Derivatives against central finite differences of the code's own loads.

// A running thrust side: 74 mm bore, 60 deg arc, 40 mm skirt from 15 mm above the pin, rough
// surfaces (Patir & Cheng and Greenwood-Tripp on one roughness pair), Reynolds cavitation.
struct RunningCase {
  ps::SkirtSideGrid grid = ps::SkirtSideGrid(ps::test::thrustSide(64, 48));
  double c0 = 20e-6, eta = 0.008, uy = 6.0;
};

// The pressure part of the film's loads (what dLoads_dPoseRate holds), split off here with
// SkirtSideGrid::calcLoadsOnPiston (tested on its own in test_skirt_side_grid).
Loads6 filmPressureLoads(const ps::SkirtSideGrid& g, const ps::SkirtSideResults& out) {
  const Eigen::ArrayXd p = out.film.pressure_Pa();
  return stack(g.calcLoadsOnPiston(p));
}

TEST(SkirtSideLubrication, SqueezeDerivativesEqualCentralDifferencesOfTheFilmLoads) {
  // For a fixed cavitation set the film pressure is affine in the pose rates, so a central
  // difference is exact up to the solver tolerance (1e-11 relative residual) as long as the
  // cavitation set is the same at both ends. Where a node changes sides between the two ends
  // the difference straddles a kink of the piecewise-affine map (one node moved: differences
  // of up to 3e-3 were seen), so the step is shrunk (from ~1e-3 of each rate, by 10) until the
  // two sets agree. Then: 1e-6 of the column's norm (seen: 1e-9 .. 2e-7).
  RunningCase rc;
  const ps::SkirtSideGrid& g = rc.grid;
  ps::SkirtSideLubrication lub = makeLubrication(g, patirCheng());
  Pose q;
  q.e = 6e-6;
  q.alpha = 3e-4;
  q.z = 1e-6;
  q.eDot = -0.0005;  // opening: the squeeze suction and the wedge share the side
  q.alphaDot = 0.05;
  q.zDot = 3e-4;
  ps::SkirtSideResults out;
  lub.solve(rigidFields(g, rc.c0, q), inputs(rc.eta, rc.uy), out);
  ASSERT_GT(out.film.cavitatedNodes, 0);  // a real cavitation boundary
  EXPECT_GT(out.minGapOverSigma, 5.0);    // film only
  const Eigen::Matrix<double, 6, 3> analytic = out.dLoads_dPoseRate;
  const double scales[3] = {1e-5, 5e-4, 3e-6};  // ~1e-3 of |de/dt|, |dalpha/dt| y, |dz/dt|
  for (int c = 0; c < 3; ++c) {
    bool sameSet = false;
    for (double step = scales[c]; !sameSet && step > 1e-6 * scales[c]; step /= 10.0) {
      Loads6 lp[2], shear[2];
      std::vector<std::uint8_t> cav[2];
      for (int side = 0; side < 2; ++side) {
        Pose qq = q;
        (c == 0 ? qq.eDot : c == 1 ? qq.alphaDot : qq.zDot) += (side == 0 ? 1.0 : -1.0) * step;
        ps::SkirtSideResults o;
        lub.solve(rigidFields(g, rc.c0, qq), inputs(rc.eta, rc.uy), o);
        lp[side] = filmPressureLoads(g, o);
        shear[side] = stack(o.hydrodynamicLoads) - lp[side];
        cav[side] = o.film.state.cavitated;
      }
      sameSet = cav[0] == cav[1];
      if (!sameSet)
        continue;
      const Loads6 fd = (lp[0] - lp[1]) / (2.0 * step);
      const Loads6 fdShear = (shear[0] - shear[1]) / (2.0 * step);
      const double scale = fd.norm();
      const double err = (fd - analytic.col(c)).norm() / scale;
      std::printf(
          "  column %d (step %.0e): |FD - analytic| / |FD| = %.2e; film-shear part left "
          "out: %.2e of the column\n",
          c, step, err, fdShear.norm() / scale);
      EXPECT_LT(err, 1e-6) << "column " << c;
      // The contract leaves the film shear's rate derivative out: the Poiseuille shear
      // -(h/2) grad p moves the loads by ~h/L, h/R of the pressure's (~1e-3 here).
      EXPECT_LT(fdShear.norm(), 1e-2 * scale) << "column " << c;
    }
    EXPECT_TRUE(sameSet) << "column " << c << ": the cavitation set moves at every step";
  }
}

// An asperity contact spread over the lower skirt (min h/sigma = 1 at the bottom edge, the
// gap rising at alpha = 2e-4 towards the crown), with boundary friction (f = 0.1, U_y = 3 m/s).
TEST(SkirtSideLubrication, AsperityStiffnessEqualsCentralDifferencesOfTheAsperityLoads) {
  // p_c(h) is smooth (exact Gaussian tail integrals); with steps of 2e-3 sigma the central
  // difference's truncation error is ~(delta / sigma)^2 times the ratio of the third to the
  // first derivative of F_5/2 (O(1..10)), ~1e-5 of a column. Tolerance 1e-4 of the column's
  // norm. (The set of Gauss-corrected cells does not change over a step of 2e-3 sigma unless
  // a corner gap lies within it of 4.5 sigma; the jump it would make is ~1e-7 of the load.)
  RunningCase rc;
  const ps::SkirtSideGrid& g = rc.grid;
  ps::SkirtSideLubrication lub = makeLubrication(g, patirCheng());
  const double sigma = lub.getCompositeSigma_m();
  Pose q;
  q.alpha = -2e-4;
  q.e = rc.c0 - (-0.025) * q.alpha - 1.0 * sigma;  // h(bottom, phi = 0) = sigma
  const double uy = 3.0;
  ps::SkirtSideResults out;
  lub.solve(rigidFields(g, rc.c0, q), inputs(rc.eta, uy), out);
  // The nearest nodes are dphi/2 off the centre line: h/sigma = 1 + e dphi^2 / (8 sigma).
  EXPECT_NEAR(out.minGapOverSigma, 1.0, 0.01);
  ASSERT_GT(out.asperityNormalForce_N, 0.0);
  const Eigen::Matrix<double, 6, 3> analytic = out.dLoads_dPose;
  const double steps[3] = {1e-9, 1e-9 / 0.025, 1e-9};  // [m], [rad], [m]
  for (int c = 0; c < 3; ++c) {
    Loads6 l[2];
    for (int side = 0; side < 2; ++side) {
      Pose qq = q;
      (c == 0 ? qq.e : c == 1 ? qq.alpha : qq.z) += (side == 0 ? 1.0 : -1.0) * steps[c];
      ps::SkirtSideResults o;
      lub.solve(rigidFields(g, rc.c0, qq), inputs(rc.eta, uy), o);
      l[side] = stack(o.asperityLoads);
    }
    const Loads6 fd = (l[0] - l[1]) / (2.0 * steps[c]);
    const double err = (fd - analytic.col(c)).norm() / fd.norm();
    std::printf(
        "  column %d: |FD - analytic| / |FD| = %.2e\n    FD       %11.4e %11.4e %11.4e "
        "%11.4e %11.4e %11.4e\n    analytic %11.4e %11.4e %11.4e %11.4e %11.4e %11.4e\n",
        c, err, fd[0], fd[1], fd[2], fd[3], fd[4], fd[5], analytic(0, c), analytic(1, c),
        analytic(2, c), analytic(3, c), analytic(4, c), analytic(5, c));
    EXPECT_LT(err, 1e-4) << "column " << c;
  }
}

// ------------------------------------------------------------------------------------------
// 5. Asperity quadrature of an edge contact.
//
// Thrust side tilted crown-away (alpha = -3 mrad) and shifted so that the bottom edge touches:
// h(phi, y) = c0 - (e + y alpha) cos phi with h(phi = 0, y_b) = -sigma/2. The mean planes
// overlap over a strip ~0.1 mm high, and p_c(h) falls by 1e-6 within ~0.8 mm: about one cell
// of the default grid (0.85 mm). Reference: the integrals of p_c(h) with this exact gap,
//   F_x = -int p_c cos phi dA,  M_z = int p_c y cos phi dA,  dA = R dphi dy,
// by a composite Gauss-Legendre rule here (y: 400 panels x 6 points over the lowest 4 mm, 40
// panels above; phi: 200 points over the arc), p_c from the law itself (Greenwood-Tripp,
// tested in contact_forces).
struct EdgeContact {
  double R = 0.037, arc = 1.0, L = 0.04, yTop = 0.015, c0 = 30e-6, alpha = -3e-3, e = 0.0;
  double yBottom() const { return yTop - L; }
  double gap(double phi, double y) const { return c0 - (e + y * alpha) * std::cos(phi); }
};

Loads6 referenceContactLoads(const EdgeContact& ec, const cf::AsperityContactLaw& law) {
  const auto [xp, wp] = ps::test::gaussLegendre(200);
  // Not a structured binding: the lambda below captures the rule, and clang before 16
  // (Debian 12's clang 14, the sanitizer build) cannot capture a structured binding.
  const auto gauss6 = ps::test::gaussLegendre(6);
  const auto& xg = gauss6.first;
  const auto& wg = gauss6.second;
  const double yB = ec.yBottom();
  std::vector<std::pair<double, double>> yPoints;  // (y, weight)
  auto panels = [&](double a, double b, int count) {
    const double d = (b - a) / count;
    for (int k = 0; k < count; ++k)
      for (std::size_t m = 0; m < xg.size(); ++m)
        yPoints.push_back({a + d * (k + 0.5 + 0.5 * xg[m]), 0.5 * d * wg[m]});
  };
  panels(yB, yB + 0.004, 400);
  panels(yB + 0.004, ec.yTop, 40);
  Loads6 r = Loads6::Zero();
  for (std::size_t a = 0; a < xp.size(); ++a) {
    const double phi = 0.5 * ec.arc * xp[a], wphi = 0.5 * ec.arc * wp[a] * ec.R;
    const double c = std::cos(phi), s = std::sin(phi);
    for (const auto& [y, wy] : yPoints) {
      const double p = law.calcPressure(ec.gap(phi, y)) * wphi * wy;
      r[0] -= p * c;
      r[2] -= p * s;
      r[3] -= p * y * s;
      r[5] += p * y * c;
    }
  }
  return r;
}

TEST(SkirtSideLubrication, EdgeContactConvergesUnderRefinementToTheExactGapQuadrature) {
  EdgeContact ec;
  const auto law = gtLaw();
  const double sigma = law->compositeSigma_m();
  ec.e = ec.c0 - ec.yBottom() * ec.alpha + 0.5 * sigma;  // h(0, y_b) = -sigma/2
  const Loads6 ref = referenceContactLoads(ec, *law);
  std::printf("  reference: F_x = %.8g N, M_z = %.8g N m\n", ref[0], ref[5]);
  std::printf("  nPhi x nY   F_x corrected  err       F_x nodal only  err       M_z err\n");
  const int sizes[][2] = {{16, 12}, {32, 24}, {64, 48}, {128, 96}, {256, 192}};
  double errDefault = 0.0, errPrev = 1e300;
  for (const auto& sz : sizes) {
    const ps::SkirtSideGrid g = makeGrid(ec.arc, ec.L, ec.yTop, sz[0], sz[1]);
    ps::SkirtSideLubrication lub = makeLubrication(g, patirCheng(), tightSolver(), law);
    Pose q;
    q.e = ec.e;
    q.alpha = ec.alpha;
    ps::SkirtSideResults out;
    lub.solve(rigidFields(g, ec.c0, q), inputs(0.01), out);
    const Loads6 code = stack(out.asperityLoads);
    const Eigen::ArrayXd pc =
        Eigen::Map<const Eigen::ArrayXd>(out.contact.pressure_Pa.data(), g.nodeCount());
    const Loads6 nodal = stack(g.calcLoadsOnPiston(pc));
    const double eF = relErr(code[0], ref[0]), eN = relErr(nodal[0], ref[0]);
    const double eM = relErr(code[5], ref[5]);
    std::printf("  %4d x %-4d  %13.7g  %8.2e  %14.7g  %8.2e  %8.2e\n", sz[0], sz[1], code[0], eF,
                nodal[0], eN, eM);
    if (sz[0] >= 32) {
      EXPECT_LT(std::max(eF, eM), errPrev) << sz[0] << " x " << sz[1];  // converges
    }
    errPrev = std::max(eF, eM);
    if (sz[0] == 64)
      errDefault = errPrev;
    // No sliding: no boundary shear; symmetric about phi = 0: no F_z.
    EXPECT_EQ(code[1], 0.0);
    EXPECT_LT(std::abs(code[2]), 1e-9 * std::abs(code[0]));
  }
  // At the default grid, within 1e-4: the Gauss points integrate p_c of the gap interpolated
  // bicubically from the nodes, whose error falls as dphi^4 (6.3e-6 seen). With the bilinear
  // gap it was 0.24 %: its chord error in phi, (dphi^2 / 8) (e + y alpha) = 1e-9 m = 0.002
  // sigma, moves p_c by ~(5/2)(F_3/2 / F_5/2) 0.002.
  EXPECT_LT(errDefault, 1e-4);
}

// A contact in the middle of the skirt, where a barrel profile and an elliptic skirt meet the
// liner: the example piston's gap h = c0 - e cos phi + 0.12 (y + 6 mm)^2 / mm^2 um + 150 um
// sin^2 phi, pressed to h_min = 0.5 um = 0.69 sigma. The bilinear interpolant of this convex
// gap lies above it between the nodes (by ~(dy^2 + (R dphi)^2 ...) / 8 of its curvature, 0.014
// um at 64 x 48) and took 7.1 % of the asperity load away; the bicubic interpolant of the
// nodes does not. Reference: p_c of the exact gap by a composite Gauss-Legendre rule here
// (6 points x 240 panels in each direction over the contact window |phi| < 0.15 rad, |y + 6
// mm| < 6 mm, outside which h > 4.5 sigma).
TEST(SkirtSideLubrication, MidSkirtBarrelContactMatchesTheExactGapQuadrature) {
  const double R = 0.03725, arc = 80.0 * kPi / 180.0, L = 0.030, yTop = 0.012, c0 = 40e-6;
  const auto law = gtLaw(0.4e-6, 0.6e-6);
  const double hMin = 0.5e-6, e = c0 - hMin;
  auto gap = [&](double phi, double y) {
    const double d = y * 1e3 + 6.0, s = std::sin(phi);
    return c0 - e * std::cos(phi) + 0.12e-6 * d * d + 150e-6 * s * s;
  };
  const auto gauss6 = ps::test::gaussLegendre(6);
  const auto& xg = gauss6.first;
  const auto& wg = gauss6.second;
  auto rule = [&](double a, double b, int panels) {
    std::vector<std::pair<double, double>> points;
    const double d = (b - a) / panels;
    for (int k = 0; k < panels; ++k)
      for (std::size_t m = 0; m < xg.size(); ++m)
        points.push_back({a + d * (k + 0.5 + 0.5 * xg[m]), 0.5 * d * wg[m]});
    return points;
  };
  double refFx = 0.0;
  for (const auto& [phi, wphi] : rule(-0.15, 0.15, 240))
    for (const auto& [y, wy] : rule(-0.012, 0.0, 240))
      refFx -= law->calcPressure(gap(phi, y)) * std::cos(phi) * R * wphi * wy;
  const ps::SkirtSideGrid g = makeGrid(arc, L, yTop, 64, 48, ps::SkirtSide::Thrust, R);
  ps::SkirtSideLubrication lub =
      makeLubrication(g, patirCheng(0.4e-6, 0.6e-6), tightSolver(), law);
  Pose q;
  q.e = e;
  ps::SkirtSideResults out;
  lub.solve(rigidFields(g, c0, q,
                        [&](double phi, double y) {
                          const double d = y * 1e3 + 6.0, s = std::sin(phi);
                          return 0.12e-6 * d * d + 150e-6 * s * s;
                        }),
            inputs(0.01), out);
  const double err = relErr(out.asperityLoads.force_N[0], refFx);
  std::printf("  reference F_x = %.8g N, 64 x 48: %.8g N, relative error %.2e\n", refFx,
              out.asperityLoads.force_N[0], err);
  EXPECT_LT(err, 1e-3);
}

// The same edge contact off-centre (z_t = 3 um) and sliding (U = (0.4, 4) m/s, boundary
// friction f = 0.1, v_eps = 1 mm/s): all six loads against the quadrature of the traction
//   t = -p_c e_r + tau_y e_y + tau_phi e_phi,  (tau_phi, tau_y) = f p_c U / sqrt(|U|^2 + v_eps^2)
// (BoundaryFriction.h: on the skirt, along U), force int t dA and moment int r x t dA with
// r = (R cos phi, y, R sin phi) and the unit vectors built here as 3-vectors (not the load
// formulas of SkirtSideGrid.h). This checks the moment arms of the Gauss correction's kernel.
TEST(SkirtSideLubrication, OffCentreSlidingEdgeContactMatchesTheTractionQuadratureRowByRow) {
  EdgeContact ec;
  const auto law = gtLaw();
  const double sigma = law->compositeSigma_m(), z = 3e-6, ux = 0.4, uy = 4.0;
  ec.e = ec.c0 - ec.yBottom() * ec.alpha + 0.5 * sigma;
  const double fg = 0.1 / std::sqrt(ux * ux + uy * uy + 1e-6);  // f g(|U|) / |U|
  // Reference (same rule as referenceContactLoads).
  const auto [xp, wp] = ps::test::gaussLegendre(200);
  // Not a structured binding: the lambda below captures the rule, and clang before 16
  // (Debian 12's clang 14, the sanitizer build) cannot capture a structured binding.
  const auto gauss6 = ps::test::gaussLegendre(6);
  const auto& xg = gauss6.first;
  const auto& wg = gauss6.second;
  Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
  const double yB = ec.yBottom();
  for (std::size_t a = 0; a < xp.size(); ++a) {
    const double phi = 0.5 * ec.arc * xp[a], wphi = 0.5 * ec.arc * wp[a] * ec.R;
    const Eigen::Vector3d er(std::cos(phi), 0.0, std::sin(phi)), ey(0.0, 1.0, 0.0),
        ephi(-std::sin(phi), 0.0, std::cos(phi));
    for (int panel = 0; panel < 440; ++panel) {
      const double y0 =
          panel < 400 ? yB + 1e-5 * panel : yB + 0.004 + (ec.L - 0.004) / 40 * (panel - 400);
      const double d = panel < 400 ? 1e-5 : (ec.L - 0.004) / 40;
      for (std::size_t m = 0; m < xg.size(); ++m) {
        const double y = y0 + 0.5 * d * (1.0 + xg[m]), w = wphi * 0.5 * d * wg[m];
        const double p = law->calcPressure(ec.gap(phi, y) - z * std::sin(phi));
        const Eigen::Vector3d t = -p * er + fg * p * uy * ey + fg * p * ux * ephi;
        const Eigen::Vector3d r(ec.R * std::cos(phi), y, ec.R * std::sin(phi));
        F += w * t;
        M += w * r.cross(t);
      }
    }
  }
  Loads6 ref;
  ref << F, M;
  std::printf("  reference: F = (%.6g, %.6g, %.6g) N, M = (%.6g, %.6g, %.6g) N m\n", ref[0], ref[1],
              ref[2], ref[3], ref[4], ref[5]);
  for (const auto& sz : {std::pair{64, 48}, std::pair{256, 192}}) {
    const ps::SkirtSideGrid g = makeGrid(ec.arc, ec.L, ec.yTop, sz.first, sz.second);
    ps::SkirtSideLubrication lub = makeLubrication(g, patirCheng(), tightSolver(), law);
    Pose q;
    q.e = ec.e;
    q.alpha = ec.alpha;
    q.z = z;
    ps::SkirtSideResults out;
    lub.solve(rigidFields(g, ec.c0, q), inputs(0.01, uy, ux), out);
    const Loads6 code = stack(out.asperityLoads);
    double worst = 0.0;
    for (int r = 0; r < 6; ++r)
      worst = std::max(worst, relErr(code[r], ref[r]));
    std::printf("  %d x %d: worst row error %.2e\n", sz.first, sz.second, worst);
    // 0.5 % at the default grid (as above), 0.05 % at 4 x the nodes (dphi^2: 1/16).
    EXPECT_LT(worst, sz.first == 64 ? 5e-3 : 5e-4) << sz.first << " x " << sz.second;
  }
}

TEST(SkirtSideLubrication, EdgeContactStiffnessEqualsCentralDifferences) {
  // The stiffness where the Gauss correction carries most of the load (the edge contact above:
  // the nodal interpolant alone is 4.8 times the load at 64 x 48): dLoads_dPose against central
  // differences of the asperity loads, with sliding (U = (0.2, 3) m/s) so that the boundary
  // shear's part shows. Steps 2e-3 sigma (tolerance 1e-4 of a column, as above).
  EdgeContact ec;
  const auto law = gtLaw();
  const double sigma = law->compositeSigma_m();
  ec.e = ec.c0 - ec.yBottom() * ec.alpha + 0.5 * sigma;
  const ps::SkirtSideGrid g = makeGrid(ec.arc, ec.L, ec.yTop);
  ps::SkirtSideLubrication lub = makeLubrication(g, patirCheng(), tightSolver(), law);
  Pose q;
  q.e = ec.e;
  q.alpha = ec.alpha;
  q.z = 2e-6;  // off-centre: the tertiary column is not zero by symmetry
  ps::SkirtSideResults out;
  lub.solve(rigidFields(g, ec.c0, q), inputs(0.01, 3.0, 0.2), out);
  const Eigen::Matrix<double, 6, 3> analytic = out.dLoads_dPose;
  const double steps[3] = {1e-9, 1e-9 / 0.025, 1e-9};
  for (int c = 0; c < 3; ++c) {
    Loads6 l[2];
    for (int side = 0; side < 2; ++side) {
      Pose qq = q;
      (c == 0 ? qq.e : c == 1 ? qq.alpha : qq.z) += (side == 0 ? 1.0 : -1.0) * steps[c];
      ps::SkirtSideResults o;
      lub.solve(rigidFields(g, ec.c0, qq), inputs(0.01, 3.0, 0.2), o);
      l[side] = stack(o.asperityLoads);
    }
    const Loads6 fd = (l[0] - l[1]) / (2.0 * steps[c]);
    const double err = (fd - analytic.col(c)).norm() / fd.norm();
    std::printf("  column %d: |FD - analytic| / |FD| = %.2e\n", c, err);
    EXPECT_LT(err, 1e-4) << "column " << c;
  }
}

TEST(SkirtSideLubrication, WithoutCellsNearContactTheAsperityLoadsAreTheNodalInterpolants) {
  // Smallest gap 4.6 sigma (> the 4.5 sigma of the Gauss correction): p_c is small but not
  // zero, and the loads must be exactly those of the nodal interpolant (SkirtSideGrid weights).
  EdgeContact ec;
  const auto law = gtLaw();
  const double sigma = law->compositeSigma_m();
  ec.e = ec.c0 - ec.yBottom() * ec.alpha - 4.6 * sigma;
  const ps::SkirtSideGrid g = makeGrid(ec.arc, ec.L, ec.yTop);
  ps::SkirtSideLubrication lub = makeLubrication(g, patirCheng(), tightSolver(), law);
  Pose q;
  q.e = ec.e;
  q.alpha = ec.alpha;
  const double ux = 0.1, uy = 2.0;
  ps::SkirtSideResults out;
  lub.solve(rigidFields(g, ec.c0, q), inputs(0.01, uy, ux), out);
  EXPECT_NEAR(out.minGapOverSigma, 4.6, 0.01);  // no node on phi = 0 (as above)
  const Eigen::ArrayXd pc =
      Eigen::Map<const Eigen::ArrayXd>(out.contact.pressure_Pa.data(), g.nodeCount());
  ASSERT_GT(pc.maxCoeff(), 0.0);
  const Loads6 nodal = stack(
      g.calcLoadsOnPiston(pc, out.boundaryShearAxial_Pa, out.boundaryShearCircumferential_Pa));
  const Loads6 code = stack(out.asperityLoads);
  for (int r = 0; r < 6; ++r)
    EXPECT_EQ(code[r], nodal[r]) << "row " << r;
  // The contact load behind the friction is the nodal one too: f g(|U|) U_y / |U| W with the
  // default f = 0.1, v_eps = 1 mm/s (Algebraic): f U_y / sqrt(|U|^2 + v_eps^2).
  const double W = (g.getAreaWeights_m2() * pc).sum();
  const double fy = 0.1 * uy / std::sqrt(uy * uy + ux * ux + 1e-6);
  EXPECT_LT(relErr(out.asperityFrictionAxial_N, fy * W), 1e-12);
}

// The anti-thrust side is the mirror image of the thrust side in the plane x = 0 (phi -> pi -
// phi; its film grid's x runs the other way). Mirroring the pose and its rates (e, alpha ->
// -e, -alpha) with the same axial sliding must mirror the loads: F_x, M_y, M_z change sign,
// F_y, F_z, M_x do not (moments are pseudo-vectors), and every scalar figure (normal forces,
// friction, power, shares, h_min, wear) is the same. A case with everything on: squeeze,
// wedge, cavitation, a mixed contact at the bottom edge with boundary friction. Tolerance
// 1e-8 of the largest load (solver tolerance; the two grids are mirror images up to rounding
// of their angles).
TEST(SkirtSideLubrication, AntiThrustSideIsTheMirrorImageOfTheThrustSide) {
  ps::SkirtSideResults r[2];
  for (int s = 0; s < 2; ++s) {
    const ps::SkirtSide side = s == 0 ? ps::SkirtSide::Thrust : ps::SkirtSide::AntiThrust;
    const ps::SkirtSideGrid g = makeGrid(kPi / 3, 0.04, 0.015, 64, 48, side);
    ps::SkirtLubricationParameters lp = tightSolver();
    lp.wearCoefficient_m2pN = 1e-17;
    ps::SkirtSideLubrication lub = makeLubrication(g, patirCheng(), lp);
    const double sign = s == 0 ? 1.0 : -1.0;
    Pose q;
    q.alpha = -2e-4 * sign;
    q.e = (20e-6 - 0.025 * 2e-4 - 1.5 * lub.getCompositeSigma_m()) * sign;
    q.eDot = -0.0005 * sign;  // opening: cavitation
    q.alphaDot = -0.05 * sign;
    lub.solve(rigidFields(g, 20e-6, q), inputs(0.008, 6.0), r[s]);
  }
  const Loads6 t = stack(r[0].totalLoads), a = stack(r[1].totalLoads);
  Loads6 mirror;
  mirror << -1, 1, 1, 1, -1, -1;
  const double scale = t.cwiseAbs().maxCoeff();
  EXPECT_LT((a - mirror.cwiseProduct(t)).cwiseAbs().maxCoeff(), 1e-8 * scale)
      << "thrust " << t.transpose() << "\nanti-thrust " << a.transpose();
  for (int c = 0; c < 2; ++c) {  // lateral, tilt columns: mirrored rows, mirrored coordinate
    EXPECT_LT((r[1].dLoads_dPoseRate.col(c) + mirror.cwiseProduct(r[0].dLoads_dPoseRate.col(c)))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-8 * r[0].dLoads_dPoseRate.col(c).cwiseAbs().maxCoeff());
    EXPECT_LT((r[1].dLoads_dPose.col(c) + mirror.cwiseProduct(r[0].dLoads_dPose.col(c)))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-8 * r[0].dLoads_dPose.col(c).cwiseAbs().maxCoeff());
  }
  auto same = [](double x, double y, const char* what) {
    EXPECT_LE(std::abs(x - y), 1e-8 * std::max(std::abs(x), 1e-300)) << what;
  };
  EXPECT_GT(r[0].hydrodynamicNormalForce_N, 0.0);
  EXPECT_GT(r[0].asperityNormalForce_N, 0.0);
  same(r[0].hydrodynamicNormalForce_N, r[1].hydrodynamicNormalForce_N, "hydrodynamic normal");
  same(r[0].asperityNormalForce_N, r[1].asperityNormalForce_N, "asperity normal");
  same(r[0].hydrodynamicFrictionAxial_N, r[1].hydrodynamicFrictionAxial_N, "film friction");
  same(r[0].asperityFrictionAxial_N, r[1].asperityFrictionAxial_N, "boundary friction");
  same(r[0].frictionPower_W, r[1].frictionPower_W, "power");
  same(r[0].minFilmThickness_m, r[1].minFilmThickness_m, "h_min");
  same(r[0].mixedShare, r[1].mixedShare, "mixed share");
  same(r[0].wearRate_m3ps, r[1].wearRate_m3ps, "wear");
  EXPECT_GT(r[0].film.cavitatedNodes, 0);
  EXPECT_EQ(r[0].film.cavitatedNodes, r[1].film.cavitatedNodes);
}

// ------------------------------------------------------------------------------------------
// 6. Allocation: every call after the first at a grid size allocates nothing.
TEST(SkirtSideLubrication, SecondAndLaterCallsAllocateNothing) {
  RunningCase rc;
  const ps::SkirtSideGrid& g = rc.grid;
  for (lub::CavitationModel model :
       {lub::CavitationModel::Reynolds, lub::CavitationModel::MassConserving}) {
    ps::SkirtLubricationParameters lp;  // the default solver options
    lp.cavitation = model;
    lp.wearCoefficient_m2pN = 1e-17;
    ps::SkirtSideLubrication lub = makeLubrication(g, patirCheng(), lp);
    const double sigma = lub.getCompositeSigma_m();
    Pose q;
    q.alpha = -2e-4;
    q.e = rc.c0 - (-0.025) * q.alpha - 1.5 * sigma;  // mixed contact at the bottom edge
    q.eDot = 0.01;
    q.alphaDot = -0.3;
    ps::GapFields f = rigidFields(g, rc.c0, q);
    ps::SkirtSideInputs in = inputs(rc.eta, rc.uy, 0.05);
    in.supplyFilm_m = 8e-6;
    Eigen::ArrayXd previousFill = Eigen::ArrayXd::Constant(g.nodeCount(), 0.8);
    lub::FilmHistory history;
    history.last.fillFraction = previousFill;
    if (model == lub::CavitationModel::MassConserving) {
      in.history = &history;
      in.timeStep_s = 2e-5;
    }
    ps::SkirtSideResults out;
    lub.solve(f, in, out);  // first call: sizes everything
    double sink = 0.0;
    const long count = pistondyn::test::allocationsDuring([&] {
      for (int call = 0; call < 10; ++call) {
        // Move the pose a little (the caller recomputes the gap in place).
        const double de = 2e-7 * call;
        for (int k = 0; k < g.nodeCount(); ++k)
          f.gap_m[k] -= de * g.getNodeCosPhi()[k];
        in.slidingVelocityAxial_mps = rc.uy - 0.5 * call;
        if (model == lub::CavitationModel::MassConserving)
          previousFill = out.film.fillFraction();
        lub.solve(f, in, out);
        sink += out.totalLoads.force_N.x() + out.dLoads_dPose(0, 0);
      }
    });
    EXPECT_EQ(count, 0) << (model == lub::CavitationModel::Reynolds ? "Reynolds" : "JFO");
    EXPECT_TRUE(std::isfinite(sink));
  }
}

// A barrel-shaped skirt: parabolic profile, 15 um drop at both edges of the 40 mm skirt
// (centre 5 mm below the pin).
double barrel(double, double y) {
  const double yMid = -0.005, drop = 15e-6, half = 0.02;
  return drop * (y - yMid) * (y - yMid) / (half * half);
}

// ------------------------------------------------------------------------------------------
// 7. Bad input: std::invalid_argument naming the input; a film that does not converge:
// std::runtime_error naming the side.
TEST(SkirtSideLubrication, BadInputIsRejectedNamingTheInput) {
  const ps::SkirtSideGrid g = makeGrid(1.0, 0.03, 0.01, 9, 7);
  const int n = g.nodeCount();  // 63
  ps::SkirtSideLubrication lub = makeLubrication(g, patirCheng());
  const ps::GapFields good = rigidFields(g, 20e-6, Pose());
  auto rejects = [&](auto editGap, auto editInputs,
                     std::initializer_list<std::string_view> fragments) {
    ps::GapFields f = good;
    ps::SkirtSideInputs in = inputs(0.01, 1.0);
    editGap(f);
    editInputs(in);
    ps::SkirtSideResults out;
    expectInvalidArgument([&] { lub.solve(f, in, out); }, fragments);
  };
  auto noGap = [](ps::GapFields&) {};
  auto noInputs = [](ps::SkirtSideInputs&) {};
  const char* s = "SkirtSideLubrication::solve";
  rejects([&](ps::GapFields& f) { f.gap_m.resize(n - 1); }, noInputs,
          {s, "gap.gap_m has 62 entries", "63", "thrust"});
  rejects([&](ps::GapFields& f) { f.gapRate_mps.resize(n + 1); }, noInputs,
          {s, "gap.gapRate_mps has 64 entries", "63"});
  rejects([&](ps::GapFields& f) { f.squeezeBasis.resize(n - 2, 3); }, noInputs,
          {s, "gap.squeezeBasis is 61 x 3", "63"});
  rejects([&](ps::GapFields& f) { f.squeezeBasis.resize(n, 1); }, noInputs,
          {s, "gap.squeezeBasis is 63 x 1", "inputs.squeezeColumns = 3"});
  rejects([&](ps::GapFields& f) { f.dGap_dPose.resize(n, 2); }, noInputs,
          {s, "gap.dGap_dPose is 63 x 2", "63 x 3"});
  rejects([&](ps::GapFields& f) { f.dGap_dPose.resize(0, 0); }, noInputs,
          {s, "gap.dGap_dPose is 0 x 0"});
  rejects([&](ps::GapFields& f) { f.gap_m[5] = NAN; }, noInputs,
          {s, "gap.gap_m[5] = nan m", "finite", "thrust"});
  rejects([&](ps::GapFields& f) { f.gapRate_mps[3] = INFINITY; }, noInputs,
          {s, "gap.gapRate_mps[3] = inf m/s", "finite"});
  rejects([&](ps::GapFields& f) { f.dGap_dPose(4, 1) = NAN; }, noInputs,
          {s, "gap.dGap_dPose(4, 1) = nan", "finite"});
  rejects([&](ps::GapFields& f) { f.squeezeBasis(2, 0) = NAN; }, noInputs,
          {s, "gap.squeezeBasis(2, 0) = nan", "finite"});
  for (double eta : {0.0, -1e-3, double(NAN), double(INFINITY)})
    rejects(noGap, [&](ps::SkirtSideInputs& in) { in.viscosity_Pas = eta; },
            {s, "inputs.viscosity_Pas = ", "Pa s", "positive and finite"});
  rejects(noGap, [](ps::SkirtSideInputs& in) { in.viscosity_Pas = 0.0; },
          {"inputs.viscosity_Pas = 0 Pa s"});
  for (double h : {0.0, -1e-6, double(NAN)})
    rejects(noGap, [&](ps::SkirtSideInputs& in) { in.supplyFilm_m = h; },
            {s, "inputs.supplyFilm_m = ", " m must be positive"});
  rejects(noGap, [](ps::SkirtSideInputs& in) { in.slidingVelocityAxial_mps = NAN; },
          {s, "inputs.slidingVelocityAxial_mps = nan m/s", "finite"});
  rejects(noGap, [](ps::SkirtSideInputs& in) { in.slidingVelocityCircumferential_mps = INFINITY; },
          {s, "inputs.slidingVelocityCircumferential_mps = inf m/s", "finite"});
  rejects(noGap, [](ps::SkirtSideInputs& in) { in.squeezeColumns = 4; },
          {s, "inputs.squeezeColumns = 4", "0..3"});

  // Mass-conserving: the history's size (checked once, by the film solver), and the step.
  ps::SkirtSideLubrication jfo =
      makeLubrication(g, patirCheng(), tightSolver(lub::CavitationModel::MassConserving));
  const Eigen::ArrayXd wrongSize = Eigen::ArrayXd::Constant(n + 3, 1.0);
  ps::SkirtSideInputs in = inputs(0.01, 1.0);
  lub::FilmHistory wrongHistory;
  wrongHistory.last.fillFraction = wrongSize;
  in.history = &wrongHistory;
  in.timeStep_s = 1e-5;
  ps::SkirtSideResults out;
  expectInvalidArgument([&] { jfo.solve(good, in, out); },
                        {"problem.history.last.fillFraction has 66 entries", "63"});
  in.history = nullptr;
  in.timeStep_s = NAN;
  expectInvalidArgument([&] { jfo.solve(good, in, out); }, {s, "inputs.timeStep_s = nan s"});

  // Constructor: parameters, null models, one roughness pair for film and contact.
  const char* c = "SkirtSideLubrication";
  auto ctorRejects = [&](auto edit, std::initializer_list<std::string_view> fragments) {
    ps::SkirtLubricationParameters p;
    edit(p);
    expectInvalidArgument([&] { makeLubrication(g, patirCheng(), p); }, fragments);
  };
  using P = ps::SkirtLubricationParameters;
  ctorRejects([](P& p) { p.clampFraction = 0.0; },
              {c, "parameters.clampFraction = 0", "positive and finite"});
  ctorRejects([](P& p) { p.minimumClampGap_m = -1e-9; },
              {c, "parameters.minimumClampGap_m = -1e-09 m", "positive and finite"});
  ctorRejects([](P& p) { p.wearCoefficient_m2pN = NAN; },
              {c, "parameters.wearCoefficient_m2pN = nan", "non-negative"});
  ctorRejects([](P& p) { p.cavitationPressure_Pa = INFINITY; },
              {c, "parameters.cavitationPressure_Pa = inf Pa", "finite"});
  ctorRejects(
      [](P& p) {
        p.cavitation = lub::CavitationModel::MassConserving;
        p.edgePressure_Pa = -1e3;
      },
      {c, "parameters.edgePressure_Pa = -1000 Pa", "parameters.cavitationPressure_Pa = 0 Pa"});
  ctorRejects([](P& p) { p.edgePressure_Pa = NAN; },
              {c, "parameters.edgePressure_Pa = nan Pa", "finite"});
  expectInvalidArgument(
      [&] { ps::SkirtSideLubrication(g, nullptr, gtLaw(), cf::BoundaryFriction(), P()); },
      {c, "flowFactors", "null"});
  expectInvalidArgument(
      [&] { ps::SkirtSideLubrication(g, patirCheng(), nullptr, cf::BoundaryFriction(), P()); },
      {c, "contactLaw", "null"});
  // Skirt Rq 0.4 um in the film, 0.5 um in the contact law: sigma 0.5 um vs 0.583 um; and a
  // difference in the 7th digit, which a 6-digit format would print as two equal numbers.
  const auto film = patirCheng(0.3e-6, 0.4e-6);
  const auto law1 = gtLaw(0.3e-6, 0.5e-6), law2 = gtLaw(0.3e-6, 0.4000005e-6);
  using pistondyn::common::formatNumber;  // the conventions' number format
  expectInvalidArgument([&] { makeLubrication(g, film, P(), law1); },
                        {c, "roughness", formatNumber(film->compositeSigma_m()) + " m",
                         formatNumber(law1->compositeSigma_m()) + " m"});
  expectInvalidArgument([&] { makeLubrication(g, film, P(), law2); },
                        {c, "roughness", formatNumber(film->compositeSigma_m()) + " m",
                         formatNumber(law2->compositeSigma_m()) + " m"});
}

TEST(SkirtSideLubrication, FilmThatDoesNotConvergeThrowsARuntimeErrorNamingTheSide) {
  for (ps::SkirtSide side : {ps::SkirtSide::Thrust, ps::SkirtSide::AntiThrust}) {
    const ps::SkirtSideGrid g = makeGrid(1.0, 0.04, 0.015, 64, 48, side);
    ps::SkirtLubricationParameters p;
    p.solver.maxActiveSetIterations = 1;  // one active-set step cannot find the cavitation set
    p.solver.fallbackToReference = false;
    ps::SkirtSideLubrication lub = makeLubrication(g, patirCheng(), p);
    ps::SkirtSideResults out;
    try {
      // The barrel of test 8 sliding up: converging-diverging, cavitated in its upper half.
      lub.solve(rigidFields(g, 12e-6, Pose(), barrel), inputs(0.01, 8.0), out);
      ADD_FAILURE() << "no exception";
    } catch (const std::invalid_argument& e) {
      ADD_FAILURE() << "invalid_argument instead of runtime_error: " << e.what();
    } catch (const std::runtime_error& e) {
      const std::string msg = e.what();
      const char* name = side == ps::SkirtSide::Thrust ? "thrust side" : "anti-thrust side";
      EXPECT_NE(msg.find(name), std::string::npos) << msg;
      EXPECT_NE(msg.find("did not converge"), std::string::npos) << msg;
      EXPECT_NE(msg.find("residual"), std::string::npos) << msg;
    }
  }
}

// ------------------------------------------------------------------------------------------
// 8. Mass-conserving (JFO) model.
//
// A barrel-shaped skirt (parabolic profile, 15 um drop at both edges) sliding up at 5 m/s with
// a starved inlet (8 um of oil on the liner) and a lateral and tilt squeeze, from a previous
// fill fraction of 0.7 over a step of 20 us: the film's discrete oil balance (FilmResult:
// inflow through the faces from the prescribed nodes, outflow, storage rate) must close,
// inflow - outflow = storage, to the solver tolerance (1e-11 relative residual per node; the
// sum over the nodes stays below 1e-8 of the throughput).
TEST(SkirtSideLubrication, MassConservingFilmClosesItsOilBalance) {
  RunningCase rc;
  const ps::SkirtSideGrid& g = rc.grid;
  ps::SkirtSideLubrication lub =
      makeLubrication(g, patirCheng(), tightSolver(lub::CavitationModel::MassConserving));
  Pose q;
  q.e = 3e-6;
  q.eDot = 0.004;
  q.alphaDot = 0.2;
  const Eigen::ArrayXd previous = Eigen::ArrayXd::Constant(g.nodeCount(), 0.7);
  ps::SkirtSideInputs in = inputs(rc.eta, 5.0);
  in.supplyFilm_m = 8e-6;
  lub::FilmHistory history;
  history.last.fillFraction = previous;
  in.history = &history;
  in.timeStep_s = 2e-5;
  ps::SkirtSideResults out;
  lub.solve(rigidFields(g, 12e-6, q, barrel), in, out);
  const lub::FilmResult& r = out.film;
  const double imbalance = r.boundaryInflow_m3ps - r.boundaryOutflow_m3ps - r.storageRate_m3ps;
  const double throughput = std::max(r.boundaryInflow_m3ps, r.boundaryOutflow_m3ps);
  std::printf(
      "  inflow %.6e, outflow %.6e, storage %.6e m^3/s; imbalance %.2e of the "
      "throughput; wetted share %.4f, min fill %.4f\n",
      r.boundaryInflow_m3ps, r.boundaryOutflow_m3ps, r.storageRate_m3ps, imbalance / throughput,
      out.wettedShare, r.fillFraction().minCoeff());
  EXPECT_GT(throughput, 0.0);
  EXPECT_LT(std::abs(imbalance), 1e-8 * throughput);
  EXPECT_LT(r.fillFraction().minCoeff(), 1.0);  // a partial film somewhere: the case is JFO's
  EXPECT_GT(out.wettedShare, 0.0);
}

TEST(SkirtSideLubrication, FloodedSteadyMassConservingFilmMatchesTheReynoldsModel) {
  // (a) The convergent slider of test 2 (arc 1 rad): nothing cavitates, the fill fraction is 1
  // everywhere, and the mass-conserving discretisation is then exactly the Reynolds one
  // (FilmProblem.h): loads equal to the solver tolerance (1e-8 of the load).
  // (b) The barrel: the film ruptures in the diverging upper half and the cavitated zone runs
  // out through the top edge; there is no reformation inside the side, and JFO's rupture
  // condition in steady flow is the Reynolds condition (p = dp/dn = 0), so the two models
  // differ only by the discretisation of the rupture boundary (upwind fill transport vs the
  // projected pressure): within 1 % of the load.
  const double eta = 0.01, U = 8.0, L = 0.02, yT = 0.01;
  const double alpha = 20e-6 / (2.0 * yT - (yT - L));
  struct Case {
    const char* name;
    Pose q;
    double c0;
    std::function<double(double, double)> extra;
    double tol;
  };
  Pose slider;
  slider.alpha = alpha;
  const Case cases[] = {{"slider", slider, 20e-6, {}, 1e-8},
                        {"barrel", Pose(), 12e-6, barrel, 1e-2}};
  for (const Case& cs : cases) {
    const bool isSlider = std::string(cs.name) == "slider";
    const ps::SkirtSideGrid g = isSlider ? makeGrid(1.0, L, yT) : makeGrid(kPi / 3, 0.04, 0.015);
    ps::SkirtSideLubrication rey = makeLubrication(g, patirCheng());
    ps::SkirtSideLubrication jfo =
        makeLubrication(g, patirCheng(), tightSolver(lub::CavitationModel::MassConserving));
    const ps::GapFields f = rigidFields(g, cs.c0, cs.q, cs.extra);
    ps::SkirtSideResults a, b;
    rey.solve(f, inputs(eta, U), a);
    jfo.solve(f, inputs(eta, U), b);  // steady (timeStep +inf), fully flooded
    const double eF = relErr(b.totalLoads.force_N.x(), a.totalLoads.force_N.x());
    const double eM = relErr(b.totalLoads.moment_Nm.z(), a.totalLoads.moment_Nm.z());
    std::printf(
        "  %s: Reynolds F_x %.8g N (%d cavitated), JFO F_x %.8g N, min fill %.4f; "
        "differ %.2e (F_x), %.2e (M_z)\n",
        cs.name, a.totalLoads.force_N.x(), a.film.cavitatedNodes, b.totalLoads.force_N.x(),
        b.film.fillFraction().minCoeff(), eF, eM);
    EXPECT_LT(std::max(eF, eM), cs.tol) << cs.name;
    if (isSlider) {
      EXPECT_EQ(a.film.cavitatedNodes, 0);
      EXPECT_NEAR(b.wettedShare, 1.0, 1e-12);
      EXPECT_DOUBLE_EQ(b.film.fillFraction().minCoeff(), 1.0);
    } else {
      EXPECT_GT(a.film.cavitatedNodes, 0);
    }
  }
}

}  // namespace
