#include "pistondyn/plugin/LinerElement.h"

#include <cmath>
#include <stdexcept>

namespace pistondyn::plugin {

ElementOutput makeLinerOutput(LinerOutput which, const LinerElement& liner,
                              const mbd::CrankTrain& crankTrain) {
  using S = const SimTK::State&;
  const LinerElement* l = &liner;
  const mbd::CrankTrain* ct = &crankTrain;
  const mbd::PistonGeometry& pg = crankTrain.getEngine().piston;
  const double yTop = pg.skirtTopAbovePin_m, yBottom = pg.skirtTopAbovePin_m - pg.skirtLength_m;
  switch (which) {
    case LinerOutput::SideForce:
      return {"side_force", "N", "lateral force the piston exerts on the liner, + towards thrust",
              [l](S s) { return l->getSideForce_N(s); }};
    case LinerOutput::LateralAtSkirtTop:
      return {"u_lat_skirt_top", "um", "lateral displacement of the piston axis at the skirt top",
              [ct, yTop](S s) {
                return 1e6 * (ct->getLateralDisplacement_m(s) + yTop * std::sin(ct->getTilt_rad(s)));
              }};
    case LinerOutput::LateralAtSkirtBottom:
      return {"u_lat_skirt_bottom", "um",
              "lateral displacement of the piston axis at the skirt bottom", [ct, yBottom](S s) {
                return 1e6 *
                       (ct->getLateralDisplacement_m(s) + yBottom * std::sin(ct->getTilt_rad(s)));
              }};
    case LinerOutput::FrictionForce:
      return {"friction_force", "N", "skirt friction force on the piston along +y (bore axis)",
              [l](S s) { return l->getFrictionForce_N(s); }};
    case LinerOutput::FrictionPower:
      return {"friction_power", "W",
              "power the axial friction force takes from the piston's primary motion",
              [l](S s) { return l->getFrictionPower_W(s); }};
    case LinerOutput::FrictionWork:
      return {"friction_work", "J", "friction work since the start of the run (integrated state)",
              [l](S s) { return l->getFrictionWork_J(s).value(); }};
    case LinerOutput::MinFilmThrust:
      return {"min_film_thickness_thrust", "um", "smallest nominal gap, thrust side",
              [l](S s) { return 1e6 * l->getMinFilmThickness_m(s, SkirtSide::Thrust).value(); }};
    case LinerOutput::MinFilmAntiThrust:
      return {"min_film_thickness_antithrust", "um", "smallest nominal gap, anti-thrust side",
              [l](S s) {
                return 1e6 * l->getMinFilmThickness_m(s, SkirtSide::AntiThrust).value();
              }};
    case LinerOutput::MinGapOverSigmaThrust:
      return {"min_h_over_sigma_thrust", "1", "smallest gap / composite roughness, thrust side",
              [l](S s) { return l->getMinGapOverSigma(s, SkirtSide::Thrust).value(); }};
    case LinerOutput::MinGapOverSigmaAntiThrust:
      return {"min_h_over_sigma_antithrust", "1",
              "smallest gap / composite roughness, anti-thrust side",
              [l](S s) { return l->getMinGapOverSigma(s, SkirtSide::AntiThrust).value(); }};
  }
  throw std::invalid_argument("makeLinerOutput: unknown output");
}

}  // namespace pistondyn::plugin
