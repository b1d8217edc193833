#pragma once
/// \file
/// Flow-factor strategy consumed by the film solvers (average Reynolds equation of
/// Patir & Cheng). The solver asks the model for the factors at every node's nominal
/// gap h; the model owns the roughness description. Swapping the model (smooth
/// surfaces, Patir & Cheng, another published set) never touches the solver.
///
/// Directions: "sliding" is the direction of the relative surface velocity (axial for a
/// piston skirt, circumferential for a journal bearing); "cross" is the in-plane
/// direction perpendicular to it. The solver maps them onto its grid axes.
///
/// Convention for the shear flow term: surface 1 moves with velocity U relative to
/// surface 2, and the average Reynolds equation carries  (U/2) * d(sigma*phiS)/d(sliding).
/// The model returns sigmaPhiS_m = sigma * phiS with phiS already combining both
/// surfaces' roughness (Vr1*Phi_s(H,gamma1) - Vr2*Phi_s(H,gamma2)).

namespace pistondyn::lubrication {

/// Flow and shear-stress factors at one node. Defaults are the smooth-surface
/// (plain Reynolds) values; a model overrides what it knows.
struct NodeFlowFactors {
  double phiPressureSliding = 1.0;  ///< pressure flow factor along sliding (phi_x), [-]
  double phiPressureCross = 1.0;    ///< pressure flow factor across sliding (phi_y), [-]
  double sigmaPhiS_m = 0.0;         ///< composite sigma times shear flow factor phi_s, [m]
  double expectedGap_m = 0.0;       ///< expected local gap h_T (mean of max(h_local,0)), [m]
  double dExpectedGap_dh = 1.0;     ///< d(h_T)/dh for the squeeze term, [-]
  double phiF = 1.0;                ///< Couette shear-stress factor phi_f, [-]
  double phiFs = 0.0;               ///< roughness shear-stress factor phi_fs, [-]
  double phiFp = 1.0;               ///< Poiseuille shear-stress factor phi_fp, [-]
};

/// Strategy interface. Implementations must be immutable after construction so one
/// model can be shared by solvers on several threads.
class FlowFactorModel {
 public:
  virtual ~FlowFactorModel() = default;

  /// Factors at nominal gap h_m (> 0, finite; implementations throw
  /// std::invalid_argument otherwise).
  virtual NodeFlowFactors calcFactors(double h_m) const = 0;

  /// Composite RMS roughness sigma = sqrt(Rq1^2 + Rq2^2) [m]; 0 for smooth surfaces.
  /// Used by solvers to report the h/sigma field.
  virtual double compositeSigma_m() const = 0;
};

/// Smooth surfaces: the average Reynolds equation reduces to the plain Reynolds equation.
class SmoothFlowFactors final : public FlowFactorModel {
 public:
  NodeFlowFactors calcFactors(double h_m) const override {
    NodeFlowFactors f;
    f.expectedGap_m = h_m;
    return f;
  }
  double compositeSigma_m() const override { return 0.0; }
};

}  // namespace pistondyn::lubrication
