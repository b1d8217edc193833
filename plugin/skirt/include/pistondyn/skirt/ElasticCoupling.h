#pragma once
// Elastohydrodynamic (EHD) coupling of ONE skirt side at one instant (issue 11, item 3): the
// film + asperity pressure and the elastic deformation of the skirt are converged together.
//
// One iteration (film grid = SkirtSideGrid::getCylinderGrid(), structural grid = the
// compliance's nodes, both in the piston frame, offset 0):
//   1. h_el = -u_film, u_film = HermiteSurface(structural u) on the film nodes (bicubic
//      Hermite, mapping/HermiteSurface.h)
//   2. p = film(h_el): the caller's film evaluation writes h_el into
//      GapFields::pistonElastic_m, assembles the gap and solves film + contact; p is the
//      total normal pressure on the skirt (SkirtSideResults::normalPressure_Pa)
//   3. f = -ForceMap(p): consistent radial nodal forces on the structural grid (static
//      equivalence, mapping/ForceMap.h), + outward
//   4. u~ = C f + g p_cyl (compliance [m/N], optional gas field [m/Pa] times the cylinder
//      pressure), the displacement the pressure p produces
//   5. r = u~ - u; converged when max |Hermite(r)| over the film nodes <= tolerance_m, else
//      u <- u + omega r (Aitken, below) and repeat.
//
// Sign (examples/fe/README.md, GapFields.h): u and f are radial, + OUTWARD. A film pressure
// p > 0 pushes the skirt inwards: f < 0, u < 0 where it acts, and the gap term
// h_pistonElastic = -u > 0 OPENS the gap. GapAssembly adds GapFields::pistonElastic_m to the
// gap as it is (when the pistonElastic switch is on); this class returns that term.
//
// Tolerance: tolerance_m = max(absoluteTolerance_m, relativeTolerance * h_min,
// deformationRelativeTolerance * max |h_el|), h_min the smallest nominal gap of the last film
// evaluation (negative in contact counts as 0), h_el the deformation's gap term. Defaults
// 1 nm, 1e-3 and 1e-3: the change the next plain fixed-point step would make to the gap, anywhere on
// the film grid, is below 0.1 % of the thinnest film and never required finer than 1 nm (film
// solver noise times the compliance; a roughness sigma is 500x that).
//
// Why this scheme. The film pressure is stiff in the gap: dp/dh ~ -3p/h in the hydrodynamic
// part and steeper still in asperity contact, so the loop's gain |d u~ / d u| (compliance x
// film stiffness) is >= 1 for thin films and a plain fixed point (omega = 1) oscillates
// (opening the gap drops the pressure, which closes it). Seen on the gasoline FE skirt
// (tests/skirt/test_elastic_coupling_film.cpp): 2 um rigid gap, the residual shrinks by only 0.88
// per step (not converged in 60); 1 um, a 2-cycle; overlap, it blows up. The feedback is
// mainly negative (a film whose pressure falls as it opens; the shell's ovalisation can push
// other nodes outward), so an under-relaxed step with omega ~ 1/(1 - lambda) <= 1 converges;
// the right omega changes with
// the film thickness along the cycle. Aitken's dynamic relaxation (vector form, Irons & Tuck
// 1969; Kuettler & Wall 2008) estimates it from the last two residuals,
//   omega_k = -omega_{k-1} r_{k-1}.(r_k - r_{k-1}) / |r_k - r_{k-1}|^2,
// for the price of two dot products: no pressure-gap Jacobian of the film (which the film
// solver does not return; a Newton scheme would need one film solve per structural node for
// it), no extra film solves. Omega is clamped to [minRelaxation, maxRelaxation] (the negative
// feedback never needs omega > 1). A safeguard for bad starts: a step after which the residual
// grows more than residualGrowthLimit-fold is retaken from the previous iterate with a quarter
// of its factor (backtracking; one film evaluation each). Without it a start that closes the
// gap somewhere (contact pressure ~ 1e4 x the film's) sends the first step millimetres away
// and the iteration never returns (seen with a random start on the gasoline skirt). Each solve
// starts from the last converged deformation (warm start) with the last relaxation factor, so along
// a cycle most calls converge in a few film evaluations.
//
// The alternative (scheme Newton): an inexact Newton method on r(u) = C f(u) - u. Its
// preconditioner is the local Newton matrix P = I + C M diag(k) H on the structural nodes that
// move the film gap (k = the film's and asperities' local -dp/dh, localPressureStiffness());
// its step is P^-1 r first, and GMRES with finite-difference film evaluations once that step
// reduces the residual by less than half; a backtracking line search (1, 1/4, 1/16) on the
// residual's 2-norm. Measured 2026-12-02 (tests/skirt/test_elastic_coupling_film.cpp, the
// gasoline FE skirt, 40 x 30 film, rigid gaps 2 / 1 / 0.5 um): Aitken 8 / 9 / 11 film
// evaluations, Newton 10 / 12 / 12, both at the same deformation within 3.5 nm. In whole
// cycles (32 x 24) neither carries the run past about 65 deg quasi-static, or past 221 deg
// with the elastic rate (plugin/README.md): the modal scheme below does. Aitken stays this
// struct's default (no film derivatives needed); the deck's default is Modal.
//
// The modal scheme (Modal). The nodal forces f act on the nodes F that take this side's film
// forces only; C_FF = Phi Lambda Phi^T (symmetric positive definite: Phi orthonormal). The
// scheme keeps the `modes` largest: f is truncated to their span, and mode j's displacement
// is what the compliance gives for it everywhere, D_j = C_:F Phi_j / Lambda_j (= Phi_j on F),
// so u = D w + g p_cyl and with all modes of F the equations are exactly the full ones. The
// equations are the modal ones, r(w) = Lambda Phi^T f(w) - w = 0, converged when max |Psi r|
// over the
// film nodes <= tolerance (Psi = Hermite(D) on the film grid, modalShapes()). Newton with
//   J = I - Lambda Phi^T (df/dw),  df/dw_j = -M (S_j + k Psi_j),
// S_j the film's EXACT pressure derivative through the elastic gap rate (the caller's
// pressureRateSensitivity_Pa_per_m: one squeeze-derivative column per mode on the film's
// converged active set, i.e. the generalised derivative of a piecewise-linear response), k
// the local stiffness (localPressureStiffness) for the static part, or, when the caller gives
// it (FilmPressureEvaluation::pressureGapSensitivity_Pa_per_m), the film's exact static
// derivative of the shapes on its active set plus the asperities' own slope (the element's
// default since 2026-12-04: with the estimate the Newton steps stalled in whole cycles,
// plugin/README.md); backtracking (1, 1/4,
// ..., 1/4^5) on |r|. Why: where the previous two schemes stall (a thin, starved, mass-conserving
// film on the soft FE skirt, plugin/README.md), the film's response to the deformation is
// dominated by its squeeze term once the rate is implicit over a short step (S ~ c/dt), and
// that part the film solver knows exactly on its active set; with m << nodes the Jacobian is
// m x m. When a solve fails anyway the element throws and the time stepper retries with a
// shorter step, which makes S dominate more. Cost: m squeeze-derivative columns per film
// evaluation. The truncation drops the share of C_FF outside the modes (modalTraceShare()
// says what is kept); tests/skirt (ModalSchemeConvergesToTheFullCouplingWithTheModes)
// measures its error against the full coupling at fixed poses.
//
// Non-convergence is never silent: solve() returns converged = false after maxIterations
// film evaluations; the deformation then holds the last iterate (and the pressure of it), and
// the warm start keeps the last CONVERGED deformation.
//
// The liner (optional, Aitken and Modal schemes): the liner's radial compliance C_L on its own
// structural grid (the liner frame: heights above the crank axis, the same angles, a full
// circle) is seen from the skirt through the bilinear interpolation Q(Y_pin) of liner nodal
// values at the skirt's structural nodes, the piston's pin axis at height Y_pin. The film
// pressure pushes the liner outwards with the forces Q^T (-f) (static equivalence of the skirt's
// nodal forces f, the hats' own transfer: the total is exact) and the liner's outward
// displacement u_L opens the gap as much as the skirt's inward one, so the two act as springs in
// series on the skirt's structural nodes:
//   u = (C_skirt + Q C_L Q^T) f + g p_cyl,   the gap term h_el = -Hermite(u)
// (u is then the skirt's displacement minus the liner's as seen from the piston; the term goes
// into GapFields::pistonElastic_m, linerElastic_m stays zero). setLinerPosition(Y_pin) rebuilds
// Q and the effective compliance (and, modal, the modes and shapes) before each solve; the
// rate of the gap term taken in the piston frame (the caller's backward Euler on the film
// grid) then holds the liner's deformation sliding past the skirt as well as its change.
// Assumptions: the liner node heights are those of the pin axis frame shifted by Y_pin (no
// tilt, no lateral offset of the piston: both are below 1 % of a liner row); each side's
// coupling sees only its own side's forces (as the skirt: the other side's load is not in this
// side's deformation).
//
// Not done here: the elastic gap RATE (GapFields::pistonElasticRate_mps) is the caller's
// (e.g. the change of the converged deformation between steps over the step).
//
// Cost: per iteration one film evaluation (the caller's), one sparse force map (film nodes),
// one dense compliance product (structural nodes^2) and two Hermite updates (O(nodes)).
// Stateful (warm start, workspaces): one object per skirt side and thread; not thread-safe.

#include <functional>
#include <limits>
#include <optional>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCore>

#include "pistondyn/mapping/CylinderGrid.h"
#include "pistondyn/mapping/ForceMap.h"
#include "pistondyn/mapping/HermiteSurface.h"
#include "pistondyn/mapping/StructuralCompliance.h"
#include "pistondyn/skirt/SkirtSideGrid.h"

namespace pistondyn::skirt {

// How the coupling steps (the header comment above says why each).
enum class ElasticCouplingScheme {
  Aitken,  // relaxed fixed point with Aitken's dynamic factor (needs no film derivative)
  Newton,  // inexact Newton: GMRES on finite-difference film evaluations, preconditioned by
           // the film's local pressure-gap stiffness, with a backtracking line search
  Modal,   // Newton on the compliance's largest modes with the film's exact squeeze
           // derivatives of the modal shapes (the caller's elastic gap rate) in its Jacobian
};

struct ElasticCouplingParameters {
  ElasticCouplingScheme scheme = ElasticCouplingScheme::Aitken;
  // Convergence: max |change of the deformation on the film grid| <= max(absoluteTolerance_m,
  // relativeTolerance * smallest nominal gap, deformationRelativeTolerance * largest
  // deformation). All >= 0, finite, the first two not both 0.
  double absoluteTolerance_m = 1.0e-9;  // [m], default 1 nm
  double relativeTolerance = 1.0e-3;    // [-], default 1e-3
  // ... or at most deformationRelativeTolerance x the largest deformation on the film grid
  // (>= 0, finite; default 1e-3): where a slap presses the skirt by tens of micrometres into
  // the asperities (smallest film <= 0) the nodal tolerance of 1 nm is below what the film
  // solver's own accuracy resolves (seen with the film at tolerance 1e-8: stalled at 1.7 nm
  // of 45 um and 6.8 nm of 45 um); 1e-3 of 20 um is 3 % of the example's roughness sigma.
  double deformationRelativeTolerance = 1.0e-3;  // [-]
  int maxIterations = 60;               // film evaluations per solve, >= 1
  // Aitken relaxation: the first step of a solve after construction or resetWarmStart() uses
  // initialRelaxation; later solves start with the last factor. All in (0, 1], min <= max.
  double initialRelaxation = 0.5;  // [-]
  double minRelaxation = 1.0e-3;   // [-]
  double maxRelaxation = 1.0;      // [-]
  // Backtracking: when the residual on the film grid grows by more than this factor in one
  // step, the step is retaken from the previous iterate with a quarter of its factor
  // (finite, >= 1; default 2).
  double residualGrowthLimit = 2.0;  // [-]
  // Newton: GMRES iterations (film evaluations) per Newton step at most, 1 ... 50, and the
  // relative GMRES tolerance (0, 1) (an inexact Newton step: Eisenstat & Walker 1996).
  int maxKrylovIterations = 10;
  double krylovTolerance = 0.1;
  // Modal: how many modes of the side's compliance carry the deformation, >= 1 (at most the
  // structural nodes that take the side's forces or move its gap; fewer are used then).
  int modes = 20;
  // Modal: solves over which a Newton Jacobian may be kept, >= 0 (default 0: none). With N > 0,
  // while the coupling is easy (the last solve took at most two film evaluations), the first
  // evaluation of a solve asks for no sensitivities (FilmPressureEvaluation::
  // sensitivitiesWanted = false); should it not converge, the first Newton step uses the
  // Jacobian of the last evaluation that had them (at most N solves old), and every later
  // evaluation asks for them again. In a time-stepped cycle the warm start (the deformation
  // moved on at its rate) is close, so most solves end at their first evaluation or after one
  // step: they save the m derivative columns. Not with a liner (its modes move with the
  // piston).
  int modalJacobianReuse = 0;
};

// What the caller's film evaluation returns for one elastic gap term.
struct FilmPressureEvaluation {
  // Normal pressure on the skirt at the film nodes [Pa] (film + asperity - edge pressure),
  // + pushes the skirt inwards; side.nodeCount() finite entries (k = i + nPhi j).
  Eigen::ArrayXd normalPressure_Pa;
  double minFilmThickness_m = 0.0;  // smallest nominal gap of this evaluation [m] (finite)
  // Newton only: -dp/dh at each film node [Pa/m] (>= 0, finite; nodeCount entries), the
  // local stiffness of the film and the asperities (localPressureStiffness()).
  Eigen::ArrayXd pressureStiffness_Pa_per_m;
  // Modal only, optional: column j = d p / d w_j through the elastic gap RATE [Pa/m]
  // (nodeCount x modeCount(), finite): the film's squeeze derivative for the gap-rate shape
  // d(dh_el/dt)/d w_j = -Psi_j * d(rate)/d(deformation) of the caller's rate formula (1/dt
  // for a backward-Euler rate over a step dt; Psi = modalShapes()). Empty: a quasi-static rate
  // (the Jacobian then holds the local stiffness only).
  Eigen::MatrixXd pressureRateSensitivity_Pa_per_m;
  // Modal only, optional: column j = d p_film / d w_j through the elastic gap itself [Pa/m]
  // (nodeCount x modeCount(), finite): the film's exact static derivative for the gap shape
  // d h_el / d w_j = -Psi_j (lubrication::FilmProblem::gapBasis). When given, it replaces the
  // film part of the local stiffness in the Jacobian, and pressureStiffness_Pa_per_m must then
  // hold only what it lacks (the asperities' -dp_c/dh). Empty: the local estimate. The
  // Jacobian adds it to pressureRateSensitivity_Pa_per_m, so a caller may put the rate's part
  // in here instead (FilmProblem::gapRateBasis) and leave that one empty.
  Eigen::MatrixXd pressureGapSensitivity_Pa_per_m;
  // Input, set by the coupling before each call: false when it will not read the two
  // sensitivities above (ElasticCouplingParameters::modalJacobianReuse), which the caller may
  // then leave out (empty) to save their derivative solves.
  bool sensitivitiesWanted = true;
};

// The local estimate of -dp/dh the Newton scheme's preconditioner uses [Pa/m], per film node:
//   3 max(p_normal - p_c, 0) / max(h_film, hFloor) + max(-dp_c/dh, 0).
// The film part (p_normal - p_c: the film's gauge pressure) is exact for a squeeze film under a
// uniform change of the gap (p ~ h^-3; a sliding wedge has p ~ h^-2); the asperity part is the
// contact law's own slope. What it lacks (the Reynolds equation spreads a local change of the
// gap) GMRES supplies from film evaluations. Inputs (equal sizes): normal pressure [Pa],
// asperity pressure [Pa], film gap [m], asperity slope dp_c/dh [Pa/m]; hFloor_m > 0 (e.g. the
// composite roughness: the film does not stiffen like 1/h below it). Output: stiffness
// (resized; no other allocation).
void localPressureStiffness(const Eigen::Ref<const Eigen::ArrayXd>& normalPressure_Pa,
                            const Eigen::Ref<const Eigen::ArrayXd>& asperityPressure_Pa,
                            const Eigen::Ref<const Eigen::ArrayXd>& filmGap_m,
                            const Eigen::Ref<const Eigen::ArrayXd>& asperitySlope_PaPerM,
                            double hFloor_m, Eigen::ArrayXd& stiffness_Pa_per_m);

// The film: given h_pistonElastic on the film nodes [m] (+ opens the gap), fill `out`.
using FilmPressureFunction =
    std::function<void(const Eigen::ArrayXd& pistonElastic_m, FilmPressureEvaluation& out)>;

struct ElasticCouplingReport {
  bool converged = false;
  int iterations = 0;        // film evaluations in this solve
  double residual_m = 0.0;   // max |Hermite(u~ - u)| on the film grid, last iteration [m]
  double tolerance_m = 0.0;  // the tolerance it was compared with [m]
  double relaxation = 0.0;   // the Aitken factor in use at the end [-]
  int backtracks = 0;        // steps retaken with a quarter of their factor (of iterations)
  int newtonSteps = 0;       // Newton: accepted Newton steps
  int krylovIterations = 0;  // Newton: GMRES iterations (film evaluations, of iterations)
  // Force bookkeeping of the last iteration: pistonForce_N = integral of p over the film grid
  // (ForceMap's sourceTotal_N) [N], + inward; structureForce_N = sum of the radial nodal
  // forces [N], + outward; unmapped_N = part of pistonForce_N outside the structural grid.
  // Static equivalence: structureForce_N = -(pistonForce_N - unmapped_N).
  double pistonForce_N = 0.0;
  double structureForce_N = 0.0;
  double unmapped_N = 0.0;
  double maxDeformation_m = 0.0;  // max |h_pistonElastic| on the film grid [m]
};

class ElasticCoupling {
 public:
  // Inputs:
  //   side        the skirt side (its film grid, absolute angles, piston-frame heights)
  //   skirt       radial compliance of the skirt on its structural grid (StructuralCompliance.h:
  //               u = C f, + outward, [m/N]; optional gas field [m/Pa]), piston frame
  //   parameters  tolerances and relaxation (ElasticCouplingParameters)
  // Throws std::invalid_argument with the member named for: a compliance whose size is not
  // nodes x nodes of its grid, a gas field of the wrong size, non-finite entries, a film grid
  // reaching outside the structural grid (heights, or angles of a sector), bad parameters.
  //   liner       optional: radial compliance of the liner on its structural grid (liner
  //               frame: heights above the crank axis; a full circle, no gas field), or null
  // Also throws for a liner that is not a full circle, has a gas field, a bad size or
  // non-finite entries, or with the Newton scheme (its preconditioner is built once).
  ElasticCoupling(const SkirtSideGrid& side, const mapping::StructuralCompliance& skirt,
                  const ElasticCouplingParameters& parameters = {},
                  const mapping::StructuralCompliance* liner = nullptr);

  // With a liner: the pin axis's height above the crank axis Y_pin [m] (finite) for the next
  // solves; rebuilds the effective compliance (and the modes). Required before the first
  // solve() with a liner; a no-op when Y_pin is the one in use. Throws std::invalid_argument
  // when a skirt structural node would lie outside the liner's heights (naming both), or
  // without a liner. Allocates (the effective compliance and, modal, an eigen-decomposition
  // of the side's loaded nodes, ~100 x 100): the price of an elastic liner per evaluation.
  void setLinerPosition(double pinHeight_m);
  bool hasLiner() const { return linerGrid_.has_value(); }

  // Converges the film pressure and the skirt deformation.
  // Inputs:
  //   film                the film evaluation (called once per iteration)
  //   cylinderPressure_Pa gauge cylinder pressure scaling the gas field [Pa] (finite; ignored
  //                       when the compliance has no gas field)
  // Outputs: the report; pistonElastic_m(), structuralDisplacement_m(), structuralForce_N()
  // and film() hold the last iterate (the converged one when report.converged).
  // Throws std::invalid_argument for a non-finite cylinder pressure or a film evaluation of
  // the wrong size or with non-finite entries (naming it); whatever the film throws passes.
  [[nodiscard]] ElasticCouplingReport solve(const FilmPressureFunction& film,
                                            double cylinderPressure_Pa = 0.0);

  // h_pistonElastic on the film nodes [m] (+ opens the gap): the term for GapFields.
  const Eigen::ArrayXd& pistonElastic_m() const { return pistonElastic_m_; }
  // Radial displacement of the structural nodes [m] and the nodal forces [N], + outward.
  const Eigen::VectorXd& structuralDisplacement_m() const { return u_m_; }
  const Eigen::VectorXd& structuralForce_N() const { return force_N_; }
  // The film evaluation at the returned deformation.
  const FilmPressureEvaluation& film() const { return film_; }

  // Starting guess of the next solve: structural radial displacement [m] (nodes entries,
  // finite). solve() replaces it by its converged result.
  void setStart(const Eigen::Ref<const Eigen::VectorXd>& structuralDisplacement_m);
  const Eigen::VectorXd& getStart() const { return start_m_; }
  // Start the next solve from zero deformation with the initial relaxation factor.
  void resetWarmStart();

  // Modal scheme (empty otherwise): the film-grid shape of each mode's structural
  // displacement (filmNodeCount() x modeCount(), + outward; the gap term changes by -Psi_j
  // per unit w_j [m/m]), the modal coordinates of the last solve [m], and the share of the
  // trace of C_FF the modes keep [-].
  int modeCount() const { return static_cast<int>(modalShapes_.cols()); }
  const Eigen::MatrixXd& modalShapes() const { return modalShapes_; }
  const Eigen::VectorXd& modalCoordinates_m() const { return modal_m_; }
  double modalTraceShare() const { return modalTraceShare_; }

  const mapping::CylinderGrid& getStructuralGrid() const { return structural_; }
  const ElasticCouplingParameters& getParameters() const { return parameters_; }
  int structuralNodeCount() const { return structural_.nodeCount(); }
  int filmNodeCount() const { return filmGrid_.nodeCount(); }

 private:
  // One film evaluation at structural displacement u: the gap term, the film, the nodal forces
  // (force_N_) and the displacement they give (target); fills the report's force figures.
  void evaluate(const Eigen::VectorXd& u, const FilmPressureFunction& film,
                double cylinderPressure_Pa, Eigen::VectorXd& target, ElasticCouplingReport& report);
  // max |Hermite(residual)| over the film nodes [m].
  double filmGridNorm(const Eigen::VectorXd& residual);
  // residual_m_ = target_m_ - u_m_, its film-grid norm and the tolerance into the report;
  // true (and report.converged) when converged.
  bool checkConvergence(ElasticCouplingReport& report);
  // Puts a residual [m] (max over the film grid) and its tolerance (the header's rule, from the
  // last film evaluation and the report's largest deformation) into the report; true (and
  // report.converged) when within it. Every scheme judges its residual here.
  bool judgeResidual(double residual_m, ElasticCouplingReport& report) const;
  // The schemes, from u_m_ = the start.
  ElasticCouplingReport solveAitken(const FilmPressureFunction& film, double cylinderPressure_Pa);
  ElasticCouplingReport solveNewton(const FilmPressureFunction& film, double cylinderPressure_Pa);
  // Newton: the set-up (nodes S that move the film gap, F that take film forces, the Hermite
  // rows on S, C_SF), the preconditioner P = I + C_SF M diag(k) H_S factorised at the film's
  // stiffness k, and GMRES for (I - dg/du)_SS d = r_S (d into step_m_).
  void setUpNewton();
  // The node sets S, F and the Hermite rows on S (Newton and Modal).
  void setUpNodeSets();
  // Modal: the node sets and the workspaces (once), then the modes of the current compliance.
  void setUpModal();
  // Modal: Phi, Lambda of C_FF, D, Psi of compliance_m_per_N_ (again after each liner move).
  void calcModes();
  // Liner: Q at the current pin height and compliance_m_per_N_ = C_skirt + Q C_L Q^T.
  void calcEffectiveCompliance();
  ElasticCouplingReport solveModal(const FilmPressureFunction& film, double cylinderPressure_Pa);
  void factorPreconditioner();
  // The preconditioner's own step into step_m_: P^-1 r on S, the plain step r elsewhere.
  void calcPreconditionedStep();
  void calcKrylovStep(const FilmPressureFunction& film, double cylinderPressure_Pa,
                      ElasticCouplingReport& report);

  // Hermite of structural nodal values onto the film nodes.
  void toFilmGrid(const Eigen::VectorXd& structural, Eigen::Ref<Eigen::VectorXd> film);

  ElasticCouplingParameters parameters_;
  mapping::CylinderGrid filmGrid_, structural_;
  Eigen::MatrixXd compliance_m_per_N_;  // the skirt's, or with a liner the effective one
  Eigen::VectorXd gas_m_per_Pa_;  // empty without a gas field
  mapping::ForceMap forceMap_;
  mapping::HermiteSurface surface_;
  mapping::HermiteGridWorkspace hermiteWs_;

  Eigen::VectorXd start_m_;  // warm start
  double startRelaxation_;
  // Liner (empty without): its grid (the skirt's radius), compliance, the skirt's own
  // compliance, Q (skirt structural nodes x liner nodes) and the pin height it was built for.
  std::optional<mapping::CylinderGrid> linerGrid_;
  Eigen::MatrixXd linerCompliance_m_per_N_, skirtCompliance_m_per_N_, linerProduct_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> linerTransfer_;
  double linerPinHeight_m_ = std::numeric_limits<double>::quiet_NaN();
  // Iterates and scratch (sized once).
  Eigen::VectorXd u_m_, force_N_, target_m_, residual_m_, previousResidual_m_, residualFilm_m_,
      uFilm_m_, previousU_m_;
  Eigen::ArrayXd pistonElastic_m_;
  FilmPressureEvaluation film_;

  // Newton scheme (sized once in setUpNewton()).
  Eigen::VectorXi nodesS_, nodesF_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> hermiteS_;  // film node x S
  Eigen::MatrixXd complianceSF_, stiffnessFS_, preconditioner_;
  Eigen::PartialPivLU<Eigen::MatrixXd> preconditionerLu_;
  Eigen::MatrixXd krylovV_, krylovZ_, hessenberg_;  // Arnoldi basis, preconditioned basis
  Eigen::VectorXd givensC_, givensS_, krylovG_, krylovY_, vectorS_, vectorS2_;
  Eigen::VectorXd baseU_m_, baseTarget_m_, step_m_, perturbedU_m_, perturbedTarget_m_;

  // Modal scheme (sized once in setUpModal()).
  Eigen::MatrixXd modes_;        // structural nodes x m: D (Phi on F)
  Eigen::VectorXd modalCompliance_m_per_N_;  // Lambda
  Eigen::MatrixXd modalShapes_;  // film nodes x m: Psi
  Eigen::VectorXd modal_m_, modalResidual_m_, modalStep_m_, modalBase_m_, gasU_m_;
  Eigen::MatrixXd modalForce_N_, modalJacobian_;  // structural x m; m x m
  Eigen::PartialPivLU<Eigen::MatrixXd> modalLu_;
  bool modalLuKept_ = false;      // modalLu_ holds the Jacobian of an earlier evaluation
  int modalLuAge_ = 0;            // solves since it was formed
  int lastSolveEvaluations_ = 0;  // film evaluations of the last solve
  Eigen::VectorXd filmColumn_;
  double modalTraceShare_ = 0.0;
};

}  // namespace pistondyn::skirt
