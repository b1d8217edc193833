#pragma once
/// \file
/// Properties of the two surfaces in contact and the composite quantities the contact laws
/// use.
///
/// Which surface is "1": the project-wide convention of lubrication/ (FlowFactorModel.h,
/// FilmProblem.h, PatirChengFlowFactors.h). The film and contact grids are attached to
/// surface 2, the piston SKIRT; surface 1, the cylinder LINER, moves with the sliding
/// velocity U relative to it. So in every "surface 1 / surface 2" pair of parameters:
///   surface 1 = liner  (GreenwoodTrippParameters `roughnessSurface1_m`, `surface1`;
///                       PatirChengParameters `rq1_m`, `peklenik1`)
///   surface 2 = skirt  (GreenwoodTrippParameters `roughnessSurface2_m`, `surface2`;
///                       PatirChengParameters `rq2_m`, `peklenik2`)
/// The asperity-contact formulas here are symmetric in the two surfaces, so the label changes
/// no contact pressure; it matters where the two modules meet (one Rq pair entered for both,
/// the composite σ = √(Rq1² + Rq2²) is then the same in both) and for the Patir & Cheng shear
/// terms, whose sign follows which surface moves. Friction signs do not depend on the labels:
/// BoundaryFriction.h states its contract in terms of the surface that receives the stress.
///
/// Two conventions for the composite modulus are in use, and they differ by a factor 2:
///   E*  = 1 / [ (1−ν1²)/E1 + (1−ν2²)/E2 ]   the Hertz reduced modulus (Johnson, Contact
///                                           Mechanics; Greenwood & Williamson 1966)
///   E′  = 2 / [ (1−ν1²)/E1 + (1−ν2²)/E2 ]   = 2E*, the "effective modulus" of EHL
///                                           (Hamrock & Dowson) and of the ring/skirt papers
/// Greenwood & Tripp's pressure, built from Hertz contacts of asperity pairs, reads
/// p = (16√2/15)·π·(ηβσ)²·√(σ/β)·E*·F_{5/2}(h/σ) (re-derived in GreenwoodTrippLaw.h); the
/// ring/skirt literature writes the same pressure as K·E′·F_{5/2} with
/// K = (8√2/15)·π·(ηβσ)²·√(σ/β) and E′ = 2E*. We follow the latter (K with 8√2/15 and
/// E′ = 2E*), so K·E′ is Greenwood & Tripp's coefficient. Pairing K = (8√2/15)… with E*
/// halves the asperity pressure — a mistake found in published codes.

namespace pistondyn::contact_forces {

/// Isotropic linear-elastic material.
struct ElasticMaterial {
  double youngsModulus_Pa = 0.0;  ///< E > 0 [Pa], no default
  double poissonRatio = 0.0;      ///< ν, −1 < ν < 0.5 [-], no default
};

/// Typical materials (for defaults and examples; use your own data).
/// Piston aluminium–silicon alloy near skirt operating temperature (surface 2).
inline constexpr ElasticMaterial kPistonAluminium{75.0e9, 0.33};
/// Grey cast-iron liner (surface 1).
inline constexpr ElasticMaterial kCastIronLiner{115.0e9, 0.26};

/// Composite RMS roughness σ = √(Rq1² + Rq2²).
/// Inputs:  rq1_m, rq2_m  RMS roughness of each surface [m], ≥ 0 and finite, not both 0
/// Outputs: σ [m] > 0; throws std::invalid_argument naming the bad argument.
double compositeRoughness_m(double rq1_m, double rq2_m);

/// Hertz reduced modulus E* = 1/[(1−ν1²)/E1 + (1−ν2²)/E2] [Pa].
/// Throws std::invalid_argument for E ≤ 0 or non-finite, ν outside (−1, 0.5).
double reducedModulusHertz_Pa(const ElasticMaterial& surface1, const ElasticMaterial& surface2);

/// Effective (EHL / ring-pack) modulus E′ = 2/[(1−ν1²)/E1 + (1−ν2²)/E2] = 2E* [Pa].
/// Throws like reducedModulusHertz_Pa.
double effectiveModulus_Pa(const ElasticMaterial& surface1, const ElasticMaterial& surface2);

/// Check one material; throws std::invalid_argument whose message starts with `where` and
/// names `argName` (e.g. "surface1").
void validateMaterial(const ElasticMaterial& material, const char* where, const char* argName);

}  // namespace pistondyn::contact_forces
