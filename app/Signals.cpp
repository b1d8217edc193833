#include "Signals.h"

#include <csignal>
#include <cstdio>
#include <cstring>

#include "pistondyn/common/Cancellation.h"

namespace pistondyn::app {
namespace {

extern "C" void onCancellationSignal(int signal) {
  common::requestCancellation(signal);
}

}  // namespace

void installCancellationHandlers() {
  struct sigaction action {};
  action.sa_handler = onCancellationSignal;
  sigemptyset(&action.sa_mask);
  // No SA_RESTART: a blocking call in the main thread returns EINTR and its loop looks at
  // the request; SA_RESETHAND: the second signal is not caught.
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int reportCancellation(int signal) {
  std::fflush(stdout);
  const char* name = signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : nullptr;
  if (name != nullptr) {
    std::fprintf(stderr,
                 "pistondyn: interrupted by %s: stopped; what was being written was removed "
                 "(results completed before the signal are kept)\n",
                 name);
  } else {
    std::fprintf(stderr,
                 "pistondyn: interrupted by signal %d: stopped; what was being written "
                 "was removed\n",
                 signal);
  }
  return 128 + signal;
}

}  // namespace pistondyn::app
