#pragma once
// A YAML engine deck with a schema enforced by use: every getter marks its key as
// known; finish() reports every key that nobody asked for as unknown. Problems are
// collected (not thrown one by one) so the user sees all of them at once, each as
//   <file>:<line>: <key.path>: <what is wrong and what is expected>
// Values overridden on the command line (--set a.b.c=value) are reported as
//   --set <key.path>: ...

#include <yaml-cpp/yaml.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace pistondyn::io {

class YamlDeck {
 public:
  // Loads and parses the file; throws DeckError (with line) on unreadable/invalid YAML.
  explicit YamlDeck(std::string filePath);

  // "a.b.c=value": value parsed as a YAML scalar. Creates missing maps on the path
  // (a misspelt key is then reported as unknown by finish()). Throws DeckError.
  void applyOverride(const std::string& assignment);

  const std::string& getFilePath() const { return filePath_; }
  // Directory of the deck file, for resolving relative paths ("" = current directory).
  std::string getDirectory() const;

  // ---- schema getters: record a problem and return a harmless value on failure ----
  enum class Sign { Any, Positive, NonNegative };
  double getNumber(const std::string& path, Sign sign = Sign::Any);
  std::optional<double> getOptionalNumber(const std::string& path, Sign sign = Sign::Any);
  double getNumberOr(const std::string& path, double fallback, Sign sign = Sign::Any);
  long getIntegerOr(const std::string& path, long fallback, long minimum, long maximum);
  // A number that must lie in [minimum, maximum] (the unit is named in the message);
  // nullopt when absent or out of range (the latter recorded as a problem).
  std::optional<double> getNumberInRange(const std::string& path, bool required, double minimum,
                                         double maximum, const std::string& unit);
  std::string getString(const std::string& path);
  std::string getChoiceOr(const std::string& path, const std::vector<std::string>& choices,
                          const std::string& fallback);
  bool has(const std::string& path) const;

  // Adds a problem about `path` found by a later, cross-key check (e.g. rod too short).
  void addProblem(const std::string& path, const std::string& message);
  bool hasProblems() const { return !problems_.empty(); }
  // Reports unknown keys, then throws DeckError listing every problem (if any).
  void finish();

 private:
  YAML::Node lookup(const std::string& path) const;  // invalid node if absent
  std::string where(const std::string& path) const;  // "<file>:<line>: key" or "--set ..."
  std::string overridingAssignment(const std::string& path) const;  // "" if from the file
  std::optional<double> readNumber(const std::string& path, Sign sign, bool required);
  void markKnown(const std::string& path);
  void collectUnknown(const YAML::Node& node, const std::string& prefix);

  std::string filePath_;
  YAML::Node root_;
  std::set<std::string> known_;       // every key path a getter asked for (and its parents)
  std::set<std::string> overridden_;  // key paths set by --set
  std::vector<std::string> problems_;
};

}  // namespace pistondyn::io
