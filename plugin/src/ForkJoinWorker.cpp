#include "ForkJoinWorker.h"

#include <utility>

namespace pistondyn::plugin::detail {

ForkJoinWorker::ForkJoinWorker() : thread_([this] { loop(); }) {}

ForkJoinWorker::~ForkJoinWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void ForkJoinWorker::start(std::function<void()> task) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    task_ = std::move(task);
    error_ = nullptr;
    pending_ = true;
  }
  wake_.notify_all();
}

void ForkJoinWorker::join() {
  std::unique_lock<std::mutex> lock(mutex_);
  wake_.wait(lock, [this] { return !pending_; });
  if (error_)
    std::rethrow_exception(std::exchange(error_, nullptr));
}

void ForkJoinWorker::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || (pending_ && task_); });
    if (stop_)
      return;
    std::function<void()> task = std::move(task_);
    task_ = nullptr;
    lock.unlock();
    std::exception_ptr error;
    try {
      task();
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    error_ = error;
    pending_ = false;
    wake_.notify_all();
  }
}

}  // namespace pistondyn::plugin::detail
