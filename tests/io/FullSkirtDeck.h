#pragma once
// The gasoline example deck with a liner section that sets every key of the lubricated
// skirt away from its default, tables included (tests/io: SkirtDeck, DeckKeys).

#include <fstream>
#include <string>

#include "ScratchDeck.h"

namespace pistondyn_test {

// A section with every key away from its default, tables included.
class FullSkirtDeck : public SkirtScratchDeck {
 protected:
  void SetUp() override {
    SkirtScratchDeck::SetUp();
    writeFile("ovality.csv", "angle_from_thrust_deg,radial_drop_um\n0,0\n45,60\n90,150\n");
    writeFile("bore.csv",
              "# two orders\ndepth_mm,order,amplitude_um,phase_deg\n0,0,2,0\n0,2,5,30\n"
              "60,2,3,45\n120,0,4,0\n120,2,1,90\n");
    writeFile("piston_t.csv", "height_above_pin_mm,temperature_degC\n-18,60\n12,70\n");
    writeFile("liner_t.csv", "depth_mm,temperature_degC\n0,130\n140,100\n");
    writeFile("supply.csv", "crank_angle_deg,film_um\n0,0.5\n360,2\n540,1\n");
    // The example's FE skirt compliance (examples/fe/gasoline_1400_2000rpm).
    const std::string fe =
        std::string(PISTONDYN_SOURCE_DIR) + "/examples/fe/gasoline_1400_2000rpm/";
    writeFile("skirt_compliance.mtx", readFile(fe + "skirt_compliance.mtx"));
    writeFile("skirt_nodes.csv", readFile(fe + "skirt_nodes.csv"));
    std::string text = readFile(deck());
    text = replaceSection(text, "liner", R"(liner:
  model: lubricated_skirt
  cold_radial_clearance_um: 60
  reference_temperature_degC: 25
  grid: {arc_width_deg: 90, nodes_circumferential: 20, nodes_axial: 14, axial_clustering: 1,
         circumferential_clustering: 1.5}
  skirt_profile:
    axial_profile_file: skirt_profile.csv
    mirrored: true
    ovality_file: ovality.csv
  bore_distortion:
    file: bore.csv
    liner_top_above_crank_mm: 250
  thermal:
    piston_expansion_per_K: 2.1e-5
    piston_temperature_file: piston_t.csv
    liner_expansion_per_K: 1.1e-5
    liner_temperature_file: liner_t.csv
  oil:
    kinematic_viscosity_1_mm2_per_s: 60
    viscosity_temperature_1_degC: 40
    kinematic_viscosity_2_mm2_per_s: 10
    viscosity_temperature_2_degC: 100
    density_kg_per_m3: 850
    temperature_degC: 90
  oil_supply: {film_file: supply.csv}
  roughness: {liner_rq_um: 0.3, skirt_rq_um: 0.5, peklenik: 2}
  asperity:
    roughness_parameter: 0.05
    sigma_over_beta: 0.002
    liner_youngs_modulus_GPa: 110
    liner_poisson_ratio: 0.27
    skirt_youngs_modulus_GPa: 70
    skirt_poisson_ratio: 0.32
    friction_coefficient: 0.12
    regularisation_speed_mm_per_s: 2
    wear_coefficient_mm3_per_N_m: 1e-6
  film: {cavitation: reynolds, solver: reference_gauss_seidel, tolerance: 1e-7,
         faces: linear_gap, fill_fraction_flux: second_order, fallback_to_reference: false}
  tertiary_motion: true
  pin_retainer_play_mm: 0.3
  pin_retainer_stiffness_N_per_mm: 1e4
  field_dumps: {crank_angles_deg: [0, 370]}
  elastic_skirt:
    compliance_file: skirt_compliance.mtx
    nodes_file: skirt_nodes.csv
    tolerance_nm: 2
    relative_tolerance: 2e-3
    max_iterations: 40

)");
    std::ofstream(deck()) << text;
  }
};

}  // namespace pistondyn_test
