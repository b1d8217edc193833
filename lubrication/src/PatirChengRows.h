#pragma once
// Private to pistondyn::lubrication (lubrication/src, not installed): the per-row evaluation of
// the Patir & Cheng fits and the interpolation weights in ln(gamma), so that
// PatirChengFlowFactors can bracket its Peklenik numbers once at construction instead of at
// every node. PatirChengFlowFactors.h stores the brackets as plain ints and doubles
// (PatirChengFlowFactors::RowBracket) so that no public header needs this one.

namespace pistondyn::lubrication::patir_cheng::detail {

// Two neighbouring tabulated rows and the weight of the upper one; value =
// (1 - wHi) f(lo) + wHi f(hi). lo == hi (wHi = 0) at a tabulated gamma or when clamped.
struct GammaBracket {
  int lo = 3;  // row index into kTabulatedGammas (3 is gamma = 1)
  int hi = 3;
  double wHi = 0.0;
};

// Inputs: gamma finite and > 0 (not checked here). Outputs: the bracket, clamped to the
// table's range [1/9, 9].
GammaBracket bracketGamma(double gamma);

// Row evaluations, H finite and > 0 (not checked here), row in [0, 7).
double pressureFlowRow(int row, double H);
double shearFlowRow(int row, double H);
double shearStressFsRow(int row, double H);
double shearStressFpRow(int row, double H);

// The docs/DESIGN.md continuous-gamma fit of the pressure flow factor (any gamma > 0).
double pressureFlowDesignNoteFit(double H, double gamma);

// Blend of one row function over a bracket.
template <class RowFunction>
double blend(const GammaBracket& b, double H, RowFunction row) {
  const double fLo = row(b.lo, H);
  if (b.hi == b.lo || b.wHi == 0.0) {
    return fLo;
  }
  return (1.0 - b.wHi) * fLo + b.wHi * row(b.hi, H);
}

}  // namespace pistondyn::lubrication::patir_cheng::detail
