// ModalCoupling.h: the deformation in the largest modes of the side's compliance, Newton with
// the film's exact derivatives of the modal shapes.

#include "pistondyn/skirt/ModalCoupling.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "Checks.h"

namespace pistondyn::skirt {
namespace {
constexpr const char* kWhere = "ElasticCoupling (modal)";
// Backtracking trials per Newton step (1, 1/4, ..., 1/4^5): near a slap the local stiffness
// underestimates the asperities' growth by up to ~100x and the full step overshoots.
constexpr int kLineSearchTrials = 6;
// Jacobian reuse: a kept Jacobian serves only after a solve of at most this many film
// evaluations. On a film where the Newton iteration itself needs many (a thin, closing film:
// 8-9 from a converged start 20 nm away), a kept Jacobian's first step is poor enough to
// triple the evaluations (tests/skirt: KeptModalJacobianReachesTheSameDeformations).
constexpr int kEasySolve = 2;
}  // namespace

ModalCoupling::ModalCoupling(const SkirtSideGrid& side, const mapping::StructuralCompliance& skirt,
                             const ElasticCouplingParameters& parameters,
                             const mapping::StructuralCompliance* liner)
    : ElasticCoupling(side, skirt, parameters, liner) {
  setUpNodeSets();
  calcModes();
  const Eigen::Index ns = structural_.nodeCount();
  const int m = modeCount();
  modal_m_ = modalResidual_m_ = modalStep_m_ = modalBase_m_ = Eigen::VectorXd::Zero(m);
  gasU_m_ = Eigen::VectorXd::Zero(ns);
  modalForce_N_ = Eigen::MatrixXd::Zero(ns, m);
  modalJacobian_ = Eigen::MatrixXd::Zero(m, m);
  modalLu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(m);  // sized once: no allocation per step
}

void ModalCoupling::prepareRate(double rateStep_s) {
  rateStep_s_ = rateStep_s;
  if (rateStep_s > 0.0)  // d(dh_el/dt)/dw_j = -Psi_j / dt through the backward-Euler rate
    rateBasis_ = (-1.0 / rateStep_s) * modalShapes_;
  // d h_el / d w_j = -Psi_j: constant, but the liner moves the shapes with the piston.
  if (parameters_.exactStaticDerivative && (gapBasis_.cols() != modeCount() || hasLiner()))
    gapBasis_ = -modalShapes_;
}

FilmSensitivityRequest ModalCoupling::getFilmRequest(bool sensitivitiesWanted) const {
  // With the exact static derivative the gap columns carry the rate's squeeze part too (gap-
  // rate basis -Psi_j / dt): the film returns the total dp/dw_j in one back-substitution per mode.
  const bool rate = sensitivitiesWanted && rateStep_s_ > 0.0;
  const bool exact = parameters_.exactStaticDerivative;
  FilmSensitivityRequest r;
  r.squeezeBasis = rate && !exact ? &rateBasis_ : nullptr;
  r.gapRateBasis = rate && exact ? &rateBasis_ : nullptr;
  r.gapBasis = sensitivitiesWanted && exact ? &gapBasis_ : nullptr;
  return r;
}

void ModalCoupling::readFilm(const SkirtSideResults& side, const GapFields& /*gap*/,
                             double compositeSigma_m, FilmPressureEvaluation& out) const {
  const Eigen::Index n = side.normalPressure_Pa.size();
  const Eigen::Map<const Eigen::ArrayXd> pc(side.contact.pressure_Pa.data(), n);
  const Eigen::Map<const Eigen::ArrayXd> slope(side.contact.dPressure_dGap_PaPerM.data(), n);
  const bool sensitivities = out.sensitivitiesWanted;
  if (parameters_.exactStaticDerivative) {
    // The film's part is exact (with the rate's squeeze part when the rate is implicit); the
    // asperities' own slope is what it lacks.
    out.pressureStiffness_Pa_per_m = (-slope).max(0.0);
    if (sensitivities)
      out.pressureGapSensitivity_Pa_per_m = side.film.dPressure_dGap;
    else
      out.pressureGapSensitivity_Pa_per_m.resize(0, 0);
  } else {
    localPressureStiffness(side.normalPressure_Pa, pc, side.filmGap_m, slope, compositeSigma_m,
                           out.pressureStiffness_Pa_per_m);
    out.pressureGapSensitivity_Pa_per_m.resize(0, 0);
  }
  if (rateStep_s_ > 0.0 && !parameters_.exactStaticDerivative && sensitivities)
    out.pressureRateSensitivity_Pa_per_m = side.film.dPressure_dVelocity.rightCols(modeCount());
  else
    out.pressureRateSensitivity_Pa_per_m.resize(0, 0);
}

void ModalCoupling::calcModes() {
  const Eigen::Index ns = structural_.nodeCount(), nf = filmGrid_.nodeCount();
  // The modes of C_FF, the compliance among the nodes F that take this side's forces: the
  // nodal forces are truncated to their span, and each mode's displacement everywhere is what
  // the compliance gives for it (C_:F Phi_j / Lambda_j, = Phi_j on F), so with all modes of F
  // the modal equations are the full ones.
  const int nN = int(nodesF_.size());
  std::vector<int> nodesN(nodesF_.data(), nodesF_.data() + nN);
  Eigen::MatrixXd cNN(nN, nN);
  for (int a = 0; a < nN; ++a)
    for (int b = 0; b < nN; ++b)  // symmetrised: the FE export is symmetric to its precision
      cNN(a, b) = 0.5 * (compliance_m_per_N_(nodesN[a], nodesN[b]) +
                         compliance_m_per_N_(nodesN[b], nodesN[a]));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cNN);
  if (eig.info() != Eigen::Success)
    detail::fail(kWhere, "the eigen-decomposition of the side's compliance (" +
                             std::to_string(nN) + " nodes) failed");
  const Eigen::VectorXd& lambda = eig.eigenvalues();  // ascending
  if (!(lambda[0] > 0.0))
    detail::fail(kWhere, "the side's compliance is not positive definite (smallest eigenvalue " +
                             detail::str(lambda[0]) + " m/N on " + std::to_string(nN) +
                             " nodes)");
  const int m = std::min(parameters_.modes, nN);
  modes_ = Eigen::MatrixXd::Zero(ns, m);
  modalCompliance_m_per_N_.resize(m);
  for (int j = 0; j < m; ++j) {
    const int e = nN - 1 - j;  // largest first
    modalCompliance_m_per_N_[j] = lambda[e];
    for (Eigen::Index i = 0; i < ns; ++i) {
      double v = 0.0;
      for (int a = 0; a < nN; ++a)
        v += compliance_m_per_N_(i, nodesN[a]) * eig.eigenvectors()(a, e);
      modes_(i, j) = v / lambda[e];
    }
    for (int a = 0; a < nN; ++a)  // exactly Phi_j on F (the symmetrised C_FF's eigenvector)
      modes_(nodesN[a], j) = eig.eigenvectors()(a, e);
  }
  modalTraceShare_ = modalCompliance_m_per_N_.sum() / lambda.sum();
  modalShapes_.resize(nf, m);
  filmColumn_.resize(nf);
  for (int j = 0; j < m; ++j) {
    toFilmGrid(modes_.col(j), filmColumn_);
    modalShapes_.col(j) = filmColumn_;
  }
}

bool ModalCoupling::evaluateModes(const Eigen::VectorXd& w, const FilmPressureFunction& film,
                                  double cylinderPressure_Pa, ElasticCouplingReport& report) {
  // u, the film, the modal residual r = Lambda Phi^T f - w, its film-grid norm and the tolerance.
  u_m_.noalias() = modes_ * w;
  u_m_ += gasU_m_;
  evaluate(u_m_, film, cylinderPressure_Pa, target_m_, report);
  modalResidual_m_.noalias() = modes_.transpose() * force_N_;
  modalResidual_m_ = modalCompliance_m_per_N_.cwiseProduct(modalResidual_m_) - w;
  residualFilm_m_.noalias() = modalShapes_ * modalResidual_m_;
  return judgeResidual(residualFilm_m_.cwiseAbs().maxCoeff(), report);
}

void ModalCoupling::formJacobian() {
  // J = I - Lambda Phi^T df/dw, df/dw_j = -M (S_j + k Psi_j) (the header says why).
  const Eigen::Index nf = filmGrid_.nodeCount();
  const int m = modeCount();
  const Eigen::ArrayXd& k = film_.pressureStiffness_Pa_per_m;
  if (k.size() != nf)
    detail::fail(kWhere, "the modal scheme needs the film evaluation's "
                         "pressureStiffness_Pa_per_m (" + std::to_string(nf) + " entries), got " +
                             std::to_string(k.size()));
  detail::requireFiniteEntries(kWhere, "film evaluation pressureStiffness_Pa_per_m", k.matrix(),
                               "Pa/m");
  // An optional film nodes x modes sensitivity of the evaluation: true when given. (Names as
  // literals: a passing check builds no string.)
  const auto checkModalColumns = [&](const Eigen::MatrixXd& s, std::string_view field,
                                     std::string_view qualified) {
    if (s.size() == 0)
      return false;
    if (s.rows() != nf || s.cols() != m)
      detail::fail(kWhere, "the film evaluation's " + std::string(field) + " is " +
                               std::to_string(s.rows()) + " x " + std::to_string(s.cols()) +
                               ", expected " + std::to_string(nf) + " x " + std::to_string(m) +
                               " (film nodes x modes) or empty");
    detail::requireFiniteEntries(kWhere, qualified, s, "Pa/m");
    return true;
  };
  const Eigen::MatrixXd& rate = film_.pressureRateSensitivity_Pa_per_m;
  const Eigen::MatrixXd& gap = film_.pressureGapSensitivity_Pa_per_m;
  const bool withRate = checkModalColumns(rate, "pressureRateSensitivity_Pa_per_m",
                                          "film evaluation pressureRateSensitivity_Pa_per_m");
  const bool withGap = checkModalColumns(gap, "pressureGapSensitivity_Pa_per_m",
                                         "film evaluation pressureGapSensitivity_Pa_per_m");
  for (int j = 0; j < m; ++j) {
    filmColumn_ = (k.max(0.0) * modalShapes_.col(j).array()).matrix();
    if (withRate)
      filmColumn_ += rate.col(j);
    if (withGap)
      filmColumn_ += gap.col(j);
    // M (dp/dw_j) = -df/dw_j (the balance figures are not needed here).
    [[maybe_unused]] const mapping::LoadBalance b =
        forceMap_.apply(filmColumn_, modalForce_N_.col(j));
  }
  modalJacobian_.noalias() = modes_.transpose() * modalForce_N_;
  for (int i = 0; i < m; ++i)
    modalJacobian_.row(i) *= modalCompliance_m_per_N_[i];
  modalJacobian_.diagonal().array() += 1.0;
}

ElasticCouplingReport ModalCoupling::iterate(const FilmPressureFunction& film,
                                             double cylinderPressure_Pa) {
  gasU_m_.setZero();
  if (gas_m_per_Pa_.size() > 0)
    gasU_m_ = cylinderPressure_Pa * gas_m_per_Pa_;
  // The warm start's modal coordinates: its part on F (Phi orthonormal there).
  modal_m_.setZero();
  for (Eigen::Index b = 0; b < nodesF_.size(); ++b) {
    const int i = nodesF_[b];
    modal_m_ += (start_m_[i] - gasU_m_[i]) * modes_.row(i).transpose();
  }

  ElasticCouplingReport report;
  // Jacobian reuse (modalJacobianReuse): while the coupling is easy (the last solve needed at
  // most kEasySolve evaluations) the first evaluation goes without the sensitivities, and
  // should it not converge, the first Newton step takes the Jacobian kept from the last
  // evaluation that had them (at most N solves old). Every later evaluation has them.
  const bool reuse = parameters_.modalJacobianReuse > 0 && !hasLiner();
  const bool useKept = reuse && modalLuKept_ && modalLuAge_ < parameters_.modalJacobianReuse &&
                       lastSolveEvaluations_ <= kEasySolve;
  ++modalLuAge_;
  // After an evaluation with the sensitivities: its Jacobian (m ForceMap applications and an
  // m x m LU, small beside a film solve), for the next step or the next solves.
  const auto refreshJacobian = [&] {
    formJacobian();
    modalLu_.compute(modalJacobian_);
    modalLuKept_ = true;
    modalLuAge_ = 0;
  };
  film_.sensitivitiesWanted = !useKept;
  evaluateModes(modal_m_, film, cylinderPressure_Pa, report);
  if (reuse && !useKept)
    refreshJacobian();
  film_.sensitivitiesWanted = true;
  while (!report.converged && report.iterations < parameters_.maxIterations) {
    if (!reuse)
      refreshJacobian();
    modalStep_m_ = modalLu_.solve(modalResidual_m_);
    if (!modalStep_m_.allFinite())
      break;
    modalBase_m_ = modal_m_;
    const double baseNorm = modalResidual_m_.norm();
    bool accepted = false;
    double lambda = 1.0;
    for (int ls = 0; ls < kLineSearchTrials && report.iterations < parameters_.maxIterations;
         ++ls) {
      modal_m_ = modalBase_m_ + lambda * modalStep_m_;
      const bool converged = evaluateModes(modal_m_, film, cylinderPressure_Pa, report);
      if (reuse)
        refreshJacobian();  // at this trial: the next step's, or the next solves'
      if (converged || modalResidual_m_.norm() <= (1.0 - 1e-4 * lambda) * baseNorm) {
        accepted = true;
        break;
      }
      ++report.backtracks;
      lambda *= 0.25;
    }
    if (accepted)
      ++report.newtonSteps;
    // Not accepted: go on from the last (shortest) trial, the evaluated state.
  }
  report.relaxation = 1.0;
  lastSolveEvaluations_ = report.iterations;
  if (report.converged)
    start_m_ = u_m_;
  return report;
}

}  // namespace pistondyn::skirt
