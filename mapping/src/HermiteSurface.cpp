#include "pistondyn/mapping/HermiteSurface.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "Cells.h"
#include "Checks.h"

namespace pistondyn::mapping {

namespace {

using detail::kTwoPi;

// Points closer than this fraction of the grid extent outside an end are clamped onto it
// (rounding of offsets must not turn an edge node into an "outside" error).
constexpr double kEdgeTolerance = 1e-12;

// Cubic Hermite basis g(t) = [h00, h01, h10, h11] (value at 0, value at 1, slope at 0,
// slope at 1, unit cell) and its derivative divided by the cell width. At t = 0 and t = 1
// they are exactly unit vectors, so a cell edge reproduces the nodal data bit for bit
// and neighbouring cells (also across the periodic seam) agree exactly there.
Eigen::Vector4d hermite(double t) {
  const double t2 = t * t, s = 1.0 - t;
  const double h01 = t2 * (3.0 - 2.0 * t);
  return Eigen::Vector4d(1.0 - h01, h01, t * s * s, t2 * (t - 1.0));
}
Eigen::Vector4d dHermite(double t, double invH) {
  const double six = 6.0 * t * (1.0 - t);
  return Eigen::Vector4d(-six, six, (1.0 - t) * (1.0 - 3.0 * t), t * (3.0 * t - 2.0)) * invH;
}

// Index of the cell containing x in [nodes[0], nodes[last]] (monotone nodes, `cells`
// cells), found by bisection; x exactly on a node goes to the cell on its right except
// at the last node.
int findCell(const Eigen::VectorXd& nodes, int cells, double x) {
  const double* begin = nodes.data();
  const double* it = std::upper_bound(begin, begin + nodes.size(), x);
  const int c = static_cast<int>(it - begin) - 1;
  return std::clamp(c, 0, cells - 1);
}

}  // namespace

HermiteSurface::HermiteSurface(CylinderGrid grid)
    : grid_(std::move(grid)),
      phiSlopes_(grid_.phi_rad(), grid_.isClosed(), kTwoPi),
      ySlopes_(grid_.y_m(), false, 0.0),
      phiCellWidth_(detail::cellWidths(grid_.phi_rad(), grid_.isClosed(), kTwoPi)),
      yCellWidth_(detail::cellWidths(grid_.y_m(), false, 0.0)),
      values_(grid_.nodeCount()),
      dPhi_(grid_.nodeCount()),
      dY_(grid_.nodeCount()),
      dPhiDY_(grid_.nodeCount()),
      coeff_(16 * static_cast<size_t>(grid_.phiCellCount() * grid_.yCellCount())),
      phiLineScratch_(grid_.nY()),
      yLineScratch_(grid_.nPhi()) {}

HermiteSurface::HermiteSurface(CylinderGrid grid, const Eigen::Ref<const Eigen::VectorXd>& values)
    : HermiteSurface(std::move(grid)) {
  updateValues(values);
}

HermiteSurface::HermiteSurface(CylinderGrid grid, const Eigen::Ref<const Eigen::VectorXd>& values,
                               const Eigen::Ref<const Eigen::VectorXd>& dPhi,
                               const Eigen::Ref<const Eigen::VectorXd>& dY,
                               const Eigen::Ref<const Eigen::VectorXd>& dPhiDY)
    : HermiteSurface(std::move(grid)) {
  updateValues(values, dPhi, dY, dPhiDY);
}

void HermiteSurface::checkValues(const char* function,
                                 const Eigen::Ref<const Eigen::VectorXd>& values) const {
  detail::requireFiniteVector(function, "values", values, grid_.nodeCount());
}

void HermiteSurface::updateValues(const Eigen::Ref<const Eigen::VectorXd>& values) {
  checkValues("HermiteSurface::updateValues", values);
  values_ = values;
  calcSplineSlopes();
  calcCellCoefficients();
}

void HermiteSurface::updateValues(const Eigen::Ref<const Eigen::VectorXd>& values,
                                  const Eigen::Ref<const Eigen::VectorXd>& dPhi,
                                  const Eigen::Ref<const Eigen::VectorXd>& dY,
                                  const Eigen::Ref<const Eigen::VectorXd>& dPhiDY) {
  const char* fn = "HermiteSurface::updateValues";
  checkValues(fn, values);
  detail::requireFiniteVector(fn, "dPhi", dPhi, grid_.nodeCount());
  detail::requireFiniteVector(fn, "dY", dY, grid_.nodeCount());
  detail::requireFiniteVector(fn, "dPhiDY", dPhiDY, grid_.nodeCount());
  values_ = values;
  dPhi_ = dPhi;
  dY_ = dY;
  dPhiDY_ = dPhiDY;
  calcCellCoefficients();
}

void HermiteSurface::calcSplineSlopes() {
  using Lines = detail::SplineSlopes::Lines;
  const int nPhi = grid_.nPhi(), nY = grid_.nY();
  using MapM = Eigen::Map<Eigen::MatrixXd>;
  using MapCM = Eigen::Map<const Eigen::MatrixXd>;
  const MapCM f(values_.data(), nPhi, nY);
  // Node (i, j) is entry (i, j) of the nPhi x nY matrix: phi-lines are its columns,
  // y-lines its rows.
  phiSlopes_.calcSlopes(f, MapM(dPhi_.data(), nPhi, nY), Lines::InColumns, phiLineScratch_);
  ySlopes_.calcSlopes(f, MapM(dY_.data(), nPhi, nY), Lines::InRows, yLineScratch_);
  // Cross derivative: y-spline slopes of the phi-slopes (the operators commute).
  ySlopes_.calcSlopes(MapCM(dPhi_.data(), nPhi, nY), MapM(dPhiDY_.data(), nPhi, nY), Lines::InRows,
                      yLineScratch_);
}

void HermiteSurface::calcCellCoefficients() {
  const int nPhi = grid_.nPhi(), cellsPhi = grid_.phiCellCount(), cellsY = grid_.yCellCount();
  Eigen::Matrix4d g;
  for (int cj = 0; cj < cellsY; ++cj) {
    const double hy = yCellWidth_[cj];
    for (int ci = 0; ci < cellsPhi; ++ci) {
      const double hp = phiCellWidth_[ci];
      const int i0 = ci, i1 = (ci + 1) % nPhi;
      const int k00 = grid_.index(i0, cj), k01 = grid_.index(i0, cj + 1);
      const int k10 = grid_.index(i1, cj), k11 = grid_.index(i1, cj + 1);
      g << values_[k00], values_[k01], hy * dY_[k00], hy * dY_[k01],  //
          values_[k10], values_[k11], hy * dY_[k10], hy * dY_[k11],   //
          hp * dPhi_[k00], hp * dPhi_[k01], hp * hy * dPhiDY_[k00], hp * hy * dPhiDY_[k01],
          hp * dPhi_[k10], hp * dPhi_[k11], hp * hy * dPhiDY_[k10], hp * hy * dPhiDY_[k11];
      Eigen::Map<Eigen::Matrix4d>(coeff_.data() + 16 * static_cast<size_t>(ci + cellsPhi * cj)) = g;
    }
  }
}

Eigen::Matrix4d HermiteSurface::cellCoefficients(int i, int j) const {
  if (i < 0 || i >= grid_.phiCellCount() || j < 0 || j >= grid_.yCellCount())
    common::throwInvalidArgument("HermiteSurface::cellCoefficients",
                                 "cell (" + std::to_string(i) + ", " + std::to_string(j) +
                                     ") outside [0, " + std::to_string(grid_.phiCellCount()) +
                                     ") x [0, " + std::to_string(grid_.yCellCount()) + ")");
  return Eigen::Map<const Eigen::Matrix4d>(coeff_.data() +
                                           16 * static_cast<size_t>(i + grid_.phiCellCount() * j));
}

HermiteSample HermiteSurface::evaluateInCell(int i, int j, double t, double u) const {
  const Eigen::Matrix4d c = cellCoefficients(i, j);
  const Eigen::Vector4d tp = hermite(t), up = hermite(u);
  const Eigen::Vector4d tdp = dHermite(t, 1.0 / phiCellWidth_[i]);
  const Eigen::Vector4d udp = dHermite(u, 1.0 / yCellWidth_[j]);
  const Eigen::Vector4d cu = c * up, cdu = c * udp;
  return {tp.dot(cu), tdp.dot(cu), tp.dot(cdu), tdp.dot(cdu)};
}

void HermiteSurface::locatePhi(const char* fn, double phi_rad, OutsidePolicy outside, int& cell,
                               double& t) const {
  const Eigen::VectorXd& x = grid_.phi_rad();
  const double phi0 = x[0];
  double w = phi_rad - phi0;
  w -= kTwoPi * std::floor(w / kTwoPi);  // [0, 2*pi] (2*pi only through rounding)
  double p = phi0 + w;
  const int cells = grid_.phiCellCount();
  const double end = grid_.phiEnd_rad();
  // A ring has no outside: its end phi_0 + 2*pi is phi_0 again, so p < end from here on.
  if (grid_.isClosed() && p >= end)
    p = phi0;
  if (p <= end) {
    cell = findCell(x, cells, p);
    t = std::clamp((p - x[cell]) / phiCellWidth_[cell], 0.0, 1.0);
    return;
  }
  // Outside the sector: nearer to its end (after) or to its start (before, one turn on)?
  const double after = p - end, before = phi0 + kTwoPi - p;
  const bool nearEnd = after <= before;
  const double distance = nearEnd ? after : before;
  cell = nearEnd ? cells - 1 : 0;
  if (distance <= kEdgeTolerance * (end - phi0)) {
    t = nearEnd ? 1.0 : 0.0;
    return;
  }
  if (outside == OutsidePolicy::Throw)
    common::throwInvalidArgument(
        fn, common::message("phi_rad = ", phi_rad, " lies outside the sector [", phi0, ", ", end,
                            "] rad (by ", distance, " rad)"));
  t = nearEnd ? (p - x[cell]) / phiCellWidth_[cell] : -before / phiCellWidth_[0];
}

void HermiteSurface::locateY(const char* fn, double y_m, OutsidePolicy outside, int& cell,
                             double& u) const {
  const Eigen::VectorXd& y = grid_.y_m();
  const int cells = grid_.yCellCount();
  const double y0 = y[0], y1 = y[y.size() - 1];
  const double tol = kEdgeTolerance * (y1 - y0);
  cell = findCell(y, cells, y_m);
  u = (y_m - y[cell]) / yCellWidth_[cell];
  if (y_m >= y0 && y_m <= y1) {
    u = std::clamp(u, 0.0, 1.0);
    return;
  }
  const double distance = y_m < y0 ? y0 - y_m : y_m - y1;
  if (distance <= tol) {
    u = y_m < y0 ? 0.0 : 1.0;
    return;
  }
  if (outside == OutsidePolicy::Throw)
    common::throwInvalidArgument(fn, common::message("y_m = ", y_m, " lies outside the grid [", y0,
                                                     ", ", y1, "] m (by ", distance, " m)"));
}

HermiteSample HermiteSurface::evaluate(double phi_rad, double y_m, OutsidePolicy outside) const {
  const char* fn = "HermiteSurface::evaluate";
  detail::requireAngle(fn, "phi_rad", phi_rad);
  detail::requireFiniteScalar(fn, "y_m", y_m);
  int ci = 0, cj = 0;
  double t = 0.0, u = 0.0;
  locatePhi(fn, phi_rad, outside, ci, t);
  locateY(fn, y_m, outside, cj, u);
  return evaluateInCell(ci, cj, t, u);
}

void HermiteSurface::prepareGrid(const char* fn, const CylinderGrid& points, GridOffset offset,
                                 Eigen::Index outputSize, HermiteGridWorkspace& ws,
                                 OutsidePolicy outside) const {
  detail::requireAngle(fn, "offset.phi_rad", offset.phi_rad);
  detail::requireFiniteScalar(fn, "offset.y_m", offset.y_m);
  if (outputSize != points.nodeCount())
    common::throwInvalidArgument(
        fn, "output has " + std::to_string(outputSize) + " entries, expected " +
                std::to_string(points.nodeCount()) + " (points.nodeCount())");
  const int nP = points.nPhi(), nY = points.nY();
  ws.phiCell.resize(nP);
  ws.yCell.resize(nY);
  ws.phiBasis.resize(4, nP);
  ws.phiDBasis.resize(4, nP);
  ws.yBasis.resize(4, nY);
  ws.yDBasis.resize(4, nY);
  for (int i = 0; i < nP; ++i) {
    double t = 0.0;
    locatePhi(fn, points.phi_rad()[i] + offset.phi_rad, outside, ws.phiCell[i], t);
    ws.phiBasis.col(i) = hermite(t);
    ws.phiDBasis.col(i) = dHermite(t, 1.0 / phiCellWidth_[ws.phiCell[i]]);
  }
  for (int j = 0; j < nY; ++j) {
    double u = 0.0;
    locateY(fn, points.y_m()[j] + offset.y_m, outside, ws.yCell[j], u);
    ws.yBasis.col(j) = hermite(u);
    ws.yDBasis.col(j) = dHermite(u, 1.0 / yCellWidth_[ws.yCell[j]]);
  }
}

void HermiteSurface::evaluateOnGrid(const CylinderGrid& points, GridOffset offset,
                                    Eigen::Ref<Eigen::VectorXd> values, HermiteGridWorkspace& ws,
                                    OutsidePolicy outside) const {
  prepareGrid("HermiteSurface::evaluateOnGrid", points, offset, values.size(), ws, outside);
  const int nP = points.nPhi(), nY = points.nY(), cellsPhi = grid_.phiCellCount();
  for (int j = 0; j < nY; ++j) {
    const Eigen::Vector4d up = ws.yBasis.col(j);
    const double* rowCoeff = coeff_.data() + 16 * static_cast<size_t>(cellsPhi * ws.yCell[j]);
    for (int i = 0; i < nP; ++i) {
      const Eigen::Map<const Eigen::Matrix4d> c(rowCoeff + 16 * ws.phiCell[i]);
      values[i + nP * j] = ws.phiBasis.col(i).dot(c * up);
    }
  }
}

void HermiteSurface::evaluateOnGrid(const CylinderGrid& points, GridOffset offset,
                                    Eigen::Ref<Eigen::VectorXd> values,
                                    Eigen::Ref<Eigen::VectorXd> dPhi,
                                    Eigen::Ref<Eigen::VectorXd> dY, HermiteGridWorkspace& ws,
                                    OutsidePolicy outside) const {
  const char* fn = "HermiteSurface::evaluateOnGrid";
  prepareGrid(fn, points, offset, values.size(), ws, outside);
  if (dPhi.size() != values.size() || dY.size() != values.size())
    common::throwInvalidArgument(
        fn, "dPhi and dY must have " + std::to_string(values.size()) + " entries");
  const int nP = points.nPhi(), nY = points.nY(), cellsPhi = grid_.phiCellCount();
  for (int j = 0; j < nY; ++j) {
    const Eigen::Vector4d up = ws.yBasis.col(j), udp = ws.yDBasis.col(j);
    const double* rowCoeff = coeff_.data() + 16 * static_cast<size_t>(cellsPhi * ws.yCell[j]);
    for (int i = 0; i < nP; ++i) {
      const Eigen::Map<const Eigen::Matrix4d> c(rowCoeff + 16 * ws.phiCell[i]);
      const Eigen::Vector4d cu = c * up;
      const int k = i + nP * j;
      values[k] = ws.phiBasis.col(i).dot(cu);
      dPhi[k] = ws.phiDBasis.col(i).dot(cu);
      dY[k] = ws.phiBasis.col(i).dot(c * udp);
    }
  }
}

}  // namespace pistondyn::mapping
