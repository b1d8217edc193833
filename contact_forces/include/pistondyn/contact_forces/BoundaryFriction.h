#pragma once
/// \file
/// Boundary (asperity) friction: Coulomb's law τ = −f_dry · p_c · (direction of sliding),
/// f_dry = 0.1 in the thesis' study, regularised near zero sliding speed so that the force
/// is a smooth function of the sliding velocity (no switch for the integrator to step over):
///
///   Algebraic (default):  τ = −f · p · v / √(|v|² + v_ε²)
///   Tanh:                 τ = −f · p · tanh(|v|/v_ε) · v/|v|      (= −f·p·v/v_ε at v = 0)
///
/// Contract (independent of which surface is called "1"):
///   v  is the 2-D velocity of the surface that RECEIVES τ relative to the other surface,
///      in the common tangent plane (axial and circumferential on a skirt);
///   τ  is the shear stress on that receiving surface; it opposes v;
///   the other surface feels −τ (its own velocity relative to the first is −v, and τ is odd
///   in v, so calling with −v gives −τ: both ends agree).
/// Skirt–liner with the film solver's convention (FilmProblem.h, SurfacePair.h: surface 1 =
/// liner moves with U relative to surface 2 = skirt, which carries the grid):
///   stress on the skirt  τ_skirt = calcShearStress_Pa(p, −U)   (skirt relative to liner)
///   stress on the liner  τ_liner = calcShearStress_Pa(p, +U) = −τ_skirt
/// τ_skirt points along U: the liner drags the skirt, like the film's Couette shear on
/// surface 2 (FilmResult::shearOnSurface2); tests/contact_forces/test_surface_convention.cpp
/// checks both against a film solve.
///
/// Both forms are C∞, vanish at v = 0, never exceed f·p in magnitude, and reach 71 %
/// (algebraic) or 76 % (tanh) of f·p at |v| = v_ε and 99.5 % at 10 v_ε (algebraic; tanh:
/// 100 % to 1e-8). The friction power τ·v = −f·p·|v|·g(|v|) is ≤ 0 at every instant, so
/// friction never does positive work. The same formulas with a normal force [N] in place of
/// p give a force [N].
///
/// v_ε should be well below the sliding speeds of interest (piston speeds are m/s; near the
/// dead centres the speed passes through zero within ~1e-3 s) and large enough that the
/// integrator resolves the ramp: 1e-3 m/s by default.
///
/// Integrator consideration (stiffness of the regularisation). Near v = 0 the friction force
/// is a linear damper, F ≈ −(f·N/v_ε)·v with N the asperity normal force, so on a body of
/// mass m it relaxes the sliding velocity with the time constant
///   t_f = m·v_ε/(f·N),   e.g. piston 0.3 kg, N = 1 kN, f = 0.1, v_ε = 1 mm/s: t_f = 3 µs.
/// The piston's tertiary motion (along the pin axis) has little else acting on it, so its
/// sliding velocity stays near 0, right where this damping is stiffest: an explicit
/// integrator needs steps below ~2·t_f (6 µs here) or it chatters. Use an implicit or stiffly
/// stable integrator with calcShearStressVelocityJacobian, or raise v_ε knowingly (t_f grows
/// in proportion, the stick becomes softer: at |v| = v_ε only 71 % of f·p is reached).
///
/// Any finite v is handled without overflow or underflow (|v| and v/|v| from scaled
/// components): τ → −f·p·v/|v| for |v| → ∞ (up to DBL_MAX), τ ≈ −f·p·v/v_ε for tiny |v|.

#include <Eigen/Core>

namespace pistondyn::contact_forces {

/// How the Coulomb law is smoothed at zero sliding speed.
enum class FrictionRegularisation {
  Algebraic,  ///< v/√(v² + v_ε²) (default)
  Tanh,       ///< tanh(|v|/v_ε)
};

/// Parameters of the boundary (asperity) friction law.
struct BoundaryFrictionParameters {
  double frictionCoefficient = 0.1;       ///< f_dry ≥ 0 [-]; 0.1 as in the thesis' study
  double regularisationSpeed_mps = 1e-3;  ///< v_ε > 0 [m/s]; default 1 mm/s
  FrictionRegularisation regularisation = FrictionRegularisation::Algebraic;  ///< default algebraic
};

/// Coulomb boundary friction with a smooth regularisation at zero sliding speed (this file's
/// documentation states the law and its contract).
class BoundaryFriction {
 public:
  /// Checks the parameters; throws std::invalid_argument naming the bad one.
  explicit BoundaryFriction(const BoundaryFrictionParameters& parameters = {});

  /// The parameters as checked.
  const BoundaryFrictionParameters& getParameters() const { return parameters_; }

  /// Effective coefficient f·g(|v|) ∈ [0, f) at sliding speed |v| [m/s] ≥ 0 [-].
  double calcEffectiveCoefficient(double slidingSpeed_mps) const;

  /// Shear stress on the surface that moves with v relative to the other one.
  /// Inputs:  contactPressure_Pa  p_c ≥ 0 [Pa] (or a normal force ≥ 0 [N])
  ///          slidingVelocity_mps v of the receiving surface relative to the other [m/s],
  ///                              finite (e.g. −U for the skirt, U the film's liner velocity)
  /// Outputs: τ [Pa] (or [N]) on the receiving surface, opposing v; the other feels −τ
  Eigen::Vector2d calcShearStress_Pa(double contactPressure_Pa,
                                     const Eigen::Vector2d& slidingVelocity_mps) const;

  /// ∂τ/∂v [Pa·s/m] (2×2, symmetric, negative semi-definite), for implicit integrators.
  Eigen::Matrix2d calcShearStressVelocityJacobian(double contactPressure_Pa,
                                                  const Eigen::Vector2d& slidingVelocity_mps) const;

  /// calcShearStress_Pa node by node over fields of one shape.
  /// Inputs:  contactPressure_Pa, slidingVelocityX_mps, slidingVelocityY_mps  same shape
  /// Outputs: shearStressX_Pa, shearStressY_Pa  resized to that shape (no allocation when
  ///          already that size)
  void calcShearStressField(const Eigen::Ref<const Eigen::ArrayXXd>& contactPressure_Pa,
                            const Eigen::Ref<const Eigen::ArrayXXd>& slidingVelocityX_mps,
                            const Eigen::Ref<const Eigen::ArrayXXd>& slidingVelocityY_mps,
                            Eigen::ArrayXXd& shearStressX_Pa,
                            Eigen::ArrayXXd& shearStressY_Pa) const;

  /// The same with one sliding velocity for every node (a rigid skirt sliding along a rigid
  /// liner: the piston's axial speed, and the tertiary / circumferential speed, are the same
  /// at every node): one speed, one coefficient and one direction for the field, so the cost
  /// is one multiply per node and component.
  /// Inputs:  contactPressure_Pa   p_c per node ≥ 0 and finite [Pa]
  ///          slidingVelocity_mps  v of the receiving surface relative to the other [m/s]
  /// Outputs: shearStressX_Pa, shearStressY_Pa  resized to the shape of contactPressure_Pa
  void calcShearStressField(const Eigen::Ref<const Eigen::ArrayXXd>& contactPressure_Pa,
                            const Eigen::Vector2d& slidingVelocity_mps,
                            Eigen::ArrayXXd& shearStressX_Pa,
                            Eigen::ArrayXXd& shearStressY_Pa) const;

 private:
  struct SpeedAndDirection {
    double speed;         ///< |v| [m/s] (+inf only beyond DBL_MAX)
    double unitX, unitY;  ///< v/|v|, 0 for v = 0
  };
  static SpeedAndDirection splitVelocity(double vx, double vy);
  /// g(|v|) = effective coefficient / f ∈ [0, 1) [-].
  double fraction(double speed_mps) const;
  /// g(s)/s and g'(s) [s/m], for the Jacobian.
  void fractionOverSpeedAndSlope(double speed_mps, double& overSpeed, double& slope) const;
  /// The factor w with τ = −f·p·w·v [s/m]. Common case (both components and v_ε below
  /// kFastPathSpeed_mps): from |v|² directly, no division per component; otherwise from
  /// splitVelocity (no overflow for any finite v).
  void weightedDirection(double vx, double vy, double& tx, double& ty) const;

  BoundaryFrictionParameters parameters_;
  double fastPathSpeed_mps_ = 0.0;  ///< components up to this use |v|² directly
};

}  // namespace pistondyn::contact_forces
