#include "pistondyn/mapping/HatOverlap1D.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "BuildHatOverlap1D.h"
#include "Cells.h"
#include "Checks.h"

namespace pistondyn::mapping {

namespace {

// Moments of the trigonometric weights about an interval midpoint, half-width w:
//   C2(w) = int_{-w}^{w} t^2 cos t dt,   S1(w) = int_{-w}^{w} t sin t dt
// (int cos = 2 sin w; the odd moments of cos and even of sin vanish). Below w = 1 the
// closed forms cancel (C2 ~ 2w^3/3 from O(w) terms), so the alternating series is used;
// its terms fall by w^2/((2k+1)(2k+2)) <= 1/2 per step and it stops at full precision.
// 2 * sum_k (-1)^k w^(2k+3) / ((2k+o)! (2k+3)): C2 for o = 0, S1 for o = 1.
double momentSeries(double w, int o) {
  const double w2 = w * w;
  double power = w2 * w, factorial = 1.0, sum = 0.0, sign = 1.0;  // factorial = (2k+o)!
  for (int k = 0; k < 30; ++k) {
    const double term = power / (factorial * (2 * k + 3));
    sum += sign * term;
    if (term <= 1e-18 * std::abs(sum))
      break;
    power *= w2;
    factorial *= (2.0 * k + 1.0 + o) * (2.0 * k + 2.0 + o);
    sign = -sign;
  }
  return 2.0 * sum;
}

double momentC2(double w) {
  if (w >= 1.0)
    return 2.0 * (w * w * std::sin(w) + 2.0 * w * std::cos(w) - 2.0 * std::sin(w));
  return momentSeries(w, 0);
}

double momentS1(double w) {
  if (w >= 1.0)
    return 2.0 * (std::sin(w) - w * std::cos(w));
  return momentSeries(w, 1);
}

// Integrals of u*v*{1, cos x, sin x} over [p, q] for u, v linear with end values
// (up, uq), (vp, vq). out[1], out[2] only when trig.
void integrateProduct(double p, double q, double up, double uq, double vp, double vq, bool trig,
                      double out[3]) {
  const double length = q - p;
  out[0] = length / 6.0 * (2.0 * up * vp + up * vq + uq * vp + 2.0 * uq * vq);
  if (!trig)
    return;
  // u v = alpha + beta*t + gamma*t^2 with t = x - midpoint.
  const double w = 0.5 * length, mid = 0.5 * (p + q);
  const double um = 0.5 * (up + uq), vm = 0.5 * (vp + vq);
  const double ud = (uq - up) / length, vd = (vq - vp) / length;
  const double alpha = um * vm, beta = um * vd + ud * vm, gamma = ud * vd;
  const double even = alpha * 2.0 * std::sin(w) + gamma * momentC2(w);
  const double odd = beta * momentS1(w);
  const double c = std::cos(mid), s = std::sin(mid);
  out[1] = c * even - s * odd;  // cos(mid + t) = cos mid cos t - sin mid sin t
  out[2] = s * even + c * odd;  // sin(mid + t) = sin mid cos t + cos mid sin t
}

// Calls f(lo, hi, shift) for every non-empty intersection of [a, b] with
// [c + m*period, d + m*period] (all integers m; only m = 0 when period == 0).
template <class F>
void forEachOverlap(double a, double b, double c, double d, double period, F&& f) {
  if (period == 0.0) {
    const double lo = std::max(a, c), hi = std::min(b, d);
    if (hi > lo)
      f(lo, hi, 0.0);
    return;
  }
  const long mFirst = static_cast<long>(std::ceil((a - d) / period));
  const long mLast = static_cast<long>(std::floor((b - c) / period));
  for (long m = mFirst; m <= mLast; ++m) {
    const double shift = static_cast<double>(m) * period;
    const double lo = std::max(a, c + shift), hi = std::min(b, d + shift);
    if (hi > lo)
      f(lo, hi, shift);
  }
}

struct Axis {
  const Eigen::VectorXd& x;
  bool closed;
  double period;
  int n() const { return static_cast<int>(x.size()); }
  int cells() const { return closed ? n() : n() - 1; }
  double node(int i) const { return detail::ringNode(x, period, i); }  // i == n: closing node
  double end() const { return node(cells()); }
};

void addEntry(std::vector<HatOverlap1D::Entry>& column, int row, const double v[3]) {
  column.push_back({row, {v[0], v[1], v[2]}});
}

// One half of a source node's hat in target coordinates: rising from 0 at a to 1 at b on the
// node's left cell, falling from 1 at a to 0 at b on its right cell.
struct HalfHat {
  double a, b, width;
  bool rising;
  double operator()(double x) const {
    const double lambda = (x - a) / width;
    return rising ? lambda : 1.0 - lambda;
  }
};

// The half hat of source node k on `side` (0: its left cell, rising; 1: its right cell,
// falling), shifted by `offset`; false when the node has no cell on that side.
bool sourceHalfHat(const Axis& src, int k, int side, double offset, HalfHat& hat) {
  const int cell = side == 0 ? k - 1 : k;
  if (cell < 0 && !src.closed)
    return false;
  if (cell >= src.cells())
    return false;
  const int c = (cell + src.n()) % src.n();  // the closing cell of a ring is cell ns-1
  // Cell ends in target coordinates. For k == 0 on a ring the left cell is the
  // closing cell, one period to the left of node 0.
  double a = src.node(c) + offset, b = src.node(c + 1) + offset;
  if (cell < 0) {
    a -= src.period;
    b -= src.period;
  }
  hat = HalfHat{a, b, b - a, side == 0};
  return true;
}

// Sizes `out` for ns source and nt target nodes, empty. Upper bounds are reserved, so that
// rebuilding for another offset never reallocates: the source and target breakpoints cut the
// overlap into at most ns + nt + 2 pieces, on each of which at most 2 source and 2 target
// basis functions are non-zero (<= 4 entries per piece); one column's unmerged pieces are at
// most 2 sides x 2 turns x (target cells + 1) x 2.
void startOverlap(int ns, int nt, bool withTrig, HatOverlap1D& out) {
  out.targetCount = nt;
  out.sourceCount = ns;
  out.withTrig = withTrig;
  out.outer.assign(1, 0);
  out.inner.clear();
  out.value.clear();
  out.valueCos.clear();
  out.valueSin.clear();
  out.sourceIntegral.setZero(ns, 3);
  out.insideIntegral.setZero(ns, 3);
  out.outsideIntegral.setZero(ns, 3);
  const size_t maxEntries = 4 * (static_cast<size_t>(ns + nt) + 2);
  out.inner.reserve(maxEntries);
  out.value.reserve(maxEntries);
  if (withTrig) {
    out.valueCos.reserve(maxEntries);
    out.valueSin.reserve(maxEntries);
  }
  out.outer.reserve(static_cast<size_t>(ns) + 1);
  out.columnScratch.reserve(8 * (static_cast<size_t>(nt) + 2));
}

// The target cell where the overlap starting at lo (target copy shifted by `shift`) begins.
// Without a period (axial factors, rebuilt every step) the overlaps start at non-decreasing
// positions as the source node runs, so the cell is found by walking on from the previous
// one (`cursor`) instead of a binary search over all target nodes.
int firstTargetCell(const Axis& tgt, double lo, double shift, int& cursor) {
  const int targetCells = tgt.cells();
  if (tgt.period == 0.0) {
    // Same cell as upper_bound(lo) - 1, clamped: the last j with node(j) <= lo.
    int j = std::min(cursor, targetCells - 1);
    while (j > 0 && tgt.x[j] > lo)
      --j;
    while (j + 1 < targetCells && tgt.x[j + 1] <= lo)
      ++j;
    cursor = j;
    return j;
  }
  const double* begin = tgt.x.data();
  const int j = static_cast<int>(std::upper_bound(begin, begin + tgt.n(), lo - shift) - begin) - 1;
  return std::clamp(j, 0, targetCells - 1);
}

// The entries of the piece [p, q] of target cell [xj, xj1] (nodes rowLeft, rowRight) under
// the half hat.
void addCellEntries(const HalfHat& hat, double xj, double xj1, double p, double q, int rowLeft,
                    int rowRight, LoadRule rule, bool withTrig,
                    std::vector<HatOverlap1D::Entry>& column) {
  double piece[3] = {0.0, 0.0, 0.0};
  const double up = hat(p), uq = hat(q);
  if (rule == LoadRule::Consistent) {
    const double h = xj1 - xj;
    const double vp = (xj1 - p) / h, vq = (xj1 - q) / h;  // left node's hat
    integrateProduct(p, q, up, uq, vp, vq, withTrig, piece);
    addEntry(column, rowLeft, piece);
    integrateProduct(p, q, up, uq, 1.0 - vp, 1.0 - vq, withTrig, piece);
    addEntry(column, rowRight, piece);
  } else {  // half-cells: the left half of the cell belongs to the left node
    const double middle = 0.5 * (xj + xj1);
    if (middle > p) {
      const double qq = std::min(q, middle);
      integrateProduct(p, qq, up, hat(qq), 1.0, 1.0, withTrig, piece);
      addEntry(column, rowLeft, piece);
    }
    if (q > middle) {
      const double pp = std::max(p, middle);
      integrateProduct(pp, q, hat(pp), uq, 1.0, 1.0, withTrig, piece);
      addEntry(column, rowRight, piece);
    }
  }
}

// Inside the target range: the entries of the target cells under each overlap of the half hat
// with the target range (and its copies a period apart).
void addInsideEntries(const HalfHat& hat, const Axis& tgt, LoadRule rule, bool withTrig,
                      int& cursor, std::vector<HatOverlap1D::Entry>& column) {
  const int nt = tgt.n(), targetCells = tgt.cells();
  forEachOverlap(hat.a, hat.b, tgt.node(0), tgt.end(), tgt.period,
                 [&](double lo, double hi, double shift) {
                   for (int j = firstTargetCell(tgt, lo, shift, cursor); j < targetCells; ++j) {
                     const double xj = tgt.node(j) + shift, xj1 = tgt.node(j + 1) + shift;
                     if (xj >= hi)
                       break;
                     const double p = std::max(lo, xj), q = std::min(hi, xj1);
                     if (!(q > p))
                       continue;
                     addCellEntries(hat, xj, xj1, p, q, j, (j + 1) % nt, rule, withTrig, column);
                   }
                 });
}

// Outside the target range (nothing is outside a closed target): the integrals of the half hat
// there, added to row k of out.outsideIntegral (1, cos, sin).
void addOutsideIntegral(const HalfHat& hat, const Axis& tgt, bool withTrig, int k,
                        HatOverlap1D& out) {
  if (tgt.closed)
    return;
  const double a = hat.a, b = hat.b, t0 = tgt.node(0), t1 = tgt.end(), period = tgt.period;
  double piece[3] = {0.0, 0.0, 0.0};
  auto addOutside = [&](double lo, double hi) {
    integrateProduct(lo, hi, hat(lo), hat(hi), 1.0, 1.0, withTrig, piece);
    for (int w = 0; w < 3; ++w)
      out.outsideIntegral(k, w) += piece[w];
  };
  if (period > 0.0) {
    // Gaps between consecutive copies of the target range, with the copies' own
    // (rounded) end points so that inside and outside pieces tile without slivers.
    const long mFirst = static_cast<long>(std::floor((a - t0) / period)) - 1;
    const long mLast = static_cast<long>(std::ceil((b - t1) / period));
    for (long m = mFirst; m <= mLast; ++m) {
      const double gapLo = t1 + static_cast<double>(m) * period;
      const double gapHi = t0 + static_cast<double>(m + 1) * period;
      const double lo = std::max(a, gapLo), hi = std::min(b, gapHi);
      if (hi > lo)
        addOutside(lo, hi);
    }
  } else {
    if (a < t0)
      addOutside(a, std::min(b, t0));
    if (b > t1)
      addOutside(std::max(a, t1), b);
  }
}

// Appends source node k's column: sorted by target node, duplicates summed; their sums also
// into insideIntegral. The sweep is not in order: the falling side restarts at the target cell
// holding node k, where the rising side ended (and overlaps on a ring wrap), so nearly every
// column needs the sort.
void appendMergedColumn(int k, bool withTrig, std::vector<HatOverlap1D::Entry>& column,
                        HatOverlap1D& out) {
  std::sort(
      column.begin(), column.end(),
      [](const HatOverlap1D::Entry& l, const HatOverlap1D::Entry& r) { return l.row < r.row; });
  for (size_t e = 0; e < column.size();) {
    const int row = column[e].row;
    double sum[3] = {0.0, 0.0, 0.0};
    for (; e < column.size() && column[e].row == row; ++e)
      for (int w = 0; w < 3; ++w)
        sum[w] += column[e].v[w];
    out.inner.push_back(row);
    out.value.push_back(sum[0]);
    if (withTrig) {
      out.valueCos.push_back(sum[1]);
      out.valueSin.push_back(sum[2]);
    }
    for (int w = 0; w < 3; ++w)
      out.insideIntegral(k, w) += sum[w];
  }
  out.outer.push_back(static_cast<int>(out.inner.size()));
}

}  // namespace

Eigen::Map<const Eigen::SparseMatrix<double>> HatOverlap1D::view(
    const std::vector<double>& v) const {
  return Eigen::Map<const Eigen::SparseMatrix<double>>(targetCount, sourceCount,
                                                       static_cast<Eigen::Index>(inner.size()),
                                                       outer.data(), inner.data(), v.data());
}

void calcHatOverlap1D(const Eigen::VectorXd& sourceNodes, bool sourceClosed,
                      const Eigen::VectorXd& targetNodes, bool targetClosed, double period,
                      double offset, LoadRule rule, bool withTrig, HatOverlap1D& out) {
  const char* fn = "calcHatOverlap1D";
  detail::requireFiniteScalar(fn, "offset", offset);
  detail::requireFiniteScalar(fn, "period", period);
  if ((sourceClosed || targetClosed) && !(period > 0.0))
    common::throwInvalidValue(fn, "period", period, "", "positive for a closed grid");
  // With a period the overlaps are found by counting periods from the offset: keep it
  // within kMaxAbsAngle_rad's number of turns (the counts stay exact integers).
  constexpr double kMaxTurns = kMaxAbsAngle_rad / detail::kTwoPi;
  if (period > 0.0 && !(std::abs(offset) <= kMaxTurns * period))
    common::throwInvalidArgument(
        fn, common::message("offset = ", offset, " must be within +-", kMaxTurns, " periods"));
  detail::requireIncreasingNodes(fn, "sourceNodes", sourceNodes, sourceClosed ? 3 : 2);
  detail::requireIncreasingNodes(fn, "targetNodes", targetNodes, targetClosed ? 3 : 2);
  auto requireSpan = [&](const char* argument, const Eigen::VectorXd& x) {
    if (period > 0.0 && !(x[x.size() - 1] - x[0] < period))
      common::throwInvalidArgument(fn, common::message(argument, " spans ", x[x.size() - 1] - x[0],
                                                       ", must be less than period = ", period));
  };
  requireSpan("sourceNodes", sourceNodes);
  requireSpan("targetNodes", targetNodes);
  if (sourceClosed)
    detail::requireReasonableClosingCell(fn, "sourceNodes", sourceNodes, period);
  if (targetClosed)
    detail::requireReasonableClosingCell(fn, "targetNodes", targetNodes, period);
  detail::buildHatOverlap1D(sourceNodes, sourceClosed, targetNodes, targetClosed, period, offset,
                            rule, withTrig, out);
}

void detail::buildHatOverlap1D(const Eigen::VectorXd& sourceNodes, bool sourceClosed,
                               const Eigen::VectorXd& targetNodes, bool targetClosed, double period,
                               double offset, LoadRule rule, bool withTrig, HatOverlap1D& out) {
  const Axis src{sourceNodes, sourceClosed, period};
  const Axis tgt{targetNodes, targetClosed, period};
  const int ns = src.n();
  startOverlap(ns, tgt.n(), withTrig, out);
  std::vector<HatOverlap1D::Entry>& column = out.columnScratch;
  double piece[3] = {0.0, 0.0, 0.0};
  int cursor = 0;  // firstTargetCell()
  for (int k = 0; k < ns; ++k) {
    column.clear();
    for (int side = 0; side < 2; ++side) {
      HalfHat hat;
      if (!sourceHalfHat(src, k, side, offset, hat))
        continue;
      const double ua = hat.rising ? 0.0 : 1.0, ub = hat.rising ? 1.0 : 0.0;
      integrateProduct(hat.a, hat.b, ua, ub, 1.0, 1.0, withTrig, piece);
      for (int w = 0; w < 3; ++w)
        out.sourceIntegral(k, w) += piece[w];
      addInsideEntries(hat, tgt, rule, withTrig, cursor, column);
      addOutsideIntegral(hat, tgt, withTrig, k, out);
    }
    appendMergedColumn(k, withTrig, column, out);
  }
}

}  // namespace pistondyn::mapping
