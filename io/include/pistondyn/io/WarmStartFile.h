#pragma once
/// \file
/// DIR/warm_start.json: where a run ended (plugin::WarmStart), written by `pistondyn run`
/// beside summary.json and read by `pistondyn run --warm-start DIR`.
///
/// The file, in SI with the unit in every name (numbers read back to the identical double):
///
///   { "note": "...",
///     "crank_angle_deg": 2880, "output_step_deg": 1,
///     "state": { "lateral_m", "tilt_rad", "transverse_m", "lateral_rate_mps",
///                "tilt_rate_radps", "transverse_rate_mps", "crank_speed_radps" },
///     "last_cycle": { "fmep_Pa" (absent without a liner's friction work),
///                     "lateral_m": [...], "tilt_rad": [...] },   // 720 / output step each
///     "elements": [ { "element": NAME, "record": [...] } ] }  // ForceElement::getWarmStartRecord

#include <string>

#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/plugin/CycleSimulation.h"

namespace pistondyn::io {

/// The file's name in a result folder.
inline constexpr const char* kWarmStartFile = "warm_start.json";

/// The text of warm_start.json for a run's end state.
std::string makeWarmStartJson(const plugin::WarmStart& end);

/// Reads DIR/warm_start.json. Throws std::runtime_error naming the file and what is missing
/// or wrong (no folder, no file, not JSON, a key missing or not a number, lists of unequal
/// length). Whether it fits a run is SimulationSettings' check (plugin::validateWarmStart).
plugin::WarmStart readWarmStart(const std::string& dir);

/// Reads one warm-start file (what readWarmStart() reads in a folder). Throws
/// std::runtime_error starting with the file's path: not readable, not JSON, a key missing,
/// not a number or a number out of double range, lists of unequal length.
plugin::WarmStart readWarmStartFile(const std::string& file);

/// Throws std::invalid_argument naming what does not fit when the deck's warm start
/// (deck.simulation.warmStart) cannot start a run of its model: the settings' check
/// (plugin::validateWarmStart) and every element record put into the model's default state
/// (another film grid, an element the model does not have). Builds the model once; nothing
/// is simulated.
void checkWarmStartFits(const EngineDeck& deck);

}  // namespace pistondyn::io
