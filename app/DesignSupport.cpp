#include "DesignSupport.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "CommandSupport.h"
#include "Subcommand.h"
#include "SweepSupport.h"
#include "pistondyn/design/Optimize.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/SweepRun.h"
#include "pistondyn/io/WarmStartFile.h"

namespace pistondyn::app {

void addDesignOptions(CLI::App& command, DesignOptions& options, const std::string& deckName,
                      const std::string& deckHelp, const std::string& outHelp) {
  command.add_option(deckName.substr(0, deckName.find('.')), options.deck, deckHelp)
      ->required()
      ->type_name(deckName);
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

void writeDesignDeck(const design::DesignStudy& study, const std::vector<double>& x,
                     const std::string& evaluationFolder, const std::string& target,
                     std::vector<std::string> header) {
  namespace fs = std::filesystem;
  const fs::path from(evaluationFolder), to(target);
  std::vector<std::pair<std::string, std::string>> files;
  std::vector<std::string> overrides = study.fixedOverrides;
  const std::vector<std::string> own = study.getOverrides(x);
  overrides.insert(overrides.end(), own.begin(), own.end());
  if (study.profile.enabled) {
    files.emplace_back("skirt_profile.csv", readWholeFile((from / "skirt_profile.csv").string()));
    overrides.push_back("liner.skirt_profile.axial_profile_file=" +
                        (to / "skirt_profile.csv").string());
  }
  std::string all;
  for (const auto& o : overrides)
    all += (all.empty() ? "" : " ") + o;
  header.push_back("the base deck " + study.baseDeckPath + " with these overrides applied:");
  header.push_back("  " + all);
  header.push_back("file paths are absolute; its results are in run/ beside this file");
  files.emplace_back("engine.yaml",
                     design::makeDeckWithOverrides(study.baseDeckPath, overrides, header));
  io::writeFilesAtomically(to.string(), files);
  std::vector<std::pair<std::string, std::string>> run = {
      {"cycle.csv", readWholeFile((from / "cycle.csv").string())},
      {"summary.json", readWholeFile((from / "summary.json").string())}};
  // Where the best design's run ended: a later `run --warm-start` of its deck starts there.
  if (fs::exists(from / io::kWarmStartFile))
    run.emplace_back(io::kWarmStartFile, readWholeFile((from / io::kWarmStartFile).string()));
  io::writeFilesAtomically((to / "run").string(), run);
}

}  // namespace pistondyn::app
