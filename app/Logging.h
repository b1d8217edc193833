#pragma once
// The program's log (spdlog, Debian libspdlog-dev) on stderr: what the program does
// (deck loaded, output folder, plots) at info, gnuplot's command lines at debug, problems
// that do not fail the command (plots not drawn) at warn. Error messages of the documented
// exit codes are printed as they always were, not through the log.

#include <CLI/CLI.hpp>

#include <string>

namespace pistondyn::app {

// The levels --log-level accepts, in increasing severity.
inline const char* kLogLevels = "trace, debug, info, warn, error, off";

// Adds --log-level LEVEL (default warn) to a subcommand; `level` receives it.
void addLogLevelOption(CLI::App& command, std::string& level);

// Sets up the stderr logger at `level` (one of kLogLevels).
void setUpLogging(const std::string& level);

}  // namespace pistondyn::app
