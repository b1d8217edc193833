#include "ColdStartSequence.h"

#include <algorithm>

namespace pistondyn::lubrication::detail {
namespace {

// Every other index, and the last one on an open direction (its edge stays an edge).
std::vector<int> keptIndices(int n, bool periodic) {
  std::vector<int> kept;
  for (int i = 0; i < n; i += 2)
    kept.push_back(i);
  if (!periodic && kept.back() != n - 1)
    kept.push_back(n - 1);
  return kept;
}

// For each fine index: the coarse interval it lies in and the weight of its upper end, by
// coordinate. Periodic: the last interval wraps to the first coarse node one period on.
void intervals(const Eigen::VectorXd& c, const std::vector<int>& kept, bool periodic,
               double period, std::vector<int>& interval, std::vector<double>& weight) {
  const int n = static_cast<int>(c.size());
  const int m = static_cast<int>(kept.size());
  interval.assign(n, 0);
  weight.assign(n, 0.0);
  int a = 0;
  for (int i = 0; i < n; ++i) {
    while (a + 1 < m && kept[a + 1] <= i)
      ++a;
    if (a + 1 < m) {
      const double lo = c[kept[a]], hi = c[kept[a + 1]];
      interval[i] = a;
      weight[i] = (c[i] - lo) / (hi - lo);
    } else if (periodic) {  // beyond the last kept node: towards the first one, wrapped
      const double lo = c[kept[a]], hi = c[kept[0]] + period;
      interval[i] = a;
      weight[i] = (c[i] - lo) / (hi - lo);
    } else {  // the last node itself (kept)
      interval[i] = std::max(a - 1, 0);
      weight[i] = m > 1 ? 1.0 : 0.0;
    }
  }
}

Eigen::ArrayXd inject(const Eigen::ArrayXd& fine, const CoarseLevel& l, int fineNx) {
  if (fine.size() == 0)
    return fine;
  const int nx = static_cast<int>(l.xCoarse.size()), ny = static_cast<int>(l.yCoarse.size());
  Eigen::ArrayXd coarse(nx * ny);
  for (int b = 0; b < ny; ++b)
    for (int a = 0; a < nx; ++a)
      coarse[a + nx * b] = fine[l.xCoarse[a] + fineNx * l.yCoarse[b]];
  return coarse;
}

Eigen::ArrayXd injectEdge(const Eigen::ArrayXd& fine, const std::vector<int>& kept) {
  if (fine.size() == 0)
    return fine;
  Eigen::ArrayXd coarse(kept.size());
  for (std::size_t a = 0; a < kept.size(); ++a)
    coarse[static_cast<Eigen::Index>(a)] = fine[kept[a]];
  return coarse;
}

}  // namespace

bool makeCoarseLevel(const FilmGrid& fine, const FilmProblem& pr, CoarseLevel& l) {
  const int nx = fine.nx(), ny = fine.ny();
  if (nx < kMinSequencedNodes || ny < kMinSequencedNodes)
    return false;
  const bool periodic = fine.isPeriodicX();
  // The same fine grid as last time (the usual case: one solver per grid): keep the coarse
  // grid, so that the coarse solver's own caches (factorisation pattern, multigrid) stay valid.
  const bool sameGrid = l.grid && l.fineX_m.size() == nx && l.fineY_m.size() == ny &&
                        l.fineX_m == fine.x_m() && l.fineY_m == fine.y_m() &&
                        l.grid->isPeriodicX() == periodic &&
                        l.grid->periodX_m() == fine.periodX_m();
  if (!sameGrid)
    makeCoarseGrid(fine, l);
  injectProblem(pr, l, nx);
  return true;
}

void makeCoarseGrid(const FilmGrid& fine, CoarseLevel& l) {
  const int nx = fine.nx(), ny = fine.ny();
  const bool periodic = fine.isPeriodicX();
  l.fineX_m = fine.x_m();
  l.fineY_m = fine.y_m();
  l.xCoarse = keptIndices(nx, periodic);
  l.yCoarse = keptIndices(ny, false);
  Eigen::VectorXd x(l.xCoarse.size()), y(l.yCoarse.size());
  for (std::size_t a = 0; a < l.xCoarse.size(); ++a)
    x[static_cast<Eigen::Index>(a)] = fine.x_m()[l.xCoarse[a]];
  for (std::size_t b = 0; b < l.yCoarse.size(); ++b)
    y[static_cast<Eigen::Index>(b)] = fine.y_m()[l.yCoarse[b]];
  intervals(fine.x_m(), l.xCoarse, periodic, fine.periodX_m(), l.xInterval, l.xWeight);
  intervals(fine.y_m(), l.yCoarse, false, 0.0, l.yInterval, l.yWeight);
  l.grid.emplace(FilmGrid::fromCoordinates(x, y, periodic, fine.periodX_m()));
}

void injectProblem(const FilmProblem& pr, CoarseLevel& l, int nx) {
  l.problem = pr;  // scalars, flow factors, boundary pressures and supplies
  l.problem.gap_m = inject(pr.gap_m, l, nx);
  l.problem.gapRate_mps = inject(pr.gapRate_mps, l, nx);
  l.problem.viscosityPerNode_Pas = inject(pr.viscosityPerNode_Pas, l, nx);
  l.problem.history.last.fillFraction = inject(pr.history.last.fillFraction, l, nx);
  l.problem.history.earlier.fillFraction = inject(pr.history.earlier.fillFraction, l, nx);
  l.problem.history.last.expectedGap_m = inject(pr.history.last.expectedGap_m, l, nx);
  l.problem.history.earlier.expectedGap_m = inject(pr.history.earlier.expectedGap_m, l, nx);
  l.problem.squeezeBasis.resize(0, 0);  // the start needs no derivatives
  l.problem.gapBasis.resize(0, 0);
  l.problem.gapRateBasis.resize(0, 0);
  for (FilmEdge* e : {&l.problem.boundary.yMin, &l.problem.boundary.yMax})
    e->supplyFilmPerNode_m = injectEdge(e->supplyFilmPerNode_m, l.xCoarse);
  for (FilmEdge* e : {&l.problem.boundary.xMin, &l.problem.boundary.xMax})
    e->supplyFilmPerNode_m = injectEdge(e->supplyFilmPerNode_m, l.yCoarse);
}

void prolongState(const CoarseLevel& l, const FilmState& coarse, int fineNx, int fineNy,
                  FilmState& fine) {
  const int cnx = static_cast<int>(l.xCoarse.size());
  fine.pressure_Pa.resize(fineNx * fineNy);
  fine.fillFraction.resize(fineNx * fineNy);
  fine.cavitated.clear();
  for (int j = 0; j < fineNy; ++j) {
    // y is open: intervals() gives every fine row an interval (b, b + 1) inside the coarse grid.
    const int b = l.yInterval[j], b1 = b + 1;
    const double wy = l.yWeight[j];
    for (int i = 0; i < fineNx; ++i) {
      const int a = l.xInterval[i];
      const int a1 = (a + 1) % cnx;  // wraps on a periodic x (weight 0 at the last kept node)
      const double wx = l.xWeight[i];
      const auto at = [&](const Eigen::ArrayXd& f) {
        return (1.0 - wy) * ((1.0 - wx) * f[a + cnx * b] + wx * f[a1 + cnx * b]) +
               wy * ((1.0 - wx) * f[a + cnx * b1] + wx * f[a1 + cnx * b1]);
      };
      const int k = i + fineNx * j;
      fine.pressure_Pa[k] = at(coarse.pressure_Pa);
      fine.fillFraction[k] = std::clamp(at(coarse.fillFraction), 0.0, 1.0);
    }
  }
}

}  // namespace pistondyn::lubrication::detail
