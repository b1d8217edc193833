#include "pistondyn/skirt/SkirtSideSolver.h"

#include <chrono>
#include <stdexcept>

#include "pistondyn/common/Validation.h"

namespace pistondyn::skirt {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

const char* sideName(SkirtSide side) {
  return side == SkirtSide::Thrust ? "thrust" : "anti-thrust";
}

}  // namespace

struct SkirtSideSolver::Impl {
  SkirtSideSettings settings;
  GapAssembly gap;
  SkirtSideLubrication lubrication;
  std::unique_ptr<ElasticCoupling> coupling;
  GapFields fields;
  SkirtSideResults results;
  SkirtSideInputs inputs;
  Eigen::VectorXd elasticStart;  // the coupling's start (scratch)
  std::optional<LinerOilFilm> linerOil;
  LinerOilState initialLiner;              // the liner's start when the history has none
  const LinerOilState* linerStart = nullptr;  // the state this evaluation starts from
  Eigen::ArrayXd supplyBottom, supplyTop;  // the liner's supply per column [m]
  lubrication::FilmHistory sameInstant;    // a film solved again at its history's instant

  Impl(const SkirtSideGrid& grid, const GapAssemblyParameters& gapParameters,
       std::shared_ptr<const lubrication::FlowFactorModel> flowFactors,
       std::shared_ptr<const contact_forces::AsperityContactLaw> contactLaw,
       const contact_forces::BoundaryFriction& friction, const SkirtSideSettings& s,
       std::unique_ptr<ElasticCoupling> c, std::optional<LinerOilFilm> liner)
      : settings(s),
        gap(grid, gapParameters),
        lubrication(grid, std::move(flowFactors), std::move(contactLaw), friction, s.lubrication),
        coupling(std::move(c)),
        fields(gap.makeFields()),
        linerOil(std::move(liner)) {
    if (linerOil && !massConserving())
      common::throwInvalidArgument(
          "SkirtSideSolver", "the liner oil film needs the mass-conserving film (its edge flows)");
    if (linerOil && linerOil->columns() != grid.nPhi())
      common::throwInvalidArgument("SkirtSideSolver",
                                   "the liner oil film was built on another grid");
    if (s.fillFractionHistoryOrder != 1 && s.fillFractionHistoryOrder != 2)
      common::throwInvalidArgument("SkirtSideSolver",
                                   "settings.fillFractionHistoryOrder must be 1 (backward Euler) "
                                   "or 2 (BDF2)");
    if (coupling && coupling->filmNodeCount() != grid.nodeCount())
      common::throwInvalidArgument("SkirtSideSolver",
                                   "the elastic coupling was built on another grid");
  }

  bool massConserving() const {
    return settings.lubrication.cavitation == lubrication::CavitationModel::MassConserving;
  }

  // A film solved again at the instant of its history (a restart from an accepted state, a
  // warm start): no time has passed since the history's last point.
  static bool atHistoryInstant(const SkirtSideConditions& c, const SkirtSideHistory& history) {
    return !(c.stepSinceHistory_s > 0.0) && !history.film.empty();
  }

  // The film inputs of an evaluation: sliding velocities, viscosity, supply, derivatives wanted,
  // the film's history.
  void setInputs(const SkirtSideMotion& motion, const SkirtSideConditions& c,
                 const SkirtSideHistory& history, bool poseDerivatives) {
    SkirtSideInputs& in = inputs;
    in.slidingVelocityAxial_mps = -motion.axialVelocity_mps;
    // The skirt's tangential velocity on the side's centre line is +dz_t/dt on the thrust
    // side (e_phi = +z at phi = 0) and -dz_t/dt on the anti-thrust side.
    in.slidingVelocityCircumferential_mps = gap.getGrid().getSide() == SkirtSide::Thrust
                                                ? -motion.rate.tertiary_mps
                                                : motion.rate.tertiary_mps;
    in.viscosity_Pas = c.viscosity_Pas;
    in.supplyFilm_m = c.supplyFilm_m;
    in.supplyBottom_m = in.supplyTop_m = nullptr;
    if (linerOil) {
      // The liner's film ahead of each edge, from the state of the last accepted step.
      if (history.liner.empty()) {
        initialLiner = linerOil->makeInitialState(motion.pinHeight_m);
        linerStart = &initialLiner;
      } else {
        linerStart = &history.liner;
      }
      linerOil->calcSupply(*linerStart, motion.pinHeight_m, supplyBottom, supplyTop);
      in.supplyBottom_m = &supplyBottom;
      in.supplyTop_m = &supplyTop;
    }
    in.squeezeColumns = poseDerivatives ? (settings.tertiaryMotion ? 3 : 2) : 0;
    in.extraBases = FilmSensitivityRequest();
    in.history = massConserving() ? &history.film : nullptr;
    in.timeStep_s = c.stepSinceHistory_s > 0.0 ? c.stepSinceHistory_s
                                               : std::numeric_limits<double>::infinity();
    const double lastStep_s = history.film.earlierStep_s;
    if (in.history && atHistoryInstant(c, history) && std::isfinite(lastStep_s) &&
        lastStep_s > 0.0) {
      // A first-order step of the history's own last length from its last point, so that the
      // fill fraction moves by what one step moves it - not the steady film, which would
      // redistribute the oil the film holds. The history itself is kept (advanceHistory).
      sameInstant.last = history.film.last;
      in.history = &sameInstant;
      in.timeStep_s = lastStep_s;
    }
  }

  // Gap and film at the motion (the elastic fields as set), counted and timed also when the film
  // throws, so that a retried step does not hide its solves.
  void gapAndFilm(const SkirtSideMotion& motion, SkirtSideCounters& counters) {
    const auto gapStart = Clock::now();
    gap.calc(motion.pose, motion.rate, motion.pinHeight_m, motion.axialVelocity_mps, fields);
    counters.gap_s += secondsSince(gapStart);
    const auto count = [&] {
      counters.film_s += results.filmTime_s;
      counters.contact_s += results.contactTime_s;
      counters.loads_s += results.loadsTime_s;
      ++counters.filmSolves;
      counters.filmFallbacks += results.film.usedFallback ? 1 : 0;
      counters.derivativeFailures += results.film.derivativesFailed ? 1 : 0;
    };
    try {
      lubrication.solve(fields, inputs, results);
    } catch (const std::runtime_error&) {
      count();
      throw;
    }
    count();
  }

  // The elastic skirt: film and deformation converged together.
  void solveElastic(const SkirtSideMotion& motion, const SkirtSideConditions& c,
                    const SkirtSideHistory& history, SkirtSideSolution& out) {
    const ElasticHistory& past = history.elastic;
    const double dt = c.stepSinceHistory_s;
    const bool rate = settings.elasticRate && massConserving() &&
                      past.gapTerm_m.size() == fields.gap_m.size() && dt > 0.0;
    // An elastic liner: its compliance seen from the skirt at the pin's height now.
    if (coupling->hasLiner())
      coupling->setLinerPosition(motion.pinHeight_m);
    if (rate && past.structural_m.size() == coupling->structuralNodeCount()) {
      // The start: the accepted deformation moved on at its last rate (the file comment).
      elasticStart = past.structural_m;
      if (past.structuralRate_mps.size() == elasticStart.size())
        elasticStart += dt * past.structuralRate_mps;
      coupling->setStart(elasticStart);
    }
    coupling->prepareRate(rate ? dt : 0.0);
    const double sigma_m = lubrication.getCompositeSigma_m();
    // The coupling's own work (mapping, modal algebra): its time less its film evaluations'.
    const auto couplingStart = Clock::now();
    const SkirtSideCounters before = out.counters;
    // The coupling's last film evaluation is the one of its returned deformation, so the
    // results left here belong to the converged gap.
    out.elastic = coupling->solve(
        [&](const Eigen::ArrayXd& elastic_m, FilmPressureEvaluation& evaluation) {
          inputs.extraBases = coupling->getFilmRequest(evaluation.sensitivitiesWanted);
          fields.pistonElastic_m = elastic_m;
          if (rate)
            fields.pistonElasticRate_mps = (elastic_m - past.gapTerm_m) / dt;
          else
            fields.pistonElasticRate_mps.setZero();
          gapAndFilm(motion, out.counters);
          evaluation.normalPressure_Pa = results.normalPressure_Pa;
          evaluation.minFilmThickness_m = results.minFilmThickness_m;
          coupling->readFilm(results, fields, sigma_m, evaluation);
        },
        c.cylinderGaugePressure_Pa);
    const SkirtSideCounters& after = out.counters;
    out.counters.coupling_s += secondsSince(couplingStart) -
                               (after.gap_s + after.film_s + after.contact_s + after.loads_s -
                                (before.gap_s + before.film_s + before.contact_s + before.loads_s));
    if (!out.elastic.converged)
      throw std::runtime_error(common::message(
          "elastic skirt (", sideName(gap.getGrid().getSide()), " side) did not converge in ",
          out.elastic.iterations, " film evaluations: deformation change ", out.elastic.residual_m,
          " m > tolerance ", out.elastic.tolerance_m,
          " m (raise elasticSkirt.coupling.maxIterations or the tolerance; a residual that "
          "stalls just above the tolerance is the film solver's noise: tighten the film's "
          "tolerance, e.g. liner.film.tolerance 1e-11)"));
  }

  // The history the evaluation leads to (mass-conserving film only; a zero step with a film
  // history keeps the history whole, see setInputs).
  void advanceHistory(const SkirtSideMotion& motion, const SkirtSideConditions& c,
                      const SkirtSideHistory& history, SkirtSideSolution& out) const {
    out.historyAdvanced = massConserving();
    if (!out.historyAdvanced)
      return;
    if (atHistoryInstant(c, history)) {
      out.next = history;  // no time has passed for the film to change what it holds
      return;
    }
    const double dt = c.stepSinceHistory_s;
    if (linerOil) {
      const lubrication::FilmResult& f = results.film;
      const EdgeOutflows flows{&f.edgeOutflowYMin_m3ps, &f.edgeOutflowYMax_m3ps,
                               &f.edgeOutflowXMin_m3ps, &f.edgeOutflowXMax_m3ps};
      out.next.liner = linerOil->advance(*linerStart, motion.pinHeight_m, motion.axialVelocity_mps,
                                         c.crankAngle_deg, std::max(dt, 0.0), flows);
    }
    const lubrication::FilmHistoryPoint now{results.film.fillFraction(),
                                            results.film.expectedGap_m};
    out.next.film = history.film.advanced(now, dt, settings.fillFractionHistoryOrder);
    ElasticHistory& elastic = out.next.elastic;
    elastic.gapTerm_m = coupling ? coupling->pistonElastic_m() : Eigen::ArrayXd();
    elastic.structural_m = coupling ? coupling->structuralDisplacement_m() : Eigen::VectorXd();
    if (dt > 0.0) {
      elastic.structuralRate_mps.resize(0);
      if (coupling && history.elastic.structural_m.size() == elastic.structural_m.size())
        elastic.structuralRate_mps = (elastic.structural_m - history.elastic.structural_m) / dt;
    } else {
      elastic.structuralRate_mps = history.elastic.structuralRate_mps;
    }
  }
};

SkirtSideSolver::SkirtSideSolver(const SkirtSideGrid& grid, const GapAssemblyParameters& gap,
                                 std::shared_ptr<const lubrication::FlowFactorModel> flowFactors,
                                 std::shared_ptr<const contact_forces::AsperityContactLaw> law,
                                 const contact_forces::BoundaryFriction& friction,
                                 const SkirtSideSettings& settings,
                                 std::unique_ptr<ElasticCoupling> coupling,
                                 std::optional<LinerOilFilm> linerOil)
    : impl_(std::make_unique<Impl>(grid, gap, std::move(flowFactors), std::move(law), friction,
                                   settings, std::move(coupling), std::move(linerOil))) {}

SkirtSideSolver::~SkirtSideSolver() = default;
SkirtSideSolver::SkirtSideSolver(SkirtSideSolver&&) noexcept = default;
SkirtSideSolver& SkirtSideSolver::operator=(SkirtSideSolver&&) noexcept = default;

void SkirtSideSolver::solve(const SkirtSideMotion& motion, const SkirtSideConditions& conditions,
                            const SkirtSideHistory& history, SkirtSideSolution& out) {
  Impl& m = *impl_;
  out.counters = SkirtSideCounters();
  out.historyAdvanced = false;
  // The pose's squeeze derivatives serve the stepper's Jacobian, and a coupling scheme that
  // reads them.
  out.poseDerivatives =
      conditions.poseDerivativesWanted || (m.coupling && m.coupling->needsPoseSqueezeDerivatives());
  m.setInputs(motion, conditions, history, out.poseDerivatives);
  if (m.coupling)
    m.solveElastic(motion, conditions, history, out);
  else
    m.gapAndFilm(motion, out.counters);
  m.advanceHistory(motion, conditions, history, out);
}

const SkirtSideGrid& SkirtSideSolver::getGrid() const {
  return impl_->gap.getGrid();
}
const SkirtSideSettings& SkirtSideSolver::getSettings() const {
  return impl_->settings;
}
const GapAssembly& SkirtSideSolver::getGapAssembly() const {
  return impl_->gap;
}
const GapFields& SkirtSideSolver::getGapFields() const {
  return impl_->fields;
}
const SkirtSideResults& SkirtSideSolver::getResults() const {
  return impl_->results;
}
const ElasticCoupling* SkirtSideSolver::getElasticCoupling() const {
  return impl_->coupling.get();
}
const LinerOilFilm* SkirtSideSolver::getLinerOilFilm() const {
  return impl_->linerOil ? &*impl_->linerOil : nullptr;
}
const Eigen::ArrayXd& SkirtSideSolver::getSupplyBottom_m() const {
  return impl_->supplyBottom;
}
const Eigen::ArrayXd& SkirtSideSolver::getSupplyTop_m() const {
  return impl_->supplyTop;
}
double SkirtSideSolver::getCompositeSigma_m() const {
  return impl_->lubrication.getCompositeSigma_m();
}

}  // namespace pistondyn::skirt
