#pragma once
/// \file
/// Patir & Cheng flow-factor model for two rough surfaces: the FlowFactorModel a film
/// solver uses for the average Reynolds equation and for the mean shear stress.
///
/// Surface 1 is the surface that moves with the sliding velocity U given to the film
/// solver, relative to surface 2 (FlowFactorModel.h, FilmProblem.h). The film solver's
/// grid is attached to surface 2: for the skirt-liner film with the grid on the skirt
/// (pistondyn's choice) surface 1 is the LINER and surface 2 the SKIRT; for a journal
/// bearing with the grid on the shell, surface 1 is the journal. Only the shear flow
/// factor and phi_fs depend on which surface is
/// which: Phi_s = Vr1 Phi_s(H, gamma1) - Vr2 Phi_s(H, gamma2) with the variance ratios
/// Vr_i = Rq_i^2 / sigma^2 (Patir & Cheng 1979), and the same for phi_fs. Swapping the
/// surfaces flips their sign.
///
/// The model is immutable after construction and safe to share between threads.

#include <optional>

#include "pistondyn/lubrication/FlowFactorModel.h"
#include "pistondyn/lubrication/PatirChengExpectedGap.h"
#include "pistondyn/lubrication/PatirChengFactors.h"

namespace pistondyn::lubrication {

/// Roughness description of the two surfaces for the Patir & Cheng factors.
struct PatirChengParameters {
  double rq1_m = 0.0;  ///< RMS roughness Rq of surface 1 (moving at U: the liner) [m], >= 0
  double rq2_m = 0.0;  ///< RMS roughness Rq of surface 2 (carries the grid: the skirt) [m], >= 0
  /// Peklenik number gamma = lambda_sliding / lambda_cross of each surface [-], > 0,
  /// default 1 (isotropic). Used for Phi_s and phi_fs.
  double peklenik1 = 1.0;
  double peklenik2 = 1.0;  ///< see peklenik1
  /// Peklenik number of the composite roughness h1 + h2 [-], > 0, used for phi_x, phi_y
  /// and phi_fp. Unset (default): taken as peklenik1, which then must equal peklenik2 —
  /// for differing surfaces the composite's gamma depends on the correlation functions
  /// and must be given.
  std::optional<double> peklenikComposite;
  /// Height density of h_T; default Gaussian. Consistency note: phi_f's closed form (the
  /// only published one, [PC79]) assumes P&C's polynomial density (35/96)(1 - x^2/9)^3,
  /// while the default h_T assumes Gaussian heights, the distribution P&C simulated for
  /// phi_x, Phi_s, Phi_fs, phi_fp (and Greenwood-Tripp's). The mix is kept on purpose: the
  /// two h_T differ by at most 0.0113 sigma (2.7 % at H = 0, <= 1.04 % from H = 0.5,
  /// <= 0.36 % from H = 1; ExpectedGap.GaussianAndPolynomialFormsDifferLittle), well inside
  /// the fits' own scatter. For h_T and phi_f on one density choose kPatirChengPolynomial
  /// (the flow factors stay Gaussian-simulated either way).
  ExpectedGapForm expectedGapForm = ExpectedGapForm::kGaussian;
  /// Cut-off eps* of phi_f [-], in (0, 0.1]; default 1/300 (R. Boman's EHD code). phi_f
  /// depends on it where asperities touch (H <= 3): 1/300 -> 1/100 lowers phi_f by 17 % at
  /// H = 1 (patir_cheng::calcShearStressFactorF documents the sensitivity).
  double phiFCutoff = patir_cheng::kDefaultPhiFCutoff;
  /// How phi_x, phi_y are evaluated between the tabulated gamma; default table + ln(gamma).
  patir_cheng::PressureFlowGammaModel pressureFlowGammaModel =
      patir_cheng::PressureFlowGammaModel::kTableLogGamma;
};

/// The Patir & Cheng flow and shear-stress factors of two rough surfaces (the
/// FlowFactorModel a film solver asks at every node).
class PatirChengFlowFactors final : public FlowFactorModel {
 public:
  /// Builds the model.
  /// Inputs:
  ///   parameters  see PatirChengParameters
  /// Throws std::invalid_argument naming the member for a negative or non-finite Rq, a
  /// non-positive or non-finite Peklenik number, an unset peklenikComposite with
  /// peklenik1 != peklenik2, or phiFCutoff outside (0, 0.1]. Rq1 = Rq2 = 0 is allowed: the model
  /// then returns the smooth (plain Reynolds) factors.
  explicit PatirChengFlowFactors(const PatirChengParameters& parameters);

  /// Factors at one node.
  /// Inputs:
  ///   h_m  nominal gap, finite and > 0 [m]
  /// Outputs (NodeFlowFactors, H = h / sigma):
  ///   phiPressureSliding = phi_x(H, gammaC), phiPressureCross = phi_x(H, 1/gammaC);
  ///   sigmaPhiS_m = sigma (Vr1 Phi_s(H, gamma1) - Vr2 Phi_s(H, gamma2)) [m];
  ///   expectedGap_m, dExpectedGap_dh from calcExpectedGap with the chosen form;
  ///   phiF = phi_f(H, phiFCutoff); phiFs = Vr1 Phi_fs(H, gamma1) - Vr2 Phi_fs(H, gamma2);
  ///   phiFp = phi_fp(H, gammaC).
  /// Throws std::invalid_argument if h_m is not positive and finite.
  ///
  /// Gap clamp for h -> 0 (asperity contact closing the film). For every h > 0 the factors
  /// are bounded: phi_x, phi_y, phi_fp >= kPressureFactorFloor (1e-3), Phi_s, Phi_fs, phi_f
  /// -> 0 and h_T > 0; below H ~ 0.5 they are continuations, not data. But the film's
  /// conductance carries the nominal h^3 and the film solver needs h > 0, so the caller
  /// (the gap assembly) must hand the film a positive gap where the nominal one closes or
  /// turns negative. Recommended: a smooth (C-infinity) clamp that is >= h_c everywhere,
  ///   h_film = (h + h_c + sqrt((h - h_c)^2 + h_c^2)) / 2,   h_c = 0.1 sigma,
  /// which changes the film gap by < 1.2 % at H >= 0.5 (the bottom of P&C's data) and
  /// < 0.3 % at H >= 1, and keeps the gap ratio of a skirt film (h up to ~100 um, sigma
  /// ~0.5 um) near 2000. The asperity contact law gets the unclamped h (it carries the
  /// load there). A hard max(h, h_c) would put a kink in the film forces.
  NodeFlowFactors calcFactors(double h_m) const override;

  /// sqrt(Rq1^2 + Rq2^2) [m].
  double compositeSigma_m() const override { return sigma_m_; }

  const PatirChengParameters& getParameters() const { return parameters_; }  ///< as checked
  /// Peklenik number used for phi_x, phi_y and phi_fp [-].
  double getCompositePeklenik() const { return gammaComposite_; }

 private:
  PatirChengParameters parameters_;
  double sigma_m_ = 0.0;
  double varianceRatio1_ = 0.0;  ///< Rq1^2 / sigma^2
  double varianceRatio2_ = 0.0;  ///< Rq2^2 / sigma^2
  double gammaComposite_ = 1.0;
  /// Interpolation in ln(gamma) between two neighbouring tabulated rows of the Patir & Cheng
  /// fits, value = (1 - wHi) f(lo) + wHi f(hi); lo == hi (wHi = 0) at a tabulated gamma or
  /// when clamped to the table's range. Fixed at construction (PatirChengFlowFactors.cpp).
  struct RowBracket {
    int lo = 3;  ///< row index (3 is gamma = 1)
    int hi = 3;
    double wHi = 0.0;
  };
  RowBracket bracketSliding_;  ///< gammaC
  RowBracket bracketCross_;    ///< 1 / gammaC
  RowBracket bracket1_;        ///< gamma1
  RowBracket bracket2_;        ///< gamma2
  /// Bracket equalities, so that calcFactors blends each row function once per bracket.
  bool crossEqualsSliding_ = false;      ///< bracketCross_ == bracketSliding_ (gammaC = 1)
  bool bracket2EqualsBracket1_ = false;  ///< bracket2_ == bracket1_ (gamma1 = gamma2)
};

}  // namespace pistondyn::lubrication
