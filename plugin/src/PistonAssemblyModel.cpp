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
  reportColumnCounts_.clear();
  for (auto& e : elements_) {
    reportColumnCounts_.push_back(e->getReportColumns().size());
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
  // Elements are frozen once the system is built (a State exists only then), so their column
  // counts were recorded by buildSystem(): no column names are built per output row.
  for (std::size_t k = 0; k < elements_.size(); ++k) {
    const std::size_t before = values.size();
    elements_[k]->calcReport(s, values);
    if (values.size() - before != reportColumnCounts_[k]) {
      throw std::logic_error("force element '" + elements_[k]->getName() +
                             "' reported a different number of values than columns");
    }
  }
}

}  // namespace pistondyn::plugin
