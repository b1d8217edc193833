#pragma once
/// \file
/// The skirt's ovality: the radial drop of the cold skirt section below its thrust-axis radius as
/// a function of the angle around the piston. Part of h_skirtProfile (SkirtProfile.h); positive
/// drop = a larger gap.
///
/// What is assumed (and checked): the section is symmetric about the thrust axis (phi -> -phi)
/// and about the pin axis (phi -> pi - phi), so the drop depends only on the angle psi in
/// [0, pi/2] between the node's radial direction and the thrust/anti-thrust axis,
/// psi = atan2(|sin phi|, |cos phi|), and both sides have the same ovality. The reference is the
/// thrust-axis diameter: drop(psi = 0) = 0.
///
/// Two ways to give it:
///
/// * Law (default; piston-drawing data "ovality Ov" and a shape coefficient k):
///       drop(phi) = (Ov / 4) [ (1 - cos 2 phi) + (k / 2) (1 - cos 4 phi) ]
///   Ov = D_thrust - D_pin is the diametral ovality [m] (drop(90 deg) = Ov/2 for every k);
///   k = 0 (default) is the pure elliptic law drop = (Ov/4)(1 - cos 2 phi) (to first order in
///   Ov/D the radius of an ellipse with diameters D and D - Ov). The cos 4 phi term changes the
///   flanks only: drop(45 deg) = (1 + k) Ov/4, i.e. k is the extra drop at 45 deg as a fraction
///   of the elliptic one. The drop rises monotonically from the thrust to the pin axis iff
///   |k| <= 1/2 (d drop/d phi = (Ov/2) sin 2phi (1 + 2k cos 2phi)); a larger |k| would put a
///   bump into the section and is rejected.
///   Where the law comes from, and what is not verified: piston drawings give the ovality as the
///   diametral difference Ov between the thrust and the pin direction (the usual definition of
///   out-of-roundness as D_max - D_min, e.g. https://www.eng-tips.com/viewthread.cfm?qid=1707),
///   with the elliptic law as the basic shape; a cos 4 phi term is described in the piston
///   makers' manuals (MAHLE GmbH (ed.), "Pistons and engine testing", Vieweg+Teubner 2012; KS
///   Kolbenschmidt piston handbooks), whose text was not available: the exact form of their
///   cos 4 phi term and the normalisation of its coefficient are NOT checked, and k above is
///   this module's own normalisation. Convert a drawing's coefficient through its 45-degree drop,
///   k = 4 drop(45 deg) / Ov - 1, or give the drop as a table.
/// * Table: angle from the thrust axis psi [rad] vs radial drop [m], one quadrant: the first
///   angle 0 with drop 0, strictly increasing, the last <= pi/2 and covering the side's largest
///   psi (half its arc width). The table is read with PCHIP after reflecting it about psi = 0
///   (and about psi = pi/2 when it ends there), so the interpolant is even about the axes and
///   C1 across them (zero slope on the thrust axis, as the symmetry demands).

#include <Eigen/Core>

#include "pistondyn/skirt/InterpolatedTable.h"

namespace pistondyn::skirt {

/// How the ovality is given.
enum class OvalityModel {
  Law,    ///< diametral ovality and cos 4 phi coefficient (default)
  Table,  ///< tabulated drop over one quadrant
};

/// The section shape of the skirt (the documentation of Ovality.h gives both forms).
struct OvalityParameters {
  OvalityModel model = OvalityModel::Law;  ///< default Law
  /// Law: diametral ovality Ov = D_thrust - D_pin [m], finite; default 0 (round skirt). A
  /// negative value is a section wider along the pin axis.
  double diametralOvality_m = 0.0;
  /// Law: coefficient k of the cos 4 phi term [-], |k| <= 0.5; default 0 (elliptic).
  double cos4Coefficient = 0.0;
  /// Table: angle from the thrust axis [rad] (0 first, increasing, <= pi/2) and drop [m].
  Eigen::VectorXd tableAngle_rad;
  Eigen::VectorXd tableRadialDrop_m;  ///< see tableAngle_rad
};

/// The ovality gap term: radial drop against the angle (law or table).
class Ovality {
 public:
  /// No ovality.
  Ovality() = default;

  /// Inputs:
  ///   parameters           law or table
  ///   maxAngleFromAxis_rad the largest psi the skirt side reaches (half its arc width) [rad]:
  ///                        a table must cover it
  /// Throws std::invalid_argument naming the member.
  Ovality(const OvalityParameters& parameters, double maxAngleFromAxis_rad);

  /// Radial drop [m] at the angle phi_rad [rad] (any side; folded by the symmetries).
  double calcDrop_m(double phi_rad) const;

 private:
  OvalityModel model_ = OvalityModel::Law;
  double ovality_m_ = 0.0, k_ = 0.0;
  InterpolatedTable table_;  ///< reflected about 0 (and pi/2)
};

}  // namespace pistondyn::skirt
