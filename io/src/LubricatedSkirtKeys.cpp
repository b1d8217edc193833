// The keys of the lubricated skirt's liner section (LubricatedSkirtDeck.h): the table its
// factory reads them by (LubricatedSkirtDeck.cpp) and the reference is generated from.
// The valid ranges are tight enough to catch the usual unit slips (a clearance in mm, an
// angle in radians, a modulus in MPa): outside them the error names the unit that fits.

#include "pistondyn/io/LubricatedSkirtDeck.h"

namespace pistondyn::io {

const DeckKeyTable& getLubricatedSkirtDeckKeys() {
  using Q = Quantity;
  using K = DeckKey;
  static const DeckKeyTable table(
      "`liner.model: lubricated_skirt`",
      "`plugin::LubricatedSkirtElement`, read by `io/LubricatedSkirtDeck.h`: oil film (average "
      "Reynolds equation with Patir–Cheng flow factors, cavitation) and Greenwood–Tripp "
      "asperity contact on a thrust and an anti-thrust sector of the skirt. Ranges catch unit "
      "slips (a clearance in mm, an angle in radians, a modulus in MPa). Cross-checks against "
      "the engine are deck errors naming the key: the profile table must cover the skirt "
      "(mirrored: minus its heights), an ovality table the grid's half arc, and the hot "
      "running clearance (`skirt::calcHotRunningClearance`) must not be negative. CSV tables: "
      "`#` comment lines allowed, a header of exactly the named columns (a column the reader "
      "does not take is an error, like an unknown key), finite numbers; every problem names "
      "the table's file and line and the deck key that named it.",
      {
          K::number("liner.cold_radial_clearance_um", Q::Length)
              .require()
              .within(Bounds::between(1, 500))
              .means("cold radial clearance at the profile's zero-drop point, centred piston"),
          K::number("liner.reference_temperature_degC", Q::Temperature)
              .byDefault(20.0)
              .within(Bounds::between(-60, 200))
              .means("temperature of the cold data (clearance, profile, bore distortion)"),
          K::number("liner.grid.arc_width_deg", Q::Angle)
              .byDefault(80.0)
              .within(Bounds{10.0, 180.0, false, true})
              .because("180 deg or more makes each side's grid wider than the skirt's side (the "
                       "thrust and anti-thrust grids would overlap)")
              .means("arc of each side's film grid; 180 or more would overlap the other side"),
          K::wholeNumber("liner.grid.nodes_circumferential", 3, 1000)
              .byDefault(64.0)
              .means("film grid nodes per side around the skirt"),
          K::wholeNumber("liner.grid.nodes_axial", 3, 1000)
              .byDefault(48.0)
              .means("film grid nodes per side along the skirt"),
          K::number("liner.grid.axial_clustering")
              .byDefault(0.0)
              .within(Bounds::between(0, 10))
              .means("tanh clustering of the axial nodes towards the skirt edges (2–3 strong)"),
          K::number("liner.grid.circumferential_clustering")
              .byDefault(0.0)
              .within(Bounds::between(0, 10))
              .means("sinh clustering of the circumferential nodes towards each side's centre "
                     "line, where the ovality puts the contact (2: 0.55× the uniform spacing "
                     "there, 2.1× at the edges)"),
          K::file("liner.skirt_profile.axial_profile_file",
                  "CSV `height_above_pin_mm, radial_drop_um`")
              .byDefault("cylindrical")
              .means("barrel profile (PCHIP, never extrapolated); heights strictly increasing "
                     "within ±2000 mm, drops within ±2000 µm, ≥ 2 rows, covering the skirt"),
          K::onOff("liner.skirt_profile.mirrored")
              .byDefault(0.0)
              .means("read the profile at −y (minimum-clearance point moved across the pin "
                     "axis)"),
          K::number("liner.skirt_profile.ovality_diametral_um", Q::Length)
              .byDefault(0.0)
              .within(Bounds::between(-2000, 2000))
              .means("ovality law: D_thrust − D_pin"),
          K::number("liner.skirt_profile.ovality_cos4_coefficient")
              .byDefault(0.0)
              .within(Bounds::between(-0.5, 0.5))
              .means("ovality law's cos 4φ coefficient k (`skirt/Ovality.h`)"),
          K::file("liner.skirt_profile.ovality_file", "CSV `angle_from_thrust_deg, radial_drop_um`")
              .byDefault("the law")
              .means("instead of the law: one quadrant, first row 0, 0, increasing, ≤ 90°, "
                     "covering half the arc, drops within ±2000 µm"),
          K::file("liner.bore_distortion.file", "CSV `depth_mm, order, amplitude_um, phase_deg`")
              .byDefault("ideal cylinder")
              .means("Fourier orders 0–12 along the bore; depth below the liner top in [0, "
                     "2000] mm, strictly increasing within each order; amplitudes within ±2000 "
                     "µm, phases in [−360, 360]°"),
          K::number("liner.bore_distortion.liner_top_above_crank_mm", Q::Length)
              .byDefault("crown at TDC")
              .within(Bounds::between(0, 2000))
              .means("liner-top height above the crank axis (depths of bore distortion and "
                     "liner temperature)"),
          K::number("liner.thermal.piston_expansion_per_K", Q::ThermalExpansion)
              .byDefault("none")
              .within(Bounds::between(0, 1e-4))
              .means("skirt's α; required with, and only with, the next key"),
          K::file("liner.thermal.piston_temperature_file",
                  "CSV `height_above_pin_mm, temperature_degC`")
              .byDefault("no growth")
              .means("skirt temperature (linear between rows, constant beyond), above −273.15 "
                     "°C and below 1000 °C; heights strictly increasing within ±2000 mm"),
          K::number("liner.thermal.liner_expansion_per_K", Q::ThermalExpansion)
              .byDefault("none")
              .within(Bounds::between(0, 1e-4))
              .means("liner's α; required with, and only with, the next key"),
          K::file("liner.thermal.liner_temperature_file", "CSV `depth_mm, temperature_degC`")
              .byDefault("no growth")
              .means("bore wall temperature against the depth below the liner top (strictly "
                     "increasing, within ±2000 mm)"),
          K::choice("liner.oil.grade", {"0W-20", "0W-30", "5W-30", "5W-40", "10W-40", "15W-40"})
              .byDefault("— (or a user oil)")
              .means("data-sheet oil (`lubrication/OilGrades.h`); or instead a user oil by the "
                     "next keys"),
          K::text("liner.oil.name").byDefault("user oil").means("a user oil's label"),
          K::number("liner.oil.kinematic_viscosity_1_mm2_per_s", Q::KinematicViscosity)
              .within(Bounds{0.0, 1e5, true})
              .means("a user oil: ν at the first temperature (Walther / ASTM D341); required "
                     "for a user oil"),
          K::number("liner.oil.viscosity_temperature_1_degC", Q::Temperature)
              .byDefault(40.0)
              .within(Bounds::between(-60, 250))
              .means("a user oil: the temperature of the first viscosity"),
          K::number("liner.oil.kinematic_viscosity_2_mm2_per_s", Q::KinematicViscosity)
              .within(Bounds{0.0, 1e5, true})
              .means("a user oil: ν at the second temperature; required for a user oil"),
          K::number("liner.oil.viscosity_temperature_2_degC", Q::Temperature)
              .byDefault(100.0)
              .within(Bounds::between(-60, 250))
              .means("a user oil: the temperature of the second viscosity"),
          K::number("liner.oil.density_kg_per_m3", Q::Density)
              .within(Bounds::between(500, 2000))
              .means("a user oil's density; required for a user oil"),
          K::number("liner.oil.density_temperature_degC", Q::Temperature)
              .byDefault(15.0)
              .within(Bounds::between(-60, 250))
              .means("the temperature of that density"),
          K::number("liner.oil.temperature_degC", Q::Temperature)
              .byDefault(105.0)
              .within(Bounds::between(-60, 250))
              .means("film temperature, inside the oil's valid range (`summary.json` adds the "
                     "resulting `film_dynamic_viscosity_Pas`)"),
          K::onOff("liner.oil_supply.fully_flooded")
              .means("exactly one of these four: fully flooded skirt …"),
          K::number("liner.oil_supply.film_um", Q::Length)
              .within(Bounds{0.0, 1000.0, true})
              .means("… a constant oil film on the liner ahead of the skirt …"),
          K::file("liner.oil_supply.film_file", "CSV `crank_angle_deg, film_um`")
              .means("… or a periodic table over the cycle: angles strictly increasing in [0, "
                     "720), film in (0, 1000] µm, ≥ 2 rows …"),
          K::number("liner.oil_supply.liner_transport.ring_height_above_pin_mm", Q::Length)
              .within(Bounds::between(0, 500))
              .means("… or the oil carried on the liner (`skirt/LinerOilFilm.h`; needs "
                     "`liner.film.cavitation: mass_conserving`): the oil-control ring's lower "
                     "edge above the pin axis, at least the skirt's top; required for it"),
          K::number("liner.oil_supply.liner_transport.ring_film_um", Q::Length)
              .within(Bounds{0.0, 100.0, true})
              .means("film the oil-control ring leaves on the liner it passes (one of this and "
                     "the next key)"),
          K::file("liner.oil_supply.liner_transport.ring_film_file",
                  "CSV `crank_angle_deg, film_um`")
              .means("the ring's film over the cycle: angles strictly increasing in [0, 720), "
                     "film in (0, 100] µm, ≥ 2 rows"),
          K::number("liner.oil_supply.liner_transport.flooded_below_mm", Q::Length)
              .byDefault("none")
              .within(Bounds::between(-2000, 2000))
              .means("crankcase splash: the liner below this bore height above the crank axis "
                     "is flooded (held at max_film_um)"),
          K::number("liner.oil_supply.liner_transport.splash_rate_mm_per_s", Q::Speed)
              .byDefault(0.0)
              .within(Bounds::between(0, 1000))
              .means("crankcase splash as a rate: the film below splash_below_mm grows by it, up "
                     "to max_film_um"),
          K::number("liner.oil_supply.liner_transport.splash_below_mm", Q::Length)
              .byDefault("none")
              .within(Bounds::between(-2000, 2000))
              .means("bore height above the crank axis below which the splash rate acts; "
                     "required with a splash rate"),
          K::number("liner.oil_supply.liner_transport.max_film_um", Q::Length)
              .byDefault(50.0)
              .within(Bounds{0.0, 1000.0, true})
              .means("a thicker liner film drains to the crankcase; the flooded film"),
          K::number("liner.oil_supply.liner_transport.skirt_share")
              .byDefault(0.5)
              .within(Bounds::between(0, 1))
              .means("share of the film's outflow at the trailing edge that leaves on the skirt "
                     "(lost to the crankcase); the rest stays on the liner"),
          K::number("liner.oil_supply.liner_transport.initial_film_um", Q::Length)
              .byDefault(1.0)
              .within(Bounds::between(0, 1000))
              .means("the liner's film at the start, outside the skirt and the flooded region"),
          K::number("liner.roughness.liner_rq_um", Q::Length)
              .require()
              .within(Bounds::between(0, 20))
              .means("Rq of the liner; entered once for the flow factors and the contact"),
          K::number("liner.roughness.skirt_rq_um", Q::Length)
              .require()
              .within(Bounds::between(0, 20))
              .means("Rq of the skirt; the composite with the liner's at least 0.01 µm"),
          K::number("liner.roughness.peklenik")
              .byDefault(1.0)
              .within(Bounds{0.0, 100.0, true})
              .means("Peklenik number γ of both surfaces"),
          K::number("liner.asperity.roughness_parameter")
              .byDefault(0.04)
              .within(Bounds{0.0, 1.0, true})
              .means("ηβσ of Greenwood–Tripp"),
          K::number("liner.asperity.sigma_over_beta")
              .byDefault(0.001)
              .within(Bounds{0.0, 1.0, true})
              .means("σ/β of Greenwood–Tripp"),
          K::number("liner.asperity.liner_youngs_modulus_GPa", Q::Pressure)
              .byDefault(115.0)
              .within(Bounds::between(1, 1000))
              .means("liner's elastic modulus"),
          K::number("liner.asperity.liner_poisson_ratio")
              .byDefault(0.26)
              .within(Bounds::between(0, 0.49))
              .means("liner's Poisson ratio"),
          K::number("liner.asperity.skirt_youngs_modulus_GPa", Q::Pressure)
              .byDefault(75.0)
              .within(Bounds::between(1, 1000))
              .means("skirt's elastic modulus"),
          K::number("liner.asperity.skirt_poisson_ratio")
              .byDefault(0.33)
              .within(Bounds::between(0, 0.49))
              .means("skirt's Poisson ratio"),
          K::number("liner.asperity.friction_coefficient")
              .byDefault(0.1)
              .within(Bounds::between(0, 1))
              .means("boundary friction f_dry"),
          K::number("liner.asperity.regularisation_speed_mm_per_s", Q::Speed)
              .byDefault(1.0)
              .within(Bounds{0.0, 1000.0, true})
              .means("Coulomb friction smoothed below this sliding speed"),
          K::number("liner.asperity.wear_coefficient_mm3_per_N_m", Q::WearCoefficient)
              .byDefault(0.0)
              .within(Bounds::between(0, 1))
              .means("Archard k/H of the liner; 0 = no wear"),
          K::choice("liner.film.cavitation", {"mass_conserving", "reynolds"})
              .byDefault("mass_conserving")
              .means("JFO / Elrod–Adams, or Swift–Stieber (the thesis')"),
          K::choice("liner.film.faces", {"nodal_mean", "linear_gap"})
              .byDefault("nodal_mean")
              .means("film face conductance: mean of the nodes', or exact for a gap linear "
                     "between them (plugin/README.md, \"Face values\")"),
          K::choice("liner.film.fill_fraction_flux", {"upwind", "second_order"})
              .byDefault("upwind")
              .means("fill fraction of the film's Couette faces (mass-conserving): the "
                     "upwind node's, or limited second order (plugin/README.md, \"Fill-"
                     "fraction flux\")"),
          K::choice("liner.film.solver", {"fast", "reference_gauss_seidel"})
              .byDefault("fast")
              .means("film solver (active set with CG/GMRES, or the thesis' projected "
                     "Gauss–Seidel)"),
          K::number("liner.film.tolerance")
              .byDefault(1e-8)
              .within(Bounds::between(1e-14, 1e-3))
              .means("film solver's relative residual"),
          K::number("liner.film.derivative_tolerance")
              .byDefault(1e-6)
              .within(Bounds::between(1e-14, 1e-2))
              .means("relative accuracy of the squeeze-derivative solves (the stepper's "
                     "Jacobian only)"),
          K::onOff("liner.film.fallback_to_reference")
              .byDefault(1.0)
              .means("fast solver: when its active set does not settle, finish with the "
                     "reference Gauss–Seidel (counted in summary.json's film_fallbacks); off: "
                     "the solve fails at once and the stepper retries a shorter step, cheaper "
                     "where the fallback cannot converge either (BENCHMARKS.md)"),
          K::choice("liner.film.fill_fraction_history", {"backward_euler", "bdf2"})
              .byDefault("bdf2")
              .means("mass-conserving model: order of the fill fraction's storage term in time "
                     "(BDF2 over the last two accepted steps)"),
          K::onOff("liner.parallel_sides")
              .byDefault(1.0)
              .means("solve the thrust and anti-thrust films (and elastic couplings) on two "
                     "threads: the same results, faster where a second core is free (1.3-1.6x; "
                     "BENCHMARKS.md)"),
          K::onOff("liner.tertiary_motion")
              .byDefault(0.0)
              .means("motion along the pin axis; sets both the element and the crank train's "
                     "mobility"),
          K::number("liner.pin_retainer_play_mm", Q::Length)
              .byDefault(0.5)
              .within(Bounds{0.0, 10.0, true})
              .means("tertiary motion: free axial play each way"),
          K::number("liner.pin_retainer_stiffness_N_per_mm", Q::Stiffness)
              .byDefault(2e4)
              .within(Bounds{0.0, 1e9, true})
              .means("tertiary motion: retainer spring outside the play"),
          K::file("liner.elastic_skirt.compliance_file",
                  "Matrix Market `array` or `coordinate`, n x n [m/N]")
              .byDefault("rigid skirt")
              .means("radial compliance of the skirt on its structural grid (`io/"
                     "ComplianceInput.h`, e.g. `examples/fe/`); with nodes_file it switches "
                     "the elastic skirt on: film pressure and deformation converged together "
                     "at every force evaluation (`skirt/ElasticCoupling.h`)"),
          K::file("liner.elastic_skirt.nodes_file", "CSV `node, phi_deg, y_mm[, gas_...]`")
              .byDefault("rigid skirt")
              .means("node table of compliance_file (piston frame: heights above the pin); "
                     "its grid must cover both film grids. Its optional gas column (radial "
                     "displacement per unit cylinder pressure) is applied with gas_deformation"),
          K::file("liner.elastic_skirt.liner_compliance_file",
                  "Matrix Market `array` or `coordinate`, n x n [m/N]")
              .byDefault("rigid liner")
              .means("radial compliance of the liner on its structural grid (e.g. `examples/"
                     "fe/*/liner_compliance.mtx`); with liner_nodes_file and the elastic skirt "
                     "the liner deforms too, in series with the skirt at the piston's height "
                     "(`skirt/ElasticCoupling.h`, \"The liner\"; schemes modal and aitken)"),
          K::file("liner.elastic_skirt.liner_nodes_file", "CSV `node, phi_deg, y_mm`")
              .byDefault("rigid liner")
              .means("node table of liner_compliance_file (heights above the crank axis, a "
                     "full circle, no gas column); its heights must cover the skirt over the "
                     "stroke"),
          K::number("liner.elastic_skirt.tolerance_nm", Q::Length)
              .byDefault(1.0)
              .within(Bounds{0.0, 1000.0, true})
              .means("elastic coupling converged when the deformation changes by at most "
                     "max(this, relative_tolerance x smallest film) on the film grid"),
          K::number("liner.elastic_skirt.relative_tolerance")
              .byDefault(1e-3)
              .within(Bounds::between(0, 0.1))
              .means("elastic coupling tolerance relative to the smallest film thickness"),
          K::number("liner.elastic_skirt.deformation_relative_tolerance")
              .byDefault(1e-3)
              .within(Bounds::between(0, 0.1))
              .means("elastic coupling tolerance relative to the largest deformation (the "
                     "floor where a slap presses the skirt into the asperities)"),
          K::wholeNumber("liner.elastic_skirt.max_iterations", 1, 10000)
              .byDefault(60.0)
              .means("film evaluations per side and force evaluation before the run stops "
                     "with an error (never silent)"),
          K::choice("liner.elastic_skirt.scheme", {"aitken", "newton", "modal"})
              .byDefault("modal")
              .means("elastic coupling iteration (skirt/ElasticCoupling.h): Aitken-relaxed "
                     "fixed point, inexact Newton (GMRES on film evaluations, preconditioned "
                     "by the film's local pressure-gap stiffness), or modal Newton (the "
                     "compliance's largest modes, the film's exact squeeze derivatives of them "
                     "with squeeze_rate; the one that carries whole cycles)"),
          K::wholeNumber("liner.elastic_skirt.modes", 1, 1000)
              .byDefault(20.0)
              .means("scheme modal: modes of each side's compliance that carry the "
                     "deformation (the run's summary reports the share of the compliance "
                     "kept)"),
          K::wholeNumber("liner.elastic_skirt.modal_jacobian_reuse", 0, 1000)
              .byDefault(0.0)
              .means("scheme modal: solves over which the coupling may keep its Newton "
                     "Jacobian while it converges in at most two film evaluations; the first "
                     "evaluation of a solve then skips the modes' derivative solves (0: "
                     "sensitivities at every evaluation; BENCHMARKS.md)"),
          K::onOff("liner.elastic_skirt.gas_deformation")
              .byDefault(1.0)
              .means("the skirt also deforms under the cylinder pressure: the node table's "
                     "gas column times the gauge pressure of gas.cylinder_pressure_file "
                     "(nothing without that column)"),
          K::onOff("liner.elastic_skirt.squeeze_rate")
              .byDefault(1.0)
              .means("the film's squeeze term includes the elastic deformation's rate "
                     "(backward Euler over the step; mass-conserving film only)"),
          K::onOff("liner.elastic_skirt.exact_static_derivative")
              .byDefault(1.0)
              .means("scheme modal: the film's exact pressure-gap derivative of each mode "
                     "shape in the Newton Jacobian (one assembly pair and back-substitution "
                     "per mode); off: the local estimate 3p/h"),
          K::numberList("liner.field_dumps.crank_angles_deg", Q::Angle)
              .byDefault("none")
              .within(Bounds{0.0, 720.0, false, true})
              .means("output crank angles of the last cycle at which the nodal fields are "
                     "written (`field_dump_<angle>deg_{thrust,antithrust}.csv`); each once"),
      });
  return table;
}

}  // namespace pistondyn::io
