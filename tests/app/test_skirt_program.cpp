// The lubricated skirt through the real program: the example decks pass `pistondyn check`,
// every table reader and cross-check of the skirt's deck section rejects bad input naming
// the file and line or the key (exit 1, nothing written), and a short run writes every
// skirt figure of summary.json, finite, agreeing with what cycle.csv holds (fmep from the
// friction_work_J column over the displacement, computed here, not by the summary code).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "NumericCsv.h"
#include "PlotChecks.h"
#include "ScratchDeck.h"
#include "pistondyn/mbd_models/SliderCrank.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

// The program exits with 1, its message holds every fragment, and no output folder appears.
class SkirtBadInput : public SkirtScratchDeck {
 protected:
  void expectRejected(const std::string& args, const std::vector<std::string>& fragments) {
    const fs::path out = dir_ / "results";
    // A deck accepted by mistake would start the example's 8-cycle run: stopped (exit 124)
    // after a minute instead.
    const std::string cmd = "timeout 60 " + std::string(PISTONDYN_EXE) + " run " + deck() +
                            " --out " + out.string() + " --quiet " + args + " > " +
                            (dir_ / "stdout.txt").string() + " 2> " +
                            (dir_ / "stderr.txt").string();
    const int status = std::system(cmd.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1) << args << "\n" << programStderr();
    const std::string err = programStderr();
    for (const auto& f : fragments)
      EXPECT_NE(err.find(f), std::string::npos) << "missing '" << f << "' in:\n" << err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  // "<deck>:<line>: <key>" of a key written in the deck.
  std::string at(const std::string& needle, const std::string& key) const {
    return deck() + ":" + std::to_string(lineOf(needle)) + ": " + key;
  }
  std::string table(const std::string& name, int line) const {
    return (dir_ / name).string() + ":" + std::to_string(line) + ": ";
  }
  // Adds `lines` (indented by two) to the liner section, after its model line.
  void addToLiner(const std::string& lines) {
    editDeck("  model: lubricated_skirt\n", "  model: lubricated_skirt\n" + lines);
  }
};

const char* kProfileKey = "liner.skirt_profile.axial_profile_file";

TEST_F(SkirtBadInput, ProfileTables) {
  const std::string key = at("axial_profile_file", kProfileKey);
  writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um\n-25,1\n0,0\n-1,0\n25,1\n");
  expectRejected("", {key, table(kProfileTable, 4) + "height_above_pin_mm -1 is not above"});
  writeFile(kProfileTable, "height_above_pin_mm,radial_drop_mm\n-25,1\n25,1\n");
  expectRejected("", {key, "needs a column 'radial_drop_um'"});
  writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um,note_um\n-25,1,0\n25,1,0\n");
  expectRejected("", {key, "unexpected column 'note_um'"});
  writeFile(kProfileTable, "# comment\nheight_above_pin_mm,radial_drop_um\n-25,nan\n25,1\n");
  expectRejected("", {key, table(kProfileTable, 3) + "radial_drop_um 'nan' is not a finite"});
  writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um\n-25,1\n");
  expectRejected("", {key, "needs at least 2 rows"});
  // Not covering the skirt (+12 .. -18 mm), and not covering it mirrored (-12 .. +18 mm).
  writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um\n-10,1\n10,1\n");
  expectRejected("",
                 {key, "covers heights [-10, 10] mm", "needs [-18, 12] mm", "never extrapolated"});
  writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um\n-18,1\n12,1\n");
  expectRejected("--set liner.skirt_profile.mirrored=true",
                 {key, "needs [-12, 18] mm with the mirrored profile"});
}

TEST_F(SkirtBadInput, OvalityTables) {
  editDeck("    ovality_diametral_um: 300.0", "    ovality_file: ovality.csv\n    #");
  editDeck("    ovality_cos4_coefficient: 0.0", "    # no law");
  const std::string key = at("ovality_file", "liner.skirt_profile.ovality_file");
  writeFile("ovality.csv", "angle_from_thrust_deg,radial_drop_um\n5,0\n90,150\n");
  expectRejected("", {key, table("ovality.csv", 2) + "the first row must be angle 0 with drop 0"});
  writeFile("ovality.csv", "angle_from_thrust_deg,radial_drop_um\n0,0\n100,150\n");
  expectRejected("", {key, table("ovality.csv", 3) + "angle_from_thrust_deg 100 deg is outside"});
  // The 80 deg grid reaches 40 deg from the axis.
  writeFile("ovality.csv", "angle_from_thrust_deg,radial_drop_um\n0,0\n30,50\n");
  expectRejected("", {key, "ends at 30 deg", "reaches 40 deg"});
  writeFile("ovality.csv", "angle_from_thrust_deg,radial_drop_um\n0,0\n90,150\n");
  expectRejected("--set liner.skirt_profile.ovality_diametral_um=300",
                 {key, "either by the law", "not both"});
}

TEST_F(SkirtBadInput, BoreDistortionAndTemperatureTables) {
  addToLiner(
      "  bore_distortion: {file: bore.csv}\n"
      "  thermal: {liner_expansion_per_K: 1.1e-5, liner_temperature_file: liner_t.csv}\n");
  const std::string bore = at("file: bore.csv", "liner.bore_distortion.file");
  writeFile("liner_t.csv", "depth_mm,temperature_degC\n0,120\n140,100\n");
  writeFile("bore.csv", "depth_mm,order,amplitude_um,phase_deg\n0,2,5,0\n50,13,1,0\n");
  expectRejected("", {bore, table("bore.csv", 3) + "order 13 must be a whole number from 0 to 12"});
  writeFile("bore.csv",
            "depth_mm,order,amplitude_um,phase_deg\n0,2,5,0\n50,2,1,0\n30,4,1,0\n40,2,1,0\n");
  expectRejected("", {bore, table("bore.csv", 5) + "depth_mm 40 of order 2 is not below",
                      "(" + table("bore.csv", 3).substr(0, table("bore.csv", 3).size() - 2)});
  writeFile("bore.csv", "depth_mm,order,amplitude_um,phase_deg\n-5,2,5,0\n");
  expectRejected("", {bore, table("bore.csv", 2) + "depth_mm -5 mm is above the liner top"});
  writeFile("bore.csv", "depth_mm,order,amplitude_um,phase_deg\n0,2,5,0\n");
  const std::string thermal = at("liner_temperature_file", "liner.thermal.liner_temperature_file");
  writeFile("liner_t.csv", "depth_mm,temperature_degC\n0,120\n140,-300\n");
  expectRejected("", {thermal, table("liner_t.csv", 3) +
                                   "temperature_degC -300 degC must be above absolute zero"});
  writeFile("liner_t.csv", "depth_mm,temperature_degC\n140,120\n0,100\n");
  expectRejected("", {thermal, table("liner_t.csv", 3) + "depth_mm 0 is not above"});
}

TEST_F(SkirtBadInput, OilSupplyTables) {
  editDeck("    film_um: 1.0", "    film_file: supply.csv\n    #");
  const std::string key = at("film_file", "liner.oil_supply.film_file");
  writeFile("supply.csv", "crank_angle_deg,film_um\n0,0.5\n360,0\n");
  expectRejected("", {key, table("supply.csv", 3) + "film_um 0 um must be positive"});
  writeFile("supply.csv", "crank_angle_deg,film_um\n0,0.5\n720,1\n");
  expectRejected("", {key, table("supply.csv", 3) + "crank_angle_deg 720 deg is outside"});
  writeFile("supply.csv", "crank_angle_deg,film_um\n360,0.5\n0,1\n");
  expectRejected("", {key, table("supply.csv", 3) + "crank_angle_deg 0 is not above"});
}

TEST_F(SkirtBadInput, ValuesAndCrossChecks) {
  // A skirt grid wider than the skirt's side.
  expectRejected("--set liner.grid.arc_width_deg=180",
                 {"--set liner.grid.arc_width_deg: must be at least 10 deg and below 180 deg (got "
                  "180): 180 deg or more makes each side's grid wider than the skirt's side"});
  // An arc in radians: the unit that fits is named.
  expectRejected("--set liner.grid.arc_width_deg=1.4",
                 {"--set liner.grid.arc_width_deg: must be at least 10 deg", "given in rad"});
  // A clearance in mm read as um.
  expectRejected("--set liner.cold_radial_clearance_um=0.04",
                 {"--set liner.cold_radial_clearance_um: must be between 1 and 500 um"});
  // A negative hot clearance: a 250 degC skirt grows by 37.25 mm x 2.2e-5 x 230 K = 188 um.
  addToLiner(
      "  thermal: {piston_expansion_per_K: 2.2e-5, piston_temperature_file: piston_t.csv}\n");
  writeFile("piston_t.csv", "height_above_pin_mm,temperature_degC\n-18,250\n12,250\n");
  expectRejected("", {at("cold_radial_clearance_um", "liner.cold_radial_clearance_um"),
                      "the hot running clearance is -", "raise the clearance"});
  SetUp();
  // A temperature table without its expansion coefficient, and a coefficient without one.
  addToLiner("  thermal: {piston_temperature_file: piston_t.csv}\n");
  writeFile("piston_t.csv", "height_above_pin_mm,temperature_degC\n-18,150\n12,150\n");
  expectRejected("", {"liner.thermal.piston_expansion_per_K: missing key: required with "
                      "piston_temperature_file"});
  SetUp();
  addToLiner("  thermal: {liner_expansion_per_K: 1.1e-5}\n");
  expectRejected("", {"liner.thermal.liner_expansion_per_K: has no effect without "
                      "liner_temperature_file"});
  SetUp();
  // The oil supply: not positive, two ways, none.
  expectRejected("--set liner.oil_supply.film_um=0",
                 {"--set liner.oil_supply.film_um: must be above 0 um and at most 1000 um (got 0)"});
  expectRejected("--set liner.oil_supply.fully_flooded=true",
                 {at("film_um", "liner.oil_supply.film_um"),
                  "give exactly one of fully_flooded: true, film_um, film_file"});
  editDeck("    film_um: 1.0", "    fully_flooded: false");
  expectRejected("", {"liner.oil_supply: missing: say how oil reaches the skirt"});
  SetUp();
  // The oil.
  expectRejected("--set liner.oil.grade=0W-31",
                 {"--set liner.oil.grade: '0W-31' is not one of: 0W-20, 0W-30"});
  expectRejected("--set liner.oil.temperature_degC=230",
                 {"--set liner.oil.temperature_degC: 230 degC is outside the oil's valid range"});
  // Field dumps off the output rows, an explicit integrator, a misspelt key.
  expectRejected("--set liner.field_dumps.crank_angles_deg=[2.5]",
                 {"--set liner.field_dumps.crank_angles_deg: 2.5 deg is not an output crank "
                  "angle"});
  expectRejected("--set simulation.integrator=rk_merson",
                 {"--set simulation.integrator: 'rk_merson' is an explicit integrator",
                  "makes the system stiff"});
  editDeck("    mirrored: false", "    mirored: false");
  expectRejected("", {at("mirored", "liner.skirt_profile.mirored"), "unknown key"});
}

// Every number summary.json holds as a finite double.
double finiteNumber(const nlohmann::json& r, const std::string& key) {
  EXPECT_TRUE(r.contains(key)) << key;
  if (!r.contains(key))
    return NAN;
  EXPECT_TRUE(r[key].is_number()) << key << " = " << r[key];
  const double v = r[key].is_number() ? r[key].get<double>() : NAN;
  EXPECT_TRUE(std::isfinite(v)) << key;
  return v;
}

// cycle.csv and the field dumps read back (tests/support/NumericCsv.h).
using Csv = pistondyn::test::NumericCsv;
Csv readCsv(const fs::path& p) {
  return pistondyn::test::readNumericCsv(p);
}

// One coarse cycle of the gasoline example through the program.
TEST_F(SkirtScratchDeck, AShortRunWritesEverySkirtFigure) {
  const fs::path out = dir_ / "results";
  ASSERT_EQ(runProgram("--set simulation.cycles=1 --set simulation.until_periodic=false "
                       "--set liner.grid.nodes_circumferential=16 --set liner.grid.nodes_axial=12 "
                       "--set simulation.output_step_deg=5 "
                       "--set liner.field_dumps.crank_angles_deg=[0,380]",
                       out),
            0)
      << programStderr();
  std::ifstream in(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  const nlohmann::json& r = summary["results"];
  for (const char* key :
       {"fmep_kPa", "friction_power_mean_W", "min_h_over_sigma_thrust",
        "min_h_over_sigma_antithrust", "min_film_thickness_thrust_um",
        "min_film_thickness_antithrust_um", "max_abs_u_lat_um", "max_abs_tilt_deg",
        "slap_energy_max_mJ", "hot_clearance_um", "cycles_run", "film_solves", "film_fallbacks",
        "film_derivative_failures", "rejected_steps", "wall_time_s"})
    finiteNumber(r, key);
  for (const char* key :
       {"min_h_over_sigma_thrust_crank_angle_deg", "min_h_over_sigma_antithrust_crank_angle_deg",
        "min_film_thickness_thrust_crank_angle_deg",
        "min_film_thickness_antithrust_crank_angle_deg"}) {
    const double a = finiteNumber(r, key);
    EXPECT_GE(a, 0.0) << key;
    EXPECT_LT(a, 720.0) << key;
  }
  ASSERT_TRUE(r["converged"].is_boolean());
  EXPECT_FALSE(r["converged"].get<bool>());
  EXPECT_EQ(r["cycles_run"].get<int>(), 1);
  EXPECT_TRUE(r["cycles_to_converge"].is_null()) << "a run that did not converge claims no count";
  ASSERT_TRUE(r["cycle_fmep_kPa"].is_array());
  ASSERT_EQ(r["cycle_fmep_kPa"].size(), 1u);
  EXPECT_EQ(r["cycle_fmep_kPa"][0].get<double>(), r["fmep_kPa"].get<double>());
  EXPECT_GT(r["film_solves"].get<long>(), 0);
  // A healthy run: every film solve also returned its squeeze derivatives.
  EXPECT_EQ(r["film_derivative_failures"].get<long>(), 0);
  // The deck's thermal section: the Al-Si skirt (20.5e-6/K, 120-140 degC on the skirt) grows
  // more than the bore (17e-6/K, 100-130 degC): hot below the cold 40 um, and at most the
  // clearance on the profile's zero-drop line (-6 mm above the pin, 126.7 degC) against the
  // hottest bore (130 degC): 40 - 37.21 mm x (20.5e-6 x 106.7 - 17e-6 x 110) = 28.2 um.
  const double hot_um = r["hot_clearance_um"].get<double>();
  EXPECT_GT(hot_um, 0.0);
  EXPECT_LT(hot_um, 40.0 - 37.21e3 * (20.5e-6 * (120.0 + 10.0 * 12.0 / 18.0 - 20.0) -
                                      17e-6 * (130.0 - 20.0)));
  // No null anywhere (nlohmann writes NaN and infinities as null) but the one documented:
  // cycles_to_converge of a run that did not converge.
  nlohmann::json withoutCount = summary;
  withoutCount["results"].erase("cycles_to_converge");
  EXPECT_EQ(withoutCount.dump().find("null"), std::string::npos);

  // fmep = the last cycle's friction work over the displacement, both computed here: the
  // work from cycle.csv's friction_work_J column (rows 0 and 720 deg), the displacement
  // from the deck's geometry by hand (bore 74.5 mm, r 40 mm, L 140 mm, pin offset 0.5 mm,
  // the kinematic stroke of the offset slider crank).
  const Csv csv = readCsv(out / "cycle.csv");
  ASSERT_EQ(csv.rows.size(), 145u);
  const auto work = csv.column("friction_work_J");
  pistondyn::mbd::CrankTrainGeometry g;
  g.crankRadius_m = 0.040;
  g.conrodLength_m = 0.140;
  g.pinOffset_m = 0.0005;
  g.compressionRatio = 10.0;
  const pistondyn::mbd::SliderCrank kin(g);
  const double displacement_m3 = M_PI / 4.0 * 0.0745 * 0.0745 * kin.stroke_m();
  const double fmep_kPa = (work.back() - work.front()) / displacement_m3 / 1e3;
  EXPECT_NEAR(r["fmep_kPa"].get<double>(), fmep_kPa, 1e-9 * fmep_kPa);
  const auto time = csv.column("time_s");
  EXPECT_NEAR(r["friction_power_mean_W"].get<double>(),
              (work.back() - work.front()) / (time.back() - time.front()),
              1e-12 * r["friction_power_mean_W"].get<double>());

  // The extremes are those of the cycle's rows (the closing row excluded), as written.
  auto minimum = [&](const std::string& column) {
    const auto v = csv.column(column);
    return *std::min_element(v.begin(), v.end() - 1);
  };
  EXPECT_EQ(r["min_film_thickness_thrust_um"].get<double>(),
            minimum("min_film_thickness_thrust_um"));
  EXPECT_EQ(r["min_film_thickness_antithrust_um"].get<double>(),
            minimum("min_film_thickness_antithrust_um"));
  EXPECT_EQ(r["min_h_over_sigma_thrust"].get<double>(), minimum("min_h_over_sigma_thrust"));
  EXPECT_EQ(r["min_h_over_sigma_antithrust"].get<double>(), minimum("min_h_over_sigma_antithrust"));
  double uMax = 0.0, tiltMax = 0.0;
  const auto u = csv.column("u_lat_um"), tilt = csv.column("tilt_mrad");
  for (std::size_t k = 0; k + 1 < u.size(); ++k) {
    uMax = std::max(uMax, std::abs(u[k]));
    tiltMax = std::max(tiltMax, std::abs(tilt[k]));
  }
  EXPECT_EQ(r["max_abs_u_lat_um"].get<double>(), uMax);
  EXPECT_NEAR(r["max_abs_tilt_deg"].get<double>(), tiltMax * 1e-3 * 180.0 / M_PI,
              1e-12 * r["max_abs_tilt_deg"].get<double>());
  // The largest slap event: one of the energies the slap_energy_mJ column shows (it changes
  // when an event completes), or 0 when none did.
  const auto slap = csv.column("slap_energy_mJ");
  double slapMax = 0.0;
  for (std::size_t k = 1; k < slap.size(); ++k) {
    if (slap[k] != slap[k - 1])
      slapMax = std::max(slapMax, slap[k]);
  }
  EXPECT_EQ(r["slap_energy_max_mJ"].get<double>(), slapMax);

  // The field dumps: one file per angle and side, a row per node with finite values.
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(out))
    files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{
                       "cycle.csv", "cycle_map_antithrust.csv", "cycle_map_thrust.csv",
                       "field_dump_0deg_antithrust.csv", "field_dump_0deg_thrust.csv",
                       "field_dump_380deg_antithrust.csv", "field_dump_380deg_thrust.csv",
                       "field_frames_antithrust.csv", "field_frames_thrust.csv",
                       "summary.json", "warm_start.json"}));
  const Csv dump = readCsv(out / "field_dump_380deg_antithrust.csv");
  EXPECT_EQ(dump.columns,
            (std::vector<std::string>{"phi_deg", "y_mm", "gap_um", "rigid_um", "skirt_profile_um",
                                      "liner_shape_um", "piston_thermal_um", "liner_thermal_um",
                                      "piston_elastic_um", "liner_elastic_um", "film_gap_um",
                                      "h_over_sigma", "film_pressure_Pa", "fill_fraction",
                                      "contact_pressure_Pa", "wear_depth_rate_um_per_h"}));
  ASSERT_EQ(dump.rows.size(), 16u * 12u);
  for (const auto& row : dump.rows) {
    for (double v : row)
      EXPECT_TRUE(std::isfinite(v));
    EXPECT_GE(row[0], 140.0 - 1e-9);  // anti-thrust side: 180 +- 40 deg
    EXPECT_LE(row[0], 220.0 + 1e-9);
  }
  // The minimum gap of the dump at 380 deg is the row's min_film_thickness column.
  double smallest = INFINITY;
  for (const auto& row : dump.rows)
    smallest = std::min(smallest, row[2]);
  const auto angle = csv.column("crank_angle_deg");
  const auto film = csv.column("min_film_thickness_antithrust_um");
  for (std::size_t k = 0; k < angle.size(); ++k) {
    if (std::abs(angle[k] - 380.0) < 1e-9) {
      EXPECT_NEAR(smallest, film[k], 1e-12 * std::max(1.0, std::abs(film[k])));
    }
  }
  // And the terminal summary names the skirt's figures.
  const std::string stdoutText = readFile(dir_ / "stdout.txt");
  for (const char* text : {"fmep", "min h/sigma", "min film", "hot running clearance"})
    EXPECT_NE(stdoutText.find(text), std::string::npos) << text << "\n" << stdoutText;

  // The same folder plotted: every skirt figure and one field map per dumped angle, PNGs
  // of the stated size (110 px + 360 px per panel; the maps 1200 x 1250).
  const std::string plot = std::string(PISTONDYN_EXE) + " plot " + out.string() + " > " +
                           (dir_ / "plot.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(plot.c_str()), 0) << readFile(dir_ / "plot.txt");
  const std::vector<std::string> figures = {
      "crank_train_forces.png", "cycle_maps.png",     "field_map_0deg.png",
      "field_map_380deg.png",   "film_thickness.png", "friction.png",
      "regime_shares.png",      "secondary_motion.png", "side_force.png"};
  EXPECT_EQ(listPngs(out / "plots"), figures);
  for (const auto& f : figures) {
    const PngSize size = readPngSize(out / "plots" / f);
    EXPECT_EQ(size.width, 1200) << f;
    if (f == "cycle_maps.png") {
      // 110 px + 330 px per mapped field that is not zero everywhere: film pressure, fill
      // fraction and h/sigma at least; asperity pressure and wear when there was contact.
      EXPECT_EQ((size.height - 110) % 330, 0) << size.height;
      EXPECT_GE((size.height - 110) / 330, 3) << size.height;
      EXPECT_LE((size.height - 110) / 330, 5) << size.height;
    } else {
      EXPECT_EQ(size.height, f.rfind("field_map", 0) == 0 ? 1250 : 830) << f;
    }
  }
  // The report: every figure embedded, the exaggeration a round factor (1, 2 or 5 x 10^n,
  // rounded down) drawing the hot clearance as about 8 % of the 74.5 mm bore (9.4 um hot:
  // 0.08 x 74.5 / 0.0094 = 632 -> 500).
  const std::string report = std::string(PISTONDYN_EXE) + " report " + out.string() + " > " +
                             (dir_ / "report.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(report.c_str()), 0) << readFile(dir_ / "report.txt");
  const std::string html = readFile(out / "report.html");
  checkReportEmbedsThePlots(html, out / "plots");
  const double wanted = 0.08 * 74.5 / (1e-3 * hot_um);
  const int factor = wanted >= 500.0 && wanted < 1000.0 ? 500 : wanted >= 200.0 ? 200 : 100;
  EXPECT_NE(html.find("exaggerated × " + std::to_string(factor) + "</strong>"), std::string::npos)
      << hot_um;
  EXPECT_NE(html.find("{\"factor\":" + std::to_string(factor) + ","), std::string::npos);
  // Issue 37: the headline names the skirt's figures in engineering units (h/σ with its
  // crank angle, films in µm, tilt in mrad, slap in mJ, fmep in kPa), with no number in
  // exponent form; the field map's frames are embedded and its script draws them.
  const std::size_t headlineAt = html.find("<section id=\"headline\">");
  ASSERT_NE(headlineAt, std::string::npos);
  const std::string headline = html.substr(headlineAt, html.find("</section>", headlineAt) - headlineAt);
  for (const char* text : {"fmep", " kPa<", "min h/σ thrust side", "min h/σ anti-thrust side",
                           "°<", " µm at ", " mrad<", " mJ<", "hot clearance", " W<", " %<"})
    EXPECT_NE(headline.find(text), std::string::npos) << text << "\n" << headline;
  EXPECT_FALSE(std::regex_search(headline, std::regex("[0-9][eE][+-]?[0-9]"))) << headline;
  EXPECT_NE(html.find("<script type=\"application/json\" id=\"field-frames\">"), std::string::npos);
  renderInChromium(out / "report.html", static_cast<int>(figures.size()),
                   {"data-field-map=\"ready\""});
}

// `pistondyn check` on both example decks as shipped.
TEST(SkirtExamples, BothExampleDecksPassCheck) {
  for (const char* engine : {"briggs_stratton_500", "gasoline_1400_2000rpm"}) {
    const std::string deck =
        std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/" + engine + "/engine.yaml";
    const fs::path log =
        fs::temp_directory_path() / ("pistondyn_check_" + std::to_string(::getpid()));
    const std::string cmd =
        std::string(PISTONDYN_EXE) + " check " + deck + " > " + log.string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << engine << "\n" << readFile(log);
    EXPECT_NE(readFile(log).find("is valid"), std::string::npos) << readFile(log);
    fs::remove(log);
  }
}

}  // namespace
