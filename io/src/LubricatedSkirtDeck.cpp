#include "pistondyn/io/LubricatedSkirtDeck.h"

#include "MessageText.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "pistondyn/common/Validation.h"
#include "pistondyn/io/ComplianceInput.h"
#include "pistondyn/io/DeckSection.h"
#include "pistondyn/lubrication/OilGrades.h"
#include "pistondyn/mbd_models/SliderCrank.h"
#include "pistondyn/plugin/LubricatedSkirtElement.h"
#include "pistondyn/skirt/ElasticCoupling.h"
#include "pistondyn/skirt/HotRunningClearance.h"

namespace pistondyn::io {
namespace {

using Q = Quantity;
using common::formatNumber;
constexpr double kAbsoluteZero_degC = -273.15;
constexpr double kMm = 1e-3, kUm = 1e-6, kDeg = M_PI / 180.0;

// A key of the section's table (LubricatedSkirtKeys.cpp): requirement, default and ranges.
const DeckKey& skirtKey(const std::string& path) {
  return getLubricatedSkirtDeckKeys().at(path);
}

std::string list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : ", ") + n;
  return out;
}

// A table takes exactly its columns: one it would not read is reported like an unknown
// key (often a unit the column does not take, e.g. radial_drop_mm).
bool hasExactlyColumns(DeckSection& s, const std::string& key, const CsvTable& t,
                       const std::vector<std::string>& columns) {
  for (const auto& c : t.columns) {
    if (std::find(columns.begin(), columns.end(), c) == columns.end()) {
      s.addProblem(key, t.filePath + ": unexpected column '" + c +
                            "' (the table takes exactly: " + list(columns) + ")");
      return false;
    }
  }
  return true;
}

bool hasRows(DeckSection& s, const std::string& key, const CsvTable& t, std::size_t minimum) {
  if (t.rows.size() < minimum) {
    s.addProblem(key, t.filePath + ": needs at least " + std::to_string(minimum) +
                          " rows of numbers, found " + std::to_string(t.rows.size()));
    return false;
  }
  return true;
}

// Values strictly increasing down the column (as written, in `unit`).
bool isIncreasing(DeckSection& s, const std::string& key, const CsvTable& t,
                  const std::string& column, const std::string& unit) {
  const std::vector<double> v = t.getColumn(column);
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (!(v[i] > v[i - 1])) {
      s.addProblem(key, t.where(i) + ": " + column + " " + formatNumber(v[i]) +
                            " is not above the previous row's " + formatNumber(v[i - 1]) + " " +
                            unit + " (the rows must be in strictly increasing " + column + ")");
      return false;
    }
  }
  return true;
}

// Every value of a column inside (lo, hi] or [lo, hi], naming the first row outside.
bool isWithin(DeckSection& s, const std::string& key, const CsvTable& t, const std::string& column,
              const Bounds& bounds, const std::string& expected) {
  const std::vector<double> v = t.getColumn(column);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!bounds.contains(v[i])) {
      s.addProblem(key, t.where(i) + ": " + column + " " + formatNumber(v[i]) + " " + expected);
      return false;
    }
  }
  return true;
}

Eigen::VectorXd toVector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

// Temperatures [degC] a table gives: above absolute zero (and below 1000 degC: a piston or
// liner hotter than that is a unit mistake).
bool hasTemperatures(DeckSection& s, const std::string& key, const CsvTable& t) {
  return isWithin(s, key, t, "temperature_degC", Bounds{kAbsoluteZero_degC, 1000.0, true},
                  "degC must be above absolute zero (-273.15 degC) and below 1000 degC");
}

// Plausibility of table values for the engines the tool is for (as the deck keys':
// ovality_diametral_um, liner_top_above_crank_mm). Beyond them a value is a unit slip or
// garbage; a finite 1e308 would pass every other check and reach the gap as 1e302 m.
const Bounds kTableHeight_mm = Bounds::between(-2000.0, 2000.0);
const Bounds kTableDepth_mm = Bounds::between(0.0, 2000.0);
const Bounds kTableRadial_um = Bounds::between(-2000.0, 2000.0);
const Bounds kTablePhase_deg = Bounds::between(-360.0, 360.0);

// Table ends as written (for messages: the SI values converted back would show rounding).
struct WrittenEnds {
  double profileFirst_mm = 0.0, profileLast_mm = 0.0;
  double ovalityLast_deg = 0.0;
};

// ---- grid -----------------------------------------------------------------------------

void readGrid(DeckSection& liner, skirt::SkirtSideGridParameters& g) {
  DeckSection grid = liner.getSection("grid");
  // Below 180 deg: the thrust and anti-thrust grids would overlap.
  g.arcWidth_rad = grid.getSI(skirtKey("liner.grid.arc_width_deg"));
  g.nPhi = static_cast<int>(grid.getInteger(skirtKey("liner.grid.nodes_circumferential")));
  g.nY = static_cast<int>(grid.getInteger(skirtKey("liner.grid.nodes_axial")));
  g.axialClustering = grid.getNumber(skirtKey("liner.grid.axial_clustering"));
  g.circumferentialClustering =
      grid.getNumber(skirtKey("liner.grid.circumferential_clustering"));
}

// ---- skirt profile --------------------------------------------------------------------

void readAxialProfile(DeckSection& profile, skirt::AxialProfileParameters& a, WrittenEnds& ends) {
  const std::string key = "axial_profile_file";
  const std::vector<std::string> cols = {"height_above_pin_mm", "radial_drop_um"};
  if (const auto t = profile.getOptionalCsvTable(key, cols)) {
    if (hasExactlyColumns(profile, key, *t, cols) && hasRows(profile, key, *t, 2) &&
        isIncreasing(profile, key, *t, "height_above_pin_mm", "mm") &&
        isWithin(profile, key, *t, "height_above_pin_mm", kTableHeight_mm,
                 "mm is not a height on a piston (at most 2000 mm from the pin; a unit "
                 "slip?)") &&
        isWithin(profile, key, *t, "radial_drop_um", kTableRadial_um,
                 "um is not a skirt's radial drop (at most 2000 um either way; mm given as "
                 "um?)")) {
      a.height_m = toVector(t->getColumnSI("height_above_pin_mm", Q::Length));
      ends.profileFirst_mm = t->rows.front()[t->columnIndex("height_above_pin_mm")];
      ends.profileLast_mm = t->rows.back()[t->columnIndex("height_above_pin_mm")];
      a.radialDrop_m = toVector(t->getColumnSI("radial_drop_um", Q::Length));
    }
  }
  a.mirrored = profile.getBool(skirtKey("liner.skirt_profile.mirrored"));
}

void readOvality(DeckSection& profile, skirt::OvalityParameters& o, WrittenEnds& ends) {
  const bool law = profile.has("ovality_diametral_um") || profile.has("ovality_cos4_coefficient");
  const std::string key = "ovality_file";
  if (!profile.has(key) || law) {
    o.model = skirt::OvalityModel::Law;
    o.diametralOvality_m = profile.getSI(skirtKey("liner.skirt_profile.ovality_diametral_um"));
    o.cos4Coefficient = profile.getNumber(skirtKey("liner.skirt_profile.ovality_cos4_coefficient"));
  }
  if (!profile.has(key))
    return;
  if (law) {
    profile.addProblem(key,
                       "give the ovality either by the law (ovality_diametral_um, "
                       "ovality_cos4_coefficient) or by this table, not both");
    profile.getOptionalFilePath(key);  // read (known), not used
    return;
  }
  const std::vector<std::string> cols = {"angle_from_thrust_deg", "radial_drop_um"};
  const auto t = profile.getOptionalCsvTable(key, cols);
  if (!t || !hasExactlyColumns(profile, key, *t, cols) || !hasRows(profile, key, *t, 2) ||
      !isIncreasing(profile, key, *t, "angle_from_thrust_deg", "deg") ||
      !isWithin(profile, key, *t, "angle_from_thrust_deg", Bounds::between(0.0, 90.0),
                "deg is outside one quadrant [0, 90] deg from the thrust axis") ||
      !isWithin(profile, key, *t, "radial_drop_um", kTableRadial_um,
                "um is not an ovality's radial drop (at most 2000 um either way; mm given "
                "as um?)"))
    return;
  const std::vector<double> angle = t->getColumn("angle_from_thrust_deg");
  const std::vector<double> drop = t->getColumn("radial_drop_um");
  if (angle[0] != 0.0 || drop[0] != 0.0) {
    profile.addProblem(key, t->where(0) +
                                ": the first row must be angle 0 with drop 0 (the ovality is the "
                                "drop below the thrust-axis radius, from the thrust axis on)");
    return;
  }
  o.model = skirt::OvalityModel::Table;
  ends.ovalityLast_deg = angle.back();
  o.tableAngle_rad = toVector(t->getColumnSI("angle_from_thrust_deg", Q::Angle));
  o.tableRadialDrop_m = toVector(t->getColumnSI("radial_drop_um", Q::Length));
}

// ---- bore distortion ------------------------------------------------------------------

void readBoreDistortion(DeckSection& bore, skirt::BoreDistortionParameters& b) {
  const std::string key = "file";
  const std::vector<std::string> cols = {"depth_mm", "order", "amplitude_um", "phase_deg"};
  const auto t = bore.getOptionalCsvTable(key, cols);
  if (!t || !hasExactlyColumns(bore, key, *t, cols) || !hasRows(bore, key, *t, 1) ||
      !isWithin(bore, key, *t, "depth_mm", Bounds::nonNegative(),
                "mm is above the liner top (depths are measured down from it, >= 0)") ||
      !isWithin(bore, key, *t, "depth_mm", kTableDepth_mm,
                "mm is deeper than a liner (at most 2000 mm; a unit slip?)") ||
      !isWithin(bore, key, *t, "amplitude_um", kTableRadial_um,
                "um is not a bore distortion (at most 2000 um either way; mm given as um?)") ||
      !isWithin(bore, key, *t, "phase_deg", kTablePhase_deg,
                "deg is not a phase in [-360, 360] deg"))
    return;
  struct Rows {
    std::vector<double> depth_m, amplitude_m, phase_rad;
    std::size_t lastRow = 0;
  };
  std::map<int, Rows> orders;
  const std::size_t iDepth = t->columnIndex("depth_mm"), iOrder = t->columnIndex("order"),
                    iAmp = t->columnIndex("amplitude_um"), iPhase = t->columnIndex("phase_deg");
  for (std::size_t i = 0; i < t->rows.size(); ++i) {
    const auto& r = t->rows[i];
    const double n = r[iOrder];
    if (n != std::floor(n) || n < 0.0 || n > skirt::kMaxBoreDistortionOrder) {
      bore.addProblem(key, t->where(i) + ": order " + formatNumber(n) +
                               " must be a whole number from 0 to " +
                               std::to_string(skirt::kMaxBoreDistortionOrder));
      return;
    }
    Rows& o = orders[static_cast<int>(n)];
    if (!o.depth_m.empty() && !(r[iDepth] * kMm > o.depth_m.back())) {
      bore.addProblem(key, t->where(i) + ": depth_mm " + formatNumber(r[iDepth]) + " of order " +
                               formatNumber(n) + " is not below that order's previous row (" +
                               t->where(o.lastRow) +
                               "): each order's depths must increase strictly");
      return;
    }
    o.depth_m.push_back(r[iDepth] * kMm);
    o.amplitude_m.push_back(r[iAmp] * kUm);
    o.phase_rad.push_back(r[iPhase] * kDeg);
    o.lastRow = i;
  }
  for (const auto& [n, o] : orders) {
    skirt::BoreDistortionOrder order;
    order.order = n;
    order.depth_m = toVector(o.depth_m);
    order.amplitude_m = toVector(o.amplitude_m);
    order.phase_rad = toVector(o.phase_rad);
    b.orders.push_back(std::move(order));
  }
}

// ---- thermal growth -------------------------------------------------------------------

// One body's expansion coefficient and temperature table; true when a field was read.
bool readThermalField(DeckSection& thermal, const std::string& alphaKey, const std::string& fileKey,
                      const std::string& positionColumn, const std::string& typical,
                      double& alpha_perK, Eigen::VectorXd& position_m,
                      Eigen::VectorXd& temperature_degC) {
  const bool hasAlpha = thermal.has(alphaKey), hasFile = thermal.has(fileKey);
  if (const auto a = thermal.getOptionalSI(skirtKey(thermal.getKeyPath(alphaKey))))
    alpha_perK = *a;
  if (hasAlpha && !hasFile) {
    thermal.addProblem(alphaKey, "has no effect without " + fileKey +
                                     ": give the temperatures, or remove the key");
  }
  if (!hasFile)
    return false;
  if (!hasAlpha) {
    thermal.addProblem(
        alphaKey, "missing key: required with " + fileKey + " (a number in 1/K, " + typical + ")");
  }
  const std::vector<std::string> cols = {positionColumn, "temperature_degC"};
  const auto t = thermal.getOptionalCsvTable(fileKey, cols);
  if (!t || !hasExactlyColumns(thermal, fileKey, *t, cols) || !hasRows(thermal, fileKey, *t, 1) ||
      !isIncreasing(thermal, fileKey, *t, positionColumn, "mm") ||
      !isWithin(thermal, fileKey, *t, positionColumn, kTableHeight_mm,
                "mm is not a position on a piston or liner (at most 2000 mm; a unit slip?)") ||
      !hasTemperatures(thermal, fileKey, *t))
    return false;
  position_m = toVector(t->getColumnSI(positionColumn, Q::Length));
  temperature_degC = toVector(t->getColumn("temperature_degC"));
  return true;
}

void readThermal(DeckSection& liner, skirt::GapAssemblyParameters& gap) {
  DeckSection thermal = liner.getSection("thermal");
  readThermalField(thermal, "piston_expansion_per_K", "piston_temperature_file",
                   "height_above_pin_mm", "e.g. 2.1e-5 for an aluminium skirt",
                   gap.pistonThermal.expansionCoefficient_perK, gap.pistonThermal.height_m,
                   gap.pistonThermal.temperature_degC);
  readThermalField(thermal, "liner_expansion_per_K", "liner_temperature_file", "depth_mm",
                   "e.g. 1.1e-5 for a cast-iron liner", gap.linerThermal.expansionCoefficient_perK,
                   gap.linerThermal.depth_m, gap.linerThermal.temperature_degC);
}

// ---- oil ------------------------------------------------------------------------------

const std::vector<std::string>& gradeNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (auto g : {lubrication::SaeGrade::k0W20, lubrication::SaeGrade::k0W30,
                   lubrication::SaeGrade::k5W30, lubrication::SaeGrade::k5W40,
                   lubrication::SaeGrade::k10W40, lubrication::SaeGrade::k15W40})
      n.push_back(lubrication::toString(g));
    return n;
  }();
  return names;
}

void readOil(DeckSection& liner, plugin::LubricatedSkirtParameters& p) {
  DeckSection oil = liner.getSection("oil");
  const char* kNu1 = "kinematic_viscosity_1_mm2_per_s";
  const char* kNu2 = "kinematic_viscosity_2_mm2_per_s";
  const std::vector<std::string> userKeys = {kNu1,
                                             kNu2,
                                             "viscosity_temperature_1_degC",
                                             "viscosity_temperature_2_degC",
                                             "density_kg_per_m3",
                                             "density_temperature_degC",
                                             "name"};
  bool user = false;
  for (const auto& k : userKeys)
    user = user || oil.has(k);
  // Part of the schema whichever way the oil is given (a --set grade=null is not unknown).
  oil.getDeck().markKnown(oil.getKeyPath("grade"));
  const bool before = oil.hasProblems();
  bool haveSpec = false;
  if (oil.has("grade")) {
    const std::string text = oil.getString("grade");
    try {
      p.oil = lubrication::makeSaeGradeOilSpec(lubrication::parseSaeGrade(text));
      haveSpec = true;
    } catch (const std::invalid_argument&) {
      oil.addProblem("grade", detail::quoteValue(text) + " is not one of: " + list(gradeNames()) +
                                  " (or give the oil by two kinematic viscosities)");
    }
    if (user) {
      oil.addProblem("grade", "give the oil either by its grade or by its viscosities (" +
                                  std::string(kNu1) + ", ...), not both");
      for (const auto& k : userKeys)
        oil.getDeck().markKnown(oil.getKeyPath(k));
      haveSpec = false;
    }
  } else if (user) {
    lubrication::OilSpec& s = p.oil;
    // A user oil's viscosities and density are required (the table's keys are optional
    // because a graded oil has none).
    auto required = [](const std::string& path) { return DeckKey(skirtKey(path)).require(); };
    s.name = oil.getString(skirtKey("liner.oil.name"));
    s.kinematicViscosity1_m2ps = oil.getSI(required("liner.oil." + std::string(kNu1)));
    s.temperature1_degC = oil.getNumber(skirtKey("liner.oil.viscosity_temperature_1_degC"));
    s.kinematicViscosity2_m2ps = oil.getSI(required("liner.oil." + std::string(kNu2)));
    s.temperature2_degC = oil.getNumber(skirtKey("liner.oil.viscosity_temperature_2_degC"));
    s.density_kgpm3 = oil.getSI(required("liner.oil.density_kg_per_m3"));
    s.densityReferenceTemperature_degC =
        oil.getNumber(skirtKey("liner.oil.density_temperature_degC"));
    haveSpec = true;
  } else {
    oil.addProblem("grade", "missing key: give the oil's SAE grade (" + list(gradeNames()) +
                                ") or its kinematic viscosities at two temperatures (" + kNu1 +
                                ", " + kNu2 + ", density_kg_per_m3)");
  }
  p.oilTemperature_degC = oil.getNumber(skirtKey("liner.oil.temperature_degC"));
  if (!haveSpec || oil.hasProblems() != before)
    return;
  // The oil's own checks (viscosity falling with temperature, ASTM D341's range) and the
  // film temperature inside its valid range.
  std::optional<lubrication::Oil> fitted;
  try {
    fitted.emplace(p.oil);
  } catch (const std::invalid_argument& e) {
    oil.addProblem(user ? kNu1 : "grade", e.what());
    return;
  }
  try {
    const double eta = fitted->calcDynamicViscosity_Pas(p.oilTemperature_degC);
    oil.getDeck().recordInput({oil.getKeyPath("film_dynamic_viscosity_Pas"),
                               oil.getKeyPath("film_dynamic_viscosity_Pas"), eta});
  } catch (const std::invalid_argument&) {
    oil.addProblem("temperature_degC", formatNumber(p.oilTemperature_degC) +
                                           " degC is outside the oil's valid range [" +
                                           formatNumber(fitted->getMinTemperature_degC()) + ", " +
                                           formatNumber(fitted->getMaxTemperature_degC()) +
                                           "] degC");
  }
}

// ---- oil supply -----------------------------------------------------------------------

// A periodic table `crank_angle_deg, film_um` over the cycle (the supply film, the ring's
// film); false (and a problem named) when absent or bad.
bool readFilmTable(DeckSection& s, const std::string& key, double maxFilm_um,
                   std::vector<double>& angle_deg, std::vector<double>& film_m) {
  const std::vector<std::string> cols = {"crank_angle_deg", "film_um"};
  const auto t = s.getOptionalCsvTable(key, cols);
  if (!t || !hasExactlyColumns(s, key, *t, cols) || !hasRows(s, key, *t, 2) ||
      !isIncreasing(s, key, *t, "crank_angle_deg", "deg") ||
      !isWithin(s, key, *t, "crank_angle_deg", Bounds{0.0, 720.0 - 1e-9, false},
                "deg is outside the cycle [0, 720) deg (the table is periodic)") ||
      !isWithin(s, key, *t, "film_um", Bounds{0.0, maxFilm_um, true},
                "um must be positive (and at most " + formatNumber(maxFilm_um) + " um)"))
    return false;
  angle_deg = t->getColumn("crank_angle_deg");
  film_m = t->getColumnSI("film_um", Q::Length);
  return true;
}

// liner.oil_supply.liner_transport: the oil carried on the liner.
void readLinerTransport(DeckSection& supply, skirt::LinerOilParameters& o) {
  DeckSection t = supply.getSection("liner_transport");
  const auto key = [](const std::string& k) {
    return skirtKey("liner.oil_supply.liner_transport." + k);
  };
  if (!t.has("ring_height_above_pin_mm"))
    t.addProblem("ring_height_above_pin_mm",
                 "missing: the oil-control ring's lower edge above the pin axis (mm), where the "
                 "film the ring leaves begins");
  else
    o.ringHeightAbovePin_m = t.getSI(key("ring_height_above_pin_mm"));
  const int ring = (t.has("ring_film_um") ? 1 : 0) + (t.has("ring_film_file") ? 1 : 0);
  if (ring != 1)
    t.addProblem(ring == 0 ? "ring_film_um" : "ring_film_file",
                 "give exactly one of ring_film_um (the film the oil-control ring leaves on the "
                 "liner) and ring_film_file (a table of it over the cycle)");
  if (const auto film = t.getOptionalSI(key("ring_film_um")))
    o.ringFilm_m = *film;
  readFilmTable(t, "ring_film_file", 100.0, o.ringFilmAngle_deg, o.ringFilmTable_m);
  if (const auto h = t.getOptionalSI(key("flooded_below_mm")))
    o.floodedBelow_m = *h;
  o.splashRate_mps = t.getSI(key("splash_rate_mm_per_s"));
  if (const auto h = t.getOptionalSI(key("splash_below_mm")))
    o.splashBelow_m = *h;
  if (o.splashRate_mps > 0.0 && std::isnan(o.splashBelow_m))
    t.addProblem("splash_rate_mm_per_s",
                 "a splash rate needs splash_below_mm (the bore height above the crank axis "
                 "below which it acts)");
  o.maxFilm_m = t.getSI(key("max_film_um"));
  o.skirtShare = t.getNumber(key("skirt_share"));
  o.initialFilm_m = t.getSI(key("initial_film_um"));
}

void readSupply(DeckSection& liner, plugin::LubricatedSkirtParameters& p) {
  plugin::SupplyFilm& f = p.supplyFilm;
  DeckSection s = liner.getSection("oil_supply");
  const bool flooded = s.has("fully_flooded") && s.getBoolOr("fully_flooded", false);
  const bool transport = s.has("liner_transport");
  const int ways = (flooded ? 1 : 0) + (s.has("film_um") ? 1 : 0) + (s.has("film_file") ? 1 : 0) +
                   (transport ? 1 : 0);
  if (ways == 0) {
    liner.addProblem("oil_supply",
                     "missing: say how oil reaches the skirt - fully_flooded: true, film_um (a "
                     "constant oil film on the liner ahead of the skirt), film_file (a table "
                     "of it over the cycle) or liner_transport (the oil carried on the liner)");
  } else if (ways > 1) {
    s.addProblem(transport ? "liner_transport" : s.has("film_file") ? "film_file" : "film_um",
                 "give exactly one of fully_flooded: true, film_um, film_file, liner_transport");
  }
  if (transport) {
    readLinerTransport(s, p.linerOil.emplace());
    if (p.lubrication.cavitation != lubrication::CavitationModel::MassConserving)
      s.addProblem("liner_transport",
                   "the oil carried on the liner needs liner.film.cavitation: mass_conserving "
                   "(the liner takes and receives the film's flows across the skirt's edges)");
  }
  if (const auto film = s.getOptionalSI(skirtKey("liner.oil_supply.film_um")))
    f.constant_m = *film;
  readFilmTable(s, "film_file", 1000.0, f.crankAngle_deg, f.thickness_m);
}

// ---- roughness, asperity contact, film ------------------------------------------------

void readSurfaces(DeckSection& liner, plugin::LubricatedSkirtParameters& p) {
  DeckSection rough = liner.getSection("roughness");
  p.roughness.rq1_m = rough.getSI(skirtKey("liner.roughness.liner_rq_um"));
  p.roughness.rq2_m = rough.getSI(skirtKey("liner.roughness.skirt_rq_um"));
  const double gamma = rough.getNumber(skirtKey("liner.roughness.peklenik"));
  p.roughness.peklenik1 = p.roughness.peklenik2 = gamma;
  if (rough.has("liner_rq_um") && rough.has("skirt_rq_um") &&
      std::hypot(p.roughness.rq1_m, p.roughness.rq2_m) < 0.01 * kUm) {
    rough.addProblem("skirt_rq_um",
                     "the composite roughness sqrt(liner_rq^2 + skirt_rq^2) must be at least "
                     "0.01 um (the asperity contact needs rough surfaces; a unit mistake?)");
  }

  DeckSection a = liner.getSection("asperity");
  contact_forces::GreenwoodTrippParameters& gt = p.asperity;
  gt.roughnessParameter = a.getNumber(skirtKey("liner.asperity.roughness_parameter"));
  gt.sigmaOverBeta = a.getNumber(skirtKey("liner.asperity.sigma_over_beta"));
  gt.surface1.youngsModulus_Pa = a.getSI(skirtKey("liner.asperity.liner_youngs_modulus_GPa"));
  gt.surface1.poissonRatio = a.getNumber(skirtKey("liner.asperity.liner_poisson_ratio"));
  gt.surface2.youngsModulus_Pa = a.getSI(skirtKey("liner.asperity.skirt_youngs_modulus_GPa"));
  gt.surface2.poissonRatio = a.getNumber(skirtKey("liner.asperity.skirt_poisson_ratio"));
  p.boundaryFriction.frictionCoefficient =
      a.getNumber(skirtKey("liner.asperity.friction_coefficient"));
  p.boundaryFriction.regularisationSpeed_mps =
      a.getSI(skirtKey("liner.asperity.regularisation_speed_mm_per_s"));
  p.lubrication.wearCoefficient_m2pN =
      a.getSI(skirtKey("liner.asperity.wear_coefficient_mm3_per_N_m"));

  DeckSection film = liner.getSection("film");
  p.lubrication.cavitation = film.getChoice<lubrication::CavitationModel>(
      skirtKey("liner.film.cavitation"),
      {{"mass_conserving", lubrication::CavitationModel::MassConserving},
       {"reynolds", lubrication::CavitationModel::Reynolds}});
  p.lubrication.faceValues = film.getChoice<lubrication::FaceValues>(
      skirtKey("liner.film.faces"), {{"nodal_mean", lubrication::FaceValues::NodalMean},
                                     {"linear_gap", lubrication::FaceValues::LinearGap}});
  p.lubrication.fillFractionFlux = film.getChoice<lubrication::FillFractionFlux>(
      skirtKey("liner.film.fill_fraction_flux"),
      {{"upwind", lubrication::FillFractionFlux::Upwind},
       {"second_order", lubrication::FillFractionFlux::LimitedSecondOrder}});
  p.lubrication.solver.solver = film.getChoice<lubrication::FilmSolverType>(
      skirtKey("liner.film.solver"),
      {{"fast", lubrication::FilmSolverType::FastActiveSet},
       {"reference_gauss_seidel", lubrication::FilmSolverType::ReferenceGaussSeidel}});
  p.lubrication.solver.tolerance = film.getNumber(skirtKey("liner.film.tolerance"));
  p.lubrication.solver.derivativeTolerance =
      film.getNumber(skirtKey("liner.film.derivative_tolerance"));
  p.lubrication.solver.fallbackToReference =
      film.getBool(skirtKey("liner.film.fallback_to_reference"));
  // The fill fraction's storage term in time (mass-conserving model): BDF2 converges with
  // the step where backward Euler smears a starved film's oil (plugin/README.md).
  p.fillFractionHistoryOrder = film.getChoice<int>(skirtKey("liner.film.fill_fraction_history"),
                                                   {{"backward_euler", 1}, {"bdf2", 2}});
}

// A compliance given as two files, the matrix under matrixKey and its node table under
// nodesKey, at least one of them given (matrix, nodes: their paths). Half a pair or a file the
// reader refuses is a problem of the section (naming the key); nullopt then.
std::optional<mapping::StructuralCompliance> readCompliancePair(
    DeckSection& e, const std::optional<std::string>& matrix,
    const std::optional<std::string>& nodes, const std::string& matrixKey,
    const std::string& nodesKey, const std::string& neither) {
  if (!matrix || !nodes) {
    e.addProblem(matrix ? nodesKey : matrixKey,
                 "give both " + matrixKey + " (the matrix) and " + nodesKey +
                     " (its node table), or neither (" + neither + ")");
    return std::nullopt;
  }
  try {
    return readStructuralCompliance(*matrix, *nodes);
  } catch (const std::exception& ex) {
    e.addProblem(matrixKey, ex.what());
    return std::nullopt;
  }
}

// The elastic skirt: on when both files are given (compliance and its node table).
void readElasticSkirt(DeckSection& liner, plugin::LubricatedSkirtParameters& p,
                      bool& gasDeformation) {
  DeckSection e = liner.getSection("elastic_skirt");
  plugin::ElasticSkirtParameters& el = p.elasticSkirt;
  el.coupling.absoluteTolerance_m = e.getSI(skirtKey("liner.elastic_skirt.tolerance_nm"));
  el.coupling.relativeTolerance = e.getNumber(skirtKey("liner.elastic_skirt.relative_tolerance"));
  el.coupling.deformationRelativeTolerance =
      e.getNumber(skirtKey("liner.elastic_skirt.deformation_relative_tolerance"));
  el.coupling.maxIterations =
      static_cast<int>(e.getInteger(skirtKey("liner.elastic_skirt.max_iterations")));
  el.coupling.scheme = e.getChoice<skirt::ElasticCouplingScheme>(
      skirtKey("liner.elastic_skirt.scheme"),
      {{"aitken", skirt::ElasticCouplingScheme::Aitken},
       {"newton", skirt::ElasticCouplingScheme::Newton},
       {"modal", skirt::ElasticCouplingScheme::Modal}});
  el.coupling.modes = static_cast<int>(e.getInteger(skirtKey("liner.elastic_skirt.modes")));
  el.coupling.modalJacobianReuse =
      static_cast<int>(e.getInteger(skirtKey("liner.elastic_skirt.modal_jacobian_reuse")));
  el.squeezeRate = e.getBool(skirtKey("liner.elastic_skirt.squeeze_rate"));
  el.coupling.exactStaticDerivative =
      e.getBool(skirtKey("liner.elastic_skirt.exact_static_derivative"));
  gasDeformation = e.getBool(skirtKey("liner.elastic_skirt.gas_deformation"));
  const auto matrix = e.getOptionalFilePath("compliance_file");
  const auto nodes = e.getOptionalFilePath("nodes_file");
  if (!matrix && !nodes) {
    if (e.has("liner_compliance_file") || e.has("liner_nodes_file"))
      e.addProblem(e.has("liner_compliance_file") ? "liner_compliance_file" : "liner_nodes_file",
                   "the elastic liner is coupled through the skirt's structural grid: give the "
                   "skirt's compliance_file and nodes_file too");
    return;
  }
  auto skirt = readCompliancePair(e, matrix, nodes, "compliance_file", "nodes_file", "rigid skirt");
  if (!matrix || !nodes)
    return;  // half a pair (reported): the liner is not read
  if (skirt) {
    el.compliance = std::move(*skirt);
    el.enabled = true;
  }
  // The elastic liner (in series with the skirt; needs it).
  const auto linerMatrix = e.getOptionalFilePath("liner_compliance_file");
  const auto linerNodes = e.getOptionalFilePath("liner_nodes_file");
  if (linerMatrix || linerNodes)
    el.liner = readCompliancePair(e, linerMatrix, linerNodes, "liner_compliance_file",
                                  "liner_nodes_file", "rigid liner");
}

void readFieldDumps(DeckSection& liner, LinerModelNeeds& needs) {
  DeckSection dumps = liner.getSection("field_dumps");
  const std::string key = "crank_angles_deg";
  if (!dumps.has(key))
    return;
  const std::vector<double> angles = dumps.getNumberList(key, Bounds::between(0.0, 720.0));
  std::set<double> seen;
  for (const double a : angles) {
    if (a >= 720.0) {
      dumps.addProblem(key, "720 deg is the next cycle's 0 deg: list angles in [0, 720)");
      return;
    }
    if (!seen.insert(a).second) {
      dumps.addProblem(key, formatNumber(a) + " deg is listed twice");
      return;
    }
  }
  needs.fieldDumpAngles_deg = angles;
  needs.fieldDumpKey = dumps.getKeyPath(key);
}

// ---- checks against the engine ---------------------------------------------------------

void checkAgainstEngine(DeckSection& liner, const mbd::EngineDescription& e,
                        const plugin::LubricatedSkirtParameters& p, const WrittenEnds& ends) {
  const double yTop = e.piston.skirtTopAbovePin_m, yBottom = yTop - e.piston.skirtLength_m;
  DeckSection profile = liner.getSection("skirt_profile");
  const skirt::AxialProfileParameters& axial = p.gap.skirtProfile.axial;
  if (axial.height_m.size() > 0) {
    const double lo = axial.mirrored ? -yTop : yBottom, hi = axial.mirrored ? -yBottom : yTop;
    const double slack = 1e-12 * e.piston.skirtLength_m;
    const double first = axial.height_m[0], last = axial.height_m[axial.height_m.size() - 1];
    if (first > lo + slack || last < hi - slack) {
      profile.addProblem(
          "axial_profile_file",
          "the table covers heights [" + formatNumber(ends.profileFirst_mm) + ", " +
              formatNumber(ends.profileLast_mm) + "] mm above the pin, but the skirt (piston." +
              "skirt_top_above_pin_mm, piston.skirt_length_mm) needs [" + formatNumber(lo / kMm) +
              ", " + formatNumber(hi / kMm) + "] mm" +
              (axial.mirrored ? " with the mirrored profile (minus the skirt's heights)" : "") +
              "; a profile is never extrapolated");
    }
  }
  if (p.linerOil && p.linerOil->ringHeightAbovePin_m < yTop) {
    liner.getSection("oil_supply")
        .getSection("liner_transport")
        .addProblem("ring_height_above_pin_mm",
                    formatNumber(p.linerOil->ringHeightAbovePin_m / kMm) +
                        " mm is below the skirt's top (piston.skirt_top_above_pin_mm = " +
                        formatNumber(yTop / kMm) +
                        " mm): the oil-control ring sits above the skirt");
  }
  const skirt::OvalityParameters& ov = p.gap.skirtProfile.ovality;
  if (ov.model == skirt::OvalityModel::Table && ov.tableAngle_rad.size() > 0) {
    const double last = ov.tableAngle_rad[ov.tableAngle_rad.size() - 1];
    const double half = 0.5 * p.grid.arcWidth_rad;
    if (last < half * (1.0 - 1e-12)) {
      profile.addProblem("ovality_file", "the table ends at " + formatNumber(ends.ovalityLast_deg) +
                                             " deg from the thrust axis, but the skirt grid "
                                             "(liner.grid.arc_width_deg) reaches " +
                                             formatNumber(half / kDeg) +
                                             " deg; an ovality table is never extrapolated");
    }
  }
  if (liner.hasProblems())
    return;

  // The hot running clearance: the thrust side's (the anti-thrust side's centre line has
  // the same profile and temperatures, so the same clearance).
  const mbd::SliderCrank kinematics(e.geometry);
  skirt::GapAssemblyParameters gap = p.gap;
  gap.travel.lowestPinHeight_m = kinematics.pinHeightAtBdc_m();
  gap.travel.highestPinHeight_m = kinematics.pinHeightAtTdc_m();
  if (!std::isfinite(gap.linerTopHeight_m))
    gap.linerTopHeight_m = kinematics.pinHeightAtTdc_m() + e.piston.compressionHeight_m;
  skirt::SkirtSideGridParameters g = p.grid;
  g.side = skirt::SkirtSide::Thrust;
  g.radius_m = 0.5 * e.piston.bore_m;
  g.skirtTopHeight_m = yTop;
  g.skirtLength_m = e.piston.skirtLength_m;
  try {
    const skirt::SkirtSideGrid grid(g);
    const skirt::HotRunningClearance hot = skirt::calcHotRunningClearance(grid, gap);
    if (hot.clearance_m < 0.0) {
      liner.addProblem("cold_radial_clearance_um",
                       "the hot running clearance is " + formatNumber(hot.clearance_m / kUm) +
                           " um at " + formatNumber(hot.skirtHeight_m / kMm) +
                           " mm above the pin (pin " + formatNumber(hot.pinHeight_m / kMm) +
                           " mm above the crank axis): the hot skirt would not fit the hot "
                           "bore; raise the clearance or check the profile and the thermal "
                           "data");
    }
  } catch (const std::exception& ex) {
    liner.addProblem("model", std::string("the skirt data do not fit this engine: ") + ex.what());
  }

  // The elastic skirt's structural grid must cover both sides' film grids.
  if (p.elasticSkirt.enabled) {
    for (const skirt::SkirtSide side : {skirt::SkirtSide::Thrust, skirt::SkirtSide::AntiThrust}) {
      g.side = side;
      try {
        (void)skirt::makeElasticCoupling(skirt::SkirtSideGrid(g), p.elasticSkirt.compliance,
                                         p.elasticSkirt.coupling);
      } catch (const std::exception& ex) {
        liner.getSection("elastic_skirt")
            .addProblem("nodes_file",
                        std::string("the compliance does not fit this skirt: ") + ex.what());
        return;
      }
      // The liner: its grid must cover the skirt's structural rows at BDC and TDC (the rows
      // move with the pin between them).
      if (!p.elasticSkirt.liner)
        continue;
      try {
        const auto check =
            skirt::makeElasticCoupling(skirt::SkirtSideGrid(g), p.elasticSkirt.compliance,
                                       p.elasticSkirt.coupling, &*p.elasticSkirt.liner);
        check->setLinerPosition(kinematics.pinHeightAtBdc_m());
        check->setLinerPosition(kinematics.pinHeightAtTdc_m());
      } catch (const std::exception& ex) {
        liner.getSection("elastic_skirt")
            .addProblem("liner_nodes_file",
                        std::string("the liner compliance does not fit this engine: ") +
                            ex.what());
        return;
      }
    }
  }
}

}  // namespace

LinerModel readLubricatedSkirt(DeckSection& liner, const LinerDeckContext& context) {
  plugin::LubricatedSkirtParameters p;
  skirt::GapAssemblyParameters& gap = p.gap;
  // 1 .. 500 um: a clearance given in mm (0.04) or nm (40000) is rejected.
  gap.coldRadialClearance_m = liner.getSI(skirtKey("liner.cold_radial_clearance_um"));
  gap.referenceTemperature_degC = liner.getNumber(skirtKey("liner.reference_temperature_degC"));
  readGrid(liner, p.grid);

  DeckSection profile = liner.getSection("skirt_profile");
  WrittenEnds ends;
  readAxialProfile(profile, gap.skirtProfile.axial, ends);
  readOvality(profile, gap.skirtProfile.ovality, ends);

  DeckSection bore = liner.getSection("bore_distortion");
  readBoreDistortion(bore, gap.linerShape);
  if (const auto top =
          bore.getOptionalSI(skirtKey("liner.bore_distortion.liner_top_above_crank_mm")))
    gap.linerTopHeight_m = *top;
  readThermal(liner, gap);

  readOil(liner, p);
  readSurfaces(liner, p);  // the film's cavitation model first: the liner transport needs it
  readSupply(liner, p);

  p.tertiaryMotion = liner.getBool(skirtKey("liner.tertiary_motion"));
  p.parallelSides = liner.getBool(skirtKey("liner.parallel_sides"));
  p.pinRetainerPlay_m = liner.getSI(skirtKey("liner.pin_retainer_play_mm"));
  p.pinRetainerStiffness_Npm = liner.getSI(skirtKey("liner.pin_retainer_stiffness_N_per_mm"));
  bool gasDeformation = false;
  readElasticSkirt(liner, p, gasDeformation);
  p.elasticSkirt.crankcasePressure_Pa = context.crankcasePressure_Pa;
  LinerModel model;
  readFieldDumps(liner, model.needs);

  model.needs.tertiaryMotion = p.tertiaryMotion;
  model.needs.stiffReason =
      "the squeeze film's damping of the piston's lateral and tilt motion grows like 1/h^3, so "
      "explicit steps collapse to nanoseconds where the film is thin";
  if (context.engineIsValid && context.engine != nullptr && !liner.hasProblems())
    checkAgainstEngine(liner, *context.engine, p, ends);
  // The gas field of the compliance, scaled by the deck's cylinder pressure (read after this
  // section: the slot is filled before any element is made).
  const auto pressure = gasDeformation && p.elasticSkirt.compliance.hasGasDisplacement()
                            ? context.cylinderPressure
                            : nullptr;
  model.maker = [p, pressure]() mutable {
    if (pressure)
      p.elasticSkirt.cylinderPressure = *pressure;
    return std::make_unique<plugin::LubricatedSkirtElement>(p);
  };
  return model;
}

}  // namespace pistondyn::io
