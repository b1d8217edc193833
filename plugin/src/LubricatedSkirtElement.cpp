#include "pistondyn/plugin/LubricatedSkirtElement.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "pistondyn/common/CrankAngle.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/mbd_models/SliderCrank.h"
#include "pistondyn/plugin/PistonPose.h"

#include "ForkJoinWorker.h"

namespace pistondyn::plugin {
namespace {

constexpr int kThrust = 0, kAntiThrust = 1;

int sideIndex(SkirtSide side) {
  return side == SkirtSide::Thrust ? kThrust : kAntiThrust;
}

[[noreturn]] void badParameter(const std::string& what) {
  throw std::invalid_argument("LubricatedSkirtParameters: " + what);
}

// Generalised pose forces Q = (F_x, -M_z, F_z) from a (force; moment) column (PistonPose.h).
Eigen::Vector3d poseForces(const Eigen::Matrix<double, 6, 1>& loads) {
  return {loads[0], -loads[5], loads[2]};
}

}  // namespace

double SupplyFilm::calcThickness_m(double angle_deg) const {
  if (crankAngle_deg.empty())
    return constant_m;
  const std::size_t n = crankAngle_deg.size();
  double a = common::wrapCrankAngle_deg(angle_deg);
  // Periodic linear interpolation: the segment after the last point wraps to the first.
  const auto it = std::upper_bound(crankAngle_deg.begin(), crankAngle_deg.end(), a);
  const std::size_t hi = static_cast<std::size_t>(it - crankAngle_deg.begin()) % n;
  const std::size_t lo = (hi + n - 1) % n;
  const double a0 = crankAngle_deg[lo];
  double a1 = crankAngle_deg[hi];
  if (a1 <= a0)
    a1 += 720.0;
  if (a < a0)
    a += 720.0;
  const double w = (a - a0) / (a1 - a0);
  return (1.0 - w) * thickness_m[lo] + w * thickness_m[hi];
}

// Per side: the gap assembly, the film/contact solver and their fields.
struct LubricatedSkirtElement::Workspace {
  std::array<std::unique_ptr<skirt::GapAssembly>, 2> gap;
  std::array<std::unique_ptr<skirt::SkirtSideLubrication>, 2> lubrication;
  std::array<skirt::GapFields, 2> gapFields;
  std::array<skirt::SkirtSideResults, 2> results;
  // Elastic skirt: one coupling per side (its warm start is the side's last deformation).
  std::array<std::unique_ptr<skirt::ElasticCoupling>, 2> elastic;
  std::array<skirt::ElasticCouplingReport, 2> elasticReports;
  std::array<Eigen::MatrixXd, 2> modalRateBasis;  // -Psi / dt per side (modal scheme)
  std::array<Eigen::MatrixXd, 2> modalGapBasis;   // -Psi per side (exact static derivative)
  std::array<Eigen::VectorXd, 2> elasticStart;     // the coupling's start per side
  std::unique_ptr<detail::ForkJoinWorker> worker;  // parallelSides: the anti-thrust side
};

LubricatedSkirtElement::LubricatedSkirtElement(const LubricatedSkirtParameters& p)
    : parameters_(p), workspace_(std::make_unique<Workspace>()) {
  if (!(p.oilTemperature_degC > -273.15) || !std::isfinite(p.oilTemperature_degC))
    badParameter("oilTemperature_degC must be finite and above absolute zero");
  const SupplyFilm& f = p.supplyFilm;
  if (f.crankAngle_deg.empty()) {
    if (!(f.constant_m > 0.0))
      badParameter("supplyFilm.constant_m must be positive (or +inf)");
  } else {
    if (f.crankAngle_deg.size() != f.thickness_m.size() || f.crankAngle_deg.size() < 2)
      badParameter("supplyFilm table: crank angles and thicknesses need the same size, >= 2");
    for (std::size_t i = 0; i < f.crankAngle_deg.size(); ++i) {
      if (!(f.crankAngle_deg[i] >= 0.0 && f.crankAngle_deg[i] < 720.0) ||
          (i > 0 && !(f.crankAngle_deg[i] > f.crankAngle_deg[i - 1])))
        badParameter("supplyFilm table: crank angles must increase strictly within [0, 720) deg");
      if (!(f.thickness_m[i] > 0.0) || !std::isfinite(f.thickness_m[i]))
        badParameter("supplyFilm table: thicknesses must be positive and finite");
    }
  }
  if (!(p.pinRetainerPlay_m > 0.0) || !std::isfinite(p.pinRetainerPlay_m))
    badParameter("pinRetainerPlay_m must be positive and finite");
  if (!(p.pinRetainerStiffness_Npm > 0.0) || !std::isfinite(p.pinRetainerStiffness_Npm))
    badParameter("pinRetainerStiffness_Npm must be positive and finite");
  if (p.fillFractionHistoryOrder != 1 && p.fillFractionHistoryOrder != 2)
    badParameter("fillFractionHistoryOrder must be 1 (backward Euler) or 2 (BDF2)");
  if (p.elasticSkirt.enabled) {
    if (!p.gap.terms.pistonElastic)
      badParameter("elasticSkirt.enabled needs the gap term switch gap.terms.pistonElastic on");
    if (!(std::isfinite(p.elasticSkirt.crankcasePressure_Pa) &&
          p.elasticSkirt.crankcasePressure_Pa >= 0.0))
      badParameter("elasticSkirt.crankcasePressure_Pa must be finite and >= 0");
  }
  if (p.elasticSkirt.liner && !p.elasticSkirt.enabled)
    badParameter("elasticSkirt.liner needs the elastic skirt (elasticSkirt.enabled with the "
                 "skirt's compliance): the liner is coupled through the skirt's structural grid");
}

LubricatedSkirtElement::~LubricatedSkirtElement() = default;

void LubricatedSkirtElement::addToModel(const ModelBuildContext& context) {
  crankTrain_ = &context.crankTrain;
  const mbd::EngineDescription& engine = crankTrain_->getEngine();
  if (engine.tertiaryMotion != parameters_.tertiaryMotion) {
    throw std::invalid_argument(
        "LubricatedSkirtElement: the crank train was built with the tertiary motion " +
        std::string(engine.tertiaryMotion ? "on" : "off") + " but the element has it " +
        (parameters_.tertiaryMotion ? "on" : "off") + " (set both the same)");
  }
  viscosity_Pas_ =
      lubrication::Oil(parameters_.oil).calcDynamicViscosity_Pas(parameters_.oilTemperature_degC);

  // The engine fills in what the deck does not repeat: radius, skirt range, travel, liner top.
  const mbd::SliderCrank kinematics(engine.geometry);
  skirt::GapAssemblyParameters gap = parameters_.gap;
  if (!std::isfinite(gap.travel.lowestPinHeight_m))
    gap.travel.lowestPinHeight_m = kinematics.pinHeightAtBdc_m();
  if (!std::isfinite(gap.travel.highestPinHeight_m))
    gap.travel.highestPinHeight_m = kinematics.pinHeightAtTdc_m();
  if (!std::isfinite(gap.linerTopHeight_m)) {
    // Default: the liner top is level with the crown at TDC.
    gap.linerTopHeight_m = kinematics.pinHeightAtTdc_m() + engine.piston.compressionHeight_m;
  }
  parameters_.gap = gap;

  auto flowFactors =
      std::make_shared<const lubrication::PatirChengFlowFactors>(parameters_.roughness);
  contact_forces::GreenwoodTrippParameters gt = parameters_.asperity;
  gt.roughnessSurface1_m = parameters_.roughness.rq1_m;  // roughness entered once (liner)
  gt.roughnessSurface2_m = parameters_.roughness.rq2_m;  // (skirt)
  parameters_.asperity = gt;
  const std::shared_ptr<const contact_forces::AsperityContactLaw> contactLaw =
      parameters_.contactLaw ? parameters_.contactLaw
                             : std::make_shared<const contact_forces::GreenwoodTrippLaw>(gt);
  const contact_forces::BoundaryFriction friction(parameters_.boundaryFriction);

  for (int k : {kThrust, kAntiThrust}) {
    skirt::SkirtSideGridParameters g = parameters_.grid;
    g.side = k == kThrust ? skirt::SkirtSide::Thrust : skirt::SkirtSide::AntiThrust;
    g.radius_m = 0.5 * engine.piston.bore_m;
    g.skirtTopHeight_m = engine.piston.skirtTopAbovePin_m;
    g.skirtLength_m = engine.piston.skirtLength_m;
    const skirt::SkirtSideGrid grid(g);
    workspace_->gap[k] = std::make_unique<skirt::GapAssembly>(grid, gap);
    workspace_->lubrication[k] = std::make_unique<skirt::SkirtSideLubrication>(
        grid, flowFactors, contactLaw, friction, parameters_.lubrication);
    workspace_->gapFields[k] = workspace_->gap[k]->makeFields();
    if (parameters_.elasticSkirt.enabled) {
      // Checks the compliance against this side's grid (size, finiteness, coverage).
      const auto& liner = parameters_.elasticSkirt.liner;
      workspace_->elastic[k] = std::make_unique<skirt::ElasticCoupling>(
          grid, parameters_.elasticSkirt.compliance, parameters_.elasticSkirt.coupling,
          liner ? &*liner : nullptr);
    }
  }
}

void LubricatedSkirtElement::realizeTopology(SimTK::State&, ElementStateAllocator& alloc) const {
  // The results depend on t, q, u and the fill / slap history, not on the z (friction work
  // and wear are integrals of the results): a stepper correcting z after an evaluation must
  // not make the next realization of that state solve the films again.
  cache_.allocate(alloc, SimTK::Stage::Dynamics, /*resultsDependOnZ=*/false);
  work_.allocate(alloc, SimTK::Vector(5, 0.0));
  fillThrust_.allocate(alloc, FillHistory{});  // empty: full film
  fillAntiThrust_.allocate(alloc, FillHistory{});
  slap_.allocate(alloc, SlapTracker{});
}

const LubricatedSkirtResults& LubricatedSkirtElement::getResults(const SimTK::State& s) const {
  return cache_.getOrCalc(s, [&](LubricatedSkirtResults& r) { calcResults(s, r); });
}

void LubricatedSkirtElement::calcResults(const SimTK::State& s, LubricatedSkirtResults& r) const {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const mbd::CrankTrain& ct = *crankTrain_;
  const mbd::EngineDescription& engine = ct.getEngine();
  const PistonPose pose = calcPistonPose(ct, s);
  const skirt::PistonPose skirtPose{pose.lateral_m, pose.tilt_rad, pose.transverse_m};
  const skirt::PistonPoseRate skirtRate{pose.lateralRate_mps, pose.tiltRate_radps,
                                        pose.transverseRate_mps};
  const double crankAngle_deg = ct.getCrankAngle_rad(s) * 180.0 / M_PI;
  r.supplyFilm_m = parameters_.supplyFilm.calcThickness_m(crankAngle_deg);
  const bool massConserving =
      parameters_.lubrication.cavitation == lubrication::CavitationModel::MassConserving;

  skirt::PistonLoads total;
  Eigen::Matrix<double, 6, 3> dRate = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix<double, 6, 3> dPose = Eigen::Matrix<double, 6, 3>::Zero();
  r.frictionPower_W = r.hydrodynamicFrictionPower_W = r.asperityFrictionPower_W = 0.0;
  // Per side: the inputs from the State (main thread), then gap and film (the two sides
  // concurrently with parallelSides: they share nothing but read-only data), then the
  // history and the sums (main thread, thrust first, so the results do not depend on it).
  std::array<skirt::SkirtSideInputs, 2> inputs;
  // The squeeze derivatives serve only the stepper's Jacobian, except in the elastic coupling.
  // (the Newton scheme's elastic rate reads the lateral column; the modal scheme its own ones).
  const bool withJacobian =
      jacobianWanted_ || (parameters_.elasticSkirt.enabled &&
                          parameters_.elasticSkirt.coupling.scheme !=
                              skirt::ElasticCouplingScheme::Modal);
  std::array<double, 2> dts{0.0, 0.0};
  std::array<const FillHistory*, 2> histories{nullptr, nullptr};  // read here, not in a worker
  for (int k : {kThrust, kAntiThrust}) {
    const auto& fill = k == kThrust ? fillThrust_ : fillAntiThrust_;
    skirt::SkirtSideInputs& in = inputs[k];
    in.slidingVelocityAxial_mps = -pose.axialVelocity_mps;
    // The skirt's tangential velocity on the side's centre line is +dz_t/dt on the thrust
    // side (e_phi = +z at phi = 0) and -dz_t/dt on the anti-thrust side.
    in.slidingVelocityCircumferential_mps =
        k == kThrust ? -pose.transverseRate_mps : pose.transverseRate_mps;
    in.viscosity_Pas = viscosity_Pas_;
    in.supplyFilm_m = r.supplyFilm_m;
    in.squeezeColumns = withJacobian ? (parameters_.tertiaryMotion ? 3 : 2) : 0;
    if (massConserving) {
      const FillHistory& history = fill.getValue(s);
      histories[k] = &history;
      in.previousFillFraction = history.current.size() > 0 ? &history.current : nullptr;
      in.previousExpectedGap = history.currentGap.size() > 0 ? &history.currentGap : nullptr;
      const double dt = fill.calcTimeSinceLastUpdate(s);
      dts[k] = dt;
      in.timeStep_s = dt > 0.0 ? dt : std::numeric_limits<double>::infinity();
      if (parameters_.fillFractionHistoryOrder == 2 && history.previous.size() > 0 &&
          history.previousStep_s > 0.0) {
        in.previousFillFraction2 = &history.previous;
        in.previousExpectedGap2 = &history.previousGap;
        in.previousTimeStep_s = history.previousStep_s;
      }
    }
  }
  // Every film solve of the side (an elastic coupling does several), counted and timed where
  // it runs so that a fallback or a failed derivative solve in a coupling iteration, or in an
  // evaluation that throws, is not lost, and the film time matches the solve count (summed on
  // this thread after the join).
  std::array<long, 2> solves{0, 0}, fallbacks{0, 0}, derivativeFailures{0, 0};
  std::array<double, 2> gapTimes{0.0, 0.0}, filmTimes{0.0, 0.0}, contactTimes{0.0, 0.0},
      loadsTimes{0.0, 0.0}, couplingTimes{0.0, 0.0};
  const ElasticSkirtParameters& elastic = parameters_.elasticSkirt;
  const double gasGauge_Pa =
      elastic.enabled && elastic.cylinderPressure
          ? elastic.cylinderPressure->calcPressure_Pa(crankAngle_deg) - elastic.crankcasePressure_Pa
          : 0.0;
  auto solveSide = [&](int k) {
    skirt::GapFields& fields = workspace_->gapFields[k];
    auto gapAndFilm = [&] {
      const auto gapStart = Clock::now();
      workspace_->gap[k]->calc(skirtPose, skirtRate, pose.pinHeight_m, pose.axialVelocity_mps,
                               fields);
      gapTimes[k] += std::chrono::duration<double>(Clock::now() - gapStart).count();
      // Counted also when the solve throws (not converged, fallback included): a step that
      // is retried must not hide its solves and fallbacks from summary.json.
      const auto count = [&] {
        const skirt::SkirtSideResults& side = workspace_->results[k];
        const lubrication::FilmResult& film = side.film;
        filmTimes[k] += side.filmTime_s;
        contactTimes[k] += side.contactTime_s;
        loadsTimes[k] += side.loadsTime_s;
        ++solves[k];
        fallbacks[k] += film.usedFallback ? 1 : 0;
        derivativeFailures[k] += film.derivativesFailed ? 1 : 0;
      };
      try {
        workspace_->lubrication[k]->solve(fields, inputs[k], workspace_->results[k]);
      } catch (const std::runtime_error&) {
        count();
        throw;
      }
      count();
    };
    skirt::ElasticCoupling* coupling = workspace_->elastic[k].get();
    // The elastic term's rate from the last accepted step (backward Euler, like the fill
    // fraction's storage term).
    const FillHistory* history = histories[k];
    const double dt = dts[k];
    const bool elasticRate = coupling && parameters_.elasticSkirt.squeezeRate && history &&
                             history->elastic_m.size() == fields.gap_m.size() && dt > 0.0;
    if (!coupling) {
      gapAndFilm();
      return;
    }
    // An elastic liner: its compliance seen from the skirt at the pin's height now (the
    // modes and their film shapes follow).
    if (coupling->hasLiner())
      coupling->setLinerPosition(pose.pinHeight_m);
    if (elasticRate && history->elasticStructural_m.size() == coupling->structuralNodeCount()) {
      // The start: the accepted deformation moved on at its last rate (FillHistory).
      Eigen::VectorXd& warm = workspace_->elasticStart[k];
      warm = history->elasticStructural_m;
      if (history->elasticStructuralRate_mps.size() == warm.size())
        warm += dt * history->elasticStructuralRate_mps;
      coupling->setStart(warm);
    }
    // Modal scheme with the elastic rate: the film's squeeze derivatives of the modal shapes
    // through the backward-Euler rate, d(dh_el/dt)/dw_j = -Psi_j / dt.
    const skirt::ElasticCouplingScheme scheme = coupling->getParameters().scheme;
    const bool modalRate = scheme == skirt::ElasticCouplingScheme::Modal && elasticRate;
    // Modal scheme, exact static part: the film's pressure derivative for the gap shapes
    // d h_el / d w_j = -Psi_j (constant: the shapes are the coupling's); with the rate, the
    // same columns carry its squeeze part too (gap-rate basis -Psi_j / dt), so the film
    // returns the total dp/dw_j in one back-substitution per mode.
    const bool modalGap = scheme == skirt::ElasticCouplingScheme::Modal &&
                          parameters_.elasticSkirt.exactStaticDerivative;
    Eigen::MatrixXd& modalBasis = workspace_->modalRateBasis[k];
    if (modalRate)
      modalBasis = (-1.0 / dt) * coupling->modalShapes();
    Eigen::MatrixXd& gapBasis = workspace_->modalGapBasis[k];
    if (modalGap && (gapBasis.cols() != coupling->modeCount() || coupling->hasLiner()))
      gapBasis = -coupling->modalShapes();  // the liner moves the shapes with the piston
    // Per evaluation: the modal sensitivities only when the coupling will read them
    // (FilmPressureEvaluation::sensitivitiesWanted; ElasticCouplingParameters::
    // modalJacobianReuse).
    const auto setSensitivityBases = [&](bool wanted) {
      inputs[k].extraSqueezeBasis = wanted && modalRate && !modalGap ? &modalBasis : nullptr;
      inputs[k].extraGapRateBasis = wanted && modalRate && modalGap ? &modalBasis : nullptr;
      inputs[k].extraGapBasis = wanted && modalGap ? &gapBasis : nullptr;
    };
    // The coupling's last film evaluation is the one of its returned deformation, so the
    // results left in the workspace belong to the converged gap.
    // The coupling's own work (mapping, modal algebra): its time less its film evaluations'.
    const auto couplingStart = std::chrono::steady_clock::now();
    const double evaluationsBefore = gapTimes[k] + filmTimes[k] + contactTimes[k] + loadsTimes[k];
    const skirt::ElasticCouplingReport report = coupling->solve(
        [&](const Eigen::ArrayXd& elastic_m, skirt::FilmPressureEvaluation& out) {
          const bool sensitivities = out.sensitivitiesWanted;
          setSensitivityBases(sensitivities);
          fields.pistonElastic_m = elastic_m;
          if (elasticRate)
            fields.pistonElasticRate_mps = (elastic_m - history->elastic_m) / dt;
          else
            fields.pistonElasticRate_mps.setZero();
          gapAndFilm();
          const skirt::SkirtSideResults& res = workspace_->results[k];
          out.normalPressure_Pa = res.normalPressure_Pa;
          out.minFilmThickness_m = res.minFilmThickness_m;
          if (scheme != skirt::ElasticCouplingScheme::Aitken) {
            const Eigen::Index n = res.normalPressure_Pa.size();
            const Eigen::Map<const Eigen::ArrayXd> pc(res.contact.pressure_Pa.data(), n);
            const Eigen::Map<const Eigen::ArrayXd> slope(res.contact.dPressure_dGap_PaPerM.data(),
                                                         n);
            if (modalGap) {
              // The film's part is exact (below; with the rate's squeeze part when modalRate);
              // the asperities' own slope is what it lacks.
              out.pressureStiffness_Pa_per_m = (-slope).max(0.0);
              if (sensitivities)
                out.pressureGapSensitivity_Pa_per_m = res.film.dPressure_dGap;
              else
                out.pressureGapSensitivity_Pa_per_m.resize(0, 0);
            } else {
              skirt::localPressureStiffness(res.normalPressure_Pa, pc, res.filmGap_m, slope,
                                            workspace_->lubrication[k]->getCompositeSigma_m(),
                                            out.pressureStiffness_Pa_per_m);
              out.pressureGapSensitivity_Pa_per_m.resize(0, 0);
            }
            if (modalRate && !modalGap && sensitivities) {
              out.pressureRateSensitivity_Pa_per_m =
                  res.film.dPressure_dVelocity.rightCols(modalBasis.cols());
            } else if (scheme == skirt::ElasticCouplingScheme::Modal) {  // modalRate is modal
              out.pressureRateSensitivity_Pa_per_m.resize(0, 0);
            } else if (elasticRate) {
              // The squeeze part: d p / d(dh/dt) / dt, estimated node by node from the film's
              // lateral squeeze derivative (dh/dt = -cos(phi) de/dt there).
              const auto lateral = res.film.dPressure_dVelocity.col(0).array();
              const auto basis = fields.squeezeBasis.col(0).array();
              out.pressureStiffness_Pa_per_m +=
                  lateral.abs() / (basis.abs().max(0.2) * dt);
            }
          }
        },
        gasGauge_Pa);
    couplingTimes[k] +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - couplingStart).count() -
        (gapTimes[k] + filmTimes[k] + contactTimes[k] + loadsTimes[k] - evaluationsBefore);
    workspace_->elasticReports[k] = report;
    if (!report.converged)
      throw std::runtime_error(common::message(
          "elastic skirt (", k == kThrust ? "thrust" : "anti-thrust", " side) did not converge in ",
          report.iterations, " film evaluations: deformation change ", report.residual_m,
          " m > tolerance ", report.tolerance_m,
          " m (raise elasticSkirt.coupling.maxIterations or the tolerance; a residual that "
          "stalls just above the tolerance is the film solver's noise: tighten the film's "
          "tolerance, e.g. liner.film.tolerance 1e-11)"));
  };
  try {
    // Both sides are always solved, also when one of them fails, and the thrust side's error is
    // the one reported: each side's film solver and elastic coupling keep their last iterate as
    // the next warm start, so a side skipped because the other one threw would start its next
    // evaluation from a different guess than it does on two threads. (That was the elastic
    // skirt's "parallel gives another trajectory": a coupling that fails on a rejected trial
    // step, one side only; its next solve then converged to other last bits, and the adaptive
    // stepper amplified them. Traced 2026-12-03.)
    std::array<std::exception_ptr, 2> errors;
    auto attemptSide = [&](int k) {
      try {
        solveSide(k);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    };
    if (parameters_.parallelSides) {
      if (!workspace_->worker)
        workspace_->worker = std::make_unique<detail::ForkJoinWorker>();
      workspace_->worker->start([&] { attemptSide(kAntiThrust); });
      attemptSide(kThrust);
      workspace_->worker->join();  // always: the task refers to this frame
    } else {
      attemptSide(kThrust);
      attemptSide(kAntiThrust);
    }
    filmSolves_ += solves[kThrust] + solves[kAntiThrust];
    timings_.gap_s += gapTimes[kThrust] + gapTimes[kAntiThrust];
    timings_.film_s += filmTimes[kThrust] + filmTimes[kAntiThrust];
    timings_.contact_s += contactTimes[kThrust] + contactTimes[kAntiThrust];
    timings_.loads_s += loadsTimes[kThrust] + loadsTimes[kAntiThrust];
    timings_.coupling_s += couplingTimes[kThrust] + couplingTimes[kAntiThrust];
    filmFallbacks_ += fallbacks[kThrust] + fallbacks[kAntiThrust];
    filmDerivativeFailures_ += derivativeFailures[kThrust] + derivativeFailures[kAntiThrust];
    for (const std::exception_ptr& error : errors)
      if (error)
        std::rethrow_exception(error);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(common::message("lubricated skirt at crank angle ",
                                             common::wrapCrankAngle_deg(crankAngle_deg),
                                             " deg: ", e.what()));
  }

  for (int k : {kThrust, kAntiThrust}) {
    const auto& fill = k == kThrust ? fillThrust_ : fillAntiThrust_;
    const double dt = dts[k];
    const skirt::SkirtSideResults& out = workspace_->results[k];
    if (massConserving) {
      // The history this step leads to, if accepted (a zero step keeps the history).
      const FillHistory& history = fill.getValue(s);
      // The elastic term is the state's at this time, whatever the step (also a zero one).
      const skirt::ElasticCoupling* coupling = workspace_->elastic[k].get();
      const Eigen::ArrayXd elasticNow = coupling ? coupling->pistonElastic_m() : Eigen::ArrayXd();
      const Eigen::VectorXd structuralNow =
          coupling ? coupling->structuralDisplacement_m() : Eigen::VectorXd();
      if (dt > 0.0) {
        Eigen::VectorXd structuralRate;
        if (coupling && history.elasticStructural_m.size() == structuralNow.size())
          structuralRate = (structuralNow - history.elasticStructural_m) / dt;
        fill.setUpdateValue(s, FillHistory{out.film.fillFraction(), out.film.expectedGap_m,
                                           history.current, history.currentGap, dt, elasticNow,
                                           structuralNow, structuralRate});
      } else {
        fill.setUpdateValue(s, FillHistory{out.film.fillFraction(), out.film.expectedGap_m,
                                           history.previous, history.previousGap,
                                           history.previousStep_s, elasticNow, structuralNow,
                                           history.elasticStructuralRate_mps});
      }
    }

    LubricatedSkirtResults::Side& side = r.sides[k];
    side.hydrodynamic = out.hydrodynamicLoads;
    side.asperity = out.asperityLoads;
    side.hydrodynamicNormalForce_N = out.hydrodynamicNormalForce_N;
    side.asperityNormalForce_N = out.asperityNormalForce_N;
    side.hydrodynamicFrictionAxial_N = out.hydrodynamicFrictionAxial_N;
    side.asperityFrictionAxial_N = out.asperityFrictionAxial_N;
    side.frictionPower_W = out.frictionPower_W;
    side.minFilmThickness_m = out.minFilmThickness_m;
    side.minGapOverSigma = out.minGapOverSigma;
    side.hydrodynamicShare = out.hydrodynamicShare;
    side.mixedShare = out.mixedShare;
    side.boundaryShare = out.boundaryShare;
    side.wettedShare = out.wettedShare;
    side.wearRate_m3ps = out.wearRate_m3ps;
    side.filmOilVolume_m3 = out.filmOilVolume_m3;
    side.filmIterations = out.film.iterations;
    side.filmUsedFallback = out.film.usedFallback;
    if (workspace_->elastic[k]) {
      side.elasticIterations = workspace_->elasticReports[k].iterations;
      side.maxElasticDeformation_m = workspace_->elasticReports[k].maxDeformation_m;
    }
    total.force_N += out.totalLoads.force_N;
    total.moment_Nm += out.totalLoads.moment_Nm;
    dRate += out.dLoads_dPoseRate;
    dPose += out.dLoads_dPose;
    r.frictionPower_W += out.frictionPower_W;
    r.hydrodynamicFrictionPower_W += out.hydrodynamicFrictionPower_W;
    r.asperityFrictionPower_W += out.asperityFrictionPower_W;
  }

  // Pin retainer (tertiary motion): a spring outside the axial play.
  r.retainerForce_N = 0.0;
  double retainerStiffness = 0.0;
  if (parameters_.tertiaryMotion) {
    const double excess = std::abs(pose.transverse_m) - parameters_.pinRetainerPlay_m;
    if (excess > 0.0) {
      r.retainerForce_N =
          -std::copysign(parameters_.pinRetainerStiffness_Npm * excess, pose.transverse_m);
      retainerStiffness = parameters_.pinRetainerStiffness_Npm;
    }
  }

  // Piston frame -> ground (the piston is tilted by alpha).
  const SimTK::Rotation& R = ct.getPiston().getBodyRotation(s);
  const SimTK::Vec3 f = R * SimTK::Vec3(total.force_N[0], total.force_N[1], total.force_N[2]);
  const SimTK::Vec3 m = R * SimTK::Vec3(total.moment_Nm[0], total.moment_Nm[1], total.moment_Nm[2]);
  r.forceOnPiston_N = Eigen::Vector3d(f[0], f[1], f[2] + r.retainerForce_N);
  r.momentOnPiston_Nm = Eigen::Vector3d(m[0], m[1], m[2]);
  // The stiff part of the Jacobian in the pose coordinates (the tilt's rotation of the loads
  // is left out: it multiplies the loads, not their stiff derivatives).
  for (int c = 0; c < 3; ++c) {
    r.dQ_dPoseRate.col(c) = poseForces(dRate.col(c));
    r.dQ_dPose.col(c) = poseForces(dPose.col(c));
  }
  r.dQ_dPose(2, 2) -= retainerStiffness;
  if (!withJacobian)  // left out (setForceJacobianWanted): never read as zero damping
    r.dQ_dPoseRate.setConstant(std::numeric_limits<double>::quiet_NaN());

  // Secondary kinetic energy (slap tracking).
  const double mass = engine.mass.piston.mass_kg + engine.mass.pin.mass_kg;
  const double vG = pose.lateralRate_mps + engine.mass.piston.comY_m * pose.tiltRate_radps;
  r.secondaryKineticEnergy_J = 0.5 * mass * vG * vG + 0.5 * engine.mass.piston.inertiaZZ_kgm2 *
                                                          pose.tiltRate_radps * pose.tiltRate_radps;
  SlapTracker next = slap_.getValue(s);
  const int direction = vG > 0.0 ? 1 : (vG < 0.0 ? -1 : 0);
  if (next.direction == 0) {
    next.direction = direction;
    next.peak_J = r.secondaryKineticEnergy_J;
  } else if (direction == next.direction || direction == 0) {
    next.peak_J = std::max(next.peak_J, r.secondaryKineticEnergy_J);
  } else {
    if (next.peak_J >= kMinSlapEnergy_J) {
      next.lastEvent_J = next.peak_J;
      ++next.events;
    }
    next.direction = direction;
    next.peak_J = r.secondaryKineticEnergy_J;
  }
  slap_.setUpdateValue(s, next);
  timings_.total_s += std::chrono::duration<double>(Clock::now() - start).count();
  ++timings_.evaluations;
}

void LubricatedSkirtElement::calcForces(const SimTK::State& s, AppliedForces& forces) const {
  const LubricatedSkirtResults& r = getResults(s);
  const SimTK::MobilizedBody& piston = crankTrain_->getPiston();
  forces.addForceAtStation(
      s, piston, SimTK::Vec3(0),
      SimTK::Vec3(r.forceOnPiston_N[0], r.forceOnPiston_N[1], r.forceOnPiston_N[2]));
  forces.addTorque(
      s, piston,
      SimTK::Vec3(r.momentOnPiston_Nm[0], r.momentOnPiston_Nm[1], r.momentOnPiston_Nm[2]));
}

void LubricatedSkirtElement::realizeAcceleration(const SimTK::State& s) const {
  const LubricatedSkirtResults& r = getResults(s);
  work_.setDerivative(s, 0, r.frictionPower_W);
  work_.setDerivative(s, 1, r.hydrodynamicFrictionPower_W);
  work_.setDerivative(s, 2, r.asperityFrictionPower_W);
  work_.setDerivative(s, 3, r.sides[kThrust].wearRate_m3ps);
  work_.setDerivative(s, 4, r.sides[kAntiThrust].wearRate_m3ps);
}

bool LubricatedSkirtElement::addForceJacobian(const SimTK::State& s,
                                              ForceJacobian& jacobian) const {
  const LubricatedSkirtResults& r = getResults(s);
  addPoseForceJacobian(*crankTrain_, s, r.dQ_dPose, r.dQ_dPoseRate, jacobian);
  return true;
}

double LubricatedSkirtElement::getSideForce_N(const SimTK::State& s) const {
  return -getResults(s).forceOnPiston_N[0];
}

double LubricatedSkirtElement::getFrictionForce_N(const SimTK::State& s) const {
  const LubricatedSkirtResults& r = getResults(s);
  double f = 0.0;
  for (const auto& side : r.sides)
    f += side.hydrodynamicFrictionAxial_N + side.asperityFrictionAxial_N;
  return f;
}

double LubricatedSkirtElement::getFrictionPower_W(const SimTK::State& s) const {
  return getResults(s).frictionPower_W;
}

std::optional<double> LubricatedSkirtElement::getFrictionWork_J(const SimTK::State& s) const {
  return work_.getValue(s, 0);
}

std::optional<double> LubricatedSkirtElement::getMinFilmThickness_m(const SimTK::State& s,
                                                                    SkirtSide side) const {
  return getResults(s).sides[sideIndex(side)].minFilmThickness_m;
}

std::optional<double> LubricatedSkirtElement::getMinGapOverSigma(const SimTK::State& s,
                                                                 SkirtSide side) const {
  return getResults(s).sides[sideIndex(side)].minGapOverSigma;
}

std::optional<double> LubricatedSkirtElement::getLastSlapEnergy_J(const SimTK::State& s) const {
  return slap_.getValue(s).lastEvent_J;
}

long LubricatedSkirtElement::getSlapEventCount(const SimTK::State& s) const {
  return slap_.getValue(s).events;
}

std::optional<double> LubricatedSkirtElement::getHotRunningClearance_m() const {
  if (!workspace_->gap[kThrust])
    return std::nullopt;
  return std::min(workspace_->gap[kThrust]->getHotRunningClearance().clearance_m,
                  workspace_->gap[kAntiThrust]->getHotRunningClearance().clearance_m);
}

const skirt::GapAssembly& LubricatedSkirtElement::getGapAssembly(SkirtSide side) const {
  const auto& g = workspace_->gap[sideIndex(side)];
  if (!g)
    throw std::logic_error("LubricatedSkirtElement: not added to a model yet");
  return *g;
}

const skirt::GapFields& LubricatedSkirtElement::getLastGapFields(SkirtSide side) const {
  return workspace_->gapFields[sideIndex(side)];
}

const skirt::SkirtSideResults& LubricatedSkirtElement::getLastSideResults(SkirtSide side) const {
  return workspace_->results[sideIndex(side)];
}

double LubricatedSkirtElement::getWearVolume_m3(const SimTK::State& s, SkirtSide side) const {
  return work_.getValue(s, side == SkirtSide::Thrust ? 3 : 4);
}

ElementOutputs LubricatedSkirtElement::getOutputs() const {
  using S = const SimTK::State&;
  const mbd::PistonGeometry& pg = crankTrain_->getEngine().piston;
  const double yTop = pg.skirtTopAbovePin_m, yBottom = pg.skirtTopAbovePin_m - pg.skirtLength_m;
  auto side = [this](S s, int k) -> const LubricatedSkirtResults::Side& {
    return getResults(s).sides[k];
  };
  ElementOutputs o = {
      {"side_force", "N", "lateral force the piston exerts on the liner, + towards thrust",
       [this](S s) { return getSideForce_N(s); }},
      {"liner_moment", "Nm",
       "moment about +z the piston exerts on the liner, about the piston-frame origin",
       [this](S s) { return -getResults(s).momentOnPiston_Nm[2]; }},
      {"u_lat_skirt_top", "um", "lateral displacement of the piston axis at the skirt top",
       [this, yTop](S s) {
         return 1e6 * (crankTrain_->getLateralDisplacement_m(s) +
                       yTop * std::sin(crankTrain_->getTilt_rad(s)));
       }},
      {"u_lat_skirt_bottom", "um", "lateral displacement of the piston axis at the skirt bottom",
       [this, yBottom](S s) {
         return 1e6 * (crankTrain_->getLateralDisplacement_m(s) +
                       yBottom * std::sin(crankTrain_->getTilt_rad(s)));
       }},
      {"hydrodynamic_normal_force_thrust", "N", "load carried by the film, thrust side",
       [side](S s) { return side(s, kThrust).hydrodynamicNormalForce_N; }},
      {"hydrodynamic_normal_force_antithrust", "N", "load carried by the film, anti-thrust side",
       [side](S s) { return side(s, kAntiThrust).hydrodynamicNormalForce_N; }},
      {"asperity_normal_force_thrust", "N", "load carried by the asperities, thrust side",
       [side](S s) { return side(s, kThrust).asperityNormalForce_N; }},
      {"asperity_normal_force_antithrust", "N", "load carried by the asperities, anti-thrust side",
       [side](S s) { return side(s, kAntiThrust).asperityNormalForce_N; }},
      {"hydrodynamic_friction", "N", "film shear force on the piston along +y (both sides)",
       [side](S s) {
         return side(s, kThrust).hydrodynamicFrictionAxial_N +
                side(s, kAntiThrust).hydrodynamicFrictionAxial_N;
       }},
      {"asperity_friction", "N", "boundary friction force on the piston along +y (both sides)",
       [side](S s) {
         return side(s, kThrust).asperityFrictionAxial_N +
                side(s, kAntiThrust).asperityFrictionAxial_N;
       }},
      {"friction_force", "N", "total skirt friction force on the piston along +y",
       [this](S s) { return getFrictionForce_N(s); }},
      {"friction_power", "W", "power dissipated by skirt friction (film and asperities)",
       [this](S s) { return getFrictionPower_W(s); }},
      {"friction_work", "J", "friction work since the start of the run (integrated state)",
       [this](S s) { return *getFrictionWork_J(s); }},
      {"min_film_thickness_thrust", "um", "smallest nominal gap, thrust side",
       [side](S s) { return 1e6 * side(s, kThrust).minFilmThickness_m; }},
      {"min_film_thickness_antithrust", "um", "smallest nominal gap, anti-thrust side",
       [side](S s) { return 1e6 * side(s, kAntiThrust).minFilmThickness_m; }},
      {"min_h_over_sigma_thrust", "1", "smallest gap / composite roughness, thrust side",
       [side](S s) { return side(s, kThrust).minGapOverSigma; }},
      {"min_h_over_sigma_antithrust", "1", "smallest gap / composite roughness, anti-thrust side",
       [side](S s) { return side(s, kAntiThrust).minGapOverSigma; }},
  };
  const char* names[2] = {"thrust", "antithrust"};
  for (int k : {kThrust, kAntiThrust}) {
    const std::string n = names[k];
    o.push_back({"hydrodynamic_share_" + n, "1", "area share with h/sigma > 3, " + n + " side",
                 [side, k](S s) { return side(s, k).hydrodynamicShare; }});
    o.push_back({"mixed_share_" + n, "1", "area share with 1 < h/sigma <= 3, " + n + " side",
                 [side, k](S s) { return side(s, k).mixedShare; }});
    o.push_back({"boundary_share_" + n, "1", "area share with h/sigma <= 1, " + n + " side",
                 [side, k](S s) { return side(s, k).boundaryShare; }});
    o.push_back({"wetted_share_" + n, "1",
                 "area share with oil (fill fraction > 0), " + n + " side",
                 [side, k](S s) { return side(s, k).wettedShare; }});
    o.push_back({"film_oil_volume_" + n, "mm3",
                 "oil held in the film (area x fill fraction x gap), " + n + " side",
                 [side, k](S s) { return 1e9 * side(s, k).filmOilVolume_m3; }});
  }
  o.push_back({"secondary_kinetic_energy", "mJ",
               "1/2 m v_G^2 + 1/2 I (dalpha/dt)^2 of the secondary motion (piston + pin)",
               [this](S s) { return 1e3 * getResults(s).secondaryKineticEnergy_J; }});
  o.push_back({"slap_energy", "mJ", "impact kinetic energy of the last completed slap event",
               [this](S s) { return 1e3 * slap_.getValue(s).lastEvent_J; }});
  o.push_back(
      {"wear_rate", "mm3ph", "Archard wear volume rate of the liner, both sides", [side](S s) {
         return 3.6e12 * (side(s, kThrust).wearRate_m3ps + side(s, kAntiThrust).wearRate_m3ps);
       }});
  // A fully flooded skirt (infinite supply) has no supply column: outputs are finite.
  const SupplyFilm& supply = parameters_.supplyFilm;
  if (!supply.crankAngle_deg.empty() || std::isfinite(supply.constant_m)) {
    o.push_back({"supply_film", "um", "oil film on the liner ahead of the skirt",
                 [this](S s) { return 1e6 * getResults(s).supplyFilm_m; }});
  }
  if (parameters_.elasticSkirt.enabled) {
    for (int k : {kThrust, kAntiThrust}) {
      const std::string n = names[k];
      o.push_back({"elastic_iterations_" + n, "1",
                   "film evaluations of the elastic coupling, " + n + " side",
                   [side, k](S s) { return double(side(s, k).elasticIterations); }});
      o.push_back({"max_elastic_deformation_" + n, "um",
                   "largest elastic gap term of the skirt (+ opens the gap), " + n + " side",
                   [side, k](S s) { return 1e6 * side(s, k).maxElasticDeformation_m; }});
    }
  }
  if (parameters_.tertiaryMotion) {
    o.push_back({"retainer_force", "N", "pin-retainer force on the piston along +z",
                 [this](S s) { return getResults(s).retainerForce_N; }});
  }
  return o;
}

}  // namespace pistondyn::plugin
