#include "pistondyn/design/Evaluations.h"

#include <condition_variable>
#include <deque>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "FileBytes.h"
#include "Sha256.h"
#include "pistondyn/io/SweepRun.h"

namespace pistondyn::design {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

const char* kMarker = "evaluation.json";

std::string absolute(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

Json requestJson(const EvaluationRequest& r) {
  Json files = Json::array();
  for (const auto& [name, content] : r.files)
    files.push_back({{"name", name}, {"content", content}});
  return {{"overrides", r.overrides}, {"files", files}, {"file_key", r.fileKey}};
}

}  // namespace

// ---- the store ---------------------------------------------------------------------------

EvaluationStore::EvaluationStore(std::string dir, std::string baseDeckPath,
                                 std::vector<std::string> sharedOverrides, std::string context)
    : dir_(absolute(dir)),
      baseDeckPath_(std::move(baseDeckPath)),
      context_(std::move(context)),
      sharedOverrides_(std::move(sharedOverrides)) {}

std::string EvaluationStore::getId(const EvaluationRequest& r) const {
  Json j = requestJson(r);
  j["context"] = context_;
  return io::detail::sha256Hex(j.dump()).substr(0, 16);
}

std::string EvaluationStore::getFolder(const std::string& id) const {
  return (fs::path(dir_) / "evaluations" / id).string();
}

std::optional<EvaluationResult> EvaluationStore::findComplete(const EvaluationRequest& r) const {
  const std::string id = getId(r);
  const fs::path folder = getFolder(id);
  std::error_code ec;
  if (!fs::is_regular_file(folder / "cycle.csv", ec))
    return std::nullopt;
  const auto marker = io::detail::readFileBytes((folder / kMarker).string());
  const auto summary = io::detail::readFileBytes((folder / "summary.json").string());
  if (!marker || !summary)
    return std::nullopt;
  try {
    const Json m = Json::parse(*marker);
    if (m.at("id").get<std::string>() != id || m.at("context").get<std::string>() != context_)
      return std::nullopt;
    if (!Json::parse(*summary).at("results").is_object())
      return std::nullopt;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  EvaluationResult out;
  out.id = id;
  out.folder = folder.string();
  out.ok = true;
  out.fromEarlierRun = true;
  out.summaryJson = *summary;
  return out;
}

EvaluationResult EvaluationStore::run(const EvaluationRequest& r,
                                      const io::LinerRegistry& registry) const {
  EvaluationResult out;
  out.id = getId(r);
  out.folder = getFolder(out.id);
  io::CaseInFolder c;
  c.baseDeckPath = baseDeckPath_;
  c.overrides = sharedOverrides_;
  c.overrides.insert(c.overrides.end(), r.overrides.begin(), r.overrides.end());
  c.folder = out.folder;
  c.inputFiles = r.files;
  if (!r.fileKey.empty() && !r.files.empty())
    c.overrides.push_back(r.fileKey + "=" +
                          (fs::path(out.folder) / r.files.front().first).string());
  Json marker = requestJson(r);
  marker.erase("files");
  Json names = Json::array();
  for (const auto& f : r.files)
    names.push_back(f.first);
  marker["files"] = names;
  marker["id"] = out.id;
  marker["context"] = context_;
  c.markerName = kMarker;
  c.markerText = marker.dump(2) + "\n";
  const io::SweepCaseResult res = io::runCaseInFolder(c, registry);
  out.ok = res.ok;
  out.message = res.message;
  out.summaryJson = res.summaryJson;
  out.wallTime_s = res.wallTime_s;
  return out;
}

std::string EvaluationStore::encode() const {
  return Json{{"dir", dir_},
              {"base_deck", baseDeckPath_},
              {"shared", sharedOverrides_},
              {"context", context_}}
      .dump();
}

EvaluationStore EvaluationStore::decode(const std::string& text) {
  try {
    const Json j = Json::parse(text);
    return EvaluationStore(j.at("dir").get<std::string>(), j.at("base_deck").get<std::string>(),
                           j.at("shared").get<std::vector<std::string>>(),
                           j.at("context").get<std::string>());
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("not an evaluation store: ") + e.what());
  }
}

// ---- executors ---------------------------------------------------------------------------

std::vector<EvaluationResult> Executor::evaluate(const std::vector<EvaluationRequest>& requests) {
  std::vector<std::shared_future<EvaluationResult>> futures;
  futures.reserve(requests.size());
  for (const auto& r : requests) {
    const std::string id = store_.getId(r);
    std::unique_lock<std::mutex> lock(mutex_);
    const auto it = known_.find(id);
    if (it != known_.end()) {
      futures.push_back(it->second);
      continue;
    }
    lock.unlock();
    // Found complete in the folder: no worker needed (reading it takes milliseconds).
    if (auto done = store_.findComplete(r)) {
      std::promise<EvaluationResult> p;
      p.set_value(std::move(*done));
      lock.lock();
      const auto [slot, inserted] = known_.emplace(id, p.get_future().share());
      if (inserted)
        ++earlier_;
      futures.push_back(slot->second);
      continue;
    }
    lock.lock();
    // Another thread may have submitted it meanwhile.
    const auto again = known_.find(id);
    if (again != known_.end()) {
      futures.push_back(again->second);
      continue;
    }
    auto future = submit(r, id);
    known_.emplace(id, future);
    ++run_;
    futures.push_back(future);
  }
  std::vector<EvaluationResult> out;
  out.reserve(futures.size());
  for (auto& f : futures)
    out.push_back(f.get());
  return out;
}

int Executor::getRunCount() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return run_;
}

int Executor::getEarlierCount() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return earlier_;
}

struct ThreadExecutor::Impl {
  const io::LinerRegistry& registry;
  std::mutex mutex;
  std::condition_variable wake;
  std::deque<std::packaged_task<EvaluationResult()>> queue;
  bool stop = false;
  std::vector<std::thread> workers;

  explicit Impl(const io::LinerRegistry& r) : registry(r) {}
  void work() {
    for (;;) {
      std::packaged_task<EvaluationResult()> task;
      {
        std::unique_lock<std::mutex> lock(mutex);
        wake.wait(lock, [this] { return stop || !queue.empty(); });
        if (queue.empty())
          return;
        task = std::move(queue.front());
        queue.pop_front();
      }
      task();
    }
  }
};

ThreadExecutor::ThreadExecutor(const EvaluationStore& store, int threads,
                               const io::LinerRegistry& registry)
    : Executor(store), impl_(std::make_unique<Impl>(registry)) {
  for (int i = 0; i < std::max(1, threads); ++i)
    impl_->workers.emplace_back([this] { impl_->work(); });
}

ThreadExecutor::~ThreadExecutor() {
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->stop = true;
  }
  impl_->wake.notify_all();
  for (auto& t : impl_->workers)
    t.join();
}

std::shared_future<EvaluationResult> ThreadExecutor::submit(const EvaluationRequest& request,
                                                            const std::string& /*id*/) {
  std::packaged_task<EvaluationResult()> task(
      [this, request] { return store_.run(request, impl_->registry); });
  auto future = task.get_future().share();
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->queue.push_back(std::move(task));
  }
  impl_->wake.notify_one();
  return future;
}

// ---- as text -----------------------------------------------------------------------------

std::string encodeRequest(const EvaluationRequest& r) {
  return requestJson(r).dump();
}

EvaluationRequest decodeRequest(const std::string& text) {
  EvaluationRequest r;
  try {
    const Json j = Json::parse(text);
    r.overrides = j.at("overrides").get<std::vector<std::string>>();
    for (const auto& f : j.at("files"))
      r.files.emplace_back(f.at("name").get<std::string>(), f.at("content").get<std::string>());
    r.fileKey = j.at("file_key").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("not an evaluation request: ") + e.what());
  }
  return r;
}

std::string encodeResult(const EvaluationResult& r) {
  Json j = {{"id", r.id},
            {"folder", r.folder},
            {"ok", r.ok},
            {"earlier", r.fromEarlierRun},
            {"message", r.message},
            {"summary", r.summaryJson},
            {"wall_time_s", r.wallTime_s}};
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

EvaluationResult decodeResult(const std::string& text) {
  EvaluationResult r;
  try {
    const Json j = Json::parse(text);
    r.id = j.at("id").get<std::string>();
    r.folder = j.at("folder").get<std::string>();
    r.ok = j.at("ok").get<bool>();
    r.fromEarlierRun = j.at("earlier").get<bool>();
    r.message = j.at("message").get<std::string>();
    r.summaryJson = j.at("summary").get<std::string>();
    r.wallTime_s = j.at("wall_time_s").get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("not an evaluation result: ") + e.what());
  }
  return r;
}

}  // namespace pistondyn::design
