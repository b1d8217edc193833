#include "pistondyn/io/DeckKeys.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace pistondyn::io {

// ---- builders ----------------------------------------------------------------------------

DeckKey DeckKey::number(std::string path, std::optional<Quantity> quantity) {
  DeckKey k;
  k.path = std::move(path);
  k.kind = DeckValueKind::Number;
  k.quantity = quantity;
  if (quantity && !k.getUnit())
    throw std::logic_error("DeckKey " + k.path + ": the key names no unit of its quantity");
  return k;
}

DeckKey DeckKey::wholeNumber(std::string path, long minimum, long maximum) {
  DeckKey k;
  k.path = std::move(path);
  k.kind = DeckValueKind::WholeNumber;
  k.valid = Bounds::between(static_cast<double>(minimum), static_cast<double>(maximum));
  return k;
}

DeckKey DeckKey::onOff(std::string path) {
  DeckKey k;
  k.path = std::move(path);
  k.kind = DeckValueKind::Switch;
  return k;
}

DeckKey DeckKey::text(std::string path) {
  DeckKey k;
  k.path = std::move(path);
  k.kind = DeckValueKind::Text;
  return k;
}

DeckKey DeckKey::choice(std::string path, std::vector<std::string> choices) {
  DeckKey k;
  k.path = std::move(path);
  k.kind = DeckValueKind::Choice;
  k.choices = std::move(choices);
  return k;
}

DeckKey DeckKey::file(std::string path, std::string content) {
  DeckKey k;
  k.path = std::move(path);
  k.kind = DeckValueKind::File;
  k.unitText = std::move(content);
  return k;
}

DeckKey DeckKey::numberList(std::string path, std::optional<Quantity> quantity) {
  DeckKey k = number(std::move(path), quantity);
  k.kind = DeckValueKind::NumberList;
  return k;
}

DeckKey DeckKey::keyList(std::string path) {
  DeckKey k;
  k.path = std::move(path);
  k.kind = DeckValueKind::KeyList;
  return k;
}

DeckKey& DeckKey::require() {
  required = true;
  return *this;
}

DeckKey& DeckKey::byDefault(double value) {
  defaultValue = value;
  return *this;
}

DeckKey& DeckKey::byDefault(std::string text) {
  defaultText = std::move(text);
  return *this;
}

DeckKey& DeckKey::within(const Bounds& bounds) {
  valid = bounds;
  return *this;
}

DeckKey& DeckKey::plausibleWithin(double minimum, double maximum) {
  plausible = Bounds::between(minimum, maximum);
  return *this;
}

DeckKey& DeckKey::unit(std::string text) {
  unitText = std::move(text);
  return *this;
}

DeckKey& DeckKey::means(std::string text) {
  meaning = std::move(text);
  return *this;
}

DeckKey& DeckKey::because(std::string reason) {
  rangeReason = std::move(reason);
  return *this;
}

std::optional<UnitSuffix> DeckKey::getUnit() const {
  if (!quantity)
    return std::nullopt;
  return findUnitSuffix(path, *quantity);
}

// ---- the table ---------------------------------------------------------------------------

DeckKeyTable::DeckKeyTable(std::string title, std::string introduction, std::vector<DeckKey> keys)
    : title_(std::move(title)), introduction_(std::move(introduction)), keys_(std::move(keys)) {
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (keys_[i].path == keys_[j].path)
        throw std::logic_error("DeckKeyTable '" + title_ + "': " + keys_[i].path + " twice");
    }
  }
}

const DeckKey* DeckKeyTable::find(const std::string& path) const {
  for (const auto& k : keys_) {
    if (k.path == path)
      return &k;
  }
  return nullptr;
}

const DeckKey& DeckKeyTable::at(const std::string& path) const {
  if (const DeckKey* k = find(path))
    return *k;
  throw std::logic_error("DeckKeyTable '" + title_ + "': no key " + path);
}

// ---- unit slips --------------------------------------------------------------------------

namespace {

std::string sixDigits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

std::string describeUnitSlip(const DeckKey& key, double value) {
  const std::optional<UnitSuffix> own = key.getUnit();
  if (!own)
    return {};
  const Bounds target = key.plausible.value_or(key.valid);
  if (!std::isfinite(target.minimum) || !std::isfinite(target.maximum) || target.contains(value))
    return {};
  std::string out;
  std::vector<UnitSuffix> seen{*own};
  for (const UnitSuffix& other : getUnits(*key.quantity)) {
    // Aliases (N_m for Nm, radps for rad_per_s) would read as the same value: name one.
    bool alias = false;
    for (const UnitSuffix& s : seen)
      alias = alias || (other.factor == s.factor && other.offset == s.offset);
    if (alias)
      continue;
    seen.push_back(other);
    const double si = value * other.factor + other.offset;
    const double inOwn = (si - own->offset) / own->factor;
    if (!std::isfinite(inOwn) || !target.contains(inOwn) || !key.valid.contains(inOwn))
      continue;
    out += (out.empty() ? "" : " or ") + std::string("in ") + other.suffix + " (" +
           sixDigits(value) + " " + other.suffix + " = " + sixDigits(inOwn) + " " + own->suffix +
           ")";
  }
  return out.empty() ? out : "given " + out + "? The key takes " + own->suffix;
}

// ---- the engine deck's keys --------------------------------------------------------------

const DeckKeyTable& getEngineDeckKeys() {
  using Q = Quantity;
  using K = DeckKey;
  const Bounds positive = Bounds::positive(), nonNegative = Bounds::nonNegative();
  static const DeckKeyTable table(
      "Engine deck",
      "A deck is YAML; the unit is part of every key. Unknown keys are errors (a misspelt key "
      "is never silently ignored). Keys without a default are required. Outside its valid "
      "range a value is an error; outside its plausible range (the engines pistondyn is for) "
      "too, with the unit slip it suggests (a bore of 0.0745 mm: given in m?), unless "
      "`checks.allow_implausible` lists the key.",
      {
          K::text("engine.name").require().means("label in outputs; not empty"),
          K::number("geometry.bore_mm", Q::Length)
              .require()
              .within(positive)
              .plausibleWithin(20, 1000)
              .means("cylinder bore"),
          K::number("geometry.stroke_mm", Q::Length)
              .require()
              .within(positive)
              .plausibleWithin(10, 2500)
              .means("twice the crank radius (the kinematic stroke with offsets is reported in "
                     "`summary.json`)"),
          K::number("geometry.conrod_length_mm", Q::Length)
              .require()
              .within(positive)
              .plausibleWithin(20, 6000)
              .means("big-end to small-end centre distance; longer than half the stroke plus "
                     "|pin offset + crank offset|"),
          K::number("geometry.pin_offset_mm", Q::Length)
              .byDefault(0.0)
              .plausibleWithin(-50, 50)
              .means("pin axis relative to the piston axis, + towards thrust; |offset| below a "
                     "quarter of the bore (the pin and its bosses inside the piston)"),
          K::number("geometry.crank_offset_mm", Q::Length)
              .byDefault(0.0)
              .plausibleWithin(-200, 200)
              .means("cylinder axis relative to the crank axis, + towards thrust"),
          K::number("geometry.compression_ratio")
              .require()
              .within(Bounds{1.0, Bounds::kInfinity, true})
              .plausibleWithin(2, 40)
              .means("(V_d + V_c)/V_c"),
          K::number("piston.compression_height_mm", Q::Length)
              .require()
              .within(positive)
              .plausibleWithin(5, 1500)
              .means("pin axis to crown top"),
          K::number("piston.skirt_length_mm", Q::Length)
              .require()
              .within(positive)
              .plausibleWithin(5, 1500)
              .means("axial skirt length"),
          K::number("piston.skirt_top_above_pin_mm", Q::Length)
              .require()
              .plausibleWithin(-500, 1500)
              .means("skirt top edge above the pin axis (negative if below); not above the "
                     "crown"),
          K::number("piston.mass_g", Q::Mass)
              .require()
              .within(positive)
              .plausibleWithin(10, 2e5)
              .means("piston without pin"),
          K::number("piston.com_above_pin_mm", Q::Length)
              .require()
              .plausibleWithin(-500, 500)
              .means("centre of mass above the pin axis; below the crown (compression_height_mm)"),
          K::number("piston.com_towards_thrust_mm", Q::Length)
              .byDefault(0.0)
              .plausibleWithin(-50, 50)
              .means("centre of mass off the piston axis, + towards thrust; |offset| below half "
                     "the bore"),
          K::number("piston.inertia_kg_mm2", Q::Inertia)
              .require()
              .within(positive)
              .plausibleWithin(0.1, 1e8)
              .means("about the centre of mass, pin-axis direction"),
          K::number("pin.mass_g", Q::Mass)
              .require()
              .within(positive)
              .plausibleWithin(1, 1e5)
              .means("piston pin"),
          K::number("pin.inertia_kg_mm2", Q::Inertia)
              .require()
              .within(positive)
              .plausibleWithin(1e-3, 1e7)
              .means("piston pin, about its axis (a floating pin of no inertia would stall the "
                     "integrator)"),
          K::choice("pin.joint", {"floating", "fixed_in_rod", "fixed_in_piston"})
              .byDefault("floating")
              .means("how the pin is held"),
          K::number("conrod.mass_g", Q::Mass)
              .require()
              .within(positive)
              .plausibleWithin(10, 1e7)
              .means("connecting rod"),
          K::number("conrod.inertia_kg_mm2", Q::Inertia)
              .require()
              .within(positive)
              .plausibleWithin(0.1, 1e10)
              .means("rod, about its centre of mass"),
          K::number("conrod.com_from_big_end_mm", Q::Length)
              .require()
              .within(nonNegative)
              .plausibleWithin(0, 6000)
              .means("centre of mass along the rod from the big end; less than "
                     "conrod_length_mm"),
          K::number("crank.mass_g", Q::Mass)
              .require()
              .within(positive)
              .plausibleWithin(50, 1e8)
              .means("one crank throw"),
          K::number("crank.inertia_kg_mm2", Q::Inertia)
              .require()
              .within(positive)
              .plausibleWithin(1, 1e10)
              .means("crank throw, about its centre of mass"),
          K::number("crank.com_radius_mm", Q::Length)
              .require()
              .plausibleWithin(-2000, 2000)
              .means("centre of mass along the throw (negative: counterweight side)"),
          K::choice("drive.mode", {"constant_speed", "free"})
              .byDefault("constant_speed")
              .means("prescribed speed, or free crank with flywheel and load torque"),
          K::number("drive.speed_rpm", Q::AngularSpeed)
              .require()
              .within(Bounds::between(1, 50000))
              .plausibleWithin(20, 25000)
              .means("prescribed (or initial, when free) speed"),
          K::number("drive.flywheel_inertia_kg_m2", Q::Inertia)
              .byDefault(0.0)
              .within(nonNegative)
              .plausibleWithin(0, 1e5)
              .means("free crank only (an error with `constant_speed`, which ignores it)"),
          K::number("drive.load_torque_Nm", Q::Moment)
              .byDefault(0.0)
              .within(nonNegative)
              .plausibleWithin(0, 1e5)
              .means("free crank only (an error with `constant_speed`); opposes rotation"),
          K::file("gas.cylinder_pressure_file", "CSV `crank_angle_deg, pressure_<unit>`")
              .require()
              .plausibleWithin(1, 500)
              .means("cylinder pressure over the cycle, relative to the deck's folder; unit "
                     "`Pa`, `kPa`, `bar` or `MPa` (absolute); angles strictly increasing, "
                     "covering 720°; plausible: the peak in bar in this range (a table in Pa "
                     "labelled bar is an error)"),
          K::number("gas.crankcase_pressure_bar", Q::Pressure)
              .byDefault(1.01325)
              .within(Bounds::between(0, 1000))
              .plausibleWithin(0.5, 5)
              .means("pressure under the piston (absolute)"),
          K::number("gas.stated_imep_kPa", Q::Pressure)
              .byDefault("none")
              .plausibleWithin(-1000, 5000)
              .means("if given (not 0), the table's imep must be within 0.5 % of it"),
          K::text("liner.model")
              .byDefault("ideal_guide")
              .unit("`ideal_guide`, `lubricated_skirt`, or a model the program registered")
              .means("liner force element, chosen through the liner registry; the model reads "
                     "the other `liner.*` keys (`lubricated_skirt`: below; `ideal_guide` reads "
                     "none)"),
          K::number("simulation.start_angle_deg", Q::Angle)
              .byDefault(0.0)
              .within(Bounds::between(-720, 720))
              .means("crank angle of the first row"),
          K::wholeNumber("simulation.cycles", 1, 1000)
              .byDefault(1.0)
              .means("whole 720° cycles; with `until_periodic` the most to run, ≥ 2"),
          K::number("simulation.output_step_deg", Q::Angle)
              .byDefault(1.0)
              .within(Bounds::between(0.001, 720))
              .means("must divide 720; at most 1e7 rows in all"),
          K::choice("simulation.integrator",
                    {"rk_merson", "rk_feldberg", "cpodes_bdf", "linearly_implicit_bdf2"})
              .byDefault("rk_merson")
              .means("Simbody integrator, or the linearly implicit BDF stepper for the stiff "
                     "squeeze film (`plugin/LinearlyImplicitStepper.h`, BDF2 or BDF3 by "
                     "`simulation.stepper_order`, default 3; no constraints: not "
                     "with `ideal_guide`). The lubricated skirt needs `linearly_implicit_bdf2` "
                     "or `cpodes_bdf`; absent, a stiff liner (the lubricated skirt) gets "
                     "`linearly_implicit_bdf2`"),
          K::number("simulation.accuracy")
              .byDefault(1e-9)
              .within(Bounds::between(1e-14, 1e-2))
              .means("Simbody integrators' relative accuracy"),
          K::number("simulation.pose_tolerance_nm", Q::Length)
              .byDefault(1.0)
              .within(Bounds::between(1e-3, 1e5))
              .means("`linearly_implicit_bdf2`: per-step tolerance on u_lat, u_tran, tilt × "
                     "skirt length (the default with the default order and step: on the "
                     "gasoline deck's 32 × 24 grid its cycle figures within 0.5 % and its films "
                     "and motion extremes within 0.01 µm of a run with 1/32 of the step, but "
                     "for the largest side force, a slap peak the 1° rows sample: −7 %; "
                     "BENCHMARKS.md)"),
          K::number("simulation.max_step_deg", Q::Angle)
              .byDefault(1.0)
              .within(Bounds{0.0, 10.0, true})
              .means("`linearly_implicit_bdf2`: largest step"),
          K::wholeNumber("simulation.stepper_order", 2, 3)
              .byDefault(3)
              .means("`linearly_implicit_bdf2`: order of the BDF formula, 2 or 3 (variable-step "
                     "BDF3: the global error of the slow secondary motion falls with the cube "
                     "of the step; BENCHMARKS.md). The elastic skirt's coupling takes more "
                     "film solves with 3: its study sets 2"),
          K::wholeNumber("simulation.jacobian_reuse_steps", 0, 1000)
              .byDefault(0)
              .means("`linearly_implicit_bdf2`: 0 evaluates the film's squeeze derivatives "
                     "(the stepper's damping Jacobian) at every force evaluation; N keeps "
                     "them for up to N steps (an evaluation then skips ~40 % of a rigid "
                     "skirt's film work). For film-borne skirts: on a starved film it moved "
                     "fmep by up to 6 % (BENCHMARKS.md)"),
          K::wholeNumber("simulation.max_steps", 1, 2000000000)
              .byDefault(2e7)
              .means("step budget of the run (a run never hangs: it stops with the crank angle "
                     "reached)"),
          K::onOff("simulation.until_periodic")
              .byDefault(0.0)
              .means("run until two cycles agree, at most `cycles`; only the last cycle is "
                     "written"),
          K::number("simulation.periodic_fmep_tolerance")
              .byDefault(0.005)
              .within(Bounds{0.0, 0.5, true})
              .means("relative change of fmep between two cycles"),
          K::number("simulation.periodic_pose_tolerance_um", Q::Length)
              .byDefault(0.2)
              .within(Bounds{0.0, 100.0, true})
              .means("change of u_lat and tilt × skirt length at equal crank angles"),
          K::number("simulation.gravity_mps2", Q::Acceleration)
              .byDefault(9.80665)
              .within(Bounds::between(0, 100))
              .plausibleWithin(0, 10)
              .means("along −y (cylinder vertical, head up)"),
          K::keyList(kAllowImplausibleKey)
              .byDefault("none")
              .means("keys whose plausible range this deck waives, e.g. `[geometry.bore_mm]` "
                     "for a model engine; the valid range still applies"),
      });
  return table;
}

}  // namespace pistondyn::io
