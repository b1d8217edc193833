#pragma once
/// @file
/// Nodal fields an element can give at a state: values on the nodes of one or more regions
/// (the lubricated skirt: its thrust and anti-thrust sides), declared once with name and unit
/// like ElementOutput.h, so that field dumps and skirt maps work for any element that has them
/// without knowing its type.

#include <string>
#include <vector>

#include <Eigen/Core>

namespace SimTK {
class State;
}

namespace pistondyn::plugin {

/// A field: name and unit as ElementOutput ("film_pressure", "Pa"; "1" = dimensionless); the
/// file column is name + "_" + unit (just name for "1").
struct NodalFieldDeclaration {
  std::string name;  ///< e.g. "film_pressure" (letters, digits, '_')
  std::string unit;  ///< e.g. "Pa", "um"; "1" = dimensionless
  /// The file column: name + "_" + unit, or name alone for unit "1".
  std::string getColumnName() const { return unit == "1" ? name : name + "_" + unit; }
};

/// A region of nodes on the piston: a structured grid, phi fastest (k = i + nPhi j).
struct NodalFieldRegion {
  std::string name;        ///< e.g. "thrust" (file names and labels: letters, digits, '_')
  ///@{
  int nPhi = 0, nY = 0;    ///< nodes around and along
  ///@}
  Eigen::VectorXd phi_rad;  ///< per node: angle from +x (thrust) towards +z (pin axis) [rad]
  Eigen::VectorXd y_m;      ///< per node: height above the pin axis, piston frame [m]
};

/// The role of an element that has nodal fields (LinerElement::getNodalFields()): its regions,
/// the fields declared on every region, and their values at a state. Field dumps and skirt
/// maps use only this interface.
class NodalFieldSource {
 public:
  virtual ~NodalFieldSource() = default;
  /// The regions, in a fixed order (a region's index is its position here); the same for
  /// every state of a run.
  virtual std::vector<NodalFieldRegion> getNodalFieldRegions() const = 0;
  /// The fields every region has, in the column order of calcNodalFields(); the same for every
  /// state of a run.
  virtual std::vector<NodalFieldDeclaration> getNodalFieldDeclarations() const = 0;
  /// The fields of region `region` at a state realized through Stage::Acceleration whose forces
  /// the element computed last (an output row): values (nodes x declarations), in the declared
  /// units, finite. Throws std::runtime_error when the element's last fields are not this
  /// state's.
  virtual void calcNodalFields(const SimTK::State& s, int region, Eigen::MatrixXd& values) const = 0;
};

}  // namespace pistondyn::plugin
