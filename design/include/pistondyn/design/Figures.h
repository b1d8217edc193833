#pragma once
/// @file
/// The figures of a run the design loop can aim at or bound: numbers under `results` in
/// its summary.json (README.md, "The command-line program"), and `min_h_over_sigma`, the
/// smaller of the two sides' minimum h/sigma.

#include <optional>
#include <string>
#include <vector>

namespace pistondyn::design {

/// Every figure name an objective, a constraint or a propagation may name.
const std::vector<std::string>& getKnownFigures();
/// Whether `name` is one of getKnownFigures().
bool isKnownFigure(const std::string& name);
/// "fmep_kPa, friction_power_mean_W, ..." for messages.
std::string listKnownFigures();

/// The figures of one summary.json text.
class RunFigures {
 public:
  /// Throws std::runtime_error if the text is not a summary with `results`.
  explicit RunFigures(const std::string& summaryJson);
  /// The figure, or nullopt if the run's summary has none (the liner does not report it).
  std::optional<double> get(const std::string& name) const;

 private:
  std::vector<std::pair<std::string, double>> values_;
};

}  // namespace pistondyn::design
