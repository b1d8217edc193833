#include "pistondyn/skirt/ElasticCoupling.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "Checks.h"

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
                                                 const mapping::StructuralCompliance* liner,
                                                 const ElasticCouplingParameters& parameters) {
  if (!liner)
    return std::nullopt;
  const std::string where = std::string(kWhere) + " (liner StructuralCompliance)";
  if (parameters.scheme == ElasticCouplingScheme::Newton)
    detail::fail(where, "the liner needs the modal or the Aitken scheme (the Newton scheme's "
                        "preconditioner is built once for a fixed compliance)");
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
      startRelaxation_(parameters.initialRelaxation),
      linerGrid_(linerGridOf(side, liner, parameters)) {
  if (linerGrid_) {
    linerCompliance_m_per_N_ = liner->compliance_m_per_N;
    skirtCompliance_m_per_N_ = compliance_m_per_N_;
  }
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
  if (parameters_.scheme == ElasticCouplingScheme::Newton)
    setUpNewton();
  else if (parameters_.scheme == ElasticCouplingScheme::Modal)
    setUpModal();
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
  switch (parameters_.scheme) {
    case ElasticCouplingScheme::Newton:
      return solveNewton(film, cylinderPressure_Pa);
    case ElasticCouplingScheme::Modal:
      return solveModal(film, cylinderPressure_Pa);
    case ElasticCouplingScheme::Aitken:
      break;
  }
  return solveAitken(film, cylinderPressure_Pa);
}

ElasticCouplingReport ElasticCoupling::solveAitken(const FilmPressureFunction& film,
                                                   double cylinderPressure_Pa) {
  ElasticCouplingReport report;
  double omega = startRelaxation_;
  double previousResidualNorm_m = 0.0;
  while (report.iterations < parameters_.maxIterations) {
    evaluate(u_m_, film, cylinderPressure_Pa, target_m_, report);
    if (checkConvergence(report))
      break;
    // Keep the last iterate consistent with its pressure when giving up.
    if (report.iterations == parameters_.maxIterations)
      break;
    if (report.iterations > 1 &&
        report.residual_m > parameters_.residualGrowthLimit * previousResidualNorm_m &&
        omega > parameters_.minRelaxation) {
      // The last step overshot (e.g. it closed the gap into the asperities' steep range): back
      // to the previous iterate with a quarter of that step. The Aitken memory (the previous
      // residual) stays valid: the new step is again along it.
      omega = std::max(0.25 * omega, parameters_.minRelaxation);
      ++report.backtracks;
      u_m_ = previousU_m_ + omega * previousResidual_m_;
      continue;
    }
    if (report.iterations > 1) {
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

void ElasticCoupling::setUpNewton() {
  setUpNodeSets();
  const Eigen::Index ns = structural_.nodeCount();
  const int nS = int(nodesS_.size()), nF = int(nodesF_.size());
  complianceSF_.resize(nS, nF);
  for (int a = 0; a < nS; ++a)
    for (int b = 0; b < nF; ++b)
      complianceSF_(a, b) = compliance_m_per_N_(nodesS_[a], nodesF_[b]);
  stiffnessFS_ = Eigen::MatrixXd::Zero(nF, nS);
  preconditioner_ = Eigen::MatrixXd::Identity(nS, nS);
  preconditionerLu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(nS);
  const int kMax = parameters_.maxKrylovIterations;
  krylovV_ = Eigen::MatrixXd::Zero(nS, kMax + 1);
  krylovZ_ = Eigen::MatrixXd::Zero(nS, kMax);
  hessenberg_ = Eigen::MatrixXd::Zero(kMax + 1, kMax);
  givensC_ = givensS_ = Eigen::VectorXd::Zero(kMax);
  krylovG_ = Eigen::VectorXd::Zero(kMax + 1);
  krylovY_ = Eigen::VectorXd::Zero(kMax);
  vectorS_ = vectorS2_ = Eigen::VectorXd::Zero(nS);
  baseU_m_ = baseTarget_m_ = step_m_ = perturbedU_m_ = perturbedTarget_m_ =
      Eigen::VectorXd::Zero(ns);
}

void ElasticCoupling::factorPreconditioner() {
  const Eigen::ArrayXd& k = film_.pressureStiffness_Pa_per_m;
  if (k.size() != filmGrid_.nodeCount())
    detail::fail(kWhere, "the Newton scheme needs the film evaluation's pressureStiffness_Pa_per_m"
                         " (" + std::to_string(filmGrid_.nodeCount()) + " entries), got " +
                             std::to_string(k.size()));
  detail::requireFiniteEntries(kWhere, "film evaluation pressureStiffness_Pa_per_m", k.matrix(),
                               "Pa/m");
  // K_FS = M diag(k) H_S: the nodal force change per unit inward displacement (f = -M p,
  // h = h_rigid - H u, dp/dh = -k), and P = I + C_SF K_FS, the local Newton matrix.
  const auto& map = forceMap_.matrix();
  using RowIterator = Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator;
  stiffnessFS_.setZero();
  for (Eigen::Index a = 0; a < nodesF_.size(); ++a) {
    for (RowIterator m(map, nodesF_[a]); m; ++m) {
      const double w = m.value() * std::max(k[m.col()], 0.0);
      if (w == 0.0)
        continue;
      for (RowIterator h(hermiteS_, m.col()); h; ++h)
        stiffnessFS_(a, h.col()) += w * h.value();
    }
  }
  preconditioner_.setIdentity();
  preconditioner_.noalias() += complianceSF_ * stiffnessFS_;
  preconditionerLu_.compute(preconditioner_);
}

void ElasticCoupling::calcPreconditionedStep() {
  step_m_ = residual_m_;  // nodes outside S: the plain fixed-point step
  for (Eigen::Index a = 0; a < nodesS_.size(); ++a)
    vectorS_[a] = residual_m_[nodesS_[a]];
  vectorS2_ = preconditionerLu_.solve(vectorS_);
  for (Eigen::Index a = 0; a < nodesS_.size(); ++a)
    step_m_[nodesS_[a]] = vectorS2_[a];
}

void ElasticCoupling::calcKrylovStep(const FilmPressureFunction& film, double cylinderPressure_Pa,
                                     ElasticCouplingReport& report) {
  // Right-preconditioned GMRES (Saad & Schultz 1986) from d = 0 for J d = r_S with
  // J = I - dg/du on S, J z by a forward difference of the film around the base iterate:
  // J z = z - (g(u + eps z) - g(u)) / eps, eps z moving the gap by about 1e-3 of the thinnest
  // film (>= 1 nm): far above the film solver's noise, small against the film.
  const Eigen::Index nS = nodesS_.size();
  for (Eigen::Index a = 0; a < nS; ++a)
    vectorS_[a] = residual_m_[nodesS_[a]];
  const double beta = vectorS_.norm();
  step_m_ = residual_m_;  // nodes outside S: the plain fixed-point step
  for (Eigen::Index a = 0; a < nS; ++a)
    step_m_[nodesS_[a]] = 0.0;
  if (!(beta > 0.0))
    return;
  const double probe_m =
      parameters_.absoluteTolerance_m + 1e-3 * std::max(film_.minFilmThickness_m, 1e-6);
  krylovV_.col(0) = vectorS_ / beta;
  krylovG_.setZero();
  krylovG_[0] = beta;
  int used = 0;
  for (int j = 0; j < parameters_.maxKrylovIterations &&
                  report.iterations < parameters_.maxIterations - 1;
       ++j) {
    krylovZ_.col(j) = preconditionerLu_.solve(krylovV_.col(j));
    const double zMax = krylovZ_.col(j).cwiseAbs().maxCoeff();
    if (!(zMax > 0.0))
      break;
    const double eps = probe_m / zMax;
    perturbedU_m_ = baseU_m_;
    for (Eigen::Index a = 0; a < nS; ++a)
      perturbedU_m_[nodesS_[a]] += eps * krylovZ_(a, j);
    evaluate(perturbedU_m_, film, cylinderPressure_Pa, perturbedTarget_m_, report);
    ++report.krylovIterations;
    for (Eigen::Index a = 0; a < nS; ++a)
      vectorS2_[a] = krylovZ_(a, j) -
                     (perturbedTarget_m_[nodesS_[a]] - baseTarget_m_[nodesS_[a]]) / eps;
    // Arnoldi (modified Gram-Schmidt) and the Givens rotations of the least-squares problem.
    for (int i = 0; i <= j; ++i) {
      hessenberg_(i, j) = krylovV_.col(i).dot(vectorS2_);
      vectorS2_ -= hessenberg_(i, j) * krylovV_.col(i);
    }
    hessenberg_(j + 1, j) = vectorS2_.norm();
    for (int i = 0; i < j; ++i) {
      const double t = givensC_[i] * hessenberg_(i, j) + givensS_[i] * hessenberg_(i + 1, j);
      hessenberg_(i + 1, j) = -givensS_[i] * hessenberg_(i, j) + givensC_[i] * hessenberg_(i + 1, j);
      hessenberg_(i, j) = t;
    }
    const double rho = std::hypot(hessenberg_(j, j), hessenberg_(j + 1, j));
    if (!(rho > 0.0 && std::isfinite(rho)))
      break;  // J z_j adds nothing (or the film evaluation was not finite): leave it out
    used = j + 1;
    givensC_[j] = hessenberg_(j, j) / rho;
    givensS_[j] = hessenberg_(j + 1, j) / rho;
    hessenberg_(j, j) = rho;
    krylovG_[j + 1] = -givensS_[j] * krylovG_[j];
    krylovG_[j] *= givensC_[j];
    if (std::abs(krylovG_[j + 1]) <= parameters_.krylovTolerance * beta)
      break;
    if (j + 1 < parameters_.maxKrylovIterations) {
      // The next basis vector: the orthogonalised J z before the rotations.
      const double h = vectorS2_.norm();
      if (!(h > 0.0))
        break;
      krylovV_.col(j + 1) = vectorS2_ / h;
    }
  }
  // y = R^-1 g, d_S = Z y.
  for (int i = used - 1; i >= 0; --i) {
    double v = krylovG_[i];
    for (int c = i + 1; c < used; ++c)
      v -= hessenberg_(i, c) * krylovY_[c];
    krylovY_[i] = v / hessenberg_(i, i);
  }
  if (used == 0) {
    // No Krylov direction (a degenerate first product): the preconditioner's own step.
    calcPreconditionedStep();
    return;
  }
  for (Eigen::Index a = 0; a < nS; ++a) {
    double v = 0.0;
    for (int i = 0; i < used; ++i)
      v += krylovZ_(a, i) * krylovY_[i];
    step_m_[nodesS_[a]] = v;
  }
}

ElasticCouplingReport ElasticCoupling::solveNewton(const FilmPressureFunction& film,
                                                   double cylinderPressure_Pa) {
  // Globalised inexact Newton (e.g. Kelley 1995, ch. 8) on r(u) = g(u) - u, g(u) = C f(u):
  // the step d solves (I - dg/du) d = r approximately; first the preconditioner's own step
  // (P^-1 r, no extra film evaluation), and GMRES once that step reduces the residual by less
  // than half. Each step is tried at lambda = 1, 1/4, 1/16 until the residual's 2-norm on the
  // nodes that move the gap falls (Armijo, 1e-4); the film evaluation of the accepted trial is
  // the next base.
  const Eigen::Index nS = nodesS_.size();
  const auto normS = [&](const Eigen::VectorXd& r) {
    double s = 0.0;
    for (Eigen::Index a = 0; a < nS; ++a)
      s += r[nodesS_[a]] * r[nodesS_[a]];
    return std::sqrt(s);
  };
  ElasticCouplingReport report;
  evaluate(u_m_, film, cylinderPressure_Pa, target_m_, report);
  bool krylov = false;
  while (true) {
    if (checkConvergence(report))
      break;
    if (report.iterations >= parameters_.maxIterations)
      break;
    // The base of this Newton step: its iterate, target and the preconditioner at its film.
    baseU_m_ = u_m_;
    baseTarget_m_ = target_m_;
    const double baseNorm = normS(residual_m_);
    factorPreconditioner();
    if (krylov)
      calcKrylovStep(film, cylinderPressure_Pa, report);
    else
      calcPreconditionedStep();
    bool accepted = false;
    double lambda = 1.0, trialNorm = 0.0;
    for (int ls = 0; ls < 3 && report.iterations < parameters_.maxIterations; ++ls) {
      u_m_ = baseU_m_ + lambda * step_m_;
      evaluate(u_m_, film, cylinderPressure_Pa, target_m_, report);
      residual_m_ = target_m_ - u_m_;
      trialNorm = normS(residual_m_);
      if (trialNorm <= (1.0 - 1e-4 * lambda) * baseNorm) {
        accepted = true;
        break;
      }
      ++report.backtracks;
      lambda *= 0.25;
    }
    if (accepted) {
      ++report.newtonSteps;
      if (!krylov && trialNorm > 0.5 * baseNorm)
        krylov = true;  // the local stiffness misses too much of the film: GMRES from now on
      continue;
    }
    if (!krylov) {
      // The preconditioner's step failed: retake this step with GMRES from the base. Its
      // film must be evaluated again (the trials replaced it).
      krylov = true;
      u_m_ = baseU_m_;
      if (report.iterations >= parameters_.maxIterations)
        break;
      evaluate(u_m_, film, cylinderPressure_Pa, target_m_, report);
      continue;
    }
    // GMRES's step failed too: keep the last (shortest) trial, which is the evaluated state,
    // and go on from there.
  }
  report.relaxation = 1.0;
  if (report.converged)
    start_m_ = u_m_;
  return report;
}

}  // namespace pistondyn::skirt
