// The power balance of a steady sliding film on one skirt side: the friction power U . F of
// the film's force on the piston equals the power the film dissipates,
//   D = int [ theta eta |U|^2 / h + h^3 |grad p|^2 / (12 eta) ] dA,
// for a smooth film whose edges are at one pressure (the integral of the viscous dissipation
// eta (du/dz)^2 over the film's thickness; the cross term of Couette and Poiseuille flow
// integrates to zero). D is evaluated here from the returned pressure and film gap with
// central differences of our own (nodes and area weights of the grid, nothing of the code
// under test), and the film solver's own viscousDissipation_W is checked against it.
//
// Two cases of the issue: a barrel-shaped skirt at zero tilt, where the film pressure's axial
// component on the sloped skirt surface (GapFields::skirtGapSlope) is what the shear alone
// misses, and a round skirt tilted by alpha, where the skirt's piston-frame loads turned into
// the bore frame (the element's rotation, done here: F_y,bore = cos(alpha) F_y - sin(alpha)
// F_x) carry it. Both cavitation models with a steady film (Reynolds; mass-conserving with
// flooded edges).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"
#include "pistondyn/lubrication/FlowFactorModel.h"
#include "pistondyn/skirt/SkirtSideLubrication.h"

namespace {

namespace ps = pistondyn::skirt;
namespace lub = pistondyn::lubrication;
namespace cf = pistondyn::contact_forces;

constexpr double kEta_Pas = 0.008, kU_mps = 8.0;

struct Case {
  ps::SkirtSideGrid grid;
  ps::GapFields gap;
};

// A thrust side of a 74 mm bore (R 37 mm), 1 rad wide, 30 mm long from 12 mm above the pin;
// the gap h = c0 - (e + alpha y) cos(phi) + b (y - y0)^2 and the analytic slope of the skirt's
// own term, d/dy [b (y - y0)^2].
Case makeCase(int nPhi, int nY, double e_m, double alpha_rad, double barrel_per_m) {
  ps::SkirtSideGridParameters p;
  p.side = ps::SkirtSide::Thrust;
  p.radius_m = 0.037;
  p.arcWidth_rad = 1.0;
  p.nPhi = nPhi;
  p.nY = nY;
  p.skirtTopHeight_m = 0.012;
  p.skirtLength_m = 0.030;
  const ps::SkirtSideGrid g(p);
  const int n = g.nodeCount();
  const double c0 = 20e-6, y0 = -0.003;
  ps::GapFields f;
  f.gap_m.resize(n);
  f.gapRate_mps.setZero(n);
  f.skirtGapSlope.resize(n);
  f.dGap_dPose.resize(n, 3);
  for (int k = 0; k < n; ++k) {
    const double phi = g.getNodePhi_rad()[k], y = g.getNodeY_m()[k];
    f.gap_m[k] = c0 - (e_m + alpha_rad * y) * std::cos(phi) + barrel_per_m * (y - y0) * (y - y0);
    f.skirtGapSlope[k] = 2.0 * barrel_per_m * (y - y0);
    f.dGap_dPose(k, 0) = -std::cos(phi);
    f.dGap_dPose(k, 1) = -y * std::cos(phi);
    f.dGap_dPose(k, 2) = -std::sin(phi);
  }
  f.squeezeBasis = f.dGap_dPose;
  return {g, f};
}

// D from the nodal pressure and film gap (this file's comment): central differences inside,
// one-sided (second order) at the edges, the grid's exact bilinear area weights.
double referenceDissipation_W(const ps::SkirtSideGrid& g, const ps::SkirtSideResults& r) {
  const int nx = g.nPhi(), ny = g.nY();
  const double R = g.getRadius_m();
  const auto& phi = g.getPhiNodes_rad();
  const auto& y = g.getYNodes_m();
  const Eigen::ArrayXd& p = r.film.pressure_Pa();
  const Eigen::ArrayXd& theta = r.film.fillFraction();
  const auto derivative = [](const Eigen::VectorXd& c, int i, auto value) {
    const int n = static_cast<int>(c.size());
    if (i == 0)
      return (-3.0 * value(0) + 4.0 * value(1) - value(2)) / (c[2] - c[0]);
    if (i == n - 1)
      return (3.0 * value(n - 1) - 4.0 * value(n - 2) + value(n - 3)) / (c[n - 1] - c[n - 3]);
    return (value(i + 1) - value(i - 1)) / (c[i + 1] - c[i - 1]);
  };
  double d = 0.0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int k = i + nx * j;
      const double h = r.filmGap_m[k];
      const double dpdx =
          derivative(phi, i, [&](int a) { return p[a + nx * j]; }) / R;  // x = R phi
      const double dpdy = derivative(y, j, [&](int b) { return p[i + nx * b]; });
      d += g.getAreaWeights_m2()[k] *
           (theta[k] * kEta_Pas * kU_mps * kU_mps / h +
            h * h * h * (dpdx * dpdx + dpdy * dpdy) / (12.0 * kEta_Pas));
    }
  }
  return d;
}

struct Balance {
  double friction_W, shearOnly_W, dissipation_W, filmDissipation_W;
};

Balance solve(const Case& c, lub::CavitationModel model, double alpha_rad) {
  ps::SkirtLubricationParameters lp;
  lp.cavitation = model;
  lp.solver.tolerance = 1e-12;
  cf::GreenwoodTrippParameters gt;
  gt.roughnessSurface1_m = 0.3e-6;
  gt.roughnessSurface2_m = 0.4e-6;
  ps::SkirtSideLubrication lub(c.grid, std::make_shared<const lub::SmoothFlowFactors>(),
                               std::make_shared<const cf::GreenwoodTrippLaw>(gt),
                               cf::BoundaryFriction(cf::BoundaryFrictionParameters()), lp);
  ps::SkirtSideInputs in;
  in.viscosity_Pas = kEta_Pas;
  in.slidingVelocityAxial_mps = kU_mps;
  in.squeezeColumns = 0;
  ps::SkirtSideResults r;
  lub.solve(c.gap, in, r);
  // A film-borne case (h/sigma >= 6): D is the film's (the film's own loads are compared).
  EXPECT_LT(r.asperityNormalForce_N, 1e-6 * r.hydrodynamicNormalForce_N);
  const Eigen::Vector3d& f = r.hydrodynamicLoads.force_N;
  const double boreAxial_N = std::cos(alpha_rad) * f.y() - std::sin(alpha_rad) * f.x();
  const double shearAxial_N = r.hydrodynamicFrictionAxial_N - r.pressureFrictionAxial_N;
  return {kU_mps * boreAxial_N, kU_mps * shearAxial_N, referenceDissipation_W(c.grid, r),
          r.film.viscousDissipation_W};
}

void expectBalance(const char* name, double e_m, double alpha_rad, double barrel_per_m) {
  for (const lub::CavitationModel model :
       {lub::CavitationModel::Reynolds, lub::CavitationModel::MassConserving}) {
    const Case c = makeCase(160, 120, e_m, alpha_rad, barrel_per_m);
    const Balance b = solve(c, model, alpha_rad);
    const double miss = b.shearOnly_W / b.dissipation_W - 1.0;
    const double withPressure = b.friction_W / b.dissipation_W - 1.0;
    std::printf("[EnergyBalance] %s, %s: D = %.5f W; U.F %+.4f %% of D with the pressure term, "
                "%+.3f %% with the shear alone; the solver's D %+.4f %%\n",
                name, model == lub::CavitationModel::Reynolds ? "Reynolds" : "mass-conserving",
                b.dissipation_W, 100.0 * withPressure, 100.0 * miss,
                100.0 * (b.filmDissipation_W / b.dissipation_W - 1.0));
    EXPECT_LT(std::abs(withPressure), 1e-3) << name;
    EXPECT_LT(std::abs(b.filmDissipation_W / b.dissipation_W - 1.0), 1e-3) << name;
    EXPECT_GT(std::abs(miss), 1e-2) << name;  // the shear-only force is measurably off
  }
}

TEST(SkirtEnergyBalance, BarrelAtZeroTiltDissipatesItsFrictionPower) {
  // 0.12 um/mm^2 about 3 mm below the pin (the example's barrel), 3 um at the crown.
  expectBalance("barrel, zero tilt", 17e-6, 0.0, 0.12);
}

TEST(SkirtEnergyBalance, TiltedRoundSkirtDissipatesItsFrictionPowerInTheBoreFrame) {
  // alpha = 4e-4 rad: 12 um over the skirt, 3 um at its top.
  expectBalance("round skirt, tilted", 12.2e-6, 4e-4, 0.0);
}

}  // namespace
