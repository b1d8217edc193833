#pragma once
/// @file
/// The lubricated skirt-liner force element: the piston held in the bore by the oil film and
/// the asperity contact between its skirt and the liner, on a thrust-side and an
/// anti-thrust-side sector of the skirt (docs/DESIGN.md §4, thesis §2).
///
/// At every force evaluation it reads the piston's pose and rates from the State
/// (PistonPose.h), builds the gap and its rate on both sides (skirt::GapAssembly: the seven
/// terms), solves film and contact there (skirt::SkirtSideLubrication: one film solve per
/// side), integrates pressure and shear to the force and moment on the piston (radial
/// pressure components in x and z, so the same film carries the secondary and the tertiary
/// motion; axial and circumferential friction) and applies them; the reaction acts on the
/// liner, which is ground. The element supplies the stiff part of its force Jacobian (the
/// film's exact squeeze damping, the asperity stiffness) for LinearlyImplicitStepper.
///
/// State it keeps (ElementState.h):
/// - z: friction work (total, hydrodynamic, asperity), dissipated energy and secondary-motion
///   work [J], Archard wear volume per side [m^3] - cycle integrals, integrated with the motion
/// - auto-update: each side's history (skirt::SkirtSideHistory: the mass-conserving model's
///   fill fraction, the elastic skirt's accepted deformation and rate, the liner oil film;
///   advanced once per accepted step; the film's transient step is t - last update time), and
///   the slap tracker (approach direction, peak secondary kinetic energy of the approach,
///   energy of the last completed slap event, event count)
/// - cache: the per-state results (loads, their derivatives, figures of both sides)
///
/// Mutable workspace: the two sides' film solvers and their warm starts (results depend on
/// them only within the film solver's tolerance; one model per thread, ForceElement.h), and
/// with the elastic skirt each side's last converged deformation, the start of the next
/// coupling (results depend on it only within the coupling tolerance). The
/// nodal fields of the last evaluation are kept there too (getLastSideResults(): valid
/// right after realizing a state, e.g. at an output row, for field dumps).
///
/// Slap events. The secondary kinetic energy K = 1/2 (m_piston + m_pin) v_G^2 +
/// 1/2 I_piston (dalpha/dt)^2, v_G the lateral velocity of the piston's centre of mass
/// relative to the cylinder axis, grows while the piston crosses the clearance and is
/// absorbed by the film and the asperities when it arrives. An approach towards one side
/// begins when v_G changes sign and ends (the event completes) at the next sign change; its
/// impact kinetic energy is the peak of K over the approach: K is evaluated at every force
/// evaluation and the tracker installed once per accepted step (an auto-update variable, so
/// with LinearlyImplicitStepper usually the value at the step's predictor or output row).
/// Events below kMinSlapEnergy_J are not counted (the film's small oscillations).
///
/// Tertiary motion (along the pin axis) is a switch. Off (the thesis' study): the crank
/// train must be built without the tertiary mobility (EngineDescription::tertiaryMotion =
/// false). On: the film's z pressure components and a pin-retainer contact (a stiff spring
/// outside the axial play, the circlips or the skirt end against the liner's wall) hold it.

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "pistondyn/contact_forces/BoundaryFriction.h"
#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"
#include "pistondyn/lubrication/Oil.h"
#include "pistondyn/lubrication/PatirChengFlowFactors.h"
#include "pistondyn/mapping/StructuralCompliance.h"
#include "pistondyn/mbd_models/CylinderPressureCurve.h"
#include "pistondyn/plugin/ElementCache.h"
#include "pistondyn/plugin/LinerElement.h"
#include "pistondyn/plugin/PistonPose.h"
#include "pistondyn/skirt/ElasticCoupling.h"
#include "pistondyn/skirt/GapAssembly.h"
#include "pistondyn/skirt/SkirtSideSolver.h"

namespace pistondyn::plugin {

/// Oil on the liner ahead of the skirt, as a function of the crank angle: a constant, or a
/// periodic table over the 720 deg cycle (linear between points). +inf = fully flooded.
struct SupplyFilm {
  double constant_m = std::numeric_limits<double>::infinity();  ///< [m], > 0
  std::vector<double> crankAngle_deg;  ///< optional table: strictly increasing, within [0, 720)
  std::vector<double> thickness_m;     ///< [m], > 0, same size
  /// Thickness at a crank angle [m] (any angle; wrapped into [0, 720)).
  double calcThickness_m(double angle_deg) const;
};

/// Elastic skirt (issue 11): at every force evaluation each side's film pressure and the
/// skirt's elastic deformation are converged together (skirt::ElasticCoupling.h: the scheme of
/// coupling.scheme; the deck's default is the modal Newton scheme with the elastic rate, the
/// one that carries whole cycles, plugin/README.md). The converged deformation goes into
/// GapFields::pistonElastic_m (the gap term switch pistonElastic must be on). With squeezeRate
/// its rate enters the film's squeeze term (backward Euler over the step), and each coupling
/// starts from the last ACCEPTED deformation moved on at its last rate (FillHistory); without
/// it the deformation is quasi-static and the coupling starts from its last converged solve
/// (mutable workspace: results depend on it only within the coupling tolerance). The Jacobian
/// is the film's at the converged deformation. A coupling that does not converge within
/// coupling.maxIterations throws std::runtime_error (never silent); the stepper then retries a
/// shorter step.
struct ElasticSkirtParameters {
  bool enabled = false;  ///< default off: rigid skirt
  /// Radial compliance of the skirt in the piston frame (io::readStructuralCompliance): its
  /// grid must cover both skirt sides.
  mapping::StructuralCompliance compliance;
  /// Optional: the liner's radial compliance on its own structural grid (liner frame: heights
  /// above the crank axis, a full circle; io::readStructuralCompliance), in series with the
  /// skirt's at the piston's current height (skirt/ElasticCoupling.h, "The liner"). Needs the
  /// elastic skirt (enabled) and the modal or Aitken scheme; its grid must cover the skirt over
  /// the stroke. Empty: a rigid liner.
  std::optional<mapping::StructuralCompliance> liner;
  /// Tolerances, iteration cap, scheme. Default: the modal scheme, the one that carries whole
  /// cycles (plugin/README.md, "The elastic coupling: which scheme and why"), as the deck's
  /// liner.elastic_skirt.scheme; ElasticCouplingParameters alone defaults to Aitken, which
  /// needs no film derivatives but stalls in cycles.
  skirt::ElasticCouplingParameters coupling = [] {
    skirt::ElasticCouplingParameters c;
    c.scheme = skirt::ElasticCouplingScheme::Modal;
    return c;
  }();
  /// Cylinder pressure scaling the compliance's gas field, gauge against crankcasePressure_Pa;
  /// null = no gas deformation (also when the compliance has no gas field).
  std::shared_ptr<const mbd::CylinderPressureCurve> cylinderPressure;
  double crankcasePressure_Pa = 1.0e5;  ///< [Pa] absolute, the pressure under the crown
  /// The film's squeeze term includes the rate of the elastic gap term, backward Euler over
  /// the step (mass-conserving film only: the Reynolds model has no step and keeps it 0).
  /// Without it the film sees the rigid approach velocity in full (quasi-static skirt).
  /// Default on, as the deck's liner.elastic_skirt.squeeze_rate: the modal scheme needs the
  /// rate's exact squeeze derivatives to carry a cycle.
  bool squeezeRate = true;
};

/// The lubricated skirt's parameters (LubricatedSkirtElement). The constructor checks those
/// that do not need the engine, addToModel() the rest; what the engine gives (the grid's
/// radius and skirt range, the piston travel and liner top when unset) is filled in there.
struct LubricatedSkirtParameters {
  /// Both sides' grids: arc width, node counts, clustering (side, radius and the skirt's
  /// height range are filled in from the engine).
  skirt::SkirtSideGridParameters grid;
  /// Gap terms; the piston travel (BDC/TDC pin heights) and the liner-top height are taken
  /// from the engine when unset (NaN). The grid's radius and skirt range always come from it.
  skirt::GapAssemblyParameters gap;
  lubrication::OilSpec oil;                           ///< oil data (grade)
  double oilTemperature_degC = 105.0;                 ///< film temperature [degC]
  lubrication::PatirChengParameters roughness;        ///< rq1 = liner, rq2 = skirt
  contact_forces::GreenwoodTrippParameters asperity;  ///< its roughness is set from `roughness`
  /// A contact law of the user's own, used on both sides instead of the Greenwood-Tripp law
  /// built from `asperity` (examples/contact_law/). Its compositeSigma_m() must be the
  /// roughness pair's sqrt(rq1^2 + rq2^2) (checked when the element joins a model).
  std::shared_ptr<const contact_forces::AsperityContactLaw> contactLaw;
  contact_forces::BoundaryFrictionParameters boundaryFriction;  ///< f_dry = 0.1
  skirt::SkirtLubricationParameters lubrication;                ///< cavitation model, solver, wear
  SupplyFilm supplyFilm;                                        ///< inlet oil film
  /// Oil transport on the liner (skirt/LinerOilFilm.h): when set, each side draws its inlet
  /// from a liner film carried from step to step (ring film, splash, what the skirt left)
  /// instead of supplyFilm; needs the mass-conserving film (its edge flows). The ring's height
  /// is above the pin axis; the flooded and splash heights are bore heights above the crank
  /// axis.
  std::optional<skirt::LinerOilParameters> linerOil;
  /// Mass-conserving model: order of the fill fraction's storage term in time. 2 = variable-
  /// step BDF2 over the last two accepted steps (default: second order like
  /// LinearlyImplicitStepper; on the starved example skirt it converges with the step where
  /// backward Euler still moved 13 % from 0.5 to 0.25 deg), 1 = backward Euler over the last
  /// accepted step (the numerics tests' reference).
  int fillFractionHistoryOrder = 2;
  bool tertiaryMotion = false;            ///< must match EngineDescription::tertiaryMotion
  double pinRetainerPlay_m = 0.5e-3;      ///< tertiary: free axial play each way [m], > 0
  double pinRetainerStiffness_Npm = 2e7;  ///< tertiary: spring outside the play [N/m], > 0
  /// Solve the two sides' films on two threads (the anti-thrust side on a helper thread the
  /// element owns). Results are bit-identical to the serial run: the sides share only
  /// read-only data and are summed in the same order. Off by default for library users
  /// (whose own threads may already use every core); the deck key liner.parallel_sides
  /// turns it on for `pistondyn run`. Also with the elastic skirt: both sides are always
  /// solved, also when one throws, so each side's warm start does not depend on the threads
  /// (tests ElasticParallelSides.TwoThreadsGiveTheSerialRows, LubricatedSkirt.ParallelSides...).
  bool parallelSides = false;
  ElasticSkirtParameters elasticSkirt;  ///< elastic skirt, off by default
};

/// The per-state results the element caches (small: no nodal fields).
struct LubricatedSkirtResults {
  /// A side's figures (skirt::SkirtSideFigures) and what its solve did.
  struct Side : skirt::SkirtSideFigures {
    /// The film solver's iterations in the side's last film solve (FilmResult::iterations,
    /// lubrication/FilmProblem.h; with the elastic skirt, the solve at the converged
    /// deformation).
    int filmIterations = 0;
    /// That film solve was finished by the reference solver's fallback
    /// (lubrication::FilmResult::usedFallback).
    bool filmUsedFallback = false;
    ///@{
    /// Elastic skirt only: film evaluations of the coupling and the largest elastic gap term
    /// [m] (+ opens the gap) of this evaluation.
    int elasticIterations = 0;
    double maxElasticDeformation_m = 0;
    ///@}
  };
  std::array<Side, 2> sides;                                    ///< [0] thrust, [1] anti-thrust
  Eigen::Vector3d skirtForce_N = Eigen::Vector3d::Zero();      ///< both sides, piston frame
  Eigen::Vector3d skirtMoment_Nm = Eigen::Vector3d::Zero();    ///< both sides, piston frame
  Eigen::Vector3d forceOnPiston_N = Eigen::Vector3d::Zero();    ///< ground, at the origin
  Eigen::Vector3d momentOnPiston_Nm = Eigen::Vector3d::Zero();  ///< ground, about the origin
  Eigen::Matrix3d dQ_dPose = Eigen::Matrix3d::Zero();           ///< PistonPose.h generalised forces
  /// NaN when the evaluation left the film's squeeze derivatives out
  /// (setForceJacobianWanted(false)); dQ_dPose stays exact.
  Eigen::Matrix3d dQ_dPoseRate = Eigen::Matrix3d::Zero();
  ///@{
  /// The skirt's axial friction force on the piston in the bore frame [N] (both sides: film shear,
  /// the film pressure's axial part on the sloped skirt, the tilt's share of the normal load,
  /// boundary friction), and the power it takes from the piston's primary motion,
  /// -frictionForce_N v_y [W], with its film and asperity parts (they sum to it).
  double frictionForce_N = 0;
  double frictionPower_W = 0;
  double hydrodynamicFrictionPower_W = 0, asperityFrictionPower_W = 0;
  ///@}
  ///@{
  /// The power the skirt forces take from the piston's secondary motion [W] (lateral, tilt,
  /// tertiary; squeeze damping and the asperities' give), and the power the two sides
  /// dissipate (films and asperity friction, >= 0) [W]. Over a periodic cycle the friction and
  /// the secondary work together equal the dissipated energy (the asperities' elastic energy
  /// returns).
  double secondaryMotionPower_W = 0;
  double dissipatedPower_W = 0;
  ///@}
  /// The secondary kinetic energy K of piston and pin [J] (lateral and tilt motion; this
  /// file's comment, "Slap events").
  double secondaryKineticEnergy_J = 0;
  /// The supply film (LubricatedSkirtParameters::supplyFilm) at this evaluation's crank angle
  /// [m]; not read with the liner oil transport (inletFilm_m).
  double supplyFilm_m = 0;
  ///@{
  /// Liner oil transport only: the mean liner film at each side's leading edge (the one the
  /// liner enters the gap through; interior columns) [m], and the oil on the liner per side
  /// after this evaluation's step [m^3].
  std::array<double, 2> inletFilm_m{0.0, 0.0};
  std::array<double, 2> linerOilVolume_m3{0.0, 0.0};
  ///@}
  double retainerForce_N = 0;  ///< tertiary: force of the pin retainer on the piston (+z)
};

/// The lubricated skirt-liner force element (this file's comment): the liner role, its nodal
/// fields and, with parameters.linerOil, its liner oil film.
class LubricatedSkirtElement final : public LinerElement,
                                     public NodalFieldSource,
                                     public LinerOilSource {
 public:
  /// Smallest impact kinetic energy of a counted slap event [J]: an approach whose peak
  /// secondary kinetic energy is below it is not counted (the film's small oscillations).
  static constexpr double kMinSlapEnergy_J = 1e-6;

  /// Checks the parameters that do not need the engine (the rest in addToModel()).
  explicit LubricatedSkirtElement(const LubricatedSkirtParameters& parameters);
  ~LubricatedSkirtElement() override;

  std::string getName() const override { return "lubricated_skirt"; }
  void addToModel(const ModelBuildContext& context) override;
  void realizeTopology(SimTK::State& s, ElementStateAllocator& alloc) const override;
  void calcForces(const SimTK::State& s, AppliedForces& forces) const override;
  void realizeAcceleration(const SimTK::State& s) const override;
  bool addForceJacobian(const SimTK::State& s, ForceJacobian& jacobian) const override;
  /// Not wanted: the evaluations solve the film without the pose's squeeze derivatives (about
  /// 40 % of a rigid skirt's solve on the 64 x 48 grid; the damping part of the Jacobian is
  /// then NaN, the stiffness part - asperity contact, pin retainer - stays). The elastic
  /// skirt's Newton scheme keeps them (its elastic rate reads the lateral column); the modal
  /// scheme has its own.
  void setForceJacobianWanted(bool wanted) const override { jacobianWanted_ = wanted; }
  ElementOutputs getOutputs() const override;

  // ---- LinerElement role ------------------------------------------------------------
  double getSideForce_N(const SimTK::State& s) const override;
  double getFrictionForce_N(const SimTK::State& s) const override;
  double getFrictionPower_W(const SimTK::State& s) const override;
  std::optional<double> getFrictionWork_J(const SimTK::State& s) const override;
  std::optional<double> getMinFilmThickness_m(const SimTK::State& s, SkirtSide side) const override;
  std::optional<double> getMinGapOverSigma(const SimTK::State& s, SkirtSide side) const override;
  std::optional<double> getLastSlapEnergy_J(const SimTK::State& s) const override;
  std::optional<double> getHotRunningClearance_m() const override;
  std::optional<double> getAsperityFrictionWork_J(const SimTK::State& s) const override {
    return integrals_.getValue(s, kAsperityFrictionWork);
  }
  std::optional<double> getDissipatedEnergy_J(const SimTK::State& s) const override {
    return integrals_.getValue(s, kDissipatedEnergy);
  }
  std::optional<double> getSecondaryMotionWork_J(const SimTK::State& s) const override {
    return integrals_.getValue(s, kSecondaryMotionWork);
  }
  /// Its nodal fields (NodalFieldSource below): the gap with its seven terms, the film gap,
  /// h/sigma, film pressure, fill fraction, asperity pressure and the Archard wear depth rate on
  /// both sides.
  const NodalFieldSource* getNodalFields() const override { return this; }
  /// Its liner oil film (LinerOilSource below) when parameters.linerOil is set.
  const LinerOilSource* getLinerOil() const override {
    return parameters_.linerOil ? this : nullptr;
  }
  /// Film solves, fallbacks, derivative failures and the time of the phases of both sides.
  std::optional<SolverCounters> getSolverCounters() const override { return counters_; }
  /// Both sides' histories (skirt::SkirtSideHistoryRecord.h), thrust side first: the
  /// mass-conserving film's fill fraction, the liner oil, the elastic skirt's deformation.
  std::vector<double> getWarmStartRecord(const SimTK::State& s) const override;
  /// Installs both sides' histories; throws std::invalid_argument naming the side when a
  /// record does not fit (another grid, a liner oil film this element does not carry).
  void setWarmStartRecord(SimTK::State& s, const std::vector<double>& record) const override;

  // ---- NodalFieldSource -------------------------------------------------------------
  std::vector<NodalFieldRegion> getNodalFieldRegions() const override;
  std::vector<NodalFieldDeclaration> getNodalFieldDeclarations() const override;
  void calcNodalFields(const SimTK::State& s, int region, Eigen::MatrixXd& values) const override;

  // ---- LinerOilSource (parameters.linerOil only; throws std::logic_error otherwise) ----
  Eigen::VectorXd getLinerOilRowHeights_m() const override;
  void calcLinerOilFilm(const SimTK::State& s, SkirtSide side,
                        Eigen::VectorXd& film_m) const override;
  LinerOilBalance calcLinerOilBalance(const SimTK::State& s) const override;

  // ---- for tests, dumps and studies -------------------------------------------------
  /// The parameters; once added to a model, with what the engine gives filled in (the gap's
  /// piston travel and liner top).
  const LubricatedSkirtParameters& getParameters() const { return parameters_; }
  /// The results of state s, computed on the first request for it and cached in s
  /// (ElementCache.h); s realized through Stage::Velocity at least (calcForces() asks there).
  const LubricatedSkirtResults& getResults(const SimTK::State& s) const;
  /// A side's gap assembly (its terms and data); throws std::logic_error before addToModel().
  const skirt::GapAssembly& getGapAssembly(SkirtSide side) const;
  /// A side's Simbody-free solver (its grid, gap assembly, last fields, elastic coupling);
  /// throws std::logic_error before addToModel().
  const skirt::SkirtSideSolver& getSideSolver(SkirtSide side) const;
  /// The film's dynamic viscosity [Pa s]: the oil's at oilTemperature_degC, set by
  /// addToModel() (0 before).
  double getViscosity_Pas() const { return viscosity_Pas_; }
  ///@{
  /// Gap fields and film/contact fields of the last evaluation (this file's comment: valid
  /// right after realizing a state); throw std::logic_error before addToModel().
  const skirt::GapFields& getLastGapFields(SkirtSide side) const;
  const skirt::SkirtSideResults& getLastSideResults(SkirtSide side) const;
  ///@}
  /// A side's Archard wear volume since the start of the run [m^3] (a continuous state).
  double getWearVolume_m3(const SimTK::State& s, SkirtSide side) const;
  /// The friction work's split since the start of the run [J] (continuous states).
  double getHydrodynamicFrictionWork_J(const SimTK::State& s) const {
    return integrals_.getValue(s, kHydrodynamicFrictionWork);
  }

  /// Slap events completed since the start of the run, those of impact energy >=
  /// kMinSlapEnergy_J (this file's comment, "Slap events").
  long getSlapEventCount(const SimTK::State& s) const;

 private:
  struct SlapTracker {
    int direction = 0;         ///< sign of v_G in the current approach (0: none yet)
    double peak_J = 0.0;       ///< peak K of the current approach
    double lastEvent_J = 0.0;  ///< impact energy of the last completed event
    long events = 0;           ///< completed events
  };
  struct Workspace;  ///< per-side solvers and their last solutions (mutable)
  /// The element's continuous states (integrals over the run).
  enum Integral : int {
    kFrictionWork,               ///< [J]
    kHydrodynamicFrictionWork,   ///< [J]
    kAsperityFrictionWork,       ///< [J]
    kWearVolumeThrust,           ///< Archard wear volume [m^3]
    kWearVolumeAntiThrust,       ///< [m^3]
    kDissipatedEnergy,           ///< [J]
    kSecondaryMotionWork,        ///< [J]
    kIntegralCount
  };

  /// One evaluation: read the State, solve both sides, sum, install the histories, add the pin
  /// retainer and turn the loads into ground, track slaps.
  void calcResults(const SimTK::State& s, LubricatedSkirtResults& r) const;
  /// Both sides (in parallel with parallelSides), their counters and clocks summed; rethrows a
  /// side's error with the crank angle.
  void solveSides(const SimTK::State& s, const skirt::SkirtSideMotion& motion,
                  double crankAngle_deg, double supplyFilm_m) const;
  /// The sides' loads, derivatives and figures into r (thrust first); the piston's axial
  /// velocity tells the liner film's leading edge.
  void sumSides(double axialVelocity_mps, LubricatedSkirtResults& r) const;
  /// Each side's history this evaluation leads to, installed if its step is accepted.
  // Throws std::invalid_argument (prefixed by `where`) when a warm-start history does not fit
  // the side: a fill fraction without the mass-conserving film, liner oil of another liner
  // film, an elastic deformation of another compliance or of a rigid skirt.
  void checkWarmStartHistory(const skirt::SkirtSideSolver& solver,
                             const skirt::SkirtSideHistory& history,
                             const std::string& where) const;
  void installHistories(const SimTK::State& s) const;
  /// The pin retainer (tertiary motion) and the loads in ground.
  void addRetainerAndRotate(const SimTK::State& s, const PistonPose& pose,
                            LubricatedSkirtResults& r) const;
  /// The powers of the skirt forces on the piston's primary and secondary motion.
  void calcPowers(const PistonPose& pose, LubricatedSkirtResults& r) const;
  /// The secondary kinetic energy and the slap tracker's update.
  void trackSlap(const SimTK::State& s, const PistonPose& pose, LubricatedSkirtResults& r) const;

  LubricatedSkirtParameters parameters_;
  const mbd::CrankTrain* crankTrain_ = nullptr;  ///< non-owning; the model owns both
  double viscosity_Pas_ = 0.0;
  std::unique_ptr<Workspace> workspace_;
  mutable bool jacobianWanted_ = true;  ///< a request of the stepper (setForceJacobianWanted)
  mutable SolverCounters counters_;      ///< since construction (getSolverCounters)
  ElementCache<LubricatedSkirtResults> cache_;
  ElementZ integrals_;  ///< indexed by Integral
  /// Each side's history (skirt::SkirtSideSolver.h: the film's fill fraction at the last
  /// accepted steps, the elastic skirt's accepted deformation and rate), [0] thrust.
  std::array<ElementAutoUpdateVariable<skirt::SkirtSideHistory>, 2> history_;
  ElementAutoUpdateVariable<SlapTracker> slap_;
};

}  // namespace pistondyn::plugin
