#include "pistondyn/skirt/AxialProfile.h"

#include "Checks.h"

namespace pistondyn::skirt {

namespace {
const char* const kWhere = "AxialProfileParameters";
}

AxialProfile::AxialProfile(const AxialProfileParameters& parameters, double skirtBottomHeight_m,
                           double skirtTopHeight_m)
    : mirrored_(parameters.mirrored) {
  if (parameters.height_m.size() == 0 && parameters.radialDrop_m.size() == 0)
    return;  // cylindrical skirt
  table_ = InterpolatedTable(parameters.height_m, parameters.radialDrop_m, Interpolation::Pchip,
                             kWhere, "height_m", "m", "radialDrop_m", "m");
  // The heights of the table that the skirt reads.
  const double lo = mirrored_ ? -skirtTopHeight_m : skirtBottomHeight_m;
  const double hi = mirrored_ ? -skirtBottomHeight_m : skirtTopHeight_m;
  // A relative slack of 1e-12 of the skirt length forgives rounding of the range ends only.
  const double slack = 1e-12 * (skirtTopHeight_m - skirtBottomHeight_m);
  if (table_.firstAbscissa() > lo + slack || table_.lastAbscissa() < hi - slack)
    detail::fail(kWhere, "height_m covers [" + detail::str(table_.firstAbscissa()) + ", " +
                             detail::str(table_.lastAbscissa()) + "] m, but the skirt" +
                             (mirrored_ ? " with the mirrored profile" : "") + " needs [" +
                             detail::str(lo) + ", " + detail::str(hi) +
                             "] m (heights above the pin axis" +
                             (mirrored_ ? ", mirrored: minus the skirt's heights" : "") +
                             "); a profile is not extrapolated");
}

}  // namespace pistondyn::skirt
