#include "pistondyn/io/NewDeck.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pistondyn/common/Cancellation.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/DeckKeys.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/PressureTableCsv.h"
#include "pistondyn/lubrication/OilGrades.h"
#include "pistondyn/mbd_models/CylinderPressureCurve.h"
#include "pistondyn/mbd_models/SingleZonePressureModel.h"
#include "pistondyn/mbd_models/SliderCrank.h"

namespace pistondyn::io {
namespace {

namespace fs = std::filesystem;

constexpr double kSteel_kg_per_m3 = 7850.0;
constexpr double kAluminium_kg_per_m3 = 2700.0;

// Plausibility limits of the command beyond the deck keys' own (README.md, "A deck from a
// drawing"): a four-stroke engine's stroke/bore ratio, rod ratio, mean piston speed and imep.
constexpr double kMinStrokeOverBore = 0.4, kMaxStrokeOverBore = 2.5;
constexpr double kMinRodOverCrank = 2.5, kMaxRodOverCrank = 8.0;
constexpr double kMaxMeanPistonSpeed_mps = 30.0;
constexpr double kMaxImep_kPa = 3000.0;

// The pressure table's step [deg] (as the example tables).
constexpr double kTableStep_deg = 0.5;

// ---- the estimating rules, one set per engine type --------------------------------------

// Every ratio of one engine type with the reason the deck's comment gives for it.
struct Ratio {
  double value;
  const char* why;
};

struct TypeRules {
  const char* label;  // in comments: "passenger-car gasoline"
  double typicalBoreMin_mm, typicalBoreMax_mm;
  Ratio rodOverCrankRadius;
  Ratio boreOverPinOffset;  // 0: no offset
  Ratio compressionRatio;
  Ratio compressionHeightOverBore;
  Ratio skirtLengthOverBore;
  Ratio skirtTopOverSkirtLength;
  Ratio pistonMass_g_per_cm3;  // piston mass / (bore in cm)^3
  Ratio pistonComOverCompressionHeight;
  Ratio pistonInertiaOverMassBore2;
  Ratio pinDiameterOverBore;
  double pinLengthOverBore;
  const char* rodMaterial;
  double rodDensity_kg_per_m3;
  Ratio rodMassOverDensityBore2Length;
  Ratio rodComOverLength;
  Ratio rodInertiaOverMassLength2;
  Ratio crankMassOverSteelBore2Stroke;
  Ratio crankComOverCrankRadius;
  Ratio crankInertiaOverMassBore2;
  Ratio speed_rpm;
  Ratio imep_kPa;
  mbd::SingleZoneCycle fired;
  const char* firedWhy;
  Ratio clearancePerMilleOfBore;
  const char* oilGrade;
  const char* oilWhy;
};

// The pin: a hollow steel tube of outer diameter D = (ratio) x bore, inner 0.6 D.
constexpr double kPinInnerOverOuter = 0.6;
// Fired film temperature (the thesis' 105 C) and motored (a rig warmed by friction only).
constexpr double kFiredOil_degC = 105.0, kMotoredOil_degC = 40.0;
// Motored: wide-open intake and exhaust (the Briggs & Stratton example's rig).
constexpr double kMotoredIntake_bar = 0.95, kMotoredExhaust_bar = 1.03;
// Skirt profile and ovality scaled from the gasoline example (74.5 mm bore, 30 mm skirt).
constexpr double kExampleBore_mm = 74.5, kExampleSkirt_mm = 30.0;
constexpr double kExampleBarrel_um_per_mm2 = 0.12, kExampleOvality_um = 300.0;
constexpr double kMinimumClearanceLineFromTop = 0.6;  // of the skirt length

mbd::SingleZoneCycle makeCycle(double k, double pInt_bar, double pExh_bar, double ivc, double evo,
                               double soc, double burn) {
  mbd::SingleZoneCycle c;
  c.polytropicExponent = k;
  c.intakePressure_Pa = pInt_bar * 1e5;
  c.exhaustPressure_Pa = pExh_bar * 1e5;
  c.intakeValveClosing_deg = ivc;
  c.exhaustValveOpening_deg = evo;
  c.combustionStart_deg = soc;
  c.combustionDuration_deg = burn;
  return c;
}

const TypeRules& getRules(EngineType type) {
  static const TypeRules gasoline{
      "passenger-car gasoline",
      60.0,
      110.0,
      {3.5, "passenger-car gasoline engines 3.0-3.6; the gasoline example's 140 mm rod"},
      {150.0, "0.5 mm on the gasoline example's 74.5 mm bore"},
      {10.0, "the gasoline example's EA211; passenger-car gasoline engines 9.5-12"},
      {0.38, "passenger-car gasoline pistons 0.33-0.42 x bore; the gasoline example 28 mm"},
      {0.40, "the gasoline example's 30 mm on 74.5 mm"},
      {0.40, "the gasoline example: 12 mm above the pin of a 30 mm skirt"},
      {0.51, "cast aluminium piston with rings, no pin; the gasoline example's 210 g"},
      {0.18, "the gasoline example's 5 mm of 28 mm"},
      {0.15, "a solid disc of the bore's diameter and height gives 0.146; the gasoline "
             "example's 180 kg mm^2"},
      {0.24, "the gasoline example's 18 x 45 mm pin"},
      0.60,
      "forged steel",
      kSteel_kg_per_m3,
      {0.069, "the gasoline example's 420 g"},
      {0.27, "the gasoline example's 38 mm of 140 mm"},
      {0.23, "the gasoline example's 1900 kg mm^2"},
      {0.72, "one throw with its counterweights; the gasoline example's 2500 g"},
      {-0.10, "counterweight side; the gasoline example's -4 mm"},
      {0.17, "both examples 0.16-0.18"},
      {2000.0, "the thesis' study point"},
      {600.0, "part load, as the thesis' study point (598 kPa)"},
      makeCycle(1.30, 0.60, 1.05, 580.0, 140.0, -15.0, 50.0),
      "the gasoline example's: throttled part load",
      {0.54, "the gasoline example's 40 um on 74.5 mm, about 0.5 per mille, usual for an Al-Si "
             "skirt"},
      "0W-30",
      "the thesis' study oil"};
  static const TypeRules smallAirCooled{
      "small air-cooled",
      50.0,
      95.0,
      {3.2, "the B&S 5 hp's 98.4 mm rod on a 61.9 mm stroke, 3.18"},
      {0.0, "none assumed, as the Briggs & Stratton example"},
      {6.0, "B&S side-valve engines 6:1; overhead-valve small engines 8-8.5: give "
            "--compression-ratio"},
      {0.46, "the B&S 5 hp's 30.2 mm on its 65.1 mm bore"},
      {0.43, "the B&S example's 28 mm on 65.1 mm"},
      {0.36, "the B&S example: 10 mm above the pin of a 28 mm skirt"},
      {0.27, "cast aluminium piston with rings, no pin; the B&S example's 75 g"},
      {0.20, "the B&S example's 6 mm of 30.2 mm"},
      {0.11, "the B&S example's 35 kg mm^2"},
      {0.19, "the B&S example's 12.5 mm pin"},
      0.60,
      "die-cast aluminium",
      kAluminium_kg_per_m3,
      {0.069, "the gasoline example's section in aluminium: the B&S example's 60 g"},
      {0.32, "the B&S example's 24 mm of 76 mm"},
      {0.13, "the B&S example's 45 kg mm^2"},
      {0.57, "one throw with its counterweight; the B&S example's 900 g"},
      {-0.125, "counterweight side; the B&S example's -3 mm"},
      {0.17, "both examples 0.16-0.18"},
      {3000.0, "governed small engines run 2500-3600 rpm"},
      {500.0, "part load of a small side-valve engine"},
      makeCycle(1.30, 0.95, 1.03, 585.0, 135.0, -20.0, 60.0),
      "the B&S example's valve events and unthrottled intake; a slow side-valve burn",
      {0.81, "the B&S example's measured 53 um on 65.1 mm [T]: air-cooled cylinders run "
             "larger clearances"},
      "5W-30",
      "B&S's all-temperature synthetic recommendation, as the B&S example"};
  static const TypeRules diesel{
      "diesel",
      70.0,
      140.0,
      {3.3, "passenger-car and light-duty diesels 3.0-3.6"},
      {0.0, "none assumed"},
      {17.0, "direct-injection diesels 15-18"},
      {0.60, "diesel pistons with a bowl and a high top land 0.5-0.7 x bore"},
      {0.50, "diesel pistons' longer skirts"},
      {0.40, "as the gasoline example"},
      {1.10, "aluminium diesel piston with bowl and ring carrier, about twice a gasoline "
             "piston of the bore"},
      {0.30, "the heavier crown of a diesel piston"},
      {0.15, "a solid disc of the bore's diameter and height gives 0.146"},
      {0.38, "diesel pins 0.35-0.40 x bore for the peak pressure"},
      0.80,
      "forged steel",
      kSteel_kg_per_m3,
      {0.090, "a heavier section than the gasoline example's 0.069 for the peak pressure"},
      {0.27, "as the gasoline example"},
      {0.23, "as the gasoline example"},
      {0.72, "one throw with its counterweights, as the gasoline example"},
      {-0.10, "counterweight side, as the gasoline example"},
      {0.17, "both examples 0.16-0.18"},
      {2000.0, "a diesel's mid-range speed"},
      {800.0, "part load of a turbocharged diesel"},
      makeCycle(1.30, 1.50, 1.70, 570.0, 130.0, -8.0, 60.0),
      "turbocharged: boost 1.5 bar, exhaust back pressure 1.7 bar; one Wiebe burn of 60 deg "
      "from 8 deg before TDC (no premixed peak)",
      {0.60, "aluminium diesel pistons run larger clearances than gasoline ones for their "
             "hotter crown"},
      "5W-40",
      "a diesel-approved multigrade"};
  switch (type) {
    case EngineType::PassengerCarGasoline:
      return gasoline;
    case EngineType::SmallAirCooled:
      return smallAirCooled;
    case EngineType::Diesel:
      return diesel;
  }
  return gasoline;
}

// ---- numbers ------------------------------------------------------------------------------

double roundTo(double x, double quantum) {
  return quantum * std::round(x / quantum);
}

double roundSignificant(double x, int digits) {
  if (x == 0.0 || !std::isfinite(x))
    return x;
  const double magnitude = std::pow(10.0, digits - 1 - std::floor(std::log10(std::abs(x))));
  return std::round(x * magnitude) / magnitude;
}

// Shortest plain text of a rounded value ("28.3", "140", "-0.1").
std::string num(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

// A ratio as the rules print it ("0.38", "0.069", "-0.125").
std::string ratio(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

// ---- the deck's text ----------------------------------------------------------------------

// Builds YAML with the example decks' layout: comments aligned at one column, wrapped
// comment lines continuing at that column.
class DeckText {
 public:
  static constexpr std::size_t kCommentColumn = 36, kWidth = 100;

  void line(const std::string& text) { text_ += text + "\n"; }
  void blank() { text_ += "\n"; }
  // "# text" lines at `indent`, wrapped.
  void comment(int indent, const std::string& text) {
    const std::string lead(static_cast<std::size_t>(indent), ' ');
    for (const std::string& l : wrap(text, kWidth - lead.size() - 2))
      text_ += lead + "# " + l + "\n";
  }
  // Comment lines that each start with `prefix` ("#    "), wrapped.
  void prefixed(const std::string& prefix, const std::string& text) {
    for (const std::string& l : wrap(text, kWidth - prefix.size()))
      text_ += prefix + l + "\n";
  }
  // "key: value   # comment" at `indent`, the comment wrapped at the comment column.
  void entry(int indent, const std::string& key, const std::string& value,
             const std::string& note = {}) {
    std::string head = std::string(static_cast<std::size_t>(indent), ' ') + key + ":" +
                       (value.empty() ? "" : " " + value);
    if (note.empty()) {
      text_ += head + "\n";
      return;
    }
    const std::size_t column = std::max(kCommentColumn, head.size() + 2);
    head.resize(column, ' ');
    const std::vector<std::string> lines = wrap(note, kWidth - column - 2);
    for (std::size_t i = 0; i < lines.size(); ++i)
      text_ += (i == 0 ? head : std::string(column, ' ')) + "# " + lines[i] + "\n";
  }
  const std::string& str() const { return text_; }

 private:
  static std::vector<std::string> wrap(const std::string& text, std::size_t width) {
    std::vector<std::string> lines;
    std::istringstream words(text);
    std::string word, current;
    while (words >> word) {
      if (!current.empty() && current.size() + 1 + word.size() > width) {
        lines.push_back(current);
        current.clear();
      }
      current += (current.empty() ? "" : " ") + word;
    }
    if (!current.empty() || lines.empty())
      lines.push_back(current);
    return lines;
  }
  std::string text_;
};

// A YAML double-quoted scalar.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + "\"";
}

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
    throw NewDeckError("NAME is empty: give the engine a name (it labels the deck's outputs)");
  for (const char c : r.name) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      throw NewDeckError("NAME holds a control character (a newline or tab): give a one-line "
                         "name");
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

// ---- the values ---------------------------------------------------------------------------

// One value of the deck: its text and the comment (its mark and rule).
struct Value {
  double number = 0.0;
  std::string note;
};

// The engine's values, given ([U]) or estimated (EST + rule), in deck units.
struct Engine {
  Value rod, pinOffset, cr, ch, skirt, skirtTop, pistonMass, pistonCom, pistonInertia;
  Value pinMass, pinInertia, rodMass, rodCom, rodInertia, crankMass, crankCom, crankInertia;
  Value speed, clearance, ovality, oilTemperature;
  std::string oilGrade, oilNote;
  double pinOuter_mm = 0, pinInner_mm = 0, pinLength_mm = 0;
};

class Estimator {
 public:
  Estimator(const NewDeckRequest& r, const TypeRules& rules, std::vector<std::string>& estimated)
      : r_(r), t_(rules), estimated_(estimated) {}

  Value given(double v) const { return {v, "[U]"}; }
  Value est(const std::string& key, double v, const std::string& rule) {
    estimated_.push_back(key);
    return {v, "EST: " + rule};
  }
  static std::string why(const Ratio& q) { return std::string(" (") + q.why + ")"; }

  Engine estimate() {
    Engine e;
    const double B = r_.bore_mm, S = r_.stroke_mm, rc = 0.5 * S;
    e.rod = r_.conrodLength_mm
                ? given(*r_.conrodLength_mm)
                : est("geometry.conrod_length_mm", roundTo(t_.rodOverCrankRadius.value * rc, 0.1),
                      "L/r = " + ratio(t_.rodOverCrankRadius.value) + why(t_.rodOverCrankRadius));
    const double L = e.rod.number;
    if (r_.pinOffset_mm) {
      e.pinOffset = given(*r_.pinOffset_mm);
    } else if (t_.boreOverPinOffset.value > 0.0) {
      e.pinOffset = est("geometry.pin_offset_mm", roundTo(B / t_.boreOverPinOffset.value, 0.1),
                        "bore/" + ratio(t_.boreOverPinOffset.value) +
                            " towards the thrust side, to 0.1 mm" + why(t_.boreOverPinOffset));
    } else {
      e.pinOffset = est("geometry.pin_offset_mm", 0.0, "no offset" + why(t_.boreOverPinOffset));
    }
    e.cr = r_.compressionRatio
               ? given(*r_.compressionRatio)
               : est("geometry.compression_ratio", t_.compressionRatio.value,
                     ratio(t_.compressionRatio.value) + why(t_.compressionRatio));
    e.ch = est("piston.compression_height_mm",
               roundTo(t_.compressionHeightOverBore.value * B, 0.1),
               "compression height " + ratio(t_.compressionHeightOverBore.value) + " x bore" +
                   why(t_.compressionHeightOverBore));
    e.skirt = est("piston.skirt_length_mm", roundTo(t_.skirtLengthOverBore.value * B, 0.1),
                  "skirt length " + ratio(t_.skirtLengthOverBore.value) + " x bore" +
                      why(t_.skirtLengthOverBore));
    const double top = roundTo(t_.skirtTopOverSkirtLength.value * e.skirt.number, 0.1);
    e.skirtTop = est("piston.skirt_top_above_pin_mm", top,
                     ratio(t_.skirtTopOverSkirtLength.value) +
                         " x skirt length: the skirt from " + num(top) + " mm above to " +
                         num(roundTo(e.skirt.number - top, 0.1)) + " mm below the pin axis" +
                         why(t_.skirtTopOverSkirtLength));
    const double boreCm = B / 10.0;
    e.pistonMass = est("piston.mass_g",
                       roundSignificant(t_.pistonMass_g_per_cm3.value * boreCm * boreCm * boreCm, 3),
                       ratio(t_.pistonMass_g_per_cm3.value) + " g x (bore/cm)^3" +
                           why(t_.pistonMass_g_per_cm3));
    e.pistonCom = est("piston.com_above_pin_mm",
                      roundTo(t_.pistonComOverCompressionHeight.value * e.ch.number, 0.1),
                      ratio(t_.pistonComOverCompressionHeight.value) + " x compression height" +
                          why(t_.pistonComOverCompressionHeight));
    e.pistonInertia = est(
        "piston.inertia_kg_mm2",
        roundSignificant(t_.pistonInertiaOverMassBore2.value * e.pistonMass.number * 1e-3 * B * B, 3),
        ratio(t_.pistonInertiaOverMassBore2.value) +
            " x mass x bore^2, about the COM, pin-axis direction" +
            why(t_.pistonInertiaOverMassBore2));
    estimatePin(e, B);
    estimateRodAndCrank(e, B, S, L);
    e.speed = r_.speed_rpm ? given(*r_.speed_rpm)
                           : est("drive.speed_rpm", t_.speed_rpm.value,
                                 num(t_.speed_rpm.value) + " rpm" + why(t_.speed_rpm) +
                                     "; give --speed-rpm");
    estimateLiner(e, B);
    return e;
  }

 private:
  void estimatePin(Engine& e, double B) {
    e.pinOuter_mm = roundTo(t_.pinDiameterOverBore.value * B, 0.1);
    e.pinInner_mm = roundTo(kPinInnerOverOuter * e.pinOuter_mm, 0.1);
    e.pinLength_mm = roundTo(t_.pinLengthOverBore * B, 0.1);
    const double D = e.pinOuter_mm, d = e.pinInner_mm, l = e.pinLength_mm;
    const double mass_g = kSteel_kg_per_m3 * 1e-6 * M_PI / 4.0 * (D * D - d * d) * l;  // g
    e.pinMass = est("pin.mass_g", roundSignificant(mass_g, 3),
                    "hollow steel pin " + num(D) + " x " + num(d) + " x " + num(l) +
                        " mm (outer " + ratio(t_.pinDiameterOverBore.value) + " x bore, inner " +
                        ratio(kPinInnerOverOuter) + " x outer, length " +
                        ratio(t_.pinLengthOverBore) + " x bore; " + t_.pinDiameterOverBore.why +
                        "): 7850 kg/m^3 x pi/4 (D^2 - d^2) x length");
    e.pinInertia = est("pin.inertia_kg_mm2",
                       roundSignificant(e.pinMass.number * 1e-3 * (D * D + d * d) / 8.0, 3),
                       "mass x (D^2 + d^2)/8 of that tube, about its axis");
  }

  void estimateRodAndCrank(Engine& e, double B, double S, double L) {
    const double rodMass_g =
        t_.rodMassOverDensityBore2Length.value * t_.rodDensity_kg_per_m3 * 1e-6 * B * B * L;
    e.rodMass = est("conrod.mass_g", roundSignificant(rodMass_g, 3),
                    std::string(t_.rodMaterial) + " rod: " +
                        ratio(t_.rodMassOverDensityBore2Length.value) + " x " +
                        num(t_.rodDensity_kg_per_m3) + " kg/m^3 x bore^2 x rod length" +
                        why(t_.rodMassOverDensityBore2Length));
    e.rodCom = est("conrod.com_from_big_end_mm", roundTo(t_.rodComOverLength.value * L, 0.1),
                   ratio(t_.rodComOverLength.value) + " x rod length from the big end" +
                       why(t_.rodComOverLength));
    e.rodInertia = est(
        "conrod.inertia_kg_mm2",
        roundSignificant(t_.rodInertiaOverMassLength2.value * e.rodMass.number * 1e-3 * L * L, 3),
        ratio(t_.rodInertiaOverMassLength2.value) + " x mass x rod length^2, about the COM" +
            why(t_.rodInertiaOverMassLength2));
    const double crankMass_g =
        t_.crankMassOverSteelBore2Stroke.value * kSteel_kg_per_m3 * 1e-6 * B * B * S;
    e.crankMass = est("crank.mass_g", roundSignificant(crankMass_g, 3),
                      ratio(t_.crankMassOverSteelBore2Stroke.value) +
                          " x 7850 kg/m^3 x bore^2 x stroke" +
                          why(t_.crankMassOverSteelBore2Stroke));
    e.crankCom = est("crank.com_radius_mm",
                     roundTo(t_.crankComOverCrankRadius.value * 0.5 * S, 0.1),
                     ratio(t_.crankComOverCrankRadius.value) + " x crank radius" +
                         why(t_.crankComOverCrankRadius));
    e.crankInertia = est(
        "crank.inertia_kg_mm2",
        roundSignificant(t_.crankInertiaOverMassBore2.value * e.crankMass.number * 1e-3 * B * B, 3),
        ratio(t_.crankInertiaOverMassBore2.value) + " x mass x bore^2, about the COM" +
            why(t_.crankInertiaOverMassBore2));
  }

  void estimateLiner(Engine& e, double B) {
    e.clearance =
        r_.coldRadialClearance_um
            ? given(*r_.coldRadialClearance_um)
            : est("liner.cold_radial_clearance_um",
                  roundTo(t_.clearancePerMilleOfBore.value * B, 1.0),
                  ratio(t_.clearancePerMilleOfBore.value) + " per mille of the bore, to 1 um" +
                      why(t_.clearancePerMilleOfBore));
    e.ovality = est("liner.skirt_profile.ovality_diametral_um",
                    roundTo(kExampleOvality_um * B / kExampleBore_mm, 10.0),
                    "elliptic skirt section, D_thrust - D_pin: the gasoline example's 300 um x "
                    "bore/74.5 mm, to 10 um (as the B&S example's 260 um)");
    e.oilGrade = r_.oilGrade ? lubrication::toString(lubrication::parseSaeGrade(*r_.oilGrade))
                             : t_.oilGrade;
    if (r_.oilGrade) {
      e.oilNote = "[U]";
    } else {
      estimated_.push_back("liner.oil.grade");
      e.oilNote = std::string("EST: ") + t_.oilWhy;
    }
    const bool motored = r_.motored;
    e.oilTemperature =
        r_.oilTemperature_degC
            ? given(*r_.oilTemperature_degC)
            : est("liner.oil.temperature_degC", motored ? kMotoredOil_degC : kFiredOil_degC,
                  motored ? "a motored engine warms its oil by friction only (as the B&S "
                            "example's rig)"
                          : "fired: the thesis' 105 C");
  }

  const NewDeckRequest& r_;
  const TypeRules& t_;
  std::vector<std::string>& estimated_;
};

// ---- the tables ---------------------------------------------------------------------------

// A step of 1, 2, 2.5 or 5 x 10^k nearest below `x`.
double niceStep(double x) {
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  double best = decade;
  for (const double m : {1.0, 2.0, 2.5, 5.0}) {
    if (m * decade <= x * (1.0 + 1e-12))
      best = m * decade;
  }
  return best;
}

struct Profile {
  std::string text;
  double barrel_um_per_mm2, minimumLine_mm, step_mm, halfRange_mm;
};

Profile makeSkirtProfile(const std::string& name, const Engine& e, double bore_mm) {
  Profile p;
  const double Ls = e.skirt.number, top = e.skirtTop.number, bottom = top - Ls;
  p.barrel_um_per_mm2 = roundSignificant(kExampleBarrel_um_per_mm2 * (kExampleSkirt_mm / Ls) *
                                             (kExampleSkirt_mm / Ls) * bore_mm / kExampleBore_mm,
                                         4);
  p.minimumLine_mm = roundTo(top - kMinimumClearanceLineFromTop * Ls, 0.01);
  p.step_mm = niceStep(Ls / 60.0);
  const double block = 10.0 * p.step_mm;
  p.halfRange_mm =
      block * std::ceil((std::max(std::abs(top), std::abs(bottom)) + 0.2 * Ls) / block - 1e-9);
  std::ostringstream t;
  t << "# Skirt axial profile (barrel) of " << name
    << ", made by pistondyn new: radial drop below\n"
       "# the largest (reference) diameter against the height above the pin axis, cold, at the\n"
       "# deck's liner.reference_temperature_degC. EST: the gasoline example's parabolic barrel\n"
       "# (0.12 um/mm^2, minimum-clearance line 60 % of its 30 mm skirt from the top) scaled to "
       "this\n# skirt ("
    << num(Ls) << " mm, +" << num(top) << " .. " << num(bottom) << " mm) and bore ("
    << num(bore_mm) << " mm):\n"
    << "#   radial_drop_um = " << num(p.barrel_um_per_mm2) << " * (height_above_pin_mm "
    << (p.minimumLine_mm <= 0 ? "+ " : "- ") << num(std::abs(p.minimumLine_mm)) << ")^2\n"
    << "# (0.12 um/mm^2 x (30 mm/skirt length)^2 x bore/74.5 mm, to 4 digits; the line at 60 % "
       "of\n# the skirt length from its top), tabulated every "
    << num(p.step_mm) << " mm over " << num(-p.halfRange_mm) << " .. +" << num(p.halfRange_mm)
    << " mm so that the skirt\n# and the mirrored skirt are covered.\n"
    << "height_above_pin_mm,radial_drop_um\n";
  const long n = std::lround(p.halfRange_mm / p.step_mm);
  char row[64];
  for (long i = -n; i <= n; ++i) {
    const double y = roundTo(static_cast<double>(i) * p.step_mm, 1e-9);
    const double dy = y - p.minimumLine_mm;
    std::snprintf(row, sizeof row, "%.10g,%.6g\n", y, p.barrel_um_per_mm2 * dy * dy);
    t << row;
  }
  p.text = t.str();
  return p;
}

struct Pressure {
  std::string fileName, text, deckComment;
  double imep_kPa = 0, peak_bar = 0, peakAngle_deg = 0;
  bool imepEstimated = false;
};

std::string readWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  if (!in && !in.eof())
    throw NewDeckError("--pressure-table " + path + ": cannot be read");
  return s.str();
}

Pressure copyPressureTable(const NewDeckRequest& r, const mbd::CylinderVolume& vol) {
  Pressure p;
  std::error_code ec;
  if (!fs::exists(r.pressureTableFile, ec))
    throw NewDeckError("--pressure-table " + r.pressureTableFile + ": no such file");
  std::string unit;
  std::optional<mbd::CylinderPressureCurve> curve;
  try {
    curve.emplace(readPressureTableCsv(r.pressureTableFile, &unit));
  } catch (const DeckError& e) {
    throw NewDeckError(std::string("--pressure-table: ") + e.what());
  }
  p.text = readWholeFile(r.pressureTableFile);
  p.fileName = "cylinder_pressure.csv";
  p.imep_kPa = mbd::calcImep_Pa(*curve, vol) / 1e3;
  p.peak_bar = curve->getPeakPressure_Pa() / 1e5;
  p.peakAngle_deg = curve->getPeakPressureAngle_deg();
  p.deckComment = "Cylinder pressure [U]: " + r.pressureTableFile +
                  " copied by pistondyn new (imep " + num(roundSignificant(p.imep_kPa, 4)) +
                  " kPa, peak " + num(roundSignificant(p.peak_bar, 4)) + " bar at " +
                  num(p.peakAngle_deg) + " deg).";
  return p;
}

std::string describeCycleArguments(const NewDeckRequest& r, double rod_mm, double cr,
                                   double pinOffset_mm, const mbd::SingleZoneCycle& c) {
  return "--bore-mm " + num(r.bore_mm) + " --stroke-mm " + num(r.stroke_mm) + " --rod-mm " +
         num(rod_mm) + " --cr " + num(cr) + " --pin-offset-mm " + num(pinOffset_mm) + " --k " +
         num(c.polytropicExponent) + " --p-int-bar " + num(c.intakePressure_Pa / 1e5) +
         " --p-exh-bar " + num(c.exhaustPressure_Pa / 1e5) + " --ivc-deg " +
         num(c.intakeValveClosing_deg) + " --evo-deg " + num(c.exhaustValveOpening_deg) +
         " --soc-deg " + num(c.combustionStart_deg) + " --burn-deg " +
         num(c.combustionDuration_deg);
}

Pressure generatePressureTable(const NewDeckRequest& r, const TypeRules& t, const Engine& e,
                               const mbd::CylinderVolume& vol) {
  Pressure p;
  mbd::SingleZoneCycle c = t.fired;
  std::optional<double> target;
  std::string describe;
  if (r.motored) {
    c.intakePressure_Pa = kMotoredIntake_bar * 1e5;
    c.exhaustPressure_Pa = kMotoredExhaust_bar * 1e5;
    p.fileName = "cylinder_pressure_motored.csv";
  } else {
    p.imepEstimated = !r.imep_kPa;
    target = 1e3 * r.imep_kPa.value_or(t.imep_kPa.value);
    p.fileName = "cylinder_pressure_fired_imep" + num(*target / 1e3) + "kPa.csv";
  }
  mbd::SingleZonePressureTable table;
  try {
    table = mbd::makeSingleZonePressureTable(c, vol, target, kTableStep_deg);
  } catch (const std::invalid_argument& ex) {
    throw NewDeckError(std::string("the pressure table cannot be generated: ") + ex.what());
  }
  std::string args =
      describeCycleArguments(r, e.rod.number, e.cr.number, e.pinOffset.number, c);
  if (target)
    args += " --target-imep-kPa " + num(*target / 1e3);
  args += " --step-deg " + num(kTableStep_deg);
  std::ostringstream result;
  result << "heat released Q_tot = " << table.heatReleased_J
         << " J per cycle; net imep (trapezoid at 0.01 deg) = " << table.netImep_Pa / 1e3
         << " kPa";
  p.text = formatPressureTableCsv(
      table.crankAngle_deg, table.pressure_Pa,
      {"Generated by pistondyn new (single-zone model: mbd_models/SingleZonePressureModel.h)",
       "the same table: make_pressure_curve " + args + " --out FILE.csv", result.str(),
       "crank angle 0 deg = firing TDC; absolute pressure"});
  const mbd::CylinderPressureCurve curve(table.crankAngle_deg, table.pressure_Pa);
  p.imep_kPa = table.netImep_Pa / 1e3;
  p.peak_bar = curve.getPeakPressure_Pa() / 1e5;
  p.peakAngle_deg = curve.getPeakPressureAngle_deg();
  const std::string valves = "IVC " + num(c.intakeValveClosing_deg) + " deg, EVO " +
                             num(c.exhaustValveOpening_deg) + " deg";
  if (r.motored) {
    p.deckComment = "Motored pressure (EST): polytropic compression and expansion, k = " +
                    num(c.polytropicExponent) + ", intake " + num(kMotoredIntake_bar) +
                    " bar, exhaust " + num(kMotoredExhaust_bar) +
                    " bar (wide open, as the B&S example's motored rig), " + valves + " (" +
                    t.label + " estimate)";
  } else {
    p.deckComment =
        "Fired pressure (EST): single-zone Wiebe heat release (start " +
        num(c.combustionStart_deg) + " deg, duration " + num(c.combustionDuration_deg) +
        " deg, a = 6.908, m = 2, k = " + num(c.polytropicExponent) + "), intake " +
        num(c.intakePressure_Pa / 1e5) + " bar, exhaust " + num(c.exhaustPressure_Pa / 1e5) +
        " bar, " + valves + " (" + t.firedWhy + "), heat release " +
        num(roundSignificant(table.heatReleased_J, 4)) +
        " J scaled so that the net imep is " + num(*target / 1e3) + " kPa " +
        (p.imepEstimated ? "(EST: " + std::string(t.imep_kPa.why) + "; give --imep-kPa)"
                         : "[U]");
  }
  p.deckComment += ". Peak " + num(roundSignificant(p.peak_bar, 4)) + " bar at " +
                   num(p.peakAngle_deg) +
                   " deg. The table's header holds the make_pressure_curve command that "
                   "makes the same table; replace it with a measured trace when you have one.";
  return p;
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

std::string makeEngineYaml(const NewDeckRequest& r, const TypeRules& t, const Engine& e,
                           const Pressure& p, const std::vector<std::string>& notes) {
  DeckText d;
  writeHeader(d, r, t, e, p, notes);
  d.blank();
  d.line("engine:");
  d.entry(2, "name", quoted(r.name), "[U]");
  d.blank();
  d.line("geometry:");
  d.entry(2, "bore_mm", num(r.bore_mm), "[U]");
  d.entry(2, "stroke_mm", num(r.stroke_mm), "[U]");
  d.entry(2, "conrod_length_mm", num(e.rod.number), e.rod.note);
  d.entry(2, "pin_offset_mm", num(e.pinOffset.number), e.pinOffset.note);
  d.entry(2, "crank_offset_mm", "0.0", "EST: no desaxe assumed");
  d.entry(2, "compression_ratio", num(e.cr.number), e.cr.note);
  d.blank();
  d.line("piston:");
  d.entry(2, "compression_height_mm", num(e.ch.number), e.ch.note);
  d.entry(2, "skirt_length_mm", num(e.skirt.number), e.skirt.note);
  d.entry(2, "skirt_top_above_pin_mm", num(e.skirtTop.number), e.skirtTop.note);
  d.entry(2, "mass_g", num(e.pistonMass.number), e.pistonMass.note);
  d.entry(2, "com_above_pin_mm", num(e.pistonCom.number), e.pistonCom.note);
  d.entry(2, "inertia_kg_mm2", num(e.pistonInertia.number), e.pistonInertia.note);
  d.blank();
  d.line("pin:");
  d.entry(2, "mass_g", num(e.pinMass.number), e.pinMass.note);
  d.entry(2, "inertia_kg_mm2", num(e.pinInertia.number), e.pinInertia.note);
  d.entry(2, "joint", "floating", "EST: a floating pin, as both examples");
  d.blank();
  d.line("conrod:");
  d.entry(2, "mass_g", num(e.rodMass.number), e.rodMass.note);
  d.entry(2, "com_from_big_end_mm", num(e.rodCom.number), e.rodCom.note);
  d.entry(2, "inertia_kg_mm2", num(e.rodInertia.number), e.rodInertia.note);
  d.blank();
  d.line("crank:");
  d.entry(2, "mass_g", num(e.crankMass.number), e.crankMass.note);
  d.entry(2, "com_radius_mm", num(e.crankCom.number), e.crankCom.note);
  d.entry(2, "inertia_kg_mm2", num(e.crankInertia.number), e.crankInertia.note);
  d.blank();
  d.line("drive:");
  d.entry(2, "mode", "constant_speed",
          r.motored ? "motored at a constant speed" : "a constant crank speed");
  d.entry(2, "speed_rpm", num(e.speed.number), e.speed.note);
  d.blank();
  d.line("gas:");
  d.comment(2, p.deckComment);
  d.entry(2, "cylinder_pressure_file", p.fileName);
  d.entry(2, "crankcase_pressure_bar", "1.01325", "EST: atmospheric");
  if (!r.motored && r.pressureTableFile.empty())
    d.entry(2, "stated_imep_kPa", num(r.imep_kPa.value_or(t.imep_kPa.value)),
            std::string(p.imepEstimated ? "EST (above)" : "[U]") +
                "; the deck is rejected if the table is > 0.5 % off");
  d.blank();
  d.line("liner:");
  d.comment(2,
            "The lubricated skirt: oil film (average Reynolds, mass-conserving cavitation) and "
            "asperity contact on both skirt sides, with the example decks' film, roughness and "
            "contact data. Run the same engine on the ideal guide with --set "
            "liner.model=ideal_guide --set simulation.integrator=rk_merson. No bore_distortion "
            "section: ideal cylindrical liner (EST, as the thesis' study). No thermal section: "
            "the cold shapes as measured, hot clearance = cold (EST, as the examples).");
  d.entry(2, "model", "lubricated_skirt");
  d.entry(2, "cold_radial_clearance_um", num(e.clearance.number), e.clearance.note);
  d.entry(2, "reference_temperature_degC", "20.0",
          "EST: the temperature the shapes are measured at");
  d.entry(2, "grid", "", "numerics (each skirt side), not engine data");
  d.entry(4, "arc_width_deg", "80.0", "the film region around the thrust / anti-thrust axis");
  d.entry(4, "nodes_circumferential", "64", "nodes around the arc (--fidelity preview: 32)");
  d.entry(4, "nodes_axial", "48", "nodes along the skirt (--fidelity preview: 24)");
  d.entry(4, "axial_clustering", "0.0", "uniform axial spacing, as the examples");
  d.entry(2, "skirt_profile", "");
  d.entry(4, "axial_profile_file", "skirt_profile.csv",
          "EST: the gasoline example's barrel scaled to this skirt and bore (the file's header "
          "states the rule)");
  d.entry(4, "mirrored", "false", "the thesis' \"original\" profile");
  d.entry(4, "ovality_diametral_um", num(e.ovality.number), e.ovality.note);
  d.entry(4, "ovality_cos4_coefficient", "0.0", "EST: the pure elliptic law, as the examples");
  d.entry(2, "oil", "");
  d.entry(4, "grade", e.oilGrade, e.oilNote + " (data-sheet oil, lubrication/OilGrades.h)");
  d.entry(4, "temperature_degC", num(e.oilTemperature.number), e.oilTemperature.note);
  d.entry(2, "oil_supply", "");
  d.entry(4, "film_um", "0.5", "EST: partially flooded, as both examples and the thesis' study");
  d.entry(2, "roughness", "", "entered once: flow factors and asperity contact");
  d.entry(4, "liner_rq_um", "0.4", "EST: plateau-honed cast-iron bore, as both examples");
  d.entry(4, "skirt_rq_um", "0.6", "EST: machined skirt with its coating, as both examples");
  d.entry(4, "peklenik", "1.0", "EST: isotropic roughness");
  d.entry(2, "asperity", "");
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
  d.entry(2, "film", "");
  d.entry(4, "cavitation", "mass_conserving", "JFO / Elrod-Adams: what partial flooding needs");
  d.entry(4, "fill_fraction_history", "bdf2", "second order in time like the stepper");
  d.entry(4, "faces", "linear_gap",
          "second order along the sliding direction, as the examples (README.md, \"Example "
          "engines\")");
  d.entry(4, "fill_fraction_flux", "second_order", "limited second-order fill fraction");
  d.entry(4, "solver", "fast", "active-set solver");
  d.entry(4, "tolerance", "1.0e-8", "film residual, relative to the driving fluxes");
  d.entry(2, "tertiary_motion", "false", "EST: as the thesis' study");
  d.blank();
  d.line("simulation:");
  d.entry(2, "start_angle_deg", "0", "first row at firing TDC");
  d.entry(2, "cycles", "8", "at most, until the cycles repeat");
  d.entry(2, "until_periodic", "true");
  d.entry(2, "periodic_fmep_tolerance", "0.005", "two cycles agree: fmep within 0.5 % ...");
  d.entry(2, "periodic_pose_tolerance_um", "0.2",
          "... and u_lat, tilt x skirt length within 0.2 um");
  d.entry(2, "output_step_deg", "1.0", "one row per crank degree");
  d.entry(2, "integrator", "linearly_implicit_bdf2", "the squeeze film is stiff");
  d.entry(2, "pose_tolerance_nm", "10",
          "stepper's per-step error on lateral, tertiary, tilt x L");
  d.entry(2, "max_step_deg", "0.25", "largest step [deg of crank], as the examples");
  d.entry(2, "gravity_mps2", "9.80665", "cylinder vertical, head up");
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
  const Engine e = Estimator(r, t, deck.estimated).estimate();
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
