#include "pistondyn/lubrication/PatirChengExpectedGap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pistondyn/common/Validation.h"

namespace pistondyn::lubrication {

namespace {

constexpr double kInvSqrt2 = 0.70710678118654752440;
constexpr double kInvSqrt2Pi = 0.39894228040143267794;

ExpectedGap gaussian(double h, double sigma) {
  const double H = h / sigma;
  // erfc keeps the lower tail accurate; Phi(H) = erfc(-H / sqrt 2) / 2.
  const double cdf = 0.5 * std::erfc(-H * kInvSqrt2);
  const double pdf = kInvSqrt2Pi * std::exp(-0.5 * H * H);
  ExpectedGap g;
  // For very negative H both terms are ~pdf/|H| and cancel; the result is then below
  // 1e-16 sigma and is clamped at 0 rather than allowed to go slightly negative.
  g.value_m = std::max(0.0, sigma * (H * cdf + pdf));
  g.dValue_dh = cdf;
  return g;
}

ExpectedGap polynomial(double h, double sigma) {
  const double z = h / (3.0 * sigma);
  ExpectedGap g;
  if (z >= 1.0) {
    g.value_m = h;
    g.dValue_dh = 1.0;
    return g;
  }
  if (z <= -1.0) {
    g.value_m = 0.0;
    g.dValue_dh = 0.0;
    return g;
  }
  const double z2 = z * z;
  const double value = 35.0 + z * (128.0 + z * (140.0 + z2 * (-70.0 + z2 * (28.0 - 5.0 * z2))));
  const double slope = 128.0 + z * (280.0 + z2 * (-280.0 + z2 * (168.0 - 40.0 * z2)));
  g.value_m = sigma * 3.0 / 256.0 * value;
  g.dValue_dh = slope / 256.0;
  return g;
}

}  // namespace

ExpectedGap calcExpectedGap(double h_m, double sigma_m, ExpectedGapForm form) {
  common::requireFinite(h_m, "calcExpectedGap", "gap h_m", "m");
  if (!std::isfinite(sigma_m) || sigma_m < 0.0)
    common::throwInvalidValue("calcExpectedGap", "composite roughness sigma_m", sigma_m, "m",
                              "finite and >= 0");
  if (sigma_m > 0.0) {
    switch (form) {
      case ExpectedGapForm::kGaussian:
        return gaussian(h_m, sigma_m);
      case ExpectedGapForm::kPatirChengPolynomial:
        return polynomial(h_m, sigma_m);
      case ExpectedGapForm::kNominal:
        break;
    }
  }
  // Smooth surfaces, or no roughness correction wanted: the gap itself where open.
  ExpectedGap g;
  g.value_m = std::max(h_m, 0.0);
  g.dValue_dh = h_m > 0.0 ? 1.0 : 0.0;
  return g;
}

}  // namespace pistondyn::lubrication
