#include "pistondyn/lubrication/PatirChengFlowFactors.h"

#include <cmath>
#include <stdexcept>

#include "PatirChengRows.h"
#include "pistondyn/common/Validation.h"

namespace pistondyn::lubrication {

namespace {

namespace pcd = patir_cheng::detail;

constexpr const char* kWhere = "PatirChengFlowFactors";

void checkRoughness(const char* name, double rq_m) {
  if (!std::isfinite(rq_m) || rq_m < 0.0)
    common::throwInvalidValue(kWhere, common::message("roughness ", name), rq_m, "m",
                              "finite and >= 0");
}

void checkPeklenik(const char* name, double gamma) {
  if (common::notPositiveFinite(gamma))
    common::throwNotPositiveFinite(gamma, kWhere, common::message("Peklenik number ", name), "");
}

// Equal brackets give bit-identical blends (same rows, same weight), so calcFactors
// evaluates the row functions once and reuses the value.
bool sameBracket(const pcd::GammaBracket& a, const pcd::GammaBracket& b) {
  return a.lo == b.lo && a.hi == b.hi && a.wHi == b.wHi;
}

}  // namespace

PatirChengFlowFactors::PatirChengFlowFactors(const PatirChengParameters& parameters)
    : parameters_(parameters) {
  checkRoughness("rq1_m", parameters.rq1_m);
  checkRoughness("rq2_m", parameters.rq2_m);
  checkPeklenik("peklenik1", parameters.peklenik1);
  checkPeklenik("peklenik2", parameters.peklenik2);
  if (!(parameters.phiFCutoff > 0.0 && parameters.phiFCutoff <= patir_cheng::kMaxPhiFCutoff)) {
    common::throwInvalidValue(
        kWhere, "phiFCutoff", parameters.phiFCutoff, "",
        common::message("in (0, ", patir_cheng::kMaxPhiFCutoff, "] (default 1/300)"));
  }
  if (parameters.peklenikComposite.has_value()) {
    checkPeklenik("peklenikComposite", *parameters.peklenikComposite);
    gammaComposite_ = *parameters.peklenikComposite;
  } else {
    if (parameters.peklenik1 != parameters.peklenik2) {
      common::throwInvalidArgument(
          kWhere,
          common::message("peklenikComposite must be given when peklenik1 (", parameters.peklenik1,
                          ") and peklenik2 (", parameters.peklenik2, ") differ"));
    }
    gammaComposite_ = parameters.peklenik1;
  }

  // hypot and ratios of Rq to sigma: Rq^2 would underflow for Rq < 1e-162 (sigma = 0,
  // i.e. silently smooth) and overflow for Rq > 1e154.
  sigma_m_ = std::hypot(parameters.rq1_m, parameters.rq2_m);
  if (sigma_m_ > 0.0) {
    const double ratio1 = parameters.rq1_m / sigma_m_;
    const double ratio2 = parameters.rq2_m / sigma_m_;
    varianceRatio1_ = ratio1 * ratio1;
    varianceRatio2_ = ratio2 * ratio2;
  }

  const pcd::GammaBracket sliding = pcd::bracketGamma(gammaComposite_);
  const pcd::GammaBracket cross = pcd::bracketGamma(1.0 / gammaComposite_);
  const pcd::GammaBracket surface1 = pcd::bracketGamma(parameters.peklenik1);
  const pcd::GammaBracket surface2 = pcd::bracketGamma(parameters.peklenik2);
  crossEqualsSliding_ = sameBracket(cross, sliding);
  bracket2EqualsBracket1_ = sameBracket(surface2, surface1);
  // Stored as plain ints and doubles (the header does not see PatirChengRows.h).
  auto store = [](const pcd::GammaBracket& b) { return RowBracket{b.lo, b.hi, b.wHi}; };
  bracketSliding_ = store(sliding);
  bracketCross_ = store(cross);
  bracket1_ = store(surface1);
  bracket2_ = store(surface2);
}

NodeFlowFactors PatirChengFlowFactors::calcFactors(double h_m) const {
  if (common::notPositiveFinite(h_m))
    common::throwNotPositiveFinite(h_m, "PatirChengFlowFactors::calcFactors", "gap h_m", "m");
  NodeFlowFactors f;
  if (sigma_m_ == 0.0) {
    f.expectedGap_m = h_m;  // smooth surfaces: plain Reynolds
    return f;
  }
  const double H = h_m / sigma_m_;

  // blend(b, row): one row function blended over a stored bracket.
  auto blend = [H](const RowBracket& b, auto row) {
    return pcd::blend(pcd::GammaBracket{b.lo, b.hi, b.wHi}, H, row);
  };
  if (parameters_.pressureFlowGammaModel == patir_cheng::PressureFlowGammaModel::kDesignNoteFit) {
    f.phiPressureSliding = pcd::pressureFlowDesignNoteFit(H, gammaComposite_);
    f.phiPressureCross = pcd::pressureFlowDesignNoteFit(H, 1.0 / gammaComposite_);
  } else {
    f.phiPressureSliding = blend(bracketSliding_, pcd::pressureFlowRow);
    f.phiPressureCross =
        crossEqualsSliding_ ? f.phiPressureSliding : blend(bracketCross_, pcd::pressureFlowRow);
  }

  // Each term only where its surface is rough: a smooth surface contributes nothing and
  // skipping it saves the transcendental calls.
  // With gamma1 = gamma2 (the default) both surfaces share one blend, evaluated once.
  double phiS = 0.0;
  double phiFs = 0.0;
  double shear1 = 0.0;
  double shearFs1 = 0.0;
  if (varianceRatio1_ > 0.0) {
    shear1 = blend(bracket1_, pcd::shearFlowRow);
    shearFs1 = blend(bracket1_, pcd::shearStressFsRow);
    phiS += varianceRatio1_ * shear1;
    phiFs += varianceRatio1_ * shearFs1;
  }
  if (varianceRatio2_ > 0.0) {
    const bool reuse = bracket2EqualsBracket1_ && varianceRatio1_ > 0.0;
    const double shear2 = reuse ? shear1 : blend(bracket2_, pcd::shearFlowRow);
    const double shearFs2 = reuse ? shearFs1 : blend(bracket2_, pcd::shearStressFsRow);
    phiS -= varianceRatio2_ * shear2;
    phiFs -= varianceRatio2_ * shearFs2;
  }
  f.sigmaPhiS_m = sigma_m_ * phiS;
  f.phiFs = phiFs;

  const ExpectedGap gap = calcExpectedGap(h_m, sigma_m_, parameters_.expectedGapForm);
  f.expectedGap_m = gap.value_m;
  f.dExpectedGap_dh = gap.dValue_dh;

  f.phiF = patir_cheng::calcShearStressFactorF(H, parameters_.phiFCutoff);
  f.phiFp = blend(bracketSliding_, pcd::shearStressFpRow);
  return f;
}

}  // namespace pistondyn::lubrication
