#pragma once
/// \file
/// An engine deck read and checked: everything needed to build and run a model, in SI.
/// Deck keys, units, defaults and ranges: DeckKeys.h (`pistondyn keys`, README.md).

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

/// How finely a run resolves the liner (`pistondyn run --fidelity`). Full: the deck as
/// written. Preview: a quick look - the film grid of a liner that has one
/// (liner.grid.nodes_circumferential x liner.grid.nodes_axial, the lubricated skirt's)
/// coarsened to 3/8 of its nodes around the arc and 5/6 along the skirt, rounded up, but not
/// below 16 x 12 nodes per side and never finer than the deck's (64 x 48 -> 24 x 40,
/// 32 x 24 -> 16 x 20); everything else as written. A
/// liner without a film grid (the ideal guide) runs the same at both.
enum class Fidelity { Full, Preview };

/// "full" / "preview".
const char* getFidelityName(Fidelity fidelity);

/// The film-grid keys a preview assigns, in the order it appends them to the overrides.
inline constexpr const char* kPreviewGridKeys[2] = {"liner.grid.nodes_circumferential",
                                                    "liner.grid.nodes_axial"};

/// An engine deck read, overridden and checked (loadEngineDeck): the crank train, cylinder
/// pressure, liner model and simulation settings in SI, with the record of what was read.
struct EngineDeck {
  std::string deckPath;                ///< the deck file as given
  std::vector<std::string> overrides;  ///< the --set assignments applied, in order
  mbd::EngineDescription engine;       ///< the crank train (geometry, masses, drive)
  std::string cylinderPressureFile;    ///< as resolved (relative to the deck's folder)
  std::shared_ptr<const mbd::CylinderPressureCurve> cylinderPressure;  ///< absolute [Pa]
  double crankcasePressure_Pa = 101325.0;  ///< absolute pressure under the piston [Pa]
  std::optional<double> statedImep_Pa;     ///< checked against the table within 0.5 %
  std::string linerModel = "ideal_guide";  ///< liner.model, a name in the LinerRegistry
  LinerElementMaker makeLinerElement;      ///< from that model's factory
  std::vector<ResolvedInput> linerInputs;  ///< what the factory read (liner.*), SI keys
  /// Every key read (defaults included) in reading order, under its deck path with the unit
  /// replaced by the SI one (geometry.bore_mm -> geometry.bore_m): summary.json's inputs.
  std::vector<ResolvedInput> inputs;
  /// Every key path the readers asked for, sections included (the schema as used; the
  /// key-table tests check it against DeckKeys.h), sorted.
  std::vector<std::string> keysRead;
  /// Crank angles [deg, in [0, 720)] of the last cycle at which a run writes the liner's
  /// nodal fields (liner.field_dumps.crank_angles_deg of the lubricated skirt); output rows.
  std::vector<double> fieldDumpAngles_deg;
  /// The simulation section: start angle, initial pose, cycles, output step, integrator and
  /// its tolerances (plugin::SimulationSettings), in SI.
  plugin::SimulationSettings simulation;
  /// What the deck was loaded for, and what the preview changed in words ("" when nothing:
  /// full, or a liner without a film grid). The preview's changes are also among
  /// `overrides` (as --set assignments after the user's) and `inputs`.
  Fidelity fidelity = Fidelity::Full;
  std::string fidelityNote;  ///< the preview's changes in words; "" when nothing changed
  /// The result folder `simulation.warmStart` was read from (`run --warm-start DIR`); "" for
  /// a run from the deck's initial pose.
  std::string warmStartFrom;
};

/// Reads, overrides and checks a deck; the liner model comes from `registry`. Throws
/// DeckError listing every problem found (file:line: key: message); nothing is simulated
/// or written before this succeeds. The last check builds a trial model (buildModel), so
/// an element's own checks against the engine are bad input too. The liner model decides
/// the crank train's tertiary mobility (LinerDeckContext::tertiaryMotion) and whether the
/// integrator fits it (explicit ones are rejected for a stiff liner, linearly_implicit_bdf2
/// for one held by constraints).
EngineDeck loadEngineDeck(const std::string& deckPath, const std::vector<std::string>& overrides,
                          const LinerRegistry& registry = LinerRegistry::getGlobal());

/// The same for a fidelity: Full is the deck as written; Preview loads it, and when its
/// liner has a film grid loads it again with that grid coarsened (Fidelity above) by
/// --set assignments appended to `overrides`, so the preview's grid is what the inputs and
/// overrides of its summary say. Throws DeckError as above.
EngineDeck loadEngineDeck(const std::string& deckPath, const std::vector<std::string>& overrides,
                          Fidelity fidelity,
                          const LinerRegistry& registry = LinerRegistry::getGlobal());

/// The deck's imep from its pressure table [Pa].
double calcDeckImep_Pa(const EngineDeck& deck);

/// Builds the Simbody model with the deck's force elements: the gas force, then the liner
/// element made by the deck's liner model. May be called many times (one model per thread).
std::unique_ptr<plugin::PistonAssemblyModel> buildModel(const EngineDeck& deck);

}  // namespace pistondyn::io
