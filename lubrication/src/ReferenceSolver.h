#pragma once
// Internal: the thesis' reference solver, point Gauss-Seidel with over-relaxation. Not installed.

#include "FilmSystem.h"

namespace pistondyn::lubrication::detail {

struct IterationReport {
  int iterations = 0;
  double residual = 0.0;
  bool converged = false;
};

// Runs Gauss-Seidel sweeps on sys.p / sys.theta from their current values until the relative
// residual is <= options.tolerance or maxSweeps sweeps are done. The exact residual is
// evaluated only when the residuals met during a sweep are near the tolerance. Leaves sys.status
// consistent with the iterate (kCav where p sits at p_cav or theta < 1).
//  * None:     SOR on the Reynolds balance.
//  * Reynolds: projected SOR, p <- max(p_cav, SOR update)  (Christopherson / Cryer).
//  * MassConserving: Elrod-Adams Gauss-Seidel in the manner of Ausas et al. (2009): a full node
//    (theta = 1) is updated in pressure; if that drops below p_cav it cavitates and its fill
//    fraction follows from the balance; a cavitated node (p = p_cav) is updated in fill
//    fraction (relaxed by fillRelaxation) and returns to full film when theta reaches 1.
IterationReport gaussSeidelSolve(FilmSystem& sys, const FilmSolverOptions& options, int maxSweeps);

}  // namespace pistondyn::lubrication::detail
