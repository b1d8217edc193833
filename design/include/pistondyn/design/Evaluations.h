#pragma once
/// @file
/// Evaluations of the design loop (optimize, fit, propagate): each one the base engine deck
/// run with its overrides into a folder of its own, by io::runCaseInFolder(), the code path
/// of a sweep case. They are stored by what decides their results:
///
/// ~~~
///   DIR/evaluations/<id>/   cycle.csv, summary.json (runDeck, all-or-nothing), the input
///                           files the design wrote (skirt_profile.csv), then
///                           evaluation.json, which marks it complete
/// ~~~
///
/// with `<id>` the first 16 hex digits of a SHA-256 of the study's context (base deck and
/// table contents, shared overrides) and the evaluation's own overrides and files. A
/// complete folder is never run again: a design loop interrupted and started again replays
/// its (deterministic) decisions, finds the evaluations it had made and continues where it
/// stopped; evaluations requested twice, by one search or by two running side by side, run
/// once.
///
/// Executors run evaluations on workers: threads of this process (ThreadExecutor) or MPI
/// ranks (the pistondyn program's, app/DesignMpi.cpp). Results do not depend on which
/// worker ran them, so the evaluated set and the loop's decisions are the same whatever
/// runs them.

#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pistondyn/io/LinerRegistry.h"

namespace pistondyn::design {

/// One evaluation asked of the store: the base deck run with these overrides and files.
/// What decides its results, and so its id (EvaluationStore::getId()).
struct EvaluationRequest {
  std::vector<std::string> overrides;  ///< "key=value", after the study's shared ones
  /// Files written into the evaluation's folder before the run; `fileKey` (if not empty) is
  /// set to the first file's path (the generated skirt profile's key).
  std::vector<std::pair<std::string, std::string>> files;  ///< name, content
  std::string fileKey;  ///< deck key set to the first file's path; "" = none
};

/// The outcome of one evaluation, run now or found complete in the folder.
struct EvaluationResult {
  std::string id;  ///< EvaluationStore::getId() of its request (16 hex digits)
  std::string folder;  ///< absolute
  bool ok = false;  ///< the run and its summary.json completed
  bool fromEarlierRun = false;  ///< found complete in DIR, not run now
  std::string message;          ///< why it failed (one line)
  std::string summaryJson;      ///< ok: the text of its summary.json
  double wallTime_s = 0.0;      ///< of the run now [s]
};

/// Where the evaluations of one study live, and how a request becomes a run.
class EvaluationStore {
 public:
  /// `dir`: the study's output folder; `context`: the hash of what every evaluation shares
  /// (DesignStudy::contextSha256).
  EvaluationStore(std::string dir, std::string baseDeckPath,
                  std::vector<std::string> sharedOverrides, std::string context);

  /// The request's id: the first 16 hex digits of the SHA-256 of its overrides, files and
  /// the study's context (this file's comment).
  std::string getId(const EvaluationRequest& r) const;
  std::string getFolder(const std::string& id) const;  ///< `DIR/evaluations/<id>`, absolute
  /// The result of a complete evaluation folder of this request, or nullopt.
  std::optional<EvaluationResult> findComplete(const EvaluationRequest& r) const;
  /// Runs the request into its folder now (never throws; a failure is ok = false).
  EvaluationResult run(const EvaluationRequest& r,
                       const io::LinerRegistry& registry = io::LinerRegistry::getGlobal()) const;

  /// The study's output folder DIR, as given.
  const std::string& getDirectory() const { return dir_; }
  /// The store as text (what the MPI ranks are sent); decode() reads it back.
  std::string encode() const;
  /// The store encode() wrote. Throws std::runtime_error for text that is not one.
  static EvaluationStore decode(const std::string& text);

 private:
  std::string dir_, baseDeckPath_, context_;
  std::vector<std::string> sharedOverrides_;
};

/// Runs evaluations on workers. evaluate() may be called from several threads at once;
/// each request is looked up in the store, then in what ran or runs now, and only then
/// submitted.
class Executor {
 public:
  /// An executor of the evaluations of `store`, which must outlive it.
  explicit Executor(const EvaluationStore& store) : store_(store) {}
  virtual ~Executor() = default;
  Executor(const Executor&) = delete;
  Executor& operator=(const Executor&) = delete;

  /// The results, in request order (blocks until every one is done). Never throws for a
  /// failed run.
  std::vector<EvaluationResult> evaluate(const std::vector<EvaluationRequest>& requests);
  /// Evaluations run now (requested at least once).
  int getRunCount() const;
  /// Evaluations found complete in the folder (requested at least once).
  int getEarlierCount() const;

 protected:
  /// Starts running `request` (whose id and folder are `id`, store.getFolder(id)).
  virtual std::shared_future<EvaluationResult> submit(const EvaluationRequest& request,
                                                      const std::string& id) = 0;
  const EvaluationStore& store_;  ///< the store given to the constructor

 private:
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_future<EvaluationResult>> known_;
  int run_ = 0, earlier_ = 0;
};

/// Threads of this process, one model each (io::runCaseInFolder).
class ThreadExecutor final : public Executor {
 public:
  /// `threads` worker threads (at least 1) running the evaluations of `store` (which must
  /// outlive it) with the liner models of `registry`. The destructor stops and joins them.
  ThreadExecutor(const EvaluationStore& store, int threads,
                 const io::LinerRegistry& registry = io::LinerRegistry::getGlobal());
  ~ThreadExecutor() override;

 protected:
  std::shared_future<EvaluationResult> submit(const EvaluationRequest& request,
                                              const std::string& id) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// @name Requests and results as text (what an MPI rank is sent and sends back)
/// Each decode reads what the matching encode wrote.
///@{
/// The request as text.
std::string encodeRequest(const EvaluationRequest& r);
/// The request encodeRequest() wrote.
EvaluationRequest decodeRequest(const std::string& text);
/// The result as text.
std::string encodeResult(const EvaluationResult& r);
/// The result encodeResult() wrote.
EvaluationResult decodeResult(const std::string& text);
///@}

}  // namespace pistondyn::design
