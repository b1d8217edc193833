// The pistondyn command-line program (runProgram, called by main.cpp): parses the command
// line (CLI11) and dispatches to one subcommand per file (RunCommand.cpp, CheckCommand.cpp,
// PlotCommand.cpp, ReportCommand.cpp, SweepCommand.cpp, StudyCommand.cpp, KeysCommand.cpp), each
// over pistondyn::io.
//
//   pistondyn run DECK.yaml --out DIR [--set key.path=value]... [--fidelity full|preview]
//                 [--quiet] [--no-plot]
//   pistondyn check DECK.yaml [--set key.path=value]... [--fidelity full|preview]
//   pistondyn plot DIR          (figures of a result folder, gnuplot)
//   pistondyn report DIR        (DIR/report.html, self-contained)
//   pistondyn sweep SWEEP.yaml --out DIR [--jobs N] [--set key.path=value]... [--list] [--quiet]
//   pistondyn study STUDY.yaml --out DIR [...]  (a sweep compared: comparison.csv, .md, plots)
//   pistondyn optimize OPT.yaml --out DIR [...]   (design loop: NLopt on the sweep machinery)
//   pistondyn fit FIT.yaml --out DIR [...]        (calibration to measured traces)
//   pistondyn propagate PROP.yaml --out DIR [...] (uncertainty bands)
//   pistondyn keys [--markdown] (the deck reference, from io/DeckKeys.h)
//   pistondyn new DIR --bore-mm B --stroke-mm S [...] (a deck from a drawing, NewCommand.cpp)
//   pistondyn --help | --version          (and pistondyn <command> --help)
//
// Exit codes: 0 success; 1 bad input (deck, table, override) - nothing written;
// 2 bad command line; 3 the simulation or writing failed - nothing written;
// 4 (sweep) some cases failed - listed in sweep.csv, the others written; (optimize) no
// feasible design; (propagate) some samples failed;
// 130 / 143 interrupted by SIGINT / SIGTERM - what was being written removed (Signals.h).

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <vector>

#include "Signals.h"
#include "Subcommand.h"
#include "pistondyn/common/Cancellation.h"
#include "pistondyn/io/Version.h"

namespace {

const char* kSynopsis =
    "usage: pistondyn run DECK.yaml --out DIR [--set key.path=value]... [--fidelity full|preview]\n"
    "                     [--quiet] [--no-plot] [--log-level LEVEL]\n"
    "       pistondyn check DECK.yaml [--set key.path=value]... [--fidelity full|preview]\n"
    "                       [--log-level LEVEL]\n"
    "       pistondyn plot DIR [--log-level LEVEL]\n"
    "       pistondyn report DIR [--log-level LEVEL]\n"
    "       pistondyn sweep SWEEP.yaml --out DIR [--jobs N] [--set key.path=value]... [--list]\n"
    "                       [--quiet] [--no-plot]  (also under mpirun -np K)\n"
    "       pistondyn study STUDY.yaml --out DIR [--jobs N] [--set key.path=value]... [--quiet]\n"
    "                       [--no-plot]         (comparison.csv, .md and figures)\n"
    "       pistondyn optimize OPT.yaml --out DIR [--jobs N] [--set key.path=value]... [--quiet]\n"
    "       pistondyn fit FIT.yaml --out DIR [--jobs N] [--set key.path=value]... [--quiet]\n"
    "       pistondyn propagate PROP.yaml --out DIR [--jobs N] [--set key.path=value]... "
    "[--quiet]\n"
    "                       (optimize, fit, propagate: also under mpirun -np K)\n"
    "       pistondyn keys [--markdown]     (every deck key: unit, default, range)\n"
    "       pistondyn new DIR --bore-mm B --stroke-mm S [--rod-mm L] [--speed-rpm N]\n"
    "                     [--imep-kPa P | --motored | --pressure-table FILE] [--type TYPE] [...]\n"
    "                                       (a deck folder from a drawing, EST estimates)\n"
    "       pistondyn --help | --version | <command> --help\n";

}  // namespace

namespace pistondyn::app {

int runProgram(int argc, char** argv) {
  CLI::App program(
      "pistondyn: piston-assembly dynamics and tribology over whole engine cycles.\n"
      "Crank angle 0 deg = firing TDC. Every deck key with its unit, default and range:\n"
      "`pistondyn keys`.",
      "pistondyn");
  program.set_version_flag("--version", "pistondyn " + pistondyn::io::getVersion(),
                           "print the version and exit");
  program.set_help_flag("-h,--help",
                        "print this help and exit (pistondyn <command> --help: "
                        "that command's options)");
  program.require_subcommand(1);
  program.footer(
      "Exit codes: 0 ok; 1 bad input, nothing written; 2 bad command line or a refused --out;\n"
      "3 run failed, nothing written; 4 (sweep, study) some cases failed, listed in sweep.csv;\n"
      "(optimize) no feasible design; (propagate) some samples failed;\n"
      "130 / 143 interrupted by SIGINT / SIGTERM, what was being written removed.");
  std::vector<std::unique_ptr<Subcommand>> commands;
  commands.push_back(addRunCommand(program));
  commands.push_back(addCheckCommand(program));
  commands.push_back(addPlotCommand(program));
  commands.push_back(addReportCommand(program));
  commands.push_back(addSweepCommand(program));
  commands.push_back(addStudyCommand(program));
  commands.push_back(addOptimizeCommand(program));
  commands.push_back(addFitCommand(program));
  commands.push_back(addPropagateCommand(program));
  commands.push_back(addKeysCommand(program));
  commands.push_back(addNewCommand(program));

  // An unknown first word is an unknown command (CLI11 would only say one is required).
  if (argc >= 2 && argv[1][0] != '-') {
    bool known = false;
    for (const auto& c : commands)
      known = known || c->getName() == argv[1];
    if (!known) {
      std::cerr << "pistondyn: unknown command " << argv[1] << "\n\n" << kSynopsis;
      return kExitUsage;
    }
  }
  try {
    program.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0)
      return program.exit(e);  // --help, --version: printed on stdout
    std::cerr << "pistondyn: " << e.what() << "\n\n" << kSynopsis;
    return kExitUsage;
  }
  for (const auto& c : commands) {
    if (!c->wasSelected())
      continue;
    // Commands that write results stop cleanly on SIGINT / SIGTERM (Signals.h); check
    // and keys write nothing and keep the default (the signal ends them at once).
    const std::string name = c->getName();
    const bool writes = name != "check" && name != "keys";
    if (writes)
      installCancellationHandlers();
    int code = kExitFailed;
    try {
      code = c->execute();
    } catch (const pistondyn::common::Cancelled&) {
      // reported below
    }
    if (const int signal = pistondyn::common::getCancellationSignal(); writes && signal > 0)
      return reportCancellation(signal);
    return code;
  }
  std::cerr << "pistondyn: missing command\n\n" << kSynopsis;
  return kExitUsage;
}

}  // namespace pistondyn::app
