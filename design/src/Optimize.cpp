#include "pistondyn/design/Optimize.h"

#include <yaml-cpp/yaml.h>

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <future>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "StudyDeckReader.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/design/Figures.h"
#include "pistondyn/io/DeckError.h"

namespace pistondyn::design {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using common::formatNumber;

// ---- the deck ----------------------------------------------------------------------------

void readObjective(detail::StudyDeckReader& r, const YAML::Node& node, OptimizeSpec& spec) {
  auto add = [&](const YAML::Node& at, const std::string& figure, double weight) {
    if (!isKnownFigure(figure)) {
      r.problem(at, "objective",
                "'" + figure +
                    "' is not a figure the design loop knows (one of: " + listKnownFigures() + ")");
      return;
    }
    spec.objective.push_back({figure, weight});
  };
  if (node.IsScalar()) {
    add(node, node.Scalar(), 1.0);
    return;
  }
  if (node.IsMap() && node.size() > 0) {
    for (const auto& [figure, weight] : r.entries(node, "objective")) {
      const auto w = r.number(weight, "objective." + figure);
      if (!w)
        continue;
      if (*w == 0.0) {
        r.problem(weight, "objective." + figure, "a weight of 0 leaves the figure out: remove it");
        continue;
      }
      add(weight, figure, *w);
    }
    return;
  }
  r.problem(node, "objective",
            "expected a figure (e.g. fmep_kPa) or a weighted sum {fmep_kPa: 1, "
            "slap_energy_max_mJ: 0.2}");
}

void readConstraints(detail::StudyDeckReader& r, const YAML::Node& node, OptimizeSpec& spec) {
  if (!node.IsMap()) {
    r.problem(node, "constraints",
              "expected a section of figure: {min: a} / {max: b}, e.g. "
              "min_h_over_sigma_thrust: {min: 1.0}");
    return;
  }
  for (const auto& [figure, bound] : r.entries(node, "constraints")) {
    const std::string where = "constraints." + figure;
    if (!isKnownFigure(figure)) {
      r.problem(bound, where,
                "'" + figure +
                    "' is not a figure the design loop knows (one of: " + listKnownFigures() + ")");
      continue;
    }
    if (!bound.IsMap() || bound.size() == 0) {
      r.problem(bound, where, "expected {min: a}, {max: b} or both");
      continue;
    }
    DesignConstraint c;
    c.figure = figure;
    for (const auto& [k, v] : r.entries(bound, where)) {
      if (k == "min")
        c.minimum = r.number(v, where + ".min");
      else if (k == "max")
        c.maximum = r.number(v, where + ".max");
      else
        r.problem(v, where + "." + k, "unknown key (expected min, max)");
    }
    if (c.minimum && c.maximum && !(*c.minimum < *c.maximum)) {
      r.problem(
          bound, where,
          "min " + formatNumber(*c.minimum) + " must be less than max " + formatNumber(*c.maximum));
      continue;
    }
    if (c.minimum || c.maximum)
      spec.constraints.push_back(c);
  }
}

void readMethod(detail::StudyDeckReader& r, const YAML::Node& node, OptimizeMethod& m) {
  if (!node.IsMap()) {
    r.problem(node, "method", "expected a section (doe_samples, seed, starts, local, ...)");
    return;
  }
  for (const auto& [key, v] : r.entries(node, "method")) {
    const std::string where = "method." + key;
    if (key == "doe_samples") {
      if (const auto n = r.wholeNumber(v, where, 1, 100000))
        m.doeSamples = *n;
    } else if (key == "seed") {
      if (const auto n = r.wholeNumber(v, where, 0, 9007199254740992L))
        m.seed = static_cast<std::uint64_t>(*n);
    } else if (key == "starts") {
      if (const auto n = r.wholeNumber(v, where, 1, 1000))
        m.starts = static_cast<int>(*n);
    } else if (key == "local") {
      const auto t = r.text(v, where);
      if (t && *t != "cobyla" && *t != "bobyqa")
        r.problem(v, where, "'" + *t + "' is not one of: cobyla, bobyqa");
      else if (t)
        m.local = *t;
    } else if (key == "max_evaluations") {
      if (const auto n = r.wholeNumber(v, where, 1, 1000000))
        m.maxEvaluations = static_cast<int>(*n);
    } else if (key == "tolerance" || key == "initial_step" || key == "constraint_tolerance") {
      const auto x = r.number(v, where);
      const double hi = key == "initial_step" ? 1.0 : 0.5;
      if (x && !(*x > 0.0 && *x <= hi))
        r.problem(v, where, "expected a number in (0, " + formatNumber(hi) + "] (relative)");
      else if (x)
        (key == "tolerance"      ? m.tolerance
         : key == "initial_step" ? m.initialStep
                                 : m.constraintTolerance) = *x;
    } else if (key == "global") {
      const auto t = r.text(v, where);
      if (t && *t != "none" && *t != "isres")
        r.problem(v, where, "'" + *t + "' is not one of: none, isres");
      else if (t)
        m.global = *t;
    } else if (key == "global_evaluations") {
      if (const auto n = r.wholeNumber(v, where, 1, 1000000))
        m.globalEvaluations = static_cast<int>(*n);
    } else {
      r.problem(v, where,
                "unknown key (expected doe_samples, seed, starts, local, max_evaluations, "
                "tolerance, initial_step, constraint_tolerance, global, global_evaluations)");
    }
  }
}

Json describe(const OptimizeSpec& spec, bool forFingerprint) {
  const DesignStudy& s = spec.study;
  Json j;
  if (!forFingerprint) {
    j["deck"] = s.deckPath;
    j["name"] = s.name;
    j["base_deck"] = s.baseDeckPath;
  }
  j["context_sha256"] = s.contextSha256;
  j["fixed_overrides"] = s.fixedOverrides;
  Json vars = Json::array();
  for (const auto& v : s.variables)
    vars.push_back({{"key", v.key}, {"lower", v.lower}, {"upper", v.upper}});
  j["variables"] = vars;
  Json profile = nullptr;
  if (s.profile.enabled) {
    profile = Json::object();
    for (std::size_t i = 0; i < ProfileSpec::kNames.size(); ++i) {
      if (s.profile.fixed[i])
        profile[ProfileSpec::kNames[i]] = *s.profile.fixed[i];
    }
    profile["rows"] = s.profile.rows;
  }
  j["profile"] = profile;
  Json objective = Json::array();
  for (const auto& t : spec.objective)
    objective.push_back({{"figure", t.figure}, {"weight", t.weight}});
  j["objective"] = objective;
  Json constraints = Json::array();
  for (const auto& c : spec.constraints) {
    Json one = {{"figure", c.figure}};
    one["min"] = c.minimum ? Json(*c.minimum) : Json(nullptr);
    one["max"] = c.maximum ? Json(*c.maximum) : Json(nullptr);
    constraints.push_back(one);
  }
  j["constraints"] = constraints;
  const OptimizeMethod& m = spec.method;
  j["method"] = {{"doe_samples", m.doeSamples},
                 {"seed", m.seed},
                 {"starts", m.starts},
                 {"local", m.local},
                 {"max_evaluations", m.maxEvaluations},
                 {"tolerance", m.tolerance},
                 {"initial_step", m.initialStep},
                 {"constraint_tolerance", m.constraintTolerance},
                 {"global", m.global},
                 {"global_evaluations", m.globalEvaluations}};
  return j;
}

// ---- the search --------------------------------------------------------------------------

double constraintScale(double bound) {
  return bound != 0.0 ? std::fabs(bound) : 1.0;
}

// Ranking of designs: feasible before infeasible before failed; then objective or violation.
bool better(const DesignPoint& a, const DesignPoint& b) {
  const int ra = a.feasible ? 0 : a.objective ? 1 : 2;
  const int rb = b.feasible ? 0 : b.objective ? 1 : 2;
  if (ra != rb)
    return ra < rb;
  if (ra == 0)
    return *a.objective < *b.objective;
  if (ra == 1)
    return a.violation < b.violation;
  return false;
}

std::string describeResult(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS:
      return "success";
    case nlopt::STOPVAL_REACHED:
      return "objective target reached";
    case nlopt::FTOL_REACHED:
      return "objective tolerance reached";
    case nlopt::XTOL_REACHED:
      return "variable tolerance reached";
    case nlopt::MAXEVAL_REACHED:
      return "evaluation limit reached";
    case nlopt::MAXTIME_REACHED:
      return "time limit reached";
    default:
      return "stopped (" + std::to_string(static_cast<int>(r)) + ")";
  }
}

// One NLopt run's view of the designs: coordinates scaled to [0, 1], repeated points
// answered from memory, the designs it evaluated in order.
class Search {
 public:
  Search(const OptimizeSpec& spec, Executor& executor, std::string stage, double penalty,
         const OptimizeProgress& progress)
      : spec_(spec),
        executor_(executor),
        stage_(std::move(stage)),
        penalty_(penalty),
        progress_(progress) {
    for (const auto& v : spec.study.variables) {
      lo_.push_back(v.lower);
      hi_.push_back(v.upper);
    }
  }

  // The design x exactly at the scaled point u0 (so the start is its DOE point's run).
  void pin(const std::vector<double>& u0, const std::vector<double>& x0) {
    pinnedU_ = u0;
    pinnedX_ = x0;
  }
  std::vector<double> toUnit(const std::vector<double>& x) const {
    std::vector<double> u(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      u[i] = std::clamp((x[i] - lo_[i]) / (hi_[i] - lo_[i]), 0.0, 1.0);
    return u;
  }

  const DesignPoint& at(const std::vector<double>& u) {
    const auto it = memo_.find(u);
    if (it != memo_.end())
      return trail_[it->second];
    std::vector<double> x(u.size());
    if (u == pinnedU_) {
      x = pinnedX_;
    } else {
      for (std::size_t i = 0; i < u.size(); ++i)
        x[i] = std::clamp(lo_[i] + std::clamp(u[i], 0.0, 1.0) * (hi_[i] - lo_[i]), lo_[i], hi_[i]);
    }
    trail_.push_back(evaluate(spec_, executor_, stage_, x));
    memo_.emplace(u, trail_.size() - 1);
    const DesignPoint& p = trail_.back();
    if (progress_) {
      progress_("[" + stage_ + "] evaluation " + std::to_string(trail_.size()) + ": " +
                (p.objective ? "objective " + formatNumber(*p.objective) : "failed") +
                (p.feasible    ? ", feasible"
                 : p.objective ? ", infeasible"
                               : "") +
                (p.result.ok ? "" : ": " + p.result.message));
    }
    return p;
  }

  // NLopt evaluates the objective once per point it tries (the constraints as well).
  double objective(const std::vector<double>& u) {
    ++requests_;
    const DesignPoint& p = at(u);
    return p.objective ? *p.objective : penalty_;
  }
  // Constraint k's NLopt value (<= 0: satisfied), relative to its bound.
  double constraint(const std::vector<double>& u, std::size_t c, bool isMinimum) {
    const DesignPoint& p = at(u);
    const auto& v = p.constraintValues.at(c);
    if (!p.result.ok || !v)
      return 1.0;
    const DesignConstraint& k = spec_.constraints[c];
    return isMinimum ? (*k.minimum - *v) / constraintScale(*k.minimum)
                     : (*v - *k.maximum) / constraintScale(*k.maximum);
  }

  static DesignPoint evaluate(const OptimizeSpec& spec, Executor& executor,
                              const std::string& stage, const std::vector<double>& x) {
    EvaluationResult r;
    try {
      r = executor.evaluate({spec.study.makeRequest(x)}).front();
    } catch (const std::exception& e) {
      r.ok = false;
      r.message = e.what();
    }
    return assessPoint(spec, stage, x, r);
  }

  std::vector<DesignPoint>& getTrail() { return trail_; }
  int getRequests() const { return requests_; }
  const std::string& getStage() const { return stage_; }

 private:
  const OptimizeSpec& spec_;
  Executor& executor_;
  std::string stage_;
  double penalty_;
  const OptimizeProgress& progress_;
  std::vector<double> lo_, hi_, pinnedU_, pinnedX_;
  std::map<std::vector<double>, std::size_t> memo_;
  std::vector<DesignPoint> trail_;
  int requests_ = 0;
};

struct ConstraintData {
  Search* search;
  std::size_t index;
  bool isMinimum;
};

double objectiveCallback(const std::vector<double>& u, std::vector<double>& grad, void* data) {
  (void)grad;  // derivative-free methods only
  return static_cast<Search*>(data)->objective(u);
}

double constraintCallback(const std::vector<double>& u, std::vector<double>& grad, void* data) {
  (void)grad;
  const auto* c = static_cast<ConstraintData*>(data);
  return c->search->constraint(u, c->index, c->isMinimum);
}

// Runs NLopt `algorithm` on the search from u0; returns the stop reason.
std::string runNlopt(nlopt::algorithm algorithm, const OptimizeSpec& spec, Search& search,
                     std::vector<double> u, int maxEvaluations) {
  const std::size_t n = spec.study.variables.size();
  nlopt::opt opt(algorithm, static_cast<unsigned>(n));
  opt.set_lower_bounds(std::vector<double>(n, 0.0));
  opt.set_upper_bounds(std::vector<double>(n, 1.0));
  opt.set_min_objective(objectiveCallback, &search);
  std::vector<ConstraintData> data;
  data.reserve(2 * spec.constraints.size());
  for (std::size_t c = 0; c < spec.constraints.size(); ++c) {
    if (spec.constraints[c].minimum)
      data.push_back({&search, c, true});
    if (spec.constraints[c].maximum)
      data.push_back({&search, c, false});
  }
  if (algorithm != nlopt::LN_BOBYQA) {
    for (auto& d : data)
      opt.add_inequality_constraint(constraintCallback, &d, spec.method.constraintTolerance);
  }
  opt.set_maxeval(maxEvaluations);
  if (algorithm != nlopt::GN_ISRES) {
    opt.set_xtol_abs(spec.method.tolerance);
    opt.set_initial_step(spec.method.initialStep);
  }
  double f = 0.0;
  try {
    return describeResult(opt.optimize(u, f));
  } catch (const nlopt::roundoff_limited&) {
    return "round-off limited";
  } catch (const std::exception& e) {
    return std::string("NLopt stopped: ") + e.what();
  }
}

std::optional<std::size_t> bestOf(const std::vector<DesignPoint>& points, std::size_t from,
                                  std::size_t to) {
  std::optional<std::size_t> best;
  for (std::size_t i = from; i < to; ++i) {
    if (points[i].feasible && (!best || *points[i].objective < *points[*best].objective))
      best = i;
  }
  return best;
}

}  // namespace

OptimizeSpec loadOptimizeDeck(const std::string& path,
                              const std::vector<std::string>& commandLineOverrides,
                              const io::LinerRegistry& registry) {
  detail::StudyDeckReader r(path, "optimize");
  OptimizeSpec spec;
  bool sawObjective = false;
  for (const auto& [key, value] : r.open()) {
    if (r.readCommon(key, value, "variables", false))
      continue;
    if (key == "objective") {
      sawObjective = true;
      readObjective(r, value, spec);
    } else if (key == "constraints") {
      readConstraints(r, value, spec);
    } else if (key == "method") {
      readMethod(r, value, spec.method);
    } else {
      r.problem(value, key,
                "unknown key (an optimisation deck has name, base_deck, set, variables, "
                "profile, objective, constraints, method)");
    }
  }
  if (!sawObjective)
    r.problem(r.getPath() +
              ": objective: missing key (a figure, e.g. fmep_kPa, or a weighted "
              "sum)");
  if (spec.method.local == "bobyqa" && !spec.constraints.empty())
    r.problem(r.getRoot()["method"]["local"], "method.local",
              "bobyqa handles bounds only; the deck has constraints: use cobyla");
  r.throwIfProblems();
  r.finishCommon(spec.study, commandLineOverrides, registry);
  const std::size_t n = spec.study.variables.size();
  if (spec.method.local.empty())
    spec.method.local = spec.constraints.empty() && n >= 2 ? "bobyqa" : "cobyla";
  if (spec.method.local == "bobyqa" && n < 2)
    r.problem(r.getRoot()["method"]["local"], "method.local",
              "bobyqa needs at least two variables: use cobyla");
  if (spec.method.doeSamples == 0)
    spec.method.doeSamples = 4 * static_cast<long>(n) + 4;
  if (spec.method.starts > spec.method.doeSamples)
    r.problem(r.getRoot()["method"]["starts"], "method.starts",
              std::to_string(spec.method.starts) +
                  " local searches need at least as many DOE "
                  "points (doe_samples " +
                  std::to_string(spec.method.doeSamples) + ")");
  r.throwIfProblems();
  spec.description = describe(spec, false).dump();
  spec.fingerprint = hashText("optimize\n" + describe(spec, true).dump());
  return spec;
}

DesignPoint assessPoint(const OptimizeSpec& spec, std::string stage, std::vector<double> x,
                        EvaluationResult result) {
  DesignPoint p;
  p.stage = std::move(stage);
  p.x = std::move(x);
  p.result = std::move(result);
  p.constraintValues.assign(spec.constraints.size(), std::nullopt);
  if (!p.result.ok)
    return p;
  try {
    const RunFigures figures(p.result.summaryJson);
    double sum = 0.0;
    for (const auto& t : spec.objective) {
      const auto v = figures.get(t.figure);
      if (!v)
        throw std::runtime_error("the run's summary.json has no " + t.figure +
                                 " (the liner reports none)");
      sum += t.weight * *v;
    }
    for (std::size_t c = 0; c < spec.constraints.size(); ++c) {
      const DesignConstraint& k = spec.constraints[c];
      const auto v = figures.get(k.figure);
      if (!v)
        throw std::runtime_error("the run's summary.json has no " + k.figure +
                                 " (the liner reports none)");
      p.constraintValues[c] = *v;
      if (k.minimum)
        p.violation = std::max(p.violation, (*k.minimum - *v) / constraintScale(*k.minimum));
      if (k.maximum)
        p.violation = std::max(p.violation, (*v - *k.maximum) / constraintScale(*k.maximum));
    }
    p.objective = sum;
    p.feasible = p.violation <= spec.method.constraintTolerance;
  } catch (const std::exception& e) {
    p.result.ok = false;
    p.result.message = e.what();
    p.objective.reset();
    p.constraintValues.assign(spec.constraints.size(), std::nullopt);
    p.violation = 0.0;
  }
  return p;
}

OptimizeOutcome runOptimization(const OptimizeSpec& spec, Executor& executor,
                                const OptimizeProgress& progress) {
  OptimizeOutcome out;
  const DesignStudy& s = spec.study;
  const std::size_t n = s.variables.size();
  // Baseline and the Latin hypercube, evaluated together.
  const auto doe = io::makeLatinHypercube(s.getBounds(), spec.method.doeSamples, spec.method.seed);
  std::vector<EvaluationRequest> requests = {s.makeBaselineRequest()};
  std::vector<std::optional<std::string>> unbuildable(doe.size() + 1);
  for (std::size_t i = 0; i < doe.size(); ++i) {
    try {
      requests.push_back(s.makeRequest(doe[i]));
    } catch (const std::exception& e) {
      unbuildable[i + 1] = e.what();
    }
  }
  if (progress)
    progress("[doe] evaluating the baseline and " + std::to_string(doe.size()) +
             " Latin-hypercube points");
  const auto results = executor.evaluate(requests);
  std::vector<double> baselineX;
  for (const auto& v : s.variables)
    baselineX.push_back(v.baseline.value_or(std::nan("")));
  out.history.push_back(assessPoint(spec, "baseline", baselineX, results[0]));
  std::size_t next = 1;
  for (std::size_t i = 0; i < doe.size(); ++i) {
    EvaluationResult r;
    if (unbuildable[i + 1]) {
      r.message = *unbuildable[i + 1];
    } else {
      r = results[next++];
    }
    out.history.push_back(assessPoint(spec, "doe", doe[i], r));
  }
  const std::size_t doeEnd = out.history.size();
  // The penalty a failed run shows the searches: above every objective seen so far.
  double fmin = std::numeric_limits<double>::infinity(), fmax = -fmin;
  for (const auto& p : out.history) {
    if (p.objective) {
      fmin = std::min(fmin, *p.objective);
      fmax = std::max(fmax, *p.objective);
    }
  }
  out.failurePenalty = std::isfinite(fmax) ? fmax + (fmax - fmin) + std::fabs(fmax) + 1.0 : 1.0;
  if (progress) {
    const auto best = bestOf(out.history, 1, doeEnd);
    progress("[doe] done: " +
             (best ? "best feasible objective " + formatNumber(*out.history[*best].objective)
                   : std::string("no feasible point")));
  }

  // Candidate starts: the DOE points, best first.
  std::vector<std::size_t> order;
  for (std::size_t i = 1; i < doeEnd; ++i)
    order.push_back(i);
  // The optional global stage, from nothing (ISRES samples the box itself).
  if (spec.method.global == "isres") {
    nlopt::srand(static_cast<unsigned long>(spec.method.seed));
    Search global(spec, executor, "global", out.failurePenalty, progress);
    const std::string why = runNlopt(nlopt::GN_ISRES, spec, global, std::vector<double>(n, 0.5),
                                     spec.method.globalEvaluations);
    LocalSearchSummary g;
    g.stage = "global";
    g.start = std::vector<double>();
    g.evaluations = global.getRequests();
    g.stopReason = why;
    const std::size_t from = out.history.size();
    for (auto& p : global.getTrail())
      out.history.push_back(std::move(p));
    g.best = bestOf(out.history, from, out.history.size());
    out.searches.push_back(g);
    for (std::size_t i = from; i < out.history.size(); ++i)
      order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return better(out.history[a], out.history[b]);
  });
  std::vector<std::size_t> starts;
  for (const std::size_t i : order) {
    if (static_cast<int>(starts.size()) >= spec.method.starts)
      break;
    if (!out.history[i].result.ok)
      continue;
    const bool seen = std::any_of(starts.begin(), starts.end(), [&](std::size_t j) {
      return out.history[j].x == out.history[i].x;
    });
    if (!seen)
      starts.push_back(i);
  }

  // The local searches, side by side (each its own NLopt object and thread).
  const nlopt::algorithm local =
      spec.method.local == "bobyqa" ? nlopt::LN_BOBYQA : nlopt::LN_COBYLA;
  std::vector<std::unique_ptr<Search>> searches;
  std::vector<std::future<std::string>> running;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    searches.push_back(std::make_unique<Search>(spec, executor, "local " + std::to_string(k + 1),
                                                out.failurePenalty, progress));
    Search& search = *searches.back();
    const std::vector<double>& x0 = out.history[starts[k]].x;
    const std::vector<double> u0 = search.toUnit(x0);
    search.pin(u0, x0);
    running.push_back(std::async(std::launch::async, [&spec, &search, u0, local] {
      return runNlopt(local, spec, search, u0, spec.method.maxEvaluations);
    }));
  }
  for (std::size_t k = 0; k < starts.size(); ++k) {
    LocalSearchSummary summary;
    summary.stage = searches[k]->getStage();
    summary.start = out.history[starts[k]].x;
    summary.stopReason = running[k].get();
    summary.evaluations = searches[k]->getRequests();
    const std::size_t from = out.history.size();
    for (auto& p : searches[k]->getTrail())
      out.history.push_back(std::move(p));
    summary.best = bestOf(out.history, from, out.history.size());
    if (progress)
      progress("[" + summary.stage + "] " + summary.stopReason + " after " +
               std::to_string(out.history.size() - from) + " designs" +
               (summary.best ? ", best feasible objective " +
                                   formatNumber(*out.history[*summary.best].objective)
                             : std::string(", none feasible")));
    out.searches.push_back(summary);
  }
  out.optimum = bestOf(out.history, 1, out.history.size());
  return out;
}

std::string makeHistoryCsv(const OptimizeSpec& spec, const OptimizeOutcome& outcome) {
  std::ostringstream out;
  out << "# pistondyn optimize: every design the optimiser evaluated, in the order of its "
         "stages (baseline, Latin-hypercube DOE, global, each local search)\n";
  out << "# study " << spec.study.deckPath << ", base deck " << spec.study.baseDeckPath
      << ", fingerprint " << spec.fingerprint << "\n";
  out << "# objective =";
  for (std::size_t i = 0; i < spec.objective.size(); ++i)
    out << (i ? " +" : "") << " " << formatNumber(spec.objective[i].weight) << " x "
        << spec.objective[i].figure;
  out << "; violation: the largest constraint violation relative to its bound; evaluation: "
         "the run folder under evaluations/\n";
  out << "number,stage";
  for (const auto& v : spec.study.variables)
    out << ',' << v.key;
  out << ",objective";
  for (const auto& c : spec.constraints)
    out << ',' << c.figure;
  out << ",violation,feasible,status,evaluation,message\n";
  int number = 0;
  for (const auto& p : outcome.history) {
    out << ++number << ',' << p.stage;
    for (const double x : p.x)
      out << ',' << (std::isfinite(x) ? formatNumber(x) : "");
    out << ',' << (p.objective ? formatNumber(*p.objective) : "");
    for (const auto& v : p.constraintValues)
      out << ',' << (v ? formatNumber(*v) : "");
    out << ',' << (p.result.ok ? formatNumber(p.violation) : "") << ','
        << (p.feasible ? "true" : "false") << ',' << (p.result.ok ? "ok" : "failed") << ','
        << p.result.id << ',';
    std::string m = p.result.message;
    std::replace(m.begin(), m.end(), '\n', ' ');
    if (!m.empty()) {
      std::string q = "\"";
      for (const char ch : m)
        q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
      out << q << '"';
    }
    out << '\n';
  }
  return out.str();
}

std::string makeDeckWithOverrides(const std::string& baseDeckPath,
                                  const std::vector<std::string>& overrides,
                                  const std::vector<std::string>& headerLines) {
  YAML::Node root = YAML::LoadFile(baseDeckPath);
  for (const auto& o : overrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument("makeDeckWithOverrides: '" + o + "' is not key=value");
    std::vector<std::string> parts;
    std::string path = o.substr(0, eq);
    for (std::size_t b = 0;;) {
      const std::size_t d = path.find('.', b);
      parts.push_back(path.substr(b, d - b));
      if (d == std::string::npos)
        break;
      b = d + 1;
    }
    // yaml-cpp nodes are references: walk down by value copies that share the tree.
    YAML::Node node = root;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      if (!node[parts[i]] || !node[parts[i]].IsMap())
        node[parts[i]] = YAML::Node(YAML::NodeType::Map);
      node.reset(node[parts[i]]);
    }
    const YAML::Node value = YAML::Load(o.substr(eq + 1));
    if (value.IsNull())
      node.remove(parts.back());
    else
      node[parts.back()] = value;
  }
  // File paths relative to the base deck's folder become absolute.
  const fs::path folder = fs::absolute(baseDeckPath).parent_path();
  std::function<void(YAML::Node)> absolutise = [&](YAML::Node map) {
    for (auto kv : map) {
      const std::string key = kv.first.Scalar();
      if (kv.second.IsMap()) {
        absolutise(kv.second);
      } else if (kv.second.IsScalar() && key.size() > 5 &&
                 key.compare(key.size() - 5, 5, "_file") == 0) {
        const fs::path p(kv.second.Scalar());
        if (p.is_relative())
          kv.second = (folder / p).lexically_normal().string();
      }
    }
  };
  absolutise(root);
  YAML::Emitter e;
  e << root;
  std::string text;
  for (const auto& l : headerLines)
    text += "# " + l + "\n";
  return text + e.c_str() + "\n";
}

}  // namespace pistondyn::design
