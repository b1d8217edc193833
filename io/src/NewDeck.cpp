// pistondyn new (NewDeck.h): the request's checks, engine.yaml, and the all-or-nothing
// write. The rules are in NewDeckRules.cpp, the tables in NewDeckTables.cpp, the key-checked
// YAML text in NewDeckText.cpp.

#include "pistondyn/io/NewDeck.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "NewDeckRules.h"
#include "NewDeckTables.h"
#include "NewDeckText.h"
#include "pistondyn/common/Cancellation.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/DeckKeys.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/lubrication/OilGrades.h"
#include "pistondyn/mbd_models/CylinderPressureCurve.h"
#include "pistondyn/mbd_models/SliderCrank.h"

namespace pistondyn::io {
namespace {

namespace fs = std::filesystem;
using namespace newdeck;

// ---- checking the request -----------------------------------------------------------------

std::string describeValue(const std::string& option, double value, const std::string& unit) {
  return option + " " + num(value) + (unit.empty() ? "" : " " + unit);
}

// "> 0", "[1, 50000]", "(0, 10]".
std::string describeBounds(const Bounds& b) {
  const bool low = std::isfinite(b.minimum), high = std::isfinite(b.maximum);
  if (low && !high)
    return (b.excludeMinimum ? "> " : ">= ") + num(b.minimum);
  if (!low && high)
    return (b.excludeMaximum ? "< " : "<= ") + num(b.maximum);
  return std::string(b.excludeMinimum ? "(" : "[") + num(b.minimum) + ", " + num(b.maximum) +
         (b.excludeMaximum ? ")" : "]");
}

// A value the deck key table bounds: positive where it must be, inside the plausible range
// (the unit-slip check names the unit that would fit).
void checkAgainstKey(const std::string& option, double value, const std::string& keyPath,
                     const std::string& unit) {
  const DeckKey& key = getEngineDeckKeys().at(keyPath);
  if (!std::isfinite(value) || !key.valid.contains(value))
    throw NewDeckError(describeValue(option, value, unit) + ": must be " +
                       describeBounds(key.valid) + (unit.empty() ? "" : " " + unit) + " (" +
                       keyPath + ")");
  if (key.plausible && !key.plausible->contains(value)) {
    const std::string slip = describeUnitSlip(key, value);
    throw NewDeckError(describeValue(option, value, unit) +
                       ": implausible for an engine (plausible " + describeBounds(*key.plausible) +
                       (unit.empty() ? "" : " " + unit) + ")" + (slip.empty() ? "" : "; " + slip));
  }
}

void checkRequest(const NewDeckRequest& r) {
  if (r.name.empty())
    throw NewDeckError("--name is empty (the engine's name; by default the folder's): give the "
                       "engine a name, it labels the deck's outputs");
  for (const char c : r.name) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      throw NewDeckError("--name holds a control character, a newline or a tab (the engine's "
                         "name; by default the folder's): give a one-line --name");
  }
  if (!(r.bore_mm > 0.0))
    throw NewDeckError(describeValue("--bore-mm", r.bore_mm, "mm") + ": the bore must be positive");
  if (!(r.stroke_mm > 0.0))
    throw NewDeckError(describeValue("--stroke-mm", r.stroke_mm, "mm") +
                       ": the stroke must be positive");
  checkAgainstKey("--bore-mm", r.bore_mm, "geometry.bore_mm", "mm");
  checkAgainstKey("--stroke-mm", r.stroke_mm, "geometry.stroke_mm", "mm");
  const double sb = r.stroke_mm / r.bore_mm;
  if (sb < kMinStrokeOverBore || sb > kMaxStrokeOverBore)
    throw NewDeckError("--stroke-mm " + num(r.stroke_mm) + " on --bore-mm " + num(r.bore_mm) +
                       ": stroke/bore " + num(roundSignificant(sb, 3)) +
                       " is implausible for a four-stroke engine (" + ratio(kMinStrokeOverBore) +
                       " .. " + ratio(kMaxStrokeOverBore) + ")");
  if (r.conrodLength_mm) {
    const double lr = *r.conrodLength_mm / (0.5 * r.stroke_mm);
    if (!(lr >= kMinRodOverCrank))
      throw NewDeckError("--rod-mm " + num(*r.conrodLength_mm) + " is too short for the " +
                         num(r.stroke_mm) + " mm stroke: L/r = " +
                         num(roundSignificant(lr, 3)) + ", at least " + ratio(kMinRodOverCrank) +
                         " (rod length at least " + num(kMinRodOverCrank * 0.5 * r.stroke_mm) +
                         " mm)");
    if (lr > kMaxRodOverCrank)
      throw NewDeckError("--rod-mm " + num(*r.conrodLength_mm) + " is implausibly long for the " +
                         num(r.stroke_mm) + " mm stroke: L/r = " +
                         num(roundSignificant(lr, 3)) + ", at most " + ratio(kMaxRodOverCrank));
  }
  if (r.compressionRatio)
    checkAgainstKey("--compression-ratio", *r.compressionRatio, "geometry.compression_ratio", "");
  if (r.pinOffset_mm && !(std::abs(*r.pinOffset_mm) < 0.25 * r.bore_mm))
    throw NewDeckError(describeValue("--pin-offset-mm", *r.pinOffset_mm, "mm") +
                       ": the pin axis must lie within a quarter of the bore of the piston axis "
                       "(|offset| < " +
                       num(0.25 * r.bore_mm) + " mm)");
  if (r.speed_rpm) {
    checkAgainstKey("--speed-rpm", *r.speed_rpm, "drive.speed_rpm", "rpm");
    const double cm = 2.0 * r.stroke_mm * 1e-3 * *r.speed_rpm / 60.0;
    if (cm > kMaxMeanPistonSpeed_mps)
      throw NewDeckError("--speed-rpm " + num(*r.speed_rpm) + " with a " + num(r.stroke_mm) +
                         " mm stroke: mean piston speed " + num(roundSignificant(cm, 3)) +
                         " m/s, implausible above " + num(kMaxMeanPistonSpeed_mps) + " m/s");
  }
  const bool table = !r.pressureTableFile.empty();
  if (r.imep_kPa && table)
    throw NewDeckError("--imep-kPa and --pressure-table both given: the imep is that of the "
                       "table; give one of them",
                       NewDeckError::Kind::Conflict);
  if (r.motored && table)
    throw NewDeckError("--motored and --pressure-table both given: --motored generates a "
                       "motored table; give one of them",
                       NewDeckError::Kind::Conflict);
  if (r.motored && r.imep_kPa)
    throw NewDeckError("--motored and --imep-kPa both given: a motored engine has no "
                       "combustion to scale to an imep; give one of them",
                       NewDeckError::Kind::Conflict);
  if (r.imep_kPa && !(*r.imep_kPa > 0.0 && *r.imep_kPa <= kMaxImep_kPa))
    throw NewDeckError(describeValue("--imep-kPa", *r.imep_kPa, "kPa") +
                       ": a fired imep must be in (0, " + num(kMaxImep_kPa) +
                       "] kPa (no combustion: --motored)");
  if (r.coldRadialClearance_um &&
      !(*r.coldRadialClearance_um >= 1.0 && *r.coldRadialClearance_um <= 500.0))
    throw NewDeckError(describeValue("--clearance-um", *r.coldRadialClearance_um, "um") +
                       ": the cold radial clearance must be in [1, 500] um");
  if (r.oilGrade) {
    try {
      lubrication::parseSaeGrade(*r.oilGrade);
    } catch (const std::invalid_argument&) {
      throw NewDeckError("--oil-grade " + *r.oilGrade +
                         ": not one of 0W-20, 0W-30, 5W-30, 5W-40, 10W-40, 15W-40");
    }
  }
  if (r.oilTemperature_degC && !(*r.oilTemperature_degC >= -60.0 && *r.oilTemperature_degC <= 250.0))
    throw NewDeckError(describeValue("--oil-temperature-degC", *r.oilTemperature_degC, "degC") +
                       ": must be in [-60, 250] degC");
}

// ---- engine.yaml ---------------------------------------------------------------------------

std::string describeOperation(const NewDeckRequest& r, const Pressure& p, double speed) {
  std::string op = num(speed) + " rpm, ";
  if (!r.pressureTableFile.empty())
    return op + "the given pressure table (imep " + num(roundSignificant(p.imep_kPa, 4)) + " kPa)";
  if (r.motored)
    return op + "motored";
  return op + "fired, imep " + num(roundSignificant(p.imep_kPa, 4)) + " kPa";
}

void writeHeader(DeckText& d, const NewDeckRequest& r, const TypeRules& t, const Engine& e,
                 const Pressure& p, const std::vector<std::string>& notes) {
  d.comment(0, "pistondyn engine deck: " + r.name + " - one cylinder of a " + t.label +
                   " engine, bore " + num(r.bore_mm) + " mm x stroke " + num(r.stroke_mm) +
                   " mm, " + describeOperation(r, p, e.speed.number) +
                   ". Made by `pistondyn new` from the values marked [U]; every other engine "
                   "value is an estimate for a " +
                   t.label + " engine of this size, marked EST with its rule. Units are part "
                   "of every key.");
  d.line("#");
  d.line("# Sources:  [U] given on the command line of pistondyn new");
  if (!r.commandLine.empty())
    d.prefixed("#               ", r.commandLine);
  d.line("#           EST estimate by pistondyn new's rules for a " + std::string(t.label) +
         " engine: ratios to");
  d.line("#               the bore, stroke and rod, most of them scaled from the example decks");
  d.line("#               (examples/engines/; README.md, \"A deck from a drawing\"). Replace them");
  d.line("#               with your engine's data when you have them: --set, or edit this file.");
  d.line("#           [T] J. Dluhos, Advanced Solution to Piston Assembly Dynamics, doctoral thesis");
  d.line("#               summary, Brno University of Technology (the examples' source)");
  for (const std::string& note : notes) {
    d.line("#");
    d.comment(0, "Note: " + note);
  }
  d.line("# Crank angle 0 deg = firing TDC.");
}

// geometry, piston, pin, conrod, crank: the drawing's values and the estimates.
void writeCrankTrain(DeckText& d, const NewDeckRequest& r, const Engine& e) {
  d.section(0, "geometry");
  d.entry(2, "bore_mm", num(r.bore_mm), "[U]");
  d.entry(2, "stroke_mm", num(r.stroke_mm), "[U]");
  d.entry(2, "conrod_length_mm", num(e.rod.number), e.rod.note);
  d.entry(2, "pin_offset_mm", num(e.pinOffset.number), e.pinOffset.note);
  d.entry(2, "crank_offset_mm", "0.0", "EST: no desaxe assumed");
  d.entry(2, "compression_ratio", num(e.cr.number), e.cr.note);
  d.blank();
  d.section(0, "piston");
  d.entry(2, "compression_height_mm", num(e.ch.number), e.ch.note);
  d.entry(2, "skirt_length_mm", num(e.skirt.number), e.skirt.note);
  d.entry(2, "skirt_top_above_pin_mm", num(e.skirtTop.number), e.skirtTop.note);
  d.entry(2, "mass_g", num(e.pistonMass.number), e.pistonMass.note);
  d.entry(2, "com_above_pin_mm", num(e.pistonCom.number), e.pistonCom.note);
  d.entry(2, "inertia_kg_mm2", num(e.pistonInertia.number), e.pistonInertia.note);
  d.blank();
  d.section(0, "pin");
  d.entry(2, "mass_g", num(e.pinMass.number), e.pinMass.note);
  d.entry(2, "inertia_kg_mm2", num(e.pinInertia.number), e.pinInertia.note);
  d.entry(2, "joint", "floating", "EST: a floating pin, as both examples");
  d.blank();
  d.section(0, "conrod");
  d.entry(2, "mass_g", num(e.rodMass.number), e.rodMass.note);
  d.entry(2, "com_from_big_end_mm", num(e.rodCom.number), e.rodCom.note);
  d.entry(2, "inertia_kg_mm2", num(e.rodInertia.number), e.rodInertia.note);
  d.blank();
  d.section(0, "crank");
  d.entry(2, "mass_g", num(e.crankMass.number), e.crankMass.note);
  d.entry(2, "com_radius_mm", num(e.crankCom.number), e.crankCom.note);
  d.entry(2, "inertia_kg_mm2", num(e.crankInertia.number), e.crankInertia.note);
}

// drive and gas: the operating point and the pressure table.
void writeOperation(DeckText& d, const NewDeckRequest& r, const TypeRules& t, const Engine& e,
                    const Pressure& p) {
  d.section(0, "drive");
  d.entry(2, "mode", "constant_speed",
          r.motored ? "motored at a constant speed" : "a constant crank speed");
  d.entry(2, "speed_rpm", num(e.speed.number), e.speed.note);
  d.blank();
  d.section(0, "gas");
  d.comment(2, p.deckComment);
  d.entry(2, "cylinder_pressure_file", p.fileName);
  d.entry(2, "crankcase_pressure_bar", "1.01325", "EST: atmospheric");
  if (!r.motored && r.pressureTableFile.empty())
    d.entry(2, "stated_imep_kPa", num(r.imep_kPa.value_or(t.imep_kPa.value)),
            std::string(p.imepEstimated ? "EST (above)" : "[U]") +
                "; the deck is rejected if the table is > 0.5 % off");
}

// liner: the lubricated skirt with the example decks' film, roughness and contact data.
void writeLiner(DeckText& d, const Engine& e) {
  d.section(0, "liner");
  d.comment(2,
            std::string("The lubricated skirt: oil film (average Reynolds, ") +
                (e.splashLubricated ? "fully flooded, Reynolds cavitation"
                                    : "partially flooded, mass-conserving cavitation") +
                ") and "
            "asperity contact on both skirt sides, with the example decks' film, roughness and "
            "contact data. Run the same engine on the ideal guide with --set "
            "liner.model=ideal_guide --set simulation.integrator=rk_merson. No bore_distortion "
            "section: ideal cylindrical liner (EST, as the thesis' study). No thermal section: "
            "the shapes and the clearance are the running (hot) ones (EST).");
  d.entry(2, "model", "lubricated_skirt");
  d.entry(2, "cold_radial_clearance_um", num(e.clearance.number), e.clearance.note);
  d.entry(2, "reference_temperature_degC", "20.0",
          "EST: the temperature the shapes are measured at");
  d.section(2, "grid", "numerics (each skirt side), not engine data");
  d.entry(4, "arc_width_deg", "80.0", "the film region around the thrust / anti-thrust axis");
  d.entry(4, "nodes_circumferential", "64", "nodes around the arc (--fidelity preview: 24)");
  d.entry(4, "nodes_axial", "48", "nodes along the skirt (--fidelity preview: 40)");
  d.entry(4, "axial_clustering", "0.0", "uniform axial spacing, as the examples");
  d.section(2, "skirt_profile");
  d.entry(4, "axial_profile_file", "skirt_profile.csv",
          "EST: the gasoline example's barrel scaled to this skirt and bore (the file's header "
          "states the rule)");
  d.entry(4, "mirrored", "false", "the thesis' \"original\" profile");
  d.entry(4, "ovality_diametral_um", num(e.ovality.number), e.ovality.note);
  d.entry(4, "ovality_cos4_coefficient", "0.0", "EST: the pure elliptic law, as the examples");
  d.section(2, "oil");
  d.entry(4, "grade", e.oilGrade, e.oilNote + " (data-sheet oil, lubrication/OilGrades.h)");
  d.entry(4, "temperature_degC", num(e.oilTemperature.number), e.oilTemperature.note);
  d.section(2, "oil_supply");
  if (e.splashLubricated)
    d.entry(4, "fully_flooded", "true", e.lubricationNote);
  else
    d.entry(4, "film_um", "1.0", e.lubricationNote);
  d.section(2, "roughness", "entered once: flow factors and asperity contact");
  d.entry(4, "liner_rq_um", "0.4", "EST: plateau-honed cast-iron bore, as both examples");
  d.entry(4, "skirt_rq_um", "0.6", "EST: machined skirt with its coating, as both examples");
  d.entry(4, "peklenik", "1.0", "EST: isotropic roughness");
  d.section(2, "asperity");
  d.entry(4, "roughness_parameter", "0.04", "EST: eta beta sigma of the ring-pack literature");
  d.entry(4, "sigma_over_beta", "0.001", "EST: of the ring-pack literature");
  d.entry(4, "liner_youngs_modulus_GPa", "115.0", "EST: grey cast iron bore or sleeve");
  d.entry(4, "liner_poisson_ratio", "0.26", "EST: grey cast iron");
  d.entry(4, "skirt_youngs_modulus_GPa", "75.0",
          "EST: Al-Si piston alloy near its operating temperature");
  d.entry(4, "skirt_poisson_ratio", "0.33", "EST: Al-Si piston alloy");
  d.entry(4, "friction_coefficient", "0.1", "EST: f_dry of the thesis' study [T]");
  d.entry(4, "regularisation_speed_mm_per_s", "1.0",
          "numerics: Coulomb friction smoothed below 1 mm/s");
  d.entry(4, "wear_coefficient_mm3_per_N_m", "0.0", "no wear computed");
  d.section(2, "film");
  if (e.splashLubricated) {
    d.entry(4, "cavitation", "reynolds",
            "flooded: p >= 0, as the B&S example (README.md, \"Example engines\")");
    d.entry(4, "faces", "linear_gap", "face conductance exact for a gap linear between nodes");
  } else {
    d.entry(4, "cavitation", "mass_conserving", "JFO / Elrod-Adams: what partial flooding needs");
    d.entry(4, "fill_fraction_history", "bdf2", "second order in time like the stepper");
    d.entry(4, "faces", "linear_gap",
            "second order along the sliding direction, as the examples (README.md, \"Example "
            "engines\")");
    d.entry(4, "fill_fraction_flux", "second_order", "limited second-order fill fraction");
  }
  d.entry(4, "solver", "fast", "active-set solver");
  d.entry(4, "tolerance", "1.0e-8", "film residual, relative to the driving fluxes");
  d.entry(2, "tertiary_motion", "false", "EST: as the thesis' study");
}

// simulation: the example decks' settings (until periodic, at most 8 cycles).
void writeSimulation(DeckText& d) {
  d.section(0, "simulation");
  d.entry(2, "start_angle_deg", "0", "first row at firing TDC");
  d.entry(2, "cycles", "8", "at most, until the cycles repeat");
  d.entry(2, "until_periodic", "true");
  d.entry(2, "periodic_fmep_tolerance", "0.005", "two cycles agree: fmep within 0.5 % ...");
  d.entry(2, "periodic_pose_tolerance_um", "0.2",
          "... and u_lat, tilt x skirt length within 0.2 um");
  d.entry(2, "output_step_deg", "1.0", "one row per crank degree");
  d.entry(2, "integrator", "linearly_implicit_bdf2", "the squeeze film is stiff");
  d.entry(2, "stepper_order", "3", "BDF3: the slow secondary motion's error falls as h^3");
  d.entry(2, "pose_tolerance_nm", "1",
          "stepper's per-step error on lateral, tertiary, tilt x L");
  d.entry(2, "max_step_deg", "1", "largest step [deg of crank], as the examples");
  d.entry(2, "gravity_mps2", "9.80665", "cylinder vertical, head up");
}

std::string makeEngineYaml(const NewDeckRequest& r, const TypeRules& t, const Engine& e,
                           const Pressure& p, const std::vector<std::string>& notes) {
  DeckText d;
  writeHeader(d, r, t, e, p, notes);
  d.blank();
  d.section(0, "engine");
  d.entry(2, "name", quoted(r.name), "[U]");
  d.blank();
  writeCrankTrain(d, r, e);
  d.blank();
  writeOperation(d, r, t, e, p);
  d.blank();
  writeLiner(d, e);
  d.blank();
  writeSimulation(d);
  return d.str();
}

std::vector<std::string> makeNotes(const NewDeckRequest& r, const TypeRules& t) {
  std::vector<std::string> notes;
  if (r.bore_mm < t.typicalBoreMin_mm || r.bore_mm > t.typicalBoreMax_mm)
    notes.push_back("the " + num(r.bore_mm) + " mm bore lies outside the " +
                    num(t.typicalBoreMin_mm) + "-" + num(t.typicalBoreMax_mm) +
                    " mm bores the " + t.label +
                    " rules are drawn from: the estimates are extrapolated; check them.");
  return notes;
}


// Removes a temporary folder unless released.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(fs::path path) : path_(std::move(path)) {}
  ~TemporaryFolder() {
    if (!path_.empty()) {
      std::error_code ec;
      fs::remove_all(path_, ec);
    }
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  void release() { path_.clear(); }

 private:
  fs::path path_;
};

// `folder` absolute, without a trailing separator.
fs::path normaliseFolder(const std::string& folder) {
  fs::path p = fs::absolute(fs::path(folder)).lexically_normal();
  if (p.filename().empty() && p.has_parent_path())
    p = p.parent_path();
  return p;
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  if (from.empty())
    return text;
  for (std::size_t pos = text.find(from); pos != std::string::npos;
       pos = text.find(from, pos + to.size()))
    text.replace(pos, from.size(), to);
  return text;
}

}  // namespace

const char* getEngineTypeName(EngineType type) {
  switch (type) {
    case EngineType::PassengerCarGasoline:
      return "gasoline";
    case EngineType::SmallAirCooled:
      return "small-air-cooled";
    case EngineType::Diesel:
      return "diesel";
  }
  return "gasoline";
}

std::vector<std::string> getEngineTypeNames() {
  return {getEngineTypeName(EngineType::PassengerCarGasoline),
          getEngineTypeName(EngineType::SmallAirCooled), getEngineTypeName(EngineType::Diesel)};
}

std::optional<EngineType> parseEngineType(const std::string& name) {
  for (const EngineType t :
       {EngineType::PassengerCarGasoline, EngineType::SmallAirCooled, EngineType::Diesel}) {
    if (name == getEngineTypeName(t))
      return t;
  }
  return std::nullopt;
}

NewDeck makeNewDeck(const NewDeckRequest& r) {
  checkRequest(r);
  const TypeRules& t = getRules(r.type);
  NewDeck deck;
  const Engine e = estimateEngine(r, t, deck.estimated);
  if (e.rod.number / (0.5 * r.stroke_mm) < kMinRodOverCrank)
    throw NewDeckError("the estimated rod is too short (a bug in the rules)");
  mbd::CrankTrainGeometry g;
  g.crankRadius_m = 0.5e-3 * r.stroke_mm;
  g.conrodLength_m = 1e-3 * e.rod.number;
  g.pinOffset_m = 1e-3 * e.pinOffset.number;
  const mbd::SliderCrank kin(g);
  const mbd::CylinderVolume vol(kin, 1e-3 * r.bore_mm, e.cr.number);
  const Pressure p = r.pressureTableFile.empty() ? generatePressureTable(r, t, e, vol)
                                                 : copyPressureTable(r, vol);
  if (p.imepEstimated)
    deck.estimated.push_back("gas.stated_imep_kPa");
  const Profile profile = makeSkirtProfile(r.name, e, r.bore_mm);
  deck.notes = makeNotes(r, t);
  deck.files.push_back({"engine.yaml", makeEngineYaml(r, t, e, p, deck.notes)});
  deck.files.push_back({"skirt_profile.csv", profile.text});
  deck.files.push_back({p.fileName, p.text});
  deck.imep_kPa = p.imep_kPa;
  deck.peakPressure_bar = p.peak_bar;
  deck.peakPressureAngle_deg = p.peakAngle_deg;
  return deck;
}

std::string findNewDeckFolderProblem(const std::string& folder) {
  if (folder.empty())
    return "is empty: name a folder";
  const fs::path given(folder);
  const std::string last =
      given.filename().empty() ? given.parent_path().filename().string() : given.filename().string();
  if (last == "." || last == "..")
    return "names the current or the parent folder: name a new folder";
  std::error_code ec;
  const fs::path target = normaliseFolder(folder);
  if (fs::exists(target, ec)) {
    if (!fs::is_directory(target, ec))
      return "exists and is a file, not a folder";
    if (!fs::is_empty(target, ec) || ec)
      return "exists and is not empty: name a new or an empty folder (nothing is overwritten)";
  }
  const fs::path parent = target.parent_path();
  if (!fs::is_directory(parent, ec))
    return "cannot be made: its parent folder " + parent.string() + " does not exist";
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    return "cannot be made: no permission to write in " + parent.string();
  return {};
}

void writeNewDeck(const NewDeck& deck, const std::string& folder) {
  if (const std::string problem = findNewDeckFolderProblem(folder); !problem.empty())
    throw NewDeckError(folder + ": " + problem, NewDeckError::Kind::Folder);
  const fs::path target = normaliseFolder(folder);
  std::string staging = (target.parent_path() / ("." + target.filename().string() +
                                                 ".pistondyn-new-XXXXXX"))
                            .string();
  if (::mkdtemp(staging.data()) == nullptr)
    throw std::runtime_error(target.parent_path().string() +
                             ": cannot make a temporary folder: " + std::strerror(errno));
  TemporaryFolder guard(staging);
  // mkdtemp makes it private (0700); the deck folder gets the usual permissions.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(staging.c_str(), 0777 & ~mask);
  for (const NewDeckFile& f : deck.files) {
    std::ofstream out(fs::path(staging) / f.name, std::ios::binary);
    out << f.text;
    out.close();
    if (!out)
      throw std::runtime_error((target / f.name).string() + ": cannot be written");
  }
  try {
    loadEngineDeck((fs::path(staging) / "engine.yaml").string(), {});
  } catch (const DeckError& e) {
    throw NewDeckError("the deck made for these values does not pass its check (the estimates "
                       "do not fit this engine; give the values that fail):\n" +
                           replaceAll(e.what(), staging, target.string()),
                       NewDeckError::Kind::FailedCheck);
  }
  common::throwIfCancelled();
  std::error_code ec;
  fs::rename(staging, target, ec);
  if (ec)
    throw std::runtime_error(target.string() + ": cannot be made: " + ec.message());
  guard.release();
}

}  // namespace pistondyn::io
