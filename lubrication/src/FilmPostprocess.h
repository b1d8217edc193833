#pragma once
// Internal: loads, moments, friction, h/sigma, minimum film and diagnostics of a solved film.
// Not installed.

#include <Eigen/Core>

#include "FilmSystem.h"

namespace pistondyn::lubrication::detail {

// Fills every output field of res from the solved system (pressure, fill fraction, active set,
// loads, shear, ...). dPressure: nodeCount x M pressure derivatives, or nullptr. The solver
// report fields (iterations, residual, converged) are left to the caller.
void postprocess(const FilmGrid& grid, const FilmProblem& problem, const FilmSystem& sys,
                 const Eigen::MatrixXd* dPressure, FilmResult& res);

}  // namespace pistondyn::lubrication::detail
