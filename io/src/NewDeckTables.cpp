// The tables of pistondyn new (NewDeckTables.h).

#include "NewDeckTables.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/PressureTableCsv.h"

namespace pistondyn::io::newdeck {
namespace {

namespace fs = std::filesystem;

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

// The file as it is: the copy keeps the user's comments and knots.
std::string readWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  if (!in && !in.eof())
    throw NewDeckError("--pressure-table " + path + ": cannot be read",
                       NewDeckError::Kind::BadTable);
  return s.str();
}

// The make_pressure_curve options that make the same cycle (the table's header).
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

}  // namespace

Profile makeSkirtProfile(const std::string& name, const Engine& e, double bore_mm) {
  Profile p;
  const double Ls = e.skirt.number, top = e.skirtTop.number, bottom = top - Ls;
  p.barrel_um_per_mm2 = roundSignificant(kExampleBarrel_um_per_mm2 * (kExampleSkirt_mm / Ls) *
                                             (kExampleSkirt_mm / Ls) * bore_mm / kExampleBore_mm,
                                         4);
  p.minimumLine_mm = roundTo(top - e.minimumLineFromTop.value * Ls, 0.01);
  p.step_mm = niceStep(Ls / 60.0);
  const double block = 10.0 * p.step_mm;
  p.halfRange_mm =
      block * std::ceil((std::max(std::abs(top), std::abs(bottom)) + 0.2 * Ls) / block - 1e-9);
  std::ostringstream t;
  t << "# Skirt axial profile (barrel) of " << name
    << ", made by pistondyn new: radial drop below\n"
       "# the largest (reference) diameter against the height above the pin axis, cold, at the\n"
       "# deck's liner.reference_temperature_degC. EST: the gasoline example's parabolic barrel\n"
       "# (0.12 um/mm^2 on its 30 mm skirt) scaled to this skirt ("
    << num(Ls) << " mm, +" << num(top) << " .. " << num(bottom) << " mm)\n# and bore ("
    << num(bore_mm) << " mm), its minimum-clearance line " << ratio(e.minimumLineFromTop.value)
    << " x the skirt length from the top\n# (" << e.minimumLineFromTop.why << "):\n"
    << "#   radial_drop_um = " << num(p.barrel_um_per_mm2) << " * (height_above_pin_mm "
    << (p.minimumLine_mm <= 0 ? "+ " : "- ") << num(std::abs(p.minimumLine_mm)) << ")^2\n"
    << "# (0.12 um/mm^2 x (30 mm/skirt length)^2 x bore/74.5 mm, to 4 digits), tabulated "
       "every "
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

Pressure copyPressureTable(const NewDeckRequest& r, const mbd::CylinderVolume& vol) {
  Pressure p;
  std::error_code ec;
  if (!fs::exists(r.pressureTableFile, ec))
    throw NewDeckError("--pressure-table " + r.pressureTableFile + ": no such file",
                       NewDeckError::Kind::BadTable);
  std::string unit;
  std::optional<mbd::CylinderPressureCurve> curve;
  try {
    curve.emplace(readPressureTableCsv(r.pressureTableFile, &unit));
  } catch (const DeckError& e) {
    throw NewDeckError(std::string("--pressure-table: ") + e.what(), NewDeckError::Kind::BadTable);
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

}  // namespace pistondyn::io::newdeck
