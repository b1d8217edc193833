#pragma once
// An engine deck read and checked: everything needed to build and run a model, in SI.
// Deck keys and units are listed in README.md ("Engine deck reference").

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pistondyn/mbd_models/CylinderPressureCurve.h"
#include "pistondyn/mbd_models/EngineDescription.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/PistonAssemblyModel.h"

namespace pistondyn::io {

struct EngineDeck {
  std::string deckPath;
  std::vector<std::string> overrides;  // the --set assignments applied, in order
  mbd::EngineDescription engine;
  std::string cylinderPressureFile;  // as resolved (relative to the deck's folder)
  std::shared_ptr<const mbd::CylinderPressureCurve> cylinderPressure;
  double crankcasePressure_Pa = 101325.0;
  std::optional<double> statedImep_Pa;  // checked against the table within 0.5 %
  std::string linerModel = "ideal_guide";
  plugin::SimulationSettings simulation;
};

// Reads, overrides and checks a deck. Throws DeckError listing every problem found
// (file:line: key: message); nothing is simulated or written before this succeeds.
EngineDeck loadEngineDeck(const std::string& deckPath, const std::vector<std::string>& overrides);

// The deck's imep from its pressure table [Pa].
double calcDeckImep_Pa(const EngineDeck& deck);

// Builds the Simbody model with the deck's force elements (gas force + liner model).
std::unique_ptr<plugin::PistonAssemblyModel> buildModel(const EngineDeck& deck);

}  // namespace pistondyn::io
