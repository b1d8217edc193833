#pragma once
// Boundary (asperity) friction: Coulomb's law τ = −f_dry · p_c · (direction of sliding),
// f_dry = 0.1 in the thesis' study, regularised near zero sliding speed so that the force
// is a smooth function of the sliding velocity (no switch for the integrator to step over):
//
//   Algebraic (default):  τ = −f · p · v / √(|v|² + v_ε²)
//   Tanh:                 τ = −f · p · tanh(|v|/v_ε) · v/|v|      (= −f·p·v/v_ε at v = 0)
//
// Contract (independent of which surface is called "1"):
//   v  is the 2-D velocity of the surface that RECEIVES τ relative to the other surface,
//      in the common tangent plane (axial and circumferential on a skirt);
//   τ  is the shear stress on that receiving surface; it opposes v;
//   the other surface feels −τ (its own velocity relative to the first is −v, and τ is odd
//   in v, so calling with −v gives −τ: both ends agree).
// Skirt–liner with the film solver's convention (FilmProblem.h, SurfacePair.h: surface 1 =
// liner moves with U relative to surface 2 = skirt, which carries the grid):
//   stress on the skirt  τ_skirt = calcShearStress_Pa(p, −U)   (skirt relative to liner)
//   stress on the liner  τ_liner = calcShearStress_Pa(p, +U) = −τ_skirt
// τ_skirt points along U: the liner drags the skirt, like the film's Couette shear on
// surface 2 (FilmResult::shearOnSurface2); tests/contact_forces/test_surface_convention.cpp
// checks both against a film solve.
//
// Both forms are C∞, vanish at v = 0, never exceed f·p in magnitude, and reach 71 %
// (algebraic) or 76 % (tanh) of f·p at |v| = v_ε and 99.5 % at 10 v_ε (algebraic; tanh:
// 100 % to 1e-8). The friction power τ·v = −f·p·|v|·g(|v|) is ≤ 0 at every instant, so
// friction never does positive work. The same formulas with a normal force [N] in place of
// p give a force [N].
//
// v_ε should be well below the sliding speeds of interest (piston speeds are m/s; near the
// dead centres the speed passes through zero within ~1e-3 s) and large enough that the
// integrator resolves the ramp: 1e-3 m/s by default.

#include <Eigen/Core>

namespace pistondyn::contact {

enum class FrictionRegularisation {
  Algebraic,  // v/√(v² + v_ε²) (default)
  Tanh,       // tanh(|v|/v_ε)
};

struct BoundaryFrictionParameters {
  double frictionCoefficient = 0.1;       // f_dry ≥ 0 [-]; 0.1 as in the thesis' study
  double regularisationSpeed_mps = 1e-3;  // v_ε > 0 [m/s]; default 1 mm/s
  FrictionRegularisation regularisation = FrictionRegularisation::Algebraic;
};

class BoundaryFriction {
 public:
  // Checks the parameters; throws std::invalid_argument naming the bad one.
  explicit BoundaryFriction(const BoundaryFrictionParameters& parameters = {});

  const BoundaryFrictionParameters& parameters() const { return parameters_; }

  // Effective coefficient f·g(|v|) ∈ [0, f) at sliding speed |v| [m/s] ≥ 0 [-].
  double calcEffectiveCoefficient(double slidingSpeed_mps) const;

  // Shear stress on the surface that moves with v relative to the other one.
  // Inputs:  contactPressure_Pa  p_c ≥ 0 [Pa] (or a normal force ≥ 0 [N])
  //          slidingVelocity_mps v of the receiving surface relative to the other [m/s],
  //                              finite (e.g. −U for the skirt, U the film's liner velocity)
  // Outputs: τ [Pa] (or [N]) on the receiving surface, opposing v; the other feels −τ
  Eigen::Vector2d calcShearStress_Pa(double contactPressure_Pa,
                                     const Eigen::Vector2d& slidingVelocity_mps) const;

  // ∂τ/∂v [Pa·s/m] (2×2, symmetric, negative semi-definite), for implicit integrators.
  Eigen::Matrix2d calcShearStressVelocityJacobian(double contactPressure_Pa,
                                                  const Eigen::Vector2d& slidingVelocity_mps) const;

  // calcShearStress_Pa node by node over fields of one shape.
  // Inputs:  contactPressure_Pa, slidingVelocityX_mps, slidingVelocityY_mps  same shape
  // Outputs: shearStressX_Pa, shearStressY_Pa  resized to that shape (no allocation when
  //          already that size)
  void calcShearStressField(const Eigen::Ref<const Eigen::ArrayXXd>& contactPressure_Pa,
                            const Eigen::Ref<const Eigen::ArrayXXd>& slidingVelocityX_mps,
                            const Eigen::Ref<const Eigen::ArrayXXd>& slidingVelocityY_mps,
                            Eigen::ArrayXXd& shearStressX_Pa,
                            Eigen::ArrayXXd& shearStressY_Pa) const;

 private:
  // τ = −f·p·w(|v|)·v with w the weight per unit velocity [s/m].
  double weightPerVelocity(double speed_mps) const;

  BoundaryFrictionParameters parameters_;
};

}  // namespace pistondyn::contact
