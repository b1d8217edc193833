#include "pistondyn/skirt/LinerShape.h"

#include <array>
#include <cmath>
#include <string>

#include "Checks.h"
#include "OutputChecks.h"
#include "pistondyn/common/NodalField.h"

namespace pistondyn::skirt {

namespace {
const char* const kWhere = "BoreDistortionParameters";
}

LinerShape::LinerShape(const BoreDistortionParameters& parameters, const SkirtSideGrid& grid,
                       double linerTopHeight_m)
    : linerTop_m_(linerTopHeight_m), nPhi_(grid.nPhi()), nY_(grid.nY()), y_m_(grid.getYNodes_m()) {
  if (parameters.orders.empty())
    return;
  detail::requireFinite("GapAssemblyParameters", "linerTopHeight_m", linerTopHeight_m, "m");
  std::array<bool, kMaxBoreDistortionOrder + 1> seen{};
  for (std::size_t o = 0; o < parameters.orders.size(); ++o) {
    const BoreDistortionOrder& in = parameters.orders[o];
    const std::string prefix = "orders[" + std::to_string(o) + "].";
    if (in.order < 0 || in.order > kMaxBoreDistortionOrder)
      detail::fail(kWhere, prefix + "order = " + std::to_string(in.order) + " must be within 0.." +
                               std::to_string(kMaxBoreDistortionOrder));
    if (seen[in.order])
      detail::fail(kWhere, prefix + "order = " + std::to_string(in.order) +
                               " is given twice; each order at most once");
    seen[in.order] = true;
    detail::requireIncreasing(kWhere, prefix + "depth_m", in.depth_m, "m", 1);
    detail::requireSameSize(kWhere, prefix + "amplitude_m", in.amplitude_m.size(),
                            prefix + "depth_m", in.depth_m.size());
    detail::requireFiniteEntries(kWhere, prefix + "amplitude_m", in.amplitude_m, "m");
    const bool phaseNeeded = in.order > 0 || in.phase_rad.size() > 0;
    if (phaseNeeded) {
      detail::requireSameSize(kWhere, prefix + "phase_rad", in.phase_rad.size(), prefix + "depth_m",
                              in.depth_m.size());
      detail::requireFiniteEntries(kWhere, prefix + "phase_rad", in.phase_rad, "rad");
    }
    const Eigen::Index rows = in.depth_m.size();
    Eigen::VectorXd a(rows), b(rows);
    for (Eigen::Index r = 0; r < rows; ++r) {
      const double nPsi = in.order * (phaseNeeded ? in.phase_rad[r] : 0.0);
      a[r] = in.amplitude_m[r] * std::cos(nPsi);
      b[r] = in.amplitude_m[r] * std::sin(nPsi);
    }
    orders_.push_back({in.order,
                       InterpolatedTable(in.depth_m, a, Interpolation::Pchip, kWhere,
                                         prefix + "depth_m", "m", prefix + "a_n", "m"),
                       InterpolatedTable(in.depth_m, b, Interpolation::Pchip, kWhere,
                                         prefix + "depth_m", "m", prefix + "b_n", "m")});
  }
  const Eigen::VectorXd& phi = grid.getPhiNodes_rad();
  const Eigen::Index nO = static_cast<Eigen::Index>(orders_.size());
  cosNPhi_.resize(nO, nPhi_);
  sinNPhi_.resize(nO, nPhi_);
  for (int i = 0; i < nPhi_; ++i)
    for (Eigen::Index o = 0; o < nO; ++o) {
      cosNPhi_(o, i) = std::cos(orders_[o].n * phi[i]);
      sinNPhi_(o, i) = std::sin(orders_[o].n * phi[i]);
    }
}

BoreSample LinerShape::calcSample(double phi_rad, double boreHeight_m) const {
  BoreSample out;
  const double depth = linerTop_m_ - boreHeight_m;
  for (const Order& o : orders_) {
    const TableSample a = o.a.evaluate(depth), b = o.b.evaluate(depth);
    const double c = std::cos(o.n * phi_rad), s = std::sin(o.n * phi_rad);
    out.radialDeviation_m += a.value * c + b.value * s;
    // d/dY = -d/d(depth)
    out.dRadialDeviation_dBoreHeight -= a.derivative * c + b.derivative * s;
  }
  return out;
}

void LinerShape::calcField(double pinHeight_m, double axialVelocity_mps,
                           Eigen::Ref<Eigen::ArrayXd> gap_m,
                           Eigen::Ref<Eigen::ArrayXd> gapRate_mps) const {
  const char* fn = "LinerShape::calcField";
  detail::requireNodalSize(fn, "gap_m", gap_m.size(), Eigen::Index(nPhi_) * nY_);
  detail::requireNodalSize(fn, "gapRate_mps", gapRate_mps.size(), Eigen::Index(nPhi_) * nY_);
  if (orders_.empty()) {
    gap_m.setZero();
    gapRate_mps.setZero();
    return;
  }
  const Eigen::Index nO = static_cast<Eigen::Index>(orders_.size());
  // Per-row coefficients on the stack (at most 13 orders): no allocation per call.
  std::array<double, kMaxBoreDistortionOrder + 1> a{}, b{}, aRate{}, bRate{};
  auto gapRows = common::asGrid(gap_m, nPhi_, nY_);
  auto rateRows = common::asGrid(gapRate_mps, nPhi_, nY_);
  for (int j = 0; j < nY_; ++j) {
    const double depth = linerTop_m_ - (pinHeight_m + y_m_[j]);
    for (Eigen::Index o = 0; o < nO; ++o) {
      const TableSample sa = orders_[o].a.evaluate(depth), sb = orders_[o].b.evaluate(depth);
      a[o] = sa.value;
      b[o] = sb.value;
      // rate = (d/dY) v_y = -(d/d depth) v_y
      aRate[o] = -sa.derivative * axialVelocity_mps;
      bRate[o] = -sb.derivative * axialVelocity_mps;
    }
    for (int i = 0; i < nPhi_; ++i) {
      double h = 0.0, rate = 0.0;
      for (Eigen::Index o = 0; o < nO; ++o) {
        h += a[o] * cosNPhi_(o, i) + b[o] * sinNPhi_(o, i);
        rate += aRate[o] * cosNPhi_(o, i) + bRate[o] * sinNPhi_(o, i);
      }
      gapRows(i, j) = h;
      rateRows(i, j) = rate;
    }
  }
}

}  // namespace pistondyn::skirt
