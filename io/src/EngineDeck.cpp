#include "pistondyn/io/EngineDeck.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <variant>

#include "pistondyn/common/Validation.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/DeckKeys.h"
#include "pistondyn/io/DeckSection.h"
#include "pistondyn/io/LubricatedSkirtDeck.h"
#include "pistondyn/io/PressureTableCsv.h"
#include "pistondyn/io/YamlDeck.h"
#include "pistondyn/plugin/GasForceElement.h"
#include "pistondyn/plugin/IdealLinerGuide.h"

namespace pistondyn::io {
namespace {

constexpr double kMm = 1e-3;  // mm -> m

// A key of the engine deck's table (DeckKeys.h): its requirement, default and ranges.
const DeckKey& key(const std::string& path) {
  return getEngineDeckKeys().at(path);
}

mbd::PlanarMassProperties readBody(DeckSection& root, const std::string& section) {
  mbd::PlanarMassProperties b;
  b.mass_kg = root.getSI(key(section + ".mass_g"));
  b.inertiaZZ_kgm2 = root.getSI(key(section + ".inertia_kg_mm2"));
  return b;
}

// The crank drive. A free crank's flywheel and load torque are ignored by a constant-speed
// drive: given with one they are an error, never silently dropped.
void readDrive(DeckSection& root, mbd::CrankDrive& drive) {
  YamlDeck& d = root.getDeck();
  const std::string mode = root.getChoice(key("drive.mode"));
  drive.mode = mode == "free" ? mbd::CrankDrive::Mode::Free : mbd::CrankDrive::Mode::ConstantSpeed;
  // 1 .. 50,000 rpm: near zero speed one cycle would take forever to simulate.
  drive.speed_radps = root.getSI(key("drive.speed_rpm"));
  drive.flywheelInertia_kgm2 = root.getSI(key("drive.flywheel_inertia_kg_m2"));
  drive.loadTorque_Nm = root.getSI(key("drive.load_torque_Nm"));
  if (mode == "constant_speed") {
    for (const char* path : {"drive.flywheel_inertia_kg_m2", "drive.load_torque_Nm"}) {
      if (d.has(path))
        d.addProblem(path,
                     "is read only with drive.mode: free; the constant-speed drive (the "
                     "default) ignores it: remove it, or set drive.mode: free");
    }
  }
}

// liner.model through the registry: the model's factory reads the rest of the section.
// An unknown model is one problem; its section's keys are then not reported as unknown.
// When --set liner.model chose another model than the file names, the file's liner keys
// are that other model's data: not reported as unknown (keys given by --set still are).
LinerModelNeeds readLiner(YamlDeck& d, const LinerRegistry& registry, EngineDeck& deck,
                          LinerDeckContext& context) {
  DeckSection liner = d.getSection("liner");
  const std::string kModelKey = "liner.model";
  const bool given = d.has(kModelKey);
  const std::optional<std::string> requested = d.readString(key(kModelKey).path, false);
  if (given && (!requested || !registry.has(*requested))) {
    if (requested) {
      std::string list;
      for (const auto& c : registry.getNames())
        list += (list.empty() ? "" : ", ") + c;
      d.addProblem(kModelKey, "'" + *requested + "' is not one of: " + list +
                                  " (the liner models registered in this program)");
    }
    d.ignoreSection("liner");
    return {};
  }
  deck.linerModel = requested.value_or(key(kModelKey).defaultText);
  d.recordInput({kModelKey, kModelKey, deck.linerModel});
  const std::optional<std::string> inFile = d.getFileValue(kModelKey);
  if (inFile && *inFile != deck.linerModel)
    d.ignoreFileKeys("liner");
  context.engine = &deck.engine;
  context.engineIsValid = !d.hasProblems();
  LinerModelNeeds needs;
  try {
    LinerModel model = registry.getFactory(deck.linerModel)(liner, context);
    deck.makeLinerElement = std::move(model.maker);
    needs = std::move(model.needs);
    if (!deck.makeLinerElement)
      d.addProblem(kModelKey,
                   "the liner model '" + deck.linerModel + "' returned no element maker");
  } catch (const std::exception& e) {
    d.addProblem(kModelKey, "the liner model '" + deck.linerModel +
                                "' could not read its section: " + e.what());
  }
  for (const auto& in : d.getResolvedInputs()) {
    if (in.path.rfind("liner.", 0) == 0 && in.path != kModelKey)
      deck.linerInputs.push_back(in);
  }
  if (needs.tertiaryMotion)
    deck.engine.tertiaryMotion = *needs.tertiaryMotion;
  deck.fieldDumpAngles_deg = needs.fieldDumpAngles_deg;
  return needs;
}

// The cylinder-pressure table, with its problems under the key that names it, and the
// plausibility of its peak (a table in Pa labelled bar gives an imep of 60 million kPa).
mbd::CylinderPressureCurve readCylinderPressure(const YamlDeck& d, const std::string& path) {
  const DeckKey& k = key("gas.cylinder_pressure_file");
  const std::string where = d.where(k.path) + ": ";
  std::string unit;
  std::optional<mbd::CylinderPressureCurve> curve;
  try {
    curve.emplace(readPressureTableCsv(path, &unit));
  } catch (const DeckError& e) {
    std::string message = e.what(), out;
    for (std::size_t b = 0; b <= message.size();) {
      const std::size_t end = std::min(message.find('\n', b), message.size());
      out += (out.empty() ? "" : "\n") + where + message.substr(b, end - b);
      b = end + 1;
    }
    throw DeckError(out);
  }
  const double peak_bar = curve->getPeakPressure_Pa() / 1e5;
  if (k.plausible && !k.plausible->contains(peak_bar) && !d.isImplausibleAllowed(k.path)) {
    // The header's unit that would make the peak plausible.
    static const std::vector<std::pair<std::string, double>> units = {
        {"Pa", 1e-5}, {"kPa", 1e-2}, {"bar", 1.0}, {"MPa", 10.0}};
    double toBar = 1.0;
    for (const auto& u : units)
      toBar = u.first == unit ? u.second : toBar;
    const double written = peak_bar / toBar;
    std::string hint;
    for (const auto& u : units) {
      if (u.first != unit && k.plausible->contains(written * u.second))
        hint += (hint.empty() ? "" : " or ") + u.first;
    }
    throw DeckError(
        where + path + ": the peak pressure is " + common::formatNumber(peak_bar) +
        " bar, outside the plausible " + common::formatNumber(k.plausible->minimum) + " .. " +
        common::formatNumber(k.plausible->maximum) + " bar of an engine's cylinder" +
        (hint.empty() ? std::string()
                      : "; the header says pressure_" + unit + ": are the numbers in " + hint +
                            "?") +
        " (if the table is right, list the key under " + kAllowImplausibleKey + ")");
  }
  return std::move(*curve);
}

// Positions that put a point of a body outside the body: the pin axis must lie well inside
// the piston, and a centre of mass inside the body's extent (it lies in the body's convex
// hull). Rules (README's deck reference states them with the keys):
//   |pin offset| < bore / 4: the pin, about a quarter of the bore in diameter in engines
//     of every size, and its bosses must fit inside the piston (real offsets are 0-3 % of
//     the bore);
//   |piston centre of mass off the axis| < bore / 2, and below the crown top;
//   conrod centre of mass between the big-end and small-end centres (< the rod length).
void checkInsideTheBodies(YamlDeck& d, const mbd::EngineDescription& e) {
  const double bore_m = e.piston.bore_m;
  auto mm = [](double m) { return common::formatNumber(m / kMm) + " mm"; };
  if (!(std::abs(e.geometry.pinOffset_m) < 0.25 * bore_m)) {
    d.addProblem("geometry.pin_offset_mm",
                 "the pin axis must lie well inside the piston: |pin offset| below a quarter of "
                 "the bore, " +
                     mm(0.25 * bore_m) +
                     " here (the pin and its bosses must fit inside the piston; real offsets "
                     "are 0-3 % of the bore), got " +
                     mm(e.geometry.pinOffset_m));
  }
  if (!(std::abs(e.mass.piston.comX_m) < 0.5 * bore_m)) {
    d.addProblem("piston.com_towards_thrust_mm",
                 "the centre of mass lies inside the piston: |offset| below half the bore (" +
                     mm(0.5 * bore_m) + "), got " + mm(e.mass.piston.comX_m));
  }
  if (!(e.mass.piston.comY_m < e.piston.compressionHeight_m)) {
    d.addProblem("piston.com_above_pin_mm",
                 "the centre of mass lies inside the piston: below the crown top "
                 "(piston.compression_height_mm = " +
                     mm(e.piston.compressionHeight_m) + "), got " + mm(e.mass.piston.comY_m));
  }
  if (!(e.mass.conrod.comY_m < e.geometry.conrodLength_m)) {
    d.addProblem("conrod.com_from_big_end_mm",
                 "the centre of mass lies between the big-end and small-end centres: less than "
                 "geometry.conrod_length_mm (" +
                     mm(e.geometry.conrodLength_m) + "), got " + mm(e.mass.conrod.comY_m));
  }
}

using Settings = plugin::SimulationSettings;

// The simulation section, and its checks against the liner model's needs.
void readSimulation(YamlDeck& d, const LinerModelNeeds& liner, const std::string& linerModel,
                    EngineDeck& deck) {
  Settings& s = deck.simulation;
  DeckSection root = d.getSection("");
  // Each section of the table is a section (`drive: [1, 2]` is that problem, once; the
  // liner's is checked where it is read).
  std::vector<std::string> sections = {"liner"};
  for (const DeckKey& k : getEngineDeckKeys().getKeys()) {
    const std::string section = k.path.substr(0, k.path.find('.'));
    if (std::find(sections.begin(), sections.end(), section) == sections.end()) {
      sections.push_back(section);
      d.getSection(section);
    }
  }
  s.startAngle_deg = root.getNumber(key("simulation.start_angle_deg"));
  s.cycles = static_cast<int>(root.getInteger(key("simulation.cycles")));
  s.outputStep_deg = root.getNumber(key("simulation.output_step_deg"));
  if (!s.outputStepDividesCycle()) {
    d.addProblem("simulation.output_step_deg", "must divide 720 deg into a whole number of steps");
  } else if (s.outputStepsPerCycle() * s.cycles > Settings::kMaxRows) {
    d.addProblem("simulation.output_step_deg",
                 "with simulation.cycles this makes more than " +
                     std::to_string(static_cast<long>(Settings::kMaxRows)) +
                     " output rows; use a coarser step");
  }
  // Absent with a stiff liner (the lubricated skirt): the linearly implicit stepper, the one
  // integrator that carries it, rather than the explicit default the deck would then refuse.
  const bool stiffDefault = !d.has("simulation.integrator") && !liner.stiffReason.empty();
  std::string integ = root.getChoice(key("simulation.integrator"));
  if (stiffDefault) {
    integ = "linearly_implicit_bdf2";
    d.recordInput({"simulation.integrator", "simulation.integrator", integ});
  }
  const std::map<std::string, Settings::Integrator> integrators = {
      {"rk_merson", Settings::Integrator::RungeKuttaMerson},
      {"rk_feldberg", Settings::Integrator::RungeKuttaFeldberg},
      {"cpodes_bdf", Settings::Integrator::CPodesBDF},
      {"linearly_implicit_bdf2", Settings::Integrator::LinearlyImplicitBDF}};
  s.integrator = integrators.at(integ);
  s.accuracy = root.getNumber(key("simulation.accuracy"));

  // The linearly implicit stepper's settings and the run to periodic steady state.
  s.poseTolerance_m = root.getSI(key("simulation.pose_tolerance_nm"));
  s.maxStep_deg = root.getNumber(key("simulation.max_step_deg"));
  s.stepperOrder = static_cast<int>(root.getInteger(key("simulation.stepper_order")));
  s.jacobianReuseSteps =
      static_cast<int>(root.getInteger(key("simulation.jacobian_reuse_steps")));
  s.maxSteps = root.getInteger(key("simulation.max_steps"));
  s.untilPeriodic = root.getBool(key("simulation.until_periodic"));
  s.periodicFmepTolerance = root.getNumber(key("simulation.periodic_fmep_tolerance"));
  s.periodicPoseTolerance_m = root.getSI(key("simulation.periodic_pose_tolerance_um"));

  const bool explicitRk = s.integrator == Settings::Integrator::RungeKuttaMerson ||
                          s.integrator == Settings::Integrator::RungeKuttaFeldberg;
  if (explicitRk && !liner.stiffReason.empty()) {
    d.addProblem("simulation.integrator",
                 "'" + integ + "' is an explicit integrator, but the liner model '" + linerModel +
                     "' makes the system stiff (" + liner.stiffReason +
                     "): use linearly_implicit_bdf2 (or cpodes_bdf)");
  }
  if (s.integrator == Settings::Integrator::LinearlyImplicitBDF && liner.usesConstraints) {
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
  // First: the keys whose plausible range the deck waives.
  d.readAllowedImplausible({&getEngineDeckKeys(), &getLubricatedSkirtDeckKeys()});
  DeckSection root = d.getSection("");
  mbd::EngineDescription& e = deck.engine;
  e.name = root.getString(key("engine.name"));
  if (d.has("engine.name") && e.name.find_first_not_of(" \t\r\n") == std::string::npos) {
    d.addProblem("engine.name",
                 "is empty: give the engine a name (it labels the summary, the figures and the "
                 "report)");
  }

  mbd::CrankTrainGeometry& g = e.geometry;
  e.piston.bore_m = root.getSI(key("geometry.bore_mm"));
  g.crankRadius_m = 0.5 * root.getSI(key("geometry.stroke_mm"));
  g.conrodLength_m = root.getSI(key("geometry.conrod_length_mm"));
  g.pinOffset_m = root.getSI(key("geometry.pin_offset_mm"));
  g.crankOffset_m = root.getSI(key("geometry.crank_offset_mm"));
  g.compressionRatio = root.getNumber(key("geometry.compression_ratio"));

  e.piston.compressionHeight_m = root.getSI(key("piston.compression_height_mm"));
  e.piston.skirtLength_m = root.getSI(key("piston.skirt_length_mm"));
  e.piston.skirtTopAbovePin_m = root.getSI(key("piston.skirt_top_above_pin_mm"));
  e.mass.piston = readBody(root, "piston");
  e.mass.piston.comY_m = root.getSI(key("piston.com_above_pin_mm"));
  e.mass.piston.comX_m = root.getSI(key("piston.com_towards_thrust_mm"));

  e.mass.pin = readBody(root, "pin");
  const std::string joint = root.getChoice(key("pin.joint"));
  e.pinJoint = joint == "fixed_in_rod"      ? mbd::PinJoint::FixedInRod
               : joint == "fixed_in_piston" ? mbd::PinJoint::FixedInPiston
                                            : mbd::PinJoint::Floating;

  e.mass.conrod = readBody(root, "conrod");
  e.mass.conrod.comY_m = root.getSI(key("conrod.com_from_big_end_mm"));

  e.mass.crank = readBody(root, "crank");
  e.mass.crank.comY_m = root.getSI(key("crank.com_radius_mm"));

  readDrive(root, e.drive);
  e.gravity_mps2 = root.getSI(key("simulation.gravity_mps2"));

  // The pressure table is read after every key is (below); a path that cannot be a table
  // is a problem of the key, reported with the others.
  deck.cylinderPressureFile = root.getFilePath(key("gas.cylinder_pressure_file").path);
  deck.crankcasePressure_Pa = root.getSI(key("gas.crankcase_pressure_bar"));
  if (const auto imep = root.getOptionalSI(key("gas.stated_imep_kPa"))) {
    deck.statedImep_Pa = *imep;
    // The table's imep is compared relative to it: 0 leaves nothing to compare with.
    if (*imep == 0.0) {
      d.addProblem("gas.stated_imep_kPa",
                   "0 is not a valid stated imep: the pressure table's imep is checked to "
                   "within 0.5 % of it; give the imep the table was made for, or leave the key "
                   "out");
    }
  }

  // Cross-key checks of the engine, only on values that are individually valid (a failed
  // read leaves a placeholder that would only produce a second, confusing message).
  if (!d.hasProblems()) {
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
    checkInsideTheBodies(d, e);
  }

  LinerDeckContext liner;
  liner.cylinderPressure = std::make_shared<std::shared_ptr<const mbd::CylinderPressureCurve>>();
  liner.crankcasePressure_Pa = deck.crankcasePressure_Pa;
  const LinerModelNeeds needs = readLiner(d, registry, deck, liner);
  readSimulation(d, needs, deck.linerModel, deck);
  deck.inputs = d.getResolvedInputs();

  // Every key is read; report unknown keys and all problems together.
  d.finish();
  deck.keysRead = d.getKnownKeys();

  // Safety net: the library's own checks (every deck-level problem above should have
  // caught these first, with a key and a line).
  try {
    mbd::validate(e);
    plugin::validate(deck.simulation);
  } catch (const std::invalid_argument& ex) {
    throw DeckError(deckPath + ": " + ex.what());
  }
  // The pressure table first: the liner's maker may need it (a skirt deformed by the gas).
  deck.cylinderPressure = std::make_shared<const mbd::CylinderPressureCurve>(
      readCylinderPressure(d, deck.cylinderPressureFile));
  *liner.cylinderPressure = deck.cylinderPressure;
  // A trial construction of the liner element: its own checks of the values its factory
  // read (std::invalid_argument, ...) are bad input too, reported before any simulation.
  try {
    if (!deck.makeLinerElement())
      throw std::invalid_argument("no element was made");
  } catch (const std::exception& ex) {
    throw DeckError(deckPath + ": liner: the liner model '" + deck.linerModel +
                    "' rejected its parameters: " + ex.what());
  }
  // The imep needs the geometry and the table; a geometry at the edge of the doubles (a
  // bore of 1e-300 mm that a deck allowed as implausible) could make it NaN.
  const double imep = calcDeckImep_Pa(deck);
  if (!std::isfinite(imep)) {
    throw DeckError(d.where("gas.cylinder_pressure_file") +
                    ": the imep of the pressure table cannot be computed with this geometry "
                    "(check the geometry keys' units)");
  }
  if (deck.statedImep_Pa) {
    const double rel = std::abs(imep - *deck.statedImep_Pa) / std::abs(*deck.statedImep_Pa);
    if (!(rel <= 0.005)) {
      throw DeckError(d.where("gas.stated_imep_kPa") + ": the pressure table " +
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

const char* getFidelityName(Fidelity fidelity) {
  return fidelity == Fidelity::Preview ? "preview" : "full";
}

namespace {

// The whole-number input `path` of a loaded deck, if it read one.
std::optional<long> findWholeInput(const EngineDeck& deck, const std::string& path) {
  for (const ResolvedInput& in : deck.inputs) {
    if (in.path == path && std::holds_alternative<long>(in.value))
      return std::get<long>(in.value);
  }
  return std::nullopt;
}

}  // namespace

EngineDeck loadEngineDeck(const std::string& deckPath, const std::vector<std::string>& overrides,
                          Fidelity fidelity, const LinerRegistry& registry) {
  EngineDeck full = loadEngineDeck(deckPath, overrides, registry);
  if (fidelity == Fidelity::Full)
    return full;
  const char* kPhi = kPreviewGridKeys[0];
  const char* kY = kPreviewGridKeys[1];
  const std::optional<long> nPhi = findWholeInput(full, kPhi), nY = findWholeInput(full, kY);
  if (!nPhi || !nY) {
    full.fidelity = Fidelity::Preview;  // nothing to coarsen: the same run
    return full;
  }
  // 3/8 of the nodes around the arc and 5/6 along the skirt (rounded up), not below 16 x 12,
  // never finer than the deck's: fmep depends on the axial count far more than on the
  // circumferential one (the gasoline deck's 64 x 48: 24 x 40 is within 0.4 % of the full
  // grid's fmep, the halved 32 x 24 3.9 % above it; README.md, "Quick start").
  auto coarser = [](long n, long num, long den, long floor) {
    return std::min(n, std::max(floor, (n * num + den - 1) / den));
  };
  const long pPhi = coarser(*nPhi, 3, 8, 16), pY = coarser(*nY, 5, 6, 12);
  std::vector<std::string> previewOverrides = overrides;
  previewOverrides.push_back(std::string(kPhi) + "=" + std::to_string(pPhi));
  previewOverrides.push_back(std::string(kY) + "=" + std::to_string(pY));
  EngineDeck preview = loadEngineDeck(deckPath, previewOverrides, registry);
  preview.fidelity = Fidelity::Preview;
  preview.fidelityNote = "film grid " + std::to_string(pPhi) + " x " + std::to_string(pY) +
                         " nodes per side, the deck's " + std::to_string(*nPhi) + " x " +
                         std::to_string(*nY) +
                         " coarsened (3/8 around, 5/6 along, not below 16 x 12); --fidelity "
                         "full runs the deck as written";
  return preview;
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
