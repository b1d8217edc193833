#pragma once
/// @file
/// Elastohydrodynamic coupling of ONE skirt side at one instant: the film + asperity pressure
/// and the elastic deformation of the skirt (and optionally the liner) are converged together.
/// This header holds what every scheme shares: the parameters, the exchange with the film
/// (FilmPressureEvaluation), the report, and the base class ElasticCoupling with the structure
/// (compliance, force map, Hermite interpolation, liner) and one coupling evaluation. The
/// schemes are AitkenCoupling.h (relaxed fixed point), NewtonCoupling.h (inexact Newton with
/// GMRES) and ModalCoupling.h (Newton on the compliance's largest modes, the one that carries
/// whole cycles); makeElasticCoupling() builds the one ElasticCouplingParameters::scheme names.
///
/// One evaluation (film grid = SkirtSideGrid::getCylinderGrid(), structural grid = the
/// compliance's nodes, both in the piston frame):
///   1. h_el = -u_film, u_film = HermiteSurface(structural u) on the film nodes (bicubic
///      Hermite, mapping/HermiteSurface.h);
///   2. p = film(h_el): the caller's film evaluation (FilmPressureFunction);
///   3. f = -ForceMap(p): consistent radial nodal forces on the structural grid (static
///      equivalence, mapping/ForceMap.h), + outward;
///   4. u~ = C f + g p_cyl (compliance [m/N], optional gas field [m/Pa] times the gauge cylinder
///      pressure), the displacement the pressure p produces;
///   5. the residual u~ - u, judged on the film grid (below).
///
/// Sign (examples/fe/README.md, GapFields.h): u and f are radial, + OUTWARD. A film pressure
/// p > 0 pushes the skirt inwards: f < 0, u < 0 where it acts, and the gap term
/// h_pistonElastic = -u > 0 OPENS the gap. GapAssembly adds GapFields::pistonElastic_m to the
/// gap as it is (when the pistonElastic switch is on); the coupling returns that term.
///
/// Tolerance: tolerance_m = max(absoluteTolerance_m, relativeTolerance * h_min,
/// deformationRelativeTolerance * max |h_el|), h_min the smallest nominal gap of the last film
/// evaluation (negative in contact counts as 0), h_el the deformation's gap term: the change
/// the next plain fixed-point step would make to the gap, anywhere on the film grid.
///
/// Why a scheme is needed at all: the film pressure is stiff in the gap (dp/dh ~ -3p/h in the
/// hydrodynamic part, steeper in asperity contact), so the loop's gain |du~/du| is >= 1 for thin
/// films and a plain fixed point oscillates (opening the gap drops the pressure, which closes
/// it again); the feedback is mainly negative, so under-relaxation or Newton converge.
///
/// The liner (optional; Aitken and Modal): the liner's radial compliance C_L on its own
/// structural grid (liner frame: heights above the crank axis, the same angles, a full circle)
/// is seen from the skirt through the bilinear interpolation Q(Y_pin) of liner nodal values at
/// the skirt's structural nodes, the pin axis at height Y_pin. The film pressure pushes the
/// liner outwards with Q^T (-f) (static equivalence) and the liner's outward displacement opens
/// the gap as much as the skirt's inward one: springs in series on the skirt's nodes,
///   u = (C_skirt + Q C_L Q^T) f + g p_cyl,   h_el = -Hermite(u).
/// setLinerPosition(Y_pin) rebuilds Q and the effective compliance before each solve.
/// Assumptions: no tilt or lateral offset in Q (both below 1 % of a liner row); each side's
/// coupling sees only its own side's forces.
///
/// Non-convergence is never silent: solve() returns converged = false after maxIterations film
/// evaluations; the deformation then holds the last iterate (and its pressure), and the warm
/// start keeps the last CONVERGED deformation.
///
/// Cost per evaluation: the film (the caller's), one sparse force map, one dense compliance
/// product (structural nodes^2), two Hermite updates. Stateful (warm start, workspaces): one
/// object per skirt side and thread; not thread-safe.

#include <functional>
#include <limits>
#include <memory>
#include <optional>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "pistondyn/mapping/CylinderGrid.h"
#include "pistondyn/mapping/ForceMap.h"
#include "pistondyn/mapping/HermiteSurface.h"
#include "pistondyn/mapping/StructuralCompliance.h"
#include "pistondyn/skirt/GapFields.h"
#include "pistondyn/skirt/SkirtSideGrid.h"
#include "pistondyn/skirt/SkirtSideLubrication.h"

namespace pistondyn::skirt {

/// How the coupling steps (each scheme's header says why).
enum class ElasticCouplingScheme {
  Aitken,  ///< relaxed fixed point with Aitken's dynamic factor (needs no film derivative)
  Newton,  ///< inexact Newton: GMRES on finite-difference film evaluations, preconditioned by
           ///< the film's local pressure-gap stiffness, with a backtracking line search
  Modal,   ///< Newton on the compliance's largest modes with the film's exact derivatives of
           ///< the modal shapes in its Jacobian
};

/// Tolerances, iteration caps and scheme options of a coupling.
struct ElasticCouplingParameters {
  ElasticCouplingScheme scheme = ElasticCouplingScheme::Aitken;  ///< makeElasticCoupling()
  /// Convergence: max |change of the deformation on the film grid| <= max(absoluteTolerance_m,
  /// relativeTolerance * smallest nominal gap, deformationRelativeTolerance * largest
  /// deformation). All >= 0 and finite, the first two not both 0.
  double absoluteTolerance_m = 1.0e-9;  ///< [m]
  double relativeTolerance = 1.0e-3;    ///< [-]
  /// [-]: where a slap presses the skirt tens of micrometres into the asperities, the nodal
  /// tolerance of 1 nm is below what the film solver's own accuracy resolves.
  double deformationRelativeTolerance = 1.0e-3;
  int maxIterations = 60;  ///< film evaluations per solve, >= 1
  /// Aitken: the factor of a solve's first step after construction or resetWarmStart(); later
  /// solves start with the last factor. All factors in (0, 1], min <= max.
  double initialRelaxation = 0.5;
  double minRelaxation = 1.0e-3;  ///< Aitken: smallest relaxation factor [-]
  double maxRelaxation = 1.0;     ///< Aitken: largest relaxation factor [-]
  /// Aitken: a step after which the residual grows more than this factor is retaken from the
  /// previous iterate with a quarter of its factor (finite, >= 1).
  double residualGrowthLimit = 2.0;
  /// Newton: GMRES iterations (film evaluations) per Newton step at most, 1 ... 50.
  int maxKrylovIterations = 10;
  /// Newton: relative GMRES tolerance in (0, 1) (an inexact Newton step, Eisenstat & Walker).
  double krylovTolerance = 0.1;
  /// Modal: modes of the side's compliance that carry the deformation, >= 1 (at most the
  /// structural nodes that take the side's forces; fewer are used then).
  int modes = 20;
  /// Modal: solves over which a Newton Jacobian may be kept, >= 0 (0: none). While the coupling
  /// is easy (the last solve took at most two film evaluations), the first evaluation of a
  /// solve asks for no sensitivities; should it not converge, the first Newton step uses the
  /// Jacobian of the last evaluation that had them (at most N solves old). Not with a liner.
  int modalJacobianReuse = 0;
  /// Modal: the film's exact static pressure derivative of each mode shape (FilmProblem::
  /// gapBasis) in the Jacobian, instead of the local estimate 3 p / h
  /// (localPressureStiffness()); the asperities keep their own slope.
  bool exactStaticDerivative = true;
};

/// What the caller's film evaluation returns for one elastic gap term.
struct FilmPressureEvaluation {
  /// Normal pressure on the skirt at the film nodes [Pa] (film + asperity - edge pressure),
  /// + pushes the skirt inwards; one finite entry per film node (k = i + nPhi j).
  Eigen::ArrayXd normalPressure_Pa;
  double minFilmThickness_m = 0.0;  ///< smallest nominal gap of this evaluation [m] (finite)
  /// Newton and Modal: -dp/dh at each film node [Pa/m] (>= 0, finite), the local stiffness of
  /// the film and the asperities (localPressureStiffness()); with pressureGapSensitivity_Pa_per_m
  /// only what that lacks (the asperities' -dp_c/dh).
  Eigen::ArrayXd pressureStiffness_Pa_per_m;
  /// Modal, optional: column j = dp/dw_j through the elastic gap RATE [Pa/m] (film nodes x
  /// modes): the film's squeeze derivative for the rate shape d(dh_el/dt)/dw_j = -Psi_j / dt
  /// of a backward-Euler rate over dt. Empty: a quasi-static rate.
  Eigen::MatrixXd pressureRateSensitivity_Pa_per_m;
  /// Modal, optional: column j = dp_film/dw_j through the elastic gap itself [Pa/m] (film nodes
  /// x modes): the film's exact derivative for the gap shape -Psi_j (FilmProblem::gapBasis),
  /// which may also carry the rate's part (FilmProblem::gapRateBasis). Empty: the local
  /// estimate.
  Eigen::MatrixXd pressureGapSensitivity_Pa_per_m;
  /// Input, set by the coupling before each call: false when it will not read the two
  /// sensitivities above, which the film may then leave empty.
  bool sensitivitiesWanted = true;
};

/// The local estimate of -dp/dh per film node [Pa/m]:
///   3 max(p_normal - p_c, 0) / max(h_film, hFloor) + max(-dp_c/dh, 0).
/// The film part is exact for a squeeze film under a uniform change of the gap (p ~ h^-3); the
/// asperity part is the contact law's own slope. Inputs of equal sizes: normal pressure [Pa],
/// asperity pressure [Pa], film gap [m], asperity slope dp_c/dh [Pa/m]; hFloor_m > 0. Output
/// resized; no other allocation. Throws std::invalid_argument for unequal sizes or a bad floor.
void localPressureStiffness(const Eigen::Ref<const Eigen::ArrayXd>& normalPressure_Pa,
                            const Eigen::Ref<const Eigen::ArrayXd>& asperityPressure_Pa,
                            const Eigen::Ref<const Eigen::ArrayXd>& filmGap_m,
                            const Eigen::Ref<const Eigen::ArrayXd>& asperitySlope_PaPerM,
                            double hFloor_m, Eigen::ArrayXd& stiffness_Pa_per_m);

/// The film: given h_pistonElastic on the film nodes [m] (+ opens the gap), fill `out`.
using FilmPressureFunction =
    std::function<void(const Eigen::ArrayXd& pistonElastic_m, FilmPressureEvaluation& out)>;

/// What one solve() did.
struct ElasticCouplingReport {
  bool converged = false;    ///< the residual met the tolerance (judgeResidual)
  int iterations = 0;        ///< film evaluations in this solve
  double residual_m = 0.0;   ///< max |residual| on the film grid, last iteration [m]
  double tolerance_m = 0.0;  ///< the tolerance it was compared with [m]
  double relaxation = 0.0;   ///< the Aitken factor in use at the end [-] (1 for Newton schemes)
  int backtracks = 0;        ///< steps retaken with a quarter of their factor
  int newtonSteps = 0;       ///< Newton schemes: accepted Newton steps
  int krylovIterations = 0;  ///< Newton: GMRES iterations (film evaluations, of iterations)
  /// Force bookkeeping of the last iteration: integral of p over the film grid [N], + inward.
  double pistonForce_N = 0.0;
  double structureForce_N = 0.0;  ///< sum of the radial nodal forces [N], + outward
  double unmapped_N = 0.0;        ///< part of pistonForce_N outside the structural grid [N]
  double maxDeformation_m = 0.0;  ///< max |h_pistonElastic| on the film grid [m]
};

/// The coupling of one skirt side (this file's top comment); a scheme derives from it.
class ElasticCoupling {
 public:
  virtual ~ElasticCoupling();
  ElasticCoupling(const ElasticCoupling&) = delete;
  ElasticCoupling& operator=(const ElasticCoupling&) = delete;

  /// Converges the film pressure and the skirt deformation from the start (setStart()).
  /// @param film the film evaluation (called once per iteration)
  /// @param cylinderPressure_Pa gauge cylinder pressure scaling the gas field [Pa] (finite;
  ///        ignored when the compliance has no gas field)
  /// @return the report; pistonElastic_m(), structuralDisplacement_m(), structuralForce_N()
  ///         and film() hold the last iterate (the converged one when report.converged).
  /// @throws std::invalid_argument for a non-finite pressure, a film evaluation of the wrong
  ///         size or with non-finite entries, or a liner without setLinerPosition(); whatever
  ///         the film throws passes.
  [[nodiscard]] ElasticCouplingReport solve(const FilmPressureFunction& film,
                                            double cylinderPressure_Pa = 0.0);

  /// @name What the scheme asks of a skirt side's film (SkirtSideSolver.h)
  /// @{
  /// Whether the film must return the pose's squeeze derivatives (a scheme that reads them).
  virtual bool needsPoseSqueezeDerivatives() const = 0;
  /// Before a solve: the elastic rate is backward Euler over rateStep_s (> 0), or quasi-static
  /// (0). A scheme whose film derivatives depend on it prepares them here.
  virtual void prepareRate(double rateStep_s) = 0;
  /// The extra derivative bases the film should return for the next evaluation.
  virtual FilmSensitivityRequest getFilmRequest(bool sensitivitiesWanted) const = 0;
  /// Fills the scheme's part of `out` (beyond normalPressure_Pa and minFilmThickness_m) from a
  /// side's film and contact results on `gap`; compositeSigma_m > 0 is the pair's roughness.
  virtual void readFilm(const SkirtSideResults& side, const GapFields& gap,
                        double compositeSigma_m, FilmPressureEvaluation& out) const = 0;
  /// @}

  /// With a liner: the pin axis's height above the crank axis Y_pin [m] (finite) for the next
  /// solves; rebuilds the effective compliance (and a scheme's modes). Required before the
  /// first solve() with a liner; a no-op when Y_pin is the one in use.
  /// @throws std::invalid_argument when a skirt structural node would lie outside the liner's
  ///         heights, or without a liner.
  void setLinerPosition(double pinHeight_m);
  /// Whether the coupling was built with a liner compliance (setLinerPosition() needed).
  bool hasLiner() const { return linerGrid_.has_value(); }

  /// Starting guess of the next solve: structural radial displacement [m] (one finite entry
  /// per structural node). A converged solve replaces it by its result.
  void setStart(const Eigen::Ref<const Eigen::VectorXd>& structuralDisplacement_m);
  /// The starting guess of the next solve [m], one entry per structural node (setStart()).
  const Eigen::VectorXd& getStart() const { return start_m_; }
  /// Start the next solve from zero deformation (and a scheme's initial settings).
  virtual void resetWarmStart();

  /// h_pistonElastic on the film nodes [m] (+ opens the gap): the term for GapFields.
  const Eigen::ArrayXd& pistonElastic_m() const { return pistonElastic_m_; }
  /// Radial displacement of the structural nodes [m], + outward.
  const Eigen::VectorXd& structuralDisplacement_m() const { return u_m_; }
  /// Radial nodal forces on the structure [N], + outward.
  const Eigen::VectorXd& structuralForce_N() const { return force_N_; }
  /// The film evaluation at the returned deformation.
  const FilmPressureEvaluation& film() const { return film_; }

  /// The skirt's structural grid (the compliance's nodes), piston frame.
  const mapping::CylinderGrid& getStructuralGrid() const { return structural_; }
  /// The parameters given to the constructor.
  const ElasticCouplingParameters& getParameters() const { return parameters_; }
  /// Nodes of the structural grid (size of structuralDisplacement_m()).
  int structuralNodeCount() const { return structural_.nodeCount(); }
  /// Nodes of the side's film grid (size of pistonElastic_m()).
  int filmNodeCount() const { return filmGrid_.nodeCount(); }

 protected:
  /// Checks and keeps the structure.
  /// @param side the skirt side (its film grid, absolute angles, piston-frame heights)
  /// @param skirt radial compliance of the skirt on its structural grid (u = C f, + outward,
  ///        [m/N]; optional gas field [m/Pa]), piston frame
  /// @param parameters tolerances and scheme options
  /// @param liner optional radial compliance of the liner (liner frame; a full circle, no gas
  ///        field), or null
  /// @throws std::invalid_argument naming the member for a compliance whose size is not nodes x
  ///         nodes, a gas field of the wrong size, non-finite entries, a film grid reaching
  ///         outside the structural grid, a liner that is not a full circle or has a gas
  ///         field, or bad parameters.
  ElasticCoupling(const SkirtSideGrid& side, const mapping::StructuralCompliance& skirt,
                  const ElasticCouplingParameters& parameters,
                  const mapping::StructuralCompliance* liner);

  /// The scheme's iteration from u_m_ = the start.
  virtual ElasticCouplingReport iterate(const FilmPressureFunction& film,
                                        double cylinderPressure_Pa) = 0;
  /// Called after setLinerPosition() changed the effective compliance.
  virtual void onComplianceChanged() {}

  /// One film evaluation at structural displacement u: the gap term, the film, the nodal forces
  /// (force_N_) and the displacement they give (target); fills the report's force figures.
  void evaluate(const Eigen::VectorXd& u, const FilmPressureFunction& film,
                double cylinderPressure_Pa, Eigen::VectorXd& target,
                ElasticCouplingReport& report);
  /// max |Hermite(residual)| over the film nodes [m].
  double filmGridNorm(const Eigen::VectorXd& residual);
  /// residual_m_ = target_m_ - u_m_, judged (judgeResidual); true when converged.
  bool checkConvergence(ElasticCouplingReport& report);
  /// Puts a residual [m] and its tolerance (this file's rule) into the report; true (and
  /// report.converged) when within it. Every scheme judges its residual here.
  bool judgeResidual(double residual_m, ElasticCouplingReport& report) const;
  /// Hermite of structural nodal values onto the film nodes.
  void toFilmGrid(const Eigen::VectorXd& structural, Eigen::Ref<Eigen::VectorXd> film);
  /// The node sets S (move the film gap), F (take film forces) and the Hermite rows on S.
  void setUpNodeSets();

  ElasticCouplingParameters parameters_;  ///< as given, checked
  ///@{
  /// The side's film grid and the skirt's structural grid, as cylinder grids for mapping.
  mapping::CylinderGrid filmGrid_, structural_;
  ///@}
  Eigen::MatrixXd compliance_m_per_N_;  ///< the skirt's, or with a liner the effective one
  Eigen::VectorXd gas_m_per_Pa_;        ///< empty without a gas field
  mapping::ForceMap forceMap_;  ///< film nodal pressures -> structural nodal forces
  /// Hermite interpolation of structural nodal values onto the film nodes (toFilmGrid()).
  mapping::HermiteSurface surface_;
  mapping::HermiteGridWorkspace hermiteWs_;  ///< surface_'s workspace (no allocation per call)
  Eigen::VectorXd start_m_;  ///< warm start

  /// Iterates and scratch (sized once).
  ///@{
  Eigen::VectorXd u_m_, force_N_, target_m_, residual_m_, residualFilm_m_, uFilm_m_;
  ///@}
  Eigen::ArrayXd pistonElastic_m_;  ///< see pistonElastic_m()
  FilmPressureEvaluation film_;     ///< see film()

  /// Node sets (setUpNodeSets(); Newton and Modal): S moves the film gap, F takes film forces.
  ///@{
  Eigen::VectorXi nodesS_, nodesF_;
  ///@}
  Eigen::SparseMatrix<double, Eigen::RowMajor> hermiteS_;  ///< film node x S

 private:
  /// Liner: Q at the current pin height and compliance_m_per_N_ = C_skirt + Q C_L Q^T.
  void calcEffectiveCompliance();

  /// Liner (empty without): its grid (the skirt's radius), compliance, the skirt's own
  /// compliance, Q (skirt structural nodes x liner nodes) and the pin height it was built for.
  std::optional<mapping::CylinderGrid> linerGrid_;
  Eigen::MatrixXd linerCompliance_m_per_N_, skirtCompliance_m_per_N_, linerProduct_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> linerTransfer_;
  double linerPinHeight_m_ = std::numeric_limits<double>::quiet_NaN();
};

/// The coupling of the scheme parameters.scheme names (the constructors' arguments and errors;
/// the Newton scheme takes no liner).
std::unique_ptr<ElasticCoupling> makeElasticCoupling(
    const SkirtSideGrid& side, const mapping::StructuralCompliance& skirt,
    const ElasticCouplingParameters& parameters,
    const mapping::StructuralCompliance* liner = nullptr);

}  // namespace pistondyn::skirt
