#pragma once
// What `pistondyn sweep` shares between its one-process run (SweepCommand.cpp) and its
// MPI run (SweepMpi.cpp, built when MPI is found): options, loading the sweep with the
// documented error report, progress lines and the final report with its exit code.

#include <optional>
#include <string>
#include <vector>

#include "pistondyn/io/StudyComparison.h"
#include "pistondyn/io/SweepDeck.h"
#include "pistondyn/io/SweepRun.h"

namespace pistondyn::app {

struct SweepOptions {
  std::string sweepDeck, outDir;
  std::vector<std::string> overrides;  // --set, shared by every case
  int jobs = 0;                        // 0: the default (cores; 1 per MPI rank)
  bool list = false, quiet = false, noPlot = false;
  std::string fidelity = "full";       // --fidelity full|preview (CommandSupport.h)
};

// kExitUsage after printing why if --out cannot be the sweep's folder (a file, a folder
// that cannot be created or written: findOutputFolderProblem), else 0.
int checkOutPath(const SweepOptions& options);
// The sweep with every case checked, or nullopt after printing every problem on stderr
// (the caller exits with kExitBadInput). --fidelity preview: the base deck's preview grid
// (io::Fidelity, with the shared overrides) is added to the shared overrides, so every
// case runs it and sweep.json's fingerprint tells the preview sweep from the full one; a
// sweep that varies the film grid itself is refused.
std::optional<io::SweepPlan> loadSweepOrReport(const SweepOptions& options);
// --list: the cases as CSV on stdout (case, one column per swept key).
void printCaseList(const io::SweepPlan& plan);
// The line printed before cases run (stderr, unless quiet).
void printSweepStart(const SweepOptions& options, const io::SweepPlan& plan,
                     const io::SweepOutputState& state, const std::string& workers);
// One line per finished case (stderr, unless quiet); `where` names the rank, if any.
void printCaseDone(const SweepOptions& options, const io::SweepPlan& plan,
                   const io::SweepCaseResult& r, int done, int total, const std::string& where);
// The closing report on stdout; returns kExitOk or kExitSomeCasesFailed.
int reportSweep(const SweepOptions& options, const io::SweepPlan& plan,
                const io::SweepOutcome& outcome, double wallTime_s);

// The cases run in this process, threads and one model each (io::runSweep), with every
// case's result (those complete from an earlier run included): what `sweep` and `study`
// share. Prints the start line and a line per case (unless quiet); `outcome` and
// `wallTime_s` for reportSweep(). Throws as io::runSweep.
std::vector<io::SweepCaseResult> runCasesHere(const SweepOptions& options,
                                              const io::SweepPlan& plan, io::SweepOutcome& outcome,
                                              double& wallTime_s);

// Comparison figures of the cases that finished (ComparisonPlots.h) in DIR/plots/ and the
// page DIR/comparison.html with the cases side by side and the figures (ComparisonReport.h):
// at most kMaxComparedCases, else neither (said on stdout). A failure (gnuplot missing, say)
// is a warning: the results are complete, the page says why it has no figures. Prints what
// was written.
void drawComparisonPlots(const SweepOptions& options, const io::StudyComparison& comparison);

// True when this process was started by mpirun / srun (the launcher's environment).
bool isMpiLaunch();
// The launcher's process count (1 if unknown).
int getMpiLaunchSize();

#ifdef PISTONDYN_WITH_MPI
// The sweep across the MPI ranks: rank 0 checks, prepares the folder, hands out case
// indices on request and writes sweep.csv; every rank runs cases. Returns the exit code
// (the same on every rank).
int runSweepMpi(const SweepOptions& options);
#endif

}  // namespace pistondyn::app
