#pragma once
// Liner models selectable from a deck by name (`liner.model: <name>`). A liner model is a
// factory: it reads its own keys from the deck's `liner` section (DeckSection.h: typed
// getters, units in the keys, defaults, choices, files, nested sections) and returns a
// maker that constructs the element, once per model built from the deck. Keys of the
// section that the factory does not read are reported as unknown, as everywhere in a deck.
//
// `ideal_guide` (plugin::IdealLinerGuide) is registered by default. A user's program
// registers its own model before loading decks and selects it without other changes:
//
//   io::registerLinerModel("spring_guide", "linear springs and dampers",
//       [](io::DeckSection& liner) -> io::LinerElementMaker {
//         SpringGuide::Parameters p;
//         p.stiffness_Npm = liner.getSIOr("lateral_stiffness_N_per_mm", io::Quantity::Stiffness,
//                                         2e4, io::Bounds::positive());
//         return [p] { return std::make_unique<SpringGuide>(p); };
//       });
//   const auto deck = io::loadEngineDeck("engine.yaml", {"liner.model=spring_guide"});
//
// Factories run while the deck is read (so `pistondyn check` and every problem report see
// them); the maker runs once at load (a trial construction whose std::exception becomes
// a deck error) and then once per buildModel(). Registries are safe to use from several
// threads; register before loading decks.

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "pistondyn/plugin/LinerElement.h"

namespace pistondyn::io {

class DeckSection;

// Constructs one liner element with the parameters its factory read.
using LinerElementMaker = std::function<std::unique_ptr<plugin::LinerElement>()>;
// Reads the liner section; problems go to the section (never thrown for bad input).
using LinerFactory = std::function<LinerElementMaker(DeckSection& liner)>;

class LinerRegistry {
 public:
  // A registry holding the built-in models (ideal_guide).
  LinerRegistry();
  LinerRegistry(const LinerRegistry& other);
  LinerRegistry& operator=(const LinerRegistry& other);

  // The registry loadEngineDeck() uses unless given another.
  static LinerRegistry& getGlobal();

  // Registers `factory` under `name` (lower-case letters, digits and '_'). Throws
  // std::invalid_argument for a bad or already registered name.
  void add(const std::string& name, const std::string& description, LinerFactory factory);
  // Removes a model (throws std::invalid_argument if there is none).
  void remove(const std::string& name);
  bool has(const std::string& name) const;
  // Registered names, sorted.
  std::vector<std::string> getNames() const;
  std::string getDescription(const std::string& name) const;
  // The factory registered as `name`; throws std::invalid_argument if there is none.
  LinerFactory getFactory(const std::string& name) const;

 private:
  struct Entry {
    std::string description;
    LinerFactory factory;
  };
  mutable std::mutex mutex_;
  std::map<std::string, Entry> entries_;
};

// LinerRegistry::getGlobal().add(name, description, factory).
void registerLinerModel(const std::string& name, const std::string& description,
                        LinerFactory factory);

}  // namespace pistondyn::io
