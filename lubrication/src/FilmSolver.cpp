#include "pistondyn/lubrication/FilmSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "ActiveSetSolver.h"
#include "ColdStartSequence.h"
#include "FilmPostprocess.h"
#include "FilmSystem.h"
#include "ReferenceSolver.h"
#include "pistondyn/common/Validation.h"

namespace pistondyn::lubrication {

namespace {

constexpr const char* kWhere = "FilmSolver::solve";

// "FilmSolver::solve: " followed by the parts of the message (common::message).
template <class... Parts>
[[noreturn]] void fail(const Parts&... parts) {
  common::throwInvalidArgument(kWhere, common::message(parts...));
}

void checkSize(Eigen::Index size, Eigen::Index expected, const char* name, bool allowEmpty) {
  if (allowEmpty && size == 0)
    return;
  if (size != expected)
    fail(name, " has ", size, " entries, expected ", expected, allowEmpty ? " (or 0)" : "",
         " for this grid");
}

// unit may be empty (dimensionless entries).
void checkFinite(const Eigen::ArrayXd& a, const char* name, const char* unit) {
  for (Eigen::Index k = 0; k < a.size(); ++k)
    if (!std::isfinite(a[k]))
      common::throwNotFinite(a[k], kWhere, common::message(name, "[", k, "]"), unit);
}

// The film history (FilmHistory.h): sizes, fill fractions in [0, 1], positive expected gaps,
// and an earlier point only with a last one and its step. Names are literals: a passing check
// allocates nothing.
void checkHistoryPoint(const FilmHistoryPoint& point, Eigen::Index n, const char* fillName,
                       const char* gapName) {
  checkSize(point.fillFraction.size(), n, fillName, true);
  for (Eigen::Index k = 0; k < point.fillFraction.size(); ++k) {
    const double t = point.fillFraction[k];
    if (!(t >= 0.0 && t <= 1.0))
      fail(fillName, "[", k, "] = ", t, " must lie in [0, 1]");
  }
  checkSize(point.expectedGap_m.size(), n, gapName, true);
  if (point.expectedGap_m.size() > 0 && point.fillFraction.size() != n)
    fail(gapName, " needs ", fillName);
  for (Eigen::Index k = 0; k < point.expectedGap_m.size(); ++k)
    if (!(std::isfinite(point.expectedGap_m[k]) && point.expectedGap_m[k] > 0.0))
      fail(gapName, "[", k, "] = ", point.expectedGap_m[k], " m must be positive and finite");
}

void checkHistory(const FilmHistory& h, Eigen::Index n) {
  checkHistoryPoint(h.last, n, "problem.history.last.fillFraction",
                    "problem.history.last.expectedGap_m");
  checkHistoryPoint(h.earlier, n, "problem.history.earlier.fillFraction",
                    "problem.history.earlier.expectedGap_m");
  if (h.earlier.empty())
    return;
  if (h.last.fillFraction.size() != n)
    fail("problem.history.earlier.fillFraction needs problem.history.last.fillFraction");
  if (!(h.earlierStep_s > 0.0) || !std::isfinite(h.earlierStep_s))
    fail("problem.history.earlierStep_s = ", h.earlierStep_s,
         " s must be > 0 and finite with problem.history.earlier.fillFraction");
  if (h.earlier.expectedGap_m.size() > 0 && h.last.expectedGap_m.size() != n)
    fail("problem.history.earlier.expectedGap_m needs problem.history.last.expectedGap_m");
}

// minPressure_Pa: the lowest admissible edge pressure (-inf where any finite one will do).
void checkEdge(const FilmEdge& e, const char* name, Eigen::Index along, double minPressure_Pa) {
  if (!std::isfinite(e.pressure_Pa))
    fail("problem.boundary.", name, ".pressure_Pa = ", e.pressure_Pa, " Pa must be finite");
  if (e.pressure_Pa < minPressure_Pa)
    fail("problem.boundary.", name, ".pressure_Pa = ", e.pressure_Pa,
         " Pa is below problem.cavitationPressure_Pa = ", minPressure_Pa,
         " Pa; the mass-conserving model needs open edges at or above the cavitation "
         "pressure (use the same gauge or absolute datum for both)");
  if (std::isnan(e.supplyFilm_m) || e.supplyFilm_m < 0.0)
    fail("problem.boundary.", name, ".supplyFilm_m = ", e.supplyFilm_m,
         " m must be >= 0 (or +inf for a flooded edge)");
  // Names are built only on failure: validation runs on every call and must not allocate.
  const Eigen::Index size = e.supplyFilmPerNode_m.size();
  if (size != 0 && size != along) {
    const std::string perNode = std::string("problem.boundary.") + name + ".supplyFilmPerNode_m";
    checkSize(size, along, perNode.c_str(), true);
  }
  for (Eigen::Index k = 0; k < size; ++k) {
    const double s = e.supplyFilmPerNode_m[k];
    if (std::isnan(s) || s < 0.0)
      fail("problem.boundary.", name, ".supplyFilmPerNode_m[", k, "] = ", s, " m must be >= 0");
  }
}

void validate(const FilmGrid& grid, const FilmProblem& pr, const FilmState* warm) {
  if (grid.nx() < 3 || grid.ny() < 3)
    fail("grid has ", grid.nx(), " x ", grid.ny(), " nodes; at least 3 x 3 are needed");
  const Eigen::Index n = grid.nodeCount();
  checkSize(pr.gap_m.size(), n, "problem.gap_m", false);
  for (Eigen::Index k = 0; k < n; ++k)
    if (!(std::isfinite(pr.gap_m[k]) && pr.gap_m[k] > 0.0))
      fail("gap h[", k, "] = ", pr.gap_m[k], " m must be positive and finite (problem.gap_m)");
  if (!(std::isfinite(pr.gapFloor_m) && pr.gapFloor_m >= 0.0))
    fail("problem.gapFloor_m = ", pr.gapFloor_m, " m must be finite and >= 0 (0: no floor)");
  if (pr.gapFloor_m > 0.0) {
    if (pr.faces != FaceValues::LinearGap)
      fail("problem.gapFloor_m = ", pr.gapFloor_m,
           " m needs problem.faces = FaceValues::LinearGap (the nodal means cannot follow the "
           "floor's knee)");
    for (Eigen::Index k = 0; k < n; ++k)
      if (!(pr.gap_m[k] > pr.gapFloor_m))
        fail("gap h[", k, "] = ", pr.gap_m[k], " m must be above problem.gapFloor_m = ",
             pr.gapFloor_m, " m (film gaps of a floored nominal gap, GapFloor.h)");
  }
  checkSize(pr.gapRate_mps.size(), n, "problem.gapRate_mps", true);
  checkFinite(pr.gapRate_mps, "problem.gapRate_mps", "m/s");
  if (!pr.slidingVelocity_mps.allFinite())
    fail("problem.slidingVelocity_mps must be finite");
  if (pr.viscosityPerNode_Pas.size() > 0) {
    checkSize(pr.viscosityPerNode_Pas.size(), n, "problem.viscosityPerNode_Pas", true);
    for (Eigen::Index k = 0; k < n; ++k)
      if (!(std::isfinite(pr.viscosityPerNode_Pas[k]) && pr.viscosityPerNode_Pas[k] > 0.0))
        common::throwNotPositiveFinite(
            pr.viscosityPerNode_Pas[k], kWhere,
            common::message("viscosity problem.viscosityPerNode_Pas[", k, "]"), "Pa s");
  } else if (!(std::isfinite(pr.viscosity_Pas) && pr.viscosity_Pas > 0.0)) {
    common::throwNotPositiveFinite(pr.viscosity_Pas, kWhere, "viscosity problem.viscosity_Pas",
                                   "Pa s");
  }
  if (!std::isfinite(pr.cavitationPressure_Pa))
    fail("problem.cavitationPressure_Pa must be finite");
  // Mass-conserving model: oil at an open edge below p_cav would have to be cavitated and full
  // at once; where a cavitated zone reaches such an edge no mass-conserving solution exists, and
  // the solvers would only report non-convergence after their whole iteration budget. The x
  // edges of an x-periodic grid are not used.
  constexpr double kAny = -std::numeric_limits<double>::infinity();
  const double minEdge =
      pr.cavitation == CavitationModel::MassConserving ? pr.cavitationPressure_Pa : kAny;
  const double minEdgeX = grid.isPeriodicX() ? kAny : minEdge;
  checkEdge(pr.boundary.yMin, "yMin", grid.nx(), minEdge);
  checkEdge(pr.boundary.yMax, "yMax", grid.nx(), minEdge);
  checkEdge(pr.boundary.xMin, "xMin", grid.ny(), minEdgeX);
  checkEdge(pr.boundary.xMax, "xMax", grid.ny(), minEdgeX);
  if (std::isnan(pr.timeStep_s) || !(pr.timeStep_s > 0.0))
    fail("problem.timeStep_s = ", pr.timeStep_s, " s must be > 0 (+inf: steady)");
  checkHistory(pr.history, n);
  if (pr.squeezeBasis.cols() > 0) {
    if (pr.squeezeBasis.rows() != n)
      fail("problem.squeezeBasis has ", pr.squeezeBasis.rows(), " rows, expected ", n,
           " (one per node)");
    if (!pr.squeezeBasis.allFinite())
      fail("problem.squeezeBasis must be finite");
  }
  if (pr.gapBasis.cols() > 0) {
    if (pr.gapBasis.rows() != n)
      fail("problem.gapBasis has ", pr.gapBasis.rows(), " rows, expected ", n, " (one per node)");
    if (!pr.gapBasis.allFinite())
      fail("problem.gapBasis must be finite");
  }
  if (pr.gapRateBasis.size() > 0) {
    if (pr.gapRateBasis.rows() != n || pr.gapRateBasis.cols() != pr.gapBasis.cols())
      fail("problem.gapRateBasis is ", pr.gapRateBasis.rows(), " x ", pr.gapRateBasis.cols(),
           ", expected ", n, " x ", pr.gapBasis.cols(), " (nodes x gap-basis columns) or empty");
    if (!pr.gapRateBasis.allFinite())
      fail("problem.gapRateBasis must be finite");
  }
  if (!pr.momentPoint_m.allFinite())
    fail("problem.momentPoint_m must be finite");
  if (!std::isfinite(pr.referencePressure_Pa))
    fail("problem.referencePressure_Pa must be finite");
  if (warm) {
    checkSize(warm->pressure_Pa.size(), n, "warmStart->pressure_Pa", true);
    checkSize(warm->fillFraction.size(), n, "warmStart->fillFraction", true);
    checkSize(static_cast<Eigen::Index>(warm->cavitated.size()), n, "warmStart->cavitated", true);
    checkFinite(warm->pressure_Pa, "warmStart->pressure_Pa", "Pa");
    checkFinite(warm->fillFraction, "warmStart->fillFraction", "");
  }
}

void validateOptions(const FilmSolverOptions& o) {
  constexpr const char* kSetOptions = "FilmSolver::setOptions";
  common::requirePositiveFinite(o.tolerance, kSetOptions, "tolerance", "");
  common::requirePositiveFinite(o.derivativeTolerance, kSetOptions, "derivativeTolerance", "");
  if (!(o.overRelaxation > 0.0 && o.overRelaxation < 2.0))
    common::throwInvalidArgument(
        kSetOptions, common::message("overRelaxation = ", o.overRelaxation, " must lie in (0, 2)"));
  if (!(o.fillRelaxation > 0.0 && o.fillRelaxation <= 1.0))
    common::throwInvalidArgument(
        kSetOptions, common::message("fillRelaxation = ", o.fillRelaxation, " must lie in (0, 1]"));
  if (o.maxSweeps < 1)
    common::throwInvalidArgument(kSetOptions, "maxSweeps must be >= 1");
  if (o.maxActiveSetIterations < 1)
    common::throwInvalidArgument(kSetOptions, "maxActiveSetIterations must be >= 1");
}

// Flow-factor models are external code: check what they return before it enters the matrices.
void checkFactors(const detail::FilmSystem& s) {
  for (int k = 0; k < s.n; ++k) {
    const bool ok = std::isfinite(s.diagP[k]) && std::isfinite(s.hT[k]) && s.hT[k] > 0.0 &&
                    std::isfinite(s.dhTdh[k]) && std::isfinite(s.aOut[k]) &&
                    std::isfinite(s.phiF[k]) && std::isfinite(s.phiFs[k]) &&
                    std::isfinite(s.phiFp[k]) && std::isfinite(s.src[k]) &&
                    std::isfinite(s.capacity[k]) && s.tE[k] >= 0.0 && s.tN[k] >= 0.0 &&
                    (s.status[k] == detail::kFixed || s.diagP[k] > 0.0);
    if (!ok)
      fail(
          "problem.flowFactors returned factors that give a non-positive or non-finite "
          "coefficient at node ",
          k, " (pressure flow factors must be > 0, expected gap > 0)");
  }
}

}  // namespace

// Relative residual to which the coarser levels of a grid-sequenced cold start are solved.
constexpr double kCoarseTolerance = 1e-6;

struct FilmSolver::Impl {
  FilmSolverOptions options;
  detail::FilmSystem sys;
  detail::ActiveSetSolver fast;
  Eigen::MatrixXd derivRhs;
  // Gap derivatives: the perturbed problem and its system (sized once), and the squeeze part
  // of derivRhs for the post-processing.
  FilmProblem gapProblem;
  detail::FilmSystem gapSystem;
  Eigen::ArrayXd gapResidualPlus, perturbedGap;
  std::vector<NodeFlowFactors> perturbedFactors;
  // d(balance_k)/d(h_l) for l in node k's five-point stencil (self, E, W, N, S): row k, slot s.
  Eigen::Matrix<double, Eigen::Dynamic, 5> balanceGapJacobian;
  Eigen::MatrixXd squeezeDerivatives;
  detail::PostprocessWorkspace post;
  // Grid-sequenced cold start (ColdStartSequence.h): the coarser level, its own solver (which
  // sequences its cold start in turn) and the fine start interpolated from its solution.
  std::unique_ptr<detail::CoarseLevel> coarseLevel;
  std::unique_ptr<FilmSolver> coarseSolver;
  FilmResult coarseResult;
  FilmState sequencedStart;

  void initialiseIterate(const FilmProblem& pr, const FilmState* warm);
  // Columns first .. first + G - 1 of derivRhs: -d(balance)/d(u_g) at the solution for each
  // gap-basis column g, plus its squeeze part when pr has a gap-rate basis.
  void calcGapColumns(const FilmGrid& grid, const FilmProblem& pr, Eigen::Index first);
  // Column `col` of derivRhs for gap-basis column g by a central difference of two assemblies.
  void calcGapRhs(const FilmGrid& grid, const FilmProblem& pr, Eigen::Index g, Eigen::Index col);
  // balanceGapJacobian by five coloured one-sided perturbations of the gap (colour
  // (i + 2 j) mod 5: the five nodes of every stencil differ in colour). False when the grid's
  // periodic wrap breaks that (nx not a multiple of 5): the caller then takes calcGapRhs.
  bool calcBalanceGapJacobian(const FilmGrid& grid, const FilmProblem& pr);
  // The converged unknowns of sys into gapSystem (just assembled for a perturbed gap); its
  // fixed nodes keep their own values (an inflow edge's fill fraction depends on the gap).
  void loadSolutionIntoGapSystem();
  // -d(balance_k)/d(gap rate) per unit of basis column c: the squeeze term's coefficient.
  double squeezeRhs(const Eigen::MatrixXd& basis, int k, Eigen::Index c,
                    const Eigen::ArrayXd& area) const {
    return -sys.theta[k] * area[k] * sys.dhTdh[k] * basis(k, c);
  }
  void solve(const FilmGrid& grid, const FilmProblem& pr, const FilmState* warm, FilmResult& r);
};

void FilmSolver::Impl::initialiseIterate(const FilmProblem& pr, const FilmState* warm) {
  detail::FilmSystem& s = sys;
  double pSum = 0.0;
  int fixedCount = 0;
  for (int k = 0; k < s.n; ++k) {
    if (s.status[k] == detail::kFixed) {
      pSum += s.fixedPressure[k];
      ++fixedCount;
    }
  }
  double pInit = fixedCount > 0 ? pSum / fixedCount : 0.0;
  if (s.model != CavitationModel::None)
    pInit = std::max(pInit, s.pCav);
  const bool warmP = warm && warm->pressure_Pa.size() == s.n;
  const bool warmT = warm && warm->fillFraction.size() == s.n;
  const bool warmC = warm && static_cast<int>(warm->cavitated.size()) == s.n;
  const bool prevT = pr.history.last.fillFraction.size() == s.n;
  for (int k = 0; k < s.n; ++k) {
    if (s.status[k] == detail::kFixed) {
      s.p[k] = s.fixedPressure[k];
      s.theta[k] = s.fixedTheta[k];
      continue;
    }
    s.p[k] = warmP ? warm->pressure_Pa[k] : pInit;
    s.theta[k] = 1.0;
    bool cav = false;
    switch (s.model) {
      case CavitationModel::None:
        break;
      case CavitationModel::Reynolds:
        cav = warmC ? warm->cavitated[k] != 0 : s.p[k] <= s.pCav;
        break;
      case CavitationModel::MassConserving: {
        const double t = warmT ? warm->fillFraction[k] : (prevT ? pr.history.last.fillFraction[k] : 1.0);
        cav = warmC ? warm->cavitated[k] != 0 : t < 1.0;
        if (cav)
          s.theta[k] = std::clamp(t, 0.0, 1.0);
        break;
      }
    }
    if (cav)
      s.p[k] = s.pCav;
    if (s.model != CavitationModel::None)
      s.p[k] = std::max(s.p[k], s.pCav);
    s.status[k] = cav ? detail::kCav : detail::kFull;
  }
}

void FilmSolver::Impl::solve(const FilmGrid& grid, const FilmProblem& pr, const FilmState* warm,
                             FilmResult& res) {
  validate(grid, pr, warm);
  int coarseSteps = 0;
  if (!warm && options.gridSequencedColdStart && options.solver == FilmSolverType::FastActiveSet &&
      pr.cavitation != CavitationModel::None) {
    if (!coarseLevel)
      coarseLevel = std::make_unique<detail::CoarseLevel>();
    if (detail::makeCoarseLevel(grid, pr, *coarseLevel)) {
      if (!coarseSolver) {
        // A start only: the coarse film to 1e-6 (the active set it finds is what counts),
        // without the Gauss-Seidel fallback (a coarse level that does not settle is not used).
        FilmSolverOptions coarseOptions = options;
        coarseOptions.tolerance = std::max(options.tolerance, kCoarseTolerance);
        coarseOptions.fallbackToReference = false;
        coarseSolver = std::make_unique<FilmSolver>(coarseOptions);
      }
      coarseSolver->solve(*coarseLevel->grid, coarseLevel->problem, nullptr, coarseResult);
      coarseSteps = coarseResult.activeSetIterations + coarseResult.coarseActiveSetIterations;
      if (coarseResult.converged && !coarseResult.usedFallback) {
        detail::prolongState(*coarseLevel, coarseResult.state, grid.nx(), grid.ny(),
                             sequencedStart);
        warm = &sequencedStart;
      }
    }
  }
  sys.assemble(grid, pr);
  checkFactors(sys);
  initialiseIterate(pr, warm);

  detail::IterationReport rep;
  const int factorisations0 = fast.factorisations();
  const int krylov0 = fast.krylovIterations();
  const int mgBuilds0 = fast.multigridBuilds();
  res.usedFallback = false;
  res.derivativesFailed = false;
  res.activeSetIterations = 0;
  if (options.solver == FilmSolverType::ReferenceGaussSeidel) {
    rep = detail::gaussSeidelSolve(sys, options, options.maxSweeps);
    fast.invalidate();
  } else {
    rep = fast.solve(sys, options);
    res.activeSetIterations = rep.iterations;
    const bool finite = sys.p.allFinite() && sys.theta.allFinite();
    if (!finite) {
      // A failed factorisation must never leak into the result: restart from the initial guess.
      initialiseIterate(pr, nullptr);
      rep.converged = false;
    }
    if (!rep.converged && options.fallbackToReference) {
      const detail::IterationReport gs = detail::gaussSeidelSolve(sys, options, options.maxSweeps);
      rep.iterations += gs.iterations;
      rep.residual = gs.residual;
      rep.converged = gs.converged;
      res.usedFallback = true;
      fast.invalidate();
    } else if (!finite) {
      rep.residual = sys.relativeResidual();
    }
  }
  res.iterations = rep.iterations;
  res.coarseActiveSetIterations = coarseSteps;
  res.residual = rep.residual;
  res.converged = rep.converged;

  // Squeeze and gap derivatives by back-substitution with the final active set's Jacobian.
  const Eigen::Index m = pr.squeezeBasis.cols();
  const Eigen::Index g = pr.gapBasis.cols();
  if (m + g > 0) {
    derivRhs.resize(sys.n, m + g);
    const Eigen::ArrayXd& area = grid.areaWeights_m2();
    for (Eigen::Index c = 0; c < m; ++c)
      for (int k = 0; k < sys.n; ++k)
        derivRhs(k, c) = squeezeRhs(pr.squeezeBasis, k, c, area);
    if (g > 0)
      calcGapColumns(grid, pr, m);
    res.derivativesFailed = !fast.solveWithCurrentSet(sys, derivRhs, options.derivativeTolerance,
                                                      options.factoriseForManyDerivativeColumns);
    for (int k = 0; k < sys.n; ++k)
      if (sys.status[k] != detail::kFull)
        derivRhs.row(k).setZero();
  }
  if (g > 0) {
    res.dPressure_dGap = derivRhs.rightCols(g);
    squeezeDerivatives = derivRhs.leftCols(m);
  } else {
    res.dPressure_dGap.resize(0, 0);
  }
  res.factorisations = fast.factorisations() - factorisations0;
  res.krylovIterations = fast.krylovIterations() - krylov0;
  res.multigridBuilds = fast.multigridBuilds() - mgBuilds0;
  detail::postprocess(grid, pr, sys, m > 0 ? (g > 0 ? &squeezeDerivatives : &derivRhs) : nullptr,
                      post, res);
}

void FilmSolver::Impl::calcGapColumns(const FilmGrid& grid, const FilmProblem& pr,
                                      Eigen::Index first) {
  const Eigen::Index g = pr.gapBasis.cols();
  gapProblem = pr;  // once per call (same sizes after the first: no allocation)
  // The perturbed assemblies keep the solve's fill-fraction limiter factors
  // (FilmSystem::freezeFillLimiter): the coloured Jacobian needs five-point stencils.
  gapSystem.resizeFor(grid);
  gapSystem.fillLimitE = sys.fillLimitE;
  gapSystem.fillLimitN = sys.fillLimitN;
  gapSystem.freezeFillLimiter = true;
  if (calcBalanceGapJacobian(grid, pr)) {
    for (Eigen::Index c = 0; c < g; ++c)
      for (int k = 0; k < sys.n; ++k) {
        const int stencil[5] = {k, sys.nbE[k], sys.nbW[k], sys.nbN[k], sys.nbS[k]};
        double d = 0.0;
        for (int s = 0; s < 5; ++s)
          d += balanceGapJacobian(k, s) * pr.gapBasis(stencil[s], c);
        derivRhs(k, first + c) = -d;
      }
  } else {
    for (Eigen::Index c = 0; c < g; ++c)
      calcGapRhs(grid, pr, c, first + c);
  }
  // A coordinate that also moves the gap rate: its squeeze part in the same column.
  if (pr.gapRateBasis.cols() > 0) {
    const Eigen::ArrayXd& area = grid.areaWeights_m2();
    for (Eigen::Index c = 0; c < g; ++c)
      for (int k = 0; k < sys.n; ++k)
        derivRhs(k, first + c) += squeezeRhs(pr.gapRateBasis, k, c, area);
  }
}

void FilmSolver::Impl::loadSolutionIntoGapSystem() {
  for (int k = 0; k < sys.n; ++k) {
    const bool fixed = sys.status[k] == detail::kFixed;
    gapSystem.p[k] = fixed ? gapSystem.fixedPressure[k] : sys.p[k];
    gapSystem.theta[k] = fixed ? gapSystem.fixedTheta[k] : sys.theta[k];
  }
}

bool FilmSolver::Impl::calcBalanceGapJacobian(const FilmGrid& grid, const FilmProblem& pr) {
  const int nx = sys.nx, n = sys.n;
  if (sys.periodicX && nx % 5 != 0)
    return false;
  const auto colour = [nx](int k) { return (k % nx + 2 * (k / nx)) % 5; };
  balanceGapJacobian.resize(n, 5);
  balanceGapJacobian.setZero();
  // Relative step per node: one-sided truncation ~1e-6 of the h^3 terms, round-off ~1e-10.
  constexpr double kRelativeStep = 1e-6;
  // The flow factors at the perturbed gaps once for all nodes (the expensive, nodal part of an
  // assembly); each colour then takes them at its own nodes only.
  perturbedGap = pr.gap_m * (1.0 + kRelativeStep);
  sys.calcNodeFactors(pr, perturbedGap, perturbedFactors);
  gapSystem.nodeFactors.resize(static_cast<std::size_t>(n));
  for (int c = 0; c < 5; ++c) {
    for (int k = 0; k < n; ++k) {
      const bool moved = colour(k) == c;
      const auto uk = static_cast<std::size_t>(k);
      gapProblem.gap_m[k] = moved ? perturbedGap[k] : pr.gap_m[k];
      gapSystem.nodeFactors[uk] = moved ? perturbedFactors[uk] : sys.nodeFactors[uk];
    }
    gapSystem.assembleFromNodeFactors(grid, gapProblem);
    loadSolutionIntoGapSystem();
    for (int k = 0; k < n; ++k) {
      if (sys.status[k] == detail::kFixed)
        continue;
      // Against the unperturbed balance at the same unknowns (sys: the converged solve).
      const double change = gapSystem.residualAt(k) - sys.residualAt(k);
      const int stencil[5] = {k, sys.nbE[k], sys.nbW[k], sys.nbN[k], sys.nbS[k]};
      for (int s = 0; s < 5; ++s) {
        const int l = stencil[s];
        if ((s > 0 && l == k) || colour(l) != c)
          continue;  // no neighbour there (a missing one is the node itself), or not this colour
        balanceGapJacobian(k, s) = change / (kRelativeStep * pr.gap_m[l]);
      }
    }
  }
  return true;
}

void FilmSolver::Impl::calcGapRhs(const FilmGrid& grid, const FilmProblem& pr, Eigen::Index g,
                                  Eigen::Index col) {
  const double largest = pr.gapBasis.col(g).lpNorm<Eigen::Infinity>();
  if (!(largest > 0.0)) {
    derivRhs.col(col).setZero();
    return;
  }
  // Step: 1e-4 of the thinnest gap in units of the column (every perturbed gap stays >= 0.9999
  // of its own value: no sign change, the flow factors stay on their branch).
  const double step = 1e-4 * pr.gap_m.minCoeff() / largest;
  for (int sign : {1, -1}) {
    // gapProblem is the caller's copy of pr; only its gap differs (assemble reads no basis).
    gapProblem.gap_m = pr.gap_m + (sign * step) * pr.gapBasis.col(g).array();
    gapSystem.assemble(grid, gapProblem);
    loadSolutionIntoGapSystem();
    if (sign > 0) {
      gapResidualPlus.resize(sys.n);
      for (int k = 0; k < sys.n; ++k)
        gapResidualPlus[k] = sys.status[k] == detail::kFixed ? 0.0 : gapSystem.residualAt(k);
    } else {
      for (int k = 0; k < sys.n; ++k)
        derivRhs(k, col) = sys.status[k] == detail::kFixed
                               ? 0.0
                               : -(gapResidualPlus[k] - gapSystem.residualAt(k)) / (2.0 * step);
    }
  }
}

FilmSolver::FilmSolver(const FilmSolverOptions& options) : impl_(std::make_unique<Impl>()) {
  setOptions(options);
}
FilmSolver::~FilmSolver() = default;
FilmSolver::FilmSolver(FilmSolver&&) noexcept = default;
FilmSolver& FilmSolver::operator=(FilmSolver&&) noexcept = default;

const FilmSolverOptions& FilmSolver::getOptions() const {
  return impl_->options;
}

void FilmSolver::setOptions(const FilmSolverOptions& options) {
  validateOptions(options);
  impl_->options = options;
  impl_->coarseSolver.reset();  // made again with these options at the next cold start
}

void FilmSolver::solve(const FilmGrid& grid, const FilmProblem& problem, const FilmState* warmStart,
                       FilmResult& result) {
  impl_->solve(grid, problem, warmStart, result);
}

FilmResult FilmSolver::solve(const FilmGrid& grid, const FilmProblem& problem,
                             const FilmState* warmStart) {
  FilmResult r;
  solve(grid, problem, warmStart, r);
  return r;
}

}  // namespace pistondyn::lubrication
