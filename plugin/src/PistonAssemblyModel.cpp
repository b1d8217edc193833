#include "pistondyn/plugin/PistonAssemblyModel.h"

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
  void realizeTopology(SimTK::State& s) const override { element_.realizeTopology(s, forces_); }

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

std::vector<std::unique_ptr<ForceElement>>::iterator PistonAssemblyModel::find(
    const std::string& name) {
  for (auto it = elements_.begin(); it != elements_.end(); ++it) {
    if ((*it)->getName() == name)
      return it;
  }
  return elements_.end();
}

std::vector<std::unique_ptr<ForceElement>>::const_iterator PistonAssemblyModel::find(
    const std::string& name) const {
  for (auto it = elements_.begin(); it != elements_.end(); ++it) {
    if ((*it)->getName() == name)
      return it;
  }
  return elements_.end();
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
  auto it = find(name);
  if (it == elements_.end()) {
    throw std::invalid_argument("PistonAssemblyModel::replaceElement: no element called '" + name +
                                "'");
  }
  const std::string newName = element->getName();
  if (newName != name && hasElement(newName)) {
    throw std::invalid_argument("PistonAssemblyModel::replaceElement: an element called '" +
                                newName + "' is already registered");
  }
  *it = std::move(element);
}

void PistonAssemblyModel::removeElement(const std::string& name) {
  requireNotBuilt("removeElement");
  auto it = find(name);
  if (it == elements_.end()) {
    throw std::invalid_argument("PistonAssemblyModel::removeElement: no element called '" + name +
                                "'");
  }
  elements_.erase(it);
}

bool PistonAssemblyModel::hasElement(const std::string& name) const {
  return find(name) != elements_.end();
}

const ForceElement& PistonAssemblyModel::getElement(const std::string& name) const {
  auto it = find(name);
  if (it == elements_.end()) {
    throw std::invalid_argument("PistonAssemblyModel::getElement: no element called '" + name +
                                "'");
  }
  return **it;
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
  for (auto& e : elements_) {
    e->addToModel(context);
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

std::vector<std::string> PistonAssemblyModel::getElementReportColumns() const {
  std::vector<std::string> columns;
  for (const auto& e : elements_) {
    for (auto& c : e->getReportColumns())
      columns.push_back(std::move(c));
  }
  return columns;
}

void PistonAssemblyModel::calcElementReports(const SimTK::State& s,
                                             std::vector<double>& values) const {
  for (const auto& e : elements_) {
    const std::size_t before = values.size();
    e->calcReport(s, values);
    if (values.size() - before != e->getReportColumns().size()) {
      throw std::logic_error("force element '" + e->getName() +
                             "' reported a different number of values than columns");
    }
  }
}

}  // namespace pistondyn::plugin
