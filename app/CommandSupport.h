#pragma once
// What the subcommands share: loading a deck with the documented error report, the
// --set option and the deck summary in --help.

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/OutputFolderLock.h"

namespace pistondyn::app {

// The deck, or nullopt after printing on stderr why it was rejected (every problem as
// file:line: key: what is wrong); the caller then exits with kExitBadInput.
std::optional<io::EngineDeck> loadDeckOrReport(const std::string& deckPath,
                                               const std::vector<std::string>& overrides,
                                               io::Fidelity fidelity = io::Fidelity::Full);

// Adds --fidelity preview|full (default full) into `fidelity`.
void addFidelityOption(CLI::App& command, std::string& fidelity);
// The option's value as io::Fidelity (CLI11 has checked it is one of the two).
io::Fidelity toFidelity(const std::string& fidelity);

// Why `dir` cannot be the output folder of a run, or "" if it can: it must be a folder
// this process may write in, or creatable in one (its nearest existing ancestor a writable
// folder: a probe folder is made there and removed at once, which also tells read-only and
// virtual file systems such as /proc). Checked before simulating, so a bad --out never
// costs a simulation.
std::string findOutputFolderProblem(const std::string& dir);

// Takes the output folder's lock (io/OutputFolderLock.h: created if needed) into `lock`.
// Returns kExitOk, or kExitUsage after printing why the folder was refused (another
// pistondyn process is writing there now, or it cannot be created or written in), the
// message starting with `option` ("--out " for run, "" for plot) and ending with what was
// not done ("nothing was simulated or written").
int lockOutputFolder(const std::string& dir, std::optional<io::OutputFolderLock>& lock,
                     const std::string& option, const std::string& notDone);

// Adds --set KEY.PATH=VALUE (repeatable, one assignment per occurrence).
void addSetOption(CLI::App& command, std::vector<std::string>& overrides);

// The --help footer: units are part of every key, the simulation defaults, the liner
// models registered, the exit codes.
std::string deckHelpFooter();

}  // namespace pistondyn::app
