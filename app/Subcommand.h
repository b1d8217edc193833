#pragma once
// One subcommand of the pistondyn program (opensim-cmd style: app/main.cpp dispatches,
// each subcommand lives in its own file over pistondyn::io calls).

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace pistondyn::app {

// Documented exit codes (README "The command-line program").
enum ExitCode : int {
  kExitOk = 0,
  kExitBadInput = 1,  // deck, pressure table or override rejected; nothing written
  kExitUsage = 2,     // bad command line
  kExitFailed = 3,    // the simulation or writing failed; nothing written
  // sweep: every case was tried, some failed (sweep.csv lists them with their messages)
  kExitSomeCasesFailed = 4,
};

class Subcommand {
 public:
  explicit Subcommand(CLI::App* app) : app_(app) {}
  virtual ~Subcommand() = default;
  // True if this subcommand was named on the command line.
  bool wasSelected() const { return app_->parsed(); }
  std::string getName() const { return app_->get_name(); }
  // Runs after a successful parse; returns the exit code.
  virtual int execute() = 0;

 protected:
  CLI::App* app_;  // owned by the program's CLI::App
};

// Each adds its CLI11 subcommand (options, --help text) to `program`.
std::unique_ptr<Subcommand> addRunCommand(CLI::App& program);
std::unique_ptr<Subcommand> addCheckCommand(CLI::App& program);
std::unique_ptr<Subcommand> addPlotCommand(CLI::App& program);
std::unique_ptr<Subcommand> addReportCommand(CLI::App& program);
std::unique_ptr<Subcommand> addSweepCommand(CLI::App& program);
std::unique_ptr<Subcommand> addKeysCommand(CLI::App& program);
std::unique_ptr<Subcommand> addNewCommand(CLI::App& program);
std::unique_ptr<Subcommand> addStudyCommand(CLI::App& program);
std::unique_ptr<Subcommand> addOptimizeCommand(CLI::App& program);
std::unique_ptr<Subcommand> addFitCommand(CLI::App& program);
std::unique_ptr<Subcommand> addPropagateCommand(CLI::App& program);

// The whole program (main.cpp calls it): parses the command line and runs the command.
// Test programs call it after registering models of their own (LinerRegistry).
int runProgram(int argc, char** argv);

}  // namespace pistondyn::app
