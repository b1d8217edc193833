#include "ReportSummary.h"

#include <cmath>
#include <cstdlib>
#include <optional>

#include "DisplayUnits.h"

namespace pistondyn::app {
namespace {

// The number a JSON text holds; nullopt for anything else (text, null, a list, "").
std::optional<double> parseNumber(const std::string& text) {
  if (text.empty())
    return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v))
    return std::nullopt;
  return v;
}

// A JSON number written without fraction or exponent: a count, shown whole.
bool isIntegerText(const std::string& text) {
  return parseNumber(text) && text.find_first_of(".eE") == std::string::npos;
}

std::optional<double> getNumber(const io::ResultFolder& f, const std::string& key) {
  return parseNumber(f.getSummaryValue(key));
}

// "1.23 µm at 382.5°": a results figure with the crank angle it occurs at, when the summary
// has that angle.
std::string valueAt(const io::ResultFolder& f, const std::string& key, double value,
                    const std::string& angleKey) {
  std::string text = units::formatDisplayValue(key, value);
  if (const auto angle = getNumber(f, angleKey))
    text += " at " + units::formatDisplayValue(angleKey, *angle);
  return text;
}

// Whether the run converged to a periodic cycle, and after how many cycles. A run that did
// not converge names no number of cycles to converge (summary.json writes null then).
HeadlineItem describeConvergence(const io::ResultFolder& f) {
  const std::string run = f.getSummaryValue("results.cycles_run");
  const std::string cyclesRun = run.empty() ? "" : run + (run == "1" ? " cycle" : " cycles");
  const bool converged = f.getSummaryValue("results.converged") == "true";
  const std::string toConverge = f.getSummaryValue("results.cycles_to_converge");
  HeadlineItem item{"periodic", "", ""};
  if (converged && isIntegerText(toConverge)) {
    item.value = "converged after " + toConverge + (toConverge == "1" ? " cycle" : " cycles");
    item.note = "the last two cycles agreed within the deck's periodic tolerances";
  } else {
    item.value = "not converged" + (cyclesRun.empty() ? "" : " (" + cyclesRun + " run)");
    item.note = f.getSummaryValue("inputs.simulation.until_periodic") == "true"
                    ? "the last two cycles did not agree within the deck's periodic tolerances: "
                      "the figures are those of the last cycle, not of a periodic one"
                    : "simulation.until_periodic is off: the cycles were not compared; the "
                      "figures are those of the last cycle";
  }
  return item;
}

}  // namespace

std::vector<HeadlineItem> makeHeadline(const io::ResultFolder& f) {
  std::vector<HeadlineItem> items;
  // A figure shown as its display value, when the summary has it.
  auto add = [&](const std::string& label, const std::string& key, const std::string& note,
                 const std::string& angleKey = "") {
    const std::string full = "results." + key;
    if (const auto v = getNumber(f, full)) {
      std::string value = angleKey.empty() ? units::formatDisplayValue(key, *v)
                                           : valueAt(f, key, *v, "results." + angleKey);
      // A run that did not become periodic: the last cycles' mean and spread beside it.
      const auto mean = getNumber(f, "results.last_cycles.mean." + key);
      const auto spread = getNumber(f, "results.last_cycles.spread." + key);
      if (mean && spread) {
        value += "; last cycles: mean " + units::formatDisplayValue(key, *mean) + ", spread " +
                 units::formatDisplayValue(key, *spread);
      }
      items.push_back({label, value, note});
    }
  };
  add("fmep", "fmep_kPa", "friction mean effective pressure of the skirt, last cycle");
  add("imep", "imep_kPa", "indicated mean effective pressure of the pressure table");
  add("mean friction power", "friction_power_mean_W", "skirt friction work over the cycle time");
  add("asperity share", "asperity_friction_work_share",
      "share of the friction work done by asperity contact");
  add("min h/σ thrust side", "min_h_over_sigma_thrust",
      "smallest film thickness over composite roughness (below about 3: mixed lubrication)",
      "min_h_over_sigma_thrust_crank_angle_deg");
  add("min h/σ anti-thrust side", "min_h_over_sigma_antithrust", "",
      "min_h_over_sigma_antithrust_crank_angle_deg");
  add("min film thrust side", "min_film_thickness_thrust_um", "",
      "min_film_thickness_thrust_crank_angle_deg");
  add("min film anti-thrust side", "min_film_thickness_antithrust_um", "",
      "min_film_thickness_antithrust_crank_angle_deg");
  add("largest slap energy", "slap_energy_max_mJ",
      "kinetic energy of the largest completed slap event");
  add("max |tilt|", "max_abs_tilt_deg", "largest piston tilt about the pin");
  add("max |lateral motion|", "max_abs_u_lat_um", "largest lateral displacement of the pin");
  add("hot clearance", "hot_clearance_um", "radial running clearance at the profile's zero drop");
  add("peak cylinder pressure", "peak_cylinder_pressure_Pa", "",
      "peak_cylinder_pressure_angle_deg");
  add("largest side force on the liner", "side_force_max_N",
      "film and contact force towards the thrust side", "side_force_max_angle_deg");
  items.push_back(describeConvergence(f));
  return items;
}

std::string formatSummaryValue(const std::string& key, const std::string& jsonText) {
  if (jsonText.empty())
    return "–";
  if (jsonText == "null") {
    const std::string name = units::splitUnit(key).first;
    return name == "cycles_to_converge" ? "not converged" : "–";
  }
  if (jsonText == "true" || jsonText == "false")
    return jsonText == "true" ? "yes" : "no";
  if (isIntegerText(jsonText) && units::getDisplayFormat(key).factor == 1.0)
    return jsonText;
  if (const auto v = parseNumber(jsonText))
    return units::formatDisplayNumber(key, *v);
  if (jsonText.size() > 2 && jsonText.front() == '[' && jsonText.back() == ']') {
    std::string out, item;
    const std::string inner = jsonText.substr(1, jsonText.size() - 2) + ",";
    for (char c : inner) {
      if (c != ',') {
        item += c;
        continue;
      }
      const std::size_t a = item.find_first_not_of(' ');
      item = a == std::string::npos ? "" : item.substr(a);
      const auto v = parseNumber(item);
      if (!v)
        return jsonText;  // not a list of numbers: as written
      out += (out.empty() ? "" : ", ") + units::formatDisplayNumber(key, *v);
      item.clear();
    }
    return out;
  }
  return jsonText;
}

}  // namespace pistondyn::app
