#pragma once
// Everything a Greenwood–Tripp node needs from the tail integrals, with one table lookup
// (private header; used by GreenwoodTrippLaw::evalNode for the exact model).

namespace pistondyn::contact_forces::detail {

struct GreenwoodTrippTails {
  double f52 = 0.0;       // F_{5/2}(λ) [-]
  double f52Slope = 0.0;  // dF_{5/2}/dλ = −(5/2)·F_{3/2}(λ) [-]
  double f2 = 0.0;        // F_2(λ) [-]
};

// Same values, bit for bit, as greenwoodTrippF52WithSlope(λ) and greenwoodTrippF2(λ).
GreenwoodTrippTails greenwoodTrippTails(double lambda);

}  // namespace pistondyn::contact_forces::detail
