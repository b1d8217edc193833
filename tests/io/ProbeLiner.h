#pragma once
// A user liner for the io tests. It holds the piston with the example's springs
// (SpringLinerGuide), but its liner role reports figures that appear in no column, so a
// summary that matches them can only have come from the role interface:
//   getSideForce_N       = roleOffset_N + crank angle [deg]
//   getMinFilmThickness  = (2 + cos theta) um on the thrust side, none on anti-thrust
//   getFrictionWork_J    = 3 J per rad of crank angle
// Its typed outputs are "spring_push" [kN] (the springs' lateral force / 1000) and
// "probe_index" [1]; it has no side_force output. With throwAt_deg set, calcForces()
// throws once the crank passes that angle (a run that fails mid-way).

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "../../examples/custom_element/SpringLinerGuide.h"
#include "pistondyn/io/DeckSection.h"
#include "pistondyn/io/LinerRegistry.h"
#include "pistondyn/plugin/LinerElement.h"

namespace pistondyn_test {

using namespace pistondyn;

class ProbeLiner final : public plugin::LinerElement {
 public:
  struct Parameters {
    double roleOffset_N = 1000.0;
    std::optional<double> throwAt_deg;
  };
  explicit ProbeLiner(Parameters p) : p_(p), springs_(examples::SpringLinerGuide::Parameters{}) {}

  std::string getName() const override { return "probe_liner"; }
  void addToModel(const plugin::ModelBuildContext& c) override {
    crankTrain_ = &c.crankTrain;
    springs_.addToModel(c);
  }
  void calcForces(const SimTK::State& s, plugin::AppliedForces& forces) const override {
    if (p_.throwAt_deg && angle_deg(s) > *p_.throwAt_deg)
      throw std::runtime_error("ProbeLiner: failing on purpose past " +
                               std::to_string(*p_.throwAt_deg) + " deg");
    springs_.calcForces(s, forces);
  }
  double getSideForce_N(const SimTK::State& s) const override {
    return p_.roleOffset_N + angle_deg(s);
  }
  std::optional<double> getMinFilmThickness_m(const SimTK::State& s,
                                              plugin::SkirtSide side) const override {
    if (side == plugin::SkirtSide::AntiThrust)
      return std::nullopt;
    return 1e-6 * (2.0 + std::cos(crankTrain_->getCrankAngle_rad(s)));
  }
  std::optional<double> getFrictionWork_J(const SimTK::State& s) const override {
    return 3.0 * crankTrain_->getCrankAngle_rad(s);
  }
  plugin::ElementOutputs getOutputs() const override {
    return {
        {"spring_push", "kN", "lateral spring force / 1000",
         [this](const SimTK::State& s) { return 1e-3 * springs_.getSideForce_N(s); }},
        {"probe_index", "1", "a dimensionless output", [](const SimTK::State&) { return 7.0; }}};
  }

 private:
  double angle_deg(const SimTK::State& s) const {
    return crankTrain_->getCrankAngle_rad(s) * 180.0 / M_PI;
  }
  Parameters p_;
  examples::SpringLinerGuide springs_;
  const mbd::CrankTrain* crankTrain_ = nullptr;
};

// The same springs as a plain force element, without the liner role: a model holding its
// piston with it has no liner element.
class SpringsWithoutRole final : public plugin::ForceElement {
 public:
  SpringsWithoutRole() : springs_(examples::SpringLinerGuide::Parameters{}) {}
  std::string getName() const override { return "springs_without_role"; }
  void addToModel(const plugin::ModelBuildContext& c) override { springs_.addToModel(c); }
  void calcForces(const SimTK::State& s, plugin::AppliedForces& f) const override {
    springs_.calcForces(s, f);
  }

 private:
  examples::SpringLinerGuide springs_;
};

// The liner model "probe_liner": keys role_offset_N (default 1000) and throw_at_deg.
inline void registerProbeLiner(io::LinerRegistry& registry) {
  registry.add("probe_liner", "test liner whose role differs from its columns",
               [](io::DeckSection& liner) -> io::LinerElementMaker {
                 ProbeLiner::Parameters p;
                 p.roleOffset_N = liner.getSIOr("role_offset_N", io::Quantity::Force, 1000.0);
                 p.throwAt_deg = liner.getOptionalNumber("throw_at_deg");
                 return [p] { return std::make_unique<ProbeLiner>(p); };
               });
}

}  // namespace pistondyn_test
