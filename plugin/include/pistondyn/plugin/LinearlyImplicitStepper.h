#pragma once
/// \file
/// A time stepper for a piston held in the bore by a squeeze film: variable-step,
/// linearly implicit BDF2 on the free generalised coordinates of a PistonAssemblyModel,
/// using the force Jacobian the elements supply (ForceElement::addForceJacobian).
///
/// Why not an explicit Runge-Kutta method: the squeeze film damps the piston's lateral
/// and tilt motion with a coefficient c ~ 1/h^3; at h = 5 um it reaches ~1e7 N s/m, so
/// the time constant m/c of a 0.3 kg piston is ~3e-8 s and explicit steps collapse to
/// nanoseconds (docs/DESIGN.md §5). Why not Simbody's CPodes BDF: it differentiates the whole
/// system numerically, one force evaluation (two film solves) per state variable for
/// every Jacobian, against a film whose solver tolerance makes such differences noisy.
/// The film solver instead returns the exact derivatives of its loads with respect to
/// the squeeze velocities (the pressure is linear in them for a fixed cavitation set),
/// and the asperity-contact law its exact stiffness: the stiff part of the Jacobian is
/// known, the rest (rigid-body coupling, film wedge stiffness, gas load) is not stiff and
/// can be left to the explicit part of the linearisation.
///
/// Method. y = (q_f, u_f, z): free q and u (not prescribed by a Motion), and the z of
/// the elements. One step from t_n to t_{n+1} = t_n + h solves the variable-step BDF2
///   y_{n+1} = a0 y_n + a1 y_{n-1} + g f(y_{n+1}),   g = beta h,
/// a0 = (1+w)^2/(1+2w), a1 = -w^2/(1+2w), beta = (1+w)/(1+2w), w = h_n/h_{n-1} (backward
/// Euler, a0 = 1, a1 = 0, beta = 1, on the first step), by Newton iterations with the
/// approximate Jacobian W = [[0, I, 0], [M^-1 K, M^-1 C, 0], [0, 0, 0]] (K = d f_gen / d q,
/// C = d f_gen / d u: the elements' parts; M the mass matrix of the free mobilities):
///   1. predict y_p and f_p by extrapolating the polynomial through the last three accepted
///      points (four with maxOrder 3; two on the second step, one with its derivative on the
///      first);
///   2. first iterate without an evaluation: (I - g W_n) d = a0 y_n + a1 y_{n-1} + g f_p - y_p,
///      y^1 = y_p + d, W_n the Jacobian of the last evaluated state;
///   3. evaluate f(y^m) (one realization: one film solve per skirt side) and W there, and
///      solve (I - g W) d = a0 y_n + a1 y_{n-1} + g f(y^m) - y^m; if the weighted norm of d
///      (the error norm below) is at most newtonTolerance the iterate y^m is the solution;
///      else y^{m+1} = y^m + d and repeat (at most maxNewtonIterations; a correction that
///      does not shrink below 0.9 of the previous one retries the step at h/4);
///   4. the z (quadratures such as friction work) take the BDF formula with f(y_{n+1});
///   5. estimate the local error from the corrector-predictor difference,
///      err ~ C_bdf / (C_bdf - C_pred) (y_{n+1} - y_p) = (2/11)(y_{n+1} - y_p) for constant
///      steps (solution errors per h^3 y^(3): C_bdf = +2/9 of BDF2, C_pred = -1 of quadratic
///      extrapolation; BDF3 with the cubic predictor: 0.12), in a weighted
///      RMS norm over (q_f, u_f) with absolute tolerances per coordinate (below); accept
///      if err <= 1, and choose the next step from err^(-1/(order+1)) (err^(-1/2) on the
///      backward-Euler start-up steps).
/// Every accepted state is an evaluated one, so its forces and the elements' history
/// updates belong to the trajectory itself, and an output row at a step's end reads the
/// cached results. Where the elements' Jacobian describes the forces well (a smooth,
/// flooded film) one evaluation per step suffices; where it does not (a starved film's
/// pressurised islands that grow and vanish with the motion, the cavitation set that
/// changes with the squeeze velocity) the Newton iteration converges the step instead of
/// leaving an unconverged linearised solution for the error test to fight with (a single
/// linearised step accepted unconverged lets a starved film's steps fall to ~5e-7 s with
/// half of them rejected).
///
/// History (auto-update discrete variables, ElementState.h): as in Simbody's integrators,
/// an element sees t - lastUpdateTime = h over a step, and the update values it computes at
/// the accepted (evaluated) state are installed for the next step.
///
/// Requirements: no enabled constraints (the piston is held by force elements, not by
/// joints); mobilizers with qdot = u (Pin, Slider, Cylinder, Weld, ...; a ball or free
/// joint's quaternions are not handled).

#include <functional>
#include <memory>

#include "pistondyn/plugin/PistonAssemblyModel.h"

namespace pistondyn::plugin {

/// Tolerances, step limits and method options of the stepper.
struct LinearlyImplicitStepperOptions {
  /// Absolute tolerance on the piston pose, as a displacement [m]: the lateral
  /// displacement, the tertiary displacement and the tilt times the skirt length.
  /// Each free q gets positionTolerance_m / (its pose lever [m per unit q]). Default 10 nm.
  double positionTolerance_m = 1e-8;
  /// Absolute tolerance on the corresponding rates [m/s]. Default 1e-8 m * 2000 rpm in rad/s.
  double velocityTolerance_mps = 1e-8 * 209.4;
  /// Relative tolerance on |q_f|, |u_f| [-], default 0. Keep it 0 (or tiny) for a piston
  /// train: the rod angle swings by ~0.3 rad with the primary motion, so 1e-4 of it would
  /// allow ~4 um of lateral error; the pose tolerances above are what matters.
  double relativeTolerance = 0.0;
  double maxStep_s = 1e-4;          ///< upper bound of the step size [s]
  double minStep_s = 1e-12;         ///< a step below this fails the run [s]
  double initialStep_s = 1e-6;      ///< first step [s]
  long maxSteps = 10000000;         ///< step budget of one stepper (a run never hangs)
  int maxConsecutiveFailures = 30;  ///< element errors or rejections in a row before giving up
  /// Newton iterations of a step: converged when the weighted RMS norm of the last correction
  /// (in units of the error tolerances above) is at most newtonTolerance, default 0.2; at
  /// most maxNewtonIterations evaluations per attempt, default 4.
  double newtonTolerance = 0.2;
  int maxNewtonIterations = 4;  ///< see newtonTolerance
  /// Order of the BDF formula once enough accepted points exist: 2 (the default, above) or 3
  /// (variable-step BDF3 with a cubic predictor and the error estimate of the same
  /// construction; step ratio at most 2 after a step that did not grow, else 1.5, for
  /// zero-stability: LinearlyImplicitStepper.cpp). BDF3 is A(86 deg)-stable,
  /// not A-stable: enough for the squeeze film's real, strongly negative eigenvalues. Its use:
  /// the global error on the piston's slow motion, which accumulates over the film's slow
  /// relaxation and which the per-step tolerance does not bound (BENCHMARKS.md).
  int maxOrder = 2;
  /// Jacobian reuse: 0 (the default) evaluates the elements' whole Jacobian (K, C) at every
  /// force evaluation. N > 0 keeps the damping part C for up to N accepted steps: a step's
  /// first evaluation then realizes the elements without it (ForceElement::
  /// setForceJacobianWanted; the lubricated skirt skips its squeeze derivatives) and the
  /// Newton correction uses the kept C with the current M, K and g (the C of step s serves
  /// steps s+1 ... s+N). A second Newton iteration and the step after a failed or rejected one
  /// always evaluate C afresh. The Newton iteration still converges the step: an iterate
  /// corrected with a kept C is accepted below half of newtonTolerance (a kept C may overstate
  /// the damping, which shrinks the correction), and the contraction test compares
  /// corrections of fresh Jacobians only.
  int jacobianReuseSteps = 0;
};

/// What the stepper did.
struct LinearlyImplicitStepperStats {
  long steps = 0;                ///< accepted steps
  long rejectedSteps = 0;        ///< by the error test
  long failedEvaluations = 0;    ///< steps retried because an element threw
  long forceEvaluations = 0;     ///< realizations to Stage::Acceleration done by the stepper
  long newtonFailures = 0;       ///< steps retried because the Newton iteration did not converge
  long jacobianEvaluations = 0;  ///< the evaluations that also evaluated the elements' Jacobian
  double realizeTime_s = 0.0;  ///< wall time in the evaluations' realizations (Simbody + elements)
  /// Sum over the accepted steps of each step's local error estimate on the piston's pose [m]:
  /// the largest over the free q of the estimated error times its pose lever (lateral,
  /// tertiary, tilt x skirt length; with a free crank also the crank angle's, as the piston's
  /// travel). An estimate of the global error those steps add to the
  /// pose where the dynamics neither amplify nor damp it: on a squeeze-damped test problem
  /// within a factor of 3 of the true error (BDF2 about 2x, BDF3 0.6-0.7x; test
  /// StepErrorEstimateFollowsTheGlobalPoseError).
  double poseErrorSum_m = 0.0;
};

/// The linearly implicit BDF2/BDF3 stepper of the documentation of LinearlyImplicitStepper.h.
class LinearlyImplicitStepper {
 public:
  /// Throws std::invalid_argument on bad options or a model with enabled constraints.
  LinearlyImplicitStepper(const PistonAssemblyModel& model,
                          const LinearlyImplicitStepperOptions& options);
  ~LinearlyImplicitStepper();
  LinearlyImplicitStepper(const LinearlyImplicitStepper&) = delete;
  LinearlyImplicitStepper& operator=(const LinearlyImplicitStepper&) = delete;

  /// Starts from `state` (its time, q, u, z, discrete variables); prescribes the
  /// prescribed coordinates and swaps the auto-update variables once.
  void initialize(const SimTK::State& state);
  /// Integrates until exactly t = tOut (> current time). Throws std::runtime_error naming
  /// the time and the reason when the step size falls below minStep_s, the step budget
  /// is used up or an element keeps failing.
  void stepTo(double tOut);
  double getTime() const;  ///< time of the last accepted step [s]
  /// The state at getTime(), not yet realized beyond Stage::Position.
  const SimTK::State& getState() const;
  const LinearlyImplicitStepperStats& getStats() const;      ///< since initialize()
  const LinearlyImplicitStepperOptions& getOptions() const;  ///< as checked

  /// Called with the failing time and a description before stepTo() throws (e.g. to add
  /// the crank angle to the message); the returned text replaces the message.
  using FailureDescriber = std::function<std::string(double time_s, const std::string& reason)>;
  void setFailureDescriber(FailureDescriber describer);  ///< see FailureDescriber

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pistondyn::plugin
