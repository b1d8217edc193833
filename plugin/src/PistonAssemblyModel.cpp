#include "pistondyn/plugin/PistonAssemblyModel.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace pistondyn::plugin {
namespace {

// Adapter: one Simbody Force::Custom per pistondyn element. Non-owning; the model
// owns the element and outlives the Simbody system.
class ElementForceAdapter final : public SimTK::Force::Custom::Implementation {
 public:
  ElementForceAdapter(const ForceElement& element, const SimTK::GeneralForceSubsystem& forces)
      : element_(element), forces_(forces) {}

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobilityForces) const override {
    AppliedForces applied(bodyForces, mobilityForces);
    element_.calcForces(s, applied);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    return element_.calcPotentialEnergy(s);
  }
  bool dependsOnlyOnPositions() const override { return element_.dependsOnlyOnPositions(); }

  // Every realize stage Simbody offers a custom force, forwarded to the element.
  void realizeTopology(SimTK::State& s) const override {
    ElementStateAllocator allocator(s, forces_);
    element_.realizeTopology(s, allocator);
  }
  void realizeModel(SimTK::State& s) const override { element_.realizeModel(s); }
  void realizeInstance(const SimTK::State& s) const override { element_.realizeInstance(s); }
  void realizeTime(const SimTK::State& s) const override { element_.realizeTime(s); }
  void realizePosition(const SimTK::State& s) const override { element_.realizePosition(s); }
  void realizeVelocity(const SimTK::State& s) const override { element_.realizeVelocity(s); }
  void realizeDynamics(const SimTK::State& s) const override { element_.realizeDynamics(s); }
  void realizeAcceleration(const SimTK::State& s) const override {
    element_.realizeAcceleration(s);
  }
  void realizeReport(const SimTK::State& s) const override { element_.realizeReport(s); }

 private:
  const ForceElement& element_;
  const SimTK::GeneralForceSubsystem& forces_;
};

}  // namespace

PistonAssemblyModel::PistonAssemblyModel(const mbd::EngineDescription& engine)
    : system_(std::make_unique<SimTK::MultibodySystem>()),
      matter_(std::make_unique<SimTK::SimbodyMatterSubsystem>(*system_)),
      forces_(std::make_unique<SimTK::GeneralForceSubsystem>(*system_)),
      crankTrain_(std::make_unique<mbd::CrankTrain>(*matter_, *forces_, engine)) {}

PistonAssemblyModel::~PistonAssemblyModel() = default;

void PistonAssemblyModel::requireNotBuilt(const char* what) const {
  if (built_) {
    throw std::logic_error(std::string("PistonAssemblyModel::") + what +
                           ": the Simbody system is already built; change elements before "
                           "buildSystem()/getDefaultState()");
  }
}

std::size_t PistonAssemblyModel::indexOf(const std::string& name) const {
  const auto it = std::find_if(elements_.begin(), elements_.end(),
                               [&](const auto& e) { return e->getName() == name; });
  return static_cast<std::size_t>(it - elements_.begin());
}

std::size_t PistonAssemblyModel::requireIndexOf(const std::string& name, const char* caller) const {
  const std::size_t k = indexOf(name);
  if (k == elements_.size()) {
    throw std::invalid_argument(std::string("PistonAssemblyModel::") + caller +
                                ": no element called '" + name + "'");
  }
  return k;
}

void PistonAssemblyModel::addElement(std::unique_ptr<ForceElement> element) {
  requireNotBuilt("addElement");
  if (!element)
    throw std::invalid_argument("PistonAssemblyModel::addElement: null element");
  const std::string name = element->getName();
  if (name.empty())
    throw std::invalid_argument("PistonAssemblyModel::addElement: empty name");
  if (hasElement(name)) {
    throw std::invalid_argument("PistonAssemblyModel::addElement: an element called '" + name +
                                "' is already registered (use replaceElement)");
  }
  elements_.push_back(std::move(element));
}

void PistonAssemblyModel::replaceElement(const std::string& name,
                                         std::unique_ptr<ForceElement> element) {
  requireNotBuilt("replaceElement");
  if (!element)
    throw std::invalid_argument("PistonAssemblyModel::replaceElement: null element");
  const std::size_t k = requireIndexOf(name, "replaceElement");
  const std::string newName = element->getName();
  if (newName != name && hasElement(newName)) {
    throw std::invalid_argument("PistonAssemblyModel::replaceElement: an element called '" +
                                newName + "' is already registered");
  }
  elements_[k] = std::move(element);
}

void PistonAssemblyModel::removeElement(const std::string& name) {
  requireNotBuilt("removeElement");
  const std::size_t k = requireIndexOf(name, "removeElement");
  elements_.erase(elements_.begin() + static_cast<std::ptrdiff_t>(k));
}

bool PistonAssemblyModel::hasElement(const std::string& name) const {
  return indexOf(name) != elements_.size();
}

const ForceElement& PistonAssemblyModel::getElement(const std::string& name) const {
  return *elements_[requireIndexOf(name, "getElement")];
}

std::vector<std::string> PistonAssemblyModel::getElementNames() const {
  std::vector<std::string> names;
  for (const auto& e : elements_)
    names.push_back(e->getName());
  return names;
}

void PistonAssemblyModel::buildSystem() {
  if (built_)
    return;
  const ModelBuildContext context{*matter_, *forces_, *crankTrain_};
  (void)findLinerElement();  // at most one element may hold the piston in the bore
  outputs_.clear();
  for (auto& e : elements_) {
    e->addToModel(context);
    for (auto& o : e->getOutputs()) {
      if (!o.getter) {
        throw std::logic_error("force element '" + e->getName() + "': output '" + o.name +
                               "' has no getter");
      }
      outputs_.push_back(std::move(o));
    }
    // Force::Custom takes ownership of the adapter (Simbody's API); the adapter only
    // refers to the element.
    SimTK::Force::Custom(*forces_, new ElementForceAdapter(*e, *forces_));
  }
  system_->realizeTopology();
  built_ = true;
}

const SimTK::State& PistonAssemblyModel::getDefaultState() {
  buildSystem();
  return system_->getDefaultState();
}

const std::vector<ElementOutput>& PistonAssemblyModel::getElementOutputs() {
  buildSystem();
  return outputs_;
}

const std::vector<ElementOutput>& PistonAssemblyModel::getElementOutputs() const {
  if (!built_) {
    throw std::logic_error(
        "PistonAssemblyModel::getElementOutputs: outputs are recorded when the system is built");
  }
  return outputs_;
}

std::vector<std::string> PistonAssemblyModel::getElementOutputColumns() const {
  std::vector<std::string> columns;
  for (const auto& o : getElementOutputs())
    columns.push_back(o.getColumnName());
  return columns;
}

void PistonAssemblyModel::calcElementOutputs(const SimTK::State& s,
                                             std::vector<double>& values) const {
  for (const auto& o : outputs_)
    values.push_back(o.getter(s));
}

const LinerElement* PistonAssemblyModel::findLinerElement() const {
  const LinerElement* found = nullptr;
  for (const auto& e : elements_) {
    if (const auto* liner = dynamic_cast<const LinerElement*>(e.get())) {
      if (found != nullptr) {
        throw std::logic_error("PistonAssemblyModel: elements '" + found->getName() + "' and '" +
                               liner->getName() +
                               "' both hold the piston in the bore (LinerElement); keep one");
      }
      found = liner;
    }
  }
  return found;
}

bool PistonAssemblyModel::calcElementForceJacobian(const SimTK::State& s,
                                                   ForceJacobian& jacobian) const {
  const int nq = s.getNQ(), nu = s.getNU();
  jacobian.dfdq.resize(nu, nq);
  jacobian.dfdu.resize(nu, nu);
  jacobian.dfdq = 0.0;
  jacobian.dfdu = 0.0;
  bool any = false;
  for (const auto& e : elements_)
    any = e->addForceJacobian(s, jacobian) || any;
  return any;
}

void PistonAssemblyModel::setForceJacobianWanted(bool wanted) const {
  for (const auto& e : elements_)
    e->setForceJacobianWanted(wanted);
}

}  // namespace pistondyn::plugin
