#pragma once
/// @file
/// A process-wide request to stop, for SIGINT / SIGTERM: the program's signal handler calls
/// requestCancellation(signal) (async-signal-safe: one store to a lock-free atomic), and
/// the long loops check it at safe points - CycleSimulation before every output row and
/// integrator step, the sweep before every case, the program while gnuplot runs - and
/// throw Cancelled. The exception unwinds like any failure, so what the run was writing is
/// removed by the same all-or-nothing destructors (ResultFileSet, OutputFolderLock,
/// temporary folders) and the program exits 128 + signal (130 for SIGINT, 143 for SIGTERM).
///
/// Header-only (pistondyn::common): one flag per process (an inline variable).

#include <atomic>
#include <stdexcept>
#include <string>

namespace pistondyn::common {

/// Thrown where a long computation noticed a cancellation request.
class Cancelled : public std::runtime_error {
 public:
  /// A cancellation by `signal` (0: without one); the message names it.
  explicit Cancelled(int signal)
      : std::runtime_error("cancelled by signal " + std::to_string(signal)), signal_(signal) {}
  /// The signal that asked for it (0: cancelled without one).
  int getSignal() const { return signal_; }

 private:
  int signal_;
};

namespace detail {
/// The process-wide request: 0 none, > 0 the signal, -1 requested without one. Use the
/// functions below, not this variable.
inline std::atomic<int> cancellationSignal{0};
static_assert(std::atomic<int>::is_always_lock_free,
              "requestCancellation must be async-signal-safe");
}  // namespace detail

/// Asks every loop that checks to stop; `signal` is reported back (use a positive number
/// when there is no signal). Async-signal-safe.
inline void requestCancellation(int signal) noexcept {
  detail::cancellationSignal.store(signal > 0 ? signal : -1, std::memory_order_relaxed);
}

/// The signal of the request, 0 if none (-1: requested without a signal).
inline int getCancellationSignal() noexcept {
  return detail::cancellationSignal.load(std::memory_order_relaxed);
}

/// True when a cancellation was requested (getCancellationSignal() != 0).
inline bool isCancellationRequested() noexcept {
  return getCancellationSignal() != 0;
}

/// Throws Cancelled if a cancellation was requested.
inline void throwIfCancelled() {
  if (const int s = getCancellationSignal(); s != 0)
    throw Cancelled(s > 0 ? s : 0);
}

/// Forgets the request (tests; a program that handled it and goes on).
inline void clearCancellation() noexcept {
  detail::cancellationSignal.store(0, std::memory_order_relaxed);
}

}  // namespace pistondyn::common
