#pragma once
// n-point Gauss-Legendre nodes and weights on [-1, 1] (exact for polynomials of degree
// 2n - 1), by Newton's iteration on the Legendre recurrence: the quadrature the mapping,
// skirt and FE-compliance tests integrate their references with, written once and
// independent of the library under test.

#include <cmath>
#include <utility>
#include <vector>

namespace pistondyn::test {

inline std::pair<std::vector<double>, std::vector<double>> gaussLegendre(int n) {
  constexpr double kPi = 3.14159265358979323846264338327950;
  std::vector<double> x(n), w(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16)
        break;
    }
    x[i] = z;
    w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
  return {x, w};
}

}  // namespace pistondyn::test
