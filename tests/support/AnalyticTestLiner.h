#pragma once
// A TEST-ONLY liner model with known answers for the design loop (tests/design, tests/app,
// python/tests): never part of the shipped program. It holds the piston as the ideal guide
// does (IdealLinerGuide: constraints, rk_merson) and reports, through the liner role,
// figures that are closed-form functions of deck keys:
//
//   fmep [kPa]       F = fmep_offset_kPa + ((c - 40) / 10)^2 + ((e - 0.5) / 0.5)^2
//                    (the friction work grows as F V_d theta / 4 pi, so the run's
//                    summary reports fmep_kPa = F: CycleSimulation's cycle difference)
//   min h/sigma      thrust c / 10 - e, anti-thrust c / 10 - e + 1
//   hot clearance    c [um]
//   output column    analytic_signal_mrad = A sin(theta + phi) + (b + k) cos(2 theta)
//
// with c = liner.clearance_um, e = geometry.pin_offset_mm [mm], A =
// liner.signal_amplitude_mrad, phi = liner.signal_phase_deg, b = liner.signal_b_mrad, k =
// liner.signal_c_mrad; liner.inert_factor is read and enters nothing (a parameter no
// trace can identify). With liner.fail_below_clearance_um set, a run with c below it
// throws at its first force evaluation (a design whose run fails). Minimising F subject to min
// h/sigma >= 4 on the bounds c in [20, 60], e in [-1, 1]: with x = (c - 40)/10, y = (e - 0.5)/0.5
// the constraint reads x - y/2 >= 1/2, and the point of that half plane nearest the origin is (x,
// y) = (0.4, -0.2): c* = 44 um, e* = 0.4 mm, F* = fmep_offset + 0.2.
//
// registerAnalyticTestLiner() adds it as "analytic_test" to a registry.

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "pistondyn/io/DeckSection.h"
#include "pistondyn/io/LinerRegistry.h"
#include "pistondyn/mbd_models/SliderCrank.h"
#include "pistondyn/plugin/IdealLinerGuide.h"
#include "pistondyn/plugin/LinerElement.h"

namespace pistondyn_test {

using namespace pistondyn;

struct AnalyticTestParameters {
  double clearance_um = 40.0;
  double pinOffset_mm = 0.0;
  double fmepOffset_kPa = 1.0;
  double amplitude_mrad = 1.0, phase_rad = 0.0, b_mrad = 0.0, c_mrad = 0.0;
  std::optional<double> failBelow_um;
};

inline double analyticFmep_kPa(const AnalyticTestParameters& p) {
  const double x = (p.clearance_um - 40.0) / 10.0, y = (p.pinOffset_mm - 0.5) / 0.5;
  return p.fmepOffset_kPa + x * x + y * y;
}

inline double analyticSignal_mrad(const AnalyticTestParameters& p, double theta_rad) {
  return p.amplitude_mrad * std::sin(theta_rad + p.phase_rad) +
         (p.b_mrad + p.c_mrad) * std::cos(2.0 * theta_rad);
}

class AnalyticTestLiner final : public plugin::LinerElement {
 public:
  explicit AnalyticTestLiner(AnalyticTestParameters p) : p_(p) {}
  std::string getName() const override { return "analytic_test_liner"; }
  void addToModel(const plugin::ModelBuildContext& c) override {
    crankTrain_ = &c.crankTrain;
    guide_.addToModel(c);
    const auto& e = c.crankTrain.getEngine();
    displacement_m3_ = mbd::CylinderVolume(mbd::SliderCrank(e.geometry), e.piston.bore_m,
                                           e.geometry.compressionRatio)
                           .displacement_m3();
  }
  void calcForces(const SimTK::State& s, plugin::AppliedForces& f) const override {
    if (p_.failBelow_um && p_.clearance_um < *p_.failBelow_um)
      throw std::runtime_error("analytic test liner: failing on purpose below a clearance of " +
                               std::to_string(*p_.failBelow_um) + " um");
    guide_.calcForces(s, f);
  }
  plugin::ElementOutputs getOutputs() const override {
    plugin::ElementOutputs out = guide_.getOutputs();
    out.push_back(
        {"analytic_signal", "mrad", "closed-form test signal", [this](const SimTK::State& s) {
           return analyticSignal_mrad(p_, crankTrain_->getCrankAngle_rad(s));
         }});
    return out;
  }
  double getSideForce_N(const SimTK::State& s) const override { return guide_.getSideForce_N(s); }
  std::optional<double> getFrictionWork_J(const SimTK::State& s) const override {
    return analyticFmep_kPa(p_) * 1e3 * displacement_m3_ * crankTrain_->getCrankAngle_rad(s) /
           (4.0 * M_PI);
  }
  std::optional<double> getMinGapOverSigma(const SimTK::State&,
                                           plugin::SkirtSide side) const override {
    const double h = p_.clearance_um / 10.0 - p_.pinOffset_mm;
    return side == plugin::SkirtSide::Thrust ? h : h + 1.0;
  }
  std::optional<double> getHotRunningClearance_m() const override { return p_.clearance_um * 1e-6; }

 private:
  AnalyticTestParameters p_;
  plugin::IdealLinerGuide guide_;
  const mbd::CrankTrain* crankTrain_ = nullptr;
  double displacement_m3_ = 0.0;
};

inline void registerAnalyticTestLiner(io::LinerRegistry& registry) {
  registry.add("analytic_test", "TEST ONLY: closed-form fmep, h/sigma and signal (tests/support)",
               [](io::DeckSection& liner, const io::LinerDeckContext& context) -> io::LinerModel {
                 io::LinerModel model;
                 model.needs.usesConstraints = true;
                 AnalyticTestParameters p;
                 p.clearance_um =
                     liner.getNumberOr("clearance_um", 40.0, io::Bounds::between(1, 500));
                 p.fmepOffset_kPa = liner.getNumberOr("fmep_offset_kPa", 1.0);
                 p.amplitude_mrad = liner.getNumberOr("signal_amplitude_mrad", 1.0);
                 p.phase_rad = liner.getNumberOr("signal_phase_deg", 0.0) * M_PI / 180.0;
                 p.b_mrad = liner.getNumberOr("signal_b_mrad", 0.0);
                 p.c_mrad = liner.getNumberOr("signal_c_mrad", 0.0);
                 (void)liner.getNumberOr("inert_factor", 1.0);
                 p.failBelow_um = liner.getOptionalNumber("fail_below_clearance_um");
                 p.pinOffset_mm = context.engine->geometry.pinOffset_m * 1e3;
                 model.maker = [p] { return std::make_unique<AnalyticTestLiner>(p); };
                 return model;
               });
}

}  // namespace pistondyn_test
