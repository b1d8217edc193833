// The estimating rules of pistondyn new (NewDeckRules.h): one set of ratios per engine
// type, each with the reason the deck's comment gives, and the estimator that applies them.

#include "NewDeckRules.h"

#include <cmath>
#include <cstdio>

#include "pistondyn/lubrication/OilGrades.h"

namespace pistondyn::io::newdeck {
namespace {


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

// Applies one type's rules to a request, noting each key it estimates.
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
    e.minimumLineFromTop = t_.minimumClearanceLineFromTop;
    e.splashLubricated = t_.splashLubricated;
    e.lubricationNote = std::string("EST: ") + t_.lubricationWhy;
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

}  // namespace

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
      {0.13, "the gasoline example's hot running clearance, 9.4 um on 74.5 mm (40 um cold with "
             "its thermal section); without a thermal section the key holds the running one"},
      "0W-30",
      "the thesis' study oil",
      {0.60, "the gasoline example's line 6 mm below the pin of its 30 mm skirt"},
      false,
      "partially flooded [T]: the film an oil-control ring leaves on a warm liner, 0.2-1.5 um, "
      "as the gasoline example"};
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
      "B&S's all-temperature synthetic recommendation, as the B&S example",
      {0.46, "the B&S example's line 3 mm below the pin of its 28 mm skirt (13 mm from the "
             "top)"},
      true,
      "splash-lubricated: the dipper on the rod's cap throws sump oil over the bore, so the "
      "skirt runs fully flooded, as the B&S example"};
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
      {0.20, "the gasoline example's running 0.13 per mille raised for a diesel piston's "
             "hotter, heavier skirt (a new deck has no thermal section: the key holds the running "
             "clearance); 0.6 per mille cold-clearance rules left this skirt rattling"},
      "5W-40",
      "a diesel-approved multigrade",
      {0.60, "as the gasoline example"},
      false,
      "partially flooded [T]: the film an oil-control ring leaves on a warm liner, 0.2-1.5 um, "
      "as the gasoline example"};
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

std::string num(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

std::string ratio(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

Engine estimateEngine(const NewDeckRequest& request, const TypeRules& rules,
                      std::vector<std::string>& estimated) {
  return Estimator(request, rules, estimated).estimate();
}

}  // namespace pistondyn::io::newdeck
