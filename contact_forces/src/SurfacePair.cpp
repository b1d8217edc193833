#include "pistondyn/contact_forces/SurfacePair.h"

#include <cmath>
#include <string>

#include "pistondyn/common/Validation.h"

namespace pistondyn::contact_forces {

void validateMaterial(const ElasticMaterial& material, const char* where, const char* argName) {
  const std::string name(argName);
  common::requirePositiveFinite(material.youngsModulus_Pa, where, name + ".youngsModulus_Pa", "Pa");
  if (!(material.poissonRatio > -1.0 && material.poissonRatio < 0.5)) {
    common::throwInvalidValue(where, name + ".poissonRatio", material.poissonRatio, "",
                              "in the open interval (-1, 0.5)");
  }
}

double compositeRoughness_m(double rq1_m, double rq2_m) {
  common::requireNonNegativeFinite(rq1_m, "compositeRoughness_m", "rq1_m", "m");
  common::requireNonNegativeFinite(rq2_m, "compositeRoughness_m", "rq2_m", "m");
  const double sigma = std::hypot(rq1_m, rq2_m);
  if (!(sigma > 0.0)) {
    common::throwInvalidValue("compositeRoughness_m", "sqrt(rq1_m^2 + rq2_m^2)", sigma, "m",
                              "positive (at least one surface must be rough)");
  }
  return sigma;
}

namespace {
double complianceSum(const ElasticMaterial& surface1, const ElasticMaterial& surface2,
                     const char* where) {
  validateMaterial(surface1, where, "surface1");
  validateMaterial(surface2, where, "surface2");
  return (1.0 - surface1.poissonRatio * surface1.poissonRatio) / surface1.youngsModulus_Pa +
         (1.0 - surface2.poissonRatio * surface2.poissonRatio) / surface2.youngsModulus_Pa;
}
}  // namespace

double reducedModulusHertz_Pa(const ElasticMaterial& surface1, const ElasticMaterial& surface2) {
  return 1.0 / complianceSum(surface1, surface2, "reducedModulusHertz_Pa");
}

double effectiveModulus_Pa(const ElasticMaterial& surface1, const ElasticMaterial& surface2) {
  return 2.0 / complianceSum(surface1, surface2, "effectiveModulus_Pa");
}

}  // namespace pistondyn::contact_forces
