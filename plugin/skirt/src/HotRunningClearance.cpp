#include "pistondyn/skirt/HotRunningClearance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "Checks.h"

namespace pistondyn::skirt {

namespace {

const char* const kWhere = "GapAssemblyParameters";

struct LinerMinimum {
  double gap_m = 0.0;
  double pinHeight_m = 0.0;
};

// Minimum of the liner term over the bore heights a skirt height y reaches, exact: the term is
// monotone between its table rows, so the minimum is at an end or a row.
LinerMinimum linerMinimum(const LinerThermalGrowth& liner, double y, const PistonTravel& travel) {
  const double lo = travel.lowestPinHeight_m + y, hi = travel.highestPinHeight_m + y;
  LinerMinimum best{liner.calcSample(lo).gap_m, travel.lowestPinHeight_m};
  const auto consider = [&](double boreHeight) {
    const double g = liner.calcSample(boreHeight).gap_m;
    if (g < best.gap_m)
      best = {g, boreHeight - y};
  };
  consider(hi);
  if (liner.isActive()) {
    const Eigen::VectorXd& depth = liner.getTemperatureTable().abscissae();
    for (Eigen::Index k = 0; k < depth.size(); ++k) {
      const double boreHeight = liner.getLinerTopHeight_m() - depth[k];
      if (boreHeight > lo && boreHeight < hi)
        consider(boreHeight);
    }
  }
  return best;
}

}  // namespace

HotRunningClearance calcHotRunningClearance(const SkirtSideGrid& grid,
                                            const GapAssemblyParameters& p) {
  detail::requireFinite(kWhere, "coldRadialClearance_m", p.coldRadialClearance_m, "m");
  detail::requireFinite(kWhere, "travel.lowestPinHeight_m", p.travel.lowestPinHeight_m, "m");
  detail::requireFinite(kWhere, "travel.highestPinHeight_m", p.travel.highestPinHeight_m, "m");
  if (!(p.travel.highestPinHeight_m >= p.travel.lowestPinHeight_m))
    detail::fail(kWhere,
                 detail::named("travel.highestPinHeight_m", p.travel.highestPinHeight_m, "m") +
                     " must not be below " +
                     detail::named("travel.lowestPinHeight_m", p.travel.lowestPinHeight_m, "m"));
  const double yBottom = grid.getSkirtBottomHeight_m(), yTop = grid.getSkirtTopHeight_m();
  const GapTermSwitches& on = p.terms;
  const AxialProfile axial =
      on.skirtProfile ? AxialProfile(p.skirtProfile.axial, yBottom, yTop) : AxialProfile();
  const Ovality ovality =
      on.skirtProfile ? Ovality(p.skirtProfile.ovality, 0.5 * grid.getArcWidth_rad()) : Ovality();
  const PistonThermalGrowth piston =
      on.pistonThermal ? PistonThermalGrowth(p.pistonThermal, grid, p.referenceTemperature_degC)
                       : PistonThermalGrowth();
  const LinerThermalGrowth liner =
      on.linerThermal ? LinerThermalGrowth(p.linerThermal, grid, p.linerTopHeight_m,
                                           p.referenceTemperature_degC)
                      : LinerThermalGrowth();
  const double centre = grid.getCentreAngle_rad();
  const double c0 = p.coldRadialClearance_m + ovality.calcDrop_m(centre);  // drop 0 on the axis

  HotRunningClearance best;
  best.clearance_m = std::numeric_limits<double>::infinity();
  const auto take = [&](double y, double pistonGap) {
    const LinerMinimum l = linerMinimum(liner, y, p.travel);
    const double c = c0 + axial.calcDrop_m(y) + pistonGap + l.gap_m;
    if (c < best.clearance_m)
      best = {c, y, l.pinHeight_m};
    return c;
  };

  if (piston.isNodal()) {
    // Centre-line value of the nodal field: linear between the node columns around phi_c.
    const Eigen::VectorXd& phi = grid.getPhiNodes_rad();
    const int i1 = static_cast<int>(std::upper_bound(phi.data(), phi.data() + phi.size(), centre) -
                                    phi.data());
    const int hi = std::clamp(i1, 1, grid.nPhi() - 1), lo = hi - 1;
    const double t = (centre - phi[lo]) / (phi[hi] - phi[lo]);
    const Eigen::ArrayXd& tNodal = piston.getNodalTemperature_degC();
    for (int j = 0; j < grid.nY(); ++j) {
      const double temp =
          (1.0 - t) * tNodal[grid.nodeIndex(lo, j)] + t * tNodal[grid.nodeIndex(hi, j)];
      take(grid.getYNodes_m()[j],
           -piston.getGrowthPerKelvin_m() * (temp - piston.getReferenceTemperature_degC()));
    }
    return best;
  }

  // Candidate heights: grid rows, table rows inside the skirt, where the liner window's ends
  // cross liner rows, and a uniform sampling.
  std::vector<double> y(grid.getYNodes_m().data(),
                        grid.getYNodes_m().data() + grid.getYNodes_m().size());
  const auto addInside = [&](double v) {
    if (v > yBottom && v < yTop)
      y.push_back(v);
  };
  const Eigen::VectorXd& profileRows = p.skirtProfile.axial.height_m;
  if (!axial.isCylindrical())
    for (Eigen::Index k = 0; k < profileRows.size(); ++k)
      addInside(axial.isMirrored() ? -profileRows[k] : profileRows[k]);
  if (piston.isActive())
    for (Eigen::Index k = 0; k < p.pistonThermal.height_m.size(); ++k)
      addInside(p.pistonThermal.height_m[k]);
  if (liner.isActive()) {
    const Eigen::VectorXd& depth = liner.getTemperatureTable().abscissae();
    for (Eigen::Index k = 0; k < depth.size(); ++k) {
      const double boreHeight = liner.getLinerTopHeight_m() - depth[k];
      addInside(boreHeight - p.travel.lowestPinHeight_m);
      addInside(boreHeight - p.travel.highestPinHeight_m);
    }
  }
  constexpr int kUniform = 256;
  for (int s = 1; s < kUniform; ++s)
    y.push_back(yBottom + (yTop - yBottom) * s / kUniform);
  std::sort(y.begin(), y.end());
  y.erase(std::unique(y.begin(), y.end()), y.end());

  const auto f = [&](double yy) { return take(yy, piston.calcGapFromTable_m(yy)); };
  std::size_t bestIndex = 0;
  double bestValue = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < y.size(); ++s) {
    const double v = f(y[s]);
    if (v < bestValue) {
      bestValue = v;
      bestIndex = s;
    }
  }
  // Golden-section refinement between the neighbours of the best candidate (take() keeps the
  // best point seen, so the result never gets worse than the sampled minimum).
  double a = y[bestIndex > 0 ? bestIndex - 1 : 0];
  double b = y[std::min(bestIndex + 1, y.size() - 1)];
  const double invPhi = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - invPhi * (b - a), x2 = a + invPhi * (b - a);
  double f1 = f(x1), f2 = f(x2);
  const double tol = 1e-9 * (yTop - yBottom);
  while (b - a > tol) {
    if (f1 < f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - invPhi * (b - a);
      f1 = f(x1);
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + invPhi * (b - a);
      f2 = f(x2);
    }
  }
  return best;
}

void requireNonNegativeHotClearance(const HotRunningClearance& hot, const SkirtSideGrid& grid) {
  if (hot.clearance_m >= 0.0)
    return;
  detail::fail("GapAssembly",
               "the hot running clearance is " + detail::str(hot.clearance_m) + " m on the " +
                   (grid.getSide() == SkirtSide::Thrust ? "thrust" : "anti-thrust") +
                   " side at skirt height y = " + detail::str(hot.skirtHeight_m) +
                   " m above the pin axis and pin height Y_pin = " + detail::str(hot.pinHeight_m) +
                   " m: the hot piston interferes with the bore (check coldRadialClearance_m, "
                   "the skirt profile and the thermal fields)");
}

}  // namespace pistondyn::skirt
