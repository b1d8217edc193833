#pragma once
// Grid-sequenced cold start of the fast film solver (FilmSolverOptions::gridSequencedColdStart):
// the problem restricted to every other node, solved there (recursively: its own cold start is
// sequenced too), and its pressure and fill fraction interpolated back as the fine grid's
// start. Why: from a cold start the active-set iteration moves a cavitation front a few cells
// per step, so its step count grows with the grid (8 / 16 / 27 at 64 x 48 / 128 x 96 /
// 256 x 192 on the skirt patch of tests/lubrication); from the coarse solution the front is
// within a cell or two of its place, at any grid.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "pistondyn/lubrication/FilmGrid.h"
#include "pistondyn/lubrication/FilmProblem.h"

namespace pistondyn::lubrication::detail {

// One coarser level: its grid, its problem (the fine one's per-node data injected), and for
// each fine node index along x and y the coarse interval it lies in and its weight.
struct CoarseLevel {
  std::optional<FilmGrid> grid;  // set by makeCoarseLevel (FilmGrid has no empty state)
  FilmProblem problem;
  std::vector<int> xCoarse, yCoarse;        // fine indices kept (ascending)
  std::vector<int> xInterval, yInterval;    // per fine index: coarse interval a (a, a+1)
  std::vector<double> xWeight, yWeight;     // per fine index: weight of coarse node a + 1
  Eigen::VectorXd fineX_m, fineY_m;         // the fine grid's coordinates it was made for
};

// Parts of makeCoarseLevel: the coarse grid and interpolation tables for `fine`, and the
// problem's per-node data injected onto it.
void makeCoarseGrid(const FilmGrid& fine, CoarseLevel& level);
void injectProblem(const FilmProblem& problem, CoarseLevel& level, int fineNx);

// Smallest fine node count along each direction that is coarsened (the coarse level then has
// at least 5 nodes that way).
constexpr int kMinSequencedNodes = 9;

// True when `fine` is large enough to coarsen; then fills `level` (allocates: a cold start only).
bool makeCoarseLevel(const FilmGrid& fine, const FilmProblem& problem, CoarseLevel& level);

// The fine start from the coarse solution: pressure and fill fraction interpolated bilinearly
// (fill fraction clamped to [0, 1]); the active set is left to the solver (empty `cavitated`:
// derived from the pressure and fill fraction as for any warm start without one).
void prolongState(const CoarseLevel& level, const FilmState& coarse, int fineNx, int fineNy,
                  FilmState& fine);

}  // namespace pistondyn::lubrication::detail
