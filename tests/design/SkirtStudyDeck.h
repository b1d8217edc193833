#pragma once
// The gasoline example deck's lubricated skirt made cheap for design-loop tests: 16 x 12
// nodes per side, one cycle (not until periodic), the fast flooded setting of README.md
// ("Benchmarks": BDF3 at 1 deg, Jacobian reuse, Reynolds cavitation, fully flooded), a 2 deg
// output step: about 0.2 s per run.

#include <string>

namespace pistondyn_test {

inline std::string fastSkirtSet(const std::string& indent = "  ") {
  std::string s;
  for (const char* kv :
       {"simulation.cycles: 1", "simulation.until_periodic: false",
        "liner.grid.nodes_circumferential: 16", "liner.grid.nodes_axial: 12",
        "simulation.stepper_order: 3", "simulation.max_step_deg: 1", "simulation.pose_tolerance_nm: 10",
        "liner.film.fallback_to_reference: false", "simulation.jacobian_reuse_steps: 20",
        "liner.film.cavitation: reynolds", "liner.oil_supply.film_um: null",
        "liner.oil_supply.fully_flooded: true", "simulation.output_step_deg: 2"})
    s += indent + kv + "\n";
  return s;
}

// The gasoline deck's cold shapes (its expansion coefficients at 0, no thermal growth): the
// cold clearance is the running one, so the clearance ranges of the design tests (25-60 um)
// all fit the bore; the tests' problems were set on these shapes.
inline std::string gasolineColdShapesSet(const std::string& indent = "  ") {
  return indent + "liner.thermal.piston_expansion_per_K: 0\n" + indent +
         "liner.thermal.liner_expansion_per_K: 0\n";
}

// A Briggs & Stratton barrel whose minimum-clearance line is 6.8 mm below the pin
// (tests/design/data): the rigid skirt rocks onto its lower edge after firing TDC, and the
// tilt in the TDC windows tells the oil temperature from the clearance. On the example's own
// barrel (3 mm below the pin) the film-borne tilt sees only their combination.
inline std::string briggsEdgeRockingBarrelSet(const std::string& indent = "  ") {
  return indent + "liner.skirt_profile.axial_profile_file: " +
         std::string(PISTONDYN_SOURCE_DIR) + "/tests/design/data/briggs_barrel_6p8mm_below_pin.csv\n";
}

}  // namespace pistondyn_test
