// `mpirun -np K pistondyn optimize|fit|propagate DECK --out DIR`: a design study whose
// evaluations are shared by K ranks. Built only when CMake finds MPI.
//
// Rank 0 checks the deck and opens DIR exactly as one process does, sends every rank the
// evaluation store (DIR, base deck, shared overrides, context), then runs the study on a
// thread of its own while its main thread hands out evaluations: a rank with a free
// thread asks for one, rank 0 sends the next evaluation requested (or keeps the rank
// waiting until the study requests one), the rank runs it into DIR/evaluations/<id>/ with
// the same EvaluationStore::run() as a thread in one process would and sends the result
// back. Rank 0 runs evaluations on its own threads too (--jobs, default 1). The study's
// decisions depend only on the results, never on which rank produced them or when, so
// the evaluated set and the outcome equal the one-process run's.
//
// Only the main thread of a rank calls MPI (MPI_THREAD_FUNNELED); waiting ranks poll with
// short sleeps instead of blocking in MPI, whose blocking calls spin a core.

#include <mpi.h>

#include <atomic>
#include <chrono>
#include <deque>
#include <future>
#include <iostream>
#include <map>
#include <memory>
#include <thread>

#include "DesignSupport.h"
#include "Subcommand.h"

namespace pistondyn::app {
namespace {

enum Tag : int {
  kTagRequest = 11,  // rank -> 0: a thread is free (an int, unused)
  kTagAssign = 12,   // 0 -> rank: "<id>\n<request>", or "" : no more evaluations
  kTagResult = 13,   // rank -> 0: an encoded EvaluationResult
  kTagDone = 14,     // rank -> 0: this rank ends and sends nothing more
};

constexpr auto kPoll = std::chrono::milliseconds(2);

void waitPolling(MPI_Request& request) {
  int done = 0;
  for (;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done)
      return;
    std::this_thread::sleep_for(kPoll);
  }
}

void broadcastInt(int& value) {
  MPI_Request request;
  MPI_Ibcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
  waitPolling(request);
}

void broadcastString(std::string& text) {
  long long size = static_cast<long long>(text.size());
  MPI_Request request;
  MPI_Ibcast(&size, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD, &request);
  waitPolling(request);
  text.resize(static_cast<std::size_t>(size));
  MPI_Ibcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD, &request);
  waitPolling(request);
}

void sendString(const std::string& text, int dest, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, dest, tag, MPI_COMM_WORLD);
}

std::string receiveString(const MPI_Status& probed) {
  int count = 0;
  MPI_Get_count(&probed, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return text;
}

void sendInt(int value, int dest, int tag) {
  MPI_Send(&value, 1, MPI_INT, dest, tag, MPI_COMM_WORLD);
}

int receiveInt(const MPI_Status& probed) {
  int value = 0;
  MPI_Recv(&value, 1, MPI_INT, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return value;
}

template <class T>
bool isReady(const std::future<T>& f) {
  return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

// Rank 0's executor: evaluations the study requests wait in a queue the main thread serves.
class MpiExecutor final : public design::Executor {
 public:
  struct Job {
    std::string id;
    design::EvaluationRequest request;
    std::promise<design::EvaluationResult> promise;
  };
  explicit MpiExecutor(const design::EvaluationStore& store) : Executor(store) {}

  std::shared_ptr<Job> take() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (pending_.empty())
      return nullptr;
    auto job = pending_.front();
    pending_.pop_front();
    return job;
  }

 protected:
  std::shared_future<design::EvaluationResult> submit(const design::EvaluationRequest& request,
                                                      const std::string& id) override {
    auto job = std::make_shared<Job>();
    job->id = id;
    job->request = request;
    auto future = job->promise.get_future().share();
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.push_back(std::move(job));
    return future;
  }

 private:
  std::mutex mutex_;
  std::deque<std::shared_ptr<Job>> pending_;
};

// Rank 0: the study on its own thread, the evaluations handed out from here.
int coordinate(DesignTask& task, int ranks, int jobs) {
  const design::EvaluationStore& store = task.getStore();
  MpiExecutor executor(store);
  std::atomic<bool> studyDone{false};
  int code = kExitFailed;
  std::thread study([&] {
    try {
      code = task.run(executor);
    } catch (const std::exception& e) {
      std::cerr << "pistondyn: the study failed: " << e.what() << "\n";
      code = kExitFailed;
    }
    studyDone = true;
  });
  std::map<std::string, std::shared_ptr<MpiExecutor::Job>> remote;
  std::vector<std::pair<std::shared_ptr<MpiExecutor::Job>, std::future<design::EvaluationResult>>>
      local;
  std::deque<int> waiting;  // ranks whose request is unanswered
  int ranksDone = 0;
  auto assign = [&](int rank, const std::shared_ptr<MpiExecutor::Job>& job) {
    sendString(job->id + "\n" + design::encodeRequest(job->request), rank, kTagAssign);
    remote.emplace(job->id, job);
  };
  bool stopping = false;
  while (!stopping || ranksDone < ranks - 1) {
    bool busy = false;
    for (auto it = local.begin(); it != local.end();) {
      if (isReady(it->second)) {
        it->first->promise.set_value(it->second.get());
        it = local.erase(it);
        busy = true;
      } else {
        ++it;
      }
    }
    while (!waiting.empty()) {
      auto job = executor.take();
      if (!job)
        break;
      assign(waiting.front(), job);
      waiting.pop_front();
      busy = true;
    }
    while (static_cast<int>(local.size()) < jobs) {
      auto job = executor.take();
      if (!job)
        break;
      const design::EvaluationRequest request = job->request;
      local.emplace_back(
          job, std::async(std::launch::async, [&store, request] { return store.run(request); }));
      busy = true;
    }
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (flag) {
      busy = true;
      if (status.MPI_TAG == kTagRequest) {
        receiveInt(status);
        if (stopping) {
          sendString("", status.MPI_SOURCE, kTagAssign);
        } else if (auto job = executor.take()) {
          assign(status.MPI_SOURCE, job);
        } else {
          waiting.push_back(status.MPI_SOURCE);
        }
      } else if (status.MPI_TAG == kTagResult) {
        design::EvaluationResult r = design::decodeResult(receiveString(status));
        const auto it = remote.find(r.id);
        if (it == remote.end())
          throw std::runtime_error("rank " + std::to_string(status.MPI_SOURCE) +
                                   " sent the result of an evaluation it was not given (" + r.id +
                                   ")");
        it->second->promise.set_value(std::move(r));
        remote.erase(it);
      } else if (status.MPI_TAG == kTagDone) {
        receiveInt(status);
        ++ranksDone;
      } else {
        throw std::runtime_error("rank " + std::to_string(status.MPI_SOURCE) +
                                 " sent an unknown message (tag " + std::to_string(status.MPI_TAG) +
                                 ")");
      }
    }
    if (!stopping && studyDone && local.empty() && remote.empty()) {
      stopping = true;
      for (const int rank : waiting)
        sendString("", rank, kTagAssign);
      waiting.clear();
    }
    if (!busy)
      std::this_thread::sleep_for(kPoll);
  }
  study.join();
  return code;
}

// Ranks 1..K-1: ask for an evaluation whenever a thread is free, run it, send the result.
void work(const design::EvaluationStore& store, int jobs) {
  std::vector<std::future<design::EvaluationResult>> running;
  int outstanding = 0;
  bool stop = false;
  for (;;) {
    bool busy = false;
    for (auto it = running.begin(); it != running.end();) {
      if (isReady(*it)) {
        sendString(design::encodeResult(it->get()), 0, kTagResult);
        it = running.erase(it);
        busy = true;
      } else {
        ++it;
      }
    }
    if (!stop) {
      for (; static_cast<int>(running.size()) + outstanding < jobs; ++outstanding)
        sendInt(0, 0, kTagRequest);
    }
    if (stop && outstanding == 0 && running.empty())
      break;
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(0, kTagAssign, MPI_COMM_WORLD, &flag, &status);
    if (flag) {
      busy = true;
      const std::string text = receiveString(status);
      --outstanding;
      if (text.empty()) {
        stop = true;
      } else {
        const std::size_t eol = text.find('\n');
        const design::EvaluationRequest request = design::decodeRequest(text.substr(eol + 1));
        running.push_back(
            std::async(std::launch::async, [&store, request] { return store.run(request); }));
      }
    }
    if (!busy)
      std::this_thread::sleep_for(kPoll);
  }
  sendInt(0, 0, kTagDone);
}

}  // namespace

int runDesignTaskMpi(const DesignOptions& options, DesignTask& task) {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    std::cerr << "pistondyn: MPI could not be initialised\n";
    return kExitFailed;
  }
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (provided < MPI_THREAD_FUNNELED) {
    if (rank == 0)
      std::cerr << "pistondyn: this MPI library offers no thread support (MPI_THREAD_FUNNELED), "
                   "which design studies need\n";
    MPI_Finalize();
    return kExitFailed;
  }
  const int jobs = options.jobs > 0 ? options.jobs : 1;
  int code = kExitOk;
  std::string storeText;
  try {
    if (rank == 0) {
      code = task.prepare();
      if (code == kExitOk)
        storeText = task.getStore().encode();
    }
    broadcastInt(code);
    if (code != kExitOk) {
      MPI_Finalize();
      return code;
    }
    broadcastString(storeText);
    if (rank == 0) {
      code = coordinate(task, ranks, jobs);
    } else {
      const design::EvaluationStore store = design::EvaluationStore::decode(storeText);
      work(store, jobs);
    }
  } catch (const std::exception& e) {
    std::cerr << "pistondyn: rank " << rank << ": the MPI study failed: " << e.what() << "\n";
    MPI_Abort(MPI_COMM_WORLD, kExitFailed);
  }
  broadcastInt(code);  // every rank exits with rank 0's code
  MPI_Finalize();
  return code;
}

}  // namespace pistondyn::app
