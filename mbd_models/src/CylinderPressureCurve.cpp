#include "pistondyn/mbd_models/CylinderPressureCurve.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pistondyn/common/Validation.h"

namespace pistondyn::mbd {
namespace {

[[noreturn]] void fail(const std::string& what, std::optional<std::size_t> row = std::nullopt) {
  throw PressureTableError("CylinderPressureCurve: " + what, row);
}

std::string rowText(std::size_t i, double angle, double p) {
  return common::message("row ", i, " (angle ", angle, " deg, pressure ", p, " Pa)");
}

// Second derivatives of the periodic cubic spline through (x_i, y_i), i = 0..n-1,
// with period T (interval n-1 -> 0 wraps). Cyclic tridiagonal system solved by the
// Sherman-Morrison correction of the Thomas algorithm.
std::vector<double> periodicSplineSecondDerivatives(const std::vector<double>& x,
                                                    const std::vector<double>& y, double T) {
  const std::size_t n = x.size();
  std::vector<double> h(n);
  for (std::size_t i = 0; i < n; ++i)
    h[i] = (i + 1 < n ? x[i + 1] : x[0] + T) - x[i];
  // Row i: h[i-1] m[i-1] + 2(h[i-1]+h[i]) m[i] + h[i] m[i+1] = 6((y[i+1]-y[i])/h[i] -
  // (y[i]-y[i-1])/h[i-1])
  std::vector<double> a(n), b(n), c(n), d(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t im = (i + n - 1) % n, ip = (i + 1) % n;
    a[i] = h[im];
    b[i] = 2.0 * (h[im] + h[i]);
    c[i] = h[i];
    d[i] = 6.0 * ((y[ip] - y[i]) / h[i] - (y[i] - y[im]) / h[im]);
  }
  // Cyclic: corner terms a[0] (couples m[n-1]) and c[n-1] (couples m[0]).
  const double alpha = c[n - 1], beta = a[0], gamma = -b[0];
  std::vector<double> bb(b), u(n, 0.0);
  bb[0] = b[0] - gamma;
  bb[n - 1] = b[n - 1] - alpha * beta / gamma;
  u[0] = gamma;
  u[n - 1] = alpha;
  auto thomas = [&](std::vector<double> rhs) {
    std::vector<double> cp(n), out(n);
    double denom = bb[0];
    cp[0] = c[0] / denom;
    rhs[0] /= denom;
    for (std::size_t i = 1; i < n; ++i) {
      denom = bb[i] - a[i] * cp[i - 1];
      cp[i] = c[i] / denom;
      rhs[i] = (rhs[i] - a[i] * rhs[i - 1]) / denom;
    }
    out[n - 1] = rhs[n - 1];
    for (std::size_t i = n - 1; i-- > 0;)
      out[i] = rhs[i] - cp[i] * out[i + 1];
    return out;
  };
  const std::vector<double> yv = thomas(d), z = thomas(u);
  const double fact = (yv[0] + beta * yv[n - 1] / gamma) / (1.0 + z[0] + beta * z[n - 1] / gamma);
  std::vector<double> m(n);
  for (std::size_t i = 0; i < n; ++i)
    m[i] = yv[i] - fact * z[i];
  return m;
}

}  // namespace

CylinderPressureCurve::CylinderPressureCurve(std::vector<double> angle, std::vector<double> p) {
  if (angle.size() != p.size()) {
    fail(common::message("angle and pressure columns differ in length (", angle.size(), " vs ",
                         p.size(), ")"));
  }
  for (std::size_t i = 0; i < angle.size(); ++i) {
    if (!std::isfinite(angle[i]))
      fail(rowText(i, angle[i], p[i]) + ": angle is not finite", i);
    if (!std::isfinite(p[i]) || p[i] <= 0.0) {
      fail(rowText(i, angle[i], p[i]) + ": absolute pressure must be positive and finite", i);
    }
    if (i > 0 && !(angle[i] > angle[i - 1])) {
      fail(common::message(rowText(i, angle[i], p[i]),
                           ": crank angle is not increasing (previous row has ", angle[i - 1],
                           " deg)"),
           i);
    }
  }
  if (angle.size() < 4)
    fail(common::message("needs at least 4 rows, has ", angle.size()));

  const double peak = *std::max_element(p.begin(), p.end());
  const double span = angle.back() - angle.front();
  const double closureTol = 1e-9 * kCycle_deg;
  if (span > kCycle_deg + closureTol) {
    fail(common::message("the table spans ", span, " deg (", angle.front(), " to ", angle.back(),
                         "), more than one 720 deg cycle"));
  }
  if (std::abs(span - kCycle_deg) <= closureTol) {
    if (std::abs(p.back() - p.front()) > 0.005 * peak) {
      fail(common::message("the table is not periodic: pressure at ", angle.back(), " deg (",
                           p.back(), " Pa) differs from the pressure at ", angle.front(), " deg (",
                           p.front(), " Pa) by more than 0.5 % of the peak"));
    }
    angle.pop_back();
    p.pop_back();
  } else {
    double maxStep = 0.0;
    for (std::size_t i = 1; i < angle.size(); ++i)
      maxStep = std::max(maxStep, angle[i] - angle[i - 1]);
    const double gap = angle.front() + kCycle_deg - angle.back();
    if (gap > maxStep * (1.0 + 1e-9)) {
      fail(common::message("the table does not cover the 720 deg cycle: it spans ", angle.front(),
                           " to ", angle.back(), " deg, leaving a gap of ", gap,
                           " deg before the cycle repeats (larger than its largest step, ", maxStep,
                           " deg)"));
    }
  }
  angle_ = std::move(angle);
  p_ = std::move(p);
  m_ = periodicSplineSecondDerivatives(angle_, p_, kCycle_deg);
  requirePositiveBetweenKnots();
  const auto it = std::max_element(p_.begin(), p_.end());
  peak_Pa_ = *it;
  peakAngle_deg_ = angle_[static_cast<std::size_t>(it - p_.begin())];
}

double CylinderPressureCurve::wrap(double a) const {
  double w = std::fmod(a - angle_.front(), kCycle_deg);
  if (w < 0.0)
    w += kCycle_deg;
  return angle_.front() + w;
}

int CylinderPressureCurve::findInterval(double w) const {
  const auto it = std::upper_bound(angle_.begin(), angle_.end(), w);
  return static_cast<int>(it - angle_.begin()) - 1;  // >= 0 because w >= angle_[0]
}

void CylinderPressureCurve::requirePositiveBetweenKnots() const {
  // A cubic spline can undershoot between knots (e.g. around a sharp peak in a coarse
  // table). Find each interval's minimum where the slope vanishes and reject <= 0.
  const std::size_t n = angle_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double a = angle_[i];
    const double b = (i + 1 < n) ? angle_[i + 1] : angle_[0] + kCycle_deg;
    // Slope is quadratic in the angle: sample it finely enough to bracket its roots.
    constexpr int kSamples = 16;
    double prevX = a, prevSlope = calcPressureSlope_Paperdeg(a);
    for (int k = 1; k <= kSamples; ++k) {
      const double x = a + (b - a) * k / kSamples;
      const double slope = calcPressureSlope_Paperdeg(x);
      if (prevSlope < 0.0 && slope >= 0.0) {
        double lo = prevX, hi = x;  // a local minimum lies in [lo, hi]
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          (calcPressureSlope_Paperdeg(mid) < 0.0 ? lo : hi) = mid;
        }
        const double pMin = calcPressure_Pa(0.5 * (lo + hi));
        if (!(pMin > 0.0)) {
          fail(common::message("the interpolated pressure falls to ", pMin, " Pa at ",
                               std::fmod(0.5 * (lo + hi), kCycle_deg), " deg, between row ", i,
                               " (", angle_[i],
                               " deg) and the next; the table is too coarse around a steep "
                               "change - give more points there"),
               i);
        }
      }
      prevX = x;
      prevSlope = slope;
    }
  }
}

CylinderPressureCurve::Segment CylinderPressureCurve::locate(double crankAngle_deg) const {
  if (!std::isfinite(crankAngle_deg))  // a bad query, not a bad table
    throw std::invalid_argument("CylinderPressureCurve: crank angle is not finite");
  const double w = wrap(crankAngle_deg);
  const std::size_t n = angle_.size();
  Segment g;
  g.i = static_cast<std::size_t>(findInterval(w));
  g.j = (g.i + 1) % n;
  const double x1 = (g.i + 1 < n) ? angle_[g.i + 1] : angle_[0] + kCycle_deg;
  g.h = x1 - angle_[g.i];
  g.a = (x1 - w) / g.h;
  g.b = 1.0 - g.a;
  return g;
}

double CylinderPressureCurve::calcPressure_Pa(double crankAngle_deg) const {
  const Segment g = locate(crankAngle_deg);
  return g.a * p_[g.i] + g.b * p_[g.j] +
         ((g.a * g.a * g.a - g.a) * m_[g.i] + (g.b * g.b * g.b - g.b) * m_[g.j]) * g.h * g.h / 6.0;
}

double CylinderPressureCurve::calcPressureSlope_Paperdeg(double crankAngle_deg) const {
  const Segment g = locate(crankAngle_deg);
  return (p_[g.j] - p_[g.i]) / g.h - (3.0 * g.a * g.a - 1.0) / 6.0 * g.h * m_[g.i] +
         (3.0 * g.b * g.b - 1.0) / 6.0 * g.h * m_[g.j];
}

double calcImep_Pa(const CylinderPressureCurve& pressure, const CylinderVolume& volume) {
  // 8-point Gauss-Legendre nodes and weights on [-1, 1].
  static constexpr double xg[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                   0.9602898564975363};
  static constexpr double wg[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                   0.1012285362903763};
  const std::vector<double>& knots = pressure.getAngles_deg();
  const std::size_t n = knots.size();
  const double deg = M_PI / 180.0;
  double work = 0.0;  // closed integral of p dV [J]
  for (std::size_t i = 0; i < n; ++i) {
    const double a = knots[i];
    const double b = (i + 1 < n) ? knots[i + 1] : knots[0] + CylinderPressureCurve::kCycle_deg;
    // dV/dtheta is not a polynomial: sub-intervals of at most 1 deg keep the rule's
    // error far below the table's own accuracy whatever the table spacing.
    const int nSub = std::max(1, static_cast<int>(std::ceil(b - a)));
    const double h = (b - a) / nSub;
    for (int j = 0; j < nSub; ++j) {
      const double mid = a + (j + 0.5) * h, half = 0.5 * h;
      for (int k = 0; k < 4; ++k) {
        for (int sgn = -1; sgn <= 1; sgn += 2) {
          const double t = mid + sgn * half * xg[k];
          work += wg[k] * half * deg * pressure.calcPressure_Pa(t) *
                  volume.calcVolumeDerivative_m3prad(t * deg);
        }
      }
    }
  }
  return work / volume.displacement_m3();
}

}  // namespace pistondyn::mbd
