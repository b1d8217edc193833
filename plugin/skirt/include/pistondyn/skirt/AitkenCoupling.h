#pragma once
/// @file
/// The relaxed fixed point with Aitken's dynamic factor (ElasticCoupling.h: the structure, the
/// evaluation and the tolerance).
///
/// The right relaxation factor omega ~ 1/(1 - lambda) <= 1 of the (mainly negative) feedback
/// changes with the film thickness along the cycle. Aitken's dynamic relaxation (vector form,
/// Irons & Tuck 1969; Kuettler & Wall 2008) estimates it from the last two residuals,
///   omega_k = -omega_{k-1} r_{k-1}.(r_k - r_{k-1}) / |r_k - r_{k-1}|^2,
/// for the price of two dot products: no pressure-gap derivative of the film. Omega is clamped
/// to [minRelaxation, maxRelaxation]. A step after which the residual grows more than
/// residualGrowthLimit-fold is retaken from the previous iterate with a quarter of its factor
/// (one film evaluation each): a start that closes the gap somewhere (contact pressure ~ 1e4 x
/// the film's) would otherwise send the first step millimetres away. Each solve starts from the
/// last converged deformation with the last factor, so along a cycle most solves converge in a
/// few film evaluations. It asks nothing of the film but its pressure; in whole cycles on a thin,
/// starved film it stalls where ModalCoupling.h carries on.

#include "pistondyn/skirt/ElasticCoupling.h"

namespace pistondyn::skirt {

/// Aitken-relaxed fixed-point coupling (this file's top comment).
class AitkenCoupling final : public ElasticCoupling {
 public:
  /// The arguments and errors of ElasticCoupling's constructor.
  AitkenCoupling(const SkirtSideGrid& side, const mapping::StructuralCompliance& skirt,
                 const ElasticCouplingParameters& parameters = {},
                 const mapping::StructuralCompliance* liner = nullptr);

  bool needsPoseSqueezeDerivatives() const override { return true; }
  void prepareRate(double /*rateStep_s*/) override {}
  FilmSensitivityRequest getFilmRequest(bool /*sensitivitiesWanted*/) const override {
    return {};
  }
  /// Needs nothing beyond the pressure.
  void readFilm(const SkirtSideResults&, const GapFields&, double,
                FilmPressureEvaluation&) const override {}
  /// Also restores the initial relaxation factor.
  void resetWarmStart() override;

 private:
  ElasticCouplingReport iterate(const FilmPressureFunction& film,
                                double cylinderPressure_Pa) override;

  double startRelaxation_;  ///< the factor the next solve starts with
  Eigen::VectorXd previousResidual_m_, previousU_m_;
};

}  // namespace pistondyn::skirt
