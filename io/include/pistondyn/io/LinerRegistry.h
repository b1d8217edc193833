#pragma once
/// \file
/// Liner models selectable from a deck by name (`liner.model: <name>`). A liner model is a
/// factory: it reads its own keys from the deck's `liner` section (DeckSection.h: typed
/// getters, units in the keys, defaults, choices, files, nested sections) and returns a
/// maker that constructs the element, once per model built from the deck. Keys of the
/// section that the factory does not read are reported as unknown, as everywhere in a deck.
///
/// `ideal_guide` (plugin::IdealLinerGuide) is registered by default. A user's program
/// registers its own model before loading decks and selects it without other changes:
///
///   io::registerLinerModel("spring_guide", "linear springs and dampers",
///       [](io::DeckSection& liner) -> io::LinerElementMaker {
///         SpringGuide::Parameters p;
///         p.stiffness_Npm = liner.getSIOr("lateral_stiffness_N_per_mm", io::Quantity::Stiffness,
///                                         2e4, io::Bounds::positive());
///         return [p] { return std::make_unique<SpringGuide>(p); };
///       });
///   const auto deck = io::loadEngineDeck("engine.yaml", {"liner.model=spring_guide"});
///
/// A factory may also take a LinerDeckContext (below): the engine the deck describes, for
/// cross-checks of the liner's data against it; it then returns, with the maker, what the liner
/// needs from the rest of the model (LinerModelNeeds: the crank train's tertiary mobility, a
/// stiff-capable integrator, field dumps).
///
/// Factories run while the deck is read (so `pistondyn check` and every problem report see
/// them); the maker runs once at load (a trial construction whose std::exception becomes
/// a deck error), once more inside a trial model built from the deck (its addToModel()
/// checks against the engine are bad input too), and then once per buildModel().
/// Registries are safe to use from several threads; register before loading decks.
///
/// `ideal_guide` reads no keys. When --set liner.model selects another model than the one
/// the deck file names, the file's other liner.* keys belong to the file's model: they are
/// not reported as unknown (keys given by --set still are), so a deck written for the
/// lubricated skirt also runs with --set liner.model=ideal_guide.

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <optional>

#include "pistondyn/mbd_models/CylinderPressureCurve.h"
#include "pistondyn/mbd_models/EngineDescription.h"
#include "pistondyn/plugin/LinerElement.h"

namespace pistondyn::io {

class DeckSection;

/// What a liner model's factory knows of the rest of the deck (read only).
struct LinerDeckContext {
  /// The engine as read from the deck's other sections (SI), never null. Use it for
  /// cross-checks only when engineIsValid: a key that failed to read leaves a placeholder
  /// (and its problem is reported already).
  const mbd::EngineDescription* engine = nullptr;
  bool engineIsValid = false;  ///< every key of the engine read without a problem
  /// The cylinder pressure (gauge against crankcasePressure_Pa [Pa], absolute) for a liner
  /// whose parts deform under it. The table is read after the liner section, so the slot is
  /// filled later; a maker that copies the slot sees the curve whenever it runs (never null
  /// by then when the deck loaded).
  std::shared_ptr<std::shared_ptr<const mbd::CylinderPressureCurve>> cylinderPressure;
  double crankcasePressure_Pa = 1.0e5;  ///< absolute [Pa]
};

/// What a liner model needs from the rest of the model (its factory's answer to the deck).
struct LinerModelNeeds {
  /// The crank train's tertiary (pin-axis) mobility, EngineDescription::tertiaryMotion,
  /// when the liner model decides it (it must agree with the element); unset keeps the
  /// engine's default (on).
  std::optional<bool> tertiaryMotion;
  /// Why Simbody's explicit integrators (rk_merson, rk_feldberg) cannot integrate this
  /// liner (empty: they can); the deck then rejects them with this reason.
  std::string stiffReason;
  /// The liner holds the piston by Simbody constraints: linearly_implicit_bdf2, which
  /// integrates models without constraints, is rejected.
  bool usesConstraints = false;
  /// Crank angles [deg], each in [0, 720), at which the run writes the liner's nodal fields
  /// (plugin::LinerElement::getNodalFields(); the deck checks that they are output rows), and
  /// the key that listed them (for that check's message).
  std::vector<double> fieldDumpAngles_deg;
  std::string fieldDumpKey;  ///< see fieldDumpAngles_deg
};

/// Constructs one liner element with the parameters its factory read.
using LinerElementMaker = std::function<std::unique_ptr<plugin::LinerElement>()>;
/// A factory's result: the maker and what the model needs for it.
struct LinerModel {
  LinerElementMaker maker;  ///< builds one element with the parameters the factory read
  LinerModelNeeds needs;    ///< what the model and the run need for this element
};
/// Reads the liner section; problems go to the section (never thrown for bad input).
using LinerFactory = std::function<LinerElementMaker(DeckSection& liner)>;
/// The same with the deck context, and the model's needs with the maker.
using LinerFactoryWithContext =
    std::function<LinerModel(DeckSection& liner, const LinerDeckContext& context)>;

/// The liner models a deck may select by `liner.model`: name, description, factory.
/// Thread-safe.
class LinerRegistry {
 public:
  /// A registry holding the built-in models (ideal_guide, lubricated_skirt).
  LinerRegistry();
  LinerRegistry(const LinerRegistry& other);             ///< copies the entries
  LinerRegistry& operator=(const LinerRegistry& other);  ///< copies the entries

  /// The registry loadEngineDeck() uses unless given another.
  static LinerRegistry& getGlobal();

  /// Registers `factory` under `name` (lower-case letters, digits and '_'). Throws
  /// std::invalid_argument for a bad or already registered name.
  void add(const std::string& name, const std::string& description, LinerFactory factory);
  /// The same for a factory that reads the deck context too.
  void add(const std::string& name, const std::string& description,
           LinerFactoryWithContext factory);
  /// No factory: throws std::invalid_argument (a null factory is a programming error).
  void add(const std::string& name, const std::string& description, std::nullptr_t);
  /// Removes a model (throws std::invalid_argument if there is none).
  void remove(const std::string& name);
  bool has(const std::string& name) const;  ///< a model of that name is registered
  /// Registered names, sorted.
  std::vector<std::string> getNames() const;
  /// The description registered with `name`; throws std::invalid_argument if there is none.
  std::string getDescription(const std::string& name) const;
  /// The factory registered as `name` (a LinerFactory is wrapped to ignore the context);
  /// throws std::invalid_argument if there is none.
  LinerFactoryWithContext getFactory(const std::string& name) const;

 private:
  struct Entry {
    std::string description;
    LinerFactoryWithContext factory;
  };
  mutable std::mutex mutex_;
  std::map<std::string, Entry> entries_;
};

/// LinerRegistry::getGlobal().add(name, description, factory).
void registerLinerModel(const std::string& name, const std::string& description,
                        LinerFactory factory);
/// LinerRegistry::getGlobal().add(name, description, factory) for a context-reading factory.
void registerLinerModel(const std::string& name, const std::string& description,
                        LinerFactoryWithContext factory);

}  // namespace pistondyn::io
