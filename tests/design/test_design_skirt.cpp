// The design loop on the real lubricated skirt (the gasoline example, coarse and one cycle:
// SkirtStudyDeck.h), through the shipped program. Whole cycles: label `cycle`.
//
// Fit: the Briggs & Stratton example's oil temperature and cold clearance from its tilt
// (motored, windows around the TDCs where the side force is large): a trace made by the
// program at known inputs plus Gaussian noise recovered within two standard errors from
// three starts; the committed example (examples/fit/briggs_stratton_tilt) recovers the
// inputs its trace's header states, and the centre-of-mass height, on which the tilt there
// barely depends, either as not identifiable or with a far larger standard error.
//
// Optimisation: clearance and pin offset for the least fmep with min h/sigma >= 2 on both
// sides and the largest slap energy <= 1.5 mJ, from three DOE seeds. Stated tolerance: each
// optimum is feasible and better than every feasible DOE point; the three optima's objectives
// agree within 1 % and their variables within 5 % of the ranges (the coarse skirt's fmep is
// rough at the 0.5 % level: adaptive steps, the film's active sets). Why 1.5 mJ: scans of
// this coarse deck put the fmep's valley along the pin offset at 0.1 mm, where the largest
// slap energy has a V-shaped minimum (the thrust side's slap on one side of it, the anti-
// thrust side's on the other) that reaches 1 mJ at a clearance of 54 um; a bound of 1 mJ
// leaves a feasible cusp on which derivative-free local searches stop apart by 2-4 % of
// fmep. At 1.5 mJ the least fmep lies at the clearance's upper bound (fmep falls with
// clearance: 2.92 kPa at 40 um, 2.45 kPa at 60 um) inside the slap bound, a well-posed
// optimum the seeds must agree on.

#include <nlohmann/json.hpp>

#include "DesignProgramFixture.h"
#include "NoisyTrace.h"
#include "SkirtStudyDeck.h"

namespace {

using namespace pistondyn_test;

Invocation invokeIn(const fs::path& dir, const std::string& args) {
  const std::string cmd = "cd " + dir.string() + " && " + PISTONDYN_EXE + " " + args + " > " +
                          (dir / "stdout.txt").string() + " 2> " + (dir / "stderr.txt").string();
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(dir / "stdout.txt"),
          readFile(dir / "stderr.txt")};
}

struct SkirtOptimum {
  double objective, clearance, pinOffset;
};

class SkirtOptimize : public SkirtScratchDeck {
 protected:
  SkirtOptimum runSeed(int seed) const {
    const fs::path dir = dir_ / ("seed" + std::to_string(seed));
    fs::create_directories(dir);
    for (const auto& entry : fs::directory_iterator(dir_)) {
      if (entry.is_regular_file())
        fs::copy_file(entry.path(), dir / entry.path().filename());
    }
    std::ofstream(dir / "opt.yaml") << "base_deck: engine.yaml\nset:\n" + fastSkirtSet() + gasolineColdShapesSet() +
                                           "variables:\n"
                                           "  liner.cold_radial_clearance_um: [25, 60]\n"
                                           "  geometry.pin_offset_mm: [-1, 1]\n"
                                           "objective: fmep_kPa\n"
                                           "constraints:\n"
                                           "  min_h_over_sigma: {min: 2.0}\n"
                                           "  slap_energy_max_mJ: {max: 1.5}\n"
                                           "method:\n"
                                           "  doe_samples: 10\n"
                                           "  starts: 2\n"
                                           "  max_evaluations: 50\n"
                                           "  seed: " +
                                           std::to_string(seed) + "\n";
    const Invocation r = invokeIn(dir, "optimize opt.yaml --out out --quiet");
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    const auto result = nlohmann::json::parse(readFile(dir / "out" / "result.json"));
    const auto& best = result.at("optimum");
    EXPECT_TRUE(best["feasible"].get<bool>());
    const CsvRows h = readCsvRows(dir / "out" / "history.csv");
    int doe = 0;
    for (std::size_t i = 0; i < h.rows.size(); ++i) {
      if (h.rows[i].at("stage") != "doe" || h.rows[i].at("status") != "ok")
        continue;
      ++doe;
      if (h.rows[i].at("feasible") != "true")
        continue;  // an infeasible design may well have the lower fmep
      EXPECT_LT(best["objective"].get<double>(), h.number(i, "objective")) << "DOE row " << i + 1;
    }
    EXPECT_EQ(doe, 10);
    // The optimum's run folder holds the figures the history reports, and meets the bounds.
    const auto summary =
        nlohmann::json::parse(readFile(dir / "out" / "optimum" / "run" / "summary.json"));
    const auto& f = summary["results"];
    EXPECT_EQ(f["fmep_kPa"].get<double>(), best["objective"].get<double>());
    EXPECT_GE(std::min(f["min_h_over_sigma_thrust"].get<double>(),
                       f["min_h_over_sigma_antithrust"].get<double>()),
              2.0 * (1 - 1e-4));
    EXPECT_LE(f["slap_energy_max_mJ"].get<double>(), 1.5 * (1 + 1e-4));
    return {best["objective"].get<double>(),
            best["variables"]["liner.cold_radial_clearance_um"].get<double>(),
            best["variables"]["geometry.pin_offset_mm"].get<double>()};
  }
};

TEST_F(SkirtOptimize, ThreeSeedsFindFeasibleOptimaThatAgree) {
  std::vector<SkirtOptimum> optima;
  for (const int seed : {1, 2, 3})
    optima.push_back(runSeed(seed));
  for (const auto& a : optima) {
    for (const auto& b : optima) {
      EXPECT_NEAR(a.objective, b.objective, 0.01 * std::min(a.objective, b.objective));
      EXPECT_NEAR(a.clearance, b.clearance, 0.05 * 35.0);
      EXPECT_NEAR(a.pinOffset, b.pinOffset, 0.05 * 2.0);
    }
  }
}

// ---- fit -------------------------------------------------------------------------------

const std::string kBriggsDir =
    std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/briggs_stratton_500";

class SkirtFit : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pistondyn_fit_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(SkirtFit, RecoversOilTemperatureAndClearanceFromThreeStarts) {
  std::string set;
  for (const std::string& line : {fastSkirtSet(""), briggsEdgeRockingBarrelSet("")}) {
    std::istringstream in(line);
    for (std::string kv; std::getline(in, kv);)
      set += " --set " + kv.replace(kv.find(": "), 2, "=");
  }
  const Invocation truth =
      invokeIn(dir_, "run " + kBriggsDir + "/engine.yaml --out truth --quiet --no-plot" + set);
  ASSERT_EQ(truth.exitCode, 0) << truth.err;
  writeNoisyTrace(dir_ / "truth", "tilt_mrad", 0.05, 7, dir_ / "tilt.csv");
  int k = 0;
  for (const auto& [t0, c0] :
       {std::pair{30.0, 70.0}, std::pair{65.0, 40.0}, std::pair{45.0, 55.0}}) {
    const std::string out = "fit" + std::to_string(++k);
    std::ofstream(dir_ / "fit.yaml")
        << "base_deck: " + kBriggsDir + "/engine.yaml\nset:\n" + fastSkirtSet() +
               briggsEdgeRockingBarrelSet() +
               "parameters:\n"
               "  liner.oil.temperature_degC: {bounds: [25, 70], start: " +
               std::to_string(t0) +
               "}\n"
               "  liner.cold_radial_clearance_um: {bounds: [35, 75], start: " +
               std::to_string(c0) +
               "}\n"
               "measured:\n"
               "  - file: tilt.csv\n"
               "    column: tilt_mrad\n"
               "    windows_deg: [[0, 120], [600, 720]]\n";
    const Invocation r = invokeIn(dir_, "fit fit.yaml --out " + out + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    const auto j = nlohmann::json::parse(readFile(dir_ / out / "result.json"));
    for (const auto& [index, truthValue] : {std::pair{0, 40.0}, std::pair{1, 53.0}}) {
      const auto& p = j["parameters"][index];
      ASSERT_TRUE(p["identifiable"].get<bool>()) << p;
      EXPECT_LT(std::fabs(p["value"].get<double>() - truthValue),
                2 * p["standard_error"].get<double>())
          << out << " " << p;
    }
  }
}

TEST_F(SkirtFit, TheCommittedExampleRecoversItsStatedInputs) {
  const std::string example =
      std::string(PISTONDYN_SOURCE_DIR) + "/examples/fit/briggs_stratton_tilt";
  // The trace's header states how it was made.
  EXPECT_NE(readFile(example + "/measured_tilt.csv")
                .find("liner.oil.temperature_degC=40, liner.cold_radial_clearance_um=53, "
                      "piston.com_above_pin_mm=6"),
            std::string::npos);
  const Invocation r = invokeIn(dir_, "fit " + example + "/fit.yaml --out out --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(readFile(dir_ / "out" / "result.json"));
  const auto& temperature = j["parameters"][0];
  ASSERT_TRUE(temperature["identifiable"].get<bool>()) << temperature;
  EXPECT_LT(std::fabs(temperature["value"].get<double>() - 40.0),
            2 * temperature["standard_error"].get<double>())
      << temperature;
  // The centre-of-mass height barely moves the tilt in these windows: either reported as not
  // identifiable, or recovered (within two standard errors) with a standard error, relative
  // to its range, at least ten times that of the temperature.
  const auto& com = j["parameters"][1];
  if (com["identifiable"].get<bool>()) {
    EXPECT_LT(std::fabs(com["value"].get<double>() - 6.0),
              2 * com["standard_error"].get<double>())
        << com;
    const double relativeCom = com["standard_error"].get<double>() / (10.0 - 2.0);
    const double relativeTemperature = temperature["standard_error"].get<double>() / (70.0 - 25.0);
    EXPECT_GT(relativeCom, 10.0 * relativeTemperature) << com;
  } else {
    EXPECT_TRUE(com["value"].is_null());
    EXPECT_NE(com["note"].get<std::string>().find("not identifiable"), std::string::npos);
  }
}

}  // namespace
