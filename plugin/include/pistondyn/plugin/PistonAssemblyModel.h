#pragma once
/// \file
/// A ready-to-simulate piston assembly: the Simbody system, the crank train and the
/// registry of force elements. Elements are added, replaced or removed by name until
/// the system is built (first call to buildSystem() / getDefaultState()); then the set
/// is frozen, because Simbody cannot remove a force or constraint from a built system.
///
///   PistonAssemblyModel model(engine);
///   model.addElement(std::make_unique<GasForceElement>(curve, 1e5));
///   model.addElement(std::make_unique<IdealLinerGuide>());
///   model.replaceElement("ideal_liner_guide", std::make_unique<MyLinerModel>());
///   SimTK::State s = model.getDefaultState();

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pistondyn/mbd_models/CrankTrain.h"
#include "pistondyn/plugin/ForceElement.h"
#include "pistondyn/plugin/LinerElement.h"

namespace pistondyn::plugin {

/// The Simbody system of one piston assembly: the crank train and the registry of force
/// elements (the documentation of PistonAssemblyModel.h).
class PistonAssemblyModel {
 public:
  /// Builds the crank train of `engine` (validated: std::invalid_argument naming the member);
  /// no element yet.
  explicit PistonAssemblyModel(const mbd::EngineDescription& engine);
  PistonAssemblyModel(const PistonAssemblyModel&) = delete;
  PistonAssemblyModel& operator=(const PistonAssemblyModel&) = delete;
  ~PistonAssemblyModel();

  // ---- element registry (before the system is built) -------------------------------
  /// Throws std::invalid_argument on a duplicate or empty name, std::logic_error once built.
  void addElement(std::unique_ptr<ForceElement> element);
  /// Replaces the element called `name` (throws if there is none); the newcomer may
  /// have a different name. Keeps the registration order.
  void replaceElement(const std::string& name, std::unique_ptr<ForceElement> element);
  /// Removes the element called `name` (throws if there is none, or once built).
  void removeElement(const std::string& name);
  bool hasElement(const std::string& name) const;  ///< an element called `name` exists
  /// The element called `name`; throws std::invalid_argument if there is none.
  const ForceElement& getElement(const std::string& name) const;
  /// The element called `name` as a T; throws std::invalid_argument if it has another type.
  template <class T>
  const T& getElementAs(const std::string& name) const {
    const T* e = dynamic_cast<const T*>(&getElement(name));
    if (e == nullptr)
      throw std::invalid_argument("element '" + name + "' has another type");
    return *e;
  }
  std::vector<std::string> getElementNames() const;  ///< in registration order

  // ---- Simbody system ------------------------------------------------------------
  /// Wraps every element in a Simbody Force::Custom, lets it add constraints, and
  /// realizes topology. Idempotent.
  void buildSystem();
  bool isBuilt() const { return built_; }  ///< buildSystem() has run: the elements are frozen
  /// Default state (builds first); every q and u zero = firing TDC, piston upright, at rest.
  const SimTK::State& getDefaultState();

  const SimTK::MultibodySystem& getSystem() const { return *system_; }         ///< the system
  SimTK::MultibodySystem& updSystem() { return *system_; }                     ///< writable system
  const SimTK::SimbodyMatterSubsystem& getMatter() const { return *matter_; }  ///< matter
  const SimTK::GeneralForceSubsystem& getForceSubsystem() const { return *forces_; }  ///< forces
  const mbd::CrankTrain& getCrankTrain() const { return *crankTrain_; }  ///< the crank train

  // ---- outputs (ElementOutput.h) ---------------------------------------------------
  /// Every element's outputs in registration order, as declared when the system was built
  /// (builds it first).
  const std::vector<ElementOutput>& getElementOutputs();
  /// The outputs of a model already built (throws std::logic_error otherwise).
  const std::vector<ElementOutput>& getElementOutputs() const;
  /// Their column names (name_unit).
  std::vector<std::string> getElementOutputColumns() const;
  /// Appends the value of every output, in that order (state realized through
  /// Stage::Acceleration).
  void calcElementOutputs(const SimTK::State& s, std::vector<double>& values) const;

  /// The element that holds the piston in the bore (LinerElement.h), or nullptr if the
  /// model has none. Throws std::logic_error if several elements claim the role.
  const LinerElement* findLinerElement() const;

  // ---- force Jacobian for implicit steppers (ForceElement::addForceJacobian) --------
  /// Sum of the elements' Jacobian parts at a state realized through Stage::Dynamics
  /// (nu x nq and nu x nu, zero where no element adds anything). Returns false if no
  /// element adds anything.
  bool calcElementForceJacobian(const SimTK::State& s, ForceJacobian& jacobian) const;
  /// Forwards ForceElement::setForceJacobianWanted to every element: whether the velocity part
  /// (dfdu) of calcElementForceJacobian will be read at the next realizations (default: yes).
  void setForceJacobianWanted(bool wanted) const;

 private:
  void requireNotBuilt(const char* what) const;
  /// Index of the element called `name`; elements_.size() when there is none.
  std::size_t indexOf(const std::string& name) const;
  /// The same, but throws std::invalid_argument naming `caller` when there is none.
  std::size_t requireIndexOf(const std::string& name, const char* caller) const;

  /// Declared before the system: members are destroyed in reverse order, so the
  /// Simbody system (whose Force::Custom adapters point at these elements) goes first.
  std::vector<std::unique_ptr<ForceElement>> elements_;
  std::unique_ptr<SimTK::MultibodySystem> system_;
  std::unique_ptr<SimTK::SimbodyMatterSubsystem> matter_;
  std::unique_ptr<SimTK::GeneralForceSubsystem> forces_;
  std::unique_ptr<mbd::CrankTrain> crankTrain_;
  std::vector<ElementOutput> outputs_;  ///< recorded by buildSystem()
  bool built_ = false;
};

}  // namespace pistondyn::plugin
