#pragma once
/// @file
/// What a transient mass-conserving film needs from the past: the fill fraction and the
/// expected gap at the last one or two accepted time steps. One value type, carried unchanged
/// from the caller's state (e.g. a Simbody auto-update variable) through the skirt side to
/// FilmProblem::history, and validated once, by FilmSolver::solve().

#include <limits>

#include <Eigen/Core>

namespace pistondyn::lubrication {

/// The film at one accepted time step.
struct FilmHistoryPoint {
  /// Fill fraction theta per node [-], in [0, 1]; empty = a full film (theta = 1).
  Eigen::ArrayXd fillFraction;
  /// Expected gap hT per node [m] (FilmResult::expectedGap_m of the solve that gave
  /// fillFraction), > 0; empty = not known (the step's own hT stands in for it).
  Eigen::ArrayXd expectedGap_m;
  /// True when the point holds a fill fraction.
  bool empty() const { return fillFraction.size() == 0; }
};

/// The history of a transient mass-conserving film (FilmProblem.h, "Discrete equation").
///
/// With `last` alone the fill fraction's time derivative in the storage term is backward Euler
/// over the step FilmProblem::timeStep_s; with `earlier` and `earlierStep_s` as well it is the
/// variable-step BDF2 formula (FilmProblem.h). The expected gaps let a cavitated node whose gap
/// moves within a step keep its oil content theta hT; without them the form is exact only for
/// a fixed gap. Requirements (checked by FilmSolver::solve()): every non-empty array has one
/// entry per node; `earlier` needs `last` and a positive, finite earlierStep_s; an expected gap
/// needs the fill fraction of its point (and `earlier`'s also `last`'s).
struct FilmHistory {
  FilmHistoryPoint last;     ///< at t_n, the start of the step being solved
  FilmHistoryPoint earlier;  ///< at t_{n-1} (empty: first order in time)
  /// t_n - t_{n-1} [s]; NaN while `earlier` is empty.
  double earlierStep_s = std::numeric_limits<double>::quiet_NaN();

  /// True when nothing is known of the past (a full film at rest).
  bool empty() const { return last.empty(); }

  /// The history after a step of `step_s` has been accepted whose solution is `now`.
  /// step_s > 0: `now` becomes `last` and, when `order` is 2, the old `last` becomes
  /// `earlier` (with order 1 no earlier point is kept). step_s <= 0 (the same instant solved
  /// again): `now` replaces `last`, `earlier` stays.
  FilmHistory advanced(const FilmHistoryPoint& now, double step_s, int order) const {
    FilmHistory h;
    h.last = now;
    if (step_s > 0.0) {
      if (order == 2) {
        h.earlier = last;
        h.earlierStep_s = step_s;
      }
    } else {
      h.earlier = earlier;
      h.earlierStep_s = earlierStep_s;
    }
    return h;
  }
};

}  // namespace pistondyn::lubrication
