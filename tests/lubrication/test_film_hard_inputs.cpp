// Hard inputs a piston-skirt simulation produces: gaps far below and far above the roughness with
// the real Patir & Cheng factors, pure squeeze without sliding, extreme viscosities and speeds,
// 100 MPa pressures, 3 x 3 and very elongated grids, a fully starved inlet, solves stopped early,
// and the mass-conserving fill fraction carried across a reversal of the sliding direction.
// Everything is checked against something independent of the solver under test: the other
// solver, a closed form, the oil balance, or the constraints p >= p_cav, 0 <= theta <= 1.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "pistondyn/lubrication/PatirChengFlowFactors.h"
#include "test_film_support.h"

namespace pistondyn::lubrication {
namespace {

bool allFinite(const FilmResult& r) {
  auto ok = [](const Eigen::ArrayXd& a) { return a.allFinite(); };
  for (const SurfaceShear* s : {&r.shearOnSurface1, &r.shearOnSurface2})
    if (!(ok(s->couetteX_Pa) && ok(s->couetteY_Pa) && ok(s->poiseuilleX_Pa) &&
          ok(s->poiseuilleY_Pa) && s->force_N().allFinite() && std::isfinite(s->moment_Nm())))
      return false;
  return ok(r.pressure_Pa()) && ok(r.fillFraction()) && std::isfinite(r.load_N) &&
         std::isfinite(r.firstMomentX_Nm) && std::isfinite(r.firstMomentY_Nm) &&
         std::isfinite(r.residual) && std::isfinite(r.boundaryInflow_m3ps) &&
         std::isfinite(r.boundaryOutflow_m3ps) && std::isfinite(r.storageRate_m3ps) &&
         ok(r.gapOverSigma);
}

// Contract of every result, converged or not (FilmProblem.h, FilmSolver.h): finite fields,
// p >= p_cav (cavitation models), 0 <= theta <= 1, and an honest converged flag.
void expectContract(const FilmResult& r, const FilmProblem& pr, const FilmSolverOptions& o,
                    const std::string& tag) {
  SCOPED_TRACE(tag);
  ASSERT_TRUE(allFinite(r));
  if (pr.cavitation != CavitationModel::None) {
    EXPECT_GE(r.pressure_Pa().minCoeff(), pr.cavitationPressure_Pa);
  }
  EXPECT_GE(r.fillFraction().minCoeff(), 0.0);
  EXPECT_LE(r.fillFraction().maxCoeff(), 1.0);
  EXPECT_EQ(r.converged, r.residual <= o.tolerance) << "residual " << r.residual;
}

// A skirt-like patch: sliding along y, barrel profile along y and x, optional uniform gap rate.
FilmProblem skirtPatch(const FilmGrid& g, double minGap_m, double speed_mps, double eta_Pas,
                       CavitationModel model, double gapRate_mps = 0.0) {
  FilmProblem pr;
  const int n = g.nodeCount();
  pr.gap_m.resize(n);
  pr.gapRate_mps.setConstant(n, gapRate_mps);
  const double lx = g.x_m()[g.nx() - 1] - g.x_m()[0], ly = g.y_m()[g.ny() - 1] - g.y_m()[0];
  for (int j = 0; j < g.ny(); ++j)
    for (int i = 0; i < g.nx(); ++i) {
      const double ym = 2.0 * (g.y_m()[j] - g.y_m()[0]) / ly - 1.1;
      const double xm = 2.0 * (g.x_m()[i] - g.x_m()[0]) / lx - 1.0;
      pr.gap_m[g.nodeIndex(i, j)] = minGap_m * (1.0 + 3.0 * ym * ym + 2.0 * xm * xm);
    }
  pr.slidingVelocity_mps = {0.0, speed_mps};
  pr.viscosity_Pas = eta_Pas;
  pr.cavitation = model;
  return pr;
}

// Oil balance defect (test_film_support.h) relative to the largest of the balance's terms: for
// the mass-conserving model it vanishes up to the residual tolerance.
double balanceDefect(const FilmResult& r) {
  const double scale = std::max(
      {r.boundaryInflow_m3ps, r.boundaryOutflow_m3ps, std::abs(r.storageRate_m3ps), 1e-300});
  return test::oilBalanceDefect_m3ps(r) / scale;
}

struct HardCase {
  std::string name;
  FilmGrid grid;
  FilmProblem problem;
};

const PatirChengFlowFactors& roughSkirt() {
  static const PatirChengFlowFactors model([] {
    PatirChengParameters p;
    p.rq1_m = 0.3e-6;  // liner
    p.rq2_m = 0.4e-6;  // skirt; sigma = 0.5 um
    return p;
  }());
  return model;
}

std::vector<HardCase> hardCases(CavitationModel m) {
  const double sigma = roughSkirt().compositeSigma_m();
  const FilmGrid g = FilmGrid::uniform(16, 0.02, 20, 0.025);
  std::vector<HardCase> c;
  auto add = [&](const std::string& name, const FilmGrid& grid, FilmProblem pr) {
    c.push_back({name, grid, std::move(pr)});
  };
  for (double H : {0.5, 0.02}) {  // asperity contact: pressure flow factors at their floor
    FilmProblem pr = skirtPatch(g, H * sigma, 5.0, 0.01, m);
    pr.flowFactors = &roughSkirt();
    add("h/sigma=" + std::to_string(H), g, pr);
  }
  {
    FilmProblem pr = skirtPatch(g, 2000.0 * sigma, 5.0, 0.01, m);
    pr.flowFactors = &roughSkirt();
    add("h/sigma=2000", g, pr);
  }
  for (double rate : {1e-3, -1e-3}) {
    FilmProblem pr = skirtPatch(g, 5e-6, 0.0, 0.01, m, rate);
    pr.flowFactors = &roughSkirt();
    add("pure squeeze dh/dt=" + std::to_string(rate), g, pr);
  }
  for (double eta : {1e-4, 1.0})
    for (double U : {1e-6, 30.0})
      add("eta=" + std::to_string(eta) + " U=" + std::to_string(U), g,
          skirtPatch(g, 2e-6, U, eta, m));
  {
    FilmProblem pr = skirtPatch(g, 5e-6, 10.0, 0.01, m);
    pr.boundary.yMin.pressure_Pa = 1e8;  // 100 MPa on the inlet edge
    add("100 MPa edge", g, pr);
  }
  {
    const FilmGrid g3 = FilmGrid::uniform(3, 0.02, 3, 0.025);
    add("3x3", g3, skirtPatch(g3, 5e-6, 10.0, 0.01, m, -1e-3));
    const FilmGrid ga = FilmGrid::uniform(12, 0.2, 40, 0.002);  // cells 100-200 : 1
    add("aspect 200", ga, skirtPatch(ga, 5e-6, 10.0, 0.01, m, -1e-3));
    const FilmGrid gg =
        FilmGrid::fromCoordinates(FilmGrid::clusteredCoordinates(14, 0.0, 0.02, 3.5),
                                  FilmGrid::clusteredCoordinates(20, 0.0, 0.025, 3.5));
    FilmProblem pr = skirtPatch(gg, 5e-6, 10.0, 0.01, m, -1e-3);
    pr.flowFactors = &roughSkirt();
    add("graded", gg, pr);
  }
  return c;
}

// Both solvers on every hard case: converged, finite, within the constraints, in agreement to
// 1e-6 of the peak pressure; the mass-conserving model closes its oil balance.
void checkHardCases(CavitationModel m) {
  for (const HardCase& hc : hardCases(m)) {
    FilmSolverOptions ref = test::tightOptions(FilmSolverType::ReferenceGaussSeidel, 1e-11);
    FilmSolverOptions fast = test::tightOptions(FilmSolverType::FastActiveSet, 1e-11);
    fast.fallbackToReference = false;
    const FilmResult rr = FilmSolver(ref).solve(hc.grid, hc.problem);
    const FilmResult rf = FilmSolver(fast).solve(hc.grid, hc.problem);
    expectContract(rr, hc.problem, ref, hc.name + " reference");
    expectContract(rf, hc.problem, fast, hc.name + " fast");
    SCOPED_TRACE(hc.name);
    ASSERT_TRUE(rr.converged);
    ASSERT_TRUE(rf.converged);
    const double peak = rr.pressure_Pa().abs().maxCoeff();
    EXPECT_LE((rf.pressure_Pa() - rr.pressure_Pa()).abs().maxCoeff(), 1e-6 * peak);
    if (m == CavitationModel::MassConserving) {
      EXPECT_LE((rf.fillFraction() - rr.fillFraction()).abs().maxCoeff(), 1e-6);
      if (rf.boundaryInflow_m3ps > 0.0) {
        EXPECT_LE(std::abs(balanceDefect(rf)), 1e-8);
        EXPECT_LE(std::abs(balanceDefect(rr)), 1e-8);
      }
    }
  }
}

TEST(FilmHardInputs, BothSolversAgreeOnHardInputsFullSommerfeld) {
  checkHardCases(CavitationModel::None);
}
TEST(FilmHardInputs, BothSolversAgreeOnHardInputsReynolds) {
  checkHardCases(CavitationModel::Reynolds);
}
TEST(FilmHardInputs, BothSolversAgreeOnHardInputsMassConserving) {
  checkHardCases(CavitationModel::MassConserving);
}

// Separating surfaces without sliding: dh/dt > 0 everywhere, ambient edges. The Reynolds
// condition then holds every node at p_cav (the unconstrained solution p'' = 12 eta dh/dt / h^3
// > 0 with p = 0 on the edges is negative everywhere), the steady mass-conserving model empties
// the film (theta dh/dt = 0 with no inflow gives theta = 0).
TEST(FilmHardInputs, SeparatingSurfacesWithoutSlidingCavitateEverywhere) {
  const FilmGrid g = FilmGrid::uniform(16, 0.02, 20, 0.025);
  for (auto m : {CavitationModel::Reynolds, CavitationModel::MassConserving})
    for (auto type : {FilmSolverType::ReferenceGaussSeidel, FilmSolverType::FastActiveSet}) {
      const FilmProblem pr = skirtPatch(g, 5e-6, 0.0, 0.01, m, 1e-3);
      const FilmSolverOptions o = test::tightOptions(type, 1e-10);
      const FilmResult r = FilmSolver(o).solve(g, pr);
      expectContract(r, pr, o, "separating");
      ASSERT_TRUE(r.converged);
      EXPECT_FALSE(r.usedFallback);
      EXPECT_EQ(r.cavitatedNodes, (g.nx() - 2) * (g.ny() - 2));
      EXPECT_EQ(r.load_N, 0.0);
      if (m == CavitationModel::MassConserving) {
        for (int j = 1; j + 1 < g.ny(); ++j)
          for (int i = 1; i + 1 < g.nx(); ++i)
            EXPECT_LE(r.fillFraction()[g.nodeIndex(i, j)], 1e-12);
      }
    }
}

// Defect found: the fast solver returned iterates outside the constraints when it stopped
// without converging (theta up to 1.12, p below p_cav by up to 1.7 MPa on this patch), although
// FilmSolver.h promises "the last finite iterate" with the constraints kept; and the Gauss-Seidel
// fallback, which starts from that iterate, kept a theta > 1 on nodes it treats as full.
TEST(FilmHardInputs, StoppedFastSolveKeepsTheConstraints) {
  const FilmGrid g = FilmGrid::uniform(24, 0.02, 30, 0.025);
  for (auto m : {CavitationModel::Reynolds, CavitationModel::MassConserving})
    for (auto ls : {FastLinearSolver::SparseDirect, FastLinearSolver::Multigrid})
      for (int steps = 1; steps <= 6; ++steps)
        for (double rate : {0.0, 1e-4}) {
          FilmProblem pr = skirtPatch(g, 3e-6, 8.0, 0.01, m, rate);
          pr.flowFactors = &roughSkirt();
          pr.boundary.yMin.supplyFilm_m = 2e-6;  // starved inlet: the sets move a lot
          FilmSolverOptions o = test::tightOptions(FilmSolverType::FastActiveSet, 1e-10);
          o.maxActiveSetIterations = steps;
          o.fallbackToReference = false;
          o.linearSolver = ls;
          const FilmResult r = FilmSolver(o).solve(g, pr);
          expectContract(r, pr, o,
                         std::string(m == CavitationModel::Reynolds ? "Reynolds" : "JFO") +
                             " linear solver " + std::to_string(static_cast<int>(ls)) + " steps " +
                             std::to_string(steps) + " rate " + std::to_string(rate));
        }
}

// Defect found: with no oil on the liner ahead of the skirt (supply film 0 or 1 nm) the
// mass-conserving active-set iteration cycled through four active sets forever and always fell
// back to Gauss-Seidel (converged = false without the fallback). Closed form: no oil enters, so
// in steady state every interior node is cavitated with theta = 0 (theta a_k = upstream inflow
// = 0 from the dry edge), the pressure is p_cav everywhere and the load vanishes.
TEST(FilmHardInputs, FullyStarvedMassConservingFilmConvergesWithoutFallback) {
  const FilmGrid g = FilmGrid::uniform(24, 0.02, 30, 0.025);
  for (double supply : {0.0, 1e-9})
    for (double rate : {0.0, -1e-3})
      for (auto ls : {FastLinearSolver::SparseDirect, FastLinearSolver::Multigrid}) {
        FilmProblem pr = skirtPatch(g, 5e-6, 10.0, 0.01, CavitationModel::MassConserving, rate);
        pr.boundary.yMin.supplyFilm_m = supply;
        FilmSolverOptions o = test::tightOptions(FilmSolverType::FastActiveSet, 1e-10);
        o.fallbackToReference = false;
        o.linearSolver = ls;
        const FilmResult r = FilmSolver(o).solve(g, pr);
        SCOPED_TRACE("supply " + std::to_string(supply) + " rate " + std::to_string(rate));
        expectContract(r, pr, o, "starved");
        ASSERT_TRUE(r.converged);
        EXPECT_EQ(r.cavitatedNodes, (g.nx() - 2) * (g.ny() - 2));
        EXPECT_EQ(r.pressure_Pa().abs().maxCoeff(), 0.0);
        // The oil layer theta h carried downstream is about 2 * supply (FilmEdge): bound it by
        // twice that.
        for (int j = 1; j + 1 < g.ny(); ++j)
          for (int i = 1; i + 1 < g.nx(); ++i)
            EXPECT_LE(r.fillFraction()[g.nodeIndex(i, j)] * pr.gap_m[g.nodeIndex(i, j)],
                      4.0 * supply + 1e-18);
      }
}

// Transient mass-conserving film whose sliding direction reverses abruptly (+5 -> -5 m/s) with
// the fill fraction carried from step to step and both edges starved: the solvers agree at every
// step, theta stays in [0, 1], and each step closes its oil balance (the storage term holds the
// change of the carried oil content, so the balance is the discrete conservation law).
TEST(FilmHardInputs, FillFractionCarriedAcrossSlidingReversal) {
  const FilmGrid g = FilmGrid::uniform(20, 0.02, 28, 0.025);
  const int n = g.nodeCount();
  const double dt = 1e-4;
  FilmSolverOptions ro = test::tightOptions(FilmSolverType::ReferenceGaussSeidel, 1e-10);
  FilmSolverOptions fo = test::tightOptions(FilmSolverType::FastActiveSet, 1e-10);
  fo.fallbackToReference = false;
  FilmSolver ref(ro), fast(fo);
  FilmResult rr, rf;
  Eigen::ArrayXd thR = Eigen::ArrayXd::Ones(n), thF = thR;
  for (int step = 0; step < 26; ++step) {
    const double U = step < 20 ? 5.0 : -5.0;
    FilmProblem pr = skirtPatch(g, 3e-6, U, 0.01, CavitationModel::MassConserving,
                                2e-3 * std::sin(2.0 * test::kPi * step / 40.0));
    pr.flowFactors = &roughSkirt();
    pr.boundary.yMin.supplyFilm_m = pr.boundary.yMax.supplyFilm_m = 2e-6;
    pr.timeStep_s = dt;
    const FilmState warmR = rr.state, warmF = rf.state;
    pr.history.last.fillFraction = thR;
    ref.solve(g, pr, step ? &warmR : nullptr, rr);
    pr.history.last.fillFraction = thF;
    fast.solve(g, pr, step ? &warmF : nullptr, rf);
    SCOPED_TRACE("step " + std::to_string(step));
    expectContract(rr, pr, ro, "reference");
    expectContract(rf, pr, fo, "fast");
    ASSERT_TRUE(rr.converged);
    ASSERT_TRUE(rf.converged);
    const double peak = std::max(rr.pressure_Pa().abs().maxCoeff(), 1.0);
    EXPECT_LE((rf.pressure_Pa() - rr.pressure_Pa()).abs().maxCoeff(), 1e-6 * peak);
    EXPECT_LE((rf.fillFraction() - rr.fillFraction()).abs().maxCoeff(), 1e-6);
    EXPECT_LE(std::abs(balanceDefect(rf)), 1e-8);
    EXPECT_LE(std::abs(balanceDefect(rr)), 1e-8);
    thR = rr.fillFraction();
    thF = rf.fillFraction();
  }
}

}  // namespace
}  // namespace pistondyn::lubrication
