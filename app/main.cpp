// pistondyn command-line program.
//
//   pistondyn run DECK.yaml --out DIR [--set key.path=value]... [--quiet]
//   pistondyn check DECK.yaml [--set key.path=value]...
//   pistondyn --help | --version
//
// Exit codes: 0 success; 1 bad input (deck, table, override) - nothing written;
// 2 bad command line; 3 the simulation or writing failed - nothing written.

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/RunDeck.h"

namespace {

constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;
constexpr int kExitFailed = 3;

const char* kUsage =
    "usage: pistondyn run DECK.yaml --out DIR [--set key.path=value]... [--quiet]\n"
    "       pistondyn check DECK.yaml [--set key.path=value]...\n"
    "       pistondyn --help | --version\n"
    "\n"
    "run    simulates the engine deck and writes DIR/cycle.csv and DIR/summary.json\n"
    "check  reads and checks the deck and its pressure table, simulates nothing\n"
    "--set  overrides one deck value, e.g. --set drive.speed_rpm=3000 (repeatable)\n"
    "Crank angle 0 deg = firing TDC. Deck keys and units: README.md.\n";

struct Args {
  std::string command, deck, outDir;
  std::vector<std::string> overrides;
  bool quiet = false;
};

bool parseArgs(int argc, char** argv, Args& a, std::string& error) {
  if (argc < 2) {
    error = "missing command";
    return false;
  }
  a.command = argv[1];
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" || arg == "--set") {
      if (i + 1 >= argc) {
        error = arg + " needs a value";
        return false;
      }
      (arg == "--out" ? a.outDir : (a.overrides.emplace_back(), a.overrides.back())) = argv[++i];
    } else if (arg == "--quiet") {
      a.quiet = true;
    } else if (!arg.empty() && arg[0] == '-') {
      error = "unknown option " + arg;
      return false;
    } else if (a.deck.empty()) {
      a.deck = arg;
    } else {
      error = "unexpected argument " + arg;
      return false;
    }
  }
  if (a.command != "run" && a.command != "check") {
    error = "unknown command " + a.command;
    return false;
  }
  if (a.deck.empty()) {
    error = "missing DECK.yaml";
    return false;
  }
  if (a.command == "run" && a.outDir.empty()) {
    error = "run needs --out DIR";
    return false;
  }
  return true;
}

void printSummary(const pistondyn::io::EngineDeck& deck, const pistondyn::io::RunOutcome& o,
                  const std::string& outDir) {
  const auto& s = o.summary;
  std::printf("pistondyn: %s\n", deck.engine.name.c_str());
  std::printf("  %d cycle(s) at %.0f rpm, %ld rows, %.3f s wall time, %ld integrator steps\n",
              deck.simulation.cycles, deck.engine.drive.speed_radps * 30.0 / M_PI, o.rows,
              o.stats.wallTime_s, o.stats.integratorSteps);
  std::printf("  imep %.1f kPa   peak cylinder pressure %.2f bar at %.1f deg\n", s.imep_Pa / 1e3,
              s.peakCylinderPressure_Pa / 1e5, s.peakCylinderPressureAngle_deg);
  if (s.liner) {
    std::printf("  side force %+.0f N at %.1f deg (thrust), %+.0f N at %.1f deg (anti-thrust)\n",
                s.liner->sideForceMax_N, s.liner->sideForceMaxAngle_deg, s.liner->sideForceMin_N,
                s.liner->sideForceMinAngle_deg);
  }
  std::printf("  conrod force %+.0f .. %+.0f N   mean crank torque %.2f N m   power %.2f kW\n",
              s.conrodForceMin_N, s.conrodForceMax_N, s.meanCrankTorque_Nm,
              s.indicatedPower_W / 1e3);
  std::printf("  wrote %s/cycle.csv and %s/summary.json (crank angle 0 = firing TDC)\n",
              outDir.c_str(), outDir.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::cout << kUsage;
    return 0;
  }
  if (argc >= 2 && std::strcmp(argv[1], "--version") == 0) {
    std::cout << "pistondyn " << PISTONDYN_VERSION << "\n";
    return 0;
  }
  Args args;
  std::string error;
  if (!parseArgs(argc, argv, args, error)) {
    std::cerr << "pistondyn: " << error << "\n\n" << kUsage;
    return kExitUsage;
  }
  if (args.command == "run") {
    // Refuse an unusable output path now, not after the simulation.
    std::error_code ec;
    if (std::filesystem::exists(args.outDir, ec) &&
        !std::filesystem::is_directory(args.outDir, ec)) {
      std::cerr << "pistondyn: --out " << args.outDir << " is not a folder\n";
      return kExitUsage;
    }
  }
  pistondyn::io::EngineDeck deck;
  try {
    deck = pistondyn::io::loadEngineDeck(args.deck, args.overrides);
  } catch (const pistondyn::io::DeckError& e) {
    std::cerr << "pistondyn: the deck was rejected; nothing was simulated or written:\n"
              << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    // Anything the deck checks did not anticipate: still bad input, still no crash.
    std::cerr << "pistondyn: " << args.deck << ": the deck could not be read; nothing was "
              << "simulated or written: " << e.what() << "\n";
    return kExitBadInput;
  }
  if (args.command == "check") {
    std::cout << "pistondyn: " << args.deck << " is valid (imep from its pressure table: "
              << pistondyn::io::calcDeckImep_Pa(deck) / 1e3 << " kPa)\n";
    return 0;
  }
  try {
    // A progress line only makes sense on a terminal; logs get the summary alone.
    const bool showProgress = !args.quiet && isatty(fileno(stderr)) != 0;
    int lastPercent = -1;
    auto progress = [&](double f) {
      const int p = static_cast<int>(f * 100.0);
      if (showProgress && p / 10 != lastPercent / 10) {
        std::fprintf(stderr, "\rpistondyn: %3d %%", p);
        lastPercent = p;
      }
    };
    const auto outcome = pistondyn::io::runDeck(deck, args.outDir, progress);
    if (!args.quiet)
      std::fprintf(stderr, "\r");
    printSummary(deck, outcome, args.outDir);
  } catch (const std::exception& e) {
    std::cerr << "\npistondyn: the run failed; no results were written: " << e.what() << "\n";
    return kExitFailed;
  }
  return 0;
}
