#include "pistondyn/io/ComplianceInput.h"

#include <cmath>
#include <sstream>

#include <Eigen/Cholesky>

#include "pistondyn/io/CsvTable.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/MatrixMarket.h"
#include "pistondyn/io/Units.h"

namespace pistondyn::io {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

std::string num(double v) {
  std::ostringstream s;
  s.precision(9);
  s << v;
  return s.str();
}

// The one column whose name starts with `prefix` and ends with a unit of `quantity`.
std::string findColumn(const CsvTable& t, const std::string& prefix, Quantity quantity,
                       const std::string& example) {
  std::string found;
  for (const std::string& c : t.columns) {
    if (c.rfind(prefix, 0) == 0 && findUnitSuffix(c, quantity)) {
      if (!found.empty()) {
        throw DeckError(t.filePath + ": two " + getQuantityName(quantity) + " columns '" + found +
                        "' and '" + c + "'; expected one (e.g. '" + example + "')");
      }
      found = c;
    }
  }
  if (found.empty()) {
    throw DeckError(t.filePath + ": no column '" + prefix + "<" + getQuantityName(quantity) +
                    " unit>' (e.g. '" + example +
                    "'); header: node,phi_deg,y_mm[,gas_u_r_um_per_MPa]");
  }
  return found;
}

struct NodeTable {
  Eigen::VectorXd phi_rad, y_m, gas_m_per_Pa;
  bool fullCircle = false;
};

NodeTable readNodeTable(const std::string& path) {
  const CsvTable t = readCsvTable(path, {"node"});
  if (t.rows.empty()) {
    throw DeckError(path + ": the node table has no rows");
  }
  const std::vector<double> id = t.getColumn("node");
  const std::vector<double> phi =
      t.getColumnSI(findColumn(t, "phi_", Quantity::Angle, "phi_deg"), Quantity::Angle);
  const std::vector<double> y =
      t.getColumnSI(findColumn(t, "y_", Quantity::Length, "y_mm"), Quantity::Length);
  const std::size_t n = t.rows.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (id[k] != static_cast<double>(k + 1)) {
      throw DeckError(t.where(k) + ": node " + num(id[k]) + ", expected " + std::to_string(k + 1) +
                      " (nodes numbered 1, 2, ... in the order of the "
                      "matrix rows)");
    }
    if (!(phi[k] >= 0.0 && phi[k] < kTwoPi)) {
      throw DeckError(t.where(k) + ": angle " + num(phi[k] * 360.0 / kTwoPi) +
                      " deg outside [0, 360)");
    }
  }
  // Tensor grid, phi fastest: the first row ends where the height changes.
  const double yRange = std::abs(y.back() - y.front());
  const double yTol = 1e-9 * std::max(yRange, 1e-3);
  std::size_t nPhi = 1;
  while (nPhi < n && std::abs(y[nPhi] - y[0]) <= yTol)
    ++nPhi;
  if (n % nPhi != 0) {
    throw DeckError(path + ": " + std::to_string(n) + " nodes, not a multiple of the " +
                    std::to_string(nPhi) +
                    " angles of the first row: expected a tensor grid "
                    "(every row the same angles, phi fastest)");
  }
  const std::size_t nY = n / nPhi;
  NodeTable out;
  out.phi_rad.resize(static_cast<Eigen::Index>(nPhi));
  out.y_m.resize(static_cast<Eigen::Index>(nY));
  for (std::size_t i = 0; i < nPhi; ++i) {
    out.phi_rad[static_cast<Eigen::Index>(i)] = phi[i];
    if (i > 0 && !(phi[i] > phi[i - 1])) {
      throw DeckError(t.where(i) + ": angle " + num(phi[i] * 360.0 / kTwoPi) +
                      " deg not above the previous one: angles must increase along a row");
    }
  }
  for (std::size_t j = 0; j < nY; ++j) {
    out.y_m[static_cast<Eigen::Index>(j)] = y[j * nPhi];
    if (j > 0 && !(y[j * nPhi] > y[(j - 1) * nPhi] + yTol)) {
      throw DeckError(t.where(j * nPhi) + ": height " + num(y[j * nPhi]) +
                      " m not above the previous row's: heights must increase row by row");
    }
    for (std::size_t i = 0; i < nPhi; ++i) {
      const std::size_t k = i + nPhi * j;
      if (std::abs(phi[k] - phi[i]) > 1e-9) {
        throw DeckError(t.where(k) + ": angle " + num(phi[k] * 360.0 / kTwoPi) + " deg, expected " +
                        num(phi[i] * 360.0 / kTwoPi) +
                        " deg as in the first row (tensor grid, phi fastest)");
      }
      if (std::abs(y[k] - y[j * nPhi]) > yTol) {
        throw DeckError(t.where(k) + ": height " + num(y[k]) + " m, expected " + num(y[j * nPhi]) +
                        " m as the row's first node (tensor grid, phi "
                        "fastest)");
      }
    }
  }
  // Full circle: equally spaced over 2 pi.
  if (nPhi >= 3) {
    const double step = kTwoPi / static_cast<double>(nPhi);
    bool equal = true;
    for (std::size_t i = 0; i < nPhi; ++i)
      equal = equal && std::abs(phi[i] - phi[0] - step * static_cast<double>(i)) <= 1e-9;
    out.fullCircle = equal;
  }
  const bool gasUm = t.hasColumn("gas_u_r_um_per_MPa"), gasM = t.hasColumn("gas_u_r_m_per_Pa");
  if (gasUm && gasM) {
    throw DeckError(path + ": both gas_u_r_um_per_MPa and gas_u_r_m_per_Pa; expected one");
  }
  if (gasUm || gasM) {
    const std::vector<double> g = t.getColumn(gasUm ? "gas_u_r_um_per_MPa" : "gas_u_r_m_per_Pa");
    const double factor = gasUm ? 1e-12 : 1.0;  // um/MPa = 1e-6 m / 1e6 Pa
    out.gas_m_per_Pa.resize(static_cast<Eigen::Index>(n));
    for (std::size_t k = 0; k < n; ++k)
      out.gas_m_per_Pa[static_cast<Eigen::Index>(k)] = g[k] * factor;
  }
  return out;
}

}  // namespace

mapping::StructuralCompliance readStructuralCompliance(const std::string& matrixPath,
                                                       const std::string& nodeTablePath,
                                                       const ComplianceReadOptions& options) {
  if (!(options.matrixToSI > 0.0 && std::isfinite(options.matrixToSI)) ||
      !(options.symmetryTolerance >= 0.0 && std::isfinite(options.symmetryTolerance))) {
    throw std::invalid_argument(
        "readStructuralCompliance: options.matrixToSI must be > 0 and "
        "options.symmetryTolerance >= 0, both finite");
  }
  NodeTable nodes = readNodeTable(nodeTablePath);
  // The node count sizes the matrix: a header claiming more is refused before allocating.
  const Eigen::Index n = nodes.phi_rad.size() * nodes.y_m.size();
  Eigen::MatrixXd c =
      readMatrixMarketDense(matrixPath, n,
                            " for the " + std::to_string(n) + " nodes of " + nodeTablePath) *
      options.matrixToSI;
  if (!c.allFinite()) {  // only reachable through matrixToSI overflow: entries are checked
    throw DeckError(matrixPath + ": entries overflow after the unit conversion");
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!(c(k, k) > 0.0)) {
      throw DeckError(matrixPath + ": diagonal entry (" + std::to_string(k + 1) + ", " +
                      std::to_string(k + 1) + ") = " + num(c(k, k)) +
                      ": a compliance's diagonal must be positive (a push moves its own node)");
    }
  }
  const double scale = c.diagonal().maxCoeff();
  Eigen::Index wi = 0, wj = 0;
  const double worst = (c - c.transpose()).cwiseAbs().maxCoeff(&wi, &wj);
  if (worst > options.symmetryTolerance * scale) {
    const Eigen::Index i = std::max(wi, wj), j = std::min(wi, wj);
    throw DeckError(matrixPath + ": not symmetric: entry (" + std::to_string(i + 1) + ", " +
                    std::to_string(j + 1) + ") = " + num(c(i, j)) + " but (" +
                    std::to_string(j + 1) + ", " + std::to_string(i + 1) + ") = " + num(c(j, i)) +
                    "; the difference is " + num(worst / scale) +
                    " of the largest diagonal entry, allowed " + num(options.symmetryTolerance) +
                    " (Maxwell-Betti reciprocity)");
  }
  mapping::StructuralCompliance out;
  out.compliance_m_per_N = 0.5 * (c + c.transpose());
  const Eigen::LLT<Eigen::MatrixXd> llt(out.compliance_m_per_N);
  if (llt.info() != Eigen::Success) {
    throw DeckError(matrixPath +
                    ": not positive definite (its Cholesky factorisation fails): "
                    "some force pattern would do no work on the structure");
  }
  out.phi_rad = std::move(nodes.phi_rad);
  out.y_m = std::move(nodes.y_m);
  out.fullCircle = nodes.fullCircle;
  out.gasDisplacement_m_per_Pa = std::move(nodes.gas_m_per_Pa);
  return out;
}

}  // namespace pistondyn::io
