#include "pistondyn/io/LinerRegistry.h"

#include <stdexcept>

#include "pistondyn/io/DeckSection.h"
#include "pistondyn/io/LubricatedSkirtDeck.h"
#include "pistondyn/plugin/IdealLinerGuide.h"

namespace pistondyn::io {
namespace {

bool isModelName(const std::string& name) {
  if (name.empty())
    return false;
  for (const char c : name) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'))
      return false;
  }
  return true;
}

}  // namespace

LinerRegistry::LinerRegistry() {
  add("ideal_guide",
      "rigid, frictionless, zero-clearance guide (three Simbody constraints); no keys",
      [](DeckSection&, const LinerDeckContext&) -> LinerModel {
        LinerModel model;
        model.maker = [] { return std::make_unique<plugin::IdealLinerGuide>(); };
        model.needs.usesConstraints = true;
        return model;
      });
  add("lubricated_skirt",
      "oil film (average Reynolds, cavitation) and asperity contact on both skirt sides; "
      "keys liner.cold_radial_clearance_um, liner.grid.*, liner.skirt_profile.*, liner.oil.*, "
      "... (`pistondyn keys` lists them)",
      readLubricatedSkirt);
}

LinerRegistry::LinerRegistry(const LinerRegistry& other) {
  std::lock_guard<std::mutex> lock(other.mutex_);
  entries_ = other.entries_;
}

LinerRegistry& LinerRegistry::operator=(const LinerRegistry& other) {
  if (this != &other) {
    std::scoped_lock lock(mutex_, other.mutex_);
    entries_ = other.entries_;
  }
  return *this;
}

LinerRegistry& LinerRegistry::getGlobal() {
  static LinerRegistry global;
  return global;
}

void LinerRegistry::add(const std::string& name, const std::string& description,
                        LinerFactory factory) {
  if (!factory)
    throw std::invalid_argument("LinerRegistry::add: '" + name + "': empty factory");
  add(name, description,
      [f = std::move(factory)](DeckSection& liner, const LinerDeckContext&) {
        return LinerModel{f(liner), {}};
      });
}

void LinerRegistry::add(const std::string& name, const std::string&, std::nullptr_t) {
  throw std::invalid_argument("LinerRegistry::add: '" + name + "': empty factory");
}

void LinerRegistry::add(const std::string& name, const std::string& description,
                        LinerFactoryWithContext factory) {
  if (!isModelName(name)) {
    throw std::invalid_argument("LinerRegistry::add: name '" + name +
                                "' must be lower-case letters, digits and '_'");
  }
  if (!factory)
    throw std::invalid_argument("LinerRegistry::add: '" + name + "': empty factory");
  std::lock_guard<std::mutex> lock(mutex_);
  if (!entries_.emplace(name, Entry{description, std::move(factory)}).second) {
    throw std::invalid_argument("LinerRegistry::add: a liner model '" + name +
                                "' is already registered");
  }
}

void LinerRegistry::remove(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (entries_.erase(name) == 0)
    throw std::invalid_argument("LinerRegistry::remove: no liner model '" + name + "'");
}

bool LinerRegistry::has(const std::string& name) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.count(name) != 0;
}

std::vector<std::string> LinerRegistry::getNames() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> names;
  for (const auto& e : entries_)
    names.push_back(e.first);
  return names;
}

std::string LinerRegistry::getDescription(const std::string& name) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = entries_.find(name);
  if (it == entries_.end())
    throw std::invalid_argument("LinerRegistry::getDescription: no liner model '" + name + "'");
  return it->second.description;
}

LinerFactoryWithContext LinerRegistry::getFactory(const std::string& name) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = entries_.find(name);
  if (it == entries_.end())
    throw std::invalid_argument("LinerRegistry::getFactory: no liner model '" + name + "'");
  return it->second.factory;
}

void registerLinerModel(const std::string& name, const std::string& description,
                        LinerFactory factory) {
  LinerRegistry::getGlobal().add(name, description, std::move(factory));
}

void registerLinerModel(const std::string& name, const std::string& description,
                        LinerFactoryWithContext factory) {
  LinerRegistry::getGlobal().add(name, description, std::move(factory));
}

}  // namespace pistondyn::io
