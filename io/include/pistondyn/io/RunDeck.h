#pragma once
/// \file
/// `pistondyn run`: simulate a deck and write DIR/cycle.csv and DIR/summary.json.
///
/// Results are streamed and all-or-nothing: rows go to DIR/.cycle.csv.partial as the
/// simulation produces them, the summary is accumulated by a CycleSummarySink at the same
/// time (no table is held in memory), and both files are renamed into place only when
/// the run and summary.json succeeded. On any failure (an element throws, the integrator
/// stops, a file cannot be written) no result file is left and earlier results in DIR
/// are kept.
///
///   const auto deck = io::loadEngineDeck("engine.yaml", {"drive.speed_rpm=3000"});
///   const io::RunOutcome o = io::runDeck(deck, "results/3000rpm");
///   std::printf("mean crank torque %.2f N m\n", o.summary.meanCrankTorque_Nm);

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pistondyn/io/CycleSummary.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/plugin/CycleSimulation.h"

namespace pistondyn::io {

/// How many of its last cycles a run that did not become periodic is summarised over
/// (summary.json results.last_cycles, and the range `pistondyn run` prints).
inline constexpr std::size_t kLastCyclesSummarised = 3;

/// What a run gives back besides its files.
struct RunOutcome {
  CycleSummary summary;           ///< the last 720 deg cycle
  /// Every simulated cycle's figures, the first cycle first (the last is `summary`); in a run
  /// to periodic steady state also the cycles whose rows were discarded.
  std::vector<CycleSummary> cycleSummaries;
  plugin::SimulationStats stats;  ///< steps, cycles, fmep per cycle, wall time
  long rows = 0;                  ///< rows simulated (and written to cycle.csv)
  /// The liner oil's balance over the last cycle (a liner element with a LinerOilSource).
  std::optional<plugin::LinerOilBalance> linerOilLastCycle;
};

/// Builds the deck's model and runs it (runModel). outDir empty: no files, the summary
/// only. extraSinks receive every row too (e.g. a ResultTableSink to keep them in memory).
RunOutcome runDeck(const EngineDeck& deck, const std::string& outDir,
                   const plugin::CycleSimulation::Progress& progress = {},
                   const std::vector<plugin::RowSink*>& extraSinks = {});

/// The same for a model the caller built from the deck (buildModel() and then elements of
/// its own added or replaced). The deck gives the settings and the summary's inputs.
RunOutcome runModel(const EngineDeck& deck, plugin::PistonAssemblyModel& model,
                    const std::string& outDir,
                    const plugin::CycleSimulation::Progress& progress = {},
                    const std::vector<plugin::RowSink*>& extraSinks = {});

/// The '#' comment lines at the top of cycle.csv (program and deck, conventions).
std::vector<std::string> makeCycleCsvComments(const EngineDeck& deck);

/// The text of summary.json: inputs in SI (the liner model's own keys under
/// inputs.liner), results, timings. Numbers are written so that they read back to the
/// identical double.
std::string makeSummaryJson(const EngineDeck& deck, const RunOutcome& outcome);

}  // namespace pistondyn::io
