#pragma once
/// \file
/// Plain description of one cylinder's crank train: geometry, mass properties, crank
/// drive. Everything in SI. Input decks in engineering units are converted at the edge
/// (pistondyn::io); nothing here parses files.
///
/// Frames (README "Frames and signs"): ground y along the cylinder axis towards the
/// head, x perpendicular to the pin axis towards the THRUST side, z along the pin axis
/// (x, y, z right-handed). The crank axis is the ground z axis through the origin and
/// the crank turns counter-clockwise about +z, which puts the thrust side at +x.
/// Crank angle 0 = firing TDC (piston at its highest point at the start of expansion).

#include <string>

namespace pistondyn::mbd {

/// How the piston pin is held. Decides which Simbody mobilizers connect rod, pin, piston.
enum class PinJoint {
  Floating,       ///< pin turns freely in both the small end and the piston bosses
  FixedInRod,     ///< pin clamped in the small end, turns in the piston bosses
  FixedInPiston,  ///< pin clamped in the piston bosses, turns in the small end
};

/// Crank-train geometry [m].
struct CrankTrainGeometry {
  double crankRadius_m = 0.0;      ///< r = stroke / 2 (for zero offsets) [m], required > 0
  double conrodLength_m = 0.0;     ///< big-end to small-end centre distance L [m], required > r
  double pinOffset_m = 0.0;        ///< pin axis x relative to the piston axis, + towards thrust [m]
  double crankOffset_m = 0.0;      ///< cylinder axis x relative to the crank axis (desaxe),
                                   ///< + towards thrust [m]
  double compressionRatio = 10.0;  ///< (V_d + V_c) / V_c [-], required > 1
};

/// Piston geometry [m].
struct PistonGeometry {
  double bore_m = 0.0;               ///< cylinder bore diameter [m], required > 0
  double compressionHeight_m = 0.0;  ///< pin axis to crown top along the piston axis [m], > 0
  double skirtLength_m = 0.0;        ///< axial length of the skirt [m], > 0
  double skirtTopAbovePin_m = 0.0;   ///< skirt top edge above the pin axis [m] (may be < 0)
};

/// Mass properties of one body. Only the in-plane (about z) inertia affects the planar
/// crank-train motion; Simbody still needs a full, physically valid inertia, so the
/// other two principal moments are taken equal to Izz (a documented, harmless choice:
/// they only enter out-of-plane reaction moments that are not reported).
struct PlanarMassProperties {
  double mass_kg = 0.0;  ///< > 0
  double comX_m = 0.0;   ///< centre of mass in the body frame [m]
  double comY_m = 0.0;   ///< centre of mass in the body frame [m]
  double inertiaZZ_kgm2 =
      0.0;  ///< moment of inertia about the z axis through the COM [kg m^2], >= 0
};

/// Body frames:
///   crank  : origin on the crank axis, +y towards the crank pin
///   conrod : origin at the big-end centre, +y towards the small end
///   pin    : origin at the pin centre
///   piston : origin on the piston axis at the pin-axis height, +y towards the crown
struct CrankTrainMassProperties {
  PlanarMassProperties crank;   ///< crank throw incl. counterweights (COM often at comY < 0)
  PlanarMassProperties conrod;  ///< connecting rod
  PlanarMassProperties pin;     ///< COM at the pin centre; comX/comY must be 0
  PlanarMassProperties piston;  ///< piston without pin and rings' gas loads
};

/// How the crank is driven.
struct CrankDrive {
  /// Prescribed constant speed, or a free crank with flywheel and load torque.
  enum class Mode {
    ConstantSpeed,  ///< theta = theta0 + omega t exactly (a Simbody Motion)
    Free,           ///< free crank: flywheel inertia, constant load torque
  };
  Mode mode = Mode::ConstantSpeed;    ///< default ConstantSpeed
  double speed_radps = 0.0;           ///< prescribed (ConstantSpeed) or initial (Free) speed, > 0
  double flywheelInertia_kgm2 = 0.0;  ///< added to the crank about its axis (Free mode) [kg m^2]
  double loadTorque_Nm = 0.0;         ///< constant torque opposing rotation (Free mode) [N m]
};

/// One cylinder's crank train, SI (the documentation of EngineDescription.h gives the frames).
struct EngineDescription {
  std::string name;                        ///< label in outputs
  CrankTrainGeometry geometry;             ///< crank radius, rod, offsets, compression ratio
  PistonGeometry piston;                   ///< bore, compression height, skirt
  CrankTrainMassProperties mass;           ///< mass properties of the four bodies
  PinJoint pinJoint = PinJoint::Floating;  ///< how the pin is held; default Floating
  /// Whether the piston may move along the pin axis (tertiary motion). On (default): the
  /// small-end slider is a Cylinder joint (rotation + translation along the pin axis), and
  /// the liner element must hold the piston along z. Off: a Pin joint, no such mobility
  /// (the thesis' parameter study).
  bool tertiaryMotion = true;
  CrankDrive drive;               ///< crank drive
  double gravity_mps2 = 9.80665;  ///< acts along -y (cylinder vertical, head up) [m/s^2], >= 0
};

/// Throws std::invalid_argument naming the first offending member when the description
/// is not physically meaningful (non-positive lengths, rod shorter than crank radius plus
/// offset, negative masses, ...).
void validate(const EngineDescription& engine);

}  // namespace pistondyn::mbd
