#include "pistondyn/skirt/Ovality.h"

#include <cmath>
#include <vector>

#include "Checks.h"

namespace pistondyn::skirt {

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
const char* const kWhere = "OvalityParameters";

void checkTable(const OvalityParameters& p, double maxAngle) {
  const Eigen::VectorXd& a = p.tableAngle_rad;
  const Eigen::VectorXd& d = p.tableRadialDrop_m;
  detail::requireIncreasing(kWhere, "tableAngle_rad", a, "rad", 2);
  detail::requireSameSize(kWhere, "tableRadialDrop_m", d.size(), "tableAngle_rad", a.size());
  detail::requireFiniteEntries(kWhere, "tableRadialDrop_m", d, "m");
  if (a[0] != 0.0)
    detail::fail(kWhere, detail::named("tableAngle_rad[0]", a[0], "rad") +
                             " must be 0: the table is one quadrant from the thrust axis (0) "
                             "towards the pin axis (pi/2); symmetry about both axes gives the "
                             "rest");
  if (d[0] != 0.0)
    detail::fail(kWhere, detail::named("tableRadialDrop_m[0]", d[0], "m") +
                             " must be 0: the ovality is the drop below the thrust-axis radius");
  const Eigen::Index last = a.size() - 1;
  if (!(a[last] <= kHalfPi * (1.0 + 1e-14)))
    detail::fail(kWhere, detail::named(detail::indexed("tableAngle_rad", last), a[last], "rad") +
                             " must be at most pi/2: the table is one quadrant, symmetry about "
                             "the pin axis gives the rest");
  if (a[last] < maxAngle * (1.0 - 1e-12))
    detail::fail(kWhere, "tableAngle_rad covers [0, " + detail::str(a[last]) +
                             "] rad, but the skirt side needs [0, " + detail::str(maxAngle) +
                             "] rad (half its arc width); an ovality table is not extrapolated");
}

}  // namespace

Ovality::Ovality(const OvalityParameters& parameters, double maxAngleFromAxis_rad)
    : model_(parameters.model) {
  if (model_ == OvalityModel::Law) {
    detail::requireFinite(kWhere, "diametralOvality_m", parameters.diametralOvality_m, "m");
    if (!(std::abs(parameters.cos4Coefficient) <= 0.5))
      detail::fail(kWhere, detail::named("cos4Coefficient", parameters.cos4Coefficient, "") +
                               " must be within [-0.5, 0.5]: beyond it the drop is not monotone "
                               "from the thrust axis to the pin axis (a bump in the section)");
    ovality_m_ = parameters.diametralOvality_m;
    k_ = parameters.cos4Coefficient;
    return;
  }
  checkTable(parameters, maxAngleFromAxis_rad);
  // Reflect about psi = 0 (and about pi/2 if the table reaches it) so that PCHIP sees the even
  // function and puts a zero slope on the axes.
  const Eigen::VectorXd& a = parameters.tableAngle_rad;
  const Eigen::VectorXd& d = parameters.tableRadialDrop_m;
  const Eigen::Index n = a.size();
  const bool reachesPinAxis = std::abs(a[n - 1] - kHalfPi) <= 1e-14 * kHalfPi;
  std::vector<double> x, f;
  for (Eigen::Index k = n - 1; k >= 1; --k) {
    x.push_back(-a[k]);
    f.push_back(d[k]);
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    x.push_back(k == n - 1 && reachesPinAxis ? kHalfPi : a[k]);
    f.push_back(d[k]);
  }
  if (reachesPinAxis)
    for (Eigen::Index k = n - 2; k >= 0; --k) {
      x.push_back(2.0 * kHalfPi - a[k]);
      f.push_back(d[k]);
    }
  table_ = InterpolatedTable(Eigen::Map<Eigen::VectorXd>(x.data(), x.size()),
                             Eigen::Map<Eigen::VectorXd>(f.data(), f.size()), Interpolation::Pchip,
                             kWhere, "tableAngle_rad (reflected)", "rad", "tableRadialDrop_m", "m");
}

double Ovality::calcDrop_m(double phi_rad) const {
  if (model_ == OvalityModel::Law) {
    if (ovality_m_ == 0.0)
      return 0.0;
    return 0.25 * ovality_m_ *
           ((1.0 - std::cos(2.0 * phi_rad)) + 0.5 * k_ * (1.0 - std::cos(4.0 * phi_rad)));
  }
  const double psi = std::atan2(std::abs(std::sin(phi_rad)), std::abs(std::cos(phi_rad)));
  return table_.value(psi);
}

}  // namespace pistondyn::skirt
