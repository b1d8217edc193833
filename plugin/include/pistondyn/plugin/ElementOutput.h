#pragma once
/// \file
/// Typed outputs of a force element, declared once (OpenSim's model outputs are the
/// model): each has a name, a unit and a getter evaluated on a state realized through
/// Stage::Acceleration. The column of an output in cycle.csv is name + "_" + unit, e.g.
/// {"side_force", "N"} -> side_force_N; plots and summaries find outputs by name and read
/// their unit from here, never by parsing column names.
///
/// Units are written as the suffixes the project uses in every name (docs/CONVENTIONS.md):
/// N, Nm, W, J, Pa, kPa, m, um, mm, rad, mrad, deg, mps, mps2, 1 (dimensionless), ...

#include <functional>
#include <string>
#include <vector>

namespace SimTK {
class State;
}

namespace pistondyn::plugin {

/// One typed output of an element (the documentation of ElementOutput.h).
struct ElementOutput {
  std::string name;         ///< e.g. "side_force" (snake case, no unit)
  std::string unit;         ///< e.g. "N"; "1" for a dimensionless number (column without suffix)
  std::string description;  ///< one line for the deck/output reference
  std::function<double(const SimTK::State&)> getter;  ///< needs Stage::Acceleration

  /// Column name in result files: name + "_" + unit (just name for "1").
  std::string getColumnName() const { return unit == "1" ? name : name + "_" + unit; }
};

/// The outputs an element declares, in order.
using ElementOutputs = std::vector<ElementOutput>;

}  // namespace pistondyn::plugin
