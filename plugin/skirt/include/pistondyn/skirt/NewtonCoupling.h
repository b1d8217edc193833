#pragma once
/// @file
/// The inexact Newton coupling (ElasticCoupling.h: the structure, the evaluation and the
/// tolerance): Newton on r(u) = C f(u) - u.
///
/// Its preconditioner is the local Newton matrix P = I + C M diag(k) H on the structural nodes
/// that move the film gap (k = the film's and asperities' local -dp/dh, localPressureStiffness());
/// its step is P^-1 r first, and GMRES with finite-difference film evaluations once that step
/// reduces the residual by less than half; a backtracking line search (1, 1/4, 1/16) on the
/// residual's 2-norm. On fixed poses it converges like AitkenCoupling.h (about the same number of
/// film evaluations, the same deformation within a few nm); in whole cycles it stalls on thin,
/// starved films like Aitken does, where ModalCoupling.h carries on. No liner: the
/// preconditioner is built for a fixed compliance.

#include <Eigen/LU>

#include "pistondyn/lubrication/Gmres.h"
#include "pistondyn/skirt/ElasticCoupling.h"

namespace pistondyn::skirt {

/// Inexact Newton coupling with GMRES (this file's top comment).
class NewtonCoupling final : public ElasticCoupling {
 public:
  /// The arguments and errors of ElasticCoupling's constructor (no liner).
  NewtonCoupling(const SkirtSideGrid& side, const mapping::StructuralCompliance& skirt,
                 const ElasticCouplingParameters& parameters = {});

  /// The lateral squeeze derivative serves the elastic rate's part of the stiffness estimate.
  bool needsPoseSqueezeDerivatives() const override { return true; }
  void prepareRate(double rateStep_s) override { rateStep_s_ = rateStep_s; }
  FilmSensitivityRequest getFilmRequest(bool /*sensitivitiesWanted*/) const override {
    return {};
  }
  /// The local stiffness (localPressureStiffness()); with an elastic rate over dt its squeeze
  /// part, estimated node by node from the film's lateral squeeze derivative,
  /// |dp/d(de/dt)| / (max(|cos phi|, 0.2) dt).
  void readFilm(const SkirtSideResults& side, const GapFields& gap, double compositeSigma_m,
                FilmPressureEvaluation& out) const override;

 private:
  ElasticCouplingReport iterate(const FilmPressureFunction& film,
                                double cylinderPressure_Pa) override;
  /// The preconditioner P = I + C_SF M diag(k) H_S factorised at the film's stiffness k.
  void factorPreconditioner();
  /// The preconditioner's own step into step_m_: P^-1 r on S, the plain step r elsewhere.
  void calcPreconditionedStep();
  /// GMRES for (I - dg/du)_SS d = r_S (d into step_m_).
  void calcKrylovStep(const FilmPressureFunction& film, double cylinderPressure_Pa,
                      ElasticCouplingReport& report);

  double rateStep_s_ = 0.0;  ///< prepareRate()
  Eigen::MatrixXd complianceSF_, stiffnessFS_, preconditioner_;
  Eigen::PartialPivLU<Eigen::MatrixXd> preconditionerLu_;
  lubrication::Gmres krylov_;  ///< calcKrylovStep()'s GMRES and its workspace
  Eigen::VectorXd vectorS_, vectorS2_;
  Eigen::VectorXd baseU_m_, baseTarget_m_, step_m_, perturbedU_m_, perturbedTarget_m_;
};

}  // namespace pistondyn::skirt
