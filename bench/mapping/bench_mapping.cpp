// pistondyn::mapping timings (Google Benchmark). Grids as in issue 5: a 64 x 48 contact
// (film) grid on one skirt side, a 17 x 30 structural grid, a 36 x 400 liner grid.
// Results and the machine go to BENCHMARKS.md ("Mapping").

#include <benchmark/benchmark.h>

#include <Eigen/Core>

#include "pistondyn/mapping/ForceMap.h"
#include "pistondyn/mapping/HermiteSurface.h"

namespace pm = pistondyn::mapping;

namespace {

constexpr double kRadius_m = 0.03255;  // bore 65.1 mm (thesis test engine)

// Contact grid of one skirt side: +-40 deg around the thrust axis, 30 mm of skirt.
pm::CylinderGrid contactGrid() {
  return pm::CylinderGrid::sector(kRadius_m, pm::uniformNodes(-0.698, 0.698, 64),
                                  pm::uniformNodes(0.0, 0.030, 48));
}
// Structural grid of the skirt half: +-90 deg, 34 mm, 17 x 30 nodes.
pm::CylinderGrid structuralGrid() {
  return pm::CylinderGrid::sector(kRadius_m, pm::uniformNodes(-1.571, 1.571, 17),
                                  pm::uniformNodes(-0.002, 0.032, 30));
}
// Liner: full circle, 120 mm of bore, 36 x 400 nodes.
pm::CylinderGrid linerGrid() {
  return pm::CylinderGrid::fullCircle(kRadius_m, pm::fullCircleNodes_rad(36),
                                      pm::uniformNodes(0.0, 0.120, 400));
}

Eigen::VectorXd contactPressure(const pm::CylinderGrid& g) {
  Eigen::VectorXd p(g.nodeCount());
  for (int j = 0; j < g.nY(); ++j)
    for (int i = 0; i < g.nPhi(); ++i)
      p[g.index(i, j)] = 1e6 * std::exp(-10.0 * g.phi_rad()[i] * g.phi_rad()[i]) *
                         std::sin(3.14159 * g.y_m()[j] / 0.03);
  return p;
}

// A deformation-like field on the structural grid [m].
Eigen::VectorXd structuralField(const pm::CylinderGrid& g) {
  Eigen::VectorXd v(g.nodeCount());
  for (int k = 0; k < v.size(); ++k)
    v[k] = 1e-5 * std::sin(0.37 * k);
  return v;
}

// Piston position in the liner frame at step k of a stroke sampled in 360 steps.
double pistonPosition_m(int k) {
  return 0.045 + 0.0435 * std::cos(2.0 * 3.14159265358979 * (k % 360) / 360.0);
}

// The contact grid over the liner: the map, its per-step workspace and a pressure and shear
// field on the contact grid (built once, outside the timed loops).
struct ContactOnLiner {
  pm::CylinderGrid contact = contactGrid(), liner = linerGrid();
  pm::TensorForceMap map{contact, liner, 0.0};
  pm::TensorForceMap::Workspace ws;
  Eigen::VectorXd p = contactPressure(contact);
  Eigen::VectorXd tau = 0.01 * p;
  Eigen::VectorXd zero = Eigen::VectorXd::Zero(p.size());  // no temporary per call
  Eigen::VectorXd linerField() const { return Eigen::VectorXd::Zero(liner.nodeCount()); }
};

// Contact pressure -> structural nodal forces, prebuilt sparse map (per call).
void BM_ForceMap_ContactToStructural_Apply(benchmark::State& state) {
  const auto contact = contactGrid(), structural = structuralGrid();
  const pm::ForceMap map(contact, structural, {});
  const Eigen::VectorXd p = contactPressure(contact);
  Eigen::VectorXd f(structural.nodeCount());
  for (auto _ : state) {
    benchmark::DoNotOptimize(map.apply(p, f));
    benchmark::DoNotOptimize(f.data());
  }
}
BENCHMARK(BM_ForceMap_ContactToStructural_Apply);

// One-off cost of building that map.
void BM_ForceMap_ContactToStructural_Build(benchmark::State& state) {
  const auto contact = contactGrid(), structural = structuralGrid();
  for (auto _ : state) {
    const pm::ForceMap map(contact, structural, {});
    benchmark::DoNotOptimize(map.matrix().nonZeros());
  }
}
BENCHMARK(BM_ForceMap_ContactToStructural_Build);

// Contact pressure -> liner nodal forces at a moving piston position: per step the axial
// factor is rebuilt for the new offset and the map applied (what the plugin does).
void BM_TensorForceMap_ContactToLiner_StepAndApply(benchmark::State& state) {
  ContactOnLiner c;
  Eigen::VectorXd f = c.linerField();
  int k = 0;
  for (auto _ : state) {
    c.map.setAxialOffset(pistonPosition_m(k++), c.ws);
    benchmark::DoNotOptimize(c.map.apply(c.ws, c.p, f));
    benchmark::DoNotOptimize(f.data());
  }
}
BENCHMARK(BM_TensorForceMap_ContactToLiner_StepAndApply);

// The same per step, split: the axial update alone and the application alone.
void BM_TensorForceMap_ContactToLiner_AxialUpdateOnly(benchmark::State& state) {
  ContactOnLiner c;
  int k = 0;
  for (auto _ : state) {
    c.map.setAxialOffset(pistonPosition_m(k++), c.ws);
    benchmark::DoNotOptimize(c.ws.axial.value.data());
  }
}
BENCHMARK(BM_TensorForceMap_ContactToLiner_AxialUpdateOnly);

void BM_TensorForceMap_ContactToLiner_ApplyOnly(benchmark::State& state) {
  ContactOnLiner c;
  c.map.setAxialOffset(0.05, c.ws);
  Eigen::VectorXd f = c.linerField();
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.map.apply(c.ws, c.p, f));
    benchmark::DoNotOptimize(f.data());
  }
}
BENCHMARK(BM_TensorForceMap_ContactToLiner_ApplyOnly);

// 3-D traction (normal, circumferential, axial) onto the liner per step.
void BM_TensorForceMap_ContactToLiner_Traction3DStep(benchmark::State& state) {
  ContactOnLiner c;
  Eigen::VectorXd fx = c.linerField(), fy = fx, fz = fx;
  int k = 0;
  for (auto _ : state) {
    c.map.setAxialOffset(pistonPosition_m(k++), c.ws);
    benchmark::DoNotOptimize(c.map.applyTraction(c.ws, c.p, c.zero, c.tau, fx, fy, fz));
    benchmark::DoNotOptimize(fx.data());
  }
}
BENCHMARK(BM_TensorForceMap_ContactToLiner_Traction3DStep);

// The windowed paths per step, as the plugin would use them: clear the liner rows the
// previous step wrote, move, add the new loads into the rows the contact grid overlaps.
// Cost scales with the contact grid, not with the 14400-node liner.
void BM_TensorForceMap_ContactToLiner_StepAndAccumulate(benchmark::State& state) {
  ContactOnLiner c;
  Eigen::VectorXd f = c.linerField();
  const int nPhi = c.liner.nPhi();
  int k = 0;
  for (auto _ : state) {
    f.segment(nPhi * c.ws.rows.first, nPhi * c.ws.rows.count).setZero();
    c.map.setAxialOffset(pistonPosition_m(k++), c.ws);
    benchmark::DoNotOptimize(c.map.accumulate(c.ws, c.p, f));
    benchmark::DoNotOptimize(f.data());
  }
}
BENCHMARK(BM_TensorForceMap_ContactToLiner_StepAndAccumulate);

void BM_TensorForceMap_ContactToLiner_Traction3DStepWindowed(benchmark::State& state) {
  ContactOnLiner c;
  Eigen::VectorXd fx = c.linerField(), fy = fx, fz = fx;
  const int nPhi = c.liner.nPhi();
  int k = 0;
  for (auto _ : state) {
    const Eigen::Index first = nPhi * c.ws.rows.first, count = nPhi * c.ws.rows.count;
    fx.segment(first, count).setZero();
    fy.segment(first, count).setZero();
    fz.segment(first, count).setZero();
    c.map.setAxialOffset(pistonPosition_m(k++), c.ws);
    benchmark::DoNotOptimize(c.map.accumulateTraction(c.ws, c.p, c.zero, c.tau, fx, fy, fz));
    benchmark::DoNotOptimize(fx.data());
  }
}
BENCHMARK(BM_TensorForceMap_ContactToLiner_Traction3DStepWindowed);

// For comparison: rebuilding a full ForceMap for every new offset, then applying it.
void BM_ForceMap_ContactToLiner_FullRebuildPerStep(benchmark::State& state) {
  const auto contact = contactGrid(), liner = linerGrid();
  const Eigen::VectorXd p = contactPressure(contact);
  Eigen::VectorXd f(liner.nodeCount());
  int k = 0;
  for (auto _ : state) {
    const pm::ForceMap map(contact, liner, {0.0, pistonPosition_m(k++)});
    benchmark::DoNotOptimize(map.apply(p, f));
    benchmark::DoNotOptimize(f.data());
  }
}
BENCHMARK(BM_ForceMap_ContactToLiner_FullRebuildPerStep);

// Structural field (e.g. skirt deformation) read onto the contact grid by the bicubic
// Hermite surface: values only, and values with d/dphi, d/dy.
void BM_Hermite_StructuralToContact_Values(benchmark::State& state) {
  const auto contact = contactGrid(), structural = structuralGrid();
  const pm::HermiteSurface surface(structural, structuralField(structural));
  pm::HermiteGridWorkspace ws;
  Eigen::VectorXd out(contact.nodeCount());
  for (auto _ : state) {
    surface.evaluateOnGrid(contact, {0.0, 0.0}, out, ws);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_Hermite_StructuralToContact_Values);

void BM_Hermite_StructuralToContact_ValuesAndDerivatives(benchmark::State& state) {
  const auto contact = contactGrid(), structural = structuralGrid();
  const pm::HermiteSurface surface(structural, structuralField(structural));
  pm::HermiteGridWorkspace ws;
  Eigen::VectorXd out(contact.nodeCount()), dPhi(contact.nodeCount()), dY(contact.nodeCount());
  for (auto _ : state) {
    surface.evaluateOnGrid(contact, {0.0, 0.0}, out, dPhi, dY, ws);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_Hermite_StructuralToContact_ValuesAndDerivatives);

// New nodal values (deformation of this step) on the structural grid: spline slopes and
// cell matrices recomputed with the stored factorisations.
void BM_Hermite_Structural_UpdateValues(benchmark::State& state) {
  const auto structural = structuralGrid();
  Eigen::VectorXd v = structuralField(structural);
  pm::HermiteSurface surface(structural, v);
  for (auto _ : state) {
    v *= 1.0000001;
    surface.updateValues(v);
    benchmark::DoNotOptimize(surface.values().data());
  }
}
BENCHMARK(BM_Hermite_Structural_UpdateValues);

// Liner field (bore distortion / liner deformation) read onto the contact grid at the
// moving piston position, and the liner surface's update when its values change.
void BM_Hermite_LinerToContact_MovingValues(benchmark::State& state) {
  const auto contact = contactGrid(), liner = linerGrid();
  Eigen::VectorXd v(liner.nodeCount());
  for (int j = 0; j < liner.nY(); ++j)
    for (int i = 0; i < liner.nPhi(); ++i)
      v[liner.index(i, j)] =
          1e-6 * std::cos(2.0 * liner.phi_rad()[i]) * (1.0 + 10.0 * liner.y_m()[j]);
  const pm::HermiteSurface surface(liner, v);
  pm::HermiteGridWorkspace ws;
  Eigen::VectorXd out(contact.nodeCount());
  int k = 0;
  for (auto _ : state) {
    surface.evaluateOnGrid(contact, {0.0, pistonPosition_m(k++)}, out, ws);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_Hermite_LinerToContact_MovingValues);

void BM_Hermite_Liner_UpdateValues(benchmark::State& state) {
  const auto liner = linerGrid();
  Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(liner.nodeCount(), 0.0, 1e-6);
  pm::HermiteSurface surface(liner, v);
  for (auto _ : state) {
    v *= 1.0000001;
    surface.updateValues(v);
    benchmark::DoNotOptimize(surface.values().data());
  }
}
BENCHMARK(BM_Hermite_Liner_UpdateValues);

}  // namespace

BENCHMARK_MAIN();
