#pragma once
/// @file
/// One skirt side solved at one instant, without Simbody: the gap of the piston's pose
/// (GapAssembly), the film and asperity contact on it (SkirtSideLubrication), and, for an
/// elastic skirt, the coupling of film and deformation (ElasticCoupling). The lubricated skirt
/// element reads the pose and the history from the Simbody State, solves both sides with this
/// type, sums and applies the loads, and installs the history each side returns.
///
/// History. A transient mass-conserving film needs the fill fraction of the last accepted steps
/// (lubrication::FilmHistory), an elastic skirt whose deformation rate enters the squeeze term
/// its last accepted deformation and rate (ElasticHistory). Both are values the caller keeps
/// (SkirtSideHistory) and passes back unchanged; the solution holds the history the step leads
/// to if accepted. With the Reynolds or no cavitation model the film has no history and the
/// elastic deformation is quasi-static: the history stays empty.
///
/// Elastic rate (settings.elasticRate, mass-conserving film with an elastic history only): the
/// film's squeeze term includes the elastic gap term's backward-Euler rate over the step,
/// (h_el - h_el,n) / (t - t_n), and each coupling starts from the last ACCEPTED deformation moved
/// on at its last rate: from the last converged solve it would start at a rejected trial of the
/// stepper, and from the accepted deformation alone the rate would jump to 0 (into cavitation
/// where that rate had opened the gap). Without it the coupling starts from its last converged
/// solve (a workspace: results depend on it only within the coupling tolerance).
///
/// Errors: whatever the gap, film or coupling throw passes (std::invalid_argument for bad
/// input; std::runtime_error for a film that does not converge), and a coupling that does not
/// converge throws std::runtime_error naming the side, the residual and the tolerance. The
/// solution's counters are valid also when solve() throws.

#include <limits>
#include <memory>
#include <optional>

#include <Eigen/Core>

#include "pistondyn/lubrication/FilmHistory.h"
#include "pistondyn/skirt/ElasticCoupling.h"
#include "pistondyn/skirt/GapAssembly.h"
#include "pistondyn/skirt/LinerOilFilm.h"
#include "pistondyn/skirt/SkirtSideLubrication.h"

namespace pistondyn::skirt {

/// The piston's motion as one side sees it (PistonPose.h).
struct SkirtSideMotion {
  PistonPose pose;      ///< lateral [m], tilt [rad] and tertiary [m] displacement (PistonPose.h)
  PistonPoseRate rate;  ///< their time derivatives [m/s], [rad/s], [m/s]
  double pinHeight_m = 0.0;        ///< Y_pin, pin-axis height above the crank axis [m]
  double axialVelocity_mps = 0.0;  ///< v_y = dY_pin/dt [m/s]
};

/// The conditions of one evaluation besides the motion.
struct SkirtSideConditions {
  double viscosity_Pas = 0.0;  ///< film viscosity [Pa s], > 0
  /// Oil on the liner ahead of the skirt [m], > 0; +inf = fully flooded. Not read with a
  /// liner oil film (the solver's constructor), which gives the supply per column.
  double supplyFilm_m = std::numeric_limits<double>::infinity();
  /// The crank angle [deg] (a liner oil film's ring table).
  double crankAngle_deg = 0.0;
  /// t - t_n, the time since the history's last accepted step [s]; <= 0: the same instant.
  double stepSinceHistory_s = 0.0;
  /// The pose's squeeze derivatives (dLoads_dPoseRate) for a stepper's Jacobian.
  bool poseDerivativesWanted = true;
  /// Gauge cylinder pressure scaling an elastic skirt's gas field [Pa].
  double cylinderGaugePressure_Pa = 0.0;
};

/// An elastic skirt's state at the last accepted step (the elastic rate's history).
struct ElasticHistory {
  Eigen::ArrayXd gapTerm_m;  ///< the converged elastic gap term on the film nodes [m]
  Eigen::VectorXd structural_m;  ///< the structural displacement it came from [m]
  /// Its backward-Euler rate over the step that led to it [m/s] (empty: none yet).
  Eigen::VectorXd structuralRate_mps;
};

/// What a side carries from accepted step to accepted step (empty: a full film at rest).
struct SkirtSideHistory {
  /// The mass-conserving film's fill fraction (and expected gap) at the last accepted steps
  /// (lubrication::FilmHistory.h); empty with the Reynolds or no cavitation model.
  lubrication::FilmHistory film;
  /// An elastic skirt's deformation and its rate at the last accepted step (read only with
  /// SkirtSideSettings::elasticRate); empty for a rigid skirt.
  ElasticHistory elastic;
  LinerOilState liner;  ///< the liner's oil along the side (LinerOilFilm.h); empty: none yet
};

/// Settings of a side besides its grid, gap and contact models.
struct SkirtSideSettings {
  SkirtLubricationParameters lubrication;  ///< cavitation model, solver, clamp, wear
  /// Mass-conserving film: order of the fill fraction's storage term in time, 2 (variable-step
  /// BDF2 over the last two accepted steps) or 1 (backward Euler).
  int fillFractionHistoryOrder = 2;
  bool tertiaryMotion = false;  ///< the pose's tertiary squeeze column too
  /// Elastic skirt: the elastic gap term's rate enters the film's squeeze term (this file's top
  /// comment); without it the deformation is quasi-static.
  bool elasticRate = true;
};

/// Work and time of one evaluation (diagnostics; results never depend on them).
struct SkirtSideCounters {
  long filmSolves = 0;          ///< film solves (an elastic coupling does several)
  long filmFallbacks = 0;       ///< of them with the film solver's reference fallback
  long derivativeFailures = 0;  ///< of them without derivatives (FilmResult::derivativesFailed)
  ///@{
  /// Time of the phases [s]: gap assembly, film solves, asperity contact, load integration
  /// (summed over the film evaluations; counted also when a film solve throws).
  double gap_s = 0.0, film_s = 0.0, contact_s = 0.0, loads_s = 0.0;
  ///@}
  double coupling_s = 0.0;  ///< the elastic coupling's own work between film evaluations [s]
};

/// One evaluation's outcome besides the fields (SkirtSideSolver::getResults()).
struct SkirtSideSolution {
  SkirtSideCounters counters;  ///< this evaluation's work and time; valid also when solve() throws
  /// Whether results.dLoads_dPoseRate holds the pose's squeeze derivatives.
  bool poseDerivatives = false;
  /// Elastic skirt only: what the coupling did (its iterations, largest deformation).
  ElasticCouplingReport elastic;
  /// The history this evaluation leads to if its step is accepted; valid when historyAdvanced
  /// (a mass-conserving film), otherwise the caller's history stays.
  bool historyAdvanced = false;
  SkirtSideHistory next;  ///< the history after this step (see historyAdvanced)
};

/// One skirt side (this file's top comment). Holds the side's gap assembly, film solver (with
/// its warm start) and elastic coupling: one object per side and thread.
class SkirtSideSolver {
 public:
  /// @param grid the side (copied)
  /// @param gap the gap terms' data and switches (GapTerms.h)
  /// @param flowFactors film flow-factor model, shared, immutable
  /// @param contactLaw asperity law with the same roughness, shared, immutable
  /// @param friction boundary friction
  /// @param settings this side's settings
  /// @param coupling an elastic coupling built on this grid, or null for a rigid skirt
  /// @param linerOil the liner's oil film along this side (its supply replaces
  ///        SkirtSideConditions::supplyFilm_m; needs the mass-conserving film), or none
  /// @throws std::invalid_argument naming the member for bad data (as GapAssembly and
  ///         SkirtSideLubrication), or a liner oil film with another cavitation model
  SkirtSideSolver(const SkirtSideGrid& grid, const GapAssemblyParameters& gap,
                  std::shared_ptr<const lubrication::FlowFactorModel> flowFactors,
                  std::shared_ptr<const contact_forces::AsperityContactLaw> contactLaw,
                  const contact_forces::BoundaryFriction& friction,
                  const SkirtSideSettings& settings,
                  std::unique_ptr<ElasticCoupling> coupling = nullptr,
                  std::optional<LinerOilFilm> linerOil = std::nullopt);
  ~SkirtSideSolver();
  ///@{
  /// Movable (the side's state moves with it), not copyable.
  SkirtSideSolver(SkirtSideSolver&&) noexcept;
  SkirtSideSolver& operator=(SkirtSideSolver&&) noexcept;
  ///@}

  /// Solves the side for a motion, conditions and history; fields in getGapFields() and
  /// getResults() until the next call. `out` is reused between calls.
  void solve(const SkirtSideMotion& motion, const SkirtSideConditions& conditions,
             const SkirtSideHistory& history, SkirtSideSolution& out);

  const SkirtSideGrid& getGrid() const;          ///< the side's film grid (copied at construction)
  const SkirtSideSettings& getSettings() const;  ///< the constructor's settings
  const GapAssembly& getGapAssembly() const;     ///< the side's gap assembly (its terms and data)
  ///@{
  /// The gap fields and the film/contact results of the last evaluation (for an elastic skirt,
  /// those of the converged deformation).
  const GapFields& getGapFields() const;
  const SkirtSideResults& getResults() const;
  ///@}
  /// The elastic coupling, or null for a rigid skirt.
  const ElasticCoupling* getElasticCoupling() const;
  /// The liner oil film, or null without one.
  const LinerOilFilm* getLinerOilFilm() const;
  ///@{
  /// The supply per column of the last evaluation [m] (a liner oil film's; empty without one):
  /// at the skirt's bottom and top edges.
  const Eigen::ArrayXd& getSupplyBottom_m() const;
  const Eigen::ArrayXd& getSupplyTop_m() const;
  ///@}
  /// The composite roughness sigma of the pair [m].
  double getCompositeSigma_m() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pistondyn::skirt
