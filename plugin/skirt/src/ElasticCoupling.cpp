#include "pistondyn/skirt/ElasticCoupling.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "Checks.h"

namespace pistondyn::skirt {
namespace {

constexpr const char* kWhere = "ElasticCoupling";
constexpr const char* kParams = "ElasticCouplingParameters";

void checkParameters(const ElasticCouplingParameters& p) {
  detail::requireNonNegative(kParams, "absoluteTolerance_m", p.absoluteTolerance_m, "m");
  detail::requireNonNegative(kParams, "relativeTolerance", p.relativeTolerance, "");
  if (p.absoluteTolerance_m == 0.0 && p.relativeTolerance == 0.0)
    detail::fail(kParams,
                 "absoluteTolerance_m and relativeTolerance are both 0: the coupling "
                 "could never converge");
  if (p.maxIterations < 1)
    detail::fail(kParams,
                 "maxIterations = " + std::to_string(p.maxIterations) + " must be at least 1");
  const auto factor = [](const char* name, double v) {
    if (!(std::isfinite(v) && v > 0.0 && v <= 1.0))
      detail::fail(kParams, detail::named(name, v, "") + " must be in (0, 1]");
  };
  factor("initialRelaxation", p.initialRelaxation);
  factor("minRelaxation", p.minRelaxation);
  factor("maxRelaxation", p.maxRelaxation);
  if (!(std::isfinite(p.residualGrowthLimit) && p.residualGrowthLimit >= 1.0))
    detail::fail(kParams, detail::named("residualGrowthLimit", p.residualGrowthLimit, "") +
                              " must be finite and at least 1");
  if (p.minRelaxation > p.maxRelaxation)
    detail::fail(kParams, detail::named("minRelaxation", p.minRelaxation, "") +
                              " must not exceed " +
                              detail::named("maxRelaxation", p.maxRelaxation, ""));
}

// The structural grid of the compliance, after its own checks (CylinderGrid checks the nodes).
mapping::CylinderGrid structuralGrid(const SkirtSideGrid& side,
                                     const mapping::StructuralCompliance& c) {
  const std::string where = std::string(kWhere) + " (StructuralCompliance)";
  if (c.nPhi() < 2 || c.nY() < 2)
    detail::fail(where, "the structural grid has " + std::to_string(c.nPhi()) + " x " +
                            std::to_string(c.nY()) +
                            " nodes (phi_rad x y_m), at least 2 x 2 "
                            "needed");
  const Eigen::Index n = c.nodeCount();
  if (c.compliance_m_per_N.rows() != n || c.compliance_m_per_N.cols() != n)
    detail::fail(where, "compliance_m_per_N is " + std::to_string(c.compliance_m_per_N.rows()) +
                            " x " + std::to_string(c.compliance_m_per_N.cols()) +
                            " but the grid has " + std::to_string(c.nPhi()) + " x " +
                            std::to_string(c.nY()) + " = " + std::to_string(n) +
                            " nodes: expected " + std::to_string(n) + " x " + std::to_string(n));
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      if (!std::isfinite(c.compliance_m_per_N(i, j)))
        detail::fail(where, "compliance_m_per_N(" + std::to_string(i) + ", " + std::to_string(j) +
                                ") = " + detail::str(c.compliance_m_per_N(i, j)) +
                                " must be finite");
  if (c.hasGasDisplacement()) {
    if (c.gasDisplacement_m_per_Pa.size() != n)
      detail::fail(where, "gasDisplacement_m_per_Pa has " +
                              std::to_string(c.gasDisplacement_m_per_Pa.size()) +
                              " entries, expected " + std::to_string(n) +
                              " (one per structural node) or none");
    detail::requireFiniteEntries(where, "gasDisplacement_m_per_Pa", c.gasDisplacement_m_per_Pa,
                                 "m/Pa");
  }
  // The skirt radius: the compliance is per radial force, independent of the grid's radius;
  // the side's radius keeps the developed lengths of both grids equal.
  return c.fullCircle ? mapping::CylinderGrid::fullCircle(side.getRadius_m(), c.phi_rad, c.y_m)
                      : mapping::CylinderGrid::sector(side.getRadius_m(), c.phi_rad, c.y_m);
}

// The film grid must lie on the structure: forces outside it would be lost (ForceMap reports
// them) and the deformation there would be extrapolated.
const mapping::CylinderGrid& checkedCoverage(const SkirtSideGrid& side,
                                             const mapping::CylinderGrid& s) {
  const auto& y = side.getYNodes_m();
  const double yLo = s.y_m()[0], yHi = s.y_m()[s.nY() - 1];
  const double slack = 1e-9 * (yHi - yLo);
  if (y[0] < yLo - slack || y[y.size() - 1] > yHi + slack)
    detail::fail(kWhere, "the skirt side's heights [" + detail::str(y[0]) + ", " +
                             detail::str(y[y.size() - 1]) +
                             "] m reach outside the structural grid's heights [" +
                             detail::str(yLo) + ", " + detail::str(yHi) +
                             "] m: the compliance must cover the film grid");
  if (!s.isClosed()) {
    // A sector: the side's absolute angles, taken on the turn of the sector's start.
    constexpr double twoPi = 6.283185307179586476925286766559;
    const auto& phi = side.getPhiNodes_rad();
    const double p0 = s.phi_rad()[0], p1 = s.phiEnd_rad();
    const double shift = twoPi * std::floor((phi[0] - p0) / twoPi);
    const double slackPhi = 1e-9 * (p1 - p0);
    if (phi[0] - shift < p0 - slackPhi || phi[phi.size() - 1] - shift > p1 + slackPhi)
      detail::fail(kWhere, "the skirt side's angles [" + detail::str(phi[0]) + ", " +
                               detail::str(phi[phi.size() - 1]) +
                               "] rad reach outside the structural sector [" + detail::str(p0) +
                               ", " + detail::str(p1) + "] rad");
  }
  return side.getCylinderGrid();
}

}  // namespace

ElasticCoupling::ElasticCoupling(const SkirtSideGrid& side,
                                 const mapping::StructuralCompliance& skirt,
                                 const ElasticCouplingParameters& parameters)
    : parameters_((checkParameters(parameters), parameters)),
      filmGrid_(side.getCylinderGrid()),
      structural_(structuralGrid(side, skirt)),
      compliance_m_per_N_(skirt.compliance_m_per_N),
      gas_m_per_Pa_(skirt.gasDisplacement_m_per_Pa),
      forceMap_(checkedCoverage(side, structural_), structural_, {0.0, 0.0}),
      surface_(structural_, Eigen::VectorXd::Zero(structural_.nodeCount())),
      start_m_(Eigen::VectorXd::Zero(structural_.nodeCount())),
      startRelaxation_(parameters.initialRelaxation) {
  const Eigen::Index ns = structural_.nodeCount(), nf = filmGrid_.nodeCount();
  u_m_ = Eigen::VectorXd::Zero(ns);
  force_N_ = Eigen::VectorXd::Zero(ns);
  target_m_ = Eigen::VectorXd::Zero(ns);
  residual_m_ = Eigen::VectorXd::Zero(ns);
  previousResidual_m_ = Eigen::VectorXd::Zero(ns);
  previousU_m_ = Eigen::VectorXd::Zero(ns);
  residualFilm_m_ = Eigen::VectorXd::Zero(nf);
  uFilm_m_ = Eigen::VectorXd::Zero(nf);
  pistonElastic_m_ = Eigen::ArrayXd::Zero(nf);
  film_.normalPressure_Pa = Eigen::ArrayXd::Zero(nf);
}

void ElasticCoupling::toFilmGrid(const Eigen::VectorXd& structural,
                                 Eigen::Ref<Eigen::VectorXd> film) {
  surface_.updateValues(structural);
  // The coverage check allows 1e-9 of the range outside; the surface clamps within 1e-12 only,
  // so the end cells are extended over that sliver.
  surface_.evaluateOnGrid(filmGrid_, {0.0, 0.0}, film, hermiteWs_,
                          mapping::OutsidePolicy::ExtendEndCells);
}

void ElasticCoupling::setStart(const Eigen::Ref<const Eigen::VectorXd>& structuralDisplacement_m) {
  detail::requireSameSize(kWhere, "setStart(structuralDisplacement_m)",
                          structuralDisplacement_m.size(), "the structural grid's nodes",
                          structural_.nodeCount());
  detail::requireFiniteEntries(kWhere, "setStart(structuralDisplacement_m)",
                               structuralDisplacement_m, "m");
  start_m_ = structuralDisplacement_m;
}

void ElasticCoupling::resetWarmStart() {
  start_m_.setZero();
  startRelaxation_ = parameters_.initialRelaxation;
}

ElasticCouplingReport ElasticCoupling::solve(const FilmPressureFunction& film,
                                             double cylinderPressure_Pa) {
  detail::requireFinite(kWhere, "solve(cylinderPressure_Pa)", cylinderPressure_Pa, "Pa");
  if (!film)
    detail::fail(kWhere, "solve(film): the film evaluation is empty");
  const Eigen::Index nf = filmGrid_.nodeCount();
  const bool gas = gas_m_per_Pa_.size() > 0;

  ElasticCouplingReport report;
  double omega = startRelaxation_;
  double previousResidualNorm_m = 0.0;
  u_m_ = start_m_;
  for (int it = 1; it <= parameters_.maxIterations; ++it) {
    report.iterations = it;
    // 1-2: the gap term of the current deformation and the film's pressure for it.
    toFilmGrid(u_m_, uFilm_m_);
    pistonElastic_m_ = -uFilm_m_.array();
    film(pistonElastic_m_, film_);
    if (film_.normalPressure_Pa.size() != nf)
      detail::fail(kWhere, "the film evaluation returned normalPressure_Pa with " +
                               std::to_string(film_.normalPressure_Pa.size()) +
                               " entries, expected " + std::to_string(nf) + " (one per film node)");
    detail::requireFiniteEntries(kWhere, "film evaluation normalPressure_Pa",
                                 film_.normalPressure_Pa.matrix(), "Pa");
    detail::requireFinite(kWhere, "film evaluation minFilmThickness_m", film_.minFilmThickness_m,
                          "m");

    // 3-4: nodal forces (+ outward: the pressure pushes inwards) and the displacement they give.
    const mapping::LoadBalance balance =
        forceMap_.apply(film_.normalPressure_Pa.matrix(), force_N_);
    force_N_ = -force_N_;
    target_m_.noalias() = compliance_m_per_N_ * force_N_;
    if (gas)
      target_m_ += cylinderPressure_Pa * gas_m_per_Pa_;
    report.pistonForce_N = balance.sourceTotal_N;
    report.unmapped_N = balance.unmapped_N;
    report.structureForce_N = force_N_.sum();
    report.maxDeformation_m = pistonElastic_m_.abs().maxCoeff();

    // 5: the change a plain fixed-point step would make, measured on the film grid.
    residual_m_ = target_m_ - u_m_;
    toFilmGrid(residual_m_, residualFilm_m_);
    report.residual_m = residualFilm_m_.cwiseAbs().maxCoeff();
    report.tolerance_m =
        std::max(parameters_.absoluteTolerance_m,
                 parameters_.relativeTolerance * std::max(film_.minFilmThickness_m, 0.0));
    if (report.residual_m <= report.tolerance_m) {
      report.converged = true;
      break;
    }
    // Keep the last iterate consistent with its pressure when giving up.
    if (it == parameters_.maxIterations)
      break;
    if (it > 1 && report.residual_m > parameters_.residualGrowthLimit * previousResidualNorm_m &&
        omega > parameters_.minRelaxation) {
      // The last step overshot (e.g. it closed the gap into the asperities' steep range): back
      // to the previous iterate with a quarter of that step. The Aitken memory (the previous
      // residual) stays valid: the new step is again along it.
      omega = std::max(0.25 * omega, parameters_.minRelaxation);
      ++report.backtracks;
      u_m_ = previousU_m_ + omega * previousResidual_m_;
      continue;
    }
    if (it > 1) {
      // Aitken: the secant estimate of the best factor along the last residual change
      // (target_m_ is free now: scratch for r_k - r_{k-1}).
      target_m_ = residual_m_ - previousResidual_m_;
      const double den = target_m_.squaredNorm();
      if (den > 0.0)
        omega = -omega * previousResidual_m_.dot(target_m_) / den;
      omega = std::clamp(omega, parameters_.minRelaxation, parameters_.maxRelaxation);
    }
    previousResidual_m_ = residual_m_;
    previousResidualNorm_m = report.residual_m;
    previousU_m_ = u_m_;
    u_m_ += omega * residual_m_;
  }
  report.relaxation = omega;
  if (report.converged) {
    start_m_ = u_m_;
    startRelaxation_ = omega;
  }
  return report;
}

}  // namespace pistondyn::skirt
