#include "CommandSupport.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "Subcommand.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/DeckReference.h"
#include "pistondyn/io/LinerRegistry.h"

namespace pistondyn::app {

std::optional<io::EngineDeck> loadDeckOrReport(const std::string& deckPath,
                                               const std::vector<std::string>& overrides,
                                               io::Fidelity fidelity) {
  try {
    return io::loadEngineDeck(deckPath, overrides, fidelity);
  } catch (const io::DeckError& e) {
    std::cerr << "pistondyn: the deck was rejected; nothing was simulated or written:\n"
              << e.what() << "\n";
  } catch (const std::exception& e) {
    // Anything the deck checks did not anticipate: still bad input, still no crash.
    std::cerr << "pistondyn: " << deckPath << ": the deck could not be read; nothing was "
              << "simulated or written: " << e.what() << "\n";
  }
  return std::nullopt;
}

std::string deckHelpFooter() {
  std::string models;
  for (const auto& name : io::LinerRegistry::getGlobal().getNames())
    models += "\n  " + name + ": " + io::LinerRegistry::getGlobal().getDescription(name);
  // The simulation section's defaults, from the key table the deck is read by.
  std::string defaults, line;
  for (const io::DeckKey& k : io::getEngineDeckKeys().getKeys()) {
    if (k.path.rfind("simulation.", 0) != 0)
      continue;
    std::string item = k.path.substr(11) + " " + io::describeDefault(k);
    item.erase(std::remove(item.begin(), item.end(), '`'), item.end());
    if (line.size() + item.size() + 2 > 88) {
      defaults += line + ",\n";
      line.clear();
    }
    line += (line.empty() ? "" : ", ") + item;
  }
  defaults += line;
  return "Deck keys carry their units (bore_mm, speed_rpm, crankcase_pressure_bar, "
         "inertia_kg_mm2, ...);\n--set values are in the key's unit. Crank angle 0 deg = "
         "firing TDC. Defaults of the\nsimulation section (the lubricated skirt needs the "
         "integrator linearly_implicit_bdf2 or cpodes_bdf):\n" +
         defaults +
         ".\nEvery key with its unit, default and range: `pistondyn keys`.\n"
         "liner.model (default ideal_guide):" +
         models +
         "\nExit codes: 0 ok; 1 bad input, nothing written; 2 bad command line, or an output\n"
         "folder that is a file, not writable or in use by another pistondyn process, nothing\n"
         "written; 3 run failed, nothing written; 130 / 143 interrupted by SIGINT / SIGTERM,\n"
         "what was being written removed.";
}

std::string findOutputFolderProblem(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (dir.empty())
    return "is empty";
  fs::path p = fs::absolute(dir, ec);
  if (ec)
    return "cannot be resolved: " + ec.message();
  if (fs::exists(p, ec) && !fs::is_directory(p, ec))
    return "is a file, not a folder";
  // The folder itself, or the nearest ancestor that exists: the run creates the rest.
  while (!fs::exists(p, ec) && p.has_parent_path() && p.parent_path() != p)
    p = p.parent_path();
  if (!fs::is_directory(p, ec))
    return "cannot be created: " + p.string() + " is a file, not a folder";
  if (::access(p.c_str(), W_OK | X_OK) != 0)
    return "cannot be written: no permission to write in " + p.string();
  // access() says yes to root everywhere, and knows nothing of read-only or virtual file
  // systems (/proc, /sys): a folder made and removed again answers for sure.
  std::string probe = (p / ".pistondyn_probe_XXXXXX").string();
  if (::mkdtemp(probe.data()) == nullptr)
    return "cannot be written: no folder can be made in " + p.string() + " (" +
           std::strerror(errno) + ")";
  ::rmdir(probe.c_str());
  return {};
}

int lockOutputFolder(const std::string& dir, std::optional<io::OutputFolderLock>& lock,
                     const std::string& option, const std::string& notDone) {
  try {
    lock.emplace(dir);
    return kExitOk;
  } catch (const io::OutputFolderBusy& e) {
    std::cerr << "pistondyn: " << option << e.what() << "; " << notDone << "\n";
  } catch (const std::exception& e) {
    std::cerr << "pistondyn: " << option << dir << " cannot be written: " << e.what() << "; "
              << notDone << "\n";
  }
  return kExitUsage;
}

void addFidelityOption(CLI::App& command, std::string& fidelity) {
  command
      .add_option("--fidelity", fidelity,
                  "full: the deck as written (default); preview: a quick look with the film "
                  "grid coarsened to 3/8 of its nodes around and 5/6 along the skirt (not "
                  "below 16 x 12 nodes per side), recorded among the "
                  "overrides and inputs of summary.json (sweeps: of every case, and in "
                  "sweep.json) and said by run's summary; a liner without a film grid runs "
                  "the same at both")
      ->check(CLI::IsMember({"full", "preview"}))
      ->type_name("full|preview");
}

io::Fidelity toFidelity(const std::string& fidelity) {
  return fidelity == "preview" ? io::Fidelity::Preview : io::Fidelity::Full;
}

void addSetOption(CLI::App& command, std::vector<std::string>& overrides) {
  command
      .add_option("--set", overrides,
                  "override one deck value, in the unit its key names, e.g. --set "
                  "drive.speed_rpm=3000 or --set liner.model=ideal_guide (repeatable; "
                  "default: none)")
      ->type_name("KEY.PATH=VALUE")
      ->allow_extra_args(false)
      ->take_all();
}

}  // namespace pistondyn::app
