#include "pistondyn/skirt/GapAssembly.h"

#include "Checks.h"
#include "OutputChecks.h"
#include "pistondyn/skirt/RigidGap.h"

namespace pistondyn::skirt {

namespace {

const char* const kWhere = "GapAssemblyParameters";

double checkedClearance(const GapAssemblyParameters& p) {
  detail::requireFinite(kWhere, "coldRadialClearance_m", p.coldRadialClearance_m, "m");
  return p.coldRadialClearance_m;
}

}  // namespace

// Every term's data is checked, switched on or not: bad data is reported where it is given.
GapAssembly::GapAssembly(const SkirtSideGrid& grid, const GapAssemblyParameters& parameters)
    : grid_(grid),
      switches_(parameters.terms),
      c0_(checkedClearance(parameters)),
      profile_(parameters.skirtProfile, grid_),
      linerShape_(parameters.linerShape, grid_, parameters.linerTopHeight_m),
      pistonThermalGrowth_(parameters.pistonThermal, grid_, parameters.referenceTemperature_degC),
      linerThermal_(parameters.linerThermal, grid_, parameters.linerTopHeight_m,
                    parameters.referenceTemperature_degC),
      skirtProfile_(grid_.nodeCount()),
      pistonThermal_(grid_.nodeCount()),
      hot_(calcHotRunningClearance(grid_, parameters)) {
  profile_.calcField(grid_, skirtProfile_);
  pistonThermalGrowth_.calcField(grid_, pistonThermal_);
  // The fixed part of the skirt surface's slope: its profile and thermal growth (switched on).
  Eigen::ArrayXd fixedSkirt = Eigen::ArrayXd::Zero(grid_.nodeCount());
  if (switches_.skirtProfile)
    fixedSkirt += skirtProfile_;
  if (switches_.pistonThermal)
    fixedSkirt += pistonThermal_;
  grid_.calcAxialDerivative(fixedSkirt, fixedSkirtSlope_);
  requireNonNegativeHotClearance(hot_, grid_);
}

GapFields GapAssembly::makeFields() const {
  const Eigen::Index n = grid_.nodeCount();
  GapFields f;
  for (Eigen::ArrayXd* a :
       {&f.gap_m, &f.gapRate_mps, &f.rigid_m, &f.skirtProfile_m, &f.linerShape_m,
        &f.pistonThermal_m, &f.linerThermal_m, &f.pistonElastic_m, &f.linerElastic_m,
        &f.rigidRate_mps, &f.linerShapeRate_mps, &f.linerThermalRate_mps, &f.pistonElasticRate_mps,
        &f.linerElasticRate_mps, &f.skirtGapSlope})
    a->setZero(n);
  f.dGap_dPose.setZero(n, 3);
  f.squeezeBasis.setZero(n, 3);
  return f;
}

void GapAssembly::calc(const PistonPose& pose, const PistonPoseRate& rate, double pinHeight_m,
                       double axialVelocity_mps, GapFields& out) const {
  const char* fn = "GapAssembly::calc";
  detail::requirePose(fn, pose, rate);
  detail::requireFinite(fn, "pinHeight_m", pinHeight_m, "m");
  detail::requireFinite(fn, "axialVelocity_mps", axialVelocity_mps, "m/s");
  const Eigen::Index n = grid_.nodeCount();
  const auto size = [&](const char* name, const Eigen::ArrayXd& a) {
    detail::requireNodalSize(fn, name, a.size(), n);
  };
  size("out.gap_m", out.gap_m);
  size("out.gapRate_mps", out.gapRate_mps);
  size("out.rigid_m", out.rigid_m);
  size("out.skirtProfile_m", out.skirtProfile_m);
  size("out.linerShape_m", out.linerShape_m);
  size("out.pistonThermal_m", out.pistonThermal_m);
  size("out.linerThermal_m", out.linerThermal_m);
  size("out.pistonElastic_m", out.pistonElastic_m);
  size("out.linerElastic_m", out.linerElastic_m);
  size("out.rigidRate_mps", out.rigidRate_mps);
  size("out.linerShapeRate_mps", out.linerShapeRate_mps);
  size("out.linerThermalRate_mps", out.linerThermalRate_mps);
  size("out.pistonElasticRate_mps", out.pistonElasticRate_mps);
  size("out.linerElasticRate_mps", out.linerElasticRate_mps);
  size("out.skirtGapSlope", out.skirtGapSlope);
  detail::requireNodalMatrix(fn, "out.dGap_dPose", out.dGap_dPose.rows(), out.dGap_dPose.cols(), n);
  detail::requireNodalMatrix(fn, "out.squeezeBasis", out.squeezeBasis.rows(),
                             out.squeezeBasis.cols(), n);

  if (switches_.rigid) {
    calcRigidGap(grid_, c0_, pose, rate, out.rigid_m, out.rigidRate_mps, out.dGap_dPose,
                 out.squeezeBasis);
  } else {
    out.rigid_m.setZero();
    out.rigidRate_mps.setZero();
    out.dGap_dPose.setZero();
    out.squeezeBasis.setZero();
  }
  if (switches_.skirtProfile)
    out.skirtProfile_m = skirtProfile_;
  else
    out.skirtProfile_m.setZero();
  if (switches_.linerShape) {
    linerShape_.calcField(pinHeight_m, axialVelocity_mps, out.linerShape_m, out.linerShapeRate_mps);
  } else {
    out.linerShape_m.setZero();
    out.linerShapeRate_mps.setZero();
  }
  if (switches_.pistonThermal)
    out.pistonThermal_m = pistonThermal_;
  else
    out.pistonThermal_m.setZero();
  if (switches_.linerThermal) {
    linerThermal_.calcField(pinHeight_m, axialVelocity_mps, out.linerThermal_m,
                            out.linerThermalRate_mps);
  } else {
    out.linerThermal_m.setZero();
    out.linerThermalRate_mps.setZero();
  }

  out.gap_m = out.rigid_m + out.skirtProfile_m + out.linerShape_m + out.pistonThermal_m +
              out.linerThermal_m;
  out.gapRate_mps = out.rigidRate_mps + out.linerShapeRate_mps + out.linerThermalRate_mps;
  if (switches_.pistonElastic) {
    out.gap_m += out.pistonElastic_m;
    out.gapRate_mps += out.pistonElasticRate_mps;
    grid_.calcAxialDerivative(out.pistonElastic_m, out.skirtGapSlope);
    out.skirtGapSlope += fixedSkirtSlope_;
  } else {
    out.skirtGapSlope = fixedSkirtSlope_;
  }
  if (switches_.linerElastic) {
    out.gap_m += out.linerElastic_m;
    out.gapRate_mps += out.linerElasticRate_mps;
  }
}

}  // namespace pistondyn::skirt
