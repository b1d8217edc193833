#pragma once
/// \file
/// Running a sweep (SweepDeck.h) into an output folder:
///
///   DIR/sweep.json        the sweep's normalised content and fingerprint, written first
///   DIR/case_0001/        one run folder per case: cycle.csv and summary.json, written
///                         all-or-nothing by runDeck(), then case.json (the sweep's
///                         fingerprint and the case's overrides) marks the case complete
///   DIR/sweep.csv         one row per case: its overrides, status and summary figures
///
/// Resuming: a folder whose sweep.json holds the same fingerprint is continued; a case
/// folder with summary.json, cycle.csv and a matching case.json is complete and not rerun;
/// any other case folder is half-finished and is removed and rerun. A folder holding
/// another sweep, or anything that is not a sweep, is refused (SweepOutputError).
///
/// Threads: every case builds its own model (runDeck), models are never shared between
/// threads. runSweepCase() may run on several threads at once; SweepCasePool does that.

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "pistondyn/io/LinerRegistry.h"
#include "pistondyn/io/SweepDeck.h"

namespace pistondyn::io {

namespace detail {
struct SweepCsvRow;  ///< a result parsed once for sweep.csv (SweepRun.cpp)
}

/// The output folder cannot be used for this sweep (a file, another sweep, a folder that
/// is not a sweep's). Nothing has been written.
class SweepOutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The outcome of one case of a sweep.
struct SweepCaseResult {
  int index = 0;                ///< the case (1-based)
  bool ok = false;              ///< the case ran and wrote its results
  bool fromEarlierRun = false;  ///< found complete in the folder, not run now
  /// Stopped by SIGINT / SIGTERM (common/Cancellation.h), or not started after one: not
  /// recorded in sweep.csv, rerun when the sweep is resumed.
  bool cancelled = false;
  std::string message;          ///< why the case failed (one line)
  std::string summaryJson;      ///< ok: the text of the case's summary.json
  double wallTime_s = 0.0;      ///< of the run now, deck reading included [s]
};

/// What openSweepOutput() found in the output folder.
struct SweepOutputState {
  bool resumed = false;                   ///< the folder held this sweep already
  std::vector<SweepCaseResult> complete;  ///< cases found complete, by index
  std::vector<int> toRun;                 ///< every other case, ascending
  std::vector<int> halfFinished;          ///< case folders found incomplete (removed)
  /// An exclusive lock on DIR/.sweep.lock, held while this state (or a copy) lives: a
  /// second sweep started into the same folder is refused instead of mixing its writes.
  std::shared_ptr<const void> folderLock;
};

/// Prepares `dir` for `plan`: creates it and writes sweep.json, or checks that its
/// sweep.json is this sweep's and finds the complete cases (half-finished case folders are
/// removed). Throws SweepOutputError if `dir` is a file, holds a different sweep, is a
/// non-empty folder without sweep.json or is in use by another sweep (its lock is held);
/// std::runtime_error if it cannot be written.
SweepOutputState openSweepOutput(const SweepPlan& plan, const std::string& dir);

/// Runs case `index` of `plan` into its case folder of `dir` (runDeck: all-or-nothing) and marks
/// it complete with case.json. Never throws: a failure is a result with ok = false and the
/// message (the case folder is then left absent).
SweepCaseResult runSweepCase(const SweepPlan& plan, const std::string& dir, int index,
                             const LinerRegistry& registry = LinerRegistry::getGlobal());

/// One case of a deck run into its own folder: what a sweep case is (runSweepCase) and
/// what each evaluation of the design loop is (pistondyn::design: optimize, fit,
/// propagate), so both run the same way on threads and MPI ranks.
struct CaseInFolder {
  std::string baseDeckPath;            ///< the deck the overrides apply to
  std::vector<std::string> overrides;  ///< --set assignments, in order
  std::string folder;                  ///< the run folder (cycle.csv, summary.json)
  /// Files the case's deck reads (a generated skirt profile table): written into the
  /// folder before the deck is loaded, kept with the results.
  std::vector<std::pair<std::string, std::string>> inputFiles;  ///< name, content
  /// The marker written (all-or-nothing) once the run and its summary.json are complete:
  /// what tells a resumed sweep or design loop that the case need not run again.
  ///@{
  std::string markerName, markerText;
  ///@}
};
/// Removes what an earlier, interrupted run left in the folder, writes the input files,
/// loads the deck with the overrides (deck reading is serialised across threads), runs it
/// with runDeck() and writes the marker. Never throws: a failure is a result with ok =
/// false and a one-line message; the folder then holds at most the input files.
SweepCaseResult runCaseInFolder(const CaseInFolder& c,
                                const LinerRegistry& registry = LinerRegistry::getGlobal());

/// The text of sweep.csv for the results given (any order, at most one per case): '#'
/// comment lines (program, sweep, conventions), a header, then one row per case in index
/// order:
/// `case`, one column per swept key, `status`, every numeric or true/false key under
/// summary.json's results (named after it), `wall_time_s`, `integrator_steps`, `message`.
/// status is ok or failed; message is the failure (quoted). Numbers are copied as
/// summary.json has them (shortest text reading back to the same double); a case that does
/// not set a key or lacks a figure leaves its cell empty (never nan or inf). wall_time_s
/// and integrator_steps are the run's (summary.json's top level), one column each.
std::string makeSweepCsv(const SweepPlan& plan, const std::vector<SweepCaseResult>& results);

/// Collects the results of a sweep and keeps DIR/sweep.csv up to date: rewritten (all-or-
/// nothing) at most every `rewriteInterval` while cases finish, and by finish().
class SweepRecorder {
 public:
  /// Records into `dir` for `plan`, starting from what openSweepOutput() found.
  SweepRecorder(const SweepPlan& plan, std::string dir, const SweepOutputState& state,
                std::chrono::milliseconds rewriteInterval = std::chrono::seconds(2));
  /// Records a case run now; rewrites sweep.csv if the last write is older than the
  /// interval. Never throws (a failed intermediate write is retried by finish()).
  void record(SweepCaseResult result);
  /// Writes sweep.csv with every result recorded. Throws std::runtime_error.
  void finish();

  int getCaseCount() const { return static_cast<int>(plan_.cases.size()); }  ///< of the plan
  int getRecordedCount() const { return recorded_; }  ///< run now or found complete
  int getFailedCount() const { return failed_; }      ///< failed cases recorded
  int getEarlierCount() const { return earlier_; }    ///< found complete in the folder

 private:
  void write();
  const SweepPlan& plan_;
  std::string dir_;
  std::vector<std::shared_ptr<const detail::SweepCsvRow>> rows_;  ///< by index - 1; null: none yet
  int recorded_ = 0, failed_ = 0, earlier_ = 0;
  std::chrono::steady_clock::time_point lastWrite_;
  std::chrono::milliseconds interval_;
};

/// A fixed number of threads that run cases from a queue the owner fills. Used by
/// runSweep() (all cases queued at once) and by the MPI coordinator (cases handed out as
/// ranks and threads ask for them).
class SweepCasePool {
 public:
  /// Runs one case (by index); must not throw.
  using RunCase = std::function<SweepCaseResult(int index)>;
  /// Starts `threads` threads that run queued cases with `run`.
  SweepCasePool(int threads, RunCase run);
  /// Drops the cases still queued and waits for the running ones.
  ~SweepCasePool();
  SweepCasePool(const SweepCasePool&) = delete;
  SweepCasePool& operator=(const SweepCasePool&) = delete;

  void push(int index);  ///< queues a case
  /// No more cases: the threads end when the queue is empty.
  void close();
  /// Threads not busy with (or reserved by) a queued or running case.
  int getFreeSlots() const;
  /// Nothing queued, running or finished-but-not-taken.
  bool isIdle() const;
  /// The results finished since the last call; waits up to `timeout` for one if none.
  std::vector<SweepCaseResult> takeFinished(std::chrono::milliseconds timeout);

 private:
  void work();
  RunCase run_;
  mutable std::mutex mutex_;
  std::condition_variable wakeWorker_, wakeOwner_;
  std::deque<int> queue_;
  std::vector<SweepCaseResult> finished_;
  int running_ = 0;
  int threads_;
  bool closed_ = false;
  std::vector<std::thread> workers_;
};

/// One line per case as it finishes (the result, cases done so far, cases to do).
using SweepProgress = std::function<void(const SweepCaseResult&, int done, int total)>;

/// What runSweep() did.
struct SweepOutcome {
  int cases = 0;                  ///< in the sweep
  int earlier = 0;                ///< complete from an earlier run, not rerun
  int ran = 0;                    ///< run now
  int failed = 0;                 ///< of those run now
  std::vector<int> halfFinished;  ///< incomplete case folders found and rerun
};

/// The whole sweep in this process: openSweepOutput(), the remaining cases on `jobs`
/// threads (each case its own model), sweep.csv. Throws SweepOutputError (folder refused,
/// nothing written) or std::runtime_error (the folder or sweep.csv cannot be written).
/// After a cancellation request (common/Cancellation.h) the running cases stop, queued ones
/// do not start, sweep.csv is written with the cases that finished, and common::Cancelled
/// is thrown: the folder is left to be resumed.
SweepOutcome runSweep(const SweepPlan& plan, const std::string& dir, int jobs,
                      const SweepProgress& progress = {},
                      const LinerRegistry& registry = LinerRegistry::getGlobal());
/// The same after the caller's own openSweepOutput() (e.g. to report what it found).
SweepOutcome runSweep(const SweepPlan& plan, const std::string& dir, const SweepOutputState& state,
                      int jobs, const SweepProgress& progress = {},
                      const LinerRegistry& registry = LinerRegistry::getGlobal());

/// Logical processors this process may run on (sched_getaffinity), at least 1.
int getAvailableCores();

}  // namespace pistondyn::io
