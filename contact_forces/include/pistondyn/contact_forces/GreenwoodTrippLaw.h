#pragma once
/// \file
/// Greenwood–Tripp asperity contact of two nominally flat rough surfaces
/// (J.A. Greenwood & J.H. Tripp, "The contact of two nominally flat rough surfaces",
/// Proc. IMechE 185 (1970–71) 625–633), in the form used by the ring-pack and skirt
/// literature:
///
///   p_c(h)   = K · E′ · F_{5/2}(h/σ),     K = (8√2/15) · π · (ηβσ)² · √(σ/β)
///   A_c/A    = π² · (ηβσ)² · F_2(h/σ)
///   ∂p_c/∂h  = −(5/2) · K · E′ · F_{3/2}(h/σ) / σ
///
/// σ  composite RMS roughness √(Rq1² + Rq2²);  η asperity density;  β asperity radius;
/// E′ = 2 / [(1−ν1²)/E1 + (1−ν2²)/E2] = 2E* (see SurfacePair.h).
///
/// σ here is the composite SURFACE Rq and h the separation of the surfaces' mean planes, as
/// in the ring-pack/skirt literature whose parameter sets (ηβσ = 0.04, σ/β = 0.001) are the
/// defaults. Greenwood & Tripp's own σ is the standard deviation of the SUMMIT heights σ_s
/// (smaller than Rq: σ_s² ≈ (1 − 0.8968/α) Rq², α the bandwidth parameter; McCool 1986),
/// with h measured from the summits' mean plane. Use σ and the parameter set together as
/// published; see contact_forces/README.md for using the summit definition instead.
///
/// Fits (TailIntegralModel::PowerLawFit, PolynomialFit) outside λ ≥ 0: they were fitted for
/// separated surfaces and overshoot in overlap; the F_{5/2} power law is 1.32× the exact
/// value at λ = −3 and 8.6× at λ = −10 (table in the README). The exact integrals follow
/// |λ|^{5/2} there.
///
/// Why K goes with E′ = 2E*: for a pair of asperities (radius β each, so Hertz radius β/2)
/// whose summits are offset laterally by r and overlap by w0 − r²/(4β), Hertz gives the
/// load (4/3)E*(β/2)^½ (w0 − r²/4β)^{3/2}. Summing over partners (η per unit area each
/// surface, η·2πr dr partners at offset r) gives (8π/5)·β·w0^{5/2} per asperity times
/// (4/3)E*(β/2)^½·η², and averaging over the Gaussian sum of the two heights (σ composite)
/// gives p_c = (16√2/15)·π·(ηβσ)²·√(σ/β)·E*·F_{5/2} = K·(2E*)·F_{5/2}. The same sum over
/// Hertz areas π(β/2)(w0 − r²/4β) gives π²(ηβσ)²F_2 for the area.
///
/// The integrals are exact by default (GaussianTailIntegrals.h); the power-law and
/// polynomial fits of other codes can be selected for comparison.

#include "pistondyn/contact_forces/AsperityContactLaw.h"
#include "pistondyn/contact_forces/GaussianTailIntegrals.h"
#include "pistondyn/contact_forces/SurfacePair.h"

namespace pistondyn::contact_forces {

/// How F_{5/2} and F_2 are evaluated.
enum class TailIntegralModel {
  Exact,          ///< exact integrals (default)
  PowerLawFit,    ///< powerLawF52 / powerLawF2 below
  PolynomialFit,  ///< polynomialF52 / polynomialF2 below
};

/// Surface 1 is the LINER, surface 2 the SKIRT (SurfacePair.h; the convention of the film
/// solver and of PatirChengParameters, whose rq1_m / rq2_m take the same two values).
struct GreenwoodTrippParameters {
  double roughnessSurface1_m = 0.3e-6;          ///< Rq of surface 1, the liner [m], ≥ 0; 0.3 µm
  double roughnessSurface2_m = 0.4e-6;          ///< Rq of surface 2, the skirt [m], ≥ 0; 0.4 µm
  ElasticMaterial surface1 = kCastIronLiner;    ///< E [Pa], ν [-] of the liner; 115 GPa, 0.26
  ElasticMaterial surface2 = kPistonAluminium;  ///< E [Pa], ν [-] of the skirt; 75 GPa, 0.33
  double roughnessParameter = 0.04;  ///< ηβσ [-], > 0; 0.04 as in many ring-pack papers
  double sigmaOverBeta = 0.001;      ///< σ/β [-], > 0; 0.001 as in many ring-pack papers
  TailIntegralModel tailModel = TailIntegralModel::Exact;  ///< default exact integrals
  PowerLawTailFit powerLawF52 = kPowerLawFitF52;           ///< used with PowerLawFit
  PowerLawTailFit powerLawF2 = kPowerLawQuotedF2;          ///< used with PowerLawFit
  PolynomialTailFit polynomialF52 = kPolynomialFitF52;     ///< used with PolynomialFit
  PolynomialTailFit polynomialF2 = kPolynomialFitF2;       ///< used with PolynomialFit
};

/// Smallest composite roughness σ the law accepts [m]: 1 pm. Below it σ can only be a unit
/// mistake (or a denormal), and h/σ overflows for ordinary gaps.
inline constexpr double kMinCompositeRoughness_m = 1e-12;

/// K = (8√2/15)·π·(ηβσ)²·√(σ/β) [-].
/// Throws std::invalid_argument when either argument is ≤ 0 or not finite.
double greenwoodTrippCoefficient(double roughnessParameter, double sigmaOverBeta);

/// The Greenwood–Tripp asperity contact law p_c = K·E′·F_{5/2}(h/σ), A_c/A = π²(ηβσ)²F_2(h/σ)
/// (the documentation of GreenwoodTrippLaw.h derives it and states the conventions).
class GreenwoodTrippLaw final : public AsperityContactLaw {
 public:
  /// Checks every parameter; throws std::invalid_argument naming the bad one, also when the
  /// composite σ is below kMinCompositeRoughness_m.
  explicit GreenwoodTrippLaw(const GreenwoodTrippParameters& parameters = {});

  const char* name() const override { return "GreenwoodTripp"; }
  double compositeSigma_m() const override { return sigma_m_; }

  /// The parameters as checked.
  const GreenwoodTrippParameters& getParameters() const { return parameters_; }
  double effectiveModulus_Pa() const { return effectiveModulus_Pa_; }  ///< E′ [Pa]
  double coefficientK() const { return coefficientK_; }                ///< K [-]
  /// K·E′ [Pa]: pressure per unit F_{5/2}.
  double pressureScale_Pa() const { return pressureScale_Pa_; }

 protected:
  double evalPressure(double gap_m) const override;
  PressureAndSlope evalPressureAndSlope(double gap_m) const override;  ///< p_c and ∂p_c/∂h
  double evalAreaFraction(double gap_m) const override;
  /// λ = h/σ once per node; the exact model gets F_{5/2}, its slope and F_2 from one table
  /// lookup (the fits go through evalF52 and evalF2). Same values as the default evalNode.
  ContactNodeState evalNode(double gap_m) const override;

 private:
  TailValueAndSlope evalF52(double lambda) const;
  double evalF2(double lambda) const;

  GreenwoodTrippParameters parameters_;
  double sigma_m_ = 0.0;
  double effectiveModulus_Pa_ = 0.0;
  double coefficientK_ = 0.0;
  double pressureScale_Pa_ = 0.0;
  double areaScale_ = 0.0;  ///< π²(ηβσ)²
};

}  // namespace pistondyn::contact_forces
