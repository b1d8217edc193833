#pragma once
// An engine deck read and checked: everything needed to build and run a model, in SI.
// Deck keys and units are listed in README.md ("Engine deck reference").

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pistondyn/io/LinerRegistry.h"
#include "pistondyn/io/YamlDeck.h"
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
  std::optional<double> statedImep_Pa;     // checked against the table within 0.5 %
  std::string linerModel = "ideal_guide";  // liner.model, a name in the LinerRegistry
  LinerElementMaker makeLinerElement;      // from that model's factory
  std::vector<ResolvedInput> linerInputs;  // what the factory read (liner.*), SI keys
  plugin::SimulationSettings simulation;
};

// Reads, overrides and checks a deck; the liner model comes from `registry`. Throws
// DeckError listing every problem found (file:line: key: message); nothing is simulated
// or written before this succeeds.
EngineDeck loadEngineDeck(const std::string& deckPath, const std::vector<std::string>& overrides,
                          const LinerRegistry& registry = LinerRegistry::getGlobal());

// The deck's imep from its pressure table [Pa].
double calcDeckImep_Pa(const EngineDeck& deck);

// Builds the Simbody model with the deck's force elements: the gas force, then the liner
// element made by the deck's liner model. May be called many times (one model per thread).
std::unique_ptr<plugin::PistonAssemblyModel> buildModel(const EngineDeck& deck);

}  // namespace pistondyn::io
