#include "pistondyn/mapping/ForceMap.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "BuildHatOverlap1D.h"
#include "Cells.h"
#include "Checks.h"

namespace pistondyn::mapping {

namespace {

using detail::kTwoPi;

using ConstMatrixMap = Eigen::Map<const Eigen::MatrixXd>;
using MatrixMap = Eigen::Map<Eigen::MatrixXd>;

// F(phi node, j) += A_y(j, l) * Q(r, l) for the compact product Q (row r = the r-th
// reached target phi node) and the 1-D axial factor A_y (target x source, compressed by
// source column). The reached phi nodes come as runs of consecutive nodes (one run, or
// two when the source straddles the target's phi_0), so the inner loops are contiguous.
// Only the target rows j that A_y reaches and the reached phi nodes are touched.
template <class Q>
void scatterRight(const Q& q, const std::vector<TensorForceMap::PhiRun>& runs,
                  const HatOverlap1D& a, MatrixMap& f) {
  for (int l = 0; l < a.sourceCount; ++l)
    for (int e = a.outer[l]; e < a.outer[l + 1]; ++e) {
      const double w = a.value[e];
      double* column = f.col(a.inner[e]).data();
      for (const TensorForceMap::PhiRun& run : runs)
        for (int i = 0; i < run.length; ++i)
          column[run.target + i] += w * q(run.compact + i, l);
    }
}

// The same for three products at once (the traction's x, y, z), sharing the loop
// overhead of the short runs.
template <class Q>
void scatterRight3(const Q& qx, const Q& qy, const Q& qz,
                   const std::vector<TensorForceMap::PhiRun>& runs, const HatOverlap1D& a,
                   MatrixMap& fx, MatrixMap& fy, MatrixMap& fz) {
  for (int l = 0; l < a.sourceCount; ++l)
    for (int e = a.outer[l]; e < a.outer[l + 1]; ++e) {
      const double w = a.value[e];
      const Eigen::Index j = a.inner[e];
      double* cx = fx.col(j).data();
      double* cy = fy.col(j).data();
      double* cz = fz.col(j).data();
      for (const TensorForceMap::PhiRun& run : runs)
        for (int i = 0; i < run.length; ++i) {
          const int t = run.target + i, c = run.compact + i;
          cx[t] += w * qx(c, l);
          cy[t] += w * qy(c, l);
          cz[t] += w * qz(c, l);
        }
    }
}

// sums = column sums of Q, added row by row (contiguous rows of the row-major products;
// each column is still summed in row order). `sums` is workspace storage: no allocation
// once it has the size.
template <class Q>
void calcColumnSums(const Q& q, Eigen::RowVectorXd& sums) {
  sums.setZero(q.cols());
  for (Eigen::Index r = 0; r < q.rows(); ++r)
    sums += q.row(r);
}

// sum_l b[l] * sums[l].
double dotColumnSums(const Eigen::RowVectorXd& sums, const Eigen::Ref<const Eigen::VectorXd>& b) {
  double sum = 0.0;
  for (Eigen::Index l = 0; l < sums.size(); ++l)
    sum += b[l] * sums[l];
  return sum;
}

// a^T P b for per-node weights a (phi) and b (y); no temporaries.
double weightedSum(const Eigen::Ref<const Eigen::VectorXd>& a, const ConstMatrixMap& p,
                   const Eigen::Ref<const Eigen::VectorXd>& b) {
  double sum = 0.0;
  for (Eigen::Index l = 0; l < p.cols(); ++l)
    sum += b[l] * a.dot(p.col(l));
  return sum;
}

// 64-bit FNV-1a over everything the axial factor is built from besides the offset: the
// source and target axial nodes (bit patterns) and the load rule. Two maps with the same
// key build the same A_y for an offset, so they may share a workspace.
std::uint64_t axialFingerprint(const Eigen::VectorXd& sourceY, const Eigen::VectorXd& targetY,
                               LoadRule rule) {
  std::uint64_t h = 1469598103934665603ull;
  auto add = [&h](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      h ^= p[i];
      h *= 1099511628211ull;
    }
  };
  for (const Eigen::VectorXd* v : {&sourceY, &targetY}) {
    const Eigen::Index n = v->size();
    add(&n, sizeof n);
    add(v->data(), sizeof(double) * static_cast<std::size_t>(n));
  }
  const int r = static_cast<int>(rule);
  add(&r, sizeof r);
  return h;
}

void checkOutput(const char* fn, const char* argument, Eigen::Index size, int expected) {
  if (size != expected)
    common::throwInvalidArgument(fn, std::string(argument) + " has " + std::to_string(size) +
                                         " entries, expected " + std::to_string(expected) +
                                         " (target.nodeCount())");
}

}  // namespace

// ---------------------------------------------------------------------------------------
TensorForceMap::TensorForceMap(const CylinderGrid& source, const CylinderGrid& target,
                               double phiOffset_rad, LoadRule rule)
    : source_(source), target_(target), phiOffset_rad_(phiOffset_rad), rule_(rule) {
  detail::requireAngle("TensorForceMap", "phiOffset_rad", phiOffset_rad);
  calcHatOverlap1D(source.phi_rad(), source.isClosed(), target.phi_rad(), target.isClosed(), kTwoPi,
                   phiOffset_rad, rule, /*withTrig=*/true, phi_);
  // Compact dense copy of A_phi restricted to the target phi nodes it reaches (a skirt
  // side covers 9 of the liner's 36), scaled by R, for the per-step products: a small
  // dense product vectorises, where the column-compressed scatter into all 36 rows
  // was bound by its indirect updates.
  phiRows_ = phi_.inner;
  std::sort(phiRows_.begin(), phiRows_.end());
  phiRows_.erase(std::unique(phiRows_.begin(), phiRows_.end()), phiRows_.end());
  std::vector<int> compactRow(static_cast<size_t>(target.nPhi()), -1);
  const int nWin = static_cast<int>(phiRows_.size());
  for (int r = 0; r < nWin; ++r)
    compactRow[phiRows_[r]] = r;
  const double radius = source.radius_m();
  phiPlain_.setZero(nWin, source.nPhi());
  phiCos_.setZero(nWin, source.nPhi());
  phiSin_.setZero(nWin, source.nPhi());
  phiBands_.assign(static_cast<size_t>(nWin), {source.nPhi(), 0});
  for (int k = 0; k < phi_.sourceCount; ++k)
    for (int e = phi_.outer[k]; e < phi_.outer[k + 1]; ++e) {
      const int r = compactRow[phi_.inner[e]];
      phiPlain_(r, k) = radius * phi_.value[e];
      phiCos_(r, k) = radius * phi_.valueCos[e];
      phiSin_(r, k) = radius * phi_.valueSin[e];
      PhiBand& band = phiBands_[r];
      const int end = std::max(band.begin + band.length, k + 1);
      band.begin = std::min(band.begin, k);
      band.length = end - band.begin;
    }
  for (int r = 0; r < nWin; ++r) {
    if (r > 0 && phiRows_[r] == phiRows_[r - 1] + 1)
      ++phiRuns_.back().length;
    else
      phiRuns_.push_back({phiRows_[r], r, 1});
  }
  phiHasOutside_ = phi_.outsideIntegral.cwiseAbs().maxCoeff() > 0.0;
  axialKey_ = axialFingerprint(source.y_m(), target.y_m(), rule);
}

void TensorForceMap::setAxialOffset(double yOffset_m, Workspace& ws) const {
  detail::requireFiniteScalar("TensorForceMap::setAxialOffset", "yOffset_m", yOffset_m);
  // The axial nodes were checked by CylinderGrid; only the offset is new each step.
  detail::buildHatOverlap1D(source_.y_m(), false, target_.y_m(), false, 0.0, yOffset_m, rule_,
                            /*withTrig=*/false, ws.axial);
  ws.yOffset_m = yOffset_m;
  ws.axialKey = axialKey_;
  ws.ready = true;
  // The rows of A_y (sorted within each column; the source columns overlap target rows
  // in increasing order, but min/max over all entries needs no such assumption).
  const std::vector<int>& rows = ws.axial.inner;
  if (rows.empty()) {
    ws.rows = {};
  } else {
    const auto [lo, hi] = std::minmax_element(rows.begin(), rows.end());
    ws.rows = {*lo, *hi - *lo + 1};
  }
}

void TensorForceMap::checkWorkspace(const char* fn, const Workspace& ws) const {
  if (!ws.ready)
    common::throwInvalidArgument(
        fn, "ws has no axial factor (call setAxialOffset with this workspace first)");
  if (ws.axialKey != axialKey_ || ws.axial.sourceCount != source_.nY() ||
      ws.axial.targetCount != target_.nY())
    common::throwInvalidArgument(
        fn,
        "ws holds the axial factor of another map (different source or target axial "
        "nodes or load rule); call setAxialOffset of this map with it first");
}

LoadBalance TensorForceMap::apply(Workspace& ws,
                                  const Eigen::Ref<const Eigen::VectorXd>& sourcePressure_Pa,
                                  Eigen::Ref<Eigen::VectorXd> targetForce_N) const {
  return mapScalar("TensorForceMap::apply", ws, sourcePressure_Pa, targetForce_N, true);
}

LoadBalance TensorForceMap::accumulate(Workspace& ws,
                                       const Eigen::Ref<const Eigen::VectorXd>& sourcePressure_Pa,
                                       Eigen::Ref<Eigen::VectorXd> targetForce_N) const {
  return mapScalar("TensorForceMap::accumulate", ws, sourcePressure_Pa, targetForce_N, false);
}

LoadBalance TensorForceMap::mapScalar(const char* fn, Workspace& ws,
                                      const Eigen::Ref<const Eigen::VectorXd>& sourcePressure_Pa,
                                      Eigen::Ref<Eigen::VectorXd> targetForce_N,
                                      bool overwrite) const {
  checkWorkspace(fn, ws);
  detail::requireFiniteVector(fn, "sourcePressure_Pa", sourcePressure_Pa, source_.nodeCount());
  checkOutput(fn, "targetForce_N", targetForce_N.size(), target_.nodeCount());
  const double r = source_.radius_m();
  const ConstMatrixMap p(sourcePressure_Pa.data(), source_.nPhi(), source_.nY());
  MatrixMap f(targetForce_N.data(), target_.nPhi(), target_.nY());
  // R * A_phi * P on the reached phi nodes, row by row over each row's band of source
  // nodes (about 16 of 64 for a skirt side on a 36-node liner).
  const int nWin = static_cast<int>(phiRows_.size());
  ws.q2.resize(nWin, source_.nY());
  for (int row = 0; row < nWin; ++row) {
    const PhiBand b = phiBands_[row];
    ws.q2.row(row).noalias() =
        phiPlain_.row(row).segment(b.begin, b.length) * p.middleRows(b.begin, b.length);
  }
  if (overwrite)
    f.setZero();
  scatterRight(ws.q2, phiRuns_, ws.axial, f);

  // Balance. Inside in phi: the column sums of A_phi are the inside integrals, so the
  // column sums of Q give them for free. Outside in phi: only when the source reaches
  // beyond a sector target. Unmapped = (outside in phi) x (all y) + (inside) x (outside y).
  const HatOverlap1D& y = ws.axial;
  calcColumnSums(ws.q2, ws.columnSums);
  const double inside = dotColumnSums(ws.columnSums, y.sourceIntegral.col(0));
  const double insideOutY = dotColumnSums(ws.columnSums, y.outsideIntegral.col(0));
  const double outside =
      phiHasOutside_ ? r * weightedSum(phi_.outsideIntegral.col(0), p, y.sourceIntegral.col(0))
                     : 0.0;
  LoadBalance balance;
  balance.sourceTotal_N = inside + outside;
  balance.unmapped_N = outside + insideOutY;
  return balance;
}

CartesianLoadBalance TensorForceMap::applyTraction(
    Workspace& ws, const Eigen::Ref<const Eigen::VectorXd>& normal_Pa,
    const Eigen::Ref<const Eigen::VectorXd>& circumferential_Pa,
    const Eigen::Ref<const Eigen::VectorXd>& axial_Pa, Eigen::Ref<Eigen::VectorXd> forceX_N,
    Eigen::Ref<Eigen::VectorXd> forceY_N, Eigen::Ref<Eigen::VectorXd> forceZ_N) const {
  return mapTraction("TensorForceMap::applyTraction", ws, normal_Pa, circumferential_Pa, axial_Pa,
                     forceX_N, forceY_N, forceZ_N, true);
}

CartesianLoadBalance TensorForceMap::accumulateTraction(
    Workspace& ws, const Eigen::Ref<const Eigen::VectorXd>& normal_Pa,
    const Eigen::Ref<const Eigen::VectorXd>& circumferential_Pa,
    const Eigen::Ref<const Eigen::VectorXd>& axial_Pa, Eigen::Ref<Eigen::VectorXd> forceX_N,
    Eigen::Ref<Eigen::VectorXd> forceY_N, Eigen::Ref<Eigen::VectorXd> forceZ_N) const {
  return mapTraction("TensorForceMap::accumulateTraction", ws, normal_Pa, circumferential_Pa,
                     axial_Pa, forceX_N, forceY_N, forceZ_N, false);
}

CartesianLoadBalance TensorForceMap::mapTraction(
    const char* fn, Workspace& ws, const Eigen::Ref<const Eigen::VectorXd>& normal_Pa,
    const Eigen::Ref<const Eigen::VectorXd>& circumferential_Pa,
    const Eigen::Ref<const Eigen::VectorXd>& axial_Pa, Eigen::Ref<Eigen::VectorXd> forceX_N,
    Eigen::Ref<Eigen::VectorXd> forceY_N, Eigen::Ref<Eigen::VectorXd> forceZ_N,
    bool overwrite) const {
  checkWorkspace(fn, ws);
  const int ns = source_.nodeCount(), nt = target_.nodeCount();
  detail::requireFiniteVector(fn, "normal_Pa", normal_Pa, ns);
  detail::requireFiniteVector(fn, "circumferential_Pa", circumferential_Pa, ns);
  detail::requireFiniteVector(fn, "axial_Pa", axial_Pa, ns);
  checkOutput(fn, "forceX_N", forceX_N.size(), nt);
  checkOutput(fn, "forceY_N", forceY_N.size(), nt);
  checkOutput(fn, "forceZ_N", forceZ_N.size(), nt);
  const double r = source_.radius_m();
  const int nsPhi = source_.nPhi(), nsY = source_.nY(), ntPhi = target_.nPhi(), ntY = target_.nY();
  const ConstMatrixMap pn(normal_Pa.data(), nsPhi, nsY);
  const ConstMatrixMap ps(circumferential_Pa.data(), nsPhi, nsY);
  const ConstMatrixMap py(axial_Pa.data(), nsPhi, nsY);
  MatrixMap fx(forceX_N.data(), ntPhi, ntY), fy(forceY_N.data(), ntPhi, ntY),
      fz(forceZ_N.data(), ntPhi, ntY);
  if (overwrite) {
    fx.setZero();
    fy.setZero();
    fz.setZero();
  }

  // f_x = normal cos - circumferential sin,  f_z = normal sin + circumferential cos.
  // q0 = R [A cos; A sin] Pn, q1 = R [A cos; A sin] Ps (reached phi nodes only).
  // Row by row over each row's band of source nodes (see mapScalar).
  const int nWin = static_cast<int>(phiRows_.size());
  ws.q0.resize(nWin, nsY);
  ws.q1.resize(nWin, nsY);
  ws.q2.resize(nWin, nsY);
  for (int row = 0; row < nWin; ++row) {
    const PhiBand b = phiBands_[row];
    const auto cosRow = phiCos_.row(row).segment(b.begin, b.length);
    const auto sinRow = phiSin_.row(row).segment(b.begin, b.length);
    const auto pnBand = pn.middleRows(b.begin, b.length);
    const auto psBand = ps.middleRows(b.begin, b.length);
    ws.q0.row(row).noalias() = cosRow * pnBand;  // x: A cos Pn - A sin Ps
    ws.q0.row(row).noalias() -= sinRow * psBand;
    ws.q1.row(row).noalias() = sinRow * pnBand;  // z: A sin Pn + A cos Ps
    ws.q1.row(row).noalias() += cosRow * psBand;
    ws.q2.row(row).noalias() =  // y: A Py
        phiPlain_.row(row).segment(b.begin, b.length) * py.middleRows(b.begin, b.length);
  }
  const auto& qx = ws.q0;
  const auto& qz = ws.q1;
  scatterRight3(qx, ws.q2, qz, phiRuns_, ws.axial, fx, fy, fz);

  // Balance as in mapScalar: inside-in-phi totals from the column sums of q.
  const HatOverlap1D& y = ws.axial;
  const auto ySource = y.sourceIntegral.col(0), yOutside = y.outsideIntegral.col(0);
  // Each product's column sums once, then both dot products (x, y, z in turn).
  Eigen::Vector3d inside, insideOutY;
  const decltype(ws.q0)* products[3] = {&qx, &ws.q2, &qz};
  for (int d = 0; d < 3; ++d) {
    calcColumnSums(*products[d], ws.columnSums);
    inside[d] = dotColumnSums(ws.columnSums, ySource);
    insideOutY[d] = dotColumnSums(ws.columnSums, yOutside);
  }
  Eigen::Vector3d outside = Eigen::Vector3d::Zero();
  if (phiHasOutside_) {
    const HatOverlap1D& a = phi_;
    outside = r * Eigen::Vector3d(weightedSum(a.outsideIntegral.col(1), pn, ySource) -
                                      weightedSum(a.outsideIntegral.col(2), ps, ySource),
                                  weightedSum(a.outsideIntegral.col(0), py, ySource),
                                  weightedSum(a.outsideIntegral.col(2), pn, ySource) +
                                      weightedSum(a.outsideIntegral.col(1), ps, ySource));
  }
  CartesianLoadBalance balance;
  balance.sourceTotal_N = inside + outside;
  balance.unmapped_N = outside + insideOutY;
  return balance;
}

// ---------------------------------------------------------------------------------------
ForceMap::ForceMap(const CylinderGrid& source, const CylinderGrid& target,
                   GridOffset sourceInTarget, LoadRule rule) {
  detail::requireAngle("ForceMap", "sourceInTarget.phi_rad", sourceInTarget.phi_rad);
  detail::requireFiniteScalar("ForceMap", "sourceInTarget.y_m", sourceInTarget.y_m);
  const TensorForceMap factors(source, target, sourceInTarget.phi_rad, rule);
  TensorForceMap::Workspace ws;
  factors.setAxialOffset(sourceInTarget.y_m, ws);
  const HatOverlap1D& aPhi = factors.phi_;
  const HatOverlap1D& aY = ws.axial;
  const double r = source.radius_m();

  // kron(A_y, A_phi): entry (i + ntPhi*j, k + nsPhi*l) = A_y(j, l) * A_phi(i, k).
  const int nsPhi = source.nPhi(), ntPhi = target.nPhi();
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(aPhi.value.size() * aY.value.size());
  for (int l = 0; l < aY.sourceCount; ++l)
    for (int ey = aY.outer[l]; ey < aY.outer[l + 1]; ++ey) {
      const int j = aY.inner[ey];
      for (int k = 0; k < aPhi.sourceCount; ++k)
        for (int ep = aPhi.outer[k]; ep < aPhi.outer[k + 1]; ++ep)
          triplets.emplace_back(aPhi.inner[ep] + ntPhi * j, k + nsPhi * l,
                                r * aY.value[ey] * aPhi.value[ep]);
    }
  matrix_.resize(target.nodeCount(), source.nodeCount());
  matrix_.setFromTriplets(triplets.begin(), triplets.end());

  sourceArea_m2_.resize(source.nodeCount());
  unmappedArea_m2_.resize(source.nodeCount());
  for (int l = 0; l < source.nY(); ++l)
    for (int k = 0; k < nsPhi; ++k) {
      const int n = k + nsPhi * l;
      sourceArea_m2_[n] = r * aPhi.sourceIntegral(k, 0) * aY.sourceIntegral(l, 0);
      unmappedArea_m2_[n] = r * (aPhi.outsideIntegral(k, 0) * aY.sourceIntegral(l, 0) +
                                 aPhi.insideIntegral(k, 0) * aY.outsideIntegral(l, 0));
    }
}

LoadBalance ForceMap::apply(const Eigen::Ref<const Eigen::VectorXd>& sourcePressure_Pa,
                            Eigen::Ref<Eigen::VectorXd> targetForce_N) const {
  const char* fn = "ForceMap::apply";
  detail::requireFiniteVector(fn, "sourcePressure_Pa", sourcePressure_Pa, matrix_.cols());
  checkOutput(fn, "targetForce_N", targetForce_N.size(), static_cast<int>(matrix_.rows()));
  targetForce_N.noalias() = matrix_ * sourcePressure_Pa;
  return {sourceArea_m2_.dot(sourcePressure_Pa), unmappedArea_m2_.dot(sourcePressure_Pa)};
}

}  // namespace pistondyn::mapping
