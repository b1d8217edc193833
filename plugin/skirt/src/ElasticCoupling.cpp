#include "pistondyn/skirt/ElasticCoupling.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "Checks.h"
#include "pistondyn/skirt/AitkenCoupling.h"
#include "pistondyn/skirt/ModalCoupling.h"
#include "pistondyn/skirt/NewtonCoupling.h"

namespace pistondyn::skirt {
namespace {

constexpr const char* kWhere = "ElasticCoupling";
constexpr const char* kParams = "ElasticCouplingParameters";

void checkParameters(const ElasticCouplingParameters& p) {
  detail::requireNonNegative(kParams, "absoluteTolerance_m", p.absoluteTolerance_m, "m");
  detail::requireNonNegative(kParams, "relativeTolerance", p.relativeTolerance, "");
  detail::requireNonNegative(kParams, "deformationRelativeTolerance",
                             p.deformationRelativeTolerance, "");
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
  if (p.maxKrylovIterations < 1 || p.maxKrylovIterations > 50)
    detail::fail(kParams, "maxKrylovIterations = " + std::to_string(p.maxKrylovIterations) +
                              " must be in 1 ... 50");
  if (!(std::isfinite(p.krylovTolerance) && p.krylovTolerance > 0.0 && p.krylovTolerance < 1.0))
    detail::fail(kParams,
                 detail::named("krylovTolerance", p.krylovTolerance, "") + " must be in (0, 1)");
  if (p.modes < 1)
    detail::fail(kParams, "modes = " + std::to_string(p.modes) + " must be at least 1");
  if (p.modalJacobianReuse < 0)
    detail::fail(kParams, "modalJacobianReuse = " + std::to_string(p.modalJacobianReuse) +
                              " must be 0 or positive");
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

// The liner's grid after its checks (the liner frame; the side's radius, as the skirt's).
std::optional<mapping::CylinderGrid> linerGridOf(const SkirtSideGrid& side,
                                                 const mapping::StructuralCompliance* liner) {
  if (!liner)
    return std::nullopt;
  const std::string where = std::string(kWhere) + " (liner StructuralCompliance)";
  if (!liner->fullCircle)
    detail::fail(where, "the liner's structural grid must be a full circle (its loaded area "
                        "turns with no side: the node table's angles must close the ring)");
  if (liner->hasGasDisplacement())
    detail::fail(where, "the liner has a gas field: only the skirt's is applied (remove the "
                        "liner node table's gas column)");
  // The skirt's checks (sizes, finite entries) apply as they are.
  return structuralGrid(side, *liner);
}

}  // namespace

ElasticCoupling::ElasticCoupling(const SkirtSideGrid& side,
                                 const mapping::StructuralCompliance& skirt,
                                 const ElasticCouplingParameters& parameters,
                                 const mapping::StructuralCompliance* liner)
    : parameters_((checkParameters(parameters), parameters)),
      filmGrid_(side.getCylinderGrid()),
      structural_(structuralGrid(side, skirt)),
      compliance_m_per_N_(skirt.compliance_m_per_N),
      gas_m_per_Pa_(skirt.gasDisplacement_m_per_Pa),
      forceMap_(checkedCoverage(side, structural_), structural_, {0.0, 0.0}),
      surface_(structural_, Eigen::VectorXd::Zero(structural_.nodeCount())),
      start_m_(Eigen::VectorXd::Zero(structural_.nodeCount())),
      linerGrid_(linerGridOf(side, liner)) {
  if (linerGrid_) {
    linerCompliance_m_per_N_ = liner->compliance_m_per_N;
    skirtCompliance_m_per_N_ = compliance_m_per_N_;
  }
  const Eigen::Index ns = structural_.nodeCount(), nf = filmGrid_.nodeCount();
  u_m_ = Eigen::VectorXd::Zero(ns);
  force_N_ = Eigen::VectorXd::Zero(ns);
  target_m_ = Eigen::VectorXd::Zero(ns);
  residual_m_ = Eigen::VectorXd::Zero(ns);
  residualFilm_m_ = Eigen::VectorXd::Zero(nf);
  uFilm_m_ = Eigen::VectorXd::Zero(nf);
  pistonElastic_m_ = Eigen::ArrayXd::Zero(nf);
  film_.normalPressure_Pa = Eigen::ArrayXd::Zero(nf);
}

ElasticCoupling::~ElasticCoupling() = default;

std::unique_ptr<ElasticCoupling> makeElasticCoupling(const SkirtSideGrid& side,
                                                     const mapping::StructuralCompliance& skirt,
                                                     const ElasticCouplingParameters& parameters,
                                                     const mapping::StructuralCompliance* liner) {
  switch (parameters.scheme) {
    case ElasticCouplingScheme::Aitken:
      return std::make_unique<AitkenCoupling>(side, skirt, parameters, liner);
    case ElasticCouplingScheme::Newton:
      if (liner)
        detail::fail(std::string(kWhere) + " (liner StructuralCompliance)",
                     "the liner needs the modal or the Aitken scheme (the Newton scheme's "
                     "preconditioner is built once for a fixed compliance)");
      return std::make_unique<NewtonCoupling>(side, skirt, parameters);
    case ElasticCouplingScheme::Modal:
      break;
  }
  return std::make_unique<ModalCoupling>(side, skirt, parameters, liner);
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
}

void ElasticCoupling::evaluate(const Eigen::VectorXd& u, const FilmPressureFunction& film,
                               double cylinderPressure_Pa, Eigen::VectorXd& target,
                               ElasticCouplingReport& report) {
  const Eigen::Index nf = filmGrid_.nodeCount();
  ++report.iterations;
  // 1-2: the gap term of the deformation and the film's pressure for it.
  toFilmGrid(u, uFilm_m_);
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
  const mapping::LoadBalance balance = forceMap_.apply(film_.normalPressure_Pa.matrix(), force_N_);
  force_N_ = -force_N_;
  target.noalias() = compliance_m_per_N_ * force_N_;
  if (gas_m_per_Pa_.size() > 0)
    target += cylinderPressure_Pa * gas_m_per_Pa_;
  report.pistonForce_N = balance.sourceTotal_N;
  report.unmapped_N = balance.unmapped_N;
  report.structureForce_N = force_N_.sum();
  report.maxDeformation_m = pistonElastic_m_.abs().maxCoeff();
}

double ElasticCoupling::filmGridNorm(const Eigen::VectorXd& residual) {
  toFilmGrid(residual, residualFilm_m_);
  return residualFilm_m_.cwiseAbs().maxCoeff();
}

bool ElasticCoupling::judgeResidual(double residual_m, ElasticCouplingReport& report) const {
  report.residual_m = residual_m;
  report.tolerance_m =
      std::max(parameters_.absoluteTolerance_m,
               std::max(parameters_.relativeTolerance * std::max(film_.minFilmThickness_m, 0.0),
                        parameters_.deformationRelativeTolerance * report.maxDeformation_m));
  report.converged = report.residual_m <= report.tolerance_m;
  return report.converged;
}

bool ElasticCoupling::checkConvergence(ElasticCouplingReport& report) {
  // 5: the change a plain fixed-point step would make, measured on the film grid.
  residual_m_ = target_m_ - u_m_;
  return judgeResidual(filmGridNorm(residual_m_), report);
}

ElasticCouplingReport ElasticCoupling::solve(const FilmPressureFunction& film,
                                             double cylinderPressure_Pa) {
  detail::requireFinite(kWhere, "solve(cylinderPressure_Pa)", cylinderPressure_Pa, "Pa");
  if (!film)
    detail::fail(kWhere, "solve(film): the film evaluation is empty");
  if (linerGrid_ && !std::isfinite(linerPinHeight_m_))
    detail::fail(kWhere, "solve(): the coupling has a liner but no position: call "
                         "setLinerPosition(pinHeight_m) first");
  u_m_ = start_m_;
  return iterate(film, cylinderPressure_Pa);
}

void localPressureStiffness(const Eigen::Ref<const Eigen::ArrayXd>& normalPressure_Pa,
                            const Eigen::Ref<const Eigen::ArrayXd>& asperityPressure_Pa,
                            const Eigen::Ref<const Eigen::ArrayXd>& filmGap_m,
                            const Eigen::Ref<const Eigen::ArrayXd>& asperitySlope_PaPerM,
                            double hFloor_m, Eigen::ArrayXd& stiffness_Pa_per_m) {
  const Eigen::Index n = normalPressure_Pa.size();
  if (asperityPressure_Pa.size() != n || filmGap_m.size() != n || asperitySlope_PaPerM.size() != n)
    detail::fail("localPressureStiffness",
                 "normalPressure_Pa, asperityPressure_Pa, filmGap_m and asperitySlope_PaPerM "
                 "must have equal sizes");
  if (!(std::isfinite(hFloor_m) && hFloor_m > 0.0))
    detail::fail("localPressureStiffness",
                 detail::named("hFloor_m", hFloor_m, "m") + " must be finite and > 0");
  stiffness_Pa_per_m.resize(n);
  stiffness_Pa_per_m = 3.0 * (normalPressure_Pa - asperityPressure_Pa).max(0.0) /
                           filmGap_m.max(hFloor_m) +
                       (-asperitySlope_PaPerM).max(0.0);
}

void ElasticCoupling::setUpNodeSets() {
  const Eigen::Index ns = structural_.nodeCount(), nf = filmGrid_.nodeCount();
  // The Hermite interpolant is linear in the nodal values: its columns are the images of the
  // unit vectors. The spline slopes spread a node's influence along its row and column,
  // decaying about 0.27 per node; entries below 1e-9 are dropped.
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<int> localS(ns, -1);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(ns), column(nf);
  int nS = 0;
  for (Eigen::Index j = 0; j < ns; ++j) {
    unit[j] = 1.0;
    toFilmGrid(unit, column);
    unit[j] = 0.0;
    for (Eigen::Index n = 0; n < nf; ++n) {
      if (std::abs(column[n]) <= 1e-9)
        continue;
      if (localS[j] < 0)
        localS[j] = nS++;
      entries.emplace_back(int(n), localS[j], column[n]);
    }
  }
  nodesS_.resize(nS);
  for (Eigen::Index j = 0; j < ns; ++j)
    if (localS[j] >= 0)
      nodesS_[localS[j]] = int(j);
  hermiteS_.resize(nf, nS);
  hermiteS_.setFromTriplets(entries.begin(), entries.end());
  const auto& map = forceMap_.matrix();
  std::vector<int> rowsF;
  for (Eigen::Index i = 0; i < ns; ++i)
    if (map.outerIndexPtr()[i + 1] > map.outerIndexPtr()[i])
      rowsF.push_back(int(i));
  const int nF = int(rowsF.size());
  nodesF_ = Eigen::Map<Eigen::VectorXi>(rowsF.data(), nF);
}

}  // namespace pistondyn::skirt
