// Film solver benchmark (issue 3): one skirt side over 100 consecutive steps of an engine
// stroke, average Reynolds with rough flow factors, each step warm-started from the last.
// Time per solve of the reference Gauss-Seidel and of the fast active-set solver at the same
// residual tolerance (FilmSolverOptions::tolerance), Reynolds cavitation and mass-conserving
// (JFO) cavitation, at 64 x 48 nodes and at 4x the node count (128 x 96); the fast solver with
// each of its preconditioners (sparse direct, multigrid) and, for Reynolds, also at 16x the node
// count (256 x 192) to show the trend.
//
// Scenario (numbers of the thesis' engine and parameter study: J. Dluhoš, Advanced Solution to
// Piston Assembly Dynamics, doctoral thesis summary, Brno University of Technology): bore
// 65.1 mm, stroke 47.7 mm, rod 80 mm (assumed), 2000 rpm, radial clearance 53 um; thrust-side
// skirt arc +-40 deg, skirt length 25 mm, barrel profile 20 um (top) / 35 um (bottom) around
// its widest point at 55 % of the length, ovality 60 um sin^2; prescribed secondary motion
// (lateral displacement and tilt) that drives the skirt from the anti-thrust side onto the
// thrust side after firing TDC; oil 8 mPa s; Patir & Cheng flow factors, composite roughness
// 0.8 um. The 100 steps cover 360 .. 409.5 deg crank angle in 0.5 deg steps (41.7 us): the force
// element of a Simbody run calls the film thousands of times per cycle. Before timing, the step
// preceding the window is solved (untimed) so that the first timed step is warm like every other.
//
// Swap in another flow-factor model by changing `makeFlowFactors()`; nothing else depends on it.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "pistondyn/lubrication/FilmSolver.h"
#include "pistondyn/lubrication/PatirChengFlowFactors.h"

namespace {

using namespace pistondyn::lubrication;

constexpr double kPi = 3.14159265358979323846;

// The product's own Patir & Cheng model (PatirChengFlowFactors.h): surface 1 = the liner
// (moving at U relative to the skirt), Rq1 = 0.5 um; surface 2 = the skirt carrying the grid,
// Rq2 = 0.62 um; composite sigma = sqrt(0.5^2 + 0.62^2) = 0.80 um; isotropic roughness
// (gamma = 1), Gaussian expected gap. Unlike simple isotropic fits of the flow factors alone,
// it carries the shear-flow term (Vr1 - Vr2 != 0) and the full shear-stress factors.
std::unique_ptr<FlowFactorModel> makeFlowFactors() {
  PatirChengParameters p;
  p.rq1_m = 0.5e-6;
  p.rq2_m = 0.62e-6;
  p.peklenik1 = p.peklenik2 = 1.0;
  return std::make_unique<PatirChengFlowFactors>(p);
}

struct Step {
  Eigen::ArrayXd gap_m, gapRate_mps;
  double pistonSpeed_mps;
};

struct Scenario {
  static constexpr int kSteps = 100;
  static constexpr double kStartCrank_deg = 360.0, kStep_deg = 0.5;
  static constexpr double kSpeed_radps = 2000.0 * 2.0 * kPi / 60.0;
  FilmGrid grid;
  std::vector<Step> steps;  // steps[0] is the untimed step before the window
  std::unique_ptr<FlowFactorModel> factors = makeFlowFactors();

  static constexpr double kRadius_m = 0.0651 / 2, kSkirtLength_m = 0.025;
  static constexpr double kPinHeight_m = 0.4 * kSkirtLength_m;

  explicit Scenario(int scale)
      : grid(FilmGrid::uniform(64 * scale, kRadius_m * 80.0 * kPi / 180.0, 48 * scale,
                               kSkirtLength_m, false, -kRadius_m * 40.0 * kPi / 180.0, 0.0)) {
    const double R = kRadius_m, c = 53e-6, L = kSkirtLength_m, crank = 0.0477 / 2, rod = 0.08;
    const double pin = kPinHeight_m, deg = kPi / 180.0;
    auto lateral = [&](double phi) {
      return c * (0.02 + 0.93 * std::tanh((phi - 368 * deg) / (12 * deg)));
    };
    auto tilt = [&](double phi) { return 4e-4 * std::sin((phi - 330 * deg) / (120 * deg) * kPi); };
    for (int s = -1; s < kSteps; ++s) {
      const double phi = (kStartCrank_deg + s * kStep_deg) * deg, w = kSpeed_radps, d = 1e-5;
      const double e = lateral(phi), de = (lateral(phi + d) - lateral(phi - d)) / (2 * d) * w;
      const double a = tilt(phi), da = (tilt(phi + d) - tilt(phi - d)) / (2 * d) * w;
      Step st;
      st.gap_m.resize(grid.nodeCount());
      st.gapRate_mps.resize(grid.nodeCount());
      for (int j = 0; j < grid.ny(); ++j)
        for (int i = 0; i < grid.nx(); ++i) {
          const int k = grid.nodeIndex(i, j);
          const double th = grid.x_m()[i] / R, y = grid.y_m()[j];
          const double ym = (y - 0.55 * L) / (0.5 * L);
          const double profile = (ym > 0 ? 20e-6 : 35e-6) * ym * ym;
          const double ovality = 60e-6 * std::pow(std::sin(th), 2);
          st.gap_m[k] = c + profile + ovality - (e + a * (y - pin)) * std::cos(th);
          st.gapRate_mps[k] = -(de + da * (y - pin)) * std::cos(th);
        }
      // Piston velocity towards the head; the liner (surface 1) moves the other way relative to
      // the skirt (surface 2, the grid).
      st.pistonSpeed_mps = -crank * w * (std::sin(phi) + crank / (2 * rod) * std::sin(2 * phi));
      steps.push_back(std::move(st));
    }
  }

  FilmProblem problem(CavitationModel model) const {
    FilmProblem pr;
    pr.viscosity_Pas = 0.008;
    pr.flowFactors = factors.get();
    pr.cavitation = model;
    pr.timeStep_s = kStep_deg * kPi / 180.0 / kSpeed_radps;
    return pr;
  }
  void setStep(FilmProblem& pr, int s) const {
    pr.gap_m = steps[s].gap_m;
    pr.gapRate_mps = steps[s].gapRate_mps;
    pr.slidingVelocity_mps = {0.0, -steps[s].pistonSpeed_mps};
  }
};

const Scenario& scenario(int scale) {
  static const Scenario s1(1), s2(2);
  if (scale == 1)
    return s1;
  if (scale == 2)
    return s2;
  static const Scenario s4(4);  // built only when a 256 x 192 row runs
  return s4;
}

// One timed pass over the stroke per benchmark iteration: a new solver, the step before the
// window solved untimed, then the kSteps steps each warm-started from the last; `perSolve`
// sees every timed result.
template <class PerSolve>
void runWarmStroke(benchmark::State& state, const Scenario& sc, const FilmSolverOptions& opt,
                   const FilmProblem& problem, PerSolve&& perSolve) {
  for (auto _ : state) {
    state.PauseTiming();
    FilmSolver solver(opt);
    FilmProblem pr = problem;
    FilmResult r;
    sc.setStep(pr, 0);
    solver.solve(sc.grid, pr, nullptr, r);  // the step before the window, untimed
    FilmState warm = r.state;
    state.ResumeTiming();
    for (int s = 1; s <= Scenario::kSteps; ++s) {
      sc.setStep(pr, s);
      if (pr.cavitation == CavitationModel::MassConserving)
        pr.history.last.fillFraction = warm.fillFraction;
      solver.solve(sc.grid, pr, &warm, r);
      warm = r.state;
      perSolve(r);
    }
  }
}

// args: scale (1: 64 x 48, 2: 128 x 96, 4: 256 x 192), solver (0 fast, 1 reference), model
// (1 Reynolds, 2 JFO), over-relaxation x 100 of the reference solver (0: the default), linear
// solver of the fast solver (0 Automatic, 1 SparseDirect, 2 Multigrid).
void BM_SkirtStroke(benchmark::State& state) {
  const Scenario& sc = scenario(static_cast<int>(state.range(0)));
  FilmSolverOptions opt;
  opt.solver =
      state.range(1) == 0 ? FilmSolverType::FastActiveSet : FilmSolverType::ReferenceGaussSeidel;
  if (state.range(3) > 0)
    opt.overRelaxation = state.range(3) / 100.0;
  opt.linearSolver = state.range(4) == 1   ? FastLinearSolver::SparseDirect
                     : state.range(4) == 2 ? FastLinearSolver::Multigrid
                                           : FastLinearSolver::Automatic;
  const CavitationModel model =
      state.range(2) == 1 ? CavitationModel::Reynolds : CavitationModel::MassConserving;
  double sweeps = 0, factorisations = 0, mgBuilds = 0, krylov = 0, activeSet = 0, notConverged = 0,
         cavitated = 0;
  double solves = 0;
  runWarmStroke(state, sc, opt, sc.problem(model), [&](const FilmResult& r) {
    sweeps += opt.solver == FilmSolverType::ReferenceGaussSeidel ? r.iterations : 0;
    factorisations += r.factorisations;
    mgBuilds += r.multigridBuilds;
    krylov += r.krylovIterations;
    activeSet += r.activeSetIterations;
    notConverged += r.converged ? 0 : 1;
    cavitated += r.cavitatedNodes;
    solves += 1;
  });
  state.SetItemsProcessed(static_cast<int64_t>(solves));
  state.counters["nodes"] = sc.grid.nodeCount();
  state.counters["time_per_solve"] =
      benchmark::Counter(solves, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["sweeps"] = sweeps / solves;
  state.counters["activeSetIt"] = activeSet / solves;
  state.counters["factorisations"] = factorisations / solves;
  state.counters["mgBuilds"] = mgBuilds / solves;
  state.counters["krylovIt"] = krylov / solves;
  state.counters["cavitatedFrac"] = cavitated / solves / sc.grid.nodeCount();
  state.counters["notConverged"] = notConverged;
}

void skirtArgs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"scale", "reference", "model", "omega", "linsolver"});
  for (int model : {1, 2})
    for (int scale : {1, 2})
      for (int reference : {0, 1})
        b->Args({scale, reference, model, 0, 0});
  // Both linear solvers of the fast Reynolds path, whatever Automatic picks, and 256 x 192 to
  // show the trend.
  for (int scale : {1, 2, 4})
    for (int linsolver : {1, 2})
      b->Args({scale, 0, 1, 0, linsolver});
  for (int scale : {1, 2})
    for (int linsolver : {1, 2})
      b->Args({scale, 0, 2, 0, linsolver});
  // Over-relaxation of the reference solver: the default 1.8 and the best factors found by
  // scanning (BENCHMARKS.md), so that speed-ups are quoted against a well-tuned baseline.
  for (int omega : {170, 184, 190})
    b->Args({1, 1, 1, omega, 0});
  b->Args({1, 1, 2, 184, 0});
  for (int omega : {192, 194})
    for (int model : {1, 2})
      b->Args({2, 1, model, omega, 0});
  b->Unit(benchmark::kMillisecond);
  b->UseRealTime();
}

BENCHMARK(BM_SkirtStroke)->Apply(skirtArgs);

// Many squeeze-derivative columns (issue 12: an elastic skirt asks for 2 pose columns and one
// per deformation mode): the stroke of BM_SkirtStroke, fast solver, with `columns` columns (the
// pose's two, then mode-like shapes cos(order * theta) * y^(c % 3)), one Krylov solve per column
// (factorise 0) or the factorisation rule of FilmSolverOptions::factoriseForManyDerivativeColumns
// (factorise 1). Args: scale, model (1 Reynolds, 2 mass-conserving), columns, factorise.
void BM_DerivativeColumns(benchmark::State& state) {
  const Scenario& sc = scenario(static_cast<int>(state.range(0)));
  const auto model =
      state.range(1) == 1 ? CavitationModel::Reynolds : CavitationModel::MassConserving;
  const int columns = static_cast<int>(state.range(2));
  FilmSolverOptions opt;
  opt.factoriseForManyDerivativeColumns = state.range(3) != 0;
  const FilmGrid& g = sc.grid;
  FilmProblem pr = sc.problem(model);
  pr.squeezeBasis.resize(g.nodeCount(), columns);
  for (int c = 0; c < columns; ++c)
    for (int j = 0; j < g.ny(); ++j)
      for (int i = 0; i < g.nx(); ++i) {
        const double th = g.x_m()[i] / Scenario::kRadius_m, y = g.y_m()[j];
        pr.squeezeBasis(g.nodeIndex(i, j), c) =
            c == 0   ? -std::cos(th)
            : c == 1 ? -(y - Scenario::kPinHeight_m) * std::cos(th)
                     : -std::cos(0.5 * (c / 2) * th) * std::pow(y / Scenario::kSkirtLength_m, c % 3);
      }
  double factorisations = 0, krylov = 0, solves = 0;
  runWarmStroke(state, sc, opt, pr, [&](const FilmResult& r) {
    factorisations += r.factorisations;
    krylov += r.krylovIterations;
    solves += 1;
  });
  state.counters["time_per_solve"] =
      benchmark::Counter(solves, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["factorisations"] = factorisations / solves;
  state.counters["krylovIt"] = krylov / solves;
}
BENCHMARK(BM_DerivativeColumns)
    ->ArgNames({"scale", "model", "columns", "factorise"})
    ->ArgsProduct({{1, 2}, {1, 2}, {2, 22}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Cold starts (issue 12): one solve without a warm start, with and without the grid-sequenced
// start (FilmSolverOptions::gridSequencedColdStart). Args: scale (64 x 48 times it), model (1
// Reynolds, 2 mass-conserving), sequenced (0 / 1), step of the scenario (1: 360 deg, the piston
// away from this side, a wide gap; 40: 379.5 deg, 0.7 of the clearance towards it).
void BM_ColdStart(benchmark::State& state) {
  const Scenario& sc = scenario(static_cast<int>(state.range(0)));
  const auto model =
      state.range(1) == 1 ? CavitationModel::Reynolds : CavitationModel::MassConserving;
  FilmProblem pr = sc.problem(model);
  sc.setStep(pr, static_cast<int>(state.range(3)));
  FilmSolverOptions opt;
  opt.gridSequencedColdStart = state.range(2) != 0;
  FilmSolver solver(opt);
  FilmResult r;
  double fine = 0, coarse = 0, fallbacks = 0, solves = 0;
  for (auto _ : state) {
    solver.solve(sc.grid, pr, nullptr, r);
    fine += r.activeSetIterations;
    coarse += r.coarseActiveSetIterations;
    fallbacks += r.usedFallback ? 1 : 0;
    solves += 1;
  }
  state.counters["nodes"] = sc.grid.nodeCount();
  state.counters["activeSetIt"] = fine / solves;
  state.counters["coarseActiveSetIt"] = coarse / solves;
  state.counters["fallbacks"] = fallbacks / solves;
}
BENCHMARK(BM_ColdStart)
    ->ArgNames({"scale", "model", "sequenced", "step"})
    ->ArgsProduct({{1, 2, 4}, {1, 2}, {0, 1}, {1, 40}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
