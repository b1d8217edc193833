#pragma once
// Independent reference for the Greenwood–Tripp integrals, written for the tests only.
//
//   F_n(λ) = 1/√(2π) ∫_0^∞ t^n e^(−(t+λ)²/2) dt      (t = s − λ)
//
// evaluated in long double by adaptive composite Gauss–Legendre quadrature after the
// substitution t = u², which turns the t^n end-point behaviour into the smooth integrand
// 2u^(2n+1) e^(−(u²+λ)²/2). Nothing here is shared with the library, which uses Chebyshev
// tables of log F_n generated from the parabolic-cylinder-function form.

#include <cmath>
#include <cstddef>
#include <vector>

namespace pistondyn::contact_forces::test {

// n-point Gauss–Legendre rule on [−1, 1], nodes by Newton's method on P_n in long double.
struct GaussLegendreRule {
  std::vector<long double> nodes;
  std::vector<long double> weights;

  explicit GaussLegendreRule(int n) : nodes(n), weights(n) {
    const long double pi = 3.141592653589793238462643383279502884L;
    for (int i = 0; i < n; ++i) {
      long double x = std::cos(pi * (i + 0.75L) / (n + 0.5L));  // Tricomi's initial guess
      long double derivative = 0.0L;
      for (int iteration = 0; iteration < 100; ++iteration) {
        long double p0 = 1.0L;
        long double p1 = x;
        for (int k = 2; k <= n; ++k) {
          const long double p2 = ((2.0L * k - 1.0L) * x * p1 - (k - 1.0L) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        derivative = n * (x * p1 - p0) / (x * x - 1.0L);
        const long double step = p1 / derivative;
        x -= step;
        if (std::fabs(step) < 1e-21L) {
          break;
        }
      }
      nodes[i] = x;
      weights[i] = 2.0L / ((1.0L - x * x) * derivative * derivative);
    }
  }
};

class ReferenceTailQuadrature {
 public:
  ReferenceTailQuadrature() : rule_(20) {}

  // F_n(λ) for any real n > −1.
  long double tail(long double n, long double lambda) const {
    const long double sqrt2pi = 2.506628274631000502415765284811045253L;
    if (lambda >= 0.0L) {
      // e^(−(u²+λ)²/2) = e^(−λ²/2) · e^(−u⁴/2 − λu²); the factor is taken out so that the
      // adaptive rule works on O(1) numbers. The integrand is below e^(−90) of its scale
      // beyond u² = −λ + √(λ² + 180).
      const long double upper = std::sqrt(-lambda + std::sqrt(lambda * lambda + 180.0L));
      auto f = [n, lambda](long double u) {
        const long double u2 = u * u;
        return 2.0L * std::pow(u, 2.0L * n + 1.0L) * std::exp(-0.5L * u2 * u2 - lambda * u2);
      };
      return integrate(f, 0.0L, upper) * std::exp(-0.5L * lambda * lambda) / sqrt2pi;
    }
    // Peak at u² = −λ with width ~1 in u²; beyond ±14 the integrand is below e^(−98).
    const long double a = -lambda;
    const long double lower = a > 14.0L ? std::sqrt(a - 14.0L) : 0.0L;
    const long double upper = std::sqrt(a + 14.0L);
    auto f = [n, lambda](long double u) {
      const long double s = u * u + lambda;
      return 2.0L * std::pow(u, 2.0L * n + 1.0L) * std::exp(-0.5L * s * s);
    };
    return integrate(f, lower, upper) / sqrt2pi;
  }

 private:
  template <class F>
  long double panel(const F& f, long double a, long double b) const {
    const long double half = 0.5L * (b - a);
    const long double mid = 0.5L * (a + b);
    long double sum = 0.0L;
    for (std::size_t i = 0; i < rule_.nodes.size(); ++i) {
      sum += rule_.weights[i] * f(mid + half * rule_.nodes[i]);
    }
    return sum * half;
  }

  template <class F>
  long double adapt(const F& f, long double a, long double b, long double whole, long double tol,
                    int depth) const {
    const long double mid = 0.5L * (a + b);
    const long double left = panel(f, a, mid);
    const long double right = panel(f, mid, b);
    const long double both = left + right;
    if (depth >= 12 || std::fabs(both - whole) <= tol) {
      return both;
    }
    return adapt(f, a, mid, left, 0.5L * tol, depth + 1) +
           adapt(f, mid, b, right, 0.5L * tol, depth + 1);
  }

  template <class F>
  long double integrate(const F& f, long double a, long double b) const {
    // A first pass on 32 panels gives the scale; then each panel is halved until its
    // 20-point result and the sum over its halves agree to 1e-18 of the total (long double
    // carries 64 bits, eps = 1.1e-19, so tighter would never be met).
    constexpr int kPanels = 32;
    const long double width = (b - a) / kPanels;
    long double estimate = 0.0L;
    std::vector<long double> panels(kPanels);
    for (int k = 0; k < kPanels; ++k) {
      panels[k] = panel(f, a + k * width, a + (k + 1) * width);
      estimate += panels[k];
    }
    const long double tol = 1e-18L * std::fabs(estimate);
    long double total = 0.0L;
    for (int k = 0; k < kPanels; ++k) {
      total += adapt(f, a + k * width, a + (k + 1) * width, panels[k], tol, 0);
    }
    return total;
  }

  GaussLegendreRule rule_;
};

}  // namespace pistondyn::contact_forces::test
