// Patir & Cheng flow factors and shear-stress factors: the tables, where each constant
// comes from, and what is done outside the papers' range of validity.
//
// Sources of the constants (see PatirChengFactors.h for the two papers [PC78], [PC79]).
// The papers themselves were not available to us; each table below was cross-checked
// against independent secondary sources:
//   [FE]  foam-extend 4.x, flowFactorsPatirCheng.C (lubricated-contact model, GPL):
//         full rows of [PC78] Table 1 (C, r), of the Phi_s table (A1, a1, a2, a3, A2) and
//         of the Phi_fs table (A3, a4, a5, a6) for all seven gamma.
//   [RB]  R. Boman, EHD code, github.com/rboman/progs apps/EHD/EHD/ehd_flow_cisail.c and
//         ehd_flow_factors.c: gamma = 1 rows of Phi_fs (11.10, 2.31, 2.38, 0.11) and of
//         phi_fp (1.40, 0.66); phi_f closed form with ln(300 (z + 1)), i.e. eps* = 1/300;
//         and the continuous-gamma fits C(gamma), r(gamma) of the pressure flow factor
//         that docs/DESIGN.md §4 quotes (plus a fit of A2: 1.0766 - 0.37758 ln gamma,
//         within 0.05 of the tabulated A2).
//   [DN]  docs/DESIGN.md §4: gamma = 1 rows of phi_x, Phi_s, Phi_fs, phi_fp.
// All three agree digit for digit wherever they overlap. The phi_fp rows for gamma != 1
// could NOT be cross-checked: no second source was found (searched again during the
// module review: public code, docs and pages; only the gamma = 1 row turns up, in the two
// versions of [RB]); they are our transcription of
// the [PC79] phi_fp table and must be verified against the paper before anisotropic
// phi_fp results are relied on (isotropic gamma = 1 is confirmed by [RB] and [DN]).
// The closed form of phi_f was re-derived symbolically from its defining integral (see
// PatirChengFactors.h) and is checked against quadrature in the tests.

#include "pistondyn/lubrication/PatirChengFactors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "PatirChengRows.h"
#include "pistondyn/common/Validation.h"

namespace pistondyn::lubrication::patir_cheng {

namespace {

constexpr int kRows = kTabulatedGammaCount;

// ---------------------------------------------------------------------------------
// [PC78] Table 1, pressure flow factor. gamma <= 1: phi = 1 - C exp(-r H);
// gamma > 1: phi = 1 + C H^-r. Lower validity bound Hmin as printed in the paper's range
// column (1, 1, 0.75, 0.5, 0.5, 0.5, 0.5); [FE] uses H >= 1 for all gamma < 1 and 0.5
// otherwise, which agrees except for gamma = 1/3 (the two choices differ there by less
// than 0.01 in phi, see the C1 continuation below).
struct PressureFlowRow {
  double C;
  double r;
  double Hmin;
};
constexpr std::array<PressureFlowRow, kRows> kPressureFlow = {{
    {1.48, 0.42, 1.0},   // gamma = 1/9  [FE]
    {1.38, 0.42, 1.0},   // gamma = 1/6  [FE]
    {1.18, 0.42, 0.75},  // gamma = 1/3  [FE]
    {0.90, 0.56, 0.5},   // gamma = 1    [FE], [DN]
    {0.225, 1.5, 0.5},   // gamma = 3    [FE]
    {0.520, 1.5, 0.5},   // gamma = 6    [FE]
    {0.870, 1.5, 0.5},   // gamma = 9    [FE]
}};
constexpr int kFirstPowerRow = 4;  // rows with gamma > 1 use 1 + C H^-r

// [PC79] shear flow factor of one surface: A1 H^a1 exp(-a2 H + a3 H^2), H <= 5;
// A2 exp(-0.25 H), H > 5. Valid H > 0.5 in the paper.
struct ShearFlowRow {
  double A1;
  double a1;
  double a2;
  double a3;
  double A2;
};
constexpr std::array<ShearFlowRow, kRows> kShearFlow = {{
    {2.046, 1.12, 0.78, 0.03, 1.856},  // gamma = 1/9  [FE]
    {1.962, 1.08, 0.77, 0.03, 1.754},  // gamma = 1/6  [FE]
    {1.858, 1.01, 0.76, 0.03, 1.561},  // gamma = 1/3  [FE]
    {1.899, 0.98, 0.92, 0.05, 1.126},  // gamma = 1    [FE], [DN]
    {1.560, 0.85, 1.13, 0.08, 0.556},  // gamma = 3    [FE]
    {1.290, 0.62, 1.09, 0.08, 0.388},  // gamma = 6    [FE]
    {1.011, 0.54, 1.07, 0.08, 0.295},  // gamma = 9    [FE]
}};
constexpr double kShearFlowBranchH = 5.0;
constexpr double kShearFlowTailRate = 0.25;

// [PC79] roughness shear-stress factor of one surface: A3 H^a4 exp(-a5 H + a6 H^2) for
// 0.5 < H < 7, zero for H > 7.
struct ShearStressFsRow {
  double A3;
  double a4;
  double a5;
  double a6;
};
constexpr std::array<ShearStressFsRow, kRows> kShearStressFs = {{
    {14.1, 2.45, 2.30, 0.10},  // gamma = 1/9  [FE]
    {13.4, 2.42, 2.30, 0.10},  // gamma = 1/6  [FE]
    {12.3, 2.32, 2.30, 0.10},  // gamma = 1/3  [FE]
    {11.1, 2.31, 2.38, 0.11},  // gamma = 1    [FE], [RB], [DN]
    {9.8, 2.25, 2.80, 0.18},   // gamma = 3    [FE]
    {10.1, 2.25, 2.90, 0.18},  // gamma = 6    [FE]
    {8.7, 2.15, 2.97, 0.18},   // gamma = 9    [FE]
}};
constexpr double kShearStressFsCutoffH = 7.0;
// Departure from [PC79] (which cuts Phi_fs to 0 at H = 7, a jump of 0.004 to 0.023, i.e.
// up to 2.2 % of phi_f ~ 1.02 there): the fit is multiplied by the C1 step
// S(x) = 1 - 3 x^2 + 2 x^3, x = (H - 6.5) / 0.5, over [6.5, 7], so Phi_fs and its slope
// are continuous (no discontinuity for the integrator; docs/DESIGN.md §4).
constexpr double kShearStressFsTaperStartH = 6.5;

// [PC79] Poiseuille shear-stress factor: 1 - D exp(-s H), H > 0.5.
struct ShearStressFpRow {
  double D;
  double s;
};
constexpr std::array<ShearStressFpRow, kRows> kShearStressFp = {{
    {1.51, 0.52},  // gamma = 1/9  NOT cross-checked (see top of file)
    {1.51, 0.54},  // gamma = 1/6  NOT cross-checked
    {1.47, 0.58},  // gamma = 1/3  NOT cross-checked
    {1.40, 0.66},  // gamma = 1    [RB], [DN]
    {0.98, 0.79},  // gamma = 3    NOT cross-checked
    {0.97, 0.91},  // gamma = 6    NOT cross-checked
    {0.73, 0.91},  // gamma = 9    NOT cross-checked
}};
constexpr double kShearStressFpHmin = 0.5;

// phi_f cut-off: the local film is taken as at least eps = eps* * 3 sigma (0.01 sigma
// for the default eps* = 1/300 of [RB], ln(300 (z + 1))) where asperities touch. The
// H <= 3 branch is the only one with contacts, so only it carries eps* (a parameter:
// kDefaultPhiFCutoff, PatirChengFactors.h).

// Smallest value an exponential-type fit (1 - C exp(-r H)) is used down to; below it
// (or below the paper's bound, whichever H is larger) the C1 power-law continuation
// takes over. 0.02 leaves every [PC78] row untouched over its printed range (the lowest
// value there is 0.0275, gamma = 1/9 at H = 1) and stops the phi_fp fits before they
// cross zero (at H = 0.79, 0.76, 0.66, 0.51 for gamma = 1/9, 1/6, 1/3, 1).
constexpr double kExpFitFloor = 0.02;
// The continuation's limit as H -> 0 (kPressureFactorFloor, PatirChengFactors.h).
constexpr double kContinuationFloor = kPressureFactorFloor;
static_assert(kContinuationFloor < kExpFitFloor, "the continuation starts above its floor");

// 1 - C exp(-r H), used from Hlo = max(Hmin, H where the fit equals kExpFitFloor);
// below Hlo: f0 + (phi(Hlo) - f0) (H / Hlo)^k, f0 = kContinuationFloor, with
// k = Hlo phi'(Hlo) / (phi(Hlo) - f0), which matches value and slope at Hlo (C1), is
// increasing, and tends to the floor f0 > 0 as H -> 0.
// The fit rises with H, so "H >= Hlo" is "H >= Hmin and fit(H) >= floor"; testing it that
// way keeps the logarithm for Hlo off the common path.
double exponentialFitWithContinuation(double C, double r, double Hmin, double H) {
  if (H >= Hmin) {
    const double phi = 1.0 - C * std::exp(-r * H);
    if (phi >= kExpFitFloor) {
      return phi;
    }
  }
  double Hlo = Hmin;
  if (C > 1.0 - kExpFitFloor) {
    Hlo = std::max(Hmin, std::log(C / (1.0 - kExpFitFloor)) / r);
  }
  const double e = std::exp(-r * Hlo);
  const double aboveFloor = 1.0 - C * e - kContinuationFloor;  // phi(Hlo) - f0 > 0
  const double slopeLo = C * r * e;
  const double k = Hlo * slopeLo / aboveFloor;
  return kContinuationFloor + aboveFloor * std::pow(H / Hlo, k);
}

// 1 + C H^-r, held at its value at Hmin below Hmin (it would grow without bound).
double powerFitHeld(double C, double r, double Hmin, double H) {
  return 1.0 + C * std::pow(std::max(H, Hmin), -r);
}

// Throws std::invalid_argument unless value is positive and finite.
void checkPositiveFinite(const char* function, const char* what, double value) {
  if (common::notPositiveFinite(value))
    common::throwNotPositiveFinite(value, common::message("patir_cheng::", function), what, "");
}

void checkH(const char* function, double H) {
  checkPositiveFinite(function, "film parameter H", H);
}

void checkGamma(const char* function, double gamma) {
  checkPositiveFinite(function, "Peklenik number gamma", gamma);
}

}  // namespace

namespace detail {

GammaBracket bracketGamma(double gamma) {
  GammaBracket b;
  if (gamma <= kTabulatedGammas[0]) {
    b.lo = b.hi = 0;
    return b;
  }
  if (gamma >= kTabulatedGammas[kRows - 1]) {
    b.lo = b.hi = kRows - 1;
    return b;
  }
  for (int i = 0; i + 1 < kRows; ++i) {
    const double g0 = kTabulatedGammas[i];
    const double g1 = kTabulatedGammas[i + 1];
    if (gamma == g0) {
      b.lo = b.hi = i;
      return b;
    }
    if (gamma < g1) {
      b.lo = i;
      b.hi = i + 1;
      b.wHi = std::log(gamma / g0) / std::log(g1 / g0);
      return b;
    }
  }
  b.lo = b.hi = kRows - 1;  // gamma == 9 exactly is caught above; unreachable
  return b;
}

double pressureFlowRow(int row, double H) {
  const PressureFlowRow& c = kPressureFlow[row];
  if (row >= kFirstPowerRow) {
    return powerFitHeld(c.C, c.r, c.Hmin, H);
  }
  return exponentialFitWithContinuation(c.C, c.r, c.Hmin, H);
}

double shearFlowRow(int row, double H) {
  const ShearFlowRow& c = kShearFlow[row];
  if (H > kShearFlowBranchH) {
    return c.A2 * std::exp(-kShearFlowTailRate * H);
  }
  return c.A1 * std::pow(H, c.a1) * std::exp(H * (c.a3 * H - c.a2));
}

double shearStressFsRow(int row, double H) {
  if (H >= kShearStressFsCutoffH) {
    return 0.0;
  }
  const ShearStressFsRow& c = kShearStressFs[row];
  const double fit = c.A3 * std::pow(H, c.a4) * std::exp(H * (c.a6 * H - c.a5));
  if (H <= kShearStressFsTaperStartH) {
    return fit;
  }
  const double x =
      (H - kShearStressFsTaperStartH) / (kShearStressFsCutoffH - kShearStressFsTaperStartH);
  return fit * (1.0 - x * x * (3.0 - 2.0 * x));
}

double shearStressFpRow(int row, double H) {
  const ShearStressFpRow& c = kShearStressFp[row];
  return exponentialFitWithContinuation(c.D, c.s, kShearStressFpHmin, H);
}

double pressureFlowDesignNoteFit(double H, double gamma) {
  // docs/DESIGN.md §4 / [RB]: gamma <= 1: C = 0.89679 - 0.26591 ln gamma,
  // r = 0.43006 - 0.10828 gamma + 0.23821 gamma^2, phi = 1 - C exp(-r H);
  // gamma > 1: C = -0.10667 + 0.1075 gamma, phi = 1 + C H^-1.5.
  // Note: [RB] applies the power branch already at gamma = 1 (its test is gamma < 1),
  // which would give phi ~ 1 for isotropic roughness; docs/DESIGN.md states gamma = 1 as
  // 1 - 0.90 exp(-0.56 H), so gamma = 1 takes the exponential branch here.
  constexpr double kHmin = 0.5;
  if (gamma <= 1.0) {
    const double C = 0.89679 - 0.26591 * std::log(gamma);
    const double r = 0.43006 - 0.10828 * gamma + 0.23821 * gamma * gamma;
    return exponentialFitWithContinuation(C, r, kHmin, H);
  }
  const double C = -0.10667 + 0.1075 * gamma;
  return powerFitHeld(C, 1.5, kHmin, H);
}

}  // namespace detail

double calcPressureFlowFactor(double H, double gamma, PressureFlowGammaModel model) {
  checkH("calcPressureFlowFactor", H);
  checkGamma("calcPressureFlowFactor", gamma);
  if (model == PressureFlowGammaModel::kDesignNoteFit) {
    return detail::pressureFlowDesignNoteFit(H, gamma);
  }
  return detail::blend(detail::bracketGamma(gamma), H, detail::pressureFlowRow);
}

double calcShearFlowFactor(double H, double gamma) {
  checkH("calcShearFlowFactor", H);
  checkGamma("calcShearFlowFactor", gamma);
  return detail::blend(detail::bracketGamma(gamma), H, detail::shearFlowRow);
}

double calcShearStressFactorFs(double H, double gamma) {
  checkH("calcShearStressFactorFs", H);
  checkGamma("calcShearStressFactorFs", gamma);
  return detail::blend(detail::bracketGamma(gamma), H, detail::shearStressFsRow);
}

double calcShearStressFactorFp(double H, double gamma) {
  checkH("calcShearStressFactorFp", H);
  checkGamma("calcShearStressFactorFp", gamma);
  return detail::blend(detail::bracketGamma(gamma), H, detail::shearStressFpRow);
}

double calcShearStressFactorF(double H, double epsStar) {
  checkH("calcShearStressFactorF", H);
  if (!(epsStar > 0.0 && epsStar <= kMaxPhiFCutoff)) {
    common::throwInvalidValue("patir_cheng::calcShearStressFactorF", "cut-off epsStar", epsStar, "",
                              common::message("in (0, ", kMaxPhiFCutoff, "] (default 1/300)"));
  }
  const double z = H / 3.0;
  if (z <= 1.0) {
    const double a = 1.0 - z * z;
    const double poly =
        -55.0 + z * (132.0 + z * (345.0 + z * (-160.0 + z * (-405.0 + z * (60.0 + 147.0 * z)))));
    return 35.0 / 32.0 * z * (a * a * a * std::log((1.0 + z) / epsStar) + poly / 60.0);
  }
  if (z < 2.0) {
    const double a = 1.0 - z * z;
    const double z2 = z * z;
    const double lnRatio = std::log1p(2.0 / (z - 1.0));  // ln((z + 1) / (z - 1))
    return 35.0 / 32.0 * z * (a * a * a * lnRatio + z / 15.0 * (66.0 + z2 * (30.0 * z2 - 80.0)));
  }
  // For z >= 2 the closed form loses digits to cancellation (terms of size z^6 cancel
  // to leave ~1). Expanding ln((z+1)/(z-1)) = 2 sum z^-(2k+1)/(2k+1) gives exactly
  //   phi_f = 105 sum_{m>=0} z^-2m / ((2m+1)(2m+3)(2m+5)(2m+7)),
  // whose terms fall at least 4x per step for z >= 2.
  const double u = 1.0 / (z * z);
  double term = 1.0;  // z^-2m
  double sum = 0.0;
  for (int m = 0; m < 60; ++m) {
    const double d = (2.0 * m + 1.0) * (2.0 * m + 3.0) * (2.0 * m + 5.0) * (2.0 * m + 7.0);
    const double add = term / d;
    sum += add;
    if (add < 1e-18 * sum) {
      break;
    }
    term *= u;
  }
  return 105.0 * sum;
}

}  // namespace pistondyn::lubrication::patir_cheng
