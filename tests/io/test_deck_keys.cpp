// The key table (io/DeckKeys.h) against what the deck readers do: every key they ask for
// is in the table and every table key is read by some deck; each documented valid and
// plausible range is the one enforced (probed just outside each end, through the deck
// loader); each documented default is the value read when the key is absent; unit slips
// are named with the unit that fits; checks.allow_implausible waives a plausible range.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "FullSkirtDeck.h"
#include "ScratchDeck.h"
#include "pistondyn/io/DeckKeys.h"
#include "pistondyn/io/DeckReference.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/LubricatedSkirtDeck.h"
#include "pistondyn/io/ResultWriters.h"

using namespace pistondyn_test;
namespace io = pistondyn::io;

namespace {

std::vector<const io::DeckKey*> allKeys() {
  std::vector<const io::DeckKey*> keys;
  for (const io::DeckKeyTable* t : io::getDeckReferenceTables()) {
    for (const auto& k : t->getKeys())
      keys.push_back(&k);
  }
  return keys;
}

const io::DeckKey* findKey(const std::string& path) {
  for (const io::DeckKey* k : allKeys()) {
    if (k->path == path)
      return k;
  }
  return nullptr;
}

// The leaves of a set of key paths: those that are no other path's section.
std::set<std::string> leaves(const std::set<std::string>& paths) {
  std::set<std::string> out;
  for (const auto& p : paths) {
    const auto next = paths.upper_bound(p);
    if (next == paths.end() || next->rfind(p + ".", 0) != 0)
      out.insert(p);
  }
  return out;
}

// The decks that together read every key: the example deck as it is, fully flooded, and
// the full skirt section with a user oil and a free crank.
class KeyCoverage : public FullSkirtDeck {
 protected:
  std::set<std::string> keysRead(const std::string& deckPath,
                                 const std::vector<std::string>& overrides) {
    const io::EngineDeck d = io::loadEngineDeck(deckPath, overrides);
    return {d.keysRead.begin(), d.keysRead.end()};
  }
};

TEST_F(KeyCoverage, EveryKeyTheReadersAskForIsInTheTableAndEveryTableKeyIsRead) {
  const std::string example = kEngineDir + "/engine.yaml";
  std::set<std::string> read;
  for (const auto& k : keysRead(example, {}))
    read.insert(k);
  for (const auto& k :
       keysRead(example, {"liner.oil_supply.film_um=null", "liner.oil_supply.fully_flooded=true"}))
    read.insert(k);
  for (const auto& k : keysRead(example, {"liner.oil_supply.film_um=null",
                                          "liner.oil_supply.liner_transport.ring_height_above_pin_mm=13",
                                          "liner.oil_supply.liner_transport.ring_film_um=1"}))
    read.insert(k);
  for (const auto& k :
       keysRead(deck(), {"liner.oil.name=test oil", "drive.mode=free",
                         "drive.flywheel_inertia_kg_m2=0.5", "drive.load_torque_Nm=10",
                         "gas.stated_imep_kPa=598", "checks.allow_implausible=[geometry.bore_mm]"}))
    read.insert(k);
  const std::set<std::string> used = leaves(read);
  std::set<std::string> table;
  for (const io::DeckKey* k : allKeys())
    table.insert(k->path);
  for (const auto& k : used)
    EXPECT_TRUE(table.count(k)) << k << " is read but not in the key table (DeckKeys.h)";
  for (const auto& k : table)
    EXPECT_TRUE(used.count(k)) << k << " is in the key table but no deck of this test reads it";
  EXPECT_GT(table.size(), 90u);
}

// A value just outside a bound: the bound itself if it is excluded, else a step beyond.
double beyond(double bound, bool excluded, double direction) {
  if (excluded)
    return bound;
  const double step = std::max(1e-6 * std::abs(bound), 1e-300);
  return bound + direction * step;
}

// What makes a key read at all (a user oil's keys are read only without a grade; the free
// crank's only in free mode).
std::vector<std::string> contextFor(const std::string& path) {
  if (path.rfind("liner.oil.", 0) == 0 && path != "liner.oil.temperature_degC" &&
      path != "liner.oil.grade") {
    return {"liner.oil.grade=null", "liner.oil.kinematic_viscosity_1_mm2_per_s=60",
            "liner.oil.kinematic_viscosity_2_mm2_per_s=10", "liner.oil.density_kg_per_m3=850"};
  }
  if (path.rfind("drive.", 0) == 0)
    return {"drive.mode=free"};
  if (path.rfind("liner.oil_supply.liner_transport.", 0) == 0)
    return {"liner.oil_supply.film_um=null",
            "liner.oil_supply.liner_transport.ring_height_above_pin_mm=13",
            "liner.oil_supply.liner_transport.ring_film_um=1",
            "liner.oil_supply.liner_transport.splash_below_mm=100"};
  if (path == "liner.oil_supply.film_um")
    return {};
  return {};
}

// Every documented range is enforced: a value just outside each end of the valid range is
// rejected naming the key; just outside the plausible range (inside the valid one) too,
// saying "plausible", and accepted as far as that key goes when checks.allow_implausible
// lists it.
TEST_F(SkirtScratchDeck, DocumentedRangesAreTheEnforcedOnes) {
  int probes = 0;
  for (const io::DeckKey* k : allKeys()) {
    if (k->kind != io::DeckValueKind::Number && k->kind != io::DeckValueKind::WholeNumber)
      continue;
    const std::vector<std::string> context = contextFor(k->path);
    auto rejectionOf = [&](double v, const std::vector<std::string>& extra = {}) {
      std::vector<std::string> o = context;
      o.insert(o.end(), extra.begin(), extra.end());
      o.push_back(k->path + "=" + io::formatNumber(v));
      return rejection(o);
    };
    const std::string named = "--set " + k->path + ": ";
    const io::Bounds& b = k->valid;
    if (std::isfinite(b.minimum)) {
      const double v = beyond(b.minimum, b.excludeMinimum, -1.0);
      EXPECT_NE(rejectionOf(v).find(named), std::string::npos) << k->path << " = " << v;
      ++probes;
    }
    if (std::isfinite(b.maximum)) {
      const double v = beyond(b.maximum, b.excludeMaximum, +1.0);
      EXPECT_NE(rejectionOf(v).find(named), std::string::npos) << k->path << " = " << v;
      ++probes;
    }
    if (k->kind == io::DeckValueKind::WholeNumber) {
      const std::string m = rejectionOf(b.minimum + 0.5);
      EXPECT_NE(m.find(named + "must be a whole number"), std::string::npos) << m;
      ++probes;
    }
    if (k->plausible) {
      for (const double v :
           {k->plausible->minimum - std::max(1e-6 * std::abs(k->plausible->minimum), 1e-9),
            k->plausible->maximum * (1 + 1e-6) + 1e-9}) {
        if (!b.contains(v))
          continue;
        const std::string m = rejectionOf(v);
        EXPECT_NE(m.find(named + io::formatNumber(v)), std::string::npos) << m;
        EXPECT_NE(m.find("plausible range"), std::string::npos) << m;
        const std::string allowed =
            rejectionOf(v, {std::string(io::kAllowImplausibleKey) + "=[" + k->path + "]"});
        EXPECT_EQ(allowed.find(named + io::formatNumber(v)), std::string::npos)
            << k->path << ": " << allowed;
        ++probes;
      }
    }
  }
  EXPECT_GT(probes, 100);
}

// Each documented default is what the readers use when the key is absent: a deck of the
// required keys only (and the lubricated skirt's), its resolved inputs against the table.
TEST_F(ScratchDeck, DocumentedDefaultsAreTheValuesReadWhenTheKeyIsAbsent) {
  std::ofstream(deck()) << R"(engine: {name: minimal}
geometry: {bore_mm: 74.5, stroke_mm: 80, conrod_length_mm: 140, compression_ratio: 10}
piston: {compression_height_mm: 30, skirt_length_mm: 30, skirt_top_above_pin_mm: 12,
         mass_g: 250, com_above_pin_mm: 5, inertia_kg_mm2: 200}
pin: {mass_g: 70, inertia_kg_mm2: 2}
conrod: {mass_g: 450, inertia_kg_mm2: 1500, com_from_big_end_mm: 40}
crank: {mass_g: 2000, inertia_kg_mm2: 2000, com_radius_mm: -5}
drive: {speed_rpm: 2000}
gas: {cylinder_pressure_file: cylinder_pressure_fired_imep598kPa.csv}
liner:
  model: lubricated_skirt
  cold_radial_clearance_um: 40
  oil: {grade: 0W-30}
  oil_supply: {film_um: 0.5}
  roughness: {liner_rq_um: 0.4, skirt_rq_um: 0.6}
simulation: {integrator: linearly_implicit_bdf2}
)";
  // Graded oil, and a user oil (whose temperatures have defaults too).
  std::vector<io::ResolvedInput> inputs = io::loadEngineDeck(deck(), {}).inputs;
  for (const auto& r : io::loadEngineDeck(deck(), {"liner.oil.grade=null",
                                                   "liner.oil.kinematic_viscosity_1_mm2_per_s=60",
                                                   "liner.oil.kinematic_viscosity_2_mm2_per_s=10",
                                                   "liner.oil.density_kg_per_m3=850"})
                           .inputs)
    inputs.push_back(r);
  // The oil carried on the liner (its keys are read only in its section).
  for (const auto& r : io::loadEngineDeck(deck(), {"liner.oil_supply.film_um=null",
                                                   "liner.oil_supply.liner_transport.ring_height_above_pin_mm=13",
                                                   "liner.oil_supply.liner_transport.ring_film_um=1"})
                           .inputs)
    inputs.push_back(r);
  int checked = 0;
  for (const io::DeckKey* k : allKeys()) {
    if (!k->defaultValue || k->required)
      continue;
    const io::ResolvedInput* in = nullptr;
    for (const auto& r : inputs) {
      if (r.path == k->path)
        in = &r;
    }
    ASSERT_NE(in, nullptr) << k->path << ": absent, but its default was not recorded";
    double expected = *k->defaultValue;
    // SI getters record the value converted by the key's unit (one product, exact), the
    // others in the key's unit.
    if (k->getUnit() && in->siPath != in->path)
      expected = expected * k->getUnit()->factor + k->getUnit()->offset;
    if (const auto* v = std::get_if<double>(&in->value)) {
      EXPECT_EQ(*v, expected) << k->path;
    } else if (const auto* n = std::get_if<long>(&in->value)) {
      EXPECT_EQ(static_cast<double>(*n), expected) << k->path;
    } else if (const auto* s = std::get_if<bool>(&in->value)) {
      EXPECT_EQ(*s, expected != 0.0) << k->path;
    } else {
      ADD_FAILURE() << k->path << ": recorded as neither number nor switch";
    }
    ++checked;
  }
  for (const io::DeckKey* k : allKeys()) {
    // (The minimal deck sets the integrator: the skirt needs an implicit one.)
    const bool defaultIsAChoice =
        std::find(k->choices.begin(), k->choices.end(), k->defaultText) != k->choices.end();
    if (k->kind != io::DeckValueKind::Choice || !defaultIsAChoice || k->required ||
        k->path == "simulation.integrator")
      continue;
    for (const auto& r : inputs) {
      if (r.path == k->path) {
        EXPECT_EQ(std::get<std::string>(r.value), k->defaultText) << k->path;
      }
    }
  }
  EXPECT_GT(checked, 40);
}

// Unit slips of the issue: the value given in another unit than the key's, named.
TEST_F(ScratchDeck, UnitSlipsNameTheUnitThatFits) {
  std::string m = rejection({"geometry.bore_mm=0.0745"});
  EXPECT_NE(
      m.find("--set geometry.bore_mm: 0.0745 mm is outside the plausible range [20, 1000] mm"),
      std::string::npos)
      << m;
  EXPECT_NE(m.find("given in m (0.0745 m = 74.5 mm)?"), std::string::npos) << m;
  m = rejection({"piston.mass_g=0.21"});
  EXPECT_NE(m.find("given in kg (0.21 kg = 210 g)?"), std::string::npos) << m;
  m = rejection({"gas.crankcase_pressure_bar=101325"});
  EXPECT_NE(m.find("given in Pa (101325 Pa = 1.01325 bar)?"), std::string::npos) << m;
  m = rejection({"piston.inertia_kg_mm2=3.5e-5"});
  EXPECT_NE(m.find("given in kg_m2 (3.5e-05 kg_m2 = 35 kg_mm2)?"), std::string::npos) << m;
  // The example's pressure table in Pa under its bar header (each pressure x 1e5): its
  // peak, and the unit that fits.
  std::istringstream table(readFile(dir_ / kTable));
  std::ofstream pa(dir_ / "pa.csv");
  for (std::string line; std::getline(table, line);) {
    const auto comma = line.find(',');
    if (line.empty() || line[0] == '#' || line.rfind("crank", 0) == 0 || comma == std::string::npos)
      pa << line << '\n';
    else
      pa << line.substr(0, comma) << ',' << std::stod(line.substr(comma + 1)) * 1e5 << '\n';
  }
  pa.close();
  m = rejection({"gas.cylinder_pressure_file=pa.csv"});
  EXPECT_NE(m.find("--set gas.cylinder_pressure_file: "), std::string::npos) << m;
  EXPECT_NE(m.find("the peak pressure is"), std::string::npos) << m;
  EXPECT_NE(m.find("the header says pressure_bar: are the numbers in Pa?"), std::string::npos) << m;
}

TEST_F(ScratchDeck, AllowImplausibleWaivesThePlausibleRangeOnly) {
  EXPECT_EQ(rejection({"piston.mass_g=0.5", "checks.allow_implausible=[piston.mass_g]"}), "");
  // The valid range still applies.
  EXPECT_NE(rejection({"piston.mass_g=-1", "checks.allow_implausible=[piston.mass_g]"})
                .find("piston.mass_g: must be positive"),
            std::string::npos);
  // Only keys with a plausible range, and only keys.
  const std::string m = rejection({"checks.allow_implausible=[simulation.cycles, no.such_key]"});
  EXPECT_NE(m.find("item 1: 'simulation.cycles' is not a key with a plausible range"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("item 2: 'no.such_key' is not a key"), std::string::npos) << m;
}

// The reference shows every key once, with its unit and range as the table has them.
TEST(DeckReference, TheMarkdownHasOneRowPerKeyBetweenTheMarkers) {
  const std::string md = io::makeDeckReferenceMarkdown();
  EXPECT_EQ(md.rfind(io::kDeckReferenceBegin, 0), 0u);
  EXPECT_NE(md.find(io::kDeckReferenceEnd), std::string::npos);
  for (const io::DeckKey* k : allKeys()) {
    const std::string row = "| `" + k->path + "` | ";
    const auto at = md.find(row);
    ASSERT_NE(at, std::string::npos) << k->path;
    EXPECT_EQ(md.find(row, at + 1), std::string::npos) << k->path << " twice";
  }
  EXPECT_NE(md.find("| `drive.speed_rpm` | rpm | — | [1, 50000]; plausible [20, 25000] |"),
            std::string::npos);
  EXPECT_NE(md.find("| `simulation.cycles` | whole number | 1 | 1 … 1000 |"), std::string::npos);
  EXPECT_NE(md.find("| `simulation.output_step_deg` | ° | 1 | [0.001, 720] |"), std::string::npos);
  EXPECT_NE(md.find("| `simulation.accuracy` | – | 1e-9 | [1e-14, 0.01] |"), std::string::npos);
  EXPECT_NE(findKey("liner.cold_radial_clearance_um"), nullptr);
}

}  // namespace
