#include "pistondyn/mapping/CylinderGrid.h"

#include <cmath>
#include <string>

#include "Cells.h"
#include "Checks.h"

namespace pistondyn::mapping {

namespace {

using detail::kTwoPi;

void checkRadius(const char* function, double radius_m) {
  common::requirePositiveFinite(radius_m, function, "radius_m", "");
}

// Trapezoid weights: integral of each 1-D hat function over its support.
Eigen::VectorXd hatIntegrals(const Eigen::VectorXd& x, bool closed, double period) {
  const Eigen::Index n = x.size();
  const Eigen::VectorXd h = detail::cellWidths(x, closed, period);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(n);
  for (Eigen::Index c = 0; c < h.size(); ++c) {  // cell c joins nodes c and c + 1 (mod n)
    w[c] += 0.5 * h[c];
    w[(c + 1) % n] += 0.5 * h[c];
  }
  return w;
}

}  // namespace

namespace {
// The checks both factories share: radius, increasing nodes (at least minPhiNodes around and
// two along), angles in range and a span short of a full turn (whyNotFullTurn says what to do).
void checkNodes(const char* fn, double radius_m, const Eigen::VectorXd& phi_rad,
                const Eigen::VectorXd& y_m, int minPhiNodes, const char* whyNotFullTurn) {
  checkRadius(fn, radius_m);
  detail::requireIncreasingNodes(fn, "phi_rad", phi_rad, minPhiNodes);
  detail::requireIncreasingNodes(fn, "y_m", y_m, 2);
  detail::requireAngle(fn, "phi_rad[0]", phi_rad[0]);
  detail::requireAngle(fn, "phi_rad[last]", phi_rad[phi_rad.size() - 1]);
  const double span = phi_rad[phi_rad.size() - 1] - phi_rad[0];
  if (!(span < kTwoPi))
    common::throwInvalidArgument(fn,
                                 common::message("phi_rad spans ", span, " rad", whyNotFullTurn));
}
}  // namespace

CylinderGrid CylinderGrid::sector(double radius_m, const Eigen::VectorXd& phi_rad,
                                  const Eigen::VectorXd& y_m) {
  checkNodes("CylinderGrid::sector", radius_m, phi_rad, y_m, 2,
             ", a sector must span less than 2*pi (use CylinderGrid::fullCircle)");
  return CylinderGrid(radius_m, phi_rad, y_m, false);
}

CylinderGrid CylinderGrid::fullCircle(double radius_m, const Eigen::VectorXd& phi_rad,
                                      const Eigen::VectorXd& y_m) {
  const char* fn = "CylinderGrid::fullCircle";
  checkNodes(fn, radius_m, phi_rad, y_m, 3,
             "; the closing node phi_rad[0] + 2*pi must not be repeated");
  detail::requireReasonableClosingCell(fn, "phi_rad", phi_rad, kTwoPi);
  return CylinderGrid(radius_m, phi_rad, y_m, true);
}

double CylinderGrid::phiEnd_rad() const {
  return closed_ ? phi_rad_[0] + kTwoPi : phi_rad_[phi_rad_.size() - 1];
}

Eigen::VectorXd CylinderGrid::nodeArea_m2() const {
  const Eigen::VectorXd wPhi = hatIntegrals(phi_rad_, closed_, kTwoPi);
  const Eigen::VectorXd wY = hatIntegrals(y_m_, false, 0.0);
  Eigen::VectorXd area(nodeCount());
  for (int j = 0; j < nY(); ++j)
    for (int i = 0; i < nPhi(); ++i)
      area[index(i, j)] = radius_m_ * wPhi[i] * wY[j];
  return area;
}

Eigen::VectorXd uniformNodes(double first, double last, int count) {
  const char* fn = "uniformNodes";
  if (count < 2)
    common::throwInvalidArgument(fn, "count = " + std::to_string(count) + " must be at least 2");
  detail::requireFiniteScalar(fn, "first", first);
  detail::requireFiniteScalar(fn, "last", last);
  if (!(last > first))
    common::throwInvalidArgument(
        fn, common::message("last = ", last, " must be greater than first = ", first));
  Eigen::VectorXd x(count);
  for (int k = 0; k < count; ++k)
    x[k] = first + (last - first) * k / (count - 1);
  x[count - 1] = last;
  return x;
}

Eigen::VectorXd fullCircleNodes_rad(int count, double phi0_rad) {
  const char* fn = "fullCircleNodes_rad";
  if (count < 3)
    common::throwInvalidArgument(fn, "count = " + std::to_string(count) + " must be at least 3");
  detail::requireFiniteScalar(fn, "phi0_rad", phi0_rad);
  Eigen::VectorXd x(count);
  for (int k = 0; k < count; ++k)
    x[k] = phi0_rad + kTwoPi * k / count;
  return x;
}

}  // namespace pistondyn::mapping
