#include "pistondyn/skirt/ThermalGrowth.h"

#include <string>

#include "Checks.h"
#include "OutputChecks.h"
#include "pistondyn/common/NodalField.h"

namespace pistondyn::skirt {

namespace {

void checkTemperatures(const char* where, const char* name,
                       const Eigen::Ref<const Eigen::VectorXd>& t) {
  for (Eigen::Index k = 0; k < t.size(); ++k)
    detail::requireAboveAbsoluteZero(where, detail::indexed(name, k), t[k]);
}

void checkExpansion(const char* where, double alpha) {
  if (!(std::isfinite(alpha) && alpha >= 0.0))
    detail::fail(where, detail::named("expansionCoefficient_perK", alpha, "1/K") +
                            " must be non-negative and finite (it must be set when a "
                            "temperature field is given)");
}

}  // namespace

PistonThermalGrowth::PistonThermalGrowth(const PistonThermalParameters& p,
                                         const SkirtSideGrid& grid,
                                         double referenceTemperature_degC)
    : tRef_(referenceTemperature_degC) {
  const char* where = "PistonThermalParameters";
  detail::requireAboveAbsoluteZero("GapAssemblyParameters", "referenceTemperature_degC",
                                   referenceTemperature_degC);
  const bool hasTable = p.height_m.size() > 0 || p.temperature_degC.size() > 0;
  const bool hasNodal = p.nodalTemperature_degC.size() > 0;
  if (!hasTable && !hasNodal)
    return;
  checkExpansion(where, p.expansionCoefficient_perK);
  radiusAlpha_m_ = grid.getRadius_m() * p.expansionCoefficient_perK;
  active_ = true;
  if (hasTable) {
    table_ = InterpolatedTable(p.height_m, p.temperature_degC, p.interpolation, where, "height_m",
                               "m", "temperature_degC", "degC");
    checkTemperatures(where, "temperature_degC", p.temperature_degC);
  }
  if (hasNodal) {
    detail::requireNodalSize(where, "nodalTemperature_degC", p.nodalTemperature_degC.size(),
                             grid.nodeCount());
    checkTemperatures(where, "nodalTemperature_degC", p.nodalTemperature_degC.matrix());
    nodal_ = p.nodalTemperature_degC;
  }
}

double PistonThermalGrowth::calcGapFromTable_m(double y_m) const {
  if (table_.empty())
    return 0.0;
  return -radiusAlpha_m_ * (table_.value(y_m) - tRef_);
}

void PistonThermalGrowth::calcField(const SkirtSideGrid& grid,
                                    Eigen::Ref<Eigen::ArrayXd> gap_m) const {
  detail::requireNodalSize("PistonThermalGrowth::calcField", "gap_m", gap_m.size(),
                           grid.nodeCount());
  if (!active_) {
    gap_m.setZero();
    return;
  }
  if (isNodal()) {
    gap_m = -radiusAlpha_m_ * (nodal_ - tRef_);
    return;
  }
  const Eigen::VectorXd& y = grid.getYNodes_m();
  auto rows = common::asGrid(gap_m, grid.nPhi(), grid.nY());
  for (int j = 0; j < grid.nY(); ++j)
    rows.col(j).setConstant(calcGapFromTable_m(y[j]));
}

LinerThermalGrowth::LinerThermalGrowth(const LinerThermalParameters& p, const SkirtSideGrid& grid,
                                       double linerTopHeight_m, double referenceTemperature_degC)
    : tRef_(referenceTemperature_degC),
      linerTop_m_(linerTopHeight_m),
      nPhi_(grid.nPhi()),
      y_m_(grid.getYNodes_m()) {
  const char* where = "LinerThermalParameters";
  detail::requireAboveAbsoluteZero("GapAssemblyParameters", "referenceTemperature_degC",
                                   referenceTemperature_degC);
  if (p.depth_m.size() == 0 && p.temperature_degC.size() == 0)
    return;
  detail::requireFinite("GapAssemblyParameters", "linerTopHeight_m", linerTopHeight_m, "m");
  checkExpansion(where, p.expansionCoefficient_perK);
  table_ = InterpolatedTable(p.depth_m, p.temperature_degC, p.interpolation, where, "depth_m", "m",
                             "temperature_degC", "degC");
  checkTemperatures(where, "temperature_degC", p.temperature_degC);
  radiusAlpha_m_ = grid.getRadius_m() * p.expansionCoefficient_perK;
  active_ = true;
}

LinerThermalSample LinerThermalGrowth::calcSample(double boreHeight_m) const {
  if (!active_)
    return {};
  const TableSample t = table_.evaluate(linerTop_m_ - boreHeight_m);
  // d/dY = -d/d(depth)
  return {radiusAlpha_m_ * (t.value - tRef_), -radiusAlpha_m_ * t.derivative};
}

void LinerThermalGrowth::calcField(double pinHeight_m, double axialVelocity_mps,
                                   Eigen::Ref<Eigen::ArrayXd> gap_m,
                                   Eigen::Ref<Eigen::ArrayXd> gapRate_mps) const {
  const char* fn = "LinerThermalGrowth::calcField";
  const Eigen::Index n = Eigen::Index(nPhi_) * y_m_.size();
  detail::requireNodalSize(fn, "gap_m", gap_m.size(), n);
  detail::requireNodalSize(fn, "gapRate_mps", gapRate_mps.size(), n);
  if (!active_) {
    gap_m.setZero();
    gapRate_mps.setZero();
    return;
  }
  auto gapRows = common::asGrid(gap_m, nPhi_, static_cast<int>(y_m_.size()));
  auto rateRows = common::asGrid(gapRate_mps, nPhi_, static_cast<int>(y_m_.size()));
  for (Eigen::Index j = 0; j < y_m_.size(); ++j) {
    const LinerThermalSample s = calcSample(pinHeight_m + y_m_[j]);
    gapRows.col(j).setConstant(s.gap_m);
    rateRows.col(j).setConstant(s.dGap_dBoreHeight * axialVelocity_mps);
  }
}

}  // namespace pistondyn::skirt
