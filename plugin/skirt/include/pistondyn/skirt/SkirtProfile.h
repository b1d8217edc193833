#pragma once
/// \file
/// h_skirtProfile (thesis §2.1, h_2): the cold skirt's shape as a gap term,
///
///   h_skirtProfile(phi, y) = axial profile drop(y) + ovality drop(phi)      [m, + opens the gap]
///
/// (AxialProfile.h, Ovality.h). Fixed to the skirt: it never changes during a run, so its rate at
/// a skirt node is 0 and GapAssembly evaluates it once.

#include <Eigen/Core>

#include "pistondyn/skirt/AxialProfile.h"
#include "pistondyn/skirt/Ovality.h"
#include "pistondyn/skirt/SkirtSideGrid.h"

namespace pistondyn::skirt {

/// The skirt profile: axial profile and ovality.
struct SkirtProfileParameters {
  AxialProfileParameters axial;  ///< barrel profile over the height; default cylindrical
  OvalityParameters ovality;     ///< section shape; default round (elliptic law with Ov = 0)
};

/// The skirt profile of one side.
class SkirtProfile {
 public:
  /// Inputs: the profile data and the side it is read on (its height range must be covered by
  /// the axial table, its angles by an ovality table).
  /// Throws std::invalid_argument naming the member.
  SkirtProfile(const SkirtProfileParameters& parameters, const SkirtSideGrid& grid);

  const AxialProfile& getAxialProfile() const { return axial_; }  ///< the barrel part
  const Ovality& getOvality() const { return ovality_; }          ///< the section part

  /// h_skirtProfile at (phi_rad [rad], y_m [m]) [m].
  double calcGap_m(double phi_rad, double y_m) const {
    return axial_.calcDrop_m(y_m) + ovality_.calcDrop_m(phi_rad);
  }

  /// h_skirtProfile at every node of grid (the grid it was built for).
  /// Outputs: gap_m (nodeCount() entries, preallocated) [m].
  void calcField(const SkirtSideGrid& grid, Eigen::Ref<Eigen::ArrayXd> gap_m) const;

 private:
  AxialProfile axial_;
  Ovality ovality_;
};

}  // namespace pistondyn::skirt
