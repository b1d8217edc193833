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
// When --set liner.model chose another model than the file names, the file's liner keys
// are that other model's data: not reported as unknown (keys given by --set still are).
void readLiner(YamlDeck& d, const LinerRegistry& registry, EngineDeck& deck,
               LinerDeckContext& context) {
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
  const std::optional<std::string> inFile = d.getFileValue(kModelKey);
  if (inFile && *inFile != deck.linerModel)
    d.ignoreFileKeys("liner");
  context.engine = &deck.engine;
  context.engineIsValid = !d.hasProblems();
  try {
    deck.makeLinerElement = registry.getFactory(deck.linerModel)(liner, context);
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
  if (context.tertiaryMotion)
    deck.engine.tertiaryMotion = *context.tertiaryMotion;
  deck.fieldDumpAngles_deg = context.fieldDumpAngles_deg;
}

using Settings = plugin::SimulationSettings;

// The simulation section, and its checks against the liner model's needs.
void readSimulation(YamlDeck& d, const LinerDeckContext& liner, const std::string& linerModel,
                    EngineDeck& deck) {
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
  const std::vector<std::pair<std::string, Settings::Integrator>> integrators = {
      {"rk_merson", Settings::Integrator::RungeKuttaMerson},
      {"rk_feldberg", Settings::Integrator::RungeKuttaFeldberg},
      {"cpodes_bdf", Settings::Integrator::CPodesBDF},
      {"linearly_implicit_bdf2", Settings::Integrator::LinearlyImplicitBDF2}};
  std::vector<std::string> names;
  for (const auto& i : integrators)
    names.push_back(i.first);
  const std::string integ = d.getChoiceOr("simulation.integrator", names, "rk_merson");
  for (const auto& i : integrators) {
    if (i.first == integ)
      s.integrator = i.second;
  }
  s.accuracy = d.getNumberInRange("simulation.accuracy", false, 1e-14, 1e-2, "").value_or(1e-9);

  // The linearly implicit stepper's settings and the run to periodic steady state.
  DeckSection sim = d.getSection("simulation");
  s.poseTolerance_m =
      sim.getSIOr("pose_tolerance_nm", Quantity::Length, 10.0, Bounds::between(1e-3, 1e5));
  s.maxStep_deg = sim.getNumberOr("max_step_deg", 0.5, Bounds{0.0, 10.0, true});
  s.maxSteps = sim.getIntegerOr("max_steps", 20000000, 1, 2000000000);
  s.untilPeriodic = sim.getBoolOr("until_periodic", false);
  s.periodicFmepTolerance =
      sim.getNumberOr("periodic_fmep_tolerance", 0.005, Bounds{0.0, 0.5, true});
  s.periodicPoseTolerance_m =
      sim.getSIOr("periodic_pose_tolerance_um", Quantity::Length, 0.2, Bounds{0.0, 100.0, true});

  const bool explicitRk = s.integrator == Settings::Integrator::RungeKuttaMerson ||
                          s.integrator == Settings::Integrator::RungeKuttaFeldberg;
  if (explicitRk && !liner.stiffReason.empty()) {
    d.addProblem("simulation.integrator",
                 "'" + integ + "' is an explicit integrator, but the liner model '" + linerModel +
                     "' makes the system stiff (" + liner.stiffReason +
                     "): use linearly_implicit_bdf2 (or cpodes_bdf)");
  }
  if (s.integrator == Settings::Integrator::LinearlyImplicitBDF2 && liner.usesConstraints) {
    d.addProblem("simulation.integrator",
                 "linearly_implicit_bdf2 integrates models without constraints, but the liner "
                 "model '" +
                     linerModel +
                     "' holds the piston by Simbody constraints: use rk_merson, rk_feldberg "
                     "or cpodes_bdf");
  }
  if (s.untilPeriodic && d.has("simulation.cycles") && s.cycles < 2) {
    d.addProblem("simulation.cycles",
                 "with simulation.until_periodic: true this is the most cycles to run, and two "
                 "cycles are needed to compare (at least 2)");
  } else if (s.untilPeriodic && s.cycles < 2) {
    d.addProblem("simulation.until_periodic",
                 "needs simulation.cycles (the most cycles to run) of at least 2");
  }
  // Field dumps are taken at output rows.
  if (!liner.fieldDumpAngles_deg.empty() && s.outputStepDividesCycle()) {
    for (const double a : liner.fieldDumpAngles_deg) {
      const double k = (a - s.startAngle_deg) / s.outputStep_deg;
      if (std::abs(k - std::round(k)) > 1e-9 * std::max(1.0, std::abs(k))) {
        d.addProblem(liner.fieldDumpKey,
                     common::formatNumber(a) +
                         " deg is not an output crank angle (simulation.start_angle_deg + k * "
                         "simulation.output_step_deg): fields are dumped at output rows");
        break;
      }
    }
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

  // Cross-key checks of the engine, only on values that are individually valid (a failed
  // read leaves a placeholder that would only produce a second, confusing message).
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

  LinerDeckContext liner;
  readLiner(d, registry, deck, liner);
  readSimulation(d, liner, deck.linerModel, deck);

  // Every key is read; report unknown keys and all problems together.
  d.finish();

  // Safety net: the library's own checks (every deck-level problem above should have
  // caught these first, with a key and a line).
  try {
    mbd::validate(e);
    plugin::validate(deck.simulation);
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
  // A trial model: the elements' checks against the engine when they join the crank train
  // (addToModel: the skirt's gap terms, its hot running clearance, ...) are bad input too.
  try {
    buildModel(deck)->buildSystem();
  } catch (const std::exception& ex) {
    throw DeckError(deckPath + ": liner: the liner model '" + deck.linerModel +
                    "' rejected its parameters for this engine: " + ex.what());
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
