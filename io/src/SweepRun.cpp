#include "pistondyn/io/SweepRun.h"

#include "CsvText.h"
#include "FileBytes.h"

#include <fcntl.h>
#include <sched.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pistondyn/common/Cancellation.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/RunDeck.h"
#include "pistondyn/io/Version.h"

namespace pistondyn::io {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

const char* kSweepJson = "sweep.json";
const char* kSweepCsv = "sweep.csv";
const char* kCaseJson = "case.json";

std::optional<std::string> readText(const fs::path& p) {
  return detail::readFileBytes(p.string());
}

// A message on one line (sweep.csv holds one row per case).
std::string oneLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
    text.pop_back();
  std::string out;
  for (const char c : text) {
    if (c == '\n')
      out += " | ";
    else if (c != '\r')
      out += c;
  }
  return out;
}

std::string caseJson(const SweepPlan& plan, const SweepCase& c) {
  Json j;
  j["sweep_fingerprint"] = plan.fingerprint;
  j["case"] = c.index;
  j["folder"] = plan.getCaseFolderName(c.index);
  j["overrides"] = plan.getOverrides(c);
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

// The summary.json text of a complete case folder of this sweep, or nullopt.
std::optional<std::string> completeCase(const SweepPlan& plan, const fs::path& folder, int index) {
  std::error_code ec;
  if (!fs::is_regular_file(folder / "cycle.csv", ec))
    return std::nullopt;
  const auto marker = readText(folder / kCaseJson);
  const auto summary = readText(folder / "summary.json");
  if (!marker || !summary)
    return std::nullopt;
  try {
    const Json m = Json::parse(*marker);
    if (m.at("sweep_fingerprint").get<std::string>() != plan.fingerprint ||
        m.at("case").get<int>() != index)
      return std::nullopt;
    if (!Json::parse(*summary).at("results").is_object())
      return std::nullopt;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  return summary;
}

// flock() on DIR/.sweep.lock; released when the last copy of the pointer goes. A file
// system without flock() support runs the sweep unlocked.
std::shared_ptr<const void> lockFolder(const fs::path& folder) {
  const std::string path = (folder / ".sweep.lock").string();
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error(path + ": cannot create the sweep's lock file");
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    if (err == EWOULDBLOCK) {
      ::close(fd);
      throw SweepOutputError(folder.string() +
                             " is in use by another pistondyn sweep running now (it holds " + path +
                             "); wait for it to end, or use another folder");
    }
  }
  return std::shared_ptr<const void>(new int(fd), [](const void* p) {
    const int* handle = static_cast<const int*>(p);
    ::close(*handle);
    delete handle;
  });
}

std::string shortHash(const std::string& sha) {
  return sha.substr(0, 12);
}

// Why the sweep stored in a folder is not this one, in words.
std::string describeDifference(const SweepPlan& stored, const SweepPlan& plan) {
  std::vector<std::string> why;
  if (stored.baseDeckSha256 != plan.baseDeckSha256) {
    why.push_back("the base deck's content differs (" + plan.baseDeckPath + " sha256 " +
                  shortHash(plan.baseDeckSha256) + "..., the folder's " + stored.baseDeckPath +
                  " " + shortHash(stored.baseDeckSha256) + "...)");
  }
  auto hashes = [](const SweepPlan& p) {
    std::vector<std::string> h;
    for (const auto& f : p.inputFiles)
      h.push_back(f.sha256);
    return h;
  };
  if (hashes(stored) != hashes(plan))
    why.push_back("a table the cases read (pressure table, liner tables) differs");
  if (stored.fixedOverrides != plan.fixedOverrides)
    why.push_back("the overrides every case shares (set:, --set) differ");
  std::vector<std::string> keysA, keysB;
  for (const auto& k : stored.sweptKeys)
    keysA.push_back(k.key);
  for (const auto& k : plan.sweptKeys)
    keysB.push_back(k.key);
  if (keysA != keysB)
    why.push_back("the swept keys differ");
  if (stored.cases.size() != plan.cases.size()) {
    why.push_back("it has " + std::to_string(stored.cases.size()) + " cases, this sweep " +
                  std::to_string(plan.cases.size()));
  } else {
    for (std::size_t i = 0; i < plan.cases.size(); ++i) {
      if (stored.getOverrides(stored.cases[i]) != plan.getOverrides(plan.cases[i]) &&
          stored.fixedOverrides == plan.fixedOverrides) {
        why.push_back("case " + std::to_string(i + 1) + "'s overrides differ");
        break;
      }
    }
  }
  if (why.empty())
    why.push_back("its fingerprint differs");
  std::string text;
  for (const auto& w : why)
    text += (text.empty() ? "" : "; ") + w;
  return text;
}

using detail::csvField;

// A JSON number as sweep.csv writes it; "" for anything else (null: a NaN never appears).
std::optional<std::string> numberText(const Json& v) {
  if (v.is_number_integer())
    return std::to_string(v.get<long long>());
  if (v.is_number_unsigned())
    return std::to_string(v.get<unsigned long long>());
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (std::isfinite(d))
      return formatNumber(d);
  }
  return std::nullopt;
}

}  // namespace

// ---- sweep.csv -------------------------------------------------------------------------

namespace detail {
struct SweepCsvRow {
  int index = 0;
  bool ok = false;
  std::string message;
  std::vector<std::pair<std::string, std::string>> figures;  // results, as written
  std::string wallTime, steps;
};
}  // namespace detail

namespace {

using Row = detail::SweepCsvRow;

std::shared_ptr<const Row> parseRow(const SweepCaseResult& r) {
  auto row = std::make_shared<Row>();
  row->index = r.index;
  row->ok = r.ok;
  row->message = oneLine(r.message);
  if (!r.ok)
    return row;
  try {
    const Json j = Json::parse(r.summaryJson);
    for (const auto& [key, value] : j.at("results").items()) {
      // The run's own figures have their columns at the end (one column per name).
      if (key == "wall_time_s" || key == "integrator_steps")
        continue;
      if (value.is_boolean())
        row->figures.emplace_back(key, value.get<bool>() ? "true" : "false");
      else if (const auto t = numberText(value))
        row->figures.emplace_back(key, *t);
    }
    if (j.contains("wall_time_s"))
      row->wallTime = numberText(j["wall_time_s"]).value_or("");
    if (j.contains("integrator_steps"))
      row->steps = numberText(j["integrator_steps"]).value_or("");
  } catch (const nlohmann::json::exception& e) {
    row->ok = false;
    row->message = std::string("its summary.json cannot be read: ") + e.what();
    row->figures.clear();
  }
  return row;
}

std::string csvFromRows(const SweepPlan& plan,
                        const std::vector<std::shared_ptr<const Row>>& rows) {
  // Figure columns: every key any case reports, in summary.json's order (a key only some
  // cases have is placed after the key it follows there).
  std::vector<std::string> figureKeys;
  for (const auto& row : rows) {
    if (!row)
      continue;
    std::size_t insertAt = 0;
    for (const auto& [key, text] : row->figures) {
      const auto it = std::find(figureKeys.begin(), figureKeys.end(), key);
      if (it != figureKeys.end()) {
        insertAt = static_cast<std::size_t>(it - figureKeys.begin()) + 1;
      } else {
        figureKeys.insert(figureKeys.begin() + static_cast<long>(insertAt), key);
        ++insertAt;
      }
    }
  }
  std::ostringstream out;
  out << "# pistondyn " << getVersion() << " sweep results for "
      << escapeForCommentLine(plan.sweepDeckPath) << " (base deck "
      << escapeForCommentLine(plan.baseDeckPath) << ")\n";
  out << "# sweep fingerprint " << plan.fingerprint << "; " << plan.cases.size()
      << " cases, run folders " << plan.getCaseFolderName(1) << "/ .. "
      << plan.getCaseFolderName(static_cast<int>(plan.cases.size()))
      << "/ (cycle.csv, summary.json)\n";
  out << "# crank angle 0 deg = firing TDC; figures of the last simulated 720 deg cycle of "
         "each case, named as under results in its summary.json\n";
  out << "case";
  for (const auto& k : plan.sweptKeys)
    out << ',' << csvField(k.key);
  out << ",status";
  for (const auto& k : figureKeys)
    out << ',' << csvField(k);
  out << ",wall_time_s,integrator_steps,message\n";
  for (const auto& row : rows) {
    if (!row)
      continue;
    const SweepCase& c = plan.getCase(row->index);
    out << row->index;
    for (const auto& k : plan.sweptKeys) {
      out << ',';
      for (const auto& a : c.assignments) {
        if (a.key == k.key)
          out << csvField(a.value);
      }
    }
    out << ',' << (row->ok ? "ok" : "failed");
    for (const auto& k : figureKeys) {
      out << ',';
      for (const auto& [key, text] : row->figures) {
        if (key == k)
          out << text;
      }
    }
    out << ',' << row->wallTime << ',' << row->steps << ',' << csvField(row->message) << '\n';
  }
  return out.str();
}

}  // namespace

std::string makeSweepCsv(const SweepPlan& plan, const std::vector<SweepCaseResult>& results) {
  std::vector<std::shared_ptr<const Row>> rows(plan.cases.size());
  for (const auto& r : results)
    rows.at(static_cast<std::size_t>(r.index - 1)) = parseRow(r);
  return csvFromRows(plan, rows);
}

SweepRecorder::SweepRecorder(const SweepPlan& plan, std::string dir, const SweepOutputState& state,
                             std::chrono::milliseconds rewriteInterval)
    : plan_(plan),
      dir_(std::move(dir)),
      rows_(plan.cases.size()),
      lastWrite_(std::chrono::steady_clock::now()),
      interval_(rewriteInterval) {
  for (const auto& r : state.complete) {
    rows_.at(static_cast<std::size_t>(r.index - 1)) = parseRow(r);
    ++recorded_;
    ++earlier_;
  }
}

void SweepRecorder::record(SweepCaseResult result) {
  auto& slot = rows_.at(static_cast<std::size_t>(result.index - 1));
  if (!slot)
    ++recorded_;
  slot = parseRow(result);
  if (!slot->ok)
    ++failed_;
  if (std::chrono::steady_clock::now() - lastWrite_ >= interval_) {
    try {
      write();
    } catch (const std::exception&) {
      // finish() writes again and reports the failure.
    }
  }
}

void SweepRecorder::write() {
  lastWrite_ = std::chrono::steady_clock::now();
  writeFilesAtomically(dir_, {{kSweepCsv, csvFromRows(plan_, rows_)}});
}

void SweepRecorder::finish() {
  write();
}

// ---- the output folder -----------------------------------------------------------------

SweepOutputState openSweepOutput(const SweepPlan& plan, const std::string& dir) {
  const fs::path folder(dir);
  std::error_code ec;
  SweepOutputState state;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
    throw SweepOutputError(dir + " is not a folder");
  if (fs::is_directory(folder, ec)) {
    const fs::path stored = folder / kSweepJson;
    if (fs::exists(stored, ec)) {
      const auto text = readText(stored);
      std::optional<SweepPlan> previous;
      std::string why;
      try {
        if (text)
          previous = parseSweepJson(*text);
      } catch (const std::exception& e) {
        why = e.what();
      }
      if (!previous) {
        throw SweepOutputError(stored.string() + " cannot be read as a sweep's description" +
                               (why.empty() ? std::string() : " (" + why + ")") +
                               "; use another --out folder");
      }
      if (previous->fingerprint != plan.fingerprint) {
        throw SweepOutputError(dir + " holds the results of a different sweep (" +
                               previous->sweepDeckPath +
                               "): " + describeDifference(*previous, plan) +
                               ". Results of different sweeps are never mixed: use another --out "
                               "folder, or delete this one to start the sweep afresh");
      }
      state.resumed = true;
    } else if (fs::directory_iterator(folder, ec) != fs::directory_iterator()) {
      throw SweepOutputError(dir +
                             " is not empty and holds no sweep.json: not the output folder of a "
                             "sweep; use a new or empty folder");
    }
  }
  if (!state.resumed) {
    // Created (with its parents) and described before any case runs.
    writeFilesAtomically(dir, {{kSweepJson, makeSweepJson(plan)}});
  }
  state.folderLock = lockFolder(folder);
  for (const auto& c : plan.cases) {
    const fs::path caseFolder = folder / plan.getCaseFolderName(c.index);
    if (!state.resumed || !fs::exists(caseFolder, ec)) {
      state.toRun.push_back(c.index);
      continue;
    }
    if (auto summary = completeCase(plan, caseFolder, c.index)) {
      SweepCaseResult r;
      r.index = c.index;
      r.ok = true;
      r.fromEarlierRun = true;
      r.summaryJson = std::move(*summary);
      state.complete.push_back(std::move(r));
      continue;
    }
    // Half-finished (interrupted, or a case that failed to be marked): start it again.
    fs::remove_all(caseFolder, ec);
    if (ec)
      throw std::runtime_error(caseFolder.string() +
                               ": cannot remove the half-finished case: " + ec.message());
    state.halfFinished.push_back(c.index);
    state.toRun.push_back(c.index);
  }
  return state;
}

// ---- one case --------------------------------------------------------------------------

namespace {

// Deck reading is serialised: yaml-cpp documents no thread safety, and it costs
// milliseconds against a simulation's seconds. Models are built and run in parallel.
std::mutex& deckMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

SweepCaseResult runCaseInFolder(const CaseInFolder& c, const LinerRegistry& registry) {
  SweepCaseResult r;
  const auto start = std::chrono::steady_clock::now();
  try {
    common::throwIfCancelled();  // queued cases after SIGINT / SIGTERM do not start
    const fs::path folder(c.folder);
    std::error_code ec;
    fs::remove_all(folder, ec);  // what an interrupted run left
    if (!c.inputFiles.empty())
      writeFilesAtomically(folder.string(), c.inputFiles);
    std::optional<EngineDeck> deck;
    {
      std::lock_guard<std::mutex> lock(deckMutex());
      deck.emplace(loadEngineDeck(c.baseDeckPath, c.overrides, registry));
    }
    runDeck(*deck, folder.string());
    const auto summary = readText(folder / "summary.json");
    if (!summary)
      throw std::runtime_error((folder / "summary.json").string() + ": cannot be read back");
    writeFilesAtomically(folder.string(), {{c.markerName, c.markerText}});
    r.ok = true;
    r.summaryJson = *summary;
  } catch (const common::Cancelled&) {
    r.cancelled = true;  // its folder was removed with what it had written
    r.message = "cancelled";
  } catch (const std::exception& e) {
    r.ok = false;
    r.message = oneLine(e.what());
    if (r.message.empty())
      r.message = "the run failed without a message";
  }
  r.wallTime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

SweepCaseResult runSweepCase(const SweepPlan& plan, const std::string& dir, int index,
                             const LinerRegistry& registry) {
  SweepCaseResult r;
  try {
    const SweepCase& c = plan.getCase(index);
    CaseInFolder job;
    job.baseDeckPath = plan.baseDeckPath;
    job.overrides = plan.getOverrides(c);
    job.folder = (fs::path(dir) / plan.getCaseFolderName(index)).string();
    job.markerName = kCaseJson;
    job.markerText = caseJson(plan, c);
    r = runCaseInFolder(job, registry);
  } catch (const std::exception& e) {
    r.ok = false;
    r.message = oneLine(e.what());
  }
  r.index = index;
  return r;
}

// ---- the pool --------------------------------------------------------------------------

SweepCasePool::SweepCasePool(int threads, RunCase run)
    : run_(std::move(run)), threads_(std::max(1, threads)) {
  workers_.reserve(static_cast<std::size_t>(threads_));
  for (int i = 0; i < threads_; ++i)
    workers_.emplace_back([this] { work(); });
}

SweepCasePool::~SweepCasePool() {
  // Normally every case has been taken already; if the owner is leaving early (an
  // exception), queued cases are dropped and only the running ones are waited for.
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.clear();
    closed_ = true;
  }
  wakeWorker_.notify_all();
  for (auto& t : workers_)
    t.join();
}

void SweepCasePool::push(int index) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(index);
  }
  wakeWorker_.notify_one();
}

void SweepCasePool::close() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }
  wakeWorker_.notify_all();
}

int SweepCasePool::getFreeSlots() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::max(0, threads_ - running_ - static_cast<int>(queue_.size()));
}

bool SweepCasePool::isIdle() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return queue_.empty() && running_ == 0 && finished_.empty();
}

std::vector<SweepCaseResult> SweepCasePool::takeFinished(std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  wakeOwner_.wait_for(lock, timeout, [this] { return !finished_.empty(); });
  std::vector<SweepCaseResult> out;
  out.swap(finished_);
  return out;
}

void SweepCasePool::work() {
  for (;;) {
    int index = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wakeWorker_.wait(lock, [this] { return closed_ || !queue_.empty(); });
      if (queue_.empty())
        return;  // closed and drained
      index = queue_.front();
      queue_.pop_front();
      ++running_;
    }
    SweepCaseResult r;
    try {
      r = run_(index);
    } catch (const std::exception& e) {
      r.index = index;
      r.ok = false;
      r.message = oneLine(e.what());
    } catch (...) {
      r.index = index;
      r.ok = false;
      r.message = "the case threw an unknown exception";
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      --running_;
      finished_.push_back(std::move(r));
    }
    wakeOwner_.notify_all();
  }
}

// ---- the whole sweep in one process ----------------------------------------------------

SweepOutcome runSweep(const SweepPlan& plan, const std::string& dir, int jobs,
                      const SweepProgress& progress, const LinerRegistry& registry) {
  return runSweep(plan, dir, openSweepOutput(plan, dir), jobs, progress, registry);
}

SweepOutcome runSweep(const SweepPlan& plan, const std::string& dir, const SweepOutputState& state,
                      int jobs, const SweepProgress& progress, const LinerRegistry& registry) {
  SweepRecorder recorder(plan, dir, state);
  SweepOutcome outcome;
  outcome.cases = static_cast<int>(plan.cases.size());
  outcome.earlier = static_cast<int>(state.complete.size());
  outcome.halfFinished = state.halfFinished;
  const int toRun = static_cast<int>(state.toRun.size());
  if (toRun > 0) {
    SweepCasePool pool(std::min(std::max(1, jobs), toRun),
                       [&](int index) { return runSweepCase(plan, dir, index, registry); });
    for (const int index : state.toRun)
      pool.push(index);
    pool.close();
    for (int taken = 0; taken < toRun;) {
      for (auto& r : pool.takeFinished(std::chrono::seconds(1))) {
        ++taken;
        if (r.cancelled)
          continue;  // neither run nor failed: a rerun of the sweep runs it
        ++outcome.ran;
        if (!r.ok)
          ++outcome.failed;
        if (progress)
          progress(r, outcome.ran, toRun);
        recorder.record(std::move(r));
      }
    }
  }
  recorder.finish();
  common::throwIfCancelled();  // sweep.csv holds the cases that finished
  return outcome;
}

int getAvailableCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) {
    const int n = CPU_COUNT(&set);
    if (n > 0)
      return n;
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace pistondyn::io
