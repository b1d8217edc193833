// The reference Gauss-Seidel solver and the fast active-set solver solve the same discrete
// problem (FilmProblem.h); run to a tight residual both must give the same pressure to 1e-6 of
// the peak pressure (the acceptance), with and without cavitation. This is a check of
// two independent algorithms against each other on problems without closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "test_film_support.h"

namespace pistondyn::lubrication {
namespace {

struct Agreement {
  double pressure;  // max |p_ref - p_fast| / max |p_fast|
  double fill;      // max |theta_ref - theta_fast|
};

Agreement compareSolvers(const FilmGrid& g, const FilmProblem& pr, const std::string& name) {
  // A residual of 1e-11 bounds the pressure error far below 1e-6 of the peak on these grids.
  FilmSolver reference(test::tightOptions(FilmSolverType::ReferenceGaussSeidel, 1e-11));
  FilmSolver fast(test::tightOptions(FilmSolverType::FastActiveSet, 1e-11));
  const FilmResult a = reference.solve(g, pr);
  const FilmResult b = fast.solve(g, pr);
  EXPECT_TRUE(a.converged) << name << " reference residual " << a.residual;
  EXPECT_TRUE(b.converged) << name << " fast residual " << b.residual;
  EXPECT_FALSE(b.usedFallback) << name;
  const double peak = b.pressure_Pa().abs().maxCoeff();
  EXPECT_GT(peak, 0.0) << name << ": a test problem must carry load";
  Agreement ag{(a.pressure_Pa() - b.pressure_Pa()).abs().maxCoeff() / peak,
               (a.fillFraction() - b.fillFraction()).abs().maxCoeff()};
  test::reportFigure("agreement." + name + ".pressure", ag.pressure);
  test::reportFigure("agreement." + name + ".fill", ag.fill);
  test::reportFigure("agreement." + name + ".referenceSweeps", a.iterations);
  test::reportFigure("agreement." + name + ".cavitatedNodes", b.cavitatedNodes);
  EXPECT_EQ(a.cavitatedNodes, b.cavitatedNodes) << name;
  EXPECT_LT(ag.pressure, 1e-6) << name;
  EXPECT_LT(ag.fill, 1e-6) << name;
  return ag;
}

// Finite inclined pad, open on all four edges, no cavitation (converging wedge).
TEST(FilmSolverAgreement, FinitePadWithoutCavitation) {
  const test::InclinedSlider s;
  const FilmGrid g = FilmGrid::uniform(31, 0.008, 41, s.length_m);
  FilmProblem pr = s.problem(g);
  pr.cavitation = CavitationModel::None;
  compareSolvers(g, pr, "pad.none");
  pr.cavitation = CavitationModel::Reynolds;
  compareSolvers(g, pr, "pad.reynolds");
}

// Journal bearing L/D = 1 with the Reynolds condition: a large cavitated zone.
TEST(FilmSolverAgreement, JournalBearingWithReynoldsCavitation) {
  const test::JournalBearing jb;
  const double L = 2.0 * jb.radius_m;
  const FilmGrid g = jb.grid(72, FilmGrid::clusteredCoordinates(25, 0.0, L, 0.0));
  const FilmResult r = [&] {
    FilmProblem pr = jb.problem(g, CavitationModel::Reynolds);
    compareSolvers(g, pr, "journal.reynolds");
    pr.cavitation = CavitationModel::None;
    compareSolvers(g, pr, "journal.none");
    return FilmResult();
  }();
  (void)r;
}

// Skirt-like rough patch: average Reynolds with flow factors, sliding along y, squeeze, Reynolds
// cavitation.
TEST(FilmSolverAgreement, RoughSkirtPatchWithSqueezeAndCavitation) {
  const test::SkirtPatch sp;
  const test::GaussianRoughFactors rough(0.8e-6);
  const FilmGrid g = sp.grid(40, 30);
  FilmProblem pr = sp.problem(g, CavitationModel::Reynolds);
  pr.flowFactors = &rough;
  compareSolvers(g, pr, "skirt.reynolds");
}

// Mass-conserving (Elrod-Adams / JFO) model: a steady journal bearing fed by an axial groove
// (x open from groove to groove at the supply pressure) with rupture and reformation, and a
// transient skirt patch carrying a partly filled previous state.
TEST(FilmSolverAgreement, MassConservingModel) {
  const test::JournalBearing jb;
  const FilmGrid g = jb.groovedGrid(73, 25);
  const FilmProblem pr = jb.groovedProblem(g);
  compareSolvers(g, pr, "groovedJournal.jfo");

  const test::SkirtPatch sp;
  const test::GaussianRoughFactors rough(0.8e-6);
  const FilmGrid gs = sp.grid(40, 30);
  FilmProblem ps = sp.partlyFilledProblem(gs);
  ps.flowFactors = &rough;
  compareSolvers(gs, ps, "skirt.jfo");
}

}  // namespace
}  // namespace pistondyn::lubrication
