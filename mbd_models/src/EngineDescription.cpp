#include "pistondyn/mbd_models/EngineDescription.h"

#include <cmath>
#include <stdexcept>

#include "pistondyn/common/Validation.h"

namespace pistondyn::mbd {
namespace {

void require(bool ok, const std::string& member, double value, const char* expected) {
  if (ok)
    return;
  common::throwInvalidArgument("EngineDescription",
                               common::message(member, " = ", value, " ", expected));
}

void requirePositive(double v, const std::string& member) {
  require(std::isfinite(v) && v > 0.0, member, v, "must be positive and finite");
}

void requireNonNegative(double v, const std::string& member) {
  require(std::isfinite(v) && v >= 0.0, member, v, "must be non-negative and finite");
}

void requireFinite(double v, const std::string& member) {
  require(std::isfinite(v), member, v, "must be finite");
}

void validateBody(const PlanarMassProperties& b, const std::string& body) {
  requirePositive(b.mass_kg, body + ".mass_kg");
  requireFinite(b.comX_m, body + ".comX_m");
  requireFinite(b.comY_m, body + ".comY_m");
  requireNonNegative(b.inertiaZZ_kgm2, body + ".inertiaZZ_kgm2");
}

}  // namespace

void validate(const EngineDescription& engine) {
  const CrankTrainGeometry& g = engine.geometry;
  requirePositive(g.crankRadius_m, "geometry.crankRadius_m");
  requirePositive(g.conrodLength_m, "geometry.conrodLength_m");
  requireFinite(g.pinOffset_m, "geometry.pinOffset_m");
  requireFinite(g.crankOffset_m, "geometry.crankOffset_m");
  const double e = std::abs(g.pinOffset_m + g.crankOffset_m);
  // The rod must reach the pin line at every crank angle: L - r > |e| (strictly, so
  // that the rod never becomes perpendicular to the cylinder axis).
  require(g.conrodLength_m > g.crankRadius_m + e, "geometry.conrodLength_m", g.conrodLength_m,
          "must exceed crank radius + |pin offset + crank offset| (the rod is too short)");
  require(std::isfinite(g.compressionRatio) && g.compressionRatio > 1.0,
          "geometry.compressionRatio", g.compressionRatio, "must be greater than 1");

  const PistonGeometry& p = engine.piston;
  requirePositive(p.bore_m, "piston.bore_m");
  requirePositive(p.compressionHeight_m, "piston.compressionHeight_m");
  requirePositive(p.skirtLength_m, "piston.skirtLength_m");
  requireFinite(p.skirtTopAbovePin_m, "piston.skirtTopAbovePin_m");
  require(p.skirtTopAbovePin_m <= p.compressionHeight_m, "piston.skirtTopAbovePin_m",
          p.skirtTopAbovePin_m, "must not be above the crown (compressionHeight_m)");

  validateBody(engine.mass.crank, "mass.crank");
  validateBody(engine.mass.conrod, "mass.conrod");
  validateBody(engine.mass.pin, "mass.pin");
  validateBody(engine.mass.piston, "mass.piston");
  require(engine.mass.pin.comX_m == 0.0, "mass.pin.comX_m", engine.mass.pin.comX_m,
          "must be 0 (pin COM on its axis)");
  require(engine.mass.pin.comY_m == 0.0, "mass.pin.comY_m", engine.mass.pin.comY_m,
          "must be 0 (pin COM on its axis)");

  requirePositive(engine.drive.speed_radps, "drive.speed_radps");
  requireNonNegative(engine.drive.flywheelInertia_kgm2, "drive.flywheelInertia_kgm2");
  requireFinite(engine.drive.loadTorque_Nm, "drive.loadTorque_Nm");
  requireNonNegative(engine.gravity_mps2, "gravity_mps2");
}

}  // namespace pistondyn::mbd
