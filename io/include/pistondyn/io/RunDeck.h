#pragma once
// `pistondyn run`: simulate a deck and write DIR/cycle.csv and DIR/summary.json.

#include <string>

#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/plugin/CycleSimulation.h"

namespace pistondyn::io {

// Figures of the last simulated 720 deg cycle.
struct CycleSummary {
  double imep_Pa = 0.0;  // from the pressure table
  double displacement_m3 = 0.0;
  double kinematicStroke_m = 0.0;
  double peakCylinderPressure_Pa = 0.0, peakCylinderPressureAngle_deg = 0.0;
  double sideForceMax_N = 0.0, sideForceMaxAngle_deg = 0.0;  // towards thrust
  double sideForceMin_N = 0.0, sideForceMinAngle_deg = 0.0;  // towards anti-thrust (< 0)
  double conrodForceMax_N = 0.0, conrodForceMin_N = 0.0;     // compression > 0
  double meanCrankTorque_Nm = 0.0;                           // rod on crank, cycle mean
  double meanDriveTorque_Nm = 0.0;
  double indicatedPower_W = 0.0;  // mean crank torque x mean speed
};

// Figures of the last simulated cycle of `table`, a run of `deck` (its simulation settings).
CycleSummary summarize(const EngineDeck& deck, const plugin::ResultTable& table);

struct RunOutcome {
  plugin::ResultTable table;
  CycleSummary summary;
  plugin::SimulationStats stats;
};

// Simulates and, if outDir is not empty, writes the two files (all-or-nothing).
RunOutcome runDeck(const EngineDeck& deck, const std::string& outDir,
                   const plugin::CycleSimulation::Progress& progress = {});

// The text of summary.json (inputs in SI, results, timings).
std::string makeSummaryJson(const EngineDeck& deck, const RunOutcome& outcome);

}  // namespace pistondyn::io
