#pragma once
// Internal: loads, moments, friction, h/sigma, minimum film and diagnostics of a solved film.
// Not installed.

#include <vector>

#include <Eigen/Core>

#include "FilmSystem.h"

namespace pistondyn::lubrication::detail {

// Derivative at node i of a nodal function f along one axis from a quadratic through three
// nodes: central on interior (and periodic) nodes, one-sided at open ends. Second order on
// graded grids. Weights (cm, c0, cp) for (f[im], f[i0], f[ip]): (f[i-1], f[i], f[i+1]) or, at an
// open start, (f[0], f[1], f[2]) and, at an open end, (f[n-3], f[n-2], f[n-1]).
struct Stencil3 {
  int im, i0, ip;
  double cm, c0, cp;
};

// Storage kept between calls: grows with the grid only (no allocation at a fixed size).
struct PostprocessWorkspace {
  std::vector<Stencil3> xStencils;  // derivative stencil along x of each column i
};

// Fills every output field of res from the solved system (pressure, fill fraction, active set,
// loads, shear, ...). dPressure: nodeCount x M pressure derivatives, or nullptr. The solver
// report fields (iterations, residual, converged) are left to the caller.
void postprocess(const FilmGrid& grid, const FilmProblem& problem, const FilmSystem& sys,
                 const Eigen::MatrixXd* dPressure, PostprocessWorkspace& workspace,
                 FilmResult& res);

}  // namespace pistondyn::lubrication::detail
