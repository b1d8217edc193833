#include "FilmPostprocess.h"

#include <algorithm>
#include <cmath>

namespace pistondyn::lubrication::detail {

namespace {

// The Stencil3 of node i along the axis with coordinates c (FilmPostprocess.h).
Stencil3 derivativeStencil(const Eigen::VectorXd& c, int i, bool periodic, double period) {
  const int n = static_cast<int>(c.size());
  if (periodic || (i > 0 && i < n - 1)) {
    const int im = (i - 1 + n) % n, ip = (i + 1) % n;
    const double a = (i > 0) ? c[i] - c[im] : c[i] + period - c[im];
    const double b = (i < n - 1) ? c[ip] - c[i] : c[ip] + period - c[i];
    return {im, i, ip, -b / (a * (a + b)), (b - a) / (a * b), a / (b * (a + b))};
  }
  if (i == 0) {
    const double a = c[1] - c[0], b = c[2] - c[1];
    return {0, 1, 2, -(2.0 * a + b) / (a * (a + b)), (a + b) / (a * b), -a / (b * (a + b))};
  }
  const double a = c[n - 1] - c[n - 2], b = c[n - 2] - c[n - 3];
  return {
      n - 3, n - 2, n - 1, a / (b * (a + b)), -(a + b) / (a * b), (2.0 * a + b) / (a * (a + b))};
}

void resizeShear(SurfaceShear& s, int n) {
  s.couetteX_Pa.resize(n);
  s.couetteY_Pa.resize(n);
  s.poiseuilleX_Pa.resize(n);
  s.poiseuilleY_Pa.resize(n);
}

void integrateShear(SurfaceShear& s, const FilmGrid& grid, const Eigen::Vector2d& point) {
  const Eigen::ArrayXd& A = grid.areaWeights_m2();
  s.couetteForce_N = {(A * s.couetteX_Pa).sum(), (A * s.couetteY_Pa).sum()};
  s.poiseuilleForce_N = {(A * s.poiseuilleX_Pa).sum(), (A * s.poiseuilleY_Pa).sum()};
  double mc = 0.0, mp = 0.0;
  for (int j = 0; j < grid.ny(); ++j) {
    const double dy = grid.y_m()[j] - point.y();
    for (int i = 0; i < grid.nx(); ++i) {
      const int k = grid.nodeIndex(i, j);
      const double dx = grid.x_m()[i] - point.x();
      mc += A[k] * (dx * s.couetteY_Pa[k] - dy * s.couetteX_Pa[k]);
      mp += A[k] * (dx * s.poiseuilleY_Pa[k] - dy * s.poiseuilleX_Pa[k]);
    }
  }
  s.couetteMoment_Nm = mc;
  s.poiseuilleMoment_Nm = mp;
}

struct LoadAndMoments {
  double load = 0.0, firstMomentX = 0.0, firstMomentY = 0.0;
};

// Load and first moments about point c of the nodal field q(k) (a pressure or a pressure
// derivative).
template <class NodalField>
LoadAndMoments integrateLoad(const FilmGrid& grid, const Eigen::Vector2d& c, int n, NodalField q) {
  const Eigen::ArrayXd& A = grid.areaWeights_m2();
  LoadAndMoments r;
  for (int k = 0; k < n; ++k) {
    const double v = q(k);
    r.load += A[k] * v;
    r.firstMomentX += (grid.xFirstMomentWeights_m3()[k] - c.x() * A[k]) * v;
    r.firstMomentY += (grid.yFirstMomentWeights_m3()[k] - c.y() * A[k]) * v;
  }
  return r;
}

// FilmResult::viscousDissipation_W: the Couette part at the nodes, the Poiseuille part over the
// faces (each east and north face once) with the system's transmissibilities.
double calcViscousDissipation_W(const FilmGrid& grid, const FilmProblem& pr, const FilmSystem& s,
                                const Eigen::ArrayXd& fillFraction) {
  const Eigen::ArrayXd& A = grid.areaWeights_m2();
  const double speed2 = pr.slidingVelocity_mps.squaredNorm();
  double couette = 0.0, poiseuille = 0.0;
  for (int k = 0; k < s.n; ++k) {
    couette += A[k] * fillFraction[k] * s.eta[k] * speed2 * s.phiF[k] / pr.gap_m[k];
    const int e = s.nbE[k], no = s.nbN[k];
    if (e != k)
      poiseuille += s.tE[k] * (s.p[k] - s.p[e]) * (s.p[k] - s.p[e]);
    if (no != k)
      poiseuille += s.tN[k] * (s.p[k] - s.p[no]) * (s.p[k] - s.p[no]);
  }
  return couette + poiseuille;
}

}  // namespace

void postprocess(const FilmGrid& grid, const FilmProblem& pr, const FilmSystem& s,
                 const Eigen::MatrixXd* dP, PostprocessWorkspace& ws, FilmResult& res) {
  const int n = s.n, nx = s.nx, ny = s.ny;
  FilmState& st = res.state;
  st.pressure_Pa = s.p;
  st.fillFraction.resize(n);
  st.cavitated.resize(n);
  res.cavitatedNodes = 0;
  for (int k = 0; k < n; ++k) {
    st.fillFraction[k] = s.jfo ? s.theta[k] : (s.dry[k] ? 0.0 : 1.0);
    st.cavitated[k] = s.status[k] == kCav ? 1 : 0;
    res.cavitatedNodes += st.cavitated[k];
  }
  // Mass-conserving model: an edge node at p_cav that no oil enters through holds the oil the
  // film brings to it, i.e. the fill fraction of the node inside it (diagonally at a corner),
  // not the full film its fixed pressure was solved with. Counting it full once put a full-film
  // shear on a strip half a cell wide around a starved skirt, which outweighed the starved
  // interior's shear and made fmep depend on the cell size.
  if (s.jfo) {
    for (int j = 0; j < ny; ++j) {
      const int jIn = std::clamp(j, 1, ny - 2);
      for (int i = 0; i < nx; ++i) {
        const int k = i + nx * j;
        if (!s.fillFromInterior[k])
          continue;
        const int iIn = s.periodicX ? i : std::clamp(i, 1, nx - 2);
        st.fillFraction[k] = s.theta[iIn + nx * jIn];
      }
    }
  }

  const Eigen::ArrayXd& A = grid.areaWeights_m2();
  res.areaWeights_m2 = A;
  res.expectedGap_m = s.hT;
  const Eigen::Vector2d& c = pr.momentPoint_m;
  const double pref = pr.referencePressure_Pa;
  const LoadAndMoments lm = integrateLoad(grid, c, n, [&](int k) { return s.p[k] - pref; });
  res.load_N = lm.load;
  res.firstMomentX_Nm = lm.firstMomentX;
  res.firstMomentY_Nm = lm.firstMomentY;

  // Shear stress (FilmResult comment) with the nodal pressure gradient.
  resizeShear(res.shearOnSurface1, n);
  resizeShear(res.shearOnSurface2, n);
  const double Ux = pr.slidingVelocity_mps.x(), Uy = pr.slidingVelocity_mps.y();
  ws.xStencils.resize(static_cast<size_t>(nx));
  for (int i = 0; i < nx; ++i)
    ws.xStencils[static_cast<size_t>(i)] =
        derivativeStencil(grid.x_m(), i, grid.isPeriodicX(), grid.periodX_m());
  for (int j = 0; j < ny; ++j) {
    const Stencil3 sy = derivativeStencil(grid.y_m(), j, false, 0.0);
    for (int i = 0; i < nx; ++i) {
      const Stencil3& sx = ws.xStencils[static_cast<size_t>(i)];
      const int k = i + nx * j;
      const double dpdx =
          sx.cm * s.p[sx.im + nx * j] + sx.c0 * s.p[sx.i0 + nx * j] + sx.cp * s.p[sx.ip + nx * j];
      const double dpdy =
          sy.cm * s.p[i + nx * sy.im] + sy.c0 * s.p[i + nx * sy.i0] + sy.cp * s.p[i + nx * sy.ip];
      const double h = pr.gap_m[k];
      const double couette = st.fillFraction[k] * s.eta[k] / h;
      const double f2 = couette * (s.phiF[k] - s.phiFs[k]);
      const double f1 = -couette * (s.phiF[k] + s.phiFs[k]);
      const double pois = -s.phiFp[k] * 0.5 * h;
      res.shearOnSurface2.couetteX_Pa[k] = f2 * Ux;
      res.shearOnSurface2.couetteY_Pa[k] = f2 * Uy;
      res.shearOnSurface1.couetteX_Pa[k] = f1 * Ux;
      res.shearOnSurface1.couetteY_Pa[k] = f1 * Uy;
      res.shearOnSurface1.poiseuilleX_Pa[k] = res.shearOnSurface2.poiseuilleX_Pa[k] = pois * dpdx;
      res.shearOnSurface1.poiseuilleY_Pa[k] = res.shearOnSurface2.poiseuilleY_Pa[k] = pois * dpdy;
    }
  }
  integrateShear(res.shearOnSurface1, grid, c);
  integrateShear(res.shearOnSurface2, grid, c);

  const double sigma = pr.flowFactors ? pr.flowFactors->compositeSigma_m() : 0.0;
  if (sigma > 0.0)
    res.gapOverSigma = pr.gap_m / sigma;
  else
    res.gapOverSigma.resize(0);
  Eigen::Index kmin = 0;
  res.minFilmThickness_m = pr.gap_m.minCoeff(&kmin);
  res.minFilmNode = static_cast<int>(kmin);
  res.minFilmLocation_m = {grid.x_m()[kmin % nx], grid.y_m()[kmin / nx]};

  s.fluxDiagnostics(res.boundaryInflow_m3ps, res.boundaryOutflow_m3ps, res.storageRate_m3ps);
  res.viscousDissipation_W = calcViscousDissipation_W(grid, pr, s, st.fillFraction);
  s.calcEdgeOutflows(res);
  res.oilVolume_m3 = (A * s.theta * s.hT).sum();

  if (dP) {
    // Column by column: Eigen products would evaluate into temporaries (allocations).
    const Eigen::Index m = dP->cols();
    res.dPressure_dVelocity = *dP;
    res.dLoad_dVelocity.resize(m);
    res.dFirstMomentX_dVelocity.resize(m);
    res.dFirstMomentY_dVelocity.resize(m);
    for (Eigen::Index col = 0; col < m; ++col) {
      const LoadAndMoments d = integrateLoad(grid, c, n, [&](int k) { return (*dP)(k, col); });
      res.dLoad_dVelocity[col] = d.load;
      res.dFirstMomentX_dVelocity[col] = d.firstMomentX;
      res.dFirstMomentY_dVelocity[col] = d.firstMomentY;
    }
  } else {
    res.dPressure_dVelocity.resize(0, 0);
    res.dLoad_dVelocity.resize(0);
    res.dFirstMomentX_dVelocity.resize(0);
    res.dFirstMomentY_dVelocity.resize(0);
  }
}

}  // namespace pistondyn::lubrication::detail
