// AitkenCoupling.h: the relaxed fixed point with Aitken's dynamic factor.

#include "pistondyn/skirt/AitkenCoupling.h"

#include <algorithm>

namespace pistondyn::skirt {

AitkenCoupling::AitkenCoupling(const SkirtSideGrid& side,
                               const mapping::StructuralCompliance& skirt,
                               const ElasticCouplingParameters& parameters,
                               const mapping::StructuralCompliance* liner)
    : ElasticCoupling(side, skirt, parameters, liner),
      startRelaxation_(parameters.initialRelaxation),
      previousResidual_m_(Eigen::VectorXd::Zero(structuralNodeCount())),
      previousU_m_(Eigen::VectorXd::Zero(structuralNodeCount())) {}

void AitkenCoupling::resetWarmStart() {
  ElasticCoupling::resetWarmStart();
  startRelaxation_ = parameters_.initialRelaxation;
}

ElasticCouplingReport AitkenCoupling::iterate(const FilmPressureFunction& film,
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

}  // namespace pistondyn::skirt
