#pragma once
/// \file
/// The liner model `lubricated_skirt` (plugin::LubricatedSkirtElement) read from a deck's
/// liner section; registered in every LinerRegistry by default. The keys, their units,
/// defaults and ranges: getLubricatedSkirtDeckKeys() (`pistondyn keys`, README.md); in short:
///
///   liner:
///     model: lubricated_skirt
///     cold_radial_clearance_um: 40        # required
///     reference_temperature_degC: 20
///     grid: {arc_width_deg: 80, nodes_circumferential: 64, nodes_axial: 48,
///            axial_clustering: 0, circumferential_clustering: 0}
///     skirt_profile: {axial_profile_file: profile.csv, mirrored: false,
///                     ovality_diametral_um: 0, ovality_cos4_coefficient: 0}  # or ovality_file
///     bore_distortion: {file: bore.csv, liner_top_above_crank_mm: ...}
///     thermal: {piston_expansion_per_K, piston_temperature_file, liner_expansion_per_K,
///               liner_temperature_file}
///     oil: {grade: 0W-30, temperature_degC: 105}    # or two kinematic viscosities
///     oil_supply: {film_um: 0.5}          # exactly one of fully_flooded, film_um, film_file
///     roughness: {liner_rq_um: 0.4, skirt_rq_um: 0.6, peklenik: 1}
///     asperity: {roughness_parameter, sigma_over_beta, *_youngs_modulus_GPa,
///                *_poisson_ratio, friction_coefficient, regularisation_speed_mm_per_s,
///                wear_coefficient_mm3_per_N_m}
///     film: {cavitation: mass_conserving, solver: fast, tolerance: 1e-8}
///     tertiary_motion: false              # also sets the crank train's pin-axis mobility
///     pin_retainer_play_mm: 0.5
///     pin_retainer_stiffness_N_per_mm: 2e4
///     field_dumps: {crank_angles_deg: [360, 380]}
///
/// Tables (CSV, '#' comments, a header of exactly the named columns):
///   axial profile     height_above_pin_mm, radial_drop_um      heights strictly increasing
///   ovality           angle_from_thrust_deg, radial_drop_um    0 first (drop 0), increasing,
///                                                               last <= 90
///   bore distortion   depth_mm, order, amplitude_um, phase_deg orders 0..12, depths strictly
///                                                               increasing within an order
///   piston temperature  height_above_pin_mm, temperature_degC
///   liner temperature   depth_mm, temperature_degC             above absolute zero
///   oil supply        crank_angle_deg, film_um                 angles in [0, 720), film > 0
///
/// Checks against the engine (deck errors naming the key, never a crash in the element):
/// the profile table covers the skirt (mirrored: minus its heights), an ovality table the
/// side's half arc, the arc stays below 180 deg (two sides that would overlap), and the hot
/// running clearance (skirt::calcHotRunningClearance) is not negative.

#include "pistondyn/io/DeckKeys.h"
#include "pistondyn/io/LinerRegistry.h"

namespace pistondyn::io {

/// The factory registered as "lubricated_skirt": reads the section, reports every problem
/// to it (file:line: liner.key: ...), and returns the maker of a plugin::LubricatedSkirtElement
/// with the model's needs (tertiary motion, stiffness, field dumps).
LinerModel readLubricatedSkirt(DeckSection& liner, const LinerDeckContext& context);

/// The keys of its section (liner.*, liner.model excepted: getEngineDeckKeys()).
const DeckKeyTable& getLubricatedSkirtDeckKeys();

}  // namespace pistondyn::io
