// Cost of F_{5/2} (exact tables vs the power-law fit) and of GreenwoodTrippLaw::calcField.
// Figures and the machine are recorded in BENCHMARKS.md ("Asperity contact").

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "pistondyn/contact_forces/BoundaryFriction.h"
#include "pistondyn/contact_forces/GaussianTailIntegrals.h"
#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"

namespace pc = pistondyn::contact_forces;

namespace {

// 1024 film ratios spread over [−1, 5] (mixed and boundary plus a margin), in an order
// that defeats branch prediction of the table piece.
std::vector<double> filmRatios() {
  std::vector<double> out(1024);
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = -1.0 + 6.0 * std::fmod(0.6180339887498949 * static_cast<double>(i), 1.0);
  }
  return out;
}

// f(λ) for every film ratio of filmRatios(), once per iteration.
template <class F>
void overFilmRatios(benchmark::State& state, F f) {
  const std::vector<double> lambdas = filmRatios();
  for (auto _ : state) {
    for (double lambda : lambdas) {
      benchmark::DoNotOptimize(f(lambda));
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(lambdas.size()));
}

void BM_F52_ExactTable(benchmark::State& state) {
  overFilmRatios(state, [](double lambda) { return pc::greenwoodTrippF52(lambda); });
}
BENCHMARK(BM_F52_ExactTable);

void BM_F52AndSlope_ExactTable(benchmark::State& state) {
  overFilmRatios(state, [](double lambda) { return pc::greenwoodTrippF52WithSlope(lambda); });
}
BENCHMARK(BM_F52AndSlope_ExactTable);

void BM_F52_PowerLawFit(benchmark::State& state) {
  overFilmRatios(state, [](double lambda) { return pc::kPowerLawFitF52.value(lambda); });
}
BENCHMARK(BM_F52_PowerLawFit);

void BM_F52_Erfc_Reference(benchmark::State& state) {
  // Not F_{5/2}: one std::erfc per node, as a yardstick for "one special function call".
  overFilmRatios(state, [](double lambda) { return std::erfc(lambda * 0.7071067811865476); });
}
BENCHMARK(BM_F52_Erfc_Reference);

// A whole field: pressure, slope, area fraction, h/σ and regime per node.
void BM_GreenwoodTrippField(benchmark::State& state) {
  pc::GreenwoodTrippParameters p;
  p.tailModel = static_cast<pc::TailIntegralModel>(state.range(1));
  const pc::GreenwoodTrippLaw law(p);
  const Eigen::Index n = state.range(0);
  Eigen::ArrayXXd gap(n, n);
  const std::vector<double> lambdas = filmRatios();
  for (Eigen::Index k = 0; k < gap.size(); ++k) {
    gap(k) = lambdas[static_cast<std::size_t>(k) % lambdas.size()] * law.compositeSigma_m();
  }
  pc::ContactField field;
  for (auto _ : state) {
    law.calcField(gap, field);
    benchmark::DoNotOptimize(field.pressure_Pa.data());
  }
  state.SetItemsProcessed(state.iterations() * gap.size());
}
BENCHMARK(BM_GreenwoodTrippField)
    ->ArgNames({"n", "model"})
    ->Args({64, static_cast<int>(pc::TailIntegralModel::Exact)})
    ->Args({64, static_cast<int>(pc::TailIntegralModel::PowerLawFit)});

void BM_BoundaryFrictionField(benchmark::State& state) {
  const pc::BoundaryFriction friction;
  const Eigen::Index n = 64;
  const Eigen::ArrayXXd p = Eigen::ArrayXXd::Constant(n, n, 1e6);
  const Eigen::ArrayXXd vx = Eigen::ArrayXXd::Random(n, n);
  const Eigen::ArrayXXd vy = 1e-2 * Eigen::ArrayXXd::Random(n, n);
  Eigen::ArrayXXd tx, ty;
  for (auto _ : state) {
    friction.calcShearStressField(p, vx, vy, tx, ty);
    benchmark::DoNotOptimize(tx.data());
  }
  state.SetItemsProcessed(state.iterations() * n * n);
}
BENCHMARK(BM_BoundaryFrictionField);

// One sliding velocity for the whole field (the piston's axial speed).
void BM_BoundaryFrictionFieldUniformVelocity(benchmark::State& state) {
  const pc::BoundaryFriction friction;
  const Eigen::Index n = 64;
  const Eigen::ArrayXXd p = 1e6 * (1.0 + Eigen::ArrayXXd::Random(n, n));
  const Eigen::Vector2d v(0.0, 7.5);
  Eigen::ArrayXXd tx, ty;
  for (auto _ : state) {
    friction.calcShearStressField(p, v, tx, ty);
    benchmark::DoNotOptimize(tx.data());
  }
  state.SetItemsProcessed(state.iterations() * n * n);
}
BENCHMARK(BM_BoundaryFrictionFieldUniformVelocity);

}  // namespace

BENCHMARK_MAIN();
