#pragma once
// The passenger-car example engine (examples/engines/gasoline_1400_2000rpm) with the
// lubricated skirt element and the example skirt data, for the element's tests. The data
// come from the example deck itself (liner.model: lubricated_skirt, read by the deck's
// factory, io/LubricatedSkirtDeck.h): skirt from 12 mm above to 18 mm below the pin,
// parabolic barrel profile 0.12 um/mm^2 (y + 6 mm)^2 tabulated in skirt_profile.csv
// (minimum-clearance line 6 mm below the pin), elliptic ovality 0.3 mm, Rq 0.4 um (liner) /
// 0.6 um (skirt), SAE 0W-30 at 105 C, f_dry 0.1, cold radial clearance 40 um, no tertiary
// motion, mass-conserving cavitation. Three things differ from the deck: the grid (the tests'
// coarse nPhi x nY instead of the deck's 64 x 48), the shapes, which are the cold ones here
// (the deck's thermal section with both expansion coefficients 0: the thesis' study lists no
// thermal growth, and the tests' fixed poses are set against the 40 um clearance; the deck
// runs hot, about 9.4 um), and the oil supply, which is fully flooded here unless a test sets
// a supply film (the deck's skirt is partially flooded, 1 um).

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/mbd_models/SliderCrank.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/GasForceElement.h"
#include "pistondyn/plugin/LubricatedSkirtElement.h"

namespace pistondyn::testsupport {

struct SkirtModel {
  mbd::EngineDescription engine;
  std::unique_ptr<plugin::PistonAssemblyModel> model;
  const plugin::LubricatedSkirtElement& skirt() const {
    return model->getElementAs<plugin::LubricatedSkirtElement>("lubricated_skirt");
  }
};

inline std::string gasolineDeckPath() {
  return std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/gasoline_1400_2000rpm/engine.yaml";
}

// The example deck with the skirt grid overridden to nPhi x nY nodes per side.
inline io::EngineDeck loadGasolineSkirtDeck(int nPhi, int nY) {
  return io::loadEngineDeck(gasolineDeckPath(),
                            {"liner.grid.nodes_circumferential=" + std::to_string(nPhi),
                             "liner.grid.nodes_axial=" + std::to_string(nY),
                             "liner.thermal.piston_expansion_per_K=0",
                             "liner.thermal.liner_expansion_per_K=0"});
}

// Radial drop [m] of the example barrel profile at height y above the pin [m]: a parabola
// about y0 = -6 mm, 0.12 um/mm^2 (17 um at the skirt bottom, 39 um at its top), the closed
// form that examples/engines/gasoline_1400_2000rpm/skirt_profile.csv tabulates (the deck
// reads the table, not this function). Mirrored about the pin it is the same barrel with
// its minimum at +6 mm (the thesis' study).
inline double exampleProfileDrop_m(double y_m) {
  const double d = y_m * 1e3 + 6.0;
  return 0.12 * d * d * 1e-6;
}

// The skirt parameters a deck's factory makes (the deck must select lubricated_skirt).
inline plugin::LubricatedSkirtParameters deckSkirtParameters(const io::EngineDeck& deck) {
  const std::unique_ptr<plugin::LinerElement> liner = deck.makeLinerElement();
  const auto* skirt = dynamic_cast<const plugin::LubricatedSkirtElement*>(liner.get());
  if (skirt == nullptr)
    throw std::logic_error("the deck does not select liner.model lubricated_skirt");
  return skirt->getParameters();
}

// The example deck's skirt parameters (as its factory read them), on an nPhi x nY grid,
// fully flooded.
inline plugin::LubricatedSkirtParameters exampleSkirtParameters(int nPhi, int nY) {
  plugin::LubricatedSkirtParameters p = deckSkirtParameters(loadGasolineSkirtDeck(nPhi, nY));
  p.supplyFilm = plugin::SupplyFilm();  // fully flooded: the tests set a supply film
  return p;
}

// The --set overrides that give the example deck the gasoline piston's committed FE skirt
// (examples/fe/gasoline_1400_2000rpm: compliance and node table with its gas column; paths
// relative to the deck's folder). Index 0 the compliance, 1 the node table, 2 the nodal-mean
// faces the elastic skirt needs (the deck's linear-gap faces broke its coupling:
// plugin/README.md, "Face values").
inline std::vector<std::string> gasolineElasticSkirtOverrides() {
  return {"liner.elastic_skirt.compliance_file=../../fe/gasoline_1400_2000rpm/"
          "skirt_compliance.mtx",
          "liner.elastic_skirt.nodes_file=../../fe/gasoline_1400_2000rpm/skirt_nodes.csv",
          "liner.film.faces=nodal_mean"};
}

// The stepper of the C++ whole-cycle tests: linearly implicit BDF2 with a 0.25 deg largest
// step and the 10 nm pose tolerance (SimulationSettings' defaults; the example decks run BDF3
// at 1 deg and 1 nm, the elastic study BDF2 as here), output rows every degree, `cycles`
// cycles.
inline plugin::SimulationSettings bdf2StepperSettings(int cycles) {
  plugin::SimulationSettings s;
  s.integrator = plugin::SimulationSettings::Integrator::LinearlyImplicitBDF;
  s.outputStep_deg = 1.0;
  s.maxStep_deg = 0.25;
  s.cycles = cycles;
  return s;
}

// The example engine (the deck's, with its skirt range and tertiary motion off; its crank
// drive replaced by `drive` when given) with the gas force and a lubricated skirt of `custom`
// parameters, or of the example's on an nPhi x nY grid.
inline SkirtModel makeGasolineSkirtModel(int nPhi, int nY,
                                         const plugin::LubricatedSkirtParameters* custom = nullptr,
                                         const mbd::CrankDrive* drive = nullptr) {
  const io::EngineDeck deck = loadGasolineSkirtDeck(nPhi, nY);
  SkirtModel m;
  m.engine = deck.engine;
  if (drive)
    m.engine.drive = *drive;
  m.model = std::make_unique<plugin::PistonAssemblyModel>(m.engine);
  m.model->addElement(
      std::make_unique<plugin::GasForceElement>(*deck.cylinderPressure, deck.crankcasePressure_Pa));
  m.model->addElement(std::make_unique<plugin::LubricatedSkirtElement>(
      custom ? *custom : exampleSkirtParameters(nPhi, nY)));
  return m;
}

// Swept volume [m^3].
inline double displacement_m3(const mbd::EngineDescription& e) {
  const mbd::SliderCrank kin(e.geometry);
  return mbd::CylinderVolume(kin, e.piston.bore_m, e.geometry.compressionRatio).displacement_m3();
}

}  // namespace pistondyn::testsupport
