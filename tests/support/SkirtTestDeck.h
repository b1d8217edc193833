#pragma once
// The passenger-car example engine (examples/engines/gasoline_1400_2000rpm) with the
// lubricated skirt element and the example skirt data, built in code for the element's
// tests: skirt from 12 mm above to 18 mm below the pin, parabolic barrel profile with its
// minimum-clearance line 6 mm below the pin (0.12 um/mm^2), elliptic ovality 0.3 mm, Rq
// 0.4 um (liner) / 0.6 um (skirt), SAE 0W-30 at 105 C, f_dry 0.1, cold radial clearance
// 40 um, no thermal growth, no tertiary motion, mass-conserving cavitation, fully flooded
// unless a supply film is set.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/lubrication/OilGrades.h"
#include "pistondyn/mbd_models/SliderCrank.h"
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

// Radial drop [m] of the example barrel profile at height y above the pin [m]: a parabola
// about y0 = -6 mm, 0.12 um/mm^2 (17 um at the skirt bottom, 39 um at its top). Mirrored
// about the pin it is the same barrel with its minimum at +6 mm (the thesis' study).
inline double exampleProfileDrop_m(double y_m) {
  const double d = y_m * 1e3 + 6.0;
  return 0.12 * d * d * 1e-6;
}

inline plugin::LubricatedSkirtParameters exampleSkirtParameters(int nPhi, int nY) {
  plugin::LubricatedSkirtParameters p;
  p.grid.arcWidth_rad = 80.0 * M_PI / 180.0;
  p.grid.nPhi = nPhi;
  p.grid.nY = nY;
  p.grid.axialClustering = 2.5;
  p.gap.coldRadialClearance_m = 40e-6;
  const int n = 101;  // -25 .. +25 mm in 0.5 mm (covers the mirrored skirt too)
  p.gap.skirtProfile.axial.height_m.resize(n);
  p.gap.skirtProfile.axial.radialDrop_m.resize(n);
  for (int i = 0; i < n; ++i) {
    const double y = (-25.0 + 0.5 * i) * 1e-3;
    p.gap.skirtProfile.axial.height_m[i] = y;
    p.gap.skirtProfile.axial.radialDrop_m[i] = exampleProfileDrop_m(y);
  }
  p.gap.skirtProfile.ovality.diametralOvality_m = 300e-6;
  p.oil = lubrication::makeSaeGradeOilSpec(lubrication::SaeGrade::k0W30);
  p.oilTemperature_degC = 105.0;
  p.roughness.rq1_m = 0.4e-6;
  p.roughness.rq2_m = 0.6e-6;
  p.boundaryFriction.frictionCoefficient = 0.1;
  p.lubrication.cavitation = lubrication::CavitationModel::MassConserving;
  return p;
}

inline SkirtModel makeGasolineSkirtModel(
    int nPhi, int nY, const plugin::LubricatedSkirtParameters* custom = nullptr) {
  const io::EngineDeck deck = io::loadEngineDeck(
      std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/gasoline_1400_2000rpm/engine.yaml",
      {});
  SkirtModel m;
  m.engine = deck.engine;
  m.engine.tertiaryMotion = false;
  m.engine.piston.skirtTopAbovePin_m = 12e-3;  // the example skirt: +12 .. -18 mm
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
