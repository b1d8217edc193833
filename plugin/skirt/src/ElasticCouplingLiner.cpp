// ElasticCoupling's liner (ElasticCoupling.h, "The liner"): the liner's compliance seen from
// the skirt's structural nodes at the piston's current height, added to the skirt's.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "Checks.h"
#include "pistondyn/skirt/ElasticCoupling.h"

namespace pistondyn::skirt {
namespace {
constexpr const char* kWhere = "ElasticCoupling (liner)";
constexpr double kTwoPi = 6.283185307179586476925286766559;

// Cell index and local coordinate t in [0, 1] of x among strictly increasing nodes; false
// when x lies outside [nodes[0], nodes[last]] by more than slack.
bool locate(const Eigen::VectorXd& nodes, double x, double slack, int& cell, double& t) {
  const Eigen::Index n = nodes.size();
  if (x < nodes[0] - slack || x > nodes[n - 1] + slack)
    return false;
  cell = 0;
  while (cell < n - 2 && x > nodes[cell + 1])
    ++cell;
  t = std::clamp((x - nodes[cell]) / (nodes[cell + 1] - nodes[cell]), 0.0, 1.0);
  return true;
}
}  // namespace

void ElasticCoupling::setLinerPosition(double pinHeight_m) {
  if (!linerGrid_)
    detail::fail(kWhere, "setLinerPosition(): this coupling has no liner");
  detail::requireFinite(kWhere, "setLinerPosition(pinHeight_m)", pinHeight_m, "m");
  if (pinHeight_m == linerPinHeight_m_)
    return;
  linerPinHeight_m_ = pinHeight_m;
  calcEffectiveCompliance();
  onComplianceChanged();
}

void ElasticCoupling::calcEffectiveCompliance() {
  const mapping::CylinderGrid& liner = *linerGrid_;
  const Eigen::Index ns = structural_.nodeCount(), nL = liner.nodeCount();
  // Q: the liner's bilinear hats at each skirt structural node (liner frame: the node's angle,
  // its height above the pin axis + Y_pin). Its transpose carries a point force at a skirt
  // node to the liner nodes with the same hats (total exact), the work-conjugate of reading
  // the liner's displacement there.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(4 * ns));
  const Eigen::VectorXd& linerY = liner.y_m();
  // 0.1 mm: the liner's top row is the skirt top's height at the kinematic TDC, and the
  // simulated pin passes it by the crank train's give (1 um seen on the gasoline example);
  // rows that far out read the end row's values.
  constexpr double slackY = 1e-4;
  // The angles do not move with the pin: each skirt angle's liner cell (i0, i1) and weight once.
  // The liner is a full circle: an angle is reduced onto its ring [phi_0, phi_0 + 2 pi).
  const int nPhiL = liner.nPhi();
  const double phi0 = liner.phi_rad()[0];
  std::vector<int> phiCell(std::size_t(structural_.nPhi()));
  std::vector<double> phiWeight(std::size_t(structural_.nPhi()));
  for (int i = 0; i < structural_.nPhi(); ++i) {
    double phi = structural_.phi_rad()[i] - phi0;
    phi -= kTwoPi * std::floor(phi / kTwoPi);
    int cell = 0;
    while (cell < nPhiL - 1 && phi >= liner.phiNode_rad(cell + 1) - phi0)
      ++cell;
    const double a = liner.phiNode_rad(cell) - phi0, b = liner.phiNode_rad(cell + 1) - phi0;
    phiCell[std::size_t(i)] = cell;
    phiWeight[std::size_t(i)] = std::clamp((phi - a) / (b - a), 0.0, 1.0);
  }
  for (int j = 0; j < structural_.nY(); ++j) {
    const double y = structural_.y_m()[j] + linerPinHeight_m_;
    int cellY = 0;
    double ty = 0.0;
    if (!locate(linerY, y, slackY, cellY, ty))
      detail::fail(kWhere, "with the pin axis at " + detail::str(linerPinHeight_m_) +
                               " m above the crank axis the skirt's structural row at " +
                               detail::str(structural_.y_m()[j]) + " m (height " +
                               detail::str(y) + " m) lies outside the liner's heights [" +
                               detail::str(linerY[0]) + ", " +
                               detail::str(linerY[linerY.size() - 1]) +
                               "] m: the liner compliance must cover the skirt over the stroke");
    for (int i = 0; i < structural_.nPhi(); ++i) {
      const double tphi = phiWeight[std::size_t(i)];
      const int i0 = phiCell[std::size_t(i)], i1 = (i0 + 1) % nPhiL;
      const int row = structural_.index(i, j);
      const double w[4] = {(1 - tphi) * (1 - ty), tphi * (1 - ty), (1 - tphi) * ty, tphi * ty};
      const int col[4] = {liner.index(i0, cellY), liner.index(i1, cellY),
                          liner.index(i0, cellY + 1), liner.index(i1, cellY + 1)};
      for (int c = 0; c < 4; ++c)
        if (w[c] != 0.0)
          entries.emplace_back(row, col[c], w[c]);
    }
  }
  linerTransfer_.resize(ns, nL);
  linerTransfer_.setFromTriplets(entries.begin(), entries.end());
  // C = C_skirt + Q C_L Q^T: in series, the liner's outward give opens the gap as the skirt's
  // inward one does (the header's sign argument).
  linerProduct_.noalias() = linerTransfer_ * linerCompliance_m_per_N_;
  compliance_m_per_N_ = skirtCompliance_m_per_N_;
  compliance_m_per_N_.noalias() += linerProduct_ * linerTransfer_.transpose();
}

}  // namespace pistondyn::skirt
