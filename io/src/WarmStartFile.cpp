#include "pistondyn/io/WarmStartFile.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "FileBytes.h"

namespace pistondyn::io {
namespace {

using Json = nlohmann::ordered_json;

// The state's keys and members, in the file's order.
struct StateKey {
  const char* name;
  double plugin::SecondaryState::*member;
};
constexpr StateKey kStateKeys[] = {
    {"lateral_m", &plugin::SecondaryState::lateral_m},
    {"tilt_rad", &plugin::SecondaryState::tilt_rad},
    {"transverse_m", &plugin::SecondaryState::transverse_m},
    {"lateral_rate_mps", &plugin::SecondaryState::lateralRate_mps},
    {"tilt_rate_radps", &plugin::SecondaryState::tiltRate_radps},
    {"transverse_rate_mps", &plugin::SecondaryState::transverseRate_mps},
    {"crank_speed_radps", &plugin::SecondaryState::crankSpeed_radps},
};

// Reads the file's values, each failure naming the file and the key.
class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(path_ + ": " + what);
  }
  const Json& member(const Json& object, const char* key, const std::string& where) const {
    const auto it = object.find(key);
    if (it == object.end())
      fail("no key " + where + key);
    return *it;
  }
  double number(const Json& object, const char* key, const std::string& where = "") const {
    const Json& v = member(object, key, where);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      fail(where + key + " must be a finite number");
    return v.get<double>();
  }
  std::vector<double> numbers(const Json& object, const char* key, const std::string& where) const {
    const Json& v = member(object, key, where);
    if (!v.is_array())
      fail(where + key + " must be a list of numbers");
    std::vector<double> out;
    out.reserve(v.size());
    for (const Json& x : v) {
      if (!x.is_number() || !std::isfinite(x.get<double>()))
        fail(where + key + " must be a list of finite numbers");
      out.push_back(x.get<double>());
    }
    return out;
  }
  const Json& object(const Json& parent, const char* key) const {
    const Json& v = member(parent, key, "");
    if (!v.is_object())
      fail(std::string(key) + " must be an object");
    return v;
  }

 private:
  std::string path_;
};

}  // namespace

std::string makeWarmStartJson(const plugin::WarmStart& w) {
  Json j;
  j["note"] = "where this run ended: the piston's secondary state at its last row and the pose "
              "of the cycle that led to it, for `pistondyn run DECK --warm-start DIR` (SI)";
  j["crank_angle_deg"] = w.crankAngle_deg;
  j["output_step_deg"] = w.outputStep_deg;
  Json& state = j["state"];
  for (const StateKey& k : kStateKeys)
    state[k.name] = w.state.*k.member;
  Json& cycle = j["last_cycle"];
  if (w.lastCycleFmep_Pa)
    cycle["fmep_Pa"] = *w.lastCycleFmep_Pa;
  cycle["lateral_m"] = w.lastCycleLateral_m;
  cycle["tilt_rad"] = w.lastCycleTilt_rad;
  Json& elements = j["elements"];
  elements = Json::array();
  for (const plugin::WarmStart::ElementRecord& e : w.elements)
    elements.push_back(Json{{"element", e.element}, {"record", e.record}});
  // Doubles in the shortest text that reads back to the same double (as summary.json).
  return j.dump(1) + "\n";
}

plugin::WarmStart readWarmStart(const std::string& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw std::runtime_error(dir + ": not a folder (a result folder of `pistondyn run`)");
  return readWarmStartFile((std::filesystem::path(dir) / kWarmStartFile).string());
}

plugin::WarmStart readWarmStartFile(const std::string& path) {
  const std::optional<std::string> text = detail::readFileBytes(path);
  if (!text) {
    throw std::runtime_error(path + ": cannot be read (a result folder of `pistondyn run` "
                                    "holds it; runs before it existed do not)");
  }
  const Json j = Json::parse(*text, nullptr, /*allow_exceptions=*/false);
  const Reader read(path);
  if (j.is_discarded())
    read.fail("not valid JSON");
  if (!j.is_object())
    read.fail("must be a JSON object");
  plugin::WarmStart w;
  w.crankAngle_deg = read.number(j, "crank_angle_deg");
  w.outputStep_deg = read.number(j, "output_step_deg");
  const Json& state = read.object(j, "state");
  for (const StateKey& k : kStateKeys)
    w.state.*k.member = read.number(state, k.name, "state.");
  const Json& cycle = read.object(j, "last_cycle");
  if (cycle.contains("fmep_Pa"))
    w.lastCycleFmep_Pa = read.number(cycle, "fmep_Pa", "last_cycle.");
  w.lastCycleLateral_m = read.numbers(cycle, "lateral_m", "last_cycle.");
  w.lastCycleTilt_rad = read.numbers(cycle, "tilt_rad", "last_cycle.");
  if (w.lastCycleLateral_m.size() != w.lastCycleTilt_rad.size())
    read.fail("last_cycle.lateral_m and last_cycle.tilt_rad must be lists of equal length");
  const Json& elements = read.member(j, "elements", "");
  if (!elements.is_array())
    read.fail("elements must be a list");
  for (const Json& e : elements) {
    if (!e.is_object() || !e.contains("element") || !e["element"].is_string())
      read.fail("every entry of elements must be an object with an element name");
    w.elements.push_back({e["element"].get<std::string>(),
                          read.numbers(e, "record", "elements[].")});
  }
  return w;
}

void checkWarmStartFits(const EngineDeck& deck) {
  if (!deck.simulation.warmStart)
    return;
  const plugin::WarmStart& w = *deck.simulation.warmStart;
  plugin::validateWarmStart(w, deck.simulation);
  const auto model = buildModel(deck);
  model->buildSystem();
  SimTK::State state = model->getDefaultState();
  plugin::applyWarmStart(*model, state, w, deck.simulation.startAngle_deg);
}

}  // namespace pistondyn::io
