#pragma once
// What `pistondyn optimize`, `fit` and `propagate` share: their options, running a study's
// evaluations on threads in one process or across MPI ranks (DesignMpi.cpp), and the
// output folder's checks.
//
// A study is a DesignTask: prepare() checks everything and opens the output folder
// (exit code != 0: nothing was simulated or written), run() makes the study's decisions
// with an executor and writes its results. Under mpirun only rank 0 prepares and runs the
// study; every rank (rank 0's threads too) runs evaluations as they are requested.

#include <CLI/CLI.hpp>

#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "FileText.h"
#include "pistondyn/design/DesignStudy.h"
#include "pistondyn/design/Evaluations.h"

namespace pistondyn::app {

struct DesignOptions {
  std::string deck, outDir;
  std::vector<std::string> overrides;  // --set, shared by every evaluation
  int jobs = 0;                        // 0: the cores (1 per MPI rank)
  bool quiet = false;
};

// DECK (shown as `deckName`, e.g. OPT.yaml), --out, --jobs, --set, --quiet.
void addDesignOptions(CLI::App& command, DesignOptions& options, const std::string& deckName,
                      const std::string& deckHelp, const std::string& outHelp);

class DesignTask {
 public:
  virtual ~DesignTask() = default;
  // Checks the command line, the deck and the output folder; prints why on stderr and
  // returns the exit code if any is refused (nothing written), else 0.
  virtual int prepare() = 0;
  // The evaluations' store (valid after a successful prepare()).
  virtual const design::EvaluationStore& getStore() const = 0;
  // The study with this executor; writes its results; returns the exit code.
  virtual int run(design::Executor& executor) = 0;
};

// Runs the task in this process (threads) or, when started by mpirun, across the ranks.
int runDesignTask(const DesignOptions& options, DesignTask& task);

// A progress line on stderr (unless quiet), whole lines from any thread.
class ProgressPrinter {
 public:
  ProgressPrinter(std::string command, bool quiet) : command_(std::move(command)), quiet_(quiet) {}
  void operator()(const std::string& line) const;

 private:
  std::string command_;
  bool quiet_;
  mutable std::mutex mutex_;
};

// The output folder check of every design command, before the deck is read: exit code 2
// (after printing why) or 0.
int checkDesignOutPath(const std::string& outDir);

// Prints the opened folder's refusal or the deck's problems in the documented form and
// returns the exit code; nullopt when `body` succeeded.
std::optional<int> reportPrepareError(const std::string& kindText,
                                      const std::function<void()>& body);

// The chosen design of a study (the optimum, the fitted values) as a deck of its own:
// `target`/engine.yaml, the base deck with the shared overrides and the design's values
// (file paths absolute; a profile table copied beside it), and `target`/run/ with the
// evaluation's cycle.csv and summary.json. `header` lines open the deck. Throws
// std::runtime_error.
void writeDesignDeck(const design::DesignStudy& study, const std::vector<double>& x,
                     const std::string& evaluationFolder, const std::string& target,
                     std::vector<std::string> header);

#ifdef PISTONDYN_WITH_MPI
int runDesignTaskMpi(const DesignOptions& options, DesignTask& task);
#endif

}  // namespace pistondyn::app
