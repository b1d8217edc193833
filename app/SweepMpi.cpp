// `mpirun -np K pistondyn sweep SWEEP.yaml --out DIR`: the cases of one sweep shared by K
// ranks with dynamic load balancing. Built only when CMake finds MPI.
//
// Rank 0 reads and checks the sweep and prepares DIR exactly as a one-process sweep does,
// then sends every rank the sweep's normalised description (sweep.json's text). From
// then on each rank runs cases on its own threads (--jobs per rank, default 1): rank 0's
// threads take the next case directly, the other ranks ask rank 0 for one whenever a
// thread is free and report each result back (its summary.json text, so sweep.csv does
// not depend on when a shared file system shows another node's files). Rank 0 writes
// sweep.csv. A case is run by the same io::runSweepCase() as in one process, so the
// results are identical case by case.
//
// Only the main thread of a rank calls MPI (MPI_THREAD_FUNNELED). Waiting ranks poll with
// short sleeps instead of blocking in MPI, whose blocking calls spin a core that a case
// could use.

#include <mpi.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <deque>
#include <filesystem>
#include <iostream>
#include <optional>
#include <thread>

#include "Subcommand.h"
#include "SweepSupport.h"

namespace pistondyn::app {
namespace {

enum Tag : int {
  kTagRequest = 1,  // rank -> 0: a thread is free (no payload)
  kTagResult = 2,   // rank -> 0: a finished case (encoded SweepCaseResult)
  kTagAssign = 3,   // 0 -> rank: the case index to run, or -1: no more cases
  kTagDone = 4,     // rank -> 0: this rank has finished and will send nothing more
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
  // MPI counts are int: a sweep.json of more than 2 GB would need chunks; kMaxCases keeps
  // it far below that.
  MPI_Ibcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD, &request);
  waitPolling(request);
}

void sendInt(int value, int dest, int tag) {
  MPI_Send(&value, 1, MPI_INT, dest, tag, MPI_COMM_WORLD);
}

std::string receiveString(const MPI_Status& probed) {
  int count = 0;
  MPI_Get_count(&probed, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return text;
}

int receiveInt(const MPI_Status& probed) {
  int value = 0;
  MPI_Recv(&value, 1, MPI_INT, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return value;
}

// index, ok, wall time (the bits of the double), message size; then message and summary.
std::string encodeResult(const io::SweepCaseResult& r) {
  std::uint64_t wallBits = 0;
  static_assert(sizeof(wallBits) == sizeof(r.wallTime_s));
  std::memcpy(&wallBits, &r.wallTime_s, sizeof(wallBits));
  return std::to_string(r.index) + "\n" + (r.ok ? "1" : "0") + "\n" + std::to_string(wallBits) +
         "\n" + std::to_string(r.message.size()) + "\n" + r.message + r.summaryJson;
}

io::SweepCaseResult decodeResult(const std::string& text) {
  io::SweepCaseResult r;
  std::size_t pos = 0;
  auto field = [&] {
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos)
      throw std::runtime_error("a rank sent a malformed case result");
    const std::string f = text.substr(pos, end - pos);
    pos = end + 1;
    return f;
  };
  r.index = std::stoi(field());
  r.ok = field() == "1";
  const std::uint64_t wallBits = std::stoull(field());
  std::memcpy(&r.wallTime_s, &wallBits, sizeof(wallBits));
  const std::size_t messageSize = std::stoull(field());
  r.message = text.substr(pos, messageSize);
  r.summaryJson = text.substr(pos + messageSize);
  return r;
}

// Rank 0: hands out cases, runs its share, records every result and writes sweep.csv.
int coordinate(const SweepOptions& options, const io::SweepPlan& plan,
               const io::SweepOutputState& state, const std::string& dir, int ranks, int jobs) {
  io::SweepRecorder recorder(plan, dir, state);
  io::SweepOutcome outcome;
  outcome.cases = static_cast<int>(plan.cases.size());
  outcome.earlier = static_cast<int>(state.complete.size());
  outcome.halfFinished = state.halfFinished;
  std::deque<int> queue(state.toRun.begin(), state.toRun.end());
  const int toRun = static_cast<int>(state.toRun.size());
  int ranksDone = 0;
  auto record = [&](io::SweepCaseResult r, int rank) {
    ++outcome.ran;
    if (!r.ok)
      ++outcome.failed;
    printCaseDone(options, plan, r, outcome.ran, toRun, ", rank " + std::to_string(rank));
    recorder.record(std::move(r));
  };
  const auto start = std::chrono::steady_clock::now();
  {
    io::SweepCasePool pool(jobs, [&](int index) { return io::runSweepCase(plan, dir, index); });
    while (outcome.ran < toRun || ranksDone < ranks - 1) {
      while (!queue.empty() && pool.getFreeSlots() > 0) {
        pool.push(queue.front());
        queue.pop_front();
      }
      bool busy = false;
      for (auto& r : pool.takeFinished(std::chrono::milliseconds(0))) {
        record(std::move(r), 0);
        busy = true;
      }
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      if (flag) {
        busy = true;
        if (status.MPI_TAG == kTagRequest) {
          receiveInt(status);
          int index = -1;
          if (!queue.empty()) {
            index = queue.front();
            queue.pop_front();
          }
          sendInt(index, status.MPI_SOURCE, kTagAssign);
        } else if (status.MPI_TAG == kTagResult) {
          record(decodeResult(receiveString(status)), status.MPI_SOURCE);
        } else if (status.MPI_TAG == kTagDone) {
          receiveInt(status);
          ++ranksDone;
        } else {
          throw std::runtime_error("rank " + std::to_string(status.MPI_SOURCE) +
                                   " sent an unknown message (tag " +
                                   std::to_string(status.MPI_TAG) + ")");
        }
      }
      if (!busy) {
        for (auto& r : pool.takeFinished(kPoll))
          record(std::move(r), 0);
      }
    }
  }
  try {
    recorder.finish();
  } catch (const std::exception& e) {
    std::cerr << "pistondyn: the sweep failed: " << e.what() << "\n";
    return kExitFailed;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return reportSweep(options, plan, outcome, wall);
}

// Ranks 1..K-1: ask for a case whenever a thread is free, run it, report it.
void work(const io::SweepPlan& plan, const std::string& dir, int jobs) {
  io::SweepCasePool pool(jobs, [&](int index) { return io::runSweepCase(plan, dir, index); });
  int outstanding = 0;  // requests not answered yet
  bool stop = false;
  for (;;) {
    for (const auto& r : pool.takeFinished(std::chrono::milliseconds(0))) {
      const std::string text = encodeResult(r);
      MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
    }
    if (!stop) {
      for (; pool.getFreeSlots() - outstanding > 0; ++outstanding)
        sendInt(0, 0, kTagRequest);
    }
    if (stop && outstanding == 0 && pool.isIdle())
      break;
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(0, kTagAssign, MPI_COMM_WORLD, &flag, &status);
    if (flag) {
      const int index = receiveInt(status);
      --outstanding;
      if (index < 0)
        stop = true;
      else
        pool.push(index);
    } else {
      for (const auto& r : pool.takeFinished(kPoll)) {
        const std::string text = encodeResult(r);
        MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kTagResult,
                 MPI_COMM_WORLD);
      }
    }
  }
  sendInt(0, 0, kTagDone);
}

}  // namespace

int runSweepMpi(const SweepOptions& options) {
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
                   "which sweeps need\n";
    MPI_Finalize();
    return kExitFailed;
  }
  // -1: nothing to run (--list), every rank exits 0.
  constexpr int kListed = -1;
  int code = kExitOk;
  std::optional<io::SweepPlan> plan;
  std::optional<io::SweepOutputState> state;
  std::string planText, dir;
  const int jobs = options.jobs > 0 ? options.jobs : 1;
  try {
    if (rank == 0) {
      code = checkOutPath(options);
      if (code == kExitOk) {
        plan = loadSweepOrReport(options);
        if (!plan)
          code = kExitBadInput;
      }
      if (code == kExitOk && options.list) {
        printCaseList(*plan);
        code = kListed;
      }
      if (code == kExitOk) {
        try {
          state = io::openSweepOutput(*plan, options.outDir);
          planText = io::makeSweepJson(*plan);
          dir = std::filesystem::absolute(options.outDir).lexically_normal().string();
          printSweepStart(options, *plan, *state,
                          std::to_string(ranks) + " MPI ranks x " + std::to_string(jobs) +
                              (jobs == 1 ? " thread" : " threads"));
        } catch (const io::SweepOutputError& e) {
          std::cerr << "pistondyn: --out " << e.what() << "; nothing was simulated or written\n";
          code = kExitUsage;
        } catch (const std::exception& e) {
          std::cerr << "pistondyn: the sweep failed: " << e.what() << "\n";
          code = kExitFailed;
        }
      }
    }
    broadcastInt(code);
    if (code != kExitOk) {
      MPI_Finalize();
      return code == kListed ? kExitOk : code;
    }
    broadcastString(planText);
    broadcastString(dir);
    if (rank == 0) {
      code = coordinate(options, *plan, *state, dir, ranks, jobs);
    } else {
      const io::SweepPlan received = io::parseSweepJson(planText);
      work(received, dir, jobs);
    }
  } catch (const std::exception& e) {
    // A broken protocol or a lost rank: nothing sensible can continue.
    std::cerr << "pistondyn: rank " << rank << ": the MPI sweep failed: " << e.what() << "\n";
    MPI_Abort(MPI_COMM_WORLD, kExitFailed);
  }
  broadcastInt(code);  // every rank exits with rank 0's code
  MPI_Finalize();
  return code;
}

}  // namespace pistondyn::app
