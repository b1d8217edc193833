#pragma once
// Quadrature shared by the flow-factor tests (reference integrals computed independently
// of the closed forms under test).

#include <functional>

namespace pistondyn::lubrication::test {

// Composite Simpson rule for Int_a^b f on n (even) panels; error O(((b - a)/n)^4 f'''').
inline double simpson(const std::function<double(double)>& f, double a, double b, int n) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) {
    s += f(a + i * h) * (i % 2 == 1 ? 4.0 : 2.0);
  }
  return s * h / 3.0;
}

}  // namespace pistondyn::lubrication::test
