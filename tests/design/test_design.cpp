// pistondyn::design's parts on their own: the parametric skirt profile against the
// examples' parabolic barrel tables and its defining properties, the figures read from a
// summary, the evaluation store's ids.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "pistondyn/design/Evaluations.h"
#include "pistondyn/design/Figures.h"
#include "pistondyn/design/Propagate.h"
#include "pistondyn/design/SkirtProfileDesign.h"
#include "pistondyn/io/CsvTable.h"

namespace {

namespace fs = std::filesystem;
using namespace pistondyn;
using design::SkirtProfileShape;

const std::string kBriggsProfile =
    std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/briggs_stratton_500/skirt_profile.csv";

// The Briggs & Stratton skirt: 10 mm above to 18 mm below the pin.
constexpr double kTop_mm = 10.0, kBottom_mm = -18.0;

// The example's barrel 0.12 (y + 3)^2 as the four numbers: edge drops 0.12 L^2.
SkirtProfileShape briggsBarrel() {
  return {0.12 * 13.0 * 13.0, 0.12 * 15.0 * 15.0, -3.0, 0.12};
}

TEST(SkirtProfileDesign, ReproducesTheExampleBarrelTableOverTheSkirt) {
  // The committed table (examples/engines/briggs_stratton_500) tabulates 0.12 (y + 3)^2
  // to four decimals: with the edge drops of that parabola the quartic term vanishes.
  const io::CsvTable t =
      io::readCsvTable(kBriggsProfile, {"height_above_pin_mm", "radial_drop_um"});
  int compared = 0;
  for (const auto& row : t.rows) {
    const double y = row[0], drop = row[1];
    if (y < kBottom_mm || y > kTop_mm)
      continue;
    EXPECT_NEAR(design::calcProfileDrop_um(briggsBarrel(), kBottom_mm, kTop_mm, y), drop, 5e-5)
        << "y = " << y;  // the table's last digit
    ++compared;
  }
  EXPECT_EQ(compared, 57);  // every 0.5 mm from -18 to 10
}

TEST(SkirtProfileDesign, MeetsItsFourNumbers) {
  const SkirtProfileShape s{30.0, 12.0, -4.0, 0.05};
  auto drop = [&](double y) { return design::calcProfileDrop_um(s, kBottom_mm, kTop_mm, y); };
  EXPECT_DOUBLE_EQ(drop(kTop_mm), 30.0);
  EXPECT_DOUBLE_EQ(drop(kBottom_mm), 12.0);
  EXPECT_EQ(drop(-4.0), 0.0);
  // Slope 0 and second derivative 2c at the minimum-clearance point, from either side
  // (central differences: errors O(h^2) of the quartic's c4 h^2 ~ 1e-7 at h = 1e-3).
  const double h = 1e-3;
  for (const double side : {1.0, -1.0}) {
    const double y = -4.0 + side * 0.5;  // half a millimetre off, on each branch
    const double second = (drop(y + h) - 2 * drop(y) + drop(y - h)) / (h * h);
    // On the branch: 2c + 12 (d - c L^2) s^2 / L^4, in closed form.
    const double L = 14.0;  // from -4 mm to either edge
    const double d = side > 0 ? 30.0 : 12.0;
    EXPECT_NEAR(second, 2 * 0.05 + 12 * (d - 0.05 * L * L) * 0.25 / std::pow(L, 4), 1e-5);
  }
  EXPECT_NEAR((drop(-4.0 + h) - drop(-4.0 - h)) / (2 * h), 0.0, 1e-9);
  EXPECT_NEAR((drop(-4.0 + h) + drop(-4.0 - h)) / (h * h), 2 * 0.05, 1e-6);
}

TEST(SkirtProfileDesign, TableCoversTheSkirtWithItsPoints) {
  const SkirtProfileShape s{30.0, 12.0, -4.3, 0.05};
  std::istringstream in(design::makeProfileTable(s, kBottom_mm, kTop_mm, 21));
  std::string line;
  bool header = false, sawMin = false, sawTop = false, sawBottom = false;
  double previous = -1e9, first = 0.0, last = 0.0;
  int rows = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    if (!header) {
      EXPECT_EQ(line, "height_above_pin_mm,radial_drop_um");
      header = true;
      continue;
    }
    const double y = std::stod(line.substr(0, line.find(',')));
    const double d = std::stod(line.substr(line.find(',') + 1));
    EXPECT_GT(y, previous);
    if (rows++ == 0)
      first = y;
    last = previous = y;
    sawMin = sawMin || (y == -4.3 && d == 0.0);
    sawTop = sawTop || (y == kTop_mm && d == 30.0);
    sawBottom = sawBottom || (y == kBottom_mm && d == 12.0);
  }
  EXPECT_TRUE(sawMin && sawTop && sawBottom);
  EXPECT_DOUBLE_EQ(first, kBottom_mm - 0.5);
  EXPECT_DOUBLE_EQ(last, kTop_mm + 0.5);
  EXPECT_GE(rows, 21);
}

TEST(SkirtProfileDesign, RejectsAMinimumOutsideTheSkirt) {
  for (const double ym : {kTop_mm, kBottom_mm, 11.0, -30.0, std::nan("")}) {
    const SkirtProfileShape s{30.0, 12.0, ym, 0.05};
    EXPECT_THROW(design::makeProfileTable(s, kBottom_mm, kTop_mm), std::invalid_argument) << ym;
  }
}

TEST(RunFigures, BothSidesMinimumAndMissingFigures) {
  const design::RunFigures f(
      R"({"results": {"fmep_kPa": 2.5, "min_h_over_sigma_thrust": 3.25,
          "min_h_over_sigma_antithrust": 1.5, "converged": false}})");
  EXPECT_EQ(f.get("fmep_kPa"), 2.5);
  EXPECT_EQ(f.get("min_h_over_sigma"), 1.5);
  EXPECT_FALSE(f.get("slap_energy_max_mJ"));
  EXPECT_FALSE(f.get("converged"));  // not a number
  EXPECT_TRUE(design::isKnownFigure("min_h_over_sigma"));
  EXPECT_FALSE(design::isKnownFigure("fmep"));
  EXPECT_THROW(design::RunFigures("{}"), std::runtime_error);
}

TEST(EvaluationStore, IdsFollowWhatDecidesTheRunAndNothingElse) {
  const design::EvaluationStore a("/data/a", "/x/engine.yaml", {"simulation.cycles=1"}, "ctx");
  const design::EvaluationStore moved("/elsewhere/b", "/y/engine.yaml", {"simulation.cycles=1"},
                                      "ctx");
  const design::EvaluationStore other("/data/a", "/x/engine.yaml", {"simulation.cycles=1"}, "ctx2");
  design::EvaluationRequest r;
  r.overrides = {"geometry.pin_offset_mm=0.5"};
  design::EvaluationRequest s = r;
  s.overrides = {"geometry.pin_offset_mm=0.50000000000000011"};
  design::EvaluationRequest withFile = r;
  withFile.files = {{"skirt_profile.csv", "height_above_pin_mm,radial_drop_um\n0,0\n1,1\n"}};
  withFile.fileKey = "liner.skirt_profile.axial_profile_file";
  EXPECT_EQ(a.getId(r).size(), 16u);
  EXPECT_EQ(a.getId(r), moved.getId(r));  // the context decides, not the folder
  EXPECT_NE(a.getId(r), other.getId(r));
  EXPECT_NE(a.getId(r), a.getId(s));
  EXPECT_NE(a.getId(r), a.getId(withFile));
  // Requests and results survive their text form (what MPI ranks exchange).
  const auto back = design::decodeRequest(design::encodeRequest(withFile));
  EXPECT_EQ(back.overrides, withFile.overrides);
  EXPECT_EQ(back.files, withFile.files);
  EXPECT_EQ(back.fileKey, withFile.fileKey);
  design::EvaluationResult res;
  res.id = "0123456789abcdef";
  res.ok = true;
  res.summaryJson = "{\"results\": {\"fmep_kPa\": 0.1}}\n";
  res.wallTime_s = 0.1 + 0.2;
  const auto back2 = design::decodeResult(design::encodeResult(res));
  EXPECT_EQ(back2.id, res.id);
  EXPECT_EQ(back2.summaryJson, res.summaryJson);
  EXPECT_EQ(back2.wallTime_s, res.wallTime_s);
  const auto store = design::EvaluationStore::decode(a.encode());
  EXPECT_EQ(store.getId(r), a.getId(r));
  EXPECT_EQ(store.getDirectory(), a.getDirectory());
}

}  // namespace

namespace {

TEST(Quantile, LinearBetweenOrderStatisticsAsNumpysDefault) {
  // numpy.quantile([4, 1, 3, 2], p) with the default 'linear' method.
  const std::vector<double> v = {4, 1, 3, 2};
  EXPECT_DOUBLE_EQ(pistondyn::design::calcQuantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(pistondyn::design::calcQuantile(v, 0.05), 1.15);
  EXPECT_DOUBLE_EQ(pistondyn::design::calcQuantile(v, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(pistondyn::design::calcQuantile(v, 0.95), 3.85);
  EXPECT_DOUBLE_EQ(pistondyn::design::calcQuantile(v, 1.0), 4.0);
  EXPECT_TRUE(std::isnan(pistondyn::design::calcQuantile({}, 0.5)));
  const auto b = pistondyn::design::calcBand(v);
  EXPECT_DOUBLE_EQ(b.mean, 2.5);
  EXPECT_DOUBLE_EQ(b.std, std::sqrt(5.0 / 3.0));  // sample standard deviation
}

TEST(EstimatedKeys, NumbersWhoseCommentCarriesTheMarkWithTheirSectionPath) {
  const auto path = fs::temp_directory_path() / "pistondyn_est_keys.yaml";
  std::ofstream(path) << "# EST in a comment line is no key\n"
                         "geometry:\n"
                         "  bore_mm: 74.5   # [V]\n"
                         "  pin_offset_mm: 0.5   # EST: usual\n"
                         "piston:\n"
                         "  mass_g: 210.0   # EST\n"
                         "  name: \"x\"     # EST but text\n"
                         "liner:\n"
                         "  oil:\n"
                         "    grade: 5W-30   # EST\n"
                         "    temperature_degC: 40.0  # ESTIMATED is not it; EST is\n"
                         "  film_um: 1e-1    # TEST is not it\n"
                         "simulation:\n"
                         "  cycles: 8   #EST\n";
  const auto keys = pistondyn::design::findEstimatedKeys(path.string());
  fs::remove(path);
  const std::vector<std::pair<std::string, double>> expected = {
      {"geometry.pin_offset_mm", 0.5},
      {"piston.mass_g", 210.0},
      {"liner.oil.temperature_degC", 40.0},
      {"simulation.cycles", 8.0}};
  EXPECT_EQ(keys, expected);
}

}  // namespace
