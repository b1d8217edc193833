#include "DesignSupport.h"

#include <cstdio>
#include <iostream>

#include "CommandSupport.h"
#include "Subcommand.h"
#include "SweepSupport.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/SweepRun.h"

namespace pistondyn::app {

void addDesignOptions(CLI::App& command, DesignOptions& options, const std::string& deckHelp,
                      const std::string& outHelp) {
  command.add_option("DECK", options.deck, deckHelp)->required()->type_name("DECK.yaml");
  command.add_option("--out", options.outDir, outHelp)->required()->type_name("DIR");
  command
      .add_option("--jobs", options.jobs,
                  "evaluations run at the same time, one thread and one model each (default: "
                  "the cores this process may use; under mpirun: per rank, default 1)")
      ->check(CLI::PositiveNumber)
      ->type_name("N");
  addSetOption(command, options.overrides);
  command.add_flag("--quiet", options.quiet, "no progress lines on stderr");
  command.set_help_flag("-h,--help", "print this help and exit");
}

void ProgressPrinter::operator()(const std::string& line) const {
  if (quiet_)
    return;
  std::lock_guard<std::mutex> lock(mutex_);
  std::fprintf(stderr, "pistondyn %s: %s\n", command_.c_str(), line.c_str());
}

int checkDesignOutPath(const std::string& outDir) {
  if (const std::string problem = findOutputFolderProblem(outDir); !problem.empty()) {
    std::cerr << "pistondyn: --out " << outDir << " " << problem
              << "; nothing was simulated or written\n";
    return kExitUsage;
  }
  return kExitOk;
}

std::optional<int> reportPrepareError(const std::string& kindText,
                                      const std::function<void()>& body) {
  try {
    body();
    return std::nullopt;
  } catch (const io::DeckError& e) {
    std::cerr << "pistondyn: the " << kindText
              << " was rejected; nothing was simulated or written:\n"
              << e.what() << "\n";
    return kExitBadInput;
  } catch (const design::DesignOutputError& e) {
    std::cerr << "pistondyn: --out " << e.what() << "; nothing was simulated or written\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "pistondyn: the " << kindText << " could not be prepared: " << e.what() << "\n";
    return kExitFailed;
  }
}

int runDesignTask(const DesignOptions& options, DesignTask& task) {
  if (isMpiLaunch()) {
#ifdef PISTONDYN_WITH_MPI
    return runDesignTaskMpi(options, task);
#else
    if (getMpiLaunchSize() > 1) {
      std::cerr << "pistondyn: this pistondyn was built without MPI, so under mpirun every "
                   "process would run the whole study; run it without mpirun (it uses every "
                   "core with threads), or rebuild with MPI (libopenmpi-dev, README.md)\n";
      return kExitUsage;
    }
#endif
  }
  if (const int code = task.prepare(); code != kExitOk)
    return code;
  const int jobs = options.jobs > 0 ? options.jobs : io::getAvailableCores();
  design::ThreadExecutor executor(task.getStore(), jobs);
  return task.run(executor);
}

}  // namespace pistondyn::app
