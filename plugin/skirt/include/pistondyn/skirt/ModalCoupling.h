#pragma once
/// @file
/// The modal Newton coupling (ElasticCoupling.h: the structure, the evaluation and the
/// tolerance): the scheme that carries whole cycles on thin, starved films.
///
/// The nodal forces f act on the nodes F that take this side's film forces; C_FF = Phi Lambda
/// Phi^T (symmetric positive definite, Phi orthonormal). The scheme keeps the `modes` largest:
/// f is truncated to their span, and mode j's displacement is what the compliance gives for it
/// everywhere, D_j = C_:F Phi_j / Lambda_j (= Phi_j on F), so u = D w + g p_cyl and with all modes
/// of F the equations are exactly the full ones. The modal equations r(w) = Lambda Phi^T f(w) - w
/// = 0 converge when max |Psi r| over the film nodes <= tolerance (Psi = Hermite(D) on the film
/// grid, modalShapes()). Newton with
///   J = I - Lambda Phi^T (df/dw),  df/dw_j = -M (S_j + k Psi_j),
/// S_j the film's EXACT pressure derivative of the mode shape (through the elastic gap rate,
/// and with exactStaticDerivative through the gap itself: one derivative column per mode on the
/// film's converged active set, the generalised derivative of a piecewise-linear response), k the
/// local stiffness (localPressureStiffness(); with the exact static derivative only the
/// asperities' own slope); backtracking (1, 1/4, ..., 1/4^5) on |r|. Where the relaxed and
/// Newton schemes stall (a thin, starved, mass-conserving film on a soft skirt), the film's
/// response to the deformation is dominated by its squeeze term once the rate is implicit over a
/// short step (S ~ c/dt), and that part the film solver knows exactly on its active set; with
/// m << nodes the Jacobian is m x m. Cost: m derivative columns per film evaluation. The
/// truncation drops the share of C_FF outside the modes (modalTraceShare()).

#include <Eigen/LU>

#include "pistondyn/skirt/ElasticCoupling.h"

namespace pistondyn::skirt {

/// Modal Newton coupling (this file's top comment).
class ModalCoupling final : public ElasticCoupling {
 public:
  /// The arguments and errors of ElasticCoupling's constructor; also throws when the side's
  /// compliance is not positive definite.
  ModalCoupling(const SkirtSideGrid& side, const mapping::StructuralCompliance& skirt,
                const ElasticCouplingParameters& parameters = {},
                const mapping::StructuralCompliance* liner = nullptr);

  /// The modal derivatives are its own: the pose's are not needed.
  bool needsPoseSqueezeDerivatives() const override { return false; }
  /// With a rate step: the rate shapes -Psi / dt; with the exact static derivative: -Psi.
  void prepareRate(double rateStep_s) override;
  /// The shapes' derivative columns: through the rate (squeeze basis), through the gap (gap
  /// basis), or both in one (the gap basis with its rate part), as prepared.
  FilmSensitivityRequest getFilmRequest(bool sensitivitiesWanted) const override;
  void readFilm(const SkirtSideResults& side, const GapFields& gap, double compositeSigma_m,
                FilmPressureEvaluation& out) const override;

  /// The number of modes in use (columns of modalShapes()).
  int modeCount() const { return static_cast<int>(modalShapes_.cols()); }
  /// The film-grid shape of each mode's structural displacement (film nodes x modes, +
  /// outward; the gap term changes by -Psi_j per unit w_j [m/m]).
  const Eigen::MatrixXd& modalShapes() const { return modalShapes_; }
  /// The modal coordinates of the last solve [m].
  const Eigen::VectorXd& modalCoordinates_m() const { return modal_m_; }
  /// The share of the trace of C_FF the modes keep [-].
  double modalTraceShare() const { return modalTraceShare_; }

 private:
  ElasticCouplingReport iterate(const FilmPressureFunction& film,
                                double cylinderPressure_Pa) override;
  void onComplianceChanged() override { calcModes(); }
  /// Phi, Lambda of C_FF, D and Psi of the current compliance.
  void calcModes();
  /// One film evaluation at w: u, the film, the modal residual, judged; true when converged.
  bool evaluateModes(const Eigen::VectorXd& w, const FilmPressureFunction& film,
                     double cylinderPressure_Pa, ElasticCouplingReport& report);
  /// J = I - Lambda Phi^T df/dw from the last film evaluation.
  void formJacobian();

  Eigen::MatrixXd modes_;                    ///< structural nodes x m: D (Phi on F)
  Eigen::VectorXd modalCompliance_m_per_N_;  ///< Lambda
  Eigen::MatrixXd modalShapes_;              ///< film nodes x m: Psi
  Eigen::VectorXd modal_m_, modalResidual_m_, modalStep_m_, modalBase_m_, gasU_m_;
  Eigen::MatrixXd modalForce_N_, modalJacobian_;  ///< structural x m; m x m
  Eigen::PartialPivLU<Eigen::MatrixXd> modalLu_;
  bool modalLuKept_ = false;      ///< modalLu_ holds the Jacobian of an earlier evaluation
  int modalLuAge_ = 0;            ///< solves since it was formed
  int lastSolveEvaluations_ = 0;  ///< film evaluations of the last solve
  Eigen::VectorXd filmColumn_;
  double modalTraceShare_ = 0.0;
  /// The film requests of prepareRate(): -Psi / dt and -Psi, and the rate step.
  Eigen::MatrixXd rateBasis_, gapBasis_;
  double rateStep_s_ = 0.0;
};

}  // namespace pistondyn::skirt
