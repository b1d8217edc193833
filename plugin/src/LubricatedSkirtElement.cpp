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
#include "pistondyn/skirt/SkirtSideHistoryRecord.h"

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
  return common::interpolateOverCycle(crankAngle_deg, thickness_m, angle_deg);
}

// Per side: its solver (gap, film, contact, elastic coupling) and the last solution.
struct LubricatedSkirtElement::Workspace {
  std::array<std::unique_ptr<skirt::SkirtSideSolver>, 2> sides;
  std::array<skirt::SkirtSideSolution, 2> solutions;
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
  if (p.linerOil &&
      p.lubrication.cavitation != lubrication::CavitationModel::MassConserving)
    badParameter("linerOil (oil transport on the liner) needs the mass-conserving film "
                 "(lubrication.cavitation): the liner takes and receives the film's edge flows");
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

  skirt::SkirtSideSettings settings;
  settings.lubrication = parameters_.lubrication;
  settings.fillFractionHistoryOrder = parameters_.fillFractionHistoryOrder;
  settings.tertiaryMotion = parameters_.tertiaryMotion;
  settings.elasticRate = parameters_.elasticSkirt.squeezeRate;
  for (int k : {kThrust, kAntiThrust}) {
    skirt::SkirtSideGridParameters g = parameters_.grid;
    g.side = k == kThrust ? skirt::SkirtSide::Thrust : skirt::SkirtSide::AntiThrust;
    g.radius_m = 0.5 * engine.piston.bore_m;
    g.skirtTopHeight_m = engine.piston.skirtTopAbovePin_m;
    g.skirtLength_m = engine.piston.skirtLength_m;
    const skirt::SkirtSideGrid grid(g);
    std::unique_ptr<skirt::ElasticCoupling> coupling;
    if (parameters_.elasticSkirt.enabled) {
      // Checks the compliance against this side's grid (size, finiteness, coverage).
      const auto& liner = parameters_.elasticSkirt.liner;
      coupling = skirt::makeElasticCoupling(grid, parameters_.elasticSkirt.compliance,
                                            parameters_.elasticSkirt.coupling,
                                            liner ? &*liner : nullptr);
    }
    std::optional<skirt::LinerOilFilm> linerOil;
    if (parameters_.linerOil)  // checks the parameters against the skirt (ring above its top)
      linerOil.emplace(grid, *parameters_.linerOil, gap.travel.lowestPinHeight_m,
                       gap.travel.highestPinHeight_m);
    workspace_->sides[k] = std::make_unique<skirt::SkirtSideSolver>(
        grid, gap, flowFactors, contactLaw, friction, settings, std::move(coupling),
        std::move(linerOil));
  }
}

void LubricatedSkirtElement::realizeTopology(SimTK::State&, ElementStateAllocator& alloc) const {
  // The results depend on t, q, u and the fill / slap history, not on the z (friction work
  // and wear are integrals of the results): a stepper correcting z after an evaluation must
  // not make the next realization of that state solve the films again.
  cache_.allocate(alloc, SimTK::Stage::Dynamics, /*resultsDependOnZ=*/false);
  integrals_.allocate(alloc, SimTK::Vector(kIntegralCount, 0.0));
  for (auto& history : history_)
    history.allocate(alloc, skirt::SkirtSideHistory{});  // empty: a full film at rest
  slap_.allocate(alloc, SlapTracker{});
}

std::vector<double> LubricatedSkirtElement::getWarmStartRecord(const SimTK::State& s) const {
  // Per side: the film grid's nodes around and along it (a record from another grid is
  // refused by its shape, not only its node count), then the side's history.
  std::vector<double> record;
  for (int k : {kThrust, kAntiThrust}) {
    const skirt::SkirtSideGrid& grid = workspace_->sides[k]->getGrid();
    record.push_back(grid.nPhi());
    record.push_back(grid.nY());
    skirt::appendSkirtSideRecord(history_[k].getValue(s), record);
  }
  return record;
}

void LubricatedSkirtElement::setWarmStartRecord(SimTK::State& s,
                                                const std::vector<double>& record) const {
  std::size_t offset = 0;
  for (int k : {kThrust, kAntiThrust}) {
    const std::string where = getName() + ", " + (k == kThrust ? "thrust" : "anti-thrust") +
                              " side: ";
    const skirt::SkirtSideSolver& solver = *workspace_->sides[k];
    const skirt::SkirtSideGrid& grid = solver.getGrid();
    if (offset + 2 > record.size())
      throw std::invalid_argument(where + "the warm-start record is cut short");
    const double nPhi = record[offset], nY = record[offset + 1];
    offset += 2;
    if (nPhi != grid.nPhi() || nY != grid.nY()) {
      throw std::invalid_argument(where + common::message("the record is of another film grid: ",
                                                         nPhi, " x ", nY, " nodes, this one ",
                                                         grid.nPhi(), " x ", grid.nY()));
    }
    skirt::SkirtSideHistory h;
    try {
      h = skirt::readSkirtSideRecord(record, offset, static_cast<std::size_t>(grid.nodeCount()));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(where + e.what());
    }
    checkWarmStartHistory(solver, h, where);
    history_[k].setValue(s, h);
  }
  if (offset != record.size()) {
    throw std::invalid_argument(getName() + ": the warm-start record holds " +
                                std::to_string(record.size() - offset) +
                                " numbers more than the two sides' histories");
  }
}

void LubricatedSkirtElement::checkWarmStartHistory(const skirt::SkirtSideSolver& solver,
                                                   const skirt::SkirtSideHistory& h,
                                                   const std::string& where) const {
  const bool massConserving =
      parameters_.lubrication.cavitation == lubrication::CavitationModel::MassConserving;
  if (!h.film.empty() && !massConserving) {
    throw std::invalid_argument(where +
                                "the record holds a fill fraction, this skirt's film has none "
                                "(liner.film.cavitation: reynolds)");
  }
  const skirt::LinerOilFilm* liner = solver.getLinerOilFilm();
  if (!h.liner.empty()) {
    if (liner == nullptr) {
      throw std::invalid_argument(where +
                                  "the record holds liner oil, this skirt has no liner oil film "
                                  "(liner.oil_supply.liner_transport)");
    }
    const long cells = static_cast<long>(liner->rows()) * liner->columns();
    if (h.liner.volume_m3.size() != cells) {
      throw std::invalid_argument(
          where + common::message("the record's liner oil has ", h.liner.volume_m3.size(),
                                  " cells, this liner's film ", cells,
                                  " (another stroke, ring height or grid?)"));
    }
  }
  const skirt::ElasticCoupling* coupling = solver.getElasticCoupling();
  const auto& e = h.elastic;
  if (e.gapTerm_m.size() != 0 || e.structural_m.size() != 0 || e.structuralRate_mps.size() != 0) {
    if (coupling == nullptr)
      throw std::invalid_argument(where + "the record holds an elastic skirt's deformation, this "
                                          "skirt is rigid");
    const long n = coupling->structuralNodeCount();
    if ((e.structural_m.size() != 0 && e.structural_m.size() != n) ||
        (e.structuralRate_mps.size() != 0 && e.structuralRate_mps.size() != n)) {
      throw std::invalid_argument(
          where + common::message("the record's deformation is of ", e.structural_m.size(),
                                  " structural nodes, this skirt's compliance has ", n));
    }
  }
}

const LubricatedSkirtResults& LubricatedSkirtElement::getResults(const SimTK::State& s) const {
  return cache_.getOrCalc(s, [&](LubricatedSkirtResults& r) { calcResults(s, r); });
}

void LubricatedSkirtElement::calcResults(const SimTK::State& s, LubricatedSkirtResults& r) const {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const mbd::CrankTrain& ct = *crankTrain_;
  const PistonPose pose = calcPistonPose(ct, s);
  const skirt::SkirtSideMotion motion{
      {pose.lateral_m, pose.tilt_rad, pose.transverse_m},
      {pose.lateralRate_mps, pose.tiltRate_radps, pose.transverseRate_mps},
      pose.pinHeight_m,
      pose.axialVelocity_mps};
  const double crankAngle_deg = ct.getCrankAngle_rad(s) * 180.0 / M_PI;
  r.supplyFilm_m = parameters_.supplyFilm.calcThickness_m(crankAngle_deg);
  solveSides(s, motion, crankAngle_deg, r.supplyFilm_m);
  sumSides(motion.axialVelocity_mps, r);
  installHistories(s);
  addRetainerAndRotate(s, pose, r);
  calcPowers(pose, r);
  trackSlap(s, pose, r);
  counters_.total_s += std::chrono::duration<double>(Clock::now() - start).count();
  ++counters_.evaluations;
}

void LubricatedSkirtElement::solveSides(const SimTK::State& s,
                                        const skirt::SkirtSideMotion& motion,
                                        double crankAngle_deg, double supplyFilm_m) const {
  const ElasticSkirtParameters& elastic = parameters_.elasticSkirt;
  skirt::SkirtSideConditions conditions;
  conditions.viscosity_Pas = viscosity_Pas_;
  conditions.supplyFilm_m = supplyFilm_m;
  conditions.crankAngle_deg = crankAngle_deg;
  conditions.poseDerivativesWanted = jacobianWanted_;
  conditions.cylinderGaugePressure_Pa =
      elastic.enabled && elastic.cylinderPressure
          ? elastic.cylinderPressure->calcPressure_Pa(crankAngle_deg) - elastic.crankcasePressure_Pa
          : 0.0;
  const bool massConserving =
      parameters_.lubrication.cavitation == lubrication::CavitationModel::MassConserving;
  // The histories and steps are read here, not in a worker.
  std::array<skirt::SkirtSideConditions, 2> sideConditions{conditions, conditions};
  std::array<const skirt::SkirtSideHistory*, 2> histories{};
  for (int k : {kThrust, kAntiThrust}) {
    histories[k] = &history_[k].getValue(s);
    sideConditions[k].stepSinceHistory_s =
        massConserving ? history_[k].calcTimeSinceLastUpdate(s) : 0.0;
  }
  // Both sides are always solved, also when one of them fails, and the thrust side's error is
  // the one reported: each side's film solver and elastic coupling keep their last iterate as
  // the next warm start, so a side skipped because the other one threw would start its next
  // evaluation from a different guess than it does on two threads.
  std::array<std::exception_ptr, 2> errors;
  auto attemptSide = [&](int k) {
    try {
      workspace_->sides[k]->solve(motion, sideConditions[k], *histories[k],
                                  workspace_->solutions[k]);
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
  // Every film solve is counted and timed where it ran, also in an evaluation that throws: a
  // step that is retried must not hide its solves and fallbacks from summary.json.
  for (int k : {kThrust, kAntiThrust}) {
    const skirt::SkirtSideCounters& c = workspace_->solutions[k].counters;
    counters_.filmSolves += c.filmSolves;
    counters_.filmFallbacks += c.filmFallbacks;
    counters_.derivativeFailures += c.derivativeFailures;
    counters_.gap_s += c.gap_s;
    counters_.film_s += c.film_s;
    counters_.contact_s += c.contact_s;
    counters_.loads_s += c.loads_s;
    counters_.coupling_s += c.coupling_s;
  }
  try {
    for (const std::exception_ptr& error : errors)
      if (error)
        std::rethrow_exception(error);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(common::message("lubricated skirt at crank angle ",
                                             common::wrapCrankAngle_deg(crankAngle_deg),
                                             " deg: ", e.what()));
  }
}

void LubricatedSkirtElement::sumSides(double axialVelocity_mps, LubricatedSkirtResults& r) const {
  skirt::PistonLoads total;
  Eigen::Matrix<double, 6, 3> dRate = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix<double, 6, 3> dPose = Eigen::Matrix<double, 6, 3>::Zero();
  r.dissipatedPower_W = 0.0;
  bool poseDerivatives = true;
  for (int k : {kThrust, kAntiThrust}) {  // thrust first: the sums do not depend on threads
    const skirt::SkirtSideSolver& solver = *workspace_->sides[k];
    const skirt::SkirtSideResults& out = solver.getResults();
    const skirt::SkirtSideSolution& solution = workspace_->solutions[k];
    LubricatedSkirtResults::Side& side = r.sides[k];
    static_cast<skirt::SkirtSideFigures&>(side) = out;
    side.filmIterations = out.film.iterations;
    side.filmUsedFallback = out.film.usedFallback;
    if (solver.getElasticCoupling()) {
      side.elasticIterations = solution.elastic.iterations;
      side.maxElasticDeformation_m = solution.elastic.maxDeformation_m;
    }
    poseDerivatives = poseDerivatives && solution.poseDerivatives;
    total.force_N += out.totalLoads.force_N;
    total.moment_Nm += out.totalLoads.moment_Nm;
    dRate += out.dLoads_dPoseRate;
    dPose += out.dLoads_dPose;
    r.dissipatedPower_W += out.dissipatedPower_W;
    if (const skirt::LinerOilFilm* liner = solver.getLinerOilFilm()) {
      // The leading edge: the top while the piston rises (the liner enters from above).
      const Eigen::ArrayXd& inlet = axialVelocity_mps >= 0.0 ? solver.getSupplyTop_m()
                                                               : solver.getSupplyBottom_m();
      const Eigen::Index n = inlet.size();
      r.inletFilm_m[k] = n > 2 ? inlet.segment(1, n - 2).mean() : inlet.mean();
      r.linerOilVolume_m3[k] = liner->storedVolume_m3(solution.next.liner);
    }
  }
  r.skirtForce_N = total.force_N;
  r.skirtMoment_Nm = total.moment_Nm;
  // The stiff part of the Jacobian in the pose coordinates (the tilt's rotation of the loads
  // is left out: it multiplies the loads, not their stiff derivatives).
  for (int c = 0; c < 3; ++c) {
    r.dQ_dPoseRate.col(c) = poseForces(dRate.col(c));
    r.dQ_dPose.col(c) = poseForces(dPose.col(c));
  }
  if (!poseDerivatives)  // left out (setForceJacobianWanted): never read as zero damping
    r.dQ_dPoseRate.setConstant(std::numeric_limits<double>::quiet_NaN());
}

void LubricatedSkirtElement::installHistories(const SimTK::State& s) const {
  for (int k : {kThrust, kAntiThrust}) {
    const skirt::SkirtSideSolution& solution = workspace_->solutions[k];
    if (solution.historyAdvanced)
      history_[k].setUpdateValue(s, solution.next);
  }
}

void LubricatedSkirtElement::addRetainerAndRotate(const SimTK::State& s, const PistonPose& pose,
                                                  LubricatedSkirtResults& r) const {
  // Pin retainer (tertiary motion): a spring outside the axial play.
  r.retainerForce_N = 0.0;
  if (parameters_.tertiaryMotion) {
    const double excess = std::abs(pose.transverse_m) - parameters_.pinRetainerPlay_m;
    if (excess > 0.0) {
      r.retainerForce_N =
          -std::copysign(parameters_.pinRetainerStiffness_Npm * excess, pose.transverse_m);
      r.dQ_dPose(2, 2) -= parameters_.pinRetainerStiffness_Npm;
    }
  }
  // Piston frame -> ground (the piston is tilted by alpha).
  const SimTK::Rotation& R = crankTrain_->getPiston().getBodyRotation(s);
  const Eigen::Vector3d& fp = r.skirtForce_N;
  const Eigen::Vector3d& mp = r.skirtMoment_Nm;
  const SimTK::Vec3 f = R * SimTK::Vec3(fp[0], fp[1], fp[2]);
  const SimTK::Vec3 m = R * SimTK::Vec3(mp[0], mp[1], mp[2]);
  r.forceOnPiston_N = Eigen::Vector3d(f[0], f[1], f[2] + r.retainerForce_N);
  r.momentOnPiston_Nm = Eigen::Vector3d(m[0], m[1], m[2]);
}

void LubricatedSkirtElement::calcPowers(const PistonPose& pose, LubricatedSkirtResults& r) const {
  // The skirt's forces in the bore frame (the pin retainer's spring is not friction).
  const Eigen::Vector3d f = r.forceOnPiston_N - Eigen::Vector3d(0.0, 0.0, r.retainerForce_N);
  const Eigen::Vector3d& m = r.momentOnPiston_Nm;
  r.frictionForce_N = f[1];
  r.frictionPower_W = -f[1] * pose.axialVelocity_mps;
  // Coulomb friction of the asperities along the axis: their exact dissipation there.
  double asperityAxial_N = 0.0;
  for (const auto& side : r.sides)
    asperityAxial_N += side.asperityFrictionAxial_N;
  r.asperityFrictionPower_W = -asperityAxial_N * pose.axialVelocity_mps;
  r.hydrodynamicFrictionPower_W = r.frictionPower_W - r.asperityFrictionPower_W;
  // Secondary motion: the origin's lateral and tertiary velocity, the tilt rate about -z.
  r.secondaryMotionPower_W = -(f[0] * pose.lateralRate_mps + f[2] * pose.transverseRate_mps -
                               m[2] * pose.tiltRate_radps);
}

void LubricatedSkirtElement::trackSlap(const SimTK::State& s, const PistonPose& pose,
                                       LubricatedSkirtResults& r) const {
  // Secondary kinetic energy of the piston and pin (the header's slap events).
  const mbd::EngineDescription& engine = crankTrain_->getEngine();
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
  integrals_.setDerivative(s, kFrictionWork, r.frictionPower_W);
  integrals_.setDerivative(s, kHydrodynamicFrictionWork, r.hydrodynamicFrictionPower_W);
  integrals_.setDerivative(s, kAsperityFrictionWork, r.asperityFrictionPower_W);
  integrals_.setDerivative(s, kWearVolumeThrust, r.sides[kThrust].wearRate_m3ps);
  integrals_.setDerivative(s, kWearVolumeAntiThrust, r.sides[kAntiThrust].wearRate_m3ps);
  integrals_.setDerivative(s, kDissipatedEnergy, r.dissipatedPower_W);
  integrals_.setDerivative(s, kSecondaryMotionWork, r.secondaryMotionPower_W);
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
  return getResults(s).frictionForce_N;
}

double LubricatedSkirtElement::getFrictionPower_W(const SimTK::State& s) const {
  return getResults(s).frictionPower_W;
}

std::optional<double> LubricatedSkirtElement::getFrictionWork_J(const SimTK::State& s) const {
  return integrals_.getValue(s, kFrictionWork);
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
  if (!workspace_->sides[kThrust])
    return std::nullopt;
  return std::min(
      workspace_->sides[kThrust]->getGapAssembly().getHotRunningClearance().clearance_m,
      workspace_->sides[kAntiThrust]->getGapAssembly().getHotRunningClearance().clearance_m);
}

// ---- LinerOilSource -------------------------------------------------------------------

namespace {

const skirt::LinerOilFilm& linerOilOf(const skirt::SkirtSideSolver& solver) {
  const skirt::LinerOilFilm* liner = solver.getLinerOilFilm();
  if (!liner)
    throw std::logic_error("LubricatedSkirtElement: no liner oil film (parameters.linerOil)");
  return *liner;
}

}  // namespace

Eigen::VectorXd LubricatedSkirtElement::getLinerOilRowHeights_m() const {
  const skirt::LinerOilFilm& liner = linerOilOf(*workspace_->sides[kThrust]);
  Eigen::VectorXd h(liner.rows());
  for (int m = 0; m < liner.rows(); ++m)
    h[m] = liner.rowHeight_m(m);
  return h;
}

void LubricatedSkirtElement::calcLinerOilFilm(const SimTK::State& s, SkirtSide side,
                                              Eigen::VectorXd& film_m) const {
  const int k = sideIndex(side);
  const skirt::LinerOilFilm& liner = linerOilOf(*workspace_->sides[k]);
  const skirt::SkirtSideHistory& history = history_[k].getValue(s);
  if (history.liner.empty()) {  // before the first accepted step: the start
    film_m.setConstant(liner.rows(), liner.getParameters().initialFilm_m);
    return;
  }
  Eigen::ArrayXd film;
  liner.calcMeanFilmPerRow(history.liner, film);
  film_m = film.matrix();
}

LinerOilBalance LubricatedSkirtElement::calcLinerOilBalance(const SimTK::State& s) const {
  LinerOilBalance b;
  for (int k : {kThrust, kAntiThrust}) {
    const skirt::LinerOilFilm& liner = linerOilOf(*workspace_->sides[k]);
    const skirt::LinerOilState& state = history_[k].getValue(s).liner;
    if (state.empty())
      continue;
    // The start is the initial film on the rows free at the run's first step.
    b.initial_m3 += liner.storedVolume_m3(state) - state.flows.netSource_m3();
    b.stored_m3 += liner.storedVolume_m3(state);
    b.flows += state.flows;
  }
  return b;
}

const skirt::SkirtSideSolver& LubricatedSkirtElement::getSideSolver(SkirtSide side) const {
  const auto& solver = workspace_->sides[sideIndex(side)];
  if (!solver)
    throw std::logic_error("LubricatedSkirtElement: not added to a model yet");
  return *solver;
}

const skirt::GapAssembly& LubricatedSkirtElement::getGapAssembly(SkirtSide side) const {
  return getSideSolver(side).getGapAssembly();
}

const skirt::GapFields& LubricatedSkirtElement::getLastGapFields(SkirtSide side) const {
  return getSideSolver(side).getGapFields();
}

const skirt::SkirtSideResults& LubricatedSkirtElement::getLastSideResults(SkirtSide side) const {
  return getSideSolver(side).getResults();
}

double LubricatedSkirtElement::getWearVolume_m3(const SimTK::State& s, SkirtSide side) const {
  return integrals_.getValue(s, side == SkirtSide::Thrust ? kWearVolumeThrust : kWearVolumeAntiThrust);
}

std::vector<NodalFieldRegion> LubricatedSkirtElement::getNodalFieldRegions() const {
  std::vector<NodalFieldRegion> regions;
  for (const SkirtSide side : {SkirtSide::Thrust, SkirtSide::AntiThrust}) {
    const skirt::SkirtSideGrid& grid = getSideSolver(side).getGrid();
    regions.push_back({side == SkirtSide::Thrust ? "thrust" : "antithrust", grid.nPhi(), grid.nY(),
                       grid.getNodePhi_rad(), grid.getNodeY_m()});
  }
  return regions;
}

std::vector<NodalFieldDeclaration> LubricatedSkirtElement::getNodalFieldDeclarations() const {
  return {{"gap", "um"},           {"rigid", "um"},          {"skirt_profile", "um"},
          {"liner_shape", "um"},   {"piston_thermal", "um"}, {"liner_thermal", "um"},
          {"piston_elastic", "um"}, {"liner_elastic", "um"}, {"film_gap", "um"},
          {"h_over_sigma", "1"},   {"film_pressure", "Pa"},  {"fill_fraction", "1"},
          {"contact_pressure", "Pa"},
          // Archard wear depth rate of the liner, k/H p_c |U| (0 when the wear coefficient is).
          {"wear_depth_rate", "um_per_h"}};
}

void LubricatedSkirtElement::calcNodalFields(const SimTK::State& s, int region,
                                             Eigen::MatrixXd& values) const {
  const SkirtSide side = region == kThrust ? SkirtSide::Thrust : SkirtSide::AntiThrust;
  const skirt::SkirtSideSolver& solver = getSideSolver(side);
  const skirt::GapFields& gap = solver.getGapFields();
  const skirt::SkirtSideResults& r = solver.getResults();
  // The solvers keep the fields of their last evaluation: they must be this state's.
  const LubricatedSkirtResults::Side& cached = getResults(s).sides[region];
  if (r.minFilmThickness_m != cached.minFilmThickness_m ||
      r.hydrodynamicNormalForce_N != cached.hydrodynamicNormalForce_N)
    throw std::runtime_error(
        "the lubricated skirt's last fields are not those of the state asked for");
  const Eigen::Index n = gap.gap_m.size();
  const Eigen::Map<const Eigen::ArrayXd> ratio(r.contact.filmRatio.data(), n);
  const Eigen::Map<const Eigen::ArrayXd> contact(r.contact.pressure_Pa.data(), n);
  values.resize(n, 14);
  const Eigen::ArrayXd* microns[] = {&gap.gap_m,           &gap.rigid_m,         &gap.skirtProfile_m,
                                     &gap.linerShape_m,    &gap.pistonThermal_m, &gap.linerThermal_m,
                                     &gap.pistonElastic_m, &gap.linerElastic_m,  &r.filmGap_m};
  for (int c = 0; c < 9; ++c)
    values.col(c) = (*microns[c] * 1e6).matrix();
  values.col(9) = ratio.matrix();
  values.col(10) = r.film.pressure_Pa().matrix();
  values.col(11) = r.film.fillFraction().matrix();
  values.col(12) = contact.matrix();
  // k/H |U| p_c per node: the side's maxWearDepthRate_mps (k/H |U| max p_c) scaled by p_c / max
  // p_c, so that the field's largest value is that figure exactly.
  const double maxContact_Pa = n > 0 ? contact.maxCoeff() : 0.0;
  values.col(13).setZero();
  if (maxContact_Pa > 0.0)
    values.col(13) = (contact * (r.maxWearDepthRate_mps * 1e6 * 3600.0 / maxContact_Pa)).matrix();
}

ElementOutputs LubricatedSkirtElement::getOutputs() const {
  using S = const SimTK::State&;
  auto side = [this](S s, int k) -> const LubricatedSkirtResults::Side& {
    return getResults(s).sides[k];
  };
  const auto role = [this](LinerOutput which) {
    return makeLinerOutput(which, *this, *crankTrain_);
  };
  ElementOutputs o = {
      role(LinerOutput::SideForce),
      {"liner_moment", "Nm",
       "moment about +z the piston exerts on the liner, about the piston-frame origin",
       [this](S s) { return -getResults(s).momentOnPiston_Nm[2]; }},
      role(LinerOutput::LateralAtSkirtTop),
      role(LinerOutput::LateralAtSkirtBottom),
      {"hydrodynamic_normal_force_thrust", "N", "load carried by the film, thrust side",
       [side](S s) { return side(s, kThrust).hydrodynamicNormalForce_N; }},
      {"hydrodynamic_normal_force_antithrust", "N", "load carried by the film, anti-thrust side",
       [side](S s) { return side(s, kAntiThrust).hydrodynamicNormalForce_N; }},
      {"asperity_normal_force_thrust", "N", "load carried by the asperities, thrust side",
       [side](S s) { return side(s, kThrust).asperityNormalForce_N; }},
      {"asperity_normal_force_antithrust", "N", "load carried by the asperities, anti-thrust side",
       [side](S s) { return side(s, kAntiThrust).asperityNormalForce_N; }},
      {"hydrodynamic_friction", "N",
       "the film's share of friction_force (shear, pressure on the sloped and tilted skirt)",
       [this, side](S s) {
         return getFrictionForce_N(s) - (side(s, kThrust).asperityFrictionAxial_N +
                                         side(s, kAntiThrust).asperityFrictionAxial_N);
       }},
      {"asperity_friction", "N", "boundary friction force on the piston along +y (both sides)",
       [side](S s) {
         return side(s, kThrust).asperityFrictionAxial_N +
                side(s, kAntiThrust).asperityFrictionAxial_N;
       }},
      role(LinerOutput::FrictionForce),
      role(LinerOutput::FrictionPower),
      role(LinerOutput::FrictionWork),
      {"dissipated_power", "W",
       "power dissipated by the films (viscous) and the asperity friction, both sides, >= 0",
       [this](S s) { return getResults(s).dissipatedPower_W; }},
      {"secondary_motion_power", "W",
       "power the skirt forces take from the piston's secondary motion (lateral, tilt, tertiary)",
       [this](S s) { return getResults(s).secondaryMotionPower_W; }},
      role(LinerOutput::MinFilmThrust),
      role(LinerOutput::MinFilmAntiThrust),
      role(LinerOutput::MinGapOverSigmaThrust),
      role(LinerOutput::MinGapOverSigmaAntiThrust),
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
  if (parameters_.linerOil) {
    for (int k : {kThrust, kAntiThrust}) {
      const std::string n = names[k];
      o.push_back({"inlet_film_" + n, "um",
                   "liner oil film at the skirt's leading edge (mean over the arc), " + n +
                       " side",
                   [this, k](S s) { return 1e6 * getResults(s).inletFilm_m[k]; }});
      o.push_back({"liner_oil_volume_" + n, "mm3",
                   "oil on the liner along the bore (outside the skirt), " + n + " side",
                   [this, k](S s) { return 1e9 * getResults(s).linerOilVolume_m3[k]; }});
    }
  } else if (!supply.crankAngle_deg.empty() || std::isfinite(supply.constant_m)) {
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
