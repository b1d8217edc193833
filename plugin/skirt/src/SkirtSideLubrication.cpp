#include "pistondyn/skirt/SkirtSideLubrication.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "pistondyn/common/Validation.h"
#include "pistondyn/lubrication/GapFloor.h"

namespace pistondyn::skirt {
namespace {

constexpr const char* kConstructor = "SkirtSideLubrication";
constexpr const char* kSolve = "SkirtSideLubrication::solve";

const char* sideName(SkirtSide s) {
  return s == SkirtSide::Thrust ? "thrust" : "anti-thrust";
}

[[noreturn]] void bad(const std::string& what) {
  common::throwInvalidArgument(kConstructor, what);
}

// Checks of one call's inputs (messages: docs/CONVENTIONS.md; names are built only to throw, so
// a passing call allocates nothing).
template <class... Parts>
[[noreturn]] void badInput(const Parts&... parts) {
  common::throwInvalidArgument(kSolve, common::message(parts...));
}

void requireFiniteEntries(const Eigen::ArrayXd& a, const char* name, const char* unit,
                          SkirtSide side) {
  for (Eigen::Index k = 0; k < a.size(); ++k)
    if (!std::isfinite(a[k]))
      badInput(name, "[", k, "] = ", a[k], " ", unit, " must be finite (", sideName(side),
               " side)");
}

void requireFiniteEntries(const Eigen::MatrixXd& a, Eigen::Index cols, const char* name,
                          SkirtSide side) {
  for (Eigen::Index c = 0; c < cols; ++c)
    for (Eigen::Index k = 0; k < a.rows(); ++k)
      if (!std::isfinite(a(k, c)))
        badInput(name, "(", k, ", ", c, ") = ", a(k, c), " must be finite (", sideName(side),
                 " side)");
}

// An optional extra basis of the inputs (nullptr = none): n rows, finite.
void requireOptionalBasis(const Eigen::MatrixXd* basis, const char* name, Eigen::Index n,
                          SkirtSide side) {
  if (!basis)
    return;
  if (basis->rows() != n)
    badInput(name, " has ", basis->rows(), " rows, expected ", n, " (nodes of the ",
             sideName(side), " side)");
  requireFiniteEntries(*basis, basis->cols(), name, side);
}

// dst = src with each row scaled by slope (the film-gap clamp's); empty when src is null.
void scaleRowsInto(const Eigen::MatrixXd* src, const Eigen::ArrayXd& slope, Eigen::MatrixXd& dst) {
  if (!src) {
    if (dst.size() > 0)
      dst.resize(0, 0);
    return;
  }
  dst.resize(src->rows(), src->cols());
  for (Eigen::Index c = 0; c < src->cols(); ++c)
    dst.col(c) = (src->col(c).array() * slope).matrix();
}

void validateInputs(const GapFields& gap, const SkirtSideInputs& in, const SkirtSideGrid& grid) {
  const Eigen::Index n = grid.nodeCount();
  const SkirtSide side = grid.getSide();
  if (gap.gap_m.size() != n)
    badInput("gap.gap_m has ", gap.gap_m.size(), " entries, expected ", n, " (nodes of the ",
             sideName(side), " side)");
  if (gap.gapRate_mps.size() != n)
    badInput("gap.gapRate_mps has ", gap.gapRate_mps.size(), " entries, expected ", n,
             " (nodes of the ", sideName(side), " side)");
  if (gap.dGap_dPose.rows() != n || gap.dGap_dPose.cols() != 3)
    badInput("gap.dGap_dPose is ", gap.dGap_dPose.rows(), " x ", gap.dGap_dPose.cols(),
             ", expected ", n, " x 3 (nodes of the ", sideName(side),
             " side x lateral, tilt, tertiary)");
  if (in.squeezeColumns < 0 || in.squeezeColumns > 3)
    badInput("inputs.squeezeColumns = ", in.squeezeColumns, " must be 0..3");
  if (gap.squeezeBasis.rows() != n || gap.squeezeBasis.cols() < in.squeezeColumns)
    badInput("gap.squeezeBasis is ", gap.squeezeBasis.rows(), " x ", gap.squeezeBasis.cols(),
             ", expected ", n, " rows (nodes of the ", sideName(side),
             " side) and at least inputs.squeezeColumns = ", in.squeezeColumns, " columns");
  requireFiniteEntries(gap.gap_m, "gap.gap_m", "m", side);
  requireFiniteEntries(gap.gapRate_mps, "gap.gapRate_mps", "m/s", side);
  if (gap.skirtGapSlope.size() != 0 && gap.skirtGapSlope.size() != n)
    badInput("gap.skirtGapSlope has ", gap.skirtGapSlope.size(), " entries, expected ", n,
             " (nodes of the ", sideName(side), " side) or none");
  requireFiniteEntries(gap.skirtGapSlope, "gap.skirtGapSlope", "", side);
  requireFiniteEntries(gap.dGap_dPose, 3, "gap.dGap_dPose", side);
  requireFiniteEntries(gap.squeezeBasis, in.squeezeColumns, "gap.squeezeBasis", side);
  const FilmSensitivityRequest& extra = in.extraBases;
  requireOptionalBasis(extra.squeezeBasis, "inputs.extraBases.squeezeBasis", n, side);
  requireOptionalBasis(extra.gapBasis, "inputs.extraBases.gapBasis", n, side);
  if (extra.gapRateBasis) {
    if (!extra.gapBasis || extra.gapRateBasis->rows() != n ||
        extra.gapRateBasis->cols() != extra.gapBasis->cols())
      badInput("inputs.extraBases.gapRateBasis needs inputs.extraBases.gapBasis and its shape (",
               n, " rows, the gap basis' columns; ", sideName(side), " side)");
    requireFiniteEntries(*extra.gapRateBasis, extra.gapRateBasis->cols(),
                         "inputs.extraBases.gapRateBasis", side);
  }
  common::requirePositiveFinite(in.viscosity_Pas, kSolve, "inputs.viscosity_Pas", "Pa s");
  common::requireFinite(in.slidingVelocityAxial_mps, kSolve, "inputs.slidingVelocityAxial_mps",
                        "m/s");
  common::requireFinite(in.slidingVelocityCircumferential_mps, kSolve,
                        "inputs.slidingVelocityCircumferential_mps", "m/s");
  if (!(in.supplyFilm_m > 0.0))
    badInput("inputs.supplyFilm_m = ", in.supplyFilm_m,
             " m must be positive (+inf: fully flooded)");
  if ((in.supplyBottom_m == nullptr) != (in.supplyTop_m == nullptr))
    badInput("inputs.supplyBottom_m and inputs.supplyTop_m must be given together");
  for (const Eigen::ArrayXd* supply : {in.supplyBottom_m, in.supplyTop_m}) {
    if (!supply)
      continue;
    if (supply->size() != grid.nPhi())
      badInput("inputs.supplyBottom_m / supplyTop_m have ", supply->size(), " entries, expected ",
               grid.nPhi(), " (columns of the ", sideName(side), " side)");
    for (Eigen::Index i = 0; i < supply->size(); ++i)
      if (!((*supply)[i] >= 0.0) || !std::isfinite((*supply)[i]))
        badInput("inputs supply[", i, "] = ", (*supply)[i], " m must be >= 0 and finite");
  }
  if (std::isnan(in.timeStep_s))
    badInput("inputs.timeStep_s = ", in.timeStep_s, " s must not be NaN (+inf or <= 0: steady)");
}

// Gauss-Legendre nodes and weights on [0, 1], 6 points (exact for degree 11).
constexpr int kGauss = 6;
constexpr double kGaussX[kGauss] = {0.033765242898423975, 0.16939530676686776, 0.38069040695840156,
                                    0.61930959304159845,  0.83060469323313224, 0.96623475710157603};
constexpr double kGaussW[kGauss] = {0.085662246189585178, 0.18038078652406930,
                                    0.23395696728634552,  0.23395696728634552,
                                    0.18038078652406930,  0.085662246189585178};

// Cells whose smallest corner gap is below this many sigma get the asperity pressure
// integrated at Gauss points (F_{5/2}(4.5) is 3.2e-7 of F_{5/2}(0): beyond it the nodal
// interpolant's error is negligible).
constexpr double kContactQuadratureFilmRatio = 4.5;

// Cubic Lagrange interpolation along one grid direction, at the Gauss points of each cell:
// cell c (between nodes c and c + 1) interpolates through the four nodes first .. first + 3
// nearest to it (c - 1 .. c + 2, shifted inwards at the grid's ends; all nodes of a line of
// fewer than four), so the asperity quadrature sees the gap's curvature within a cell. The
// bilinear interpolant of a barrel or an oval skirt lies above the gap between the nodes and
// under-estimated the steep contact pressure: 7 % of the asperity load at 64 x 48 near
// h/sigma = 0.7 (lubrication/README.md's skirt grid study).
struct CellStencils {
  int points = 0;                     // nodes per stencil (4, or the line's nodes if fewer)
  std::vector<int> first;             // per cell: index of the stencil's first node
  std::vector<double> weights;        // per cell, Gauss point, stencil node
  double weight(int cell, int gauss, int m) const {
    return weights[(static_cast<std::size_t>(cell) * kGauss + gauss) * points + m];
  }
};

CellStencils makeCellStencils(const Eigen::VectorXd& nodes) {
  CellStencils s;
  const int n = static_cast<int>(nodes.size());
  s.points = std::min(4, n);
  s.first.resize(std::max(0, n - 1));
  s.weights.resize(static_cast<std::size_t>(std::max(0, n - 1)) * kGauss * s.points);
  for (int c = 0; c + 1 < n; ++c) {
    const int first = std::clamp(c - 1, 0, n - s.points);
    s.first[c] = first;
    for (int a = 0; a < kGauss; ++a) {
      const double x = nodes[c] + kGaussX[a] * (nodes[c + 1] - nodes[c]);
      for (int m = 0; m < s.points; ++m) {
        double w = 1.0;
        for (int q = 0; q < s.points; ++q)
          if (q != m)
            w *= (x - nodes[first + q]) / (nodes[first + m] - nodes[first + q]);
        s.weights[(static_cast<std::size_t>(c) * kGauss + a) * s.points + m] = w;
      }
    }
  }
  return s;
}

// (force; moment) of one PistonLoads as a 6-vector.
Eigen::Matrix<double, 6, 1> stack(const PistonLoads& l) {
  Eigen::Matrix<double, 6, 1> v;
  v << l.force_N, l.moment_Nm;
  return v;
}

}  // namespace

struct SkirtSideLubrication::Impl {
  SkirtSideGrid grid;
  std::shared_ptr<const lubrication::FlowFactorModel> flowFactors;
  std::shared_ptr<const contact_forces::AsperityContactLaw> contactLaw;
  contact_forces::BoundaryFriction friction;
  SkirtLubricationParameters parameters;
  double sigma_m = 0.0, clamp_m = 0.0;
  lubrication::FilmSolver solver;
  lubrication::FilmProblem problem;
  lubrication::FilmState warmStart;
  bool haveWarmStart = false;
  // The film-gap clamp's slope per node, and its curvature times the nominal gap rate (the
  // rate part of a gap column, below).
  Eigen::ArrayXd clampSlope, rateCurvature;
  Eigen::ArrayXd pressureColumn, shearColumnX, shearColumnY;
  Eigen::ArrayXd pressureAxial;  // the film pressure's axial traction on the sloped skirt [Pa]
  Eigen::ArrayXd couetteY, couetteX;     // film shear on the skirt (Couette + Poiseuille)
  Eigen::ArrayXXd boundaryX, boundaryY;  // boundary shear as grid-shaped scratch
  // Outward normal of the side's centre line (cos phi_c, sin phi_c) in (x, z).
  double normalX = 1.0;
  // Contact quadrature results (integrateContact).
  PistonLoads contactCorrection;  // exact minus nodal-interpolant loads
  Eigen::Matrix<double, 6, 3> contactStiffnessCorrection = Eigen::Matrix<double, 6, 3>::Zero();
  double contactPressureIntegralCorrection_N = 0.0;            // of int p_c dA
  Eigen::Vector2d shearPerPressure = Eigen::Vector2d::Zero();  // boundary (x, y) shear per Pa

  // Cubic stencils of the grid's two directions (makeCellStencils), fixed with the grid.
  CellStencils stencilPhi, stencilY;

  // The asperity pressure p_c(h) is steep (Greenwood-Tripp: F_{5/2}), and a contact at a
  // skirt edge is often narrower than a cell: the integral of the nodal interpolant then
  // misses most of it (at 32 x 24 vs 64 x 48 nodes it halved). In every cell whose
  // smallest corner gap is below kContactQuadratureFilmRatio sigma, the loads are therefore
  // integrated at 6 x 6 Gauss points of p_c(h) itself, h interpolated bicubically from the
  // 4 x 4 nearest nodes (CellStencils), and the difference to the nodal interpolant's
  // integral is added (elsewhere the interpolant is exact enough).
  void integrateContact(const GapFields& gap, const Eigen::Vector2d& skirtVelocity,
                        SkirtSideResults& out) {
    contactCorrection = PistonLoads();
    contactStiffnessCorrection.setZero();
    contactPressureIntegralCorrection_N = 0.0;
    shearPerPressure = friction.calcShearStress_Pa(1.0, skirtVelocity);
    const int nPhi = grid.nPhi(), nY = grid.nY();
    const Eigen::VectorXd& phiN = grid.getPhiNodes_rad();
    const Eigen::VectorXd& yN = grid.getYNodes_m();
    const double R = grid.getRadius_m();
    const double limit = kContactQuadratureFilmRatio * contactLaw->compositeSigma_m();
    const double* h = gap.gap_m.data();
    const double* pNode = out.contact.pressure_Pa.data();
    const double* sNode = out.contact.dPressure_dGap_PaPerM.data();
    const double tx = shearPerPressure[0], ty = shearPerPressure[1];
    for (int j = 0; j + 1 < nY; ++j) {
      for (int i = 0; i + 1 < nPhi; ++i) {
        const int k00 = i + nPhi * j, k10 = k00 + 1, k01 = k00 + nPhi, k11 = k01 + 1;
        if (std::min({h[k00], h[k10], h[k01], h[k11]}) >= limit)
          continue;
        const double dphi = phiN[i + 1] - phiN[i], dy = yN[j + 1] - yN[j];
        const double area = R * dphi * dy;
        const int firstPhi = stencilPhi.first[i], firstY = stencilY.first[j];
        // Bicubic value at Gauss point (a, b) of a nodal field f.
        auto cubic = [&](const double* f, int a, int b) {
          double v = 0.0;
          for (int q = 0; q < stencilY.points; ++q) {
            const double* row = f + firstPhi + nPhi * (firstY + q);
            double line = 0.0;
            for (int m = 0; m < stencilPhi.points; ++m)
              line += stencilPhi.weight(i, a, m) * row[m];
            v += stencilY.weight(j, b, q) * line;
          }
          return v;
        };
        for (int a = 0; a < kGauss; ++a) {
          const double t = kGaussX[a], phi = phiN[i] + t * dphi;
          const double c = std::cos(phi), sn = std::sin(phi);
          for (int b = 0; b < kGauss; ++b) {
            const double u = kGaussX[b], y = yN[j] + u * dy;
            const double n00 = (1 - t) * (1 - u), n10 = t * (1 - u), n01 = (1 - t) * u, n11 = t * u;
            const double hg = cubic(h, a, b);
            const contact_forces::PressureAndSlope ps = contactLaw->calcPressureAndSlope(hg);
            const double pInterp =
                n00 * pNode[k00] + n10 * pNode[k10] + n01 * pNode[k01] + n11 * pNode[k11];
            const double wgt = kGaussW[a] * kGaussW[b] * area;
            const double dp = (ps.pressure_Pa - pInterp) * wgt;
            contactPressureIntegralCorrection_N += dp;
            // Normal pressure, axial and circumferential boundary shear (SkirtSideGrid.h).
            Eigen::Matrix<double, 6, 1> kernel;
            kernel << -c + tx * (-sn), ty, -sn + tx * c, -y * sn - R * sn * ty + tx * y * c,
                -R * tx, y * c + R * c * ty + tx * y * sn;
            contactCorrection.force_N += dp * kernel.head<3>();
            contactCorrection.moment_Nm += dp * kernel.tail<3>();
            // Stiffness: the derivative of p_c(h_bicubic) at the point is
            // dp_c/dh(h_g) * (bicubic interpolant of dGap_dPose), that of the nodal
            // interpolant the interpolant of the nodal products s_k dGap_dPose_k; their
            // difference, with the same kernel (the boundary shear is shearPerPressure p_c
            // for the fixed sliding velocity), corrects the nodal stiffness exactly.
            for (int col = 0; col < 3; ++col) {
              const double* dh = gap.dGap_dPose.col(col).data();
              const double dhg = cubic(dh, a, b);
              const double sdInterp = n00 * sNode[k00] * dh[k00] + n10 * sNode[k10] * dh[k10] +
                                      n01 * sNode[k01] * dh[k01] + n11 * sNode[k11] * dh[k11];
              contactStiffnessCorrection.col(col) +=
                  ((ps.dPressure_dGap_PaPerM * dhg - sdInterp) * wgt) * kernel;
            }
          }
        }
      }
    }
  }

  // The film problem of a call: the clamped film gap and its rates, the derivative bases, the
  // sliding velocity, viscosity, supply and the history.
  void setFilmProblem(const GapFields& gap, const SkirtSideInputs& in) {
    lubrication::FilmProblem& p = problem;
    const int n = grid.nodeCount();
    for (int k = 0; k < n; ++k) {
      const lubrication::FlooredGap f = lubrication::calcFlooredGap(gap.gap_m[k], clamp_m);
      p.gap_m[k] = f.film_m;
      clampSlope[k] = f.slope;
      rateCurvature[k] = f.curvature_per_m * gap.gapRate_mps[k];
    }
    p.gapRate_mps = gap.gapRate_mps * clampSlope;
    setBases(gap, in);
    p.slidingVelocity_mps =
        Eigen::Vector2d(in.slidingVelocityCircumferential_mps, in.slidingVelocityAxial_mps);
    p.viscosity_Pas = in.viscosity_Pas;
    p.boundary.yMin.supplyFilm_m = in.supplyFilm_m;
    p.boundary.yMax.supplyFilm_m = in.supplyFilm_m;
    if (in.supplyBottom_m) {
      p.boundary.yMin.supplyFilmPerNode_m = *in.supplyBottom_m;
      p.boundary.yMax.supplyFilmPerNode_m = *in.supplyTop_m;
    } else if (p.boundary.yMin.supplyFilmPerNode_m.size() > 0) {
      p.boundary.yMin.supplyFilmPerNode_m.resize(0);
      p.boundary.yMax.supplyFilmPerNode_m.resize(0);
    }
    if (p.cavitation == lubrication::CavitationModel::MassConserving) {
      // The history as it is: the film solver checks it and uses what the step allows.
      if (in.history != nullptr)
        p.history = *in.history;
      else if (!p.history.empty())
        p.history = lubrication::FilmHistory();
      p.timeStep_s =
          in.timeStep_s > 0.0 ? in.timeStep_s : std::numeric_limits<double>::infinity();
    }
  }

  // The squeeze, gap and gap-rate bases of the film problem (the pose's squeeze columns and
  // the extra bases), each row scaled by the film-gap clamp's slope.
  void setBases(const GapFields& gap, const SkirtSideInputs& in) {
    lubrication::FilmProblem& p = problem;
    const int n = grid.nodeCount();
    const FilmSensitivityRequest& bases = in.extraBases;
    const Eigen::Index extra = bases.squeezeBasis ? bases.squeezeBasis->cols() : 0;
    p.squeezeBasis.resize(n, in.squeezeColumns + extra);
    for (int c = 0; c < in.squeezeColumns; ++c)
      p.squeezeBasis.col(c) = (gap.squeezeBasis.col(c).array() * clampSlope).matrix();
    for (Eigen::Index c = 0; c < extra; ++c)
      p.squeezeBasis.col(in.squeezeColumns + c) =
          (bases.squeezeBasis->col(c).array() * clampSlope).matrix();
    scaleRowsInto(bases.gapBasis, clampSlope, p.gapBasis);
    if (bases.gapBasis) {
      // The film's rate is slope(h) dh/dt, so a gap column moves it also through the clamp's
      // curvature: d(rate_f)/du_g = slope d(dh/dt)/du_g + curvature dh/dt dh/du_g. Where the gap
      // closes fast near the floor this part is as large as the others (the elastic coupling's
      // Newton steps overshoot by 2-3.5x without it).
      p.gapRateBasis.resize(n, bases.gapBasis->cols());
      for (Eigen::Index c = 0; c < bases.gapBasis->cols(); ++c) {
        p.gapRateBasis.col(c) = (bases.gapBasis->col(c).array() * rateCurvature).matrix();
        if (bases.gapRateBasis)
          p.gapRateBasis.col(c) += (bases.gapRateBasis->col(c).array() * clampSlope).matrix();
      }
    } else if (p.gapRateBasis.size() > 0) {
      p.gapRateBasis.resize(0, 0);
    }
  }

  // The film solve from the warm start; a solve that does not converge throws (naming the
  // side) and forgets the warm start.
  void solveFilm(SkirtSideResults& out) {
    solver.solve(grid.getFilmGrid(), problem, haveWarmStart ? &warmStart : nullptr, out.film);
    const lubrication::FilmResult& film = out.film;
    if (!film.converged) {
      haveWarmStart = false;  // a failed iterate is a poor start
      // the caller's clocks and counters still see this solve (out.film says what it did)
      out.contactTime_s = out.loadsTime_s = 0.0;
      throw std::runtime_error(common::message(
          kSolve, ": the ", sideName(grid.getSide()),
          " side's film solve did not converge (residual ", film.residual, " > tolerance ",
          solver.getOptions().tolerance, " after ", film.iterations, " iterations",
          film.usedFallback ? ", reference-solver fallback included" : "", ")"));
    }
    warmStart = film.state;
    haveWarmStart = true;
    out.filmGap_m = problem.gap_m;
  }

  // Asperity contact on the nominal gap, boundary friction with the skirt's velocity -U, and
  // the Gauss-point integrals where the contact is active (integrateContact).
  void calcContact(const GapFields& gap, SkirtSideResults& out) {
    const int n = grid.nodeCount();
    const Eigen::Map<const Eigen::ArrayXXd> nominal(gap.gap_m.data(), grid.nPhi(), grid.nY());
    contactLaw->calcField(nominal, out.contact);
    const Eigen::Vector2d skirtVelocity = -problem.slidingVelocity_mps;
    friction.calcShearStressField(out.contact.pressure_Pa, skirtVelocity, boundaryX, boundaryY);
    out.boundaryShearCircumferential_Pa = Eigen::Map<const Eigen::ArrayXd>(boundaryX.data(), n);
    out.boundaryShearAxial_Pa = Eigen::Map<const Eigen::ArrayXd>(boundaryY.data(), n);
    integrateContact(gap, skirtVelocity, out);
  }

  // The film pressure's axial traction on the skirt, -(p - p_ref) slope (GapFields::
  // skirtGapSlope; none where the skirt surface is parallel to the axis or no slope is given).
  void calcPressureAxialTraction(const GapFields& gap, const Eigen::ArrayXd& pressure_Pa,
                                 Eigen::ArrayXd& traction_Pa) const {
    if (gap.skirtGapSlope.size() == 0)
      traction_Pa.setZero(pressure_Pa.size());
    else
      traction_Pa = -pressure_Pa * gap.skirtGapSlope;
  }

  // Tractions and loads: the film's (pressure, its axial component on the sloped skirt, shear)
  // and the asperities' (contact pressure and boundary shear, with the Gauss correction).
  void calcLoads(const GapFields& gap, SkirtSideResults& out) {
    const int n = grid.nodeCount();
    const lubrication::FilmResult& film = out.film;
    const lubrication::SurfaceShear& shear = film.shearOnSurface2;
    pressureColumn = film.pressure_Pa() - problem.referencePressure_Pa;
    calcPressureAxialTraction(gap, pressureColumn, pressureAxial);
    couetteY = shear.couetteY_Pa + shear.poiseuilleY_Pa + pressureAxial;
    couetteX = shear.couetteX_Pa + shear.poiseuilleX_Pa;
    out.hydrodynamicLoads = grid.calcLoadsOnPiston(pressureColumn, couetteY, couetteX);
    const Eigen::Map<const Eigen::ArrayXd> pc(out.contact.pressure_Pa.data(), n);
    out.asperityLoads =
        grid.calcLoadsOnPiston(pc, out.boundaryShearAxial_Pa, out.boundaryShearCircumferential_Pa);
    out.asperityLoads.force_N += contactCorrection.force_N;
    out.asperityLoads.moment_Nm += contactCorrection.moment_Nm;
    out.totalLoads.force_N = out.hydrodynamicLoads.force_N + out.asperityLoads.force_N;
    out.totalLoads.moment_Nm = out.hydrodynamicLoads.moment_Nm + out.asperityLoads.moment_Nm;
    out.normalPressure_Pa = pressureColumn + pc;
  }

  // Derivatives: the film's squeeze columns (its pressure with the pressure's axial traction),
  // the asperity stiffness (contact pressure and the boundary shear it carries, for the fixed
  // sliding velocity, with the Gauss correction).
  void calcDerivatives(const GapFields& gap, int squeezeColumns, SkirtSideResults& out) {
    const int n = grid.nodeCount();
    out.dLoads_dPoseRate.setZero();
    out.dLoads_dPose.setZero();
    for (int c = 0; c < squeezeColumns; ++c) {
      pressureColumn = out.film.dPressure_dVelocity.col(c).array();
      calcPressureAxialTraction(gap, pressureColumn, shearColumnY);
      out.dLoads_dPoseRate.col(c) =
          stack(grid.calcLoadsOnPiston(pressureColumn, shearColumnY, Eigen::ArrayXd()));
    }
    const Eigen::Map<const Eigen::ArrayXd> slope(out.contact.dPressure_dGap_PaPerM.data(), n);
    for (int c = 0; c < 3; ++c) {
      pressureColumn = slope * gap.dGap_dPose.col(c).array();
      shearColumnX = shearPerPressure[0] * pressureColumn;
      shearColumnY = shearPerPressure[1] * pressureColumn;
      out.dLoads_dPose.col(c) =
          stack(grid.calcLoadsOnPiston(pressureColumn, shearColumnY, shearColumnX)) +
          contactStiffnessCorrection.col(c);
    }
  }

  // The side's figures (SkirtSideFigures): normal loads, friction, powers, films, regime shares,
  // oil, wear.
  void calcFigures(const GapFields& gap, SkirtSideResults& out) const {
    const int n = grid.nodeCount();
    const lubrication::FilmResult& film = out.film;
    const Eigen::ArrayXd& w = grid.getAreaWeights_m2();
    const Eigen::Map<const Eigen::ArrayXd> pc(out.contact.pressure_Pa.data(), n);
    // Normal loads: minus the force component along the side's outward normal (x here; the
    // z components of the two halves of a side cancel for a centred load).
    out.hydrodynamicNormalForce_N = -normalX * out.hydrodynamicLoads.force_N[0];
    out.asperityNormalForce_N = -normalX * out.asperityLoads.force_N[0];
    out.hydrodynamicFrictionAxial_N = (w * couetteY).sum();
    out.pressureFrictionAxial_N = (w * pressureAxial).sum();
    const double contactLoad_N = (w * pc).sum() + contactPressureIntegralCorrection_N;
    out.asperityFrictionAxial_N = shearPerPressure[1] * contactLoad_N;
    const double hydroCirc = (w * couetteX).sum();
    const double asperityCirc = shearPerPressure[0] * contactLoad_N;
    const Eigen::Vector2d& U = problem.slidingVelocity_mps;
    out.hydrodynamicFrictionPower_W = U[1] * out.hydrodynamicFrictionAxial_N + U[0] * hydroCirc;
    out.asperityFrictionPower_W = U[1] * out.asperityFrictionAxial_N + U[0] * asperityCirc;
    out.frictionPower_W = out.hydrodynamicFrictionPower_W + out.asperityFrictionPower_W;
    out.filmDissipation_W = film.viscousDissipation_W;
    out.dissipatedPower_W = out.filmDissipation_W + out.asperityFrictionPower_W;

    Eigen::Index kMin = 0;
    out.minFilmThickness_m = gap.gap_m.minCoeff(&kMin);
    out.minFilmPhi_rad = grid.getNodePhi_rad()[kMin];
    out.minFilmY_m = grid.getNodeY_m()[kMin];
    out.minGapOverSigma =
        sigma_m > 0.0 ? out.minFilmThickness_m / sigma_m : std::numeric_limits<double>::max();
    double hydro = 0.0, mixed = 0.0, boundary = 0.0, wetted = 0.0, maxPc = 0.0;
    for (int k = 0; k < n; ++k) {
      const double ratio = out.contact.filmRatio.data()[k];
      if (ratio > contact_forces::kMixedRegimeUpperFilmRatio)
        hydro += w[k];
      else if (ratio > contact_forces::kBoundaryRegimeUpperFilmRatio)
        mixed += w[k];
      else
        boundary += w[k];
      if (film.fillFraction()[k] > 0.0)
        wetted += w[k];
      maxPc = std::max(maxPc, pc[k]);
    }
    const double area = w.sum();
    out.hydrodynamicShare = hydro / area;
    out.mixedShare = mixed / area;
    out.boundaryShare = boundary / area;
    out.wettedShare = wetted / area;
    out.filmOilVolume_m3 = (w * film.fillFraction() * problem.gap_m).sum();
    const double speed = U.norm();
    out.wearRate_m3ps = parameters.wearCoefficient_m2pN * contactLoad_N * speed;
    out.maxWearDepthRate_mps = parameters.wearCoefficient_m2pN * maxPc * speed;
  }

  Impl(const SkirtSideGrid& g, std::shared_ptr<const lubrication::FlowFactorModel> ff,
       std::shared_ptr<const contact_forces::AsperityContactLaw> law,
       const contact_forces::BoundaryFriction& f, const SkirtLubricationParameters& p)
      : grid(g),
        flowFactors(std::move(ff)),
        contactLaw(std::move(law)),
        friction(f),
        parameters(p),
        solver(p.solver) {
    if (!flowFactors)
      bad("flowFactors is null");
    if (!contactLaw)
      bad("contactLaw is null");
    common::requirePositiveFinite(p.clampFraction, kConstructor, "parameters.clampFraction", "");
    common::requirePositiveFinite(p.minimumClampGap_m, kConstructor, "parameters.minimumClampGap_m",
                                  "m");
    common::requireNonNegativeFinite(p.wearCoefficient_m2pN, kConstructor,
                                     "parameters.wearCoefficient_m2pN", "m^2/N");
    common::requireFinite(p.cavitationPressure_Pa, kConstructor, "parameters.cavitationPressure_Pa",
                          "Pa");
    common::requireFinite(p.edgePressure_Pa, kConstructor, "parameters.edgePressure_Pa", "Pa");
    // The mass-conserving model has no solution with an open edge below p_cav (FilmProblem.h):
    // say so here, in the caller's names, rather than at the first solve.
    if (p.cavitation == lubrication::CavitationModel::MassConserving &&
        p.edgePressure_Pa < p.cavitationPressure_Pa)
      bad(common::message(
          "parameters.edgePressure_Pa = ", p.edgePressure_Pa,
          " Pa is below parameters.cavitationPressure_Pa = ", p.cavitationPressure_Pa,
          " Pa; the mass-conserving model needs the edges at or above it"));
    sigma_m = flowFactors->compositeSigma_m();
    const double lawSigma = contactLaw->compositeSigma_m();
    if (sigma_m > 0.0 && std::abs(lawSigma - sigma_m) > 1e-9 * sigma_m) {
      bad(common::message("the flow factors' composite roughness sigma = ", sigma_m,
                          " m and the contact law's sigma = ", lawSigma,
                          " m differ: enter one roughness pair (Rq of liner and skirt) for both"));
    }
    if (sigma_m == 0.0)
      sigma_m = lawSigma;
    clamp_m = std::max(p.clampFraction * sigma_m, p.minimumClampGap_m);
    normalX = grid.getSide() == SkirtSide::Thrust ? 1.0 : -1.0;
    stencilPhi = makeCellStencils(grid.getPhiNodes_rad());
    stencilY = makeCellStencils(grid.getYNodes_m());

    const int n = grid.nodeCount();
    problem.gap_m.resize(n);
    problem.gapRate_mps.resize(n);
    problem.flowFactors = flowFactors.get();
    problem.cavitation = p.cavitation;
    problem.cavitationPressure_Pa = p.cavitationPressure_Pa;
    for (lubrication::FilmEdge* e : {&problem.boundary.xMin, &problem.boundary.xMax,
                                     &problem.boundary.yMin, &problem.boundary.yMax}) {
      e->pressure_Pa = p.edgePressure_Pa;
    }
    problem.referencePressure_Pa = p.edgePressure_Pa;
    problem.faces = p.faceValues;
    problem.fillFractionFlux = p.fillFractionFlux;
    // LinearGap faces integrate along the nominal gap through the clamp's knee (GapFloor.h).
    problem.gapFloor_m = p.faceValues == lubrication::FaceValues::LinearGap ? clamp_m : 0.0;
    clampSlope.resize(n);
    rateCurvature.resize(n);
  }
};

SkirtSideLubrication::SkirtSideLubrication(
    const SkirtSideGrid& grid, std::shared_ptr<const lubrication::FlowFactorModel> flowFactors,
    std::shared_ptr<const contact_forces::AsperityContactLaw> contactLaw,
    const contact_forces::BoundaryFriction& friction, const SkirtLubricationParameters& parameters)
    : impl_(std::make_unique<Impl>(grid, std::move(flowFactors), std::move(contactLaw), friction,
                                   parameters)) {}

SkirtSideLubrication::~SkirtSideLubrication() = default;
SkirtSideLubrication::SkirtSideLubrication(SkirtSideLubrication&&) noexcept = default;
SkirtSideLubrication& SkirtSideLubrication::operator=(SkirtSideLubrication&&) noexcept = default;

const SkirtSideGrid& SkirtSideLubrication::getGrid() const {
  return impl_->grid;
}
const SkirtLubricationParameters& SkirtSideLubrication::getParameters() const {
  return impl_->parameters;
}
double SkirtSideLubrication::getCompositeSigma_m() const {
  return impl_->sigma_m;
}
double SkirtSideLubrication::getClampGap_m() const {
  return impl_->clamp_m;
}
void SkirtSideLubrication::resetWarmStart() {
  impl_->haveWarmStart = false;
}

void SkirtSideLubrication::solve(const GapFields& gap, const SkirtSideInputs& in,
                                 SkirtSideResults& out) {
  Impl& m = *impl_;
  validateInputs(gap, in, m.grid);
  m.setFilmProblem(gap, in);
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  m.solveFilm(out);
  const auto t1 = Clock::now();
  out.filmTime_s = std::chrono::duration<double>(t1 - t0).count();
  m.calcContact(gap, out);
  const auto t2 = Clock::now();
  m.calcLoads(gap, out);
  m.calcDerivatives(gap, in.squeezeColumns, out);
  m.calcFigures(gap, out);
  out.contactTime_s = std::chrono::duration<double>(t2 - t1).count();
  out.loadsTime_s = std::chrono::duration<double>(Clock::now() - t2).count();
}

}  // namespace pistondyn::skirt
