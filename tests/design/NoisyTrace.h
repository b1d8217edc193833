#pragma once
// Synthetic measured traces for the fit tests: a run's column plus Gaussian noise of a
// stated standard deviation, reproducible on every platform (std::mt19937_64, whose output
// the C++ standard fixes, with Box-Muller written out here).

#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <string>

#include "DesignProgramFixture.h"

namespace pistondyn_test {

class GaussianNoise {
 public:
  explicit GaussianNoise(std::uint64_t seed) : rng_(seed) {}
  double next(double sigma) {
    const double u1 = uniform(), u2 = uniform();
    return sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
  }

 private:
  double uniform() { return (static_cast<double>(rng_() >> 11) + 0.5) * 0x1.0p-53; }
  std::mt19937_64 rng_;
};

// Writes `target` (CSV crank_angle_deg,<column>) from the run folder's cycle.csv rows in
// [0, 720) with noise of standard deviation sigma added.
inline void writeNoisyTrace(const fs::path& runFolder, const std::string& column, double sigma,
                            std::uint64_t seed, const fs::path& target) {
  const CsvRows run = readCsvRows(runFolder / "cycle.csv");
  GaussianNoise noise(seed);
  std::ofstream out(target);
  out << "# synthetic: " << column << " of " << runFolder.string() << " + N(0, " << sigma
      << ") noise, seed " << seed << "\n";
  out << "crank_angle_deg," << column << "\n";
  out.precision(17);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double a = run.number(i, "crank_angle_deg");
    if (a >= 0.0 && a < 720.0)
      out << run.rows[i].at("crank_angle_deg") << ',' << run.number(i, column) + noise.next(sigma)
          << "\n";
  }
}

}  // namespace pistondyn_test
