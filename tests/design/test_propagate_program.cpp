// `pistondyn propagate` through the program on the analytic test liner, whose figures are
// closed-form functions of deck keys (AnalyticTestLiner.h): for an input with a linear
// response the bands match the analytic propagation within the Latin hypercube's sampling
// error (one input: each of the n samples lies in its own of n equal strata, so every
// p-quantile lies within (range of the response) / n of the exact one), the curves' bands
// at every crank angle too; two inputs with a linear response: the mean within its
// stratified bound and the quantiles of the exact (trapezoidal) distribution within three
// sampling standard errors; the deck's EST marks become the inputs; resume; bad input.

#include <nlohmann/json.hpp>

#include "AnalyticTestLiner.h"
#include "DesignProgramFixture.h"

namespace {

using namespace pistondyn_test;

class PropagateProgram : public DesignProgram {
 protected:
  nlohmann::json result(const std::string& out) const {
    return nlohmann::json::parse(readFile(dir_ / out / "result.json"));
  }
};

TEST_F(PropagateProgram, ALinearResponseMatchesTheAnalyticPropagation) {
  // fmep = fmep_offset + ((40 - 40)/10)^2 + ((0.5 - 0.5)/0.5)^2 = offset with the deck's
  // clearance 40 um and pin offset 0.5 mm; the offset uniform on [1, 3]: so is fmep.
  constexpr int n = 40;
  write("prop.yaml",
        "base_deck: engine.yaml\n"
        "inputs:\n"
        "  liner.fmep_offset_kPa: [1, 3]\n"
        "samples: 40\n"
        "figures: [fmep_kPa, hot_clearance_um]\n"
        "curves: [analytic_signal_mrad]\n");
  const Invocation r = invoke("propagate prop.yaml --out out --jobs 2 --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const auto j = result("out");
  const auto& f = j["figures"]["fmep_kPa"];
  for (const auto& [key, p] :
       {std::pair{"p05", 0.05}, std::pair{"p50", 0.5}, std::pair{"p95", 0.95}})
    EXPECT_NEAR(f[key].get<double>(), 1.0 + 2.0 * p, 2.0 / n) << key;
  // The sample mean of a stratified uniform: within half a stratum of the exact 2 kPa.
  EXPECT_NEAR(f["mean"].get<double>(), 2.0, 1.0 / n);
  EXPECT_EQ(f["samples"].get<int>(), n);
  EXPECT_NEAR(f["baseline"].get<double>(), 1.0, 1e-12);  // the liner's default offset
  // A figure the input does not move has no band at all.
  EXPECT_EQ(j["figures"]["hot_clearance_um"]["p05"], j["figures"]["hot_clearance_um"]["p95"]);
  // Each sample's fmep is its offset (samples.csv).
  const CsvRows s = readCsvRows(dir_ / "out" / "samples.csv");
  ASSERT_EQ(s.rows.size(), static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < s.rows.size(); ++i)
    EXPECT_NEAR(s.number(i, "fmep_kPa"), s.number(i, "liner.fmep_offset_kPa"), 1e-12);
}

TEST_F(PropagateProgram, CurveBandsMatchTheAnalyticPropagationAtEveryAngle) {
  // signal = A sin(theta), A uniform on [1, 2]: at each angle its p-quantile is
  // (1 + p) sin(theta) where sin >= 0 and (2 - p) sin(theta) where sin < 0.
  constexpr int n = 30;
  write("prop.yaml",
        "base_deck: engine.yaml\n"
        "inputs:\n"
        "  liner.signal_amplitude_mrad: [1, 2]\n"
        "samples: 30\n"
        "figures: [fmep_kPa]\n"
        "curves: [analytic_signal_mrad]\n");
  const Invocation r = invoke("propagate prop.yaml --out out --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const CsvRows b = readCsvRows(dir_ / "out" / "bands.csv");
  ASSERT_EQ(b.rows.size(), 73u);  // 0, 10, ..., 720
  for (std::size_t i = 0; i < b.rows.size(); ++i) {
    const double s = std::sin(b.number(i, "crank_angle_deg") * M_PI / 180.0);
    for (const auto& [column, p] :
         {std::pair{"analytic_signal_mrad_p05", 0.05}, std::pair{"analytic_signal_mrad_p50", 0.5},
          std::pair{"analytic_signal_mrad_p95", 0.95}}) {
      const double exact = s >= 0 ? (1 + p) * s : (2 - p) * s;
      EXPECT_NEAR(b.number(i, column), exact, std::fabs(s) / n + 1e-12)
          << column << " at " << b.rows[i].at("crank_angle_deg");
    }
    EXPECT_NEAR(b.number(i, "analytic_signal_mrad_baseline"), s, 1e-12);
  }
}

TEST_F(PropagateProgram, TwoInputsOfALinearResponseMatchTheTrapezoidalDistribution) {
  // min h/sigma (thrust) = c/10 - e, c uniform on [30, 50] um, e uniform on [0, 1] mm: the
  // difference of U(3, 5) and U(0, 1), a trapezoid on [2, 5] with quantiles 2 + sqrt(4p)
  // below p = 1/4, 3 + 2 (p - 1/4) up to 3/4, 5 - sqrt(4 (1 - p)) above.
  constexpr int n = 64;
  write("prop.yaml",
        "base_deck: engine.yaml\n"
        "inputs:\n"
        "  liner.clearance_um: [30, 50]\n"
        "  geometry.pin_offset_mm: [0, 1]\n"
        "samples: 64\n"
        "seed: 5\n"
        "figures: [min_h_over_sigma_thrust]\n"
        "curves: [analytic_signal_mrad]\n");
  const Invocation r = invoke("propagate prop.yaml --out out --jobs 2 --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const auto j = result("out");
  const auto& f = j["figures"]["min_h_over_sigma_thrust"];
  auto quantile = [](double p) {
    return p < 0.25    ? 2 + std::sqrt(4 * p)
           : p <= 0.75 ? 3 + 2 * (p - 0.25)
                       : 5 - std::sqrt(4 * (1 - p));
  };
  auto density = [](double z) { return z < 3 ? (z - 2) / 2 : z <= 4 ? 0.5 : (5 - z) / 2; };
  for (const auto& [key, p] :
       {std::pair{"p05", 0.05}, std::pair{"p50", 0.5}, std::pair{"p95", 0.95}}) {
    const double q = quantile(p);
    const double se = std::sqrt(p * (1 - p) / n) / density(q);  // of a simple random sample
    EXPECT_NEAR(f[key].get<double>(), q, 3 * se) << key;
  }
  // Each input's stratified sample mean is within half a stratum of its own: c/10 within
  // (20/10) / (2n), e within 1 / (2n).
  EXPECT_NEAR(f["mean"].get<double>(), 3.5, 1.0 / n + 0.5 / n);
}

TEST_F(PropagateProgram, TheDecksEstMarksBecomeTheInputs) {
  // The gasoline deck marks its masses, inertias and offsets EST (pin offset 0.5, crank
  // offset 0); a mark on the liner section and a comment that only starts with EST added.
  editDeck("  clearance_um: 40\n", "  clearance_um: 40   # EST\n");
  editDeck("  bore_mm: 74.5", "  bore_mm: 74.5  # ESTIMATED is not the mark,");
  write("prop.yaml",
        "base_deck: engine.yaml\n"
        // The imep the deck states changes with the rod length and the
        // compression ratio: not checked here.
        "set: {piston.com_above_pin_mm: 5.5, gas.stated_imep_kPa: null}\n"
        "inputs:\n"
        "  liner.clearance_um: [35, 36]\n"
        "est_inputs: 0.1\n"
        "samples: 4\n"
        "figures: [fmep_kPa]\n"
        "curves: [tilt_mrad]\n");
  const Invocation r = invoke("propagate prop.yaml --out out --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const auto j = result("out");
  std::map<std::string, std::pair<double, double>> inputs;
  for (const auto& i : j["inputs"])
    inputs[i["key"].get<std::string>()] = {i["lower"].get<double>(), i["upper"].get<double>()};
  // The listed range is kept, the set key stays fixed, zeros are left out, the other EST
  // numbers are varied by +-10 %.
  EXPECT_EQ(inputs.at("liner.clearance_um"), std::make_pair(35.0, 36.0));
  EXPECT_FALSE(inputs.count("piston.com_above_pin_mm"));
  EXPECT_FALSE(inputs.count("geometry.bore_mm"));
  EXPECT_FALSE(inputs.count("geometry.crank_offset_mm"));
  EXPECT_NEAR(inputs.at("piston.mass_g").first, 189.0, 1e-12);
  EXPECT_NEAR(inputs.at("piston.mass_g").second, 231.0, 1e-12);
  EXPECT_NEAR(inputs.at("geometry.pin_offset_mm").first, 0.45, 1e-12);
  EXPECT_NEAR(inputs.at("pin.inertia_kg_mm2").second, 3.3, 1e-12);
  const auto zeros = j["est_zero_not_varied"].get<std::vector<std::string>>();
  EXPECT_NE(std::find(zeros.begin(), zeros.end(), "geometry.crank_offset_mm"), zeros.end());
}

TEST_F(PropagateProgram, ResumingRunsNothingAgain) {
  write("prop.yaml",
        "base_deck: engine.yaml\ninputs:\n  liner.fmep_offset_kPa: [1, 3]\n"
        "samples: 6\nfigures: [fmep_kPa]\ncurves: [tilt_mrad]\n");
  ASSERT_EQ(invoke("propagate prop.yaml --out out --quiet").exitCode, 0);
  const std::string samples = readFile(dir_ / "out" / "samples.csv");
  ASSERT_EQ(invoke("propagate prop.yaml --out out --quiet").exitCode, 0);
  EXPECT_EQ(readFile(dir_ / "out" / "samples.csv"), samples);
  EXPECT_EQ(result("out")["evaluations_run_now"].get<int>(), 0);
  EXPECT_EQ(result("out")["evaluations_from_earlier_run"].get<int>(), 7);
}

TEST_F(PropagateProgram, BadInputIsRefusedWithNothingWritten) {
  const std::string good =
      "base_deck: engine.yaml\n"
      "inputs:\n"
      "  liner.fmep_offset_kPa: [1, 3]\n"
      "samples: 6\n"
      "figures: [fmep_kPa]\n"
      "curves: [tilt_mrad]\n";
  const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> cases = {
      {{"[1, 3]", "[3, 1]"}, "prop.yaml:3: inputs.liner.fmep_offset_kPa: bounds [3, 1]"},
      {{"figures: [fmep_kPa]", "figures: [fmep]"}, "prop.yaml:5: figures: 'fmep' is not a figure"},
      {{"curves: [tilt_mrad]", "curves: [tilt_deg]"},
       "prop.yaml:6: curves: the run writes no column tilt_deg"},
      {{"samples: 6", "samples: 1"}, "prop.yaml:4: samples: expected a whole number from 2"},
      {{"samples: 6", "samples: 6\nest_inputs: 1.5"},
       "prop.yaml:5: est_inputs: expected the "
       "relative half-range"},
      {{"  liner.fmep_offset_kPa: [1, 3]", "  liner.model: [1, 3]"},
       "prop.yaml:3: inputs.liner.model: "},
  };
  for (const auto& [edit, expected] : cases) {
    std::string text = good;
    text.replace(text.find(edit.first), edit.first.size(), edit.second);
    write("prop.yaml", text);
    const auto before = listFiles();
    const Invocation r = invoke("propagate prop.yaml --out out --quiet");
    EXPECT_EQ(r.exitCode, 1) << expected << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(listFiles(), before);
    EXPECT_FALSE(fs::exists(dir_ / "out"));
  }
  const Invocation h = invoke("propagate --help");
  EXPECT_EQ(h.exitCode, 0);
  for (const char* text : {"PROP", "EST", "5 / 50 / 95", "Exit codes", "mpirun -np K"})
    EXPECT_NE(h.out.find(text), std::string::npos) << text;
}

}  // namespace
