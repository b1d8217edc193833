#include "CommandSupport.h"

#include <iostream>

#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/LinerRegistry.h"

namespace pistondyn::app {

std::optional<io::EngineDeck> loadDeckOrReport(const std::string& deckPath,
                                               const std::vector<std::string>& overrides) {
  try {
    return io::loadEngineDeck(deckPath, overrides);
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
  return "Deck keys carry their units (bore_mm, speed_rpm, crankcase_pressure_bar, "
         "inertia_kg_mm2, ...);\n--set values are in the key's unit. Crank angle 0 deg = "
         "firing TDC. Defaults of the\nsimulation section: start_angle_deg 0, cycles 1, "
         "output_step_deg 1 (must divide 720),\nintegrator rk_merson (rk_feldberg, cpodes_bdf, "
         "linearly_implicit_bdf2: the lubricated skirt\nneeds an implicit one), accuracy "
         "1e-9, pose_tolerance_nm 10, max_step_deg 0.5, until_periodic false,\n"
         "periodic_fmep_tolerance 0.005, periodic_pose_tolerance_um 0.2, gravity_mps2 "
         "9.80665.\nFull deck reference: README.md.\n"
         "liner.model (default ideal_guide):" +
         models +
         "\nExit codes: 0 ok; 1 bad input, nothing written; 2 bad command line; 3 run failed, "
         "nothing written.";
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
