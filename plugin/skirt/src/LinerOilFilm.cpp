#include "pistondyn/skirt/LinerOilFilm.h"

#include <algorithm>
#include <cmath>

#include "Checks.h"
#include "pistondyn/common/CrankAngle.h"

namespace pistondyn::skirt {
namespace {

constexpr const char* kWhere = "LinerOilParameters";

void checkParameters(const LinerOilParameters& p, double skirtTop_m) {
  if (p.ringFilmAngle_deg.empty()) {
    detail::requirePositive(kWhere, "ringFilm_m", p.ringFilm_m, "m");
  } else {
    const std::size_t n = p.ringFilmAngle_deg.size();
    if (n != p.ringFilmTable_m.size() || n < 2)
      detail::fail(kWhere, "ringFilmAngle_deg and ringFilmTable_m need the same size, >= 2");
    for (std::size_t i = 0; i < n; ++i) {
      const double a = p.ringFilmAngle_deg[i];
      if (!(a >= 0.0 && a < 720.0) || (i > 0 && !(a > p.ringFilmAngle_deg[i - 1])))
        detail::fail(kWhere, "ringFilmAngle_deg must increase strictly within [0, 720) deg");
      detail::requirePositive(kWhere, "ringFilmTable_m", p.ringFilmTable_m[i], "m");
    }
  }
  detail::requireFinite(kWhere, "ringHeightAbovePin_m", p.ringHeightAbovePin_m, "m");
  if (p.ringHeightAbovePin_m < skirtTop_m)
    detail::fail(kWhere, detail::named("ringHeightAbovePin_m", p.ringHeightAbovePin_m, "m") +
                             " is below the skirt's top (" + detail::str(skirtTop_m) +
                             " m above the pin): the oil-control ring sits above the skirt");
  if (!std::isnan(p.floodedBelow_m))
    detail::requireFinite(kWhere, "floodedBelow_m", p.floodedBelow_m, "m");
  if (!std::isnan(p.splashBelow_m))
    detail::requireFinite(kWhere, "splashBelow_m", p.splashBelow_m, "m");
  detail::requireNonNegative(kWhere, "splashRate_mps", p.splashRate_mps, "m/s");
  detail::requirePositive(kWhere, "maxFilm_m", p.maxFilm_m, "m");
  if (!(p.skirtShare >= 0.0 && p.skirtShare <= 1.0))
    detail::fail(kWhere, detail::named("skirtShare", p.skirtShare, "") + " must lie in [0, 1]");
  detail::requireNonNegative(kWhere, "initialFilm_m", p.initialFilm_m, "m");
}

}  // namespace

LinerOilFlows& LinerOilFlows::operator+=(const LinerOilFlows& o) {
  ringSource_m3 += o.ringSource_m3;
  splashSource_m3 += o.splashSource_m3;
  deficitSource_m3 += o.deficitSource_m3;
  drainLoss_m3 += o.drainLoss_m3;
  filmIntake_m3 += o.filmIntake_m3;
  sideLeakage_m3 += o.sideLeakage_m3;
  skirtShareLoss_m3 += o.skirtShareLoss_m3;
  return *this;
}

LinerOilFlows LinerOilFlows::operator-(const LinerOilFlows& earlier) const {
  LinerOilFlows d;
  d.ringSource_m3 = ringSource_m3 - earlier.ringSource_m3;
  d.splashSource_m3 = splashSource_m3 - earlier.splashSource_m3;
  d.deficitSource_m3 = deficitSource_m3 - earlier.deficitSource_m3;
  d.drainLoss_m3 = drainLoss_m3 - earlier.drainLoss_m3;
  d.filmIntake_m3 = filmIntake_m3 - earlier.filmIntake_m3;
  d.sideLeakage_m3 = sideLeakage_m3 - earlier.sideLeakage_m3;
  d.skirtShareLoss_m3 = skirtShareLoss_m3 - earlier.skirtShareLoss_m3;
  return d;
}

LinerOilFilm::LinerOilFilm(const SkirtSideGrid& side, const LinerOilParameters& parameters,
                           double lowestPinHeight_m, double highestPinHeight_m)
    : parameters_(parameters),
      yBottom_(side.getSkirtBottomHeight_m()),
      yTop_(side.getSkirtTopHeight_m()) {
  checkParameters(parameters, yTop_);
  detail::requireFinite("LinerOilFilm", "lowestPinHeight_m", lowestPinHeight_m, "m");
  detail::requireFinite("LinerOilFilm", "highestPinHeight_m", highestPinHeight_m, "m");
  if (!(highestPinHeight_m > lowestPinHeight_m))
    detail::fail("LinerOilFilm", "highestPinHeight_m must exceed lowestPinHeight_m");
  // Rows of the skirt's mean axial spacing, two to spare beyond the skirt's lowest reach and
  // the ring's highest.
  dY_ = (yTop_ - yBottom_) / (side.nY() - 1);
  y0_ = lowestPinHeight_m + yBottom_ - 2.0 * dY_;
  const double top = highestPinHeight_m + parameters.ringHeightAbovePin_m + 2.0 * dY_;
  rows_ = static_cast<int>(std::ceil((top - y0_) / dY_)) + 1;
  // Each column's arc length: the trapezoidal share of its film nodes.
  const Eigen::VectorXd& phi = side.getPhiNodes_rad();
  const int n = static_cast<int>(phi.size());
  width_m_.setZero(n);
  for (int i = 0; i + 1 < n; ++i) {
    const double half = 0.5 * side.getRadius_m() * (phi[i + 1] - phi[i]);
    width_m_[i] += half;
    width_m_[i + 1] += half;
  }
}

int LinerOilFilm::rowAbove(double height_m) const {
  // From the floor estimate, then corrected against rowHeight_m itself, so that the row found
  // agrees with covered() when an edge lands on a row's centre (round-off would put the oil
  // the edge leaves into a covered row).
  int m = std::clamp(static_cast<int>(std::floor((height_m - y0_) / dY_)) + 1, 0, rows_);
  while (m < rows_ && rowHeight_m(m) <= height_m)
    ++m;
  while (m > 0 && rowHeight_m(m - 1) > height_m)
    --m;
  return m;
}

int LinerOilFilm::rowBelow(double height_m) const {
  int m = std::clamp(static_cast<int>(std::ceil((height_m - y0_) / dY_)) - 1, -1, rows_ - 1);
  while (m >= 0 && rowHeight_m(m) >= height_m)
    --m;
  while (m + 1 < rows_ && rowHeight_m(m + 1) < height_m)
    ++m;
  return m;
}

bool LinerOilFilm::covered(int m, double pinHeight_m) const {
  const double c = rowHeight_m(m);
  return c >= pinHeight_m + yBottom_ && c <= pinHeight_m + yTop_;
}

double LinerOilFilm::calcRingFilm_m(double crankAngle_deg) const {
  if (parameters_.ringFilmAngle_deg.empty())
    return parameters_.ringFilm_m;
  return common::interpolateOverCycle(parameters_.ringFilmAngle_deg, parameters_.ringFilmTable_m,
                                      crankAngle_deg);
}

LinerOilState LinerOilFilm::makeInitialState(double pinHeight_m) const {
  detail::requireFinite("LinerOilFilm::makeInitialState", "pinHeight_m", pinHeight_m, "m");
  LinerOilState s;
  const int nc = columns();
  s.volume_m3.setZero(nc * rows_);
  for (int m = 0; m < rows_; ++m) {
    if (covered(m, pinHeight_m))
      continue;
    const bool flooded = rowHeight_m(m) < parameters_.floodedBelow_m;
    const double film = flooded ? parameters_.maxFilm_m : parameters_.initialFilm_m;
    for (int i = 0; i < nc; ++i)
      s.volume_m3[i + nc * m] = cellCapacity_m3(i, film);
  }
  s.pinHeight_m = pinHeight_m;
  return s;
}

void LinerOilFilm::calcSupply(const LinerOilState& state, double pinHeight_m,
                              Eigen::ArrayXd& bottom_m, Eigen::ArrayXd& top_m) const {
  const int nc = columns();
  bottom_m.setZero(nc);
  top_m.setZero(nc);
  const int up = rowAbove(pinHeight_m + yTop_), down = rowBelow(pinHeight_m + yBottom_);
  const double middle = pinHeight_m + 0.5 * (yBottom_ + yTop_);
  for (int m = 0; m < rows_; ++m) {
    // The free rows just outside the edges, with the oil of the rows the step covers (pushed
    // ahead by advance()).
    const bool pushed = covered(m, pinHeight_m) && !covered(m, state.pinHeight_m);
    const bool toTop = m == up || (pushed && rowHeight_m(m) >= middle);
    const bool toBottom = m == down || (pushed && rowHeight_m(m) < middle);
    if (!toTop && !toBottom)
      continue;
    for (int i = 0; i < nc; ++i)
      (toTop ? top_m : bottom_m)[i] += state.volume_m3[i + nc * m];
  }
  for (int i = 0; i < nc; ++i) {
    top_m[i] /= width_m_[i] * dY_;
    bottom_m[i] /= width_m_[i] * dY_;
  }
}

LinerOilState LinerOilFilm::advance(const LinerOilState& state, double pinHeight_m,
                                    double axialVelocity_mps, double crankAngle_deg, double dt_s,
                                    const EdgeOutflows& edgeFlows) const {
  const int nc = columns();
  LinerOilState s = state;
  Eigen::ArrayXd& v = s.volume_m3;
  const double Y = pinHeight_m;
  const int up = rowAbove(Y + yTop_), down = rowBelow(Y + yBottom_);
  const auto free = [&](int m) { return m >= 0 && m < rows_ && !covered(m, Y); };

  // 1. Rows covered now give their oil to the free row ahead of the edge that covered them.
  const double middle = Y + 0.5 * (yBottom_ + yTop_);
  for (int m = 0; m < rows_; ++m) {
    if (!covered(m, Y))
      continue;
    const int target = rowHeight_m(m) >= middle ? up : down;
    for (int i = 0; i < nc; ++i) {
      double& cell = v[i + nc * m];
      if (cell == 0.0)
        continue;
      if (free(target))
        v[i + nc * target] += cell;
      else
        s.flows.drainLoss_m3 += cell;  // beyond the liner's rows: the oil leaves the model
      cell = 0.0;
    }
  }

  // 2. The film's flows across its axial edges, to and from the free row outside each edge.
  // The liner slides relative to the skirt with U = -v_y: out through the top when v_y < 0.
  const auto exchange = [&](int row, int outward, const Eigen::ArrayXd& out, bool trailing) {
    for (int i = 0; i < nc; ++i) {
      const double V = out[i] * dt_s;  // + leaves the film
      s.flows.filmIntake_m3 -= V;
      if (V >= 0.0) {
        const double share = trailing ? parameters_.skirtShare * V : 0.0;
        s.flows.skirtShareLoss_m3 += share;
        if (free(row))
          v[i + nc * row] += V - share;
        else
          s.flows.drainLoss_m3 += V - share;
        continue;
      }
      double need = -V;  // drawn by the film: from the row outside, then the rows beyond it
      for (int m = row; need > 0.0 && free(m); m += outward) {
        double& cell = v[i + nc * m];
        const double take = std::min(cell, need);
        cell -= take;
        need -= take;
      }
      s.flows.deficitSource_m3 += need;
    }
  };
  if (edgeFlows.top)
    exchange(up, +1, *edgeFlows.top, axialVelocity_mps < 0.0);
  if (edgeFlows.bottom)
    exchange(down, -1, *edgeFlows.bottom, axialVelocity_mps > 0.0);
  // 3. Side leakage leaves the model.
  for (const Eigen::ArrayXd* side : {edgeFlows.sideMin, edgeFlows.sideMax}) {
    if (!side)
      continue;
    const double V = side->sum() * dt_s;
    s.flows.sideLeakage_m3 += V;
    s.flows.filmIntake_m3 -= V;
  }

  // 4. The rows whose centres the oil-control ring passed get the film it leaves.
  const double ringFrom = state.pinHeight_m + parameters_.ringHeightAbovePin_m;
  const double ringTo = Y + parameters_.ringHeightAbovePin_m;
  const double ringFilm = calcRingFilm_m(crankAngle_deg);
  for (int m = 0; m < rows_ && ringTo != ringFrom; ++m) {
    const double c = rowHeight_m(m);
    const bool passed = ringTo > ringFrom ? (c > ringFrom && c <= ringTo)
                                          : (c < ringFrom && c >= ringTo);
    if (!passed || !free(m))
      continue;
    for (int i = 0; i < nc; ++i) {
      double& cell = v[i + nc * m];
      const double metered = cellCapacity_m3(i, ringFilm);
      s.flows.ringSource_m3 += metered - cell;
      cell = metered;
    }
  }

  // 5. Crankcase splash, and 6. the drain above the largest film.
  const double dSplash = parameters_.splashRate_mps * dt_s;
  for (int m = 0; m < rows_; ++m) {
    if (!free(m))
      continue;
    const double c = rowHeight_m(m);
    for (int i = 0; i < nc; ++i) {
      double& cell = v[i + nc * m];
      const double cap = cellCapacity_m3(i, parameters_.maxFilm_m);
      if (c < parameters_.floodedBelow_m) {
        s.flows.splashSource_m3 += cap - cell;
        cell = cap;
        continue;
      }
      if (c < parameters_.splashBelow_m && cell < cap) {
        const double add = std::min(cellCapacity_m3(i, dSplash), cap - cell);
        s.flows.splashSource_m3 += add;
        cell += add;
      }
      if (cell > cap) {
        s.flows.drainLoss_m3 += cell - cap;
        cell = cap;
      }
    }
  }
  s.pinHeight_m = Y;
  return s;
}

void LinerOilFilm::calcFilm(const LinerOilState& state, Eigen::ArrayXd& film_m) const {
  const int nc = columns();
  film_m.resize(nc * rows_);
  for (int m = 0; m < rows_; ++m)
    for (int i = 0; i < nc; ++i)
      film_m[i + nc * m] = state.volume_m3[i + nc * m] / (width_m_[i] * dY_);
}

void LinerOilFilm::calcMeanFilmPerRow(const LinerOilState& state, Eigen::ArrayXd& film_m) const {
  const int nc = columns();
  const double arc = width_m_.sum();
  film_m.resize(rows_);
  for (int m = 0; m < rows_; ++m)
    film_m[m] = state.volume_m3.segment(nc * m, nc).sum() / (arc * dY_);
}

}  // namespace pistondyn::skirt
