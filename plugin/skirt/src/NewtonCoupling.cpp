// NewtonCoupling.h: inexact Newton with a local-stiffness preconditioner and GMRES.

#include "pistondyn/skirt/NewtonCoupling.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "Checks.h"

namespace pistondyn::skirt {
namespace {
constexpr const char* kWhere = "ElasticCoupling";
}  // namespace

NewtonCoupling::NewtonCoupling(const SkirtSideGrid& side,
                               const mapping::StructuralCompliance& skirt,
                               const ElasticCouplingParameters& parameters)
    : ElasticCoupling(side, skirt, parameters, nullptr) {
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
  // One cycle of at most maxKrylovIterations film evaluations, flexible form, a direction whose
  // rotation is degenerate left out.
  const int kMax = parameters_.maxKrylovIterations;
  krylov_ = lubrication::Gmres(
      lubrication::GmresOptions{/*restart=*/kMax, /*maxIterations=*/kMax, /*flexible=*/true,
                                /*skipDegenerateDirections=*/true},
      nS);
  vectorS_ = vectorS2_ = Eigen::VectorXd::Zero(nS);
  baseU_m_ = baseTarget_m_ = step_m_ = perturbedU_m_ = perturbedTarget_m_ =
      Eigen::VectorXd::Zero(ns);
}

void NewtonCoupling::readFilm(const SkirtSideResults& side, const GapFields& gap,
                              double compositeSigma_m, FilmPressureEvaluation& out) const {
  const Eigen::Index n = side.normalPressure_Pa.size();
  const Eigen::Map<const Eigen::ArrayXd> pc(side.contact.pressure_Pa.data(), n);
  const Eigen::Map<const Eigen::ArrayXd> slope(side.contact.dPressure_dGap_PaPerM.data(), n);
  localPressureStiffness(side.normalPressure_Pa, pc, side.filmGap_m, slope, compositeSigma_m,
                         out.pressureStiffness_Pa_per_m);
  out.pressureGapSensitivity_Pa_per_m.resize(0, 0);
  if (rateStep_s_ > 0.0) {
    // The squeeze part: d p / d(dh/dt) / dt, estimated node by node from the film's lateral
    // squeeze derivative (dh/dt = -cos(phi) de/dt there).
    const auto lateral = side.film.dPressure_dVelocity.col(0).array();
    const auto basis = gap.squeezeBasis.col(0).array();
    out.pressureStiffness_Pa_per_m += lateral.abs() / (basis.abs().max(0.2) * rateStep_s_);
  }
}

void NewtonCoupling::factorPreconditioner() {
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

void NewtonCoupling::calcPreconditionedStep() {
  step_m_ = residual_m_;  // nodes outside S: the plain fixed-point step
  for (Eigen::Index a = 0; a < nodesS_.size(); ++a)
    vectorS_[a] = residual_m_[nodesS_[a]];
  vectorS2_ = preconditionerLu_.solve(vectorS_);
  for (Eigen::Index a = 0; a < nodesS_.size(); ++a)
    step_m_[nodesS_[a]] = vectorS2_[a];
}

void NewtonCoupling::calcKrylovStep(const FilmPressureFunction& film, double cylinderPressure_Pa,
                                     ElasticCouplingReport& report) {
  // Flexible right-preconditioned GMRES (lubrication/Gmres.h) from d = 0 for J d = r_S with
  // J = I - dg/du on S, J z by a forward difference of the film around the base iterate:
  // J z = z - (g(u + eps z) - g(u)) / eps, eps z moving the gap by about 1e-3 of the thinnest
  // film (>= 1 nm): far above the film solver's noise, small against the film. The flexible
  // form keeps z = P^-1 v, the very directions the film was evaluated along.
  const Eigen::Index nS = nodesS_.size();
  for (Eigen::Index a = 0; a < nS; ++a)
    vectorS_[a] = residual_m_[nodesS_[a]];
  step_m_ = residual_m_;  // nodes outside S: the plain fixed-point step
  for (Eigen::Index a = 0; a < nS; ++a)
    step_m_[nodesS_[a]] = 0.0;
  const double probe_m =
      parameters_.absoluteTolerance_m + 1e-3 * std::max(film_.minFilmThickness_m, 1e-6);
  const auto jacobianTimes = [&](const Eigen::Ref<const Eigen::VectorXd>& z,
                                 Eigen::VectorXd& product) {
    if (report.iterations >= parameters_.maxIterations - 1)
      return false;  // keep one film evaluation for the step itself
    const double zMax = z.cwiseAbs().maxCoeff();
    if (!(zMax > 0.0))
      return false;
    const double eps = probe_m / zMax;
    perturbedU_m_ = baseU_m_;
    for (Eigen::Index a = 0; a < nS; ++a)
      perturbedU_m_[nodesS_[a]] += eps * z[a];
    evaluate(perturbedU_m_, film, cylinderPressure_Pa, perturbedTarget_m_, report);
    ++report.krylovIterations;
    for (Eigen::Index a = 0; a < nS; ++a)
      product[a] = z[a] - (perturbedTarget_m_[nodesS_[a]] - baseTarget_m_[nodesS_[a]]) / eps;
    return true;
  };
  const auto precondition = [&](const Eigen::Ref<const Eigen::VectorXd>& v,
                                Eigen::Ref<Eigen::VectorXd> z) { z = preconditionerLu_.solve(v); };
  lubrication::GmresRelativeReduction stop(parameters_.krylovTolerance);
  const lubrication::GmresReport gmres = krylov_.solve(jacobianTimes, precondition, vectorS_, stop);
  if (gmres.lastCycleDirections > 0) {
    const Eigen::VectorXd& d = krylov_.solution();
    for (Eigen::Index a = 0; a < nS; ++a)
      step_m_[nodesS_[a]] = d[a];
  } else if (!gmres.converged) {
    // No Krylov direction (a degenerate first product): the preconditioner's own step.
    calcPreconditionedStep();
  }  // else r_S = 0 (or not finite): no step on S
}

ElasticCouplingReport NewtonCoupling::iterate(const FilmPressureFunction& film,
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
