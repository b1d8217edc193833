#pragma once
// What the subcommands share: loading a deck with the documented error report, the
// --set option and the deck summary in --help.

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "pistondyn/io/EngineDeck.h"

namespace pistondyn::app {

// The deck, or nullopt after printing on stderr why it was rejected (every problem as
// file:line: key: what is wrong); the caller then exits with kExitBadInput.
std::optional<io::EngineDeck> loadDeckOrReport(const std::string& deckPath,
                                               const std::vector<std::string>& overrides);

// Why `dir` cannot be the output folder of a run, or "" if it can: it must be a folder
// this process may write in, or creatable in one (its nearest existing ancestor a writable
// folder). Checked before simulating, so a bad --out never costs a simulation.
std::string findOutputFolderProblem(const std::string& dir);

// Adds --set KEY.PATH=VALUE (repeatable, one assignment per occurrence).
void addSetOption(CLI::App& command, std::vector<std::string>& overrides);

// The --help footer: units are part of every key, the simulation defaults, the liner
// models registered, the exit codes.
std::string deckHelpFooter();

}  // namespace pistondyn::app
