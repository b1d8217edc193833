#pragma once
// Helpers for the ElasticCoupling tests that do not use the code under test: a half-space
// (Boussinesq) compliance built from Love's closed-form patch integral, a reader of the
// committed FE compliance files (plain text parsing, independent of pistondyn::io), and a
// smooth gap clamp.

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "pistondyn/mapping/StructuralCompliance.h"
#include "pistondyn/skirt/SkirtSideGrid.h"

namespace pistondyn::skirt::test {

// Integral of 1/r over the rectangle [x1, x2] x [y1, y2] seen from the origin [m].
inline double inverseDistanceOverRectangle(double x1, double x2, double y1, double y2) {
  // Split at the origin's lines so that every piece lies in one quadrant (the antiderivative
  // above is for X, Y of one sign: use |.| per piece).
  const auto quadrant = [](double a, double b) {  // [0, a] x [0, b], a, b >= 0
    if (a <= 0.0 || b <= 0.0)
      return 0.0;
    const double r = std::hypot(a, b);
    return a * std::log((b + r) / a) + b * std::log((a + r) / b);
  };
  // Signed integral of the quadrant function over [0, x] x [0, y] for any signs.
  const auto corner = [&](double x, double y) {
    const double s = (x < 0.0 ? -1.0 : 1.0) * (y < 0.0 ? -1.0 : 1.0);
    return s * quadrant(std::abs(x), std::abs(y));
  };
  return corner(x2, y2) - corner(x1, y2) - corner(x2, y1) + corner(x1, y1);
}

// Half-space compliance on a tensor grid of the developed surface (s = R phi, y): the load of
// node J spread uniformly over its tributary rectangle (cell-width patch), the displacement
// read at node I's point (Johnson's influence coefficients of piecewise-constant pressure):
//   C_IJ = (1 - nu^2) / (pi E) * (1 / |patch J|) * integral over patch J of dA / |x_I - x|.
// Symmetrised. Grid layout of StructuralCompliance (phi fastest). Uniform spacing expected.
inline mapping::StructuralCompliance halfSpaceCompliance(double radius_m,
                                                         const Eigen::VectorXd& phi_rad,
                                                         const Eigen::VectorXd& y_m,
                                                         double youngs_Pa, double poisson) {
  constexpr double pi = 3.14159265358979323846;
  mapping::StructuralCompliance c;
  c.phi_rad = phi_rad;
  c.y_m = y_m;
  c.fullCircle = false;
  const int np = static_cast<int>(phi_rad.size()), ny = static_cast<int>(y_m.size());
  const int n = np * ny;
  const double hs = radius_m * (phi_rad[1] - phi_rad[0]), hy = y_m[1] - y_m[0];
  const double factor = (1.0 - poisson * poisson) / (pi * youngs_Pa) / (hs * hy);
  c.compliance_m_per_N.resize(n, n);
  for (int j = 0; j < n; ++j) {
    const double sj = radius_m * phi_rad[j % np], yj = y_m[j / np];
    for (int i = 0; i < n; ++i) {
      const double si = radius_m * phi_rad[i % np], yi = y_m[i / np];
      const double dx = sj - si, dy = yj - yi;  // patch centre relative to the read point
      c.compliance_m_per_N(i, j) =
          factor * inverseDistanceOverRectangle(dx - hs / 2, dx + hs / 2, dy - hy / 2, dy + hy / 2);
    }
  }
  const Eigen::MatrixXd sym = 0.5 * (c.compliance_m_per_N + c.compliance_m_per_N.transpose());
  c.compliance_m_per_N = sym;
  return c;
}

// The committed FE compliance (examples/fe/): Matrix Market "array real general" (column-major)
// and the node table node,phi_deg,y_mm,gas_u_r_um_per_MPa. Plain parsing, no checks beyond
// the sizes: the io reader and its tests own the validation.
inline mapping::StructuralCompliance readCommittedCompliance(const std::string& mtxPath,
                                                             const std::string& nodesPath) {
  constexpr double degToRad = 3.14159265358979323846 / 180.0;
  std::ifstream nodes(nodesPath);
  if (!nodes)
    throw std::runtime_error("cannot open " + nodesPath);
  std::vector<double> phiDeg, yMm, gas;
  std::string line;
  bool header = false;
  while (std::getline(nodes, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    if (!header) {
      header = true;
      continue;
    }
    std::stringstream ss(line);
    std::string field;
    std::vector<double> v;
    while (std::getline(ss, field, ','))
      v.push_back(std::stod(field));
    phiDeg.push_back(v.at(1));
    yMm.push_back(v.at(2));
    if (v.size() > 3)
      gas.push_back(v[3]);
  }
  // Tensor grid, phi fastest: the first row's angles, and one height per row.
  std::vector<double> phis, ys;
  for (size_t k = 0; k < phiDeg.size(); ++k) {
    if (yMm[k] == yMm[0])
      phis.push_back(phiDeg[k]);
    if (ys.empty() || yMm[k] != ys.back())
      ys.push_back(yMm[k]);
  }
  mapping::StructuralCompliance c;
  c.phi_rad = Eigen::Map<Eigen::VectorXd>(phis.data(), phis.size()) * degToRad;
  c.y_m = Eigen::Map<Eigen::VectorXd>(ys.data(), ys.size()) * 1e-3;
  c.fullCircle = true;
  const Eigen::Index n = static_cast<Eigen::Index>(phiDeg.size());
  if (c.nodeCount() != n)
    throw std::runtime_error("node table is not a tensor grid");
  if (!gas.empty())
    c.gasDisplacement_m_per_Pa = Eigen::Map<Eigen::VectorXd>(gas.data(), gas.size()) * 1e-12;

  std::ifstream mtx(mtxPath);
  if (!mtx)
    throw std::runtime_error("cannot open " + mtxPath);
  bool sized = false;
  Eigen::Index rows = 0, cols = 0, k = 0;
  while (std::getline(mtx, line)) {
    if (line.empty() || line[0] == '%')
      continue;
    std::stringstream ss(line);
    if (!sized) {
      ss >> rows >> cols;
      if (rows != n || cols != n)
        throw std::runtime_error("matrix size differs from the nodes");
      c.compliance_m_per_N.resize(rows, cols);
      sized = true;
      continue;
    }
    double v = 0.0;
    ss >> v;
    c.compliance_m_per_N(k % rows, k / rows) = v;
    ++k;
  }
  if (k != rows * cols)
    throw std::runtime_error("matrix has too few entries");
  return c;
}

// The skirt's film-gap clamp shape (SkirtSideLubrication.h): smooth, >= hc.
inline double smoothClamp(double h, double hc) {
  return 0.5 * (h + hc + std::sqrt((h - hc) * (h - hc) + hc * hc));
}

// The gasoline example's committed FE files (examples/fe/gasoline_1400_2000rpm), by the plain
// parser above: "skirt" or "liner".
inline mapping::StructuralCompliance gasolineCompliance(const std::string& part) {
  const std::string dir =
      std::string(PISTONDYN_SOURCE_DIR) + "/examples/fe/gasoline_1400_2000rpm/";
  return readCommittedCompliance(dir + part + "_compliance.mtx", dir + part + "_nodes.csv");
}

// The gasoline example's thrust side (examples/engines/gasoline_1400_2000rpm/engine.yaml):
// bore 74.5 mm, skirt 30 mm from 12 mm above the pin axis, 80 deg sides; the film grid
// coarser than the deck's 64 x 48 to keep the tests fast.
inline SkirtSideGrid gasolineThrustSide(int nPhi = 40, int nY = 30) {
  SkirtSideGridParameters gp;
  gp.side = SkirtSide::Thrust;
  gp.radius_m = 0.0745 / 2.0;
  gp.arcWidth_rad = 80.0 * 3.14159265358979323846 / 180.0;
  gp.skirtTopHeight_m = 0.012;
  gp.skirtLength_m = 0.030;
  gp.nPhi = nPhi;
  gp.nY = nY;
  return SkirtSideGrid(gp);
}

}  // namespace pistondyn::skirt::test
