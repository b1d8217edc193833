#include "pistondyn/io/EngineDeck.h"

#include <cmath>

#include "pistondyn/common/Validation.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/DeckSection.h"
#include "pistondyn/io/PressureTableCsv.h"
#include "pistondyn/io/YamlDeck.h"
#include "pistondyn/plugin/GasForceElement.h"
#include "pistondyn/plugin/IdealLinerGuide.h"

namespace pistondyn::io {
namespace {

constexpr double kMm = 1e-3;     // mm -> m
constexpr double kGram = 1e-3;   // g -> kg
constexpr double kKgMm2 = 1e-6;  // kg mm^2 -> kg m^2
constexpr double kBar = 1e5;     // bar -> Pa
using Sign = YamlDeck::Sign;

mbd::PlanarMassProperties readBody(YamlDeck& d, const std::string& section) {
  mbd::PlanarMassProperties b;
  b.mass_kg = d.getNumber(section + ".mass_g", Sign::Positive) * kGram;
  b.inertiaZZ_kgm2 = d.getNumber(section + ".inertia_kg_mm2", Sign::NonNegative) * kKgMm2;
  return b;
}

// liner.model through the registry: the model's factory reads the rest of the section.
// An unknown model is one problem; its section's keys are then not reported as unknown.
void readLiner(YamlDeck& d, const LinerRegistry& registry, EngineDeck& deck) {
  DeckSection liner = d.getSection("liner");
  const std::string kModelKey = "liner.model";
  const bool given = d.has(kModelKey);
  const std::optional<std::string> requested = d.readString(kModelKey, false);
  if (given && (!requested || !registry.has(*requested))) {
    if (requested) {
      std::string list;
      for (const auto& c : registry.getNames())
        list += (list.empty() ? "" : ", ") + c;
      d.addProblem(kModelKey, "'" + *requested + "' is not one of: " + list +
                                  " (the liner models registered in this program)");
    }
    d.ignoreSection("liner");
    return;
  }
  deck.linerModel = requested.value_or("ideal_guide");
  try {
    deck.makeLinerElement = registry.getFactory(deck.linerModel)(liner);
    if (!deck.makeLinerElement)
      d.addProblem(kModelKey,
                   "the liner model '" + deck.linerModel + "' returned no element maker");
  } catch (const std::exception& e) {
    d.addProblem(kModelKey, "the liner model '" + deck.linerModel +
                                "' could not read its section: " + e.what());
  }
  for (const auto& in : d.getResolvedInputs()) {
    if (in.path.rfind("liner.", 0) == 0)
      deck.linerInputs.push_back(in);
  }
}

}  // namespace

EngineDeck loadEngineDeck(const std::string& deckPath, const std::vector<std::string>& overrides,
                          const LinerRegistry& registry) {
  YamlDeck d(deckPath);
  for (const auto& o : overrides)
    d.applyOverride(o);

  EngineDeck deck;
  deck.deckPath = deckPath;
  deck.overrides = overrides;
  mbd::EngineDescription& e = deck.engine;
  e.name = d.getString("engine.name");

  mbd::CrankTrainGeometry& g = e.geometry;
  e.piston.bore_m = d.getNumber("geometry.bore_mm", Sign::Positive) * kMm;
  g.crankRadius_m = 0.5 * d.getNumber("geometry.stroke_mm", Sign::Positive) * kMm;
  g.conrodLength_m = d.getNumber("geometry.conrod_length_mm", Sign::Positive) * kMm;
  g.pinOffset_m = d.getNumberOr("geometry.pin_offset_mm", 0.0) * kMm;
  g.crankOffset_m = d.getNumberOr("geometry.crank_offset_mm", 0.0) * kMm;
  g.compressionRatio = d.getNumber("geometry.compression_ratio", Sign::Positive);

  e.piston.compressionHeight_m = d.getNumber("piston.compression_height_mm", Sign::Positive) * kMm;
  e.piston.skirtLength_m = d.getNumber("piston.skirt_length_mm", Sign::Positive) * kMm;
  e.piston.skirtTopAbovePin_m = d.getNumber("piston.skirt_top_above_pin_mm") * kMm;
  e.mass.piston = readBody(d, "piston");
  e.mass.piston.comY_m = d.getNumber("piston.com_above_pin_mm") * kMm;
  e.mass.piston.comX_m = d.getNumberOr("piston.com_towards_thrust_mm", 0.0) * kMm;

  e.mass.pin = readBody(d, "pin");
  const std::string joint =
      d.getChoiceOr("pin.joint", {"floating", "fixed_in_rod", "fixed_in_piston"}, "floating");
  e.pinJoint = joint == "fixed_in_rod"      ? mbd::PinJoint::FixedInRod
               : joint == "fixed_in_piston" ? mbd::PinJoint::FixedInPiston
                                            : mbd::PinJoint::Floating;

  e.mass.conrod = readBody(d, "conrod");
  e.mass.conrod.comY_m = d.getNumber("conrod.com_from_big_end_mm", Sign::NonNegative) * kMm;

  e.mass.crank = readBody(d, "crank");
  e.mass.crank.comY_m = d.getNumber("crank.com_radius_mm") * kMm;

  const std::string mode =
      d.getChoiceOr("drive.mode", {"constant_speed", "free"}, "constant_speed");
  e.drive.mode =
      mode == "free" ? mbd::CrankDrive::Mode::Free : mbd::CrankDrive::Mode::ConstantSpeed;
  // 1 .. 50,000 rpm: outside this range the deck is almost surely in the wrong unit,
  // and near zero speed one cycle would take forever to simulate.
  e.drive.speed_radps =
      d.getNumberInRange("drive.speed_rpm", true, 1.0, 50000.0, "rpm").value_or(1000.0) * M_PI /
      30.0;
  e.drive.flywheelInertia_kgm2 =
      d.getNumberOr("drive.flywheel_inertia_kg_m2", 0.0, Sign::NonNegative);
  e.drive.loadTorque_Nm = d.getNumberOr("drive.load_torque_Nm", 0.0);
  e.gravity_mps2 =
      d.getNumberInRange("simulation.gravity_mps2", false, 0.0, 100.0, "m/s^2").value_or(9.80665);

  const std::string table = d.getString("gas.cylinder_pressure_file");
  deck.cylinderPressureFile = d.resolvePath(table);
  deck.crankcasePressure_Pa =
      d.getNumberOr("gas.crankcase_pressure_bar", 1.01325, Sign::NonNegative) * kBar;
  if (const auto imep = d.getOptionalNumber("gas.stated_imep_kPa"))
    deck.statedImep_Pa = *imep * 1e3;

  readLiner(d, registry, deck);

  using Settings = plugin::SimulationSettings;
  Settings& s = deck.simulation;
  s.startAngle_deg =
      d.getNumberInRange("simulation.start_angle_deg", false, -720.0, 720.0, "deg").value_or(0.0);
  s.cycles = static_cast<int>(d.getIntegerOr("simulation.cycles", 1, 1, Settings::kMaxCycles));
  s.outputStep_deg = d.getNumberInRange("simulation.output_step_deg", false,
                                        Settings::kMinOutputStep_deg, 720.0, "deg")
                         .value_or(1.0);
  if (!s.outputStepDividesCycle()) {
    d.addProblem("simulation.output_step_deg", "must divide 720 deg into a whole number of steps");
  } else if (s.outputStepsPerCycle() * s.cycles > Settings::kMaxRows) {
    d.addProblem("simulation.output_step_deg",
                 "with simulation.cycles this makes more than " +
                     std::to_string(static_cast<long>(Settings::kMaxRows)) +
                     " output rows; use a coarser step");
  }
  const std::string integ = d.getChoiceOr("simulation.integrator",
                                          {"rk_merson", "rk_feldberg", "cpodes_bdf"}, "rk_merson");
  s.integrator = integ == "rk_feldberg"  ? Settings::Integrator::RungeKuttaFeldberg
                 : integ == "cpodes_bdf" ? Settings::Integrator::CPodesBDF
                                         : Settings::Integrator::RungeKuttaMerson;
  s.accuracy = d.getNumberInRange("simulation.accuracy", false, 1e-14, 1e-2, "").value_or(1e-9);

  // Cross-key checks, only on values that are individually valid (a failed read
  // leaves a placeholder that would only produce a second, confusing message).
  if (!d.hasProblems()) {
    if (g.compressionRatio <= 1.0) {
      d.addProblem("geometry.compression_ratio", "must be greater than 1");
    }
    const double reach = g.crankRadius_m + std::abs(g.pinOffset_m + g.crankOffset_m);
    if (g.conrodLength_m <= reach) {
      d.addProblem("geometry.conrod_length_mm",
                   "the rod must be longer than half the stroke plus |pin offset + crank "
                   "offset| = " +
                       common::formatNumber(reach / kMm) + " mm");
    }
    if (e.piston.skirtTopAbovePin_m > e.piston.compressionHeight_m) {
      d.addProblem("piston.skirt_top_above_pin_mm",
                   "the skirt top cannot be above the crown (compression_height_mm)");
    }
  }
  // Every key is read; report unknown keys and all problems together.
  d.finish();

  // Safety net: the library's own checks (every deck-level problem above should have
  // caught these first, with a key and a line).
  try {
    mbd::validate(e);
    plugin::validate(s);
  } catch (const std::invalid_argument& ex) {
    throw DeckError(deckPath + ": " + ex.what());
  }
  // A trial construction of the liner element: its own checks of the values its factory
  // read (std::invalid_argument, ...) are bad input too, reported before any simulation.
  try {
    if (!deck.makeLinerElement())
      throw std::invalid_argument("no element was made");
  } catch (const std::exception& ex) {
    throw DeckError(deckPath + ": liner: the liner model '" + deck.linerModel +
                    "' rejected its parameters: " + ex.what());
  }
  deck.cylinderPressure = std::make_shared<const mbd::CylinderPressureCurve>(
      readPressureTableCsv(deck.cylinderPressureFile));
  if (deck.statedImep_Pa) {
    const double imep = calcDeckImep_Pa(deck);
    if (!std::isfinite(imep)) {
      throw DeckError(deckPath +
                      ": gas.stated_imep_kPa: the imep of the pressure table cannot be "
                      "computed with this geometry (check the geometry keys' units)");
    }
    const double rel = std::abs(imep - *deck.statedImep_Pa) / std::abs(*deck.statedImep_Pa);
    if (!(rel <= 0.005)) {
      throw DeckError(deckPath + ": gas.stated_imep_kPa: the pressure table " +
                      deck.cylinderPressureFile + " gives an imep of " +
                      common::formatNumber(imep / 1e3) + " kPa, " +
                      common::formatNumber(rel * 100.0) + " % away from the stated " +
                      common::formatNumber(*deck.statedImep_Pa / 1e3) + " kPa (tolerance 0.5 %)");
    }
  }
  return deck;
}

double calcDeckImep_Pa(const EngineDeck& deck) {
  const mbd::SliderCrank kin(deck.engine.geometry);
  const mbd::CylinderVolume vol(kin, deck.engine.piston.bore_m,
                                deck.engine.geometry.compressionRatio);
  return mbd::calcImep_Pa(*deck.cylinderPressure, vol);
}

std::unique_ptr<plugin::PistonAssemblyModel> buildModel(const EngineDeck& deck) {
  auto model = std::make_unique<plugin::PistonAssemblyModel>(deck.engine);
  model->addElement(
      std::make_unique<plugin::GasForceElement>(*deck.cylinderPressure, deck.crankcasePressure_Pa));
  // liner.model, through the maker its registered factory returned.
  if (deck.makeLinerElement) {
    model->addElement(deck.makeLinerElement());
  } else if (deck.linerModel == "ideal_guide") {
    model->addElement(std::make_unique<plugin::IdealLinerGuide>());
  } else {
    throw std::invalid_argument("buildModel: the deck has no maker for liner model '" +
                                deck.linerModel + "'; read decks with loadEngineDeck()");
  }
  return model;
}

}  // namespace pistondyn::io
