#pragma once
// Internal to pistondyn new (NewDeck.h): the estimating rules of each engine type and the
// engine values they give, the numbers' rounding and text. README.md, "A deck from a
// drawing (`pistondyn new`)", lists every rule; a rule changed here is changed there.

#include <string>
#include <vector>

#include "pistondyn/io/NewDeck.h"
#include "pistondyn/mbd_models/SingleZonePressureModel.h"

namespace pistondyn::io::newdeck {

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

// Every ratio of one engine type with the reason the deck's comment gives for it.
struct Ratio {
  double value;
  const char* why;
};

/// One engine type's rules: ratios to the bore, stroke and rod, the operating point and
/// the single-zone cycle of its generated pressure table (README.md's rule table).
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
  Ratio minimumClearanceLineFromTop;  // of the skirt length: the barrel's zero-drop line
  // Splash-lubricated (a dipper on the rod's cap): the skirt runs fully flooded, with
  // Reynolds cavitation; otherwise the oil-control ring's film as a constant supply.
  bool splashLubricated;
  const char* lubricationWhy;
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

/// The rules of an engine type (one static set each).
const TypeRules& getRules(EngineType type);

/// `x` rounded to a multiple of `quantum`.
double roundTo(double x, double quantum);
/// `x` rounded to `digits` significant digits (0 and non-finite values unchanged).
double roundSignificant(double x, int digits);
/// Shortest plain text of a rounded value ("28.3", "140", "-0.1").
std::string num(double x);
/// A ratio as the rules print it ("0.38", "0.069", "-0.125").
std::string ratio(double x);

/// One value of the deck and its comment (its mark and rule).
struct Value {
  double number = 0.0;  ///< in the unit of the deck key it is written to
  std::string note;     ///< "[U]" or "EST: <rule> (<source>)"
};

/// The engine's values, given ([U]) or estimated (EST + rule), each in its deck key's unit:
/// rod geometry.conrod_length_mm, pinOffset geometry.pin_offset_mm, cr
/// geometry.compression_ratio, ch piston.compression_height_mm, skirt and skirtTop
/// piston.skirt_length_mm and skirt_top_above_pin_mm, the masses [g] and inertias [kg mm^2]
/// of piston, pin, conrod and crank, pistonCom piston.com_above_pin_mm, rodCom
/// conrod.com_from_big_end_mm, crankCom crank.com_radius_mm, speed drive.speed_rpm,
/// clearance liner.cold_radial_clearance_um, ovality
/// liner.skirt_profile.ovality_diametral_um, oilTemperature liner.oil.temperature_degC.
struct Engine {
  Value rod, pinOffset, cr, ch, skirt, skirtTop, pistonMass, pistonCom, pistonInertia;
  Value pinMass, pinInertia, rodMass, rodCom, rodInertia, crankMass, crankCom, crankInertia;
  Value speed, clearance, ovality, oilTemperature;
  std::string oilGrade, oilNote;
  Ratio minimumLineFromTop;  // the barrel's zero-drop line, of the skirt length from its top
  bool splashLubricated = false;
  std::string lubricationNote;  // "EST: <why>" of the oil supply
  double pinOuter_mm = 0, pinInner_mm = 0, pinLength_mm = 0;
};

/// The engine's values: those the request gives marked [U], every other one estimated by
/// `rules` and marked "EST: <rule>"; the path of each estimated key is appended to
/// `estimated` in the order the deck writes them. The request must have passed the
/// command's checks (positive bore and stroke).
Engine estimateEngine(const NewDeckRequest& request, const TypeRules& rules,
                      std::vector<std::string>& estimated);

}  // namespace pistondyn::io::newdeck
