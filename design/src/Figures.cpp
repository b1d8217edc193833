#include "pistondyn/design/Figures.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace pistondyn::design {

const std::vector<std::string>& getKnownFigures() {
  static const std::vector<std::string> names = {
      "fmep_kPa",
      "friction_power_mean_W",
      "friction_work_J",
      "asperity_friction_work_J",
      "asperity_friction_work_share",
      "slap_energy_max_mJ",
      "min_h_over_sigma",
      "min_h_over_sigma_thrust",
      "min_h_over_sigma_antithrust",
      "min_film_thickness_thrust_um",
      "min_film_thickness_antithrust_um",
      "max_abs_u_lat_um",
      "max_abs_tilt_deg",
      "hot_clearance_um",
      "side_force_max_N",
      "side_force_min_N",
      "conrod_force_max_N",
      "conrod_force_min_N",
      "mean_crank_torque_Nm",
      "indicated_power_W",
  };
  return names;
}

bool isKnownFigure(const std::string& name) {
  const auto& n = getKnownFigures();
  return std::find(n.begin(), n.end(), name) != n.end();
}

std::string listKnownFigures() {
  std::string s;
  for (const auto& n : getKnownFigures())
    s += (s.empty() ? "" : ", ") + n;
  return s;
}

RunFigures::RunFigures(const std::string& summaryJson) {
  try {
    const auto j = nlohmann::json::parse(summaryJson);
    for (const auto& [key, value] : j.at("results").items()) {
      if (value.is_number())
        values_.emplace_back(key, value.get<double>());
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("not a run's summary.json: ") + e.what());
  }
}

std::optional<double> RunFigures::get(const std::string& name) const {
  if (name == "min_h_over_sigma") {
    const auto a = get("min_h_over_sigma_thrust"), b = get("min_h_over_sigma_antithrust");
    if (a && b)
      return std::min(*a, *b);
    return a ? a : b;
  }
  for (const auto& [key, value] : values_) {
    if (key == name && std::isfinite(value))
      return value;
  }
  return std::nullopt;
}

}  // namespace pistondyn::design
