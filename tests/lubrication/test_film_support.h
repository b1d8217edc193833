#pragma once
// Shared set-ups of the film-solver tests: closed-form reference solutions and the problems
// they describe. Every closed form is derived or cited where it is defined.

#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "pistondyn/lubrication/FilmGrid.h"
#include "pistondyn/lubrication/FilmProblem.h"
#include "pistondyn/lubrication/FilmSolver.h"

namespace pistondyn::lubrication::test {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------
// Infinitely wide fixed-incline slider (Hamrock, Schmid & Jacobson, "Fundamentals of Fluid Film
// Lubrication", 2nd ed., ch. 8). Pad length B along the sliding direction y, surface 1 slides
// with U along +y, gap h(y) = ho (1 + K (1 - y/B)) from hi = ho (1 + K) at the inlet y = 0 to
// ho at the outlet y = B, ambient pressure 0 at both ends. From the Reynolds equation,
// h^3/(12 eta) p' = (U/2)(h - h*), p(0) = p(B) = 0 gives h* = 2 hi ho / (hi + ho) and, per unit
// width,
//   load                 W' = 6 eta U B^2 / (K^2 ho^2) [ln(1+K) - 2K/(2+K)]
//   shear on the pad     F2' = int (eta U/h - (h/2) p') dy = eta U B/(K ho) [6K/(2+K) - 2 ln(1+K)]
//   shear on the runner  F1' = int (-eta U/h - (h/2) p') dy = -eta U B/(K ho) [4 ln(1+K) -
//   6K/(2+K)]
// (F1' is the classical friction force on the moving surface; F2' differs by int h p' dy.)
struct InclinedSlider {
  double viscosity_Pas = 0.01;
  double speed_mps = 5.0;
  double length_m = 0.01;     // B
  double outletGap_m = 5e-6;  // ho
  double inclination = 1.2;   // K = hi/ho - 1
  double width_m = 1e-3;      // width of the periodic strip that models the infinite width

  double gapAt(double y) const { return outletGap_m * (1.0 + inclination * (1.0 - y / length_m)); }
  double loadPerWidth() const {
    const double K = inclination;
    return 6.0 * viscosity_Pas * speed_mps * length_m * length_m /
           (K * K * outletGap_m * outletGap_m) * (std::log1p(K) - 2.0 * K / (2.0 + K));
  }
  double padShearPerWidth() const {
    const double K = inclination;
    return viscosity_Pas * speed_mps * length_m / (K * outletGap_m) *
           (6.0 * K / (2.0 + K) - 2.0 * std::log1p(K));
  }
  double runnerShearPerWidth() const {
    const double K = inclination;
    return -viscosity_Pas * speed_mps * length_m / (K * outletGap_m) *
           (4.0 * std::log1p(K) - 6.0 * K / (2.0 + K));
  }

  // Periodic strip of 3 nodes across (the solution does not vary across: exactly 1-D). The
  // problem below fits any grid whose y spans the pad (finite pads too), without cavitation.
  FilmGrid grid(int ny) const { return FilmGrid::uniform(3, width_m, ny, length_m, true); }
  FilmGrid grid(const Eigen::VectorXd& y) const {
    return FilmGrid::fromCoordinates(Eigen::Vector3d(0.0, width_m / 3, 2 * width_m / 3), y, true,
                                     width_m);
  }
  FilmProblem problem(const FilmGrid& g) const {
    FilmProblem pr;
    pr.gap_m.resize(g.nodeCount());
    for (int j = 0; j < g.ny(); ++j)
      for (int i = 0; i < g.nx(); ++i)
        pr.gap_m[g.nodeIndex(i, j)] = gapAt(g.y_m()[j]);
    pr.slidingVelocity_mps = {0.0, speed_mps};
    pr.viscosity_Pas = viscosity_Pas;
    pr.cavitation = CavitationModel::None;
    return pr;
  }
};

// ---------------------------------------------------------------------------------------------
// Plain journal bearing on the stationary bush (surface 2): x = R theta around the bush, theta
// measured from the maximum gap, h = c (1 + eps cos theta), the journal (surface 1) slides with
// U = omega R along +x, axial length L with ambient pressure 0 at both ends.
struct JournalBearing {
  double radius_m = 0.02;
  double clearance_m = 20e-6;
  double eccentricity = 0.6;
  double speed_mps = 10.0;
  double viscosity_Pas = 0.01;

  // Infinitely long bearing, full Sommerfeld (Hamrock et al., ch. 10): load per unit length
  // W' = 12 pi eta U R^2 eps / (c^2 (2 + eps^2) sqrt(1 - eps^2)), at 90 deg to the line of
  // centres.
  double sommerfeldLoadPerLength() const {
    const double e = eccentricity;
    return 12.0 * kPi * viscosity_Pas * speed_mps * radius_m * radius_m * e /
           (clearance_m * clearance_m * (2.0 + e * e) * std::sqrt(1.0 - e * e));
  }
  // Short bearing, Ocvirk (half-Sommerfeld): W = eta U L^3 / (4 c^2) eps / (1-eps^2)^2
  // sqrt(pi^2 (1 - eps^2) + 16 eps^2), attitude tan(phi) = pi sqrt(1 - eps^2) / (4 eps).
  double ocvirkLoad(double length_m) const {
    const double e = eccentricity;
    return viscosity_Pas * speed_mps * std::pow(length_m, 3) / (4.0 * clearance_m * clearance_m) *
           e / std::pow(1.0 - e * e, 2) * std::sqrt(kPi * kPi * (1.0 - e * e) + 16.0 * e * e);
  }
  double ocvirkAttitude_rad() const {
    const double e = eccentricity;
    return std::atan(kPi * std::sqrt(1.0 - e * e) / (4.0 * e));
  }

  FilmGrid grid(int nx, const Eigen::VectorXd& y) const {
    Eigen::VectorXd x(nx);
    for (int i = 0; i < nx; ++i)
      x[i] = 2.0 * kPi * radius_m * i / nx;
    return FilmGrid::fromCoordinates(x, y, true, 2.0 * kPi * radius_m);
  }
  FilmProblem problem(const FilmGrid& g, CavitationModel model) const {
    FilmProblem pr;
    pr.gap_m.resize(g.nodeCount());
    for (int j = 0; j < g.ny(); ++j)
      for (int i = 0; i < g.nx(); ++i)
        pr.gap_m[g.nodeIndex(i, j)] =
            clearance_m * (1.0 + eccentricity * std::cos(g.x_m()[i] / radius_m));
    pr.slidingVelocity_mps = {speed_mps, 0.0};
    pr.viscosity_Pas = viscosity_Pas;
    pr.cavitation = model;
    return pr;
  }
  // Fed by an axial groove: x runs once around from groove to groove (open edges at the supply
  // pressure of 1e5 Pa), the minimum gap 90 deg after the groove; axial length 2R on a grid
  // clustered towards both ends. Steady mass-conserving model, with rupture and reformation.
  FilmGrid groovedGrid(int nx, int ny) const {
    Eigen::VectorXd x(nx);
    for (int i = 0; i < nx; ++i)
      x[i] = 2.0 * kPi * radius_m * i / (nx - 1);
    return FilmGrid::fromCoordinates(x,
                                     FilmGrid::clusteredCoordinates(ny, 0.0, 2.0 * radius_m, 0.0));
  }
  FilmProblem groovedProblem(const FilmGrid& g) const {
    FilmProblem pr = problem(g, CavitationModel::MassConserving);
    for (int j = 0; j < g.ny(); ++j)
      for (int i = 0; i < g.nx(); ++i)
        pr.gap_m[g.nodeIndex(i, j)] =
            clearance_m * (1.0 + eccentricity * std::cos(g.x_m()[i] / radius_m - 0.5 * kPi));
    pr.boundary.xMin.pressure_Pa = pr.boundary.xMax.pressure_Pa = 1e5;
    return pr;
  }
  // Load components (along the line of centres towards the maximum gap, and perpendicular),
  // from the nodal pressure with the grid's area weights.
  Eigen::Vector2d loadComponents(const FilmGrid& g, const Eigen::ArrayXd& p) const {
    Eigen::Vector2d w = Eigen::Vector2d::Zero();
    for (int j = 0; j < g.ny(); ++j)
      for (int i = 0; i < g.nx(); ++i) {
        const int k = g.nodeIndex(i, j);
        const double t = g.x_m()[i] / radius_m;
        w += g.areaWeights_m2()[k] * p[k] * Eigen::Vector2d(std::cos(t), std::sin(t));
      }
    return w;
  }
};

// Test-only rough-surface flow factors of the Patir & Cheng (1978, 1979) form for isotropic
// roughness (gamma = 1), H = h / sigma: phi_x = phi_y = 1 - 0.90 exp(-0.56 H), sigma*phi_s with
// phi_s = 1.899 H^0.98 exp(-0.92 H + 0.05 H^2) (H <= 5), 1.126 exp(-0.25 H) (H > 5), scaled by
// `shearScale` (the (Rq1^2 - Rq2^2)/sigma^2 of roughness on both surfaces), phi_fp = 1 - 1.40
// exp(-0.66 H), phi_f = 1, phi_fs = 0, and the exact Gaussian expected gap
// hT = h/2 (1 + erf(H/sqrt2)) + sigma/sqrt(2 pi) exp(-H^2/2). Only here to exercise the
// average-Reynolds terms; the project's checked model lives in FlowFactors*.
class GaussianRoughFactors final : public FlowFactorModel {
 public:
  explicit GaussianRoughFactors(double sigma_m, double shearScale = 0.5)
      : sigma_(sigma_m), shearScale_(shearScale) {}
  NodeFlowFactors calcFactors(double h) const override {
    NodeFlowFactors f;
    const double H = h / sigma_;
    f.phiPressureSliding = f.phiPressureCross = 1.0 - 0.90 * std::exp(-0.56 * H);
    const double phiS = H <= 5.0 ? 1.899 * std::pow(H, 0.98) * std::exp(-0.92 * H + 0.05 * H * H)
                                 : 1.126 * std::exp(-0.25 * H);
    f.sigmaPhiS_m = shearScale_ * sigma_ * phiS;
    const double z = H / std::sqrt(2.0);
    f.expectedGap_m = 0.5 * h * (1.0 + std::erf(z)) +
                      (H < 40.0 ? sigma_ / std::sqrt(2.0 * kPi) * std::exp(-0.5 * H * H) : 0.0);
    f.dExpectedGap_dh = 0.5 * (1.0 + std::erf(z));
    f.phiFp = 1.0 - 1.40 * std::exp(-0.66 * H);
    return f;
  }
  double compositeSigma_m() const override { return sigma_; }

 private:
  double sigma_, shearScale_;
};

// A skirt-like film patch: thin, barrel-shaped, tilted and eccentric gap with sliding along y
// and squeeze; used where no closed form exists (solver agreement, derivatives).
struct SkirtPatch {
  double radius_m = 0.0325;
  double arc_m = 0.0325 * 80.0 * kPi / 180.0;
  double length_m = 0.025;
  double clearance_m = 20e-6;
  double lateral_m = 14e-6;  // eccentricity towards this side
  double tilt_rad = 2e-4;
  double lateralRate_mps = -2e-3;
  double tiltRate_radps = 0.1;
  double pinHeight_m = 0.01;
  double speed_mps = -4.0;  // liner relative to skirt along y
  double viscosity_Pas = 0.008;

  FilmGrid grid(int nx, int ny) const {
    return FilmGrid::uniform(nx, arc_m, ny, length_m, false, -0.5 * arc_m, 0.0);
  }
  // d(gap rate)/d(lateral velocity) and d(gap rate)/d(tilt rate) per node.
  Eigen::MatrixXd squeezeBasis(const FilmGrid& g) const {
    Eigen::MatrixXd b(g.nodeCount(), 2);
    for (int j = 0; j < g.ny(); ++j)
      for (int i = 0; i < g.nx(); ++i) {
        const double c = std::cos(g.x_m()[i] / radius_m);
        b(g.nodeIndex(i, j), 0) = -c;
        b(g.nodeIndex(i, j), 1) = -(g.y_m()[j] - pinHeight_m) * c;
      }
    return b;
  }
  FilmProblem problem(const FilmGrid& g, CavitationModel model) const {
    FilmProblem pr;
    const int n = g.nodeCount();
    pr.gap_m.resize(n);
    pr.gapRate_mps.resize(n);
    const Eigen::MatrixXd basis = squeezeBasis(g);
    for (int j = 0; j < g.ny(); ++j)
      for (int i = 0; i < g.nx(); ++i) {
        const int k = g.nodeIndex(i, j);
        const double th = g.x_m()[i] / radius_m;
        const double y = g.y_m()[j];
        const double ym = (y - 0.55 * length_m) / (0.5 * length_m);
        const double profile = (ym > 0.0 ? 20e-6 : 35e-6) * ym * ym;
        const double ovality = 60e-6 * std::pow(std::sin(th), 2);
        pr.gap_m[k] = clearance_m + profile + ovality -
                      (lateral_m + tilt_rad * (y - pinHeight_m)) * std::cos(th);
        pr.gapRate_mps[k] = basis(k, 0) * lateralRate_mps + basis(k, 1) * tiltRate_radps;
      }
    pr.slidingVelocity_mps = {0.0, speed_mps};
    pr.viscosity_Pas = viscosity_Pas;
    pr.cavitation = model;
    return pr;
  }
  // One transient step of the mass-conserving model (dt = 0.1 ms) after a partly filled
  // history: fill 0.5 in the diverging lower half (oil enters at the top, U_y < 0), 1 above.
  FilmProblem partlyFilledProblem(const FilmGrid& g) const {
    FilmProblem pr = problem(g, CavitationModel::MassConserving);
    setPartlyFilledHistory(g, 0.5, pr);
    return pr;
  }
  // The step of 0.1 ms and its history: fill `fill` in the lower half of the grid, 1 above.
  static void setPartlyFilledHistory(const FilmGrid& g, double fill, FilmProblem& pr) {
    pr.timeStep_s = 1e-4;
    pr.history.last.fillFraction.setOnes(g.nodeCount());
    for (int j = 0; j < g.ny() / 2; ++j)
      for (int i = 0; i < g.nx(); ++i)
        pr.history.last.fillFraction[g.nodeIndex(i, j)] = fill;
  }
};

// Prints a measured figure into the test log and the XML report (the acceptance figures of
// issue 3 are read from there).
inline void reportFigure(const std::string& name, double value) {
  ::testing::Test::RecordProperty(name, std::to_string(value));
  std::printf("[ figure   ] %s = %.6g\n", name.c_str(), value);
}

// Independent solver objects on several threads give exactly the answers of the same call
// sequence run serially (no shared mutable state; the solver is deterministic): five warm
// calls on the rough skirt patch (nx x ny) with a growing squeeze rate, with `options`.
inline void expectSameLoadsOnThreads(const FilmSolverOptions& options, int nx, int ny) {
  const SkirtPatch sp;
  const GaussianRoughFactors rough(0.8e-6);  // shared, immutable
  const FilmGrid g = sp.grid(nx, ny);
  FilmProblem pr = sp.problem(g, CavitationModel::Reynolds);
  pr.flowFactors = &rough;
  auto sequence = [&] {
    FilmSolver solver(options);
    FilmResult r;
    for (int rep = 0; rep < 5; ++rep) {
      FilmProblem step = pr;
      step.gapRate_mps *= 1.0 + 0.1 * rep;
      solver.solve(g, step, rep ? &r.state : nullptr, r);
    }
    return r.load_N;
  };
  const double serial = sequence();
  std::vector<double> loads(4, 0.0);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < loads.size(); ++t)
    threads.emplace_back([&, t] { loads[t] = sequence(); });
  for (std::thread& th : threads)
    th.join();
  for (double l : loads)
    EXPECT_EQ(l, serial);
}

// Oil balance of the unknown nodes from a result's flux diagnostics, [m^3/s]: inflow - outflow -
// storage rate, which the mass-conserving model drives to zero. The diagnostics themselves are
// checked against a balance recomputed from p and theta in test_film_mass_conserving.cpp.
inline double oilBalanceDefect_m3ps(const FilmResult& r) {
  return r.boundaryInflow_m3ps - r.boundaryOutflow_m3ps - r.storageRate_m3ps;
}

// Options for a tightly converged solve.
inline FilmSolverOptions tightOptions(FilmSolverType type, double tolerance) {
  FilmSolverOptions o;
  o.solver = type;
  o.tolerance = tolerance;
  o.derivativeTolerance = tolerance;  // derivatives as accurate as the film in the tests
  o.maxSweeps = 1000000;
  return o;
}

}  // namespace pistondyn::lubrication::test
