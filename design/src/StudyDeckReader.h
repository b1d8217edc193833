#pragma once
// Reading a design-loop deck (not installed): the YAML with line numbers, the blocks every
// study has (name, base_deck, set, the variables, profile) and the checks of the variables
// against the base deck. Problems are collected, each as
//   <file>:<line>: <block>.<key>: what is wrong and what is expected
// and thrown together as io::DeckError by throwIfProblems().

#include <yaml-cpp/yaml.h>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pistondyn/design/DesignStudy.h"
#include "pistondyn/io/EngineDeck.h"

namespace pistondyn::design::detail {

class StudyDeckReader {
 public:
  StudyDeckReader(std::string path, std::string kind);

  // The root mapping's entries, each key once. Throws io::DeckError if the file cannot be
  // read, is not YAML or not a mapping.
  std::vector<std::pair<std::string, YAML::Node>> open();

  // The common top-level keys; false if `key` is none of them.
  bool readCommon(const std::string& key, const YAML::Node& value,
                  const std::string& variablesBlock, bool withStart);
  // After every block is read: the command line's overrides, the base deck loaded with
  // the shared ones, each variable's bounds loaded, the input files hashed. Fills `study`.
  // Returns the base deck (with the shared overrides) when it loaded.
  std::optional<io::EngineDeck> finishCommon(DesignStudy& study,
                                             const std::vector<std::string>& commandLineOverrides,
                                             const io::LinerRegistry& registry);

  // ---- helpers for the kind's own blocks ----
  std::string at(const YAML::Node& node, const std::string& keyPath) const;
  void problem(const YAML::Node& node, const std::string& keyPath, const std::string& what);
  void problem(const std::string& line) { problems_.push_back(line); }
  std::vector<std::pair<std::string, YAML::Node>> entries(const YAML::Node& map,
                                                          const std::string& prefix);
  std::optional<double> number(const YAML::Node& node, const std::string& where);
  std::optional<long> wholeNumber(const YAML::Node& node, const std::string& where, long minimum,
                                  long maximum);
  std::optional<std::string> text(const YAML::Node& node, const std::string& where);
  // [lower, upper] with lower < upper.
  std::optional<std::pair<double, double>> range(const YAML::Node& node, const std::string& where);
  bool hasProblems() const { return !problems_.empty(); }
  void throwIfProblems() const;
  const std::string& getPath() const { return path_; }
  // A path relative to the study deck's folder, made absolute.
  std::string resolve(const std::string& path) const;
  const YAML::Node& getRoot() const { return root_; }
  // The base deck's path as resolved, once base_deck was read (nullopt before, or if it is
  // not a path).
  std::optional<std::string> getBaseDeckPath() const;
  // Adds a variable unless one of that key exists (variables read from the deck come first).
  void addVariable(const DesignVariable& v);
  bool hasVariable(const std::string& key) const;
  // True if the deck's `set` names the key.
  bool isSet(const std::string& key) const;
  // The variables block may be absent (the variables come from elsewhere).
  void setVariablesBlockOptional() { sawVariables_ = true; }

 private:
  bool checkKeyPath(const YAML::Node& node, const std::string& key, const std::string& where);
  void readSet(const YAML::Node& node);
  void readVariables(const YAML::Node& node, const std::string& block, bool withStart);
  void readProfile(const YAML::Node& node);

  std::string path_, kind_;
  YAML::Node root_;
  std::vector<std::string> problems_;
  std::string name_;
  YAML::Node baseNode_;
  std::vector<std::string> setOverrides_;
  std::vector<std::pair<std::string, std::string>> setOrigins_;  // key, origin
  std::vector<DesignVariable> variables_;
  ProfileSpec profile_;
  std::string variablesBlock_;
  bool sawVariables_ = false;
};

// "key=value" with the value in the shortest text that reads back to the same double.
std::string assignment(const std::string& key, double value);

}  // namespace pistondyn::design::detail
