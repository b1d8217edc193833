#pragma once

// One helper thread that runs one task at a time for its owner: the fork-join of the two
// skirt sides (LubricatedSkirtElement, parallelSides). The owner hands a task over with
// start(), does its own share of the work, and collects the helper's with join(), which
// rethrows what the task threw. A persistent thread rather than one per call: a force
// evaluation lasts about a millisecond, thread creation tens of microseconds.
//
// Not for concurrent owners: one start() / join() pair at a time, from one thread.

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace pistondyn::plugin::detail {

class ForkJoinWorker {
 public:
  ForkJoinWorker();
  ~ForkJoinWorker();
  ForkJoinWorker(const ForkJoinWorker&) = delete;
  ForkJoinWorker& operator=(const ForkJoinWorker&) = delete;

  // Runs `task` on the helper thread; the task must stay valid until join() returns.
  void start(std::function<void()> task);
  // Waits for the task started last; rethrows its exception, if any.
  void join();

 private:
  void loop();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::function<void()> task_;
  bool pending_ = false;  // a task handed over and not yet finished
  bool stop_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: started after the members it uses exist
};

}  // namespace pistondyn::plugin::detail
