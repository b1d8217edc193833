#include "pistondyn/mapping/ForceMap.h"

#include <string>
#include <vector>

#include "Checks.h"

namespace pistondyn::mapping {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

using ConstMatrixMap = Eigen::Map<const Eigen::MatrixXd>;
using MatrixMap = Eigen::Map<Eigen::MatrixXd>;

// q = A * P for a 1-D factor A (target x source, compressed by source column) and P with
// source rows: q(i, l) = sum_k A(i, k) P(k, l). `values` picks 1, cos or sin weights.
void multiplyLeft(const HatOverlap1D& a, const std::vector<double>& values, double scale,
                  const ConstMatrixMap& p, Eigen::MatrixXd& q) {
  q.setZero(a.targetCount, p.cols());
  for (Eigen::Index l = 0; l < p.cols(); ++l)
    for (int k = 0; k < a.sourceCount; ++k) {
      const double pk = scale * p(k, l);
      for (int e = a.outer[k]; e < a.outer[k + 1]; ++e)
        q(a.inner[e], l) += values[e] * pk;
    }
}

// F = Q * A^T for a 1-D factor A (target x source): F(:, j) += A(j, l) * Q(:, l).
void multiplyRightTransposed(const Eigen::MatrixXd& q, const HatOverlap1D& a, MatrixMap& f) {
  f.setZero();
  for (int l = 0; l < a.sourceCount; ++l)
    for (int e = a.outer[l]; e < a.outer[l + 1]; ++e)
      f.col(a.inner[e]) += a.value[e] * q.col(l);
}

// a^T P b for per-node weights a (phi) and b (y); no temporaries.
double weightedSum(const Eigen::Ref<const Eigen::VectorXd>& a, const ConstMatrixMap& p,
                   const Eigen::Ref<const Eigen::VectorXd>& b) {
  double sum = 0.0;
  for (Eigen::Index l = 0; l < p.cols(); ++l)
    sum += b[l] * a.dot(p.col(l));
  return sum;
}

void checkOutput(const char* fn, const char* argument, Eigen::Index size, int expected) {
  if (size != expected)
    detail::fail(fn, std::string(argument) + " has " + std::to_string(size) +
                         " entries, expected " + std::to_string(expected) +
                         " (target.nodeCount())");
}

}  // namespace

// ---------------------------------------------------------------------------------------
TensorForceMap::TensorForceMap(const CylinderGrid& source, const CylinderGrid& target,
                               double phiOffset_rad, LoadRule rule)
    : source_(source), target_(target), phiOffset_rad_(phiOffset_rad), rule_(rule) {
  detail::requireFiniteScalar("TensorForceMap", "phiOffset_rad", phiOffset_rad);
  calcHatOverlap1D(source.phi_rad(), source.isClosed(), target.phi_rad(), target.isClosed(), kTwoPi,
                   phiOffset_rad, rule, /*withTrig=*/true, phi_);
}

void TensorForceMap::setAxialOffset(double yOffset_m, Workspace& ws) const {
  detail::requireFiniteScalar("TensorForceMap::setAxialOffset", "yOffset_m", yOffset_m);
  calcHatOverlap1D(source_.y_m(), false, target_.y_m(), false, 0.0, yOffset_m, rule_,
                   /*withTrig=*/false, ws.axial);
  ws.yOffset_m = yOffset_m;
  ws.ready = true;
}

void TensorForceMap::checkWorkspace(const char* fn, const Workspace& ws) const {
  if (!ws.ready || ws.axial.sourceCount != source_.nY() || ws.axial.targetCount != target_.nY())
    detail::fail(fn, "workspace has no axial factor for this map (call setAxialOffset first)");
}

LoadBalance TensorForceMap::apply(Workspace& ws,
                                  const Eigen::Ref<const Eigen::VectorXd>& sourcePressure_Pa,
                                  Eigen::Ref<Eigen::VectorXd> targetForce_N) const {
  const char* fn = "TensorForceMap::apply";
  checkWorkspace(fn, ws);
  detail::requireFiniteVector(fn, "sourcePressure_Pa", sourcePressure_Pa, source_.nodeCount());
  checkOutput(fn, "targetForce_N", targetForce_N.size(), target_.nodeCount());
  const double r = source_.radius_m();
  const ConstMatrixMap p(sourcePressure_Pa.data(), source_.nPhi(), source_.nY());
  MatrixMap f(targetForce_N.data(), target_.nPhi(), target_.nY());
  multiplyLeft(phi_, phi_.value, r, p, ws.q0);
  multiplyRightTransposed(ws.q0, ws.axial, f);

  // Unmapped region = (outside in phi) x (all y)  +  (inside in phi) x (outside in y).
  const HatOverlap1D& y = ws.axial;
  LoadBalance balance;
  balance.sourceTotal_N = r * weightedSum(phi_.sourceIntegral.col(0), p, y.sourceIntegral.col(0));
  balance.unmapped_N = r * (weightedSum(phi_.outsideIntegral.col(0), p, y.sourceIntegral.col(0)) +
                            weightedSum(phi_.insideIntegral.col(0), p, y.outsideIntegral.col(0)));
  return balance;
}

CartesianLoadBalance TensorForceMap::applyTraction(
    Workspace& ws, const Eigen::Ref<const Eigen::VectorXd>& normal_Pa,
    const Eigen::Ref<const Eigen::VectorXd>& circumferential_Pa,
    const Eigen::Ref<const Eigen::VectorXd>& axial_Pa, Eigen::Ref<Eigen::VectorXd> forceX_N,
    Eigen::Ref<Eigen::VectorXd> forceY_N, Eigen::Ref<Eigen::VectorXd> forceZ_N) const {
  const char* fn = "TensorForceMap::applyTraction";
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

  // f_x = normal cos - circumferential sin,  f_z = normal sin + circumferential cos.
  multiplyLeft(phi_, phi_.valueCos, r, pn, ws.q0);
  multiplyLeft(phi_, phi_.valueSin, r, ps, ws.q1);
  ws.q0 -= ws.q1;
  multiplyRightTransposed(ws.q0, ws.axial, fx);
  multiplyLeft(phi_, phi_.valueSin, r, pn, ws.q0);
  multiplyLeft(phi_, phi_.valueCos, r, ps, ws.q1);
  ws.q0 += ws.q1;
  multiplyRightTransposed(ws.q0, ws.axial, fz);
  multiplyLeft(phi_, phi_.value, r, py, ws.q2);
  multiplyRightTransposed(ws.q2, ws.axial, fy);

  const HatOverlap1D& y = ws.axial;
  // 3-D force of the source traction over (phi region) x (y region), each region given
  // by its per-node integrals of (1, cos, sin) x shape function.
  auto total = [&](const Eigen::MatrixX3d& phiIntegral, const Eigen::MatrixX3d& yIntegral) {
    const auto wy = yIntegral.col(0);
    const double x =
        weightedSum(phiIntegral.col(1), pn, wy) - weightedSum(phiIntegral.col(2), ps, wy);
    const double z =
        weightedSum(phiIntegral.col(2), pn, wy) + weightedSum(phiIntegral.col(1), ps, wy);
    const double a = weightedSum(phiIntegral.col(0), py, wy);
    return Eigen::Vector3d(r * x, r * a, r * z);
  };
  CartesianLoadBalance balance;
  balance.sourceTotal_N = total(phi_.sourceIntegral, y.sourceIntegral);
  balance.unmapped_N =
      total(phi_.outsideIntegral, y.sourceIntegral) + total(phi_.insideIntegral, y.outsideIntegral);
  return balance;
}

// ---------------------------------------------------------------------------------------
ForceMap::ForceMap(const CylinderGrid& source, const CylinderGrid& target,
                   GridOffset sourceInTarget, LoadRule rule) {
  detail::requireFiniteScalar("ForceMap", "sourceInTarget.phi_rad", sourceInTarget.phi_rad);
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
