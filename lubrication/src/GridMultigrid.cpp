#include "GridMultigrid.h"

#include <algorithm>
#include <cmath>

namespace pistondyn::lubrication::detail {

void GridMultigrid::buildMap(int fineCount, bool periodic, bool coarsen, Map1d& m) {
  m.c0.assign(static_cast<size_t>(fineCount), 0);
  m.c1.assign(static_cast<size_t>(fineCount), 0);
  m.w0.assign(static_cast<size_t>(fineCount), 1.0);
  m.w1.assign(static_cast<size_t>(fineCount), 0.0);
  if (!coarsen) {
    m.coarseCount = fineCount;
    for (int f = 0; f < fineCount; ++f)
      m.c0[static_cast<size_t>(f)] = m.c1[static_cast<size_t>(f)] = f;
  } else {
    // Coarse nodes: the even fine indices, plus the last one of an open direction with an even
    // count (so both open ends stay nodes of every level).
    const bool extraLast = !periodic && fineCount % 2 == 0;
    m.coarseCount = (fineCount + 1) / 2 + (extraLast ? 1 : 0);
    for (int f = 0; f < fineCount; ++f) {
      const size_t s = static_cast<size_t>(f);
      if (f % 2 == 0) {
        m.c0[s] = m.c1[s] = f / 2;
      } else if (extraLast && f == fineCount - 1) {
        m.c0[s] = m.c1[s] = m.coarseCount - 1;
      } else {
        m.c0[s] = (f - 1) / 2;
        m.c1[s] = ((f + 1) % fineCount) / 2;
        m.w0[s] = m.w1[s] = 0.5;
      }
    }
  }
  // Transpose into the gather lists of the restriction.
  std::vector<int> count(static_cast<size_t>(m.coarseCount), 0);
  for (int t = 0; t < 3; ++t) {
    m.g[t].assign(static_cast<size_t>(m.coarseCount), 0);
    m.gw[t].assign(static_cast<size_t>(m.coarseCount), 0.0);
  }
  auto add = [&](int c, int f, double w) {
    const size_t sc = static_cast<size_t>(c);
    const int t = count[sc]++;
    m.g[t][sc] = f;
    m.gw[t][sc] = w;
  };
  for (int f = 0; f < fineCount; ++f) {
    const size_t s = static_cast<size_t>(f);
    add(m.c0[s], f, m.w0[s]);
    if (m.w1[s] != 0.0)
      add(m.c1[s], f, m.w1[s]);
  }
  for (int c = 0; c < m.coarseCount; ++c)  // pads point at a valid node
    for (int t = count[static_cast<size_t>(c)]; t < 3; ++t)
      m.g[t][static_cast<size_t>(c)] = m.g[0][static_cast<size_t>(c)];
}

// Mean east-west over mean north-south transmissibility of the fine operator: > 1 where the
// nodes are coupled more strongly along x (cells long in y, or a larger pressure flow factor
// along x), < 1 the other way round.
double GridMultigrid::couplingRatio(const FilmSystem& s) {
  double sx = 0.0, sy = 0.0;
  int nxCount = 0, nyCount = 0;
  for (int k = 0; k < s.n; ++k) {
    if (s.nbE[k] != k) {
      sx += s.tE[k];
      ++nxCount;
    }
    if (s.nbN[k] != k) {
      sy += s.tN[k];
      ++nyCount;
    }
  }
  if (!(sx > 0.0 && sy > 0.0) || nxCount == 0 || nyCount == 0)
    return 1.0;
  return (sx / nxCount) / (sy / nyCount);
}

// Directions each level coarsens (bit 0: x, bit 1: y; 0 ends the list). Full coarsening while
// the couplings are comparable; where one direction is coupled more than kSemiCoarsening times
// more strongly, only that one is coarsened (point smoothing leaves the error smooth along the
// strong direction only). A Galerkin coarsening by two along x halves the x couplings and doubles
// the y couplings (ratio / 4), along y the other way round.
void GridMultigrid::coarseningPattern(const FilmSystem& sys, Pattern& pattern) {
  pattern.fill(0);
  double ratio = couplingRatio(sys);
  int nx = sys.nx, ny = sys.ny;
  const bool periodic = sys.periodicX;
  for (size_t l = 0; l + 1 < pattern.size() && nx * ny > kMaxCoarsest; ++l) {
    // An open direction coarsens while it has more than 3 nodes, a periodic one while the coarse
    // circle keeps at least 3 (so that east and west neighbours stay distinct).
    bool cx = periodic ? nx >= 5 : nx > 3;
    bool cy = ny > 3;
    if (cx && cy) {
      if (ratio > kSemiCoarsening)
        cy = false;
      else if (ratio < 1.0 / kSemiCoarsening)
        cx = false;
    }
    if (!cx && !cy)
      break;
    pattern[l] = static_cast<std::uint8_t>((cx ? 1 : 0) | (cy ? 2 : 0));
    if (cx) {
      nx = (nx + 1) / 2 + (!periodic && nx % 2 == 0 ? 1 : 0);
      ratio *= 0.25;
    }
    if (cy) {
      ny = (ny + 1) / 2 + (ny % 2 == 0 ? 1 : 0);
      ratio *= 4.0;
    }
  }
}

void GridMultigrid::prepare(const FilmSystem& sys) {
  if (sys.n == shapeN_ && sys.nx == shapeNx_ && sys.periodicX == shapePeriodic_)
    return;
  coarseningPattern(sys, pattern_);
  shapeN_ = sys.n;
  shapeNx_ = sys.nx;
  shapePeriodic_ = sys.periodicX;
  levels_.clear();
  Level fine;
  fine.nx = sys.nx;
  fine.ny = sys.ny;
  fine.n = sys.n;
  fine.periodic = sys.periodicX;
  fine.r.assign(static_cast<size_t>(fine.n), 0.0);
  fineInvDiag_.assign(static_cast<size_t>(fine.n), 0.0);
  fineMask_.assign(static_cast<size_t>(fine.n), 0.0);
  oddSeam_ = fine.periodic && fine.nx % 2 == 1;
  levels_.push_back(std::move(fine));
  for (size_t l = 0; l < pattern_.size() && pattern_[l] != 0; ++l) {
    const Level& f = levels_.back();
    const bool cx = (pattern_[l] & 1) != 0, cy = (pattern_[l] & 2) != 0;
    Level c;
    buildMap(f.nx, f.periodic, cx, c.mx);
    buildMap(f.ny, false, cy, c.my);
    c.nx = c.mx.coarseCount;
    c.ny = c.my.coarseCount;
    c.n = c.nx * c.ny;
    c.periodic = f.periodic;
    const size_t n = static_cast<size_t>(c.n);
    c.a.assign(9 * n, 0.0);
    c.nb.assign(9 * n, 0);
    for (int J = 0; J < c.ny; ++J)
      for (int I = 0; I < c.nx; ++I) {
        const int k = I + c.nx * J;
        for (int dJ = -1; dJ <= 1; ++dJ)
          for (int dI = -1; dI <= 1; ++dI) {
            int I2 = I + dI;
            const int J2 = J + dJ;
            if (c.periodic)
              I2 = (I2 + c.nx) % c.nx;
            const bool inside = I2 >= 0 && I2 < c.nx && J2 >= 0 && J2 < c.ny;
            c.nb[9 * static_cast<size_t>(k) + static_cast<size_t>((dI + 1) + 3 * (dJ + 1))] =
                inside ? I2 + c.nx * J2 : k;
          }
      }
    c.invDiag.assign(n, 0.0);
    c.active.assign(n, 0);
    c.activeMask.assign(n, 0.0);
    c.x.assign(n, 0.0);
    c.b.assign(n, 0.0);
    c.r.assign(n, 0.0);
    levels_.push_back(std::move(c));
  }
  const Level& last = levels_.back();
  dense_.assign(static_cast<size_t>(last.n) * static_cast<size_t>(last.n), 0.0);
  size_t maxN = 0;
  for (const Level& L : levels_)
    maxN = std::max(maxN, static_cast<size_t>(L.n));
  unmaskedDiag_.assign(maxN, 0.0);
  levelDiag_.assign(maxN, 0.0);
  fine9_.assign(9 * static_cast<size_t>(sys.n), 0.0);
  fineDiag_.assign(static_cast<size_t>(sys.n), 0.0);
  size_t stage = 0;  // intermediate of the Galerkin product: coarse in x, fine in y
  for (size_t l = 1; l < levels_.size(); ++l)
    stage = std::max(stage, static_cast<size_t>(levels_[l].nx) * levels_[l - 1].ny);
  stage_.assign(9 * stage, 0.0);
  stageDiag_.assign(stage, 0.0);
  size_t rows = 0;  // prolongation scratch: coarse rows interpolated to the finer x
  for (size_t l = 1; l < levels_.size(); ++l)
    rows = std::max(rows, static_cast<size_t>(levels_[l].ny) * levels_[l - 1].nx);
  rowScratch_.assign(rows, 0.0);

  // Cost of a rebuild in PCG iterations, from operation counts (stencil coefficients touched): a
  // cycle smooths 2 nu times and forms one residual per level, plus the transfers; a PCG
  // iteration adds a 5-point product and ~6 vector passes; a rebuild forms ~16 products per
  // stencil coefficient of the finer level (two 1-D stages, up to 2 x 2 parents) plus the dense
  // factorisation. The factor 2.1 is the measured cost per operation of the rebuild relative to
  // the streaming sweeps (index arithmetic and branches): with it the estimate matches the
  // measured ratio (rebuild ~7 cycles at 64 x 48 and 128 x 96, BENCHMARKS.md).
  double cycle = 0.0, rebuild = 0.0;
  for (size_t l = 0; l < levels_.size(); ++l) {
    const double n = levels_[l].n, stencil = l == 0 ? 5.0 : 9.0;
    if (l + 1 < levels_.size()) {
      cycle += n * stencil * (2.0 * smoothingSteps + 1.0) + 2.0 * 4.0 * n;
      rebuild += n * stencil * 16.0;
    }
  }
  const double nc = last.n;
  cycle += 2.0 * nc * nc / 2.0;
  rebuild = 2.1 * (rebuild + nc * nc * nc / 6.0);
  const double iteration = cycle + 5.0 * sys.n + 6.0 * sys.n;
  rebuildCost_ = rebuild / iteration;
}

bool GridMultigrid::rebuild(const FilmSystem& sys, const std::uint8_t* eqRow) {
  if (levels_.size() > 1) {
    fineAsNinePoint(sys);
    galerkin(0, fine9_.data(), fineDiag_.data(), eqRow);
    finishLevel(levels_[1]);
    for (size_t l = 1; l + 1 < levels_.size(); ++l) {
      const Level& L = levels_[l];
      for (int k = 0; k < L.n; ++k)
        levelDiag_[static_cast<size_t>(k)] = L.a[9 * static_cast<size_t>(k) + 4];
      galerkin(static_cast<int>(l), L.a.data(), levelDiag_.data(), L.active.data());
      finishLevel(levels_[l + 1]);
    }
    if (!factorCoarsest())
      return false;
  }
  return true;
}

// One direction of the Galerkin product: out = P1' in P1 for the 1-D interpolation P1 of map m
// along x (alongX) or y, with in a 9-point operator on (nxIn x nyIn) (rows and columns of nodes
// with active[k] == 0 removed, when active is given) and out a 9-point operator on the grid
// coarsened along that direction. Each output row is gathered from the (at most 3) input rows
// that interpolate from it, into a local accumulator: no scattered read-modify-writes. The
// unmasked diagonal ud (sum of w^2 * diagonal, masked nodes included) is carried along.
void GridMultigrid::galerkinStage(const double* in, const double* udIn, const std::uint8_t* active,
                                  int nxIn, int nyIn, bool periodic, const Map1d& m, bool alongX,
                                  double* out, double* udOut) {
  const int nxOut = alongX ? m.coarseCount : nxIn;
  const int nyOut = alongX ? nyIn : m.coarseCount;
  for (int jo = 0; jo < nyOut; ++jo)
    for (int io = 0; io < nxOut; ++io) {
      const int C = alongX ? io : jo;  // coarse index along the coarsened direction
      double acc[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
      double ud = 0.0;
      for (int t = 0; t < 3; ++t) {
        const double w = m.gw[t][static_cast<size_t>(C)];
        if (w == 0.0)
          continue;
        const int f = m.g[t][static_cast<size_t>(C)];
        const int i = alongX ? f : io, j = alongX ? jo : f;
        const int k = i + nxIn * j;
        const double* ak = in + 9 * static_cast<size_t>(k);
        ud += w * w * udIn[k];
        if (active && !active[k])
          continue;
        for (int sl = 0; sl < 9; ++sl) {
          const double v = ak[sl];
          if (v == 0.0)
            continue;
          const int di = sl % 3 - 1, dj = sl / 3 - 1;
          int i2 = i + di;
          const int j2 = j + dj;
          if (periodic)
            i2 = i2 < 0 ? i2 + nxIn : (i2 >= nxIn ? i2 - nxIn : i2);
          if (active && !active[i2 + nxIn * j2])
            continue;
          const int f2 = alongX ? i2 : j2;
          const size_t s2 = static_cast<size_t>(f2);
          for (int r = 0; r < 2; ++r) {
            const double w2 = r == 0 ? m.w0[s2] : m.w1[s2];
            if (w2 == 0.0)
              continue;
            int d = (r == 0 ? m.c0[s2] : m.c1[s2]) - C;
            if (alongX && periodic)
              d = d > 1 ? d - nxOut : (d < -1 ? d + nxOut : d);
            const int slot = alongX ? (d + 1) + 3 * (dj + 1) : (di + 1) + 3 * (d + 1);
            acc[slot] += w * v * w2;
          }
        }
      }
      double* o = out + 9 * static_cast<size_t>(io + nxOut * jo);
      for (int sl = 0; sl < 9; ++sl)
        o[sl] = acc[sl];
      udOut[io + nxOut * jo] = ud;
    }
}

// A_{l+1} = P~' A_l P~, one direction after the other (P = Px Py, the mask applied to A_l).
void GridMultigrid::galerkin(int l, const double* in, const double* udIn,
                             const std::uint8_t* active) {
  const Level& f = levels_[static_cast<size_t>(l)];
  Level& c = levels_[static_cast<size_t>(l) + 1];
  galerkinStage(in, udIn, active, f.nx, f.ny, f.periodic, c.mx, true, stage_.data(),
                stageDiag_.data());
  galerkinStage(stage_.data(), stageDiag_.data(), nullptr, c.nx, f.ny, f.periodic, c.my, false,
                c.a.data(), unmaskedDiag_.data());
}

// The fine operator as a 9-point array (the 5-point stencil of FilmSystem), for galerkin().
void GridMultigrid::fineAsNinePoint(const FilmSystem& s) {
  double* a = fine9_.data();
  for (int k = 0; k < s.n; ++k) {
    double* ak = a + 9 * static_cast<size_t>(k);
    for (int sl = 0; sl < 9; ++sl)
      ak[sl] = 0.0;
    ak[4] = s.diagP[k];
    if (s.nbW[k] != k)
      ak[3] = -s.tW[k];
    if (s.nbE[k] != k)
      ak[5] = -s.tE[k];
    if (s.nbS[k] != k)
      ak[1] = -s.tS[k];
    if (s.nbN[k] != k)
      ak[7] = -s.tN[k];
    fineDiag_[static_cast<size_t>(k)] = s.diagP[k] > 0.0 ? s.diagP[k] : 0.0;
  }
}

// Marks the active nodes of a freshly formed level (positive Galerkin diagonal) and gives the
// others a decoupled row with the unmasked Galerkin diagonal.
void GridMultigrid::finishLevel(Level& c) {
  for (int k = 0; k < c.n; ++k) {
    const size_t k9 = 9 * static_cast<size_t>(k);
    const double ud = unmaskedDiag_[static_cast<size_t>(k)];
    const bool active = c.a[k9 + 4] > 1e-12 * ud;
    c.active[static_cast<size_t>(k)] = active ? 1 : 0;
    c.activeMask[static_cast<size_t>(k)] = active ? 1.0 : 0.0;
    if (!active) {
      for (size_t q = 0; q < 9; ++q)
        c.a[k9 + q] = 0.0;
      c.a[k9 + 4] = ud > 0.0 ? ud : 1.0;
    }
    c.invDiag[static_cast<size_t>(k)] = 1.0 / c.a[k9 + 4];
  }
}

bool GridMultigrid::factorCoarsest() {
  const Level& L = levels_.back();
  const int n = L.n;
  const size_t N = static_cast<size_t>(n);
  std::fill(dense_.begin(), dense_.end(), 0.0);
  for (int k = 0; k < n; ++k)
    for (size_t q = 0; q < 9; ++q) {
      const double v = L.a[9 * static_cast<size_t>(k) + q];
      if (v != 0.0)
        dense_[static_cast<size_t>(L.nb[9 * static_cast<size_t>(k) + q]) * N +
               static_cast<size_t>(k)] += v;  // column-major (symmetric anyway)
    }
  // In-place Cholesky, lower triangle (column j below the diagonal holds L(:, j)). The masked
  // Galerkin product can be singular (two coarse nodes whose supports meet the unmasked nodes in
  // one shared fine node have proportional columns): a pivot that vanishes against its diagonal
  // is replaced by the diagonal, i.e. L L' = A + E with E diagonal and >= 0, which keeps the
  // coarsest solve, and so the cycle, symmetric positive definite.
  for (size_t j = 0; j < N; ++j) {
    const double ajj = dense_[j * N + j];
    double d = ajj;
    for (size_t k = 0; k < j; ++k)
      d -= dense_[k * N + j] * dense_[k * N + j];
    if (!std::isfinite(d) || !(ajj > 0.0))
      return false;
    if (!(d > 1e-10 * ajj))
      d = ajj;
    d = std::sqrt(d);
    dense_[j * N + j] = d;
    for (size_t i = j + 1; i < N; ++i) {
      double t = dense_[j * N + i];
      for (size_t k = 0; k < j; ++k)
        t -= dense_[k * N + i] * dense_[k * N + j];
      dense_[j * N + i] = t / d;
    }
  }
  return true;
}

void GridMultigrid::coarsestSolve(Level& L) {
  const size_t N = static_cast<size_t>(L.n);
  double* x = L.x.data();
  for (size_t i = 0; i < N; ++i) {  // L y = b
    double t = L.b[i];
    for (size_t k = 0; k < i; ++k)
      t -= dense_[k * N + i] * x[k];
    x[i] = t / dense_[i * N + i];
  }
  for (size_t i = N; i-- > 0;) {  // L' x = y
    double t = x[i];
    for (size_t k = i + 1; k < N; ++k)
      t -= dense_[i * N + k] * x[k];
    x[i] = t / dense_[i * N + i];
  }
}

void GridMultigrid::setFineOperator(const FilmSystem& s, const std::uint8_t* eq) {
  for (int k = 0; k < s.n; ++k) {
    fineInvDiag_[static_cast<size_t>(k)] = eq[k] ? 1.0 / s.diagP[k] : 0.0;
    fineMask_[static_cast<size_t>(k)] = eq[k] ? 1.0 : 0.0;
  }
}

// Red-black ordering: the updates of one colour are independent of each other on the 5-point
// stencil (no dependency chain, unlike lexicographic sweeps), except across the seam of a
// periodic x with an odd count, where the sweep is still a Gauss-Seidel sweep in a fixed order.
// The masked rows have inverse diagonal 0, so they stay 0 without a branch.
void GridMultigrid::smoothFineColour(const FilmSystem& s, double* x, const double* b, int colour,
                                     bool descending) const {
  const int nx = s.nx, ny = s.ny;
  const double *tE = s.tE.data(), *tW = s.tW.data(), *tN = s.tN.data(), *tS = s.tS.data(),
               *inv = fineInvDiag_.data();
  const int *nE = s.nbE.data(), *nW = s.nbW.data(), *nN = s.nbN.data(), *nS = s.nbS.data();
  // Any node (edges, wrap-around) through the neighbour lists; interior nodes with fixed offsets.
  auto general = [&](int k) {
    x[k] =
        (b[k] + tE[k] * x[nE[k]] + tW[k] * x[nW[k]] + tN[k] * x[nN[k]] + tS[k] * x[nS[k]]) * inv[k];
  };
  auto interior = [&](int k) {
    x[k] = (b[k] + tE[k] * x[k + 1] + tW[k] * x[k - 1] + tN[k] * x[k + nx] + tS[k] * x[k - nx]) *
           inv[k];
  };
  auto row = [&](int j) {
    const int i0 = (j + colour) & 1;
    const int last = i0 + 2 * ((nx - 1 - i0) / 2);
    const int base = nx * j;
    const bool edgeRow = j == 0 || j == ny - 1;
    // The first and last node of the row are edge nodes; the others are interior unless the
    // row itself is an edge row.
    const int lo = i0 == 0 ? 2 : i0, hi = last == nx - 1 ? last - 2 : last;
    if (!descending) {
      if (i0 == 0)
        general(base);
      if (edgeRow)
        for (int i = lo; i <= hi; i += 2)
          general(base + i);
      else
        for (int i = lo; i <= hi; i += 2)
          interior(base + i);
      if (last == nx - 1 && last != 0)
        general(base + last);
    } else {
      if (last == nx - 1 && last != 0)
        general(base + last);
      if (edgeRow)
        for (int i = hi; i >= lo; i -= 2)
          general(base + i);
      else
        for (int i = hi; i >= lo; i -= 2)
          interior(base + i);
      if (i0 == 0)
        general(base);
    }
  };
  if (!descending)
    for (int j = 0; j < ny; ++j)
      row(j);
  else
    for (int j = ny - 1; j >= 0; --j)
      row(j);
}

// Red-black Gauss-Seidel on a 9-point level (forward: red then black; backward: black then
// red, each in exactly the reverse order). On 9 points the colours are not decoupled (diagonal
// neighbours share a colour), but a node then depends on nodes of the previous row only, so the
// loop carries no dependency chain; it is a plain Gauss-Seidel sweep in a fixed order.
void GridMultigrid::smoothLevel(Level& L, bool forward) const {
  const int nx = L.nx, ny = L.ny;
  const double* a = L.a.data();
  const int* nb = L.nb.data();
  const double* inv = L.invDiag.data();
  double* x = L.x.data();
  const double* b = L.b.data();
  auto update = [&](int k) {
    const double* ak = a + 9 * static_cast<size_t>(k);
    const int* nk = nb + 9 * static_cast<size_t>(k);
    const double t =
        b[k] - (ak[0] * x[nk[0]] + ak[1] * x[nk[1]] + ak[2] * x[nk[2]] + ak[3] * x[nk[3]] +
                ak[5] * x[nk[5]] + ak[6] * x[nk[6]] + ak[7] * x[nk[7]] + ak[8] * x[nk[8]]);
    x[k] = t * inv[k];
  };
  auto sweep = [&](int colour, bool descending) {
    if (!descending) {
      for (int j = 0; j < ny; ++j)
        for (int i = (j + colour) & 1, k = i + nx * j; i < nx; i += 2, k += 2)
          update(k);
    } else {
      for (int j = ny - 1; j >= 0; --j) {
        const int i0 = (j + colour) & 1;
        const int last = i0 + 2 * ((nx - 1 - i0) / 2);
        for (int i = last, k = i + nx * j; i >= i0; i -= 2, k -= 2)
          update(k);
      }
    }
  };
  if (forward) {
    sweep(0, false);
    sweep(1, false);
  } else {
    sweep(1, true);
    sweep(0, true);
  }
}

// Fine level: pre-smoothing red then black (nu times), post-smoothing black then red in exactly
// the reverse order (the adjoint sweep), so that the cycle is symmetric.
void GridMultigrid::apply(const FilmSystem& s, const double* rIn, double* z) {
  const int n0 = s.n, nx = s.nx, ny = s.ny;
  const size_t levels = levels_.size();
  const double* inv = fineInvDiag_.data();
  // First red half sweep from z = 0: the neighbours are still 0 (unless the periodic seam
  // couples two red nodes: then the plain sweep, so that the backward sweep stays its adjoint).
  if (oddSeam_) {
    std::fill(z, z + n0, 0.0);
    smoothFineColour(s, z, rIn, 0, false);
  } else {
    for (int j = 0; j < ny; ++j) {
      double* zr = z + nx * j;
      const double *br = rIn + nx * j, *ir = inv + nx * j;
      for (int i = 0; i < nx; ++i)
        zr[i] = ((i + j) & 1) == 0 ? br[i] * ir[i] : 0.0;
    }
  }
  smoothFineColour(s, z, rIn, 1, false);
  for (int it = 1; it < smoothingSteps; ++it) {
    smoothFineColour(s, z, rIn, 0, false);
    smoothFineColour(s, z, rIn, 1, false);
  }
  if (levels > 1) {
    // Residual of the fine level on the equation rows. The black half sweep has just zeroed it
    // on the black nodes (their neighbours are red), unless the periodic seam couples blacks.
    double* r = levels_[0].r.data();
    const double* m = fineMask_.data();
    const double *tE = s.tE.data(), *tW = s.tW.data(), *tN = s.tN.data(), *tS = s.tS.data(),
                 *dg = s.diagP.data();
    const int *nE = s.nbE.data(), *nW = s.nbW.data(), *nN = s.nbN.data(), *nS = s.nbS.data();
    auto res = [&](int k) {
      r[k] = m[k] * (rIn[k] - dg[k] * z[k] + tE[k] * z[nE[k]] + tW[k] * z[nW[k]] +
                     tN[k] * z[nN[k]] + tS[k] * z[nS[k]]);
    };
    if (oddSeam_) {
      for (int k = 0; k < n0; ++k)
        res(k);
    } else {
      for (int j = 0; j < ny; ++j)
        for (int i = j & 1, k = i + nx * j; i < nx; i += 2, k += 2)
          res(k);
    }
    restrictTo(levels_[1], r, nx);
    for (size_t l = 1; l + 1 < levels; ++l) {
      Level& L = levels_[l];
      std::fill(L.x.begin(), L.x.end(), 0.0);
      for (int it = 0; it < smoothingSteps; ++it)
        smoothLevel(L, true);
      residualLevel(L);
      restrictTo(levels_[l + 1], L.r.data(), L.nx);
    }
    coarsestSolve(levels_.back());
    for (size_t l = levels - 1; l-- > 1;) {
      Level& L = levels_[l];
      prolongFrom(levels_[l + 1], L.x.data(), L.nx, L.ny, L.activeMask.data());
      for (int it = 0; it < smoothingSteps; ++it)
        smoothLevel(L, false);
    }
    prolongFrom(levels_[1], z, nx, ny, fineMask_.data());
  }
  for (int it = 0; it < smoothingSteps; ++it) {
    smoothFineColour(s, z, rIn, 1, true);
    smoothFineColour(s, z, rIn, 0, true);
  }
}

void GridMultigrid::residualLevel(Level& L) const {
  const double* a = L.a.data();
  const int* nb = L.nb.data();
  const double* x = L.x.data();
  const double* m = L.activeMask.data();
  for (int k = 0; k < L.n; ++k) {
    const double* ak = a + 9 * static_cast<size_t>(k);
    const int* nk = nb + 9 * static_cast<size_t>(k);
    double t = L.b[static_cast<size_t>(k)];
    for (int q = 0; q < 9; ++q)
      t -= ak[q] * x[nk[q]];
    L.r[static_cast<size_t>(k)] = m[k] * t;
  }
}

// c.b = P' r (r vanishes on masked fine nodes), as a gather over each coarse node's fine
// neighbours.
void GridMultigrid::restrictTo(Level& c, const double* r, int fnx) const {
  const Map1d &mx = c.mx, &my = c.my;
  const int *g0 = mx.g[0].data(), *g1 = mx.g[1].data(), *g2 = mx.g[2].data();
  const double *w0 = mx.gw[0].data(), *w1 = mx.gw[1].data(), *w2 = mx.gw[2].data();
  for (int J = 0; J < c.ny; ++J) {
    double* out = c.b.data() + static_cast<size_t>(c.nx) * J;
    for (int I = 0; I < c.nx; ++I)
      out[I] = 0.0;
    for (int t = 0; t < 3; ++t) {
      const double wy = my.gw[t][static_cast<size_t>(J)];
      if (wy == 0.0)
        continue;
      const double* row = r + static_cast<size_t>(fnx) * my.g[t][static_cast<size_t>(J)];
      for (int I = 0; I < c.nx; ++I)
        out[I] += wy * (w0[I] * row[g0[I]] + w1[I] * row[g1[I]] + w2[I] * row[g2[I]]);
    }
  }
}

// x += mask .* (P c.x): each coarse row is first interpolated along x (tmp row J), then each
// fine row blends at most two of those rows.
void GridMultigrid::prolongFrom(const Level& c, double* x, int fnx, int fny, const double* mask) {
  const double* xc = c.x.data();
  const int *c0 = c.mx.c0.data(), *c1 = c.mx.c1.data();
  const double *u0 = c.mx.w0.data(), *u1 = c.mx.w1.data();
  double* tmp = rowScratch_.data();
  for (int J = 0; J < c.ny; ++J) {
    const double* xr = xc + static_cast<size_t>(c.nx) * J;
    double* t = tmp + static_cast<size_t>(fnx) * J;
    for (int i = 0; i < fnx; ++i)
      t[i] = u0[i] * xr[c0[i]] + u1[i] * xr[c1[i]];
  }
  for (int j = 0; j < fny; ++j) {
    const size_t sj = static_cast<size_t>(j);
    const double* t0 = tmp + static_cast<size_t>(fnx) * c.my.c0[sj];
    const double* t1 = tmp + static_cast<size_t>(fnx) * c.my.c1[sj];
    const double v0 = c.my.w0[sj], v1 = c.my.w1[sj];
    double* xr = x + static_cast<size_t>(fnx) * j;
    const double* mr = mask + static_cast<size_t>(fnx) * j;
    if (v1 == 0.0)
      for (int i = 0; i < fnx; ++i)
        xr[i] += mr[i] * (v0 * t0[i]);
    else
      for (int i = 0; i < fnx; ++i)
        xr[i] += mr[i] * (v0 * t0[i] + v1 * t1[i]);
  }
}

}  // namespace pistondyn::lubrication::detail
