// bench_cycle: wall time and cost breakdown of whole engine cycles with the lubricated
// skirt. A timing program, not a test: it asserts nothing about speed. Figures and machine go
// to BENCHMARKS.md.
//
//   bench_cycle DECK [--set key=value]... [--configs fast,reference_gauss_seidel]
//               [--parallel-sides]   (one core by default, as the targets are stated)
//   bench_cycle DECK --targets [--set key=value]...
//
// Each configuration is the deck with liner.film.solver set to that solver, run until
// periodic (or the deck's cycle count) in this process, one after the other, so that the
// fast solver and the thesis' Gauss-Seidel baseline are compared in the same run. For the
// last simulated cycle it prints: wall time, film solves and force evaluations, the time
// share of gap / film / contact / loads / the elastic coupling's own work (mapping, modal
// algebra) / the rest of the element (the element's own clocks) and of what lies outside the
// element (Simbody realizations, the integrator, row output), the mean in-cycle film solve and
// the ratio cycle time / (film solves x mean solve); over the whole run, the integrator's
// steps, rejected steps and force evaluations (Newton iterations) per step, and the split of
// the outside into Simbody (the stepper's realizations less the element) and the integrator.
// Peak RSS is the process' high-water mark (getrusage) after each configuration; run one
// configuration per process to read it alone.
//
// --targets runs the cycle-engine targets' table (issue 35) on DECK, which must be the
// gasoline example (examples/engines/gasoline_1400_2000rpm/engine.yaml: the table's cases are
// that engine's): each case is the deck with the overrides printed beside it, at most 4
// cycles until periodic, and prints its time per cycle against the target as met or missed
// by how much, whether it converged and after how many cycles; the flagship case also with the
// thesis' Gauss-Seidel (the ratio's target), and the peak memory last.
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/RunDeck.h"
#include "pistondyn/plugin/LinerElement.h"

namespace {

using Clock = std::chrono::steady_clock;
using pistondyn::plugin::LinerElement;
using pistondyn::plugin::SolverCounters;

// What the element and the clock say at one instant; a cycle is the difference of two.
struct Snapshot {
  double wall_s = 0.0;
  double cpu_s = 0.0;  // this thread's CPU time: the figure that survives a loaded machine
  double processCpu_s = 0.0;  // all threads (with --parallel-sides the helper's too)
  SolverCounters timings;
};

// Takes a snapshot at the start of every cycle and at the end of the run.
class CycleClock final : public pistondyn::plugin::RowSink {
 public:
  explicit CycleClock(const LinerElement& element) : element_(element) {}
  void beginCycle(int /*cycle*/) override { snapshots_.push_back(take()); }
  void consumeRow(const SimTK::State&, const std::vector<double>&) override {}
  void discardRows() override {}
  void endRun() override { snapshots_.push_back(take()); }
  const std::vector<Snapshot>& getSnapshots() const { return snapshots_; }

 private:
  Snapshot take() const {
    Snapshot s;
    s.wall_s = std::chrono::duration<double>(Clock::now() - start_).count();
    timespec cpu{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu);
    s.cpu_s = static_cast<double>(cpu.tv_sec) + 1e-9 * static_cast<double>(cpu.tv_nsec);
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu);
    s.processCpu_s =
        static_cast<double>(cpu.tv_sec) + 1e-9 * static_cast<double>(cpu.tv_nsec);
    s.timings = element_.getSolverCounters().value_or(SolverCounters());
    return s;
  }
  const LinerElement& element_;
  Clock::time_point start_ = Clock::now();
  std::vector<Snapshot> snapshots_;
};

double peakRss_MB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

// The model's liner when it counts film solves (the lubricated skirt, or a user's film model).
const LinerElement* findFilmLiner(const pistondyn::plugin::PistonAssemblyModel& model) {
  const LinerElement* liner = model.findLinerElement();
  return liner && liner->getSolverCounters() ? liner : nullptr;
}

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty())
      out.push_back(item);
  return out;
}

// One target line: "met" or "missed by <ratio>x".
void printTarget(const char* what, double value, double limit, bool atMost, const char* unit) {
  const bool met = atMost ? value <= limit : value >= limit;
  const double ratio = atMost ? value / limit : limit / value;
  if (met)
    std::printf("    %-34s %.3g %s (target %s %.3g %s): met\n", what, value, unit,
                atMost ? "<=" : ">=", limit, unit);
  else
    std::printf("    %-34s %.3g %s (target %s %.3g %s): MISSED by %.2fx\n", what, value, unit,
                atMost ? "<=" : ">=", limit, unit, ratio);
}

// What one configuration's run gave.
struct ConfigurationResult {
  double lastCycleWall_s = 0.0;  ///< wall time of the last simulated cycle
  int cyclesRun = 0;
  bool converged = false;
  int cyclesToConverge = 0;
  double fmep_kPa = 0.0;
};

// Runs one configuration and prints its breakdown. Returns the wall time of the last cycle
// [s] (0 on failure, with rc set).
ConfigurationResult runConfiguration(const std::string& deckPath,
                                     std::vector<std::string> overrides,
                                     const std::string& solver, int& rc) {
  rc = 1;
  ConfigurationResult result;
  overrides.push_back("liner.film.solver=" + solver);
  const auto deck = pistondyn::io::loadEngineDeck(deckPath, overrides);
  auto model = pistondyn::io::buildModel(deck);
  const LinerElement* skirt = findFilmLiner(*model);
  if (!skirt) {
    std::fprintf(stderr, "bench_cycle: %s has no film liner (liner.model: lubricated_skirt)\n",
                 deckPath.c_str());
    return result;
  }
  CycleClock clock(*skirt);
  const auto outcome = pistondyn::io::runModel(deck, *model, "", {}, {&clock});
  const auto& snaps = clock.getSnapshots();
  if (snaps.size() < 2) {
    std::fprintf(stderr, "bench_cycle: no whole cycle was simulated\n");
    return result;
  }
  const Snapshot& a = snaps[snaps.size() - 2];
  const Snapshot& b = snaps.back();
  const double wall = b.wall_s - a.wall_s;
  const double gap = b.timings.gap_s - a.timings.gap_s;
  const double film = b.timings.film_s - a.timings.film_s;
  const double contact = b.timings.contact_s - a.timings.contact_s;
  const double loads = b.timings.loads_s - a.timings.loads_s;
  const double coupling = b.timings.coupling_s - a.timings.coupling_s;
  const double element = b.timings.total_s - a.timings.total_s;
  const long solves = b.timings.filmSolves - a.timings.filmSolves;
  const long evaluations = b.timings.evaluations - a.timings.evaluations;
  const double meanSolve = solves > 0 ? film / static_cast<double>(solves) : 0.0;
  // The element's own rest (inputs, history, sums) and what lies outside it.
  const double elementRest = std::max(0.0, element - gap - film - contact - loads - coupling);
  const double outside = wall - std::max(element, gap + film + contact + loads + coupling);
  const auto pct = [wall](double t) { return wall > 0.0 ? 100.0 * t / wall : 0.0; };

  const auto& s = outcome.stats;
  std::printf("solver %s: %d cycle(s) run, %s after %d; last cycle:\n", solver.c_str(),
              s.cyclesRun, s.converged ? "periodic" : "NOT periodic", s.cyclesToConverge);
  std::printf("  wall %.3f s (CPU %.3f s this thread, %.3f s process)   fmep %.4f kPa   film solves %ld (fallbacks %ld, "
              "without derivatives %ld)   force evaluations %ld\n",
              wall, b.cpu_s - a.cpu_s, b.processCpu_s - a.processCpu_s, s.cycleFmep_Pa.empty() ? 0.0 : s.cycleFmep_Pa.back() / 1e3, solves,
              b.timings.filmFallbacks - a.timings.filmFallbacks,
              b.timings.derivativeFailures - a.timings.derivativeFailures, evaluations);
  std::printf("  shares: film %.1f %%  contact %.1f %%  gap %.1f %%  loads %.1f %%  elastic "
              "coupling (mapping, modal algebra) %.1f %%  element other %.1f %%  outside the "
              "element (Simbody, integrator, output) %.1f %%\n",
              pct(film), pct(contact), pct(gap), pct(loads), pct(coupling), pct(elementRest),
              pct(outside));
  std::printf("  mean film solve %.3f ms   cycle / (solves x mean solve) = %.2f\n",
              meanSolve * 1e3, solves > 0 && meanSolve > 0 ? wall / film : 0.0);
  std::printf("  whole run: %ld integrator steps, %ld rejected, %.2f force evaluations (Newton "
              "iterations) per step, %.1f s   peak RSS %.1f MB\n",
              s.integratorSteps, s.rejectedSteps,
              s.integratorSteps > 0
                  ? static_cast<double>(s.realizations) / static_cast<double>(s.integratorSteps)
                  : 0.0,
              s.wallTime_s, peakRss_MB());
  if (s.realizeTime_s > 0.0 && s.wallTime_s > 0.0) {
    // Over the whole run (the stepper's clock is not read per cycle): Simbody's share is its
    // realizations less the element's time in them, the integrator's (with output) the rest.
    const double simbody = std::max(0.0, s.realizeTime_s - b.timings.total_s);
    std::printf("  whole run split: force evaluations %.1f %% (the element %.1f %%, Simbody %.1f "
                "%%), integrator and output %.1f %%\n",
                100.0 * s.realizeTime_s / s.wallTime_s, 100.0 * b.timings.total_s / s.wallTime_s,
                100.0 * simbody / s.wallTime_s,
                100.0 * std::max(0.0, s.wallTime_s - s.realizeTime_s) / s.wallTime_s);
  }
  if (solves > 0 && film > 0.0)
    printTarget("cycle / (solves x mean solve)", wall / film, 1.5, true, "");
  std::fflush(stdout);
  rc = 0;
  result.lastCycleWall_s = wall;
  result.cyclesRun = s.cyclesRun;
  result.converged = s.converged;
  result.cyclesToConverge = s.cyclesToConverge;
  result.fmep_kPa = s.cycleFmep_Pa.empty() ? 0.0 : s.cycleFmep_Pa.back() / 1e3;
  return result;
}

// One row of issue 35's table: the case, its overrides of the gasoline deck, the target.
struct TargetCase {
  const char* name;
  std::vector<std::string> overrides;
  double wallTarget_s;
  bool withReference;  ///< also run the thesis' Gauss-Seidel (the ratio's row)
};

// The flooded and elastic rows on the cold shapes, as the table's figures were measured.
const std::vector<std::string> kFlooded = {"liner.oil_supply.fully_flooded=true",
                                           "liner.oil_supply.film_um=null",
                                           "liner.thermal.piston_expansion_per_K=0",
                                           "liner.thermal.liner_expansion_per_K=0"};
const std::vector<std::string> kElastic = {
    "liner.elastic_skirt.compliance_file=../../fe/gasoline_1400_2000rpm/skirt_compliance.mtx",
    "liner.elastic_skirt.nodes_file=../../fe/gasoline_1400_2000rpm/skirt_nodes.csv",
    "liner.film.tolerance=1e-11", "liner.film.faces=nodal_mean",
    // the elastic study's stepper (examples/studies/elastic_skirt.yaml): with the decks' BDF3
    // the coupling needs more film solves
    "simulation.stepper_order=2", "simulation.max_step_deg=0.25", "simulation.pose_tolerance_nm=10"};

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<TargetCase> issue35Cases() {
  return {
      {"rigid, flooded, Reynolds cavitation, 40 x 24",
       joined(kFlooded, {"liner.film.cavitation=reynolds", "liner.grid.nodes_circumferential=40",
                         "liner.grid.nodes_axial=24"}),
       0.15, false},
      {"rigid, flooded, mass-conserving, 64 x 48", kFlooded, 0.5, false},
      {"the flagship deck as it stands (hot shapes, 1 um supply, 64 x 48)", {}, 2.0, true},
      {"the starved deck (cold shapes, 0.5 um supply, 64 x 48)",
       {"liner.thermal.piston_expansion_per_K=0", "liner.thermal.liner_expansion_per_K=0",
        "liner.oil_supply.film_um=0.5"},
       5.0, false},
      {"elastic skirt, flooded, 64 x 48", joined(kFlooded, kElastic), 10.0, false},
  };
}

int runTargets(const std::string& deckPath, const std::vector<std::string>& userOverrides) {
  struct Line {
    std::string name;
    double target_s;
    ConfigurationResult result;
  };
  std::vector<Line> lines;
  // The flagship (the case run with both solvers): its fast run and the reference's.
  std::optional<ConfigurationResult> flagship, flagshipReference;
  for (const TargetCase& c : issue35Cases()) {
    std::vector<std::string> o = joined(userOverrides, c.overrides);
    o = joined(o, {"simulation.cycles=4", "simulation.until_periodic=true"});
    std::printf("== %s:", c.name);
    for (const std::string& x : c.overrides)
      std::printf(" --set %s", x.c_str());
    std::printf("\n");
    int rc = 0;
    const ConfigurationResult fast = runConfiguration(deckPath, o, "fast", rc);
    if (rc != 0)
      return rc;
    lines.push_back({c.name, c.wallTarget_s, fast});
    if (c.withReference) {
      flagship = fast;
      flagshipReference = runConfiguration(deckPath, o, "reference_gauss_seidel", rc);
      if (rc != 0)
        return rc;
    }
  }
  std::printf("\nissue 35's targets (one core; wall time of the last cycle of a run of at most 4 "
              "cycles until periodic):\n");
  for (const Line& l : lines) {
    printTarget(l.name.c_str(), l.result.lastCycleWall_s, l.target_s, true, "s");
    std::printf("      %s after %d cycle(s), fmep %.4f kPa\n",
                l.result.converged ? "periodic" : "NOT periodic", l.result.cyclesRun,
                l.result.fmep_kPa);
  }
  if (flagship) {
    if (flagship->converged)
      printTarget("cycles to converge, flagship", flagship->cyclesToConverge, 3.0, true, "");
    else
      std::printf("    %-34s NOT converged in %d cycles (target <= 3): MISSED\n",
                  "cycles to converge, flagship", flagship->cyclesRun);
    if (flagship->lastCycleWall_s > 0.0 && flagshipReference->lastCycleWall_s > 0.0)
      printTarget("thesis' Gauss-Seidel / fast, flagship",
                  flagshipReference->lastCycleWall_s / flagship->lastCycleWall_s, 10.0, false,
                  "x");
  }
  printTarget("peak RSS of the whole table", peakRss_MB(), 200.0, true, "MB");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string deckPath;
  std::vector<std::string> overrides;
  std::vector<std::string> solvers{"fast", "reference_gauss_seidel"};
  bool parallelSides = false;  // one core, as the targets are stated
  bool targets = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--set" && i + 1 < argc) {
      overrides.push_back(argv[++i]);
    } else if (arg == "--targets") {
      targets = true;
    } else if (arg == "--parallel-sides") {
      parallelSides = true;
    } else if (arg == "--configs" && i + 1 < argc) {
      solvers = splitCommas(argv[++i]);
    } else if (arg == "-h" || arg == "--help") {
      std::printf("usage: bench_cycle DECK [--set key=value]... [--configs "
                  "fast,reference_gauss_seidel] [--parallel-sides]\n"
                  "       bench_cycle DECK --targets [--set key=value]...   (issue 35's "
                  "table on the gasoline example deck)\n"
                  "  one core unless --parallel-sides (liner.parallel_sides of the deck is "
                  "overridden)\n");
      return 0;
    } else if (deckPath.empty() && arg.rfind("--", 0) != 0) {
      deckPath = arg;
    } else {
      std::fprintf(stderr, "bench_cycle: unexpected argument '%s' (see --help)\n", arg.c_str());
      return 2;
    }
  }
  if (deckPath.empty()) {
    std::fprintf(stderr, "bench_cycle: give the engine deck (see --help)\n");
    return 2;
  }
  overrides.insert(overrides.begin(),
                   std::string("liner.parallel_sides=") + (parallelSides ? "true" : "false"));
  try {
    if (targets)
      return runTargets(deckPath, overrides);
    double fastWall = 0.0, referenceWall = 0.0;
    for (const std::string& solver : solvers) {
      int rc = 0;
      const double wall = runConfiguration(deckPath, overrides, solver, rc).lastCycleWall_s;
      if (rc != 0)
        return rc;
      if (solver == "fast")
        fastWall = wall;
      else if (solver == "reference_gauss_seidel")
        referenceWall = wall;
    }
    if (fastWall > 0.0 && referenceWall > 0.0) {
      std::printf("reference / fast, last cycle:\n");
      printTarget("reference / fast wall per cycle", referenceWall / fastWall, 10.0, false, "x");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_cycle: %s\n", e.what());
    return 1;
  }
  return 0;
}
