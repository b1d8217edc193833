#pragma once
/// \file
/// Single-surface flow factors and shear-stress factors of Patir & Cheng as functions of
/// the film parameter H = h / sigma (nominal gap over composite RMS roughness) and the
/// Peklenik number gamma = lambda_x / lambda_y (ratio of the 0.5-autocorrelation lengths
/// along and across the sliding direction x; gamma > 1: ridges along the sliding
/// direction, gamma < 1: ridges across it).
///
/// References
///   [PC78] N. Patir, H. S. Cheng, "An average flow model for determining effects of
///          three-dimensional roughness on partial hydrodynamic lubrication",
///          ASME J. Lubr. Technol. 100 (1978) 12-17. Table 1: pressure flow factor.
///   [PC79] N. Patir, H. S. Cheng, "Application of average flow model to lubrication
///          between rough sliding surfaces", ASME J. Lubr. Technol. 101 (1979) 220-229.
///          Tables of the shear flow factor Phi_s and of the shear-stress factors
///          Phi_fs and phi_fp; closed form of phi_f.
/// Every constant, its cross-checks and the treatment outside the papers' range of
/// validity are documented in src/PatirChengFactors.cpp.
///
/// These are the building blocks; PatirChengFlowFactors.h combines them for two rough
/// surfaces into the NodeFlowFactors a film solver consumes.

namespace pistondyn::lubrication::patir_cheng {

/// The number of Peklenik numbers at which [PC78] and [PC79] tabulate their curve fits.
inline constexpr int kTabulatedGammaCount = 7;
/// Those Peklenik numbers [-].
inline constexpr double kTabulatedGammas[kTabulatedGammaCount] = {
    1.0 / 9.0, 1.0 / 6.0, 1.0 / 3.0, 1.0, 3.0, 6.0, 9.0};

/// How the pressure flow factor is obtained for a Peklenik number gamma.
enum class PressureFlowGammaModel {
  /// Default. The [PC78] Table 1 fit of each tabulated row is evaluated and the factor
  /// values (not the constants) of the two neighbouring rows are interpolated linearly in
  /// ln(gamma); outside [1/9, 9] the end row is used (the paper has no data there). A
  /// convex combination of two valid factor values stays positive and continuous in gamma.
  kTableLogGamma,
  /// The continuous-gamma curve fits quoted in docs/DESIGN.md §4 (C and r as functions
  /// of gamma). They are somebody's least-squares fit of [PC78] Table 1, not the paper's
  /// own; they reproduce the table to within about 0.02 in C, but they jump at gamma = 1
  /// (just above 1 the fit gives phi ~ 1 + 0.0008 H^-1.5, i.e. practically no roughness
  /// effect, while gamma = 1 gives 1 - 0.9 exp(-0.56 H)). Kept only to reproduce results
  /// made with them; do not use for 1 < gamma < 3.
  kDesignNoteFit,
};

/// Smallest value of the pressure flow factors phi_x, phi_y and of phi_fp [-]: their
/// continuations below the fitted range tend to it as H -> 0 instead of to 0.
/// Why a floor, and why 1e-3: below H_lo there are no data (P&C simulated H >= 0.5); the
/// fits' own continuation towards the percolation limit is an extrapolation, not physics,
/// and without a floor it fell to 1e-46 at H = 1e-3 (gamma = 1/9) and to exactly 0 near
/// H = 1e-21 (phi_fp near 1e-15), breaking the "> 0" contract and making the film matrix
/// singular where contacts close the gap. 1e-3 keeps the ratio of conductances that phi
/// adds to the film matrix (on top of h^3) below 1e3, while a node at the floor passes only
/// 0.1 % of the flow of a smooth film of the same gap, i.e. flow is still blocked for any
/// load or friction result (the contact law carries the load there anyway).
inline constexpr double kPressureFactorFloor = 1e-3;

/// Pressure flow factor phi_x(H, gamma) of [PC78] for flow along x (the direction in
/// which gamma's numerator correlation length lies). The factor across is
/// phi_y(H, gamma) = phi_x(H, 1/gamma) [PC78].
/// Below the paper's lower validity bound H_lo (1 for gamma = 1/9 and 1/6, 0.75 for 1/3,
/// 0.5 otherwise; raised where the fit would fall below 0.02) the factor is continued
/// so that it stays positive, continuous and monotone: rows of the form 1 - C exp(-r H)
/// continue as f0 + (phi(H_lo) - f0) (H/H_lo)^k, f0 = kPressureFactorFloor, with k matching
/// the slope at H_lo (value and slope continuous at H_lo; tends to the floor f0 = 1e-3 as
/// H -> 0, where flow is blocked by contacts); rows of the form 1 + C H^-r keep their value
/// at H_lo (they would grow without bound).
/// Inputs:
///   H      film parameter h/sigma, finite and > 0 [-]
///   gamma  Peklenik number of the composite roughness, finite and > 0 [-]
///   model  how gamma between and beyond the tabulated values is handled
/// Outputs:
///   returns phi_x >= kPressureFactorFloor [-]; tends to 1 as H -> infinity.
double calcPressureFlowFactor(
    double H, double gamma, PressureFlowGammaModel model = PressureFlowGammaModel::kTableLogGamma);

/// Shear flow factor Phi_s(H, gamma) of ONE rough surface [PC79]:
/// A1 H^a1 exp(-a2 H + a3 H^2) for H <= 5 and A2 exp(-0.25 H) for H > 5.
/// The combination for two surfaces is Vr1 Phi_s(H, gamma1) - Vr2 Phi_s(H, gamma2)
/// (PatirChengFlowFactors). Below H = 0.5 the H <= 5 expression is used as it stands:
/// it is positive, increasing, and tends to 0 as H -> 0 for every tabulated gamma
/// (the maxima of the fits lie at H >= 0.55). Between tabulated gamma the factor values
/// are interpolated linearly in ln(gamma); outside [1/9, 9] the end row is used.
/// Inputs:
///   H      film parameter h/sigma (sigma = composite roughness), finite and > 0 [-]
///   gamma  Peklenik number of that surface, finite and > 0 [-]
/// Outputs:
///   returns Phi_s >= 0 [-]; tends to 0 as H -> infinity.
double calcShearFlowFactor(double H, double gamma);

/// Default cut-off eps* of phi_f [-]: 1/300, as in R. Boman's EHD code (ln(300 (z + 1)));
/// Patir & Cheng 1979 leave the cut-off as a parameter of the model.
inline constexpr double kDefaultPhiFCutoff = 1.0 / 300.0;
/// Largest accepted eps* [-]: the cut-off film eps* 3 sigma at most 0.3 sigma (phi_f then
/// stays positive for every H; it would turn negative near H = 0 for eps* > e^(-11/12)).
inline constexpr double kMaxPhiFCutoff = 0.1;

/// Couette shear-stress factor phi_f(H) of [PC79] for the polynomial height density
/// (35/96)(1 - x^2/9)^3 on |x| <= 3 sigma, in z = H/3:
///   H <= 3: (35/32) z [ (1-z^2)^3 ln((1+z)/eps*) + (1/60)(-55 + 132 z + 345 z^2 - 160 z^3
///                       - 405 z^4 + 60 z^5 + 147 z^6) ]
///   H  > 3: (35/32) z [ (1-z^2)^3 ln((z+1)/(z-1)) + (z/15)(66 - 80 z^2 + 30 z^4) ]
/// For H >= 6 an exactly equivalent series is used to avoid cancellation.
/// eps* is the cut-off of the mean of h/h_local where asperities touch: the local film is
/// taken as at least eps* 3 sigma. It is a modelling choice, not data, and phi_f is
/// sensitive to it where asperities touch (H <= 3; the H > 3 branch has no contacts and
/// does not depend on it):
///   d phi_f / d ln(eps*) = -(35/32) z (1 - z^2)^3,
/// e.g. going from 1/300 to 1/100 lowers phi_f by (35/32) z (1 - z^2)^3 ln 3: by 0.18
/// (-20 %) at H = 0.5, 0.28 (-17 %) at H = 1, 0.14 (-8 %) at H = 2, 0 from H = 3 on.
/// Inputs:
///   H        film parameter, finite and > 0 [-]
///   epsStar  cut-off eps* [-], 0 < eps* <= kMaxPhiFCutoff (0.1); default 1/300
/// Outputs:
///   returns phi_f > 0 [-]; 7/6 at H = 3, tends to 1 as H -> infinity, to 0 as H -> 0.
double calcShearStressFactorF(double H, double epsStar = kDefaultPhiFCutoff);

/// Roughness shear-stress factor Phi_fs(H, gamma) of ONE rough surface [PC79]:
/// A3 H^a4 exp(-a5 H + a6 H^2) for H <= 6.5, 0 for H >= 7, and in between the fit times the
/// C1 step 1 - 3x^2 + 2x^3, x = (H - 6.5)/0.5. DEPARTURE from the paper, which cuts the
/// fit to 0 at H = 7: the fit is 0.004 to 0.023 there, a jump of up to 2.2 % of phi_f
/// (~1.02) in the Couette shear, which an integrator would see; the taper removes it and
/// changes Phi_fs only on [6.5, 7), where it is below 0.04. Two surfaces combine
/// as Vr1 Phi_fs(H, gamma1) - Vr2 Phi_fs(H, gamma2). Below H = 0.5 the fit is used as it
/// stands (positive, increasing, -> 0 as H -> 0). Gamma handled as calcShearFlowFactor.
/// Inputs:
///   H      film parameter, finite and > 0 [-]
///   gamma  Peklenik number of that surface, finite and > 0 [-]
/// Outputs:
///   returns Phi_fs >= 0 [-].
double calcShearStressFactorFs(double H, double gamma);

/// Poiseuille shear-stress factor phi_fp(H, gamma) = 1 - D exp(-s H) of [PC79] for the
/// composite roughness. Below H_lo (0.5, raised where the fit would fall below 0.02; the
/// gamma <= 1 fits cross zero between H = 0.51 and 0.79) it continues as
/// f0 + (phi(H_lo) - f0) (H/H_lo)^k, C1 at H_lo, -> f0 = kPressureFactorFloor as H -> 0.
/// Gamma handled as calcPressureFlowFactor with kTableLogGamma.
/// SOURCE CAVEAT: only the gamma = 1 row (1.40, 0.66) is confirmed by a second source (R.
/// Boman's EHD code, docs/DESIGN.md §4). The rows for gamma != 1 are our transcription of the
/// [PC79] table and are NOT cross-checked (no second source found); verify them against the
/// paper before relying on anisotropic phi_fp.
/// Inputs:
///   H      film parameter, finite and > 0 [-]
///   gamma  Peklenik number of the composite roughness, finite and > 0 [-]
/// Outputs:
///   returns phi_fp >= kPressureFactorFloor [-]; tends to 1 as H -> infinity.
double calcShearStressFactorFp(double H, double gamma);

}  // namespace pistondyn::lubrication::patir_cheng
