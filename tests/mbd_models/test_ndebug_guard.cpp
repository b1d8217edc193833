// docs/DESIGN.md §5: Debian's Simbody 3.7 is built without NDEBUG and a translation
// unit that includes Simbody with NDEBUG crashes in realizeTopology(). These checks fail
// if any pistondyn code including Simbody is built with NDEBUG. (A separate CTest entry,
// ndebug_guard_rejects_NDEBUG, shows the header guard stops such a build outright.)

#include <gtest/gtest.h>

#include "pistondyn/mbd_models/CrankTrain.h"
#include "pistondyn/mbd_models/SimbodyBuildCheck.h"

namespace {

TEST(NdebugGuard, ThisTestIsBuiltWithoutNdebug) {
#ifdef NDEBUG
  FAIL() << "tests including Simbody are compiled with NDEBUG";
#endif
}

TEST(NdebugGuard, PistondynSimbodyLibrariesAreBuiltWithoutNdebug) {
  EXPECT_FALSE(pistondyn::mbd::libraryBuiltWithNDEBUG());
}

// The crash needs constraints or motions: build a model with both and realize it.
TEST(NdebugGuard, ModelWithMotionAndConstraintRealizes) {
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter(system);
  SimTK::GeneralForceSubsystem forces(system);
  SimTK::MobilizedBody::Pin wheel(
      matter.Ground(), SimTK::Transform(),
      SimTK::Body::Rigid(SimTK::MassProperties(1, SimTK::Vec3(0), SimTK::Inertia(1))),
      SimTK::Transform());
  SimTK::Motion::Steady(wheel, 2.0);
  SimTK::MobilizedBody::Slider slider(
      matter.Ground(), SimTK::Transform(),
      SimTK::Body::Rigid(SimTK::MassProperties(1, SimTK::Vec3(0), SimTK::Inertia(1))),
      SimTK::Transform());
  SimTK::Constraint::ConstantSpeed(slider, 0.5);
  system.realizeTopology();
  SimTK::State s = system.getDefaultState();
  system.realize(s, SimTK::Stage::Time);
  system.prescribe(s);  // applies the Motion's prescribed speed
  system.realize(s, SimTK::Stage::Acceleration);
  EXPECT_NEAR(wheel.getOneU(s, SimTK::MobilizerUIndex(0)), 2.0, 1e-12);
}

}  // namespace
