#pragma once
/// \file
/// The skirt's axial profile (barrel shape): the radial drop of the cold skirt below its reference
/// diameter as a function of the height above the pin axis, as a piston drawing gives it. Part of
/// h_skirtProfile (SkirtProfile.h). Positive drop = smaller skirt = a larger gap.
///
/// The table is read with PCHIP (InterpolatedTable.h: C1, exact at the rows, no overshoot, so a
/// measured profile gains no bumps between its rows). The reference point of the cold clearance
/// c0 (RigidGap.h) is the profile's zero-drop point; drawings give drops >= 0 from the largest
/// diameter, but any finite drop is accepted (a negative one is a point wider than the
/// reference).
///
/// Mirror switch: mirrored = true reads drop(-y) instead of drop(y), i.e. the profile mirrored
/// about the pin-axis height: the thesis' study of the original against the mirrored profile
/// (minimum-clearance point below vs above the pin) is this one switch.
///
/// Coverage: the table must cover the skirt's height range [y_bottom, y_top] (mirrored:
/// [-y_top, -y_bottom]); a profile is never extrapolated.

#include <Eigen/Core>

#include "pistondyn/skirt/InterpolatedTable.h"

namespace pistondyn::skirt {

/// The measured axial profile of the skirt (the table and its mirror switch).
struct AxialProfileParameters {
  /// Height above the pin axis [m], strictly increasing. Empty (default) = cylindrical skirt.
  Eigen::VectorXd height_m;
  /// Radial drop below the reference diameter at each height [m], finite; same length.
  Eigen::VectorXd radialDrop_m;
  /// Read drop(-y): the profile mirrored about the pin-axis height. Default false.
  bool mirrored = false;
};

/// The axial profile term: radial drop against height, PCHIP through the table (this file's
/// documentation).
class AxialProfile {
 public:
  /// A cylindrical skirt (no drop).
  AxialProfile() = default;

  /// Inputs:
  ///   parameters            the table and the mirror switch
  ///   skirtBottomHeight_m, skirtTopHeight_m   the skirt's height range [m] that must be covered
  /// Throws std::invalid_argument naming the member and row (non-increasing heights, sizes,
  /// non-finite values) or the range the table must cover.
  AxialProfile(const AxialProfileParameters& parameters, double skirtBottomHeight_m,
               double skirtTopHeight_m);

  /// Radial drop [m] at piston-frame height y_m [m] (mirrored: the table at -y_m).
  double calcDrop_m(double y_m) const { return table_.value(mirrored_ ? -y_m : y_m); }
  bool isCylindrical() const { return table_.empty(); }  ///< no table: no drop
  bool isMirrored() const { return mirrored_; }          ///< the table is read at -y

 private:
  InterpolatedTable table_;
  bool mirrored_ = false;
};

}  // namespace pistondyn::skirt
