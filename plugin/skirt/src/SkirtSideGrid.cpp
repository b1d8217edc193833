#include "pistondyn/skirt/SkirtSideGrid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "Checks.h"
#include "OutputChecks.h"

namespace pistondyn::skirt {

namespace {

constexpr double kPi = 3.14159265358979323846;
const char* const kWhere = "SkirtSideGridParameters";

const SkirtSideGridParameters& validated(const SkirtSideGridParameters& p) {
  detail::requirePositive(kWhere, "radius_m", p.radius_m, "m");
  if (!(std::isfinite(p.arcWidth_rad) && p.arcWidth_rad > 0.0))
    detail::fail(kWhere, detail::named("arcWidth_rad", p.arcWidth_rad, "rad") +
                             " must be positive and finite");
  if (!(p.arcWidth_rad < kPi))
    detail::fail(kWhere, detail::named("arcWidth_rad", p.arcWidth_rad, "rad") +
                             " must be less than pi: a skirt grid wider than the skirt (each side "
                             "covers at most half the circumference)");
  if (p.nPhi < 3)
    detail::fail(kWhere, "nPhi = " + std::to_string(p.nPhi) + " must be at least 3");
  if (p.nY < 3)
    detail::fail(kWhere, "nY = " + std::to_string(p.nY) + " must be at least 3");
  detail::requireFinite(kWhere, "skirtTopHeight_m", p.skirtTopHeight_m, "m");
  detail::requirePositive(kWhere, "skirtLength_m", p.skirtLength_m, "m");
  detail::requireNonNegative(kWhere, "axialClustering", p.axialClustering, "");
  detail::requireNonNegative(kWhere, "circumferentialClustering", p.circumferentialClustering,
                             "");
  return p;
}

double centreAngle(SkirtSide side) {
  return side == SkirtSide::Thrust ? 0.0 : kPi;
}

// Angles relative to the centre line, (Phi / 2) xi with xi = (2i - (n-1)) / (n-1), or
// (Phi / 2) sinh(b xi) / sinh(b) with the circumferential clustering b: the integer numerator
// and the stretching of |xi| with its sign make the offsets exactly antisymmetric about the
// centre line.
Eigen::VectorXd relativeAngles(const SkirtSideGridParameters& p) {
  Eigen::VectorXd s(p.nPhi);
  const double b = p.circumferentialClustering;
  for (int i = 0; i < p.nPhi; ++i) {
    const double num = 2.0 * i - (p.nPhi - 1);
    if (b > 0.0) {
      const double xi = num / (p.nPhi - 1.0);
      s[i] = 0.5 * p.arcWidth_rad * std::copysign(std::sinh(b * std::abs(xi)) / std::sinh(b), xi);
    } else {
      s[i] = p.arcWidth_rad * (num / (2.0 * (p.nPhi - 1)));
    }
  }
  return s;
}

Eigen::VectorXd heights(const SkirtSideGridParameters& p) {
  return lubrication::FilmGrid::clusteredCoordinates(p.nY, p.skirtTopHeight_m - p.skirtLength_m,
                                                     p.skirtTopHeight_m, p.axialClustering);
}

// g(d) = (sin d - d cos d) / d = sum_{n>=1} (-1)^(n+1) 2n d^(2n) / (2n+1)!; the series avoids
// the cancellation of the closed form for the small half-widths of a fine grid.
double hatMomentG(double d) {
  if (d > 0.5)
    return (std::sin(d) - d * std::cos(d)) / d;
  const double d2 = d * d;
  double term = d2 / 3.0;  // n = 1
  double sum = term;
  for (int n = 2; n < 30; ++n) {
    // ratio of consecutive terms: -(n / (n-1)) d^2 / ((2n) (2n+1))
    term *= -d2 * n / ((n - 1.0) * (2.0 * n) * (2.0 * n + 1.0));
    sum += term;
    if (std::abs(term) < 1e-18 * std::abs(sum))
      break;
  }
  return sum;
}

// 1-D weights along phi: int N_i dphi, int N_i cos phi dphi, int N_i sin phi dphi (exact).
void phiWeights(const Eigen::VectorXd& phi, Eigen::VectorXd& a, Eigen::VectorXd& c,
                Eigen::VectorXd& s) {
  const Eigen::Index n = phi.size();
  a.setZero(n);
  c.setZero(n);
  s.setZero(n);
  for (Eigen::Index e = 0; e + 1 < n; ++e) {
    const double m = 0.5 * (phi[e] + phi[e + 1]);
    const double d = 0.5 * (phi[e + 1] - phi[e]);
    const double cm = std::cos(m), sm = std::sin(m);
    const double sind = std::sin(d);
    const double g = hatMomentG(d);
    // Falling hat of node e, rising hat of node e + 1 (phi = m + t, t in [-d, d]).
    a[e] += d;
    a[e + 1] += d;
    c[e] += cm * sind + sm * g;
    c[e + 1] += cm * sind - sm * g;
    s[e] += sm * sind - cm * g;
    s[e + 1] += sm * sind + cm * g;
  }
}

}  // namespace

SkirtSideGrid::SkirtSideGrid(const SkirtSideGridParameters& parameters)
    : side_(validated(parameters).side),
      centre_rad_(centreAngle(parameters.side)),
      radius_m_(parameters.radius_m),
      arcWidth_rad_(parameters.arcWidth_rad),
      phi_rad_((relativeAngles(parameters).array() + centre_rad_).matrix()),
      y_m_(heights(parameters)),
      filmGrid_(lubrication::FilmGrid::fromCoordinates(
          parameters.radius_m * relativeAngles(parameters), y_m_)),
      cylinderGrid_(mapping::CylinderGrid::sector(parameters.radius_m, phi_rad_, y_m_)) {
  const int n = nodeCount();
  nodePhi_rad_.resize(n);
  nodeY_m_.resize(n);
  nodeCos_.resize(n);
  nodeSin_.resize(n);
  Eigen::VectorXd a, c, s;
  phiWeights(phi_rad_, a, c, s);
  const Eigen::VectorXd& wy = filmGrid_.yWeights_m();              // int M_j dy
  const Eigen::VectorXd& my = filmGrid_.yFirstMomentWeights_m2();  // int M_j y dy
  w_.resize(n);
  wc_.resize(n);
  ws_.resize(n);
  wyc_.resize(n);
  wys_.resize(n);
  for (int j = 0; j < nY(); ++j) {
    for (int i = 0; i < nPhi(); ++i) {
      const int k = nodeIndex(i, j);
      nodePhi_rad_[k] = phi_rad_[i];
      nodeY_m_[k] = y_m_[j];
      nodeCos_[k] = std::cos(phi_rad_[i]);
      nodeSin_[k] = std::sin(phi_rad_[i]);
      w_[k] = radius_m_ * a[i] * wy[j];
      wc_[k] = radius_m_ * c[i] * wy[j];
      ws_[k] = radius_m_ * s[i] * wy[j];
      wyc_[k] = radius_m_ * c[i] * my[j];
      wys_[k] = radius_m_ * s[i] * my[j];
    }
  }
}

PistonLoads SkirtSideGrid::calcLoadsOnPiston(
    const Eigen::Ref<const Eigen::ArrayXd>& normalPressure_Pa,
    const Eigen::Ref<const Eigen::ArrayXd>& axialShear_Pa,
    const Eigen::Ref<const Eigen::ArrayXd>& circumferentialShear_Pa) const {
  const char* fn = "SkirtSideGrid::calcLoadsOnPiston";
  const Eigen::Index n = nodeCount();
  const auto checkSize = [&](const char* name, Eigen::Index size, bool mayBeEmpty) {
    if (size != n && !(mayBeEmpty && size == 0))
      detail::fail(fn, std::string(name) + " has " + std::to_string(size) + " entries, expected " +
                           std::to_string(n) + (mayBeEmpty ? " (or 0 for none)" : ""));
  };
  checkSize("normalPressure_Pa", normalPressure_Pa.size(), false);
  checkSize("axialShear_Pa", axialShear_Pa.size(), true);
  checkSize("circumferentialShear_Pa", circumferentialShear_Pa.size(), true);

  const auto& p = normalPressure_Pa;  // the Ref itself: binding it to an ArrayXd& would copy
  PistonLoads out;
  out.force_N.x() = -(p * wc_).sum();
  out.force_N.z() = -(p * ws_).sum();
  out.moment_Nm.x() = -(p * wys_).sum();
  out.moment_Nm.z() = (p * wyc_).sum();
  if (axialShear_Pa.size() > 0) {
    const auto& t = axialShear_Pa;
    out.force_N.y() += (t * w_).sum();
    out.moment_Nm.x() -= radius_m_ * (t * ws_).sum();
    out.moment_Nm.z() += radius_m_ * (t * wc_).sum();
  }
  if (circumferentialShear_Pa.size() > 0) {
    const auto& t = circumferentialShear_Pa;
    out.force_N.x() -= (t * ws_).sum();
    out.force_N.z() += (t * wc_).sum();
    out.moment_Nm.x() += (t * wyc_).sum();
    out.moment_Nm.y() -= radius_m_ * (t * w_).sum();
    out.moment_Nm.z() += (t * wys_).sum();
  }
  // One test of the result instead of three scans of the inputs: a non-finite input makes a
  // non-finite resultant; only then is the offending entry looked for and named.
  if (!(out.force_N.allFinite() && out.moment_Nm.allFinite())) {
    const auto name = [&](const char* field, const Eigen::Ref<const Eigen::ArrayXd>& v) {
      for (Eigen::Index k = 0; k < v.size(); ++k)
        if (!std::isfinite(v[k]))
          detail::fail(fn,
                       detail::named(detail::indexed(field, k), v[k], "Pa") + " must be finite");
    };
    name("normalPressure_Pa", normalPressure_Pa);
    name("axialShear_Pa", axialShear_Pa);
    name("circumferentialShear_Pa", circumferentialShear_Pa);
    detail::fail(fn, "the resultant overflowed (finite inputs too large)");
  }
  return out;
}

void SkirtSideGrid::calcAxialDerivative(const Eigen::Ref<const Eigen::ArrayXd>& field,
                                        Eigen::ArrayXd& out) const {
  detail::requireNodalSize("SkirtSideGrid::calcAxialDerivative", "field", field.size(),
                           nodeCount());
  const int nP = nPhi(), n = nY();
  out.resize(nodeCount());
  for (int j = 0; j < n; ++j) {
    // Three nodes j0 < j1 < j2 around j (shifted inwards at the ends) and the derivative of the
    // quadratic through them at y_j: Lagrange weights' derivatives.
    const int j0 = std::clamp(j - 1, 0, n - 3), j1 = j0 + 1, j2 = j0 + 2;
    const double y = y_m_[j], a = y_m_[j0], b = y_m_[j1], c = y_m_[j2];
    const double w0 = ((y - b) + (y - c)) / ((a - b) * (a - c));
    const double w1 = ((y - a) + (y - c)) / ((b - a) * (b - c));
    const double w2 = ((y - a) + (y - b)) / ((c - a) * (c - b));
    for (int i = 0; i < nP; ++i)
      out[i + nP * j] = w0 * field[i + nP * j0] + w1 * field[i + nP * j1] + w2 * field[i + nP * j2];
  }
}

}  // namespace pistondyn::skirt
