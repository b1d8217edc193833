#pragma once
// SIGINT and SIGTERM during a command that writes results (run, plot, report, sweep,
// study): the handler only records the request (common::requestCancellation, async-signal-
// safe); the simulation, the sweep and the wait for gnuplot check it and throw
// common::Cancelled, so the command unwinds through the same all-or-nothing cleanup as any
// failure (staged files, the temporary gnuplot folder, a folder the run created, the
// folder's lock) and the program exits 128 + signal: 130 (SIGINT), 143 (SIGTERM). The
// handler is installed once (SA_RESETHAND): a second signal of the same kind ends the
// program at once, as if none were installed.

namespace pistondyn::app {

void installCancellationHandlers();

// The exit code of a command stopped by `signal` (128 + signal), after printing on stderr
// that it was interrupted and that what it was writing was removed.
int reportCancellation(int signal);

}  // namespace pistondyn::app
