#include "SparseFactor.h"

#include <cholmod.h>
#include <klu.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

namespace pistondyn::lubrication::detail {

void StencilPattern::build(const FilmSystem& sys) {
  n = sys.n;
  colPtr.assign(n + 1, 0);
  rowIdx.clear();
  rowIdx.reserve(5 * n);
  posSelf.assign(n, -1);
  posE.assign(n, -1);
  posW.assign(n, -1);
  posN.assign(n, -1);
  posS.assign(n, -1);
  for (int k = 0; k < n; ++k) {
    // (row, direction): 0 self, 1 E, 2 W, 3 N, 4 S
    std::array<std::pair<int, int>, 5> rows{};
    int m = 0;
    rows[m++] = {k, 0};
    if (sys.nbE[k] != k)
      rows[m++] = {sys.nbE[k], 1};
    if (sys.nbW[k] != k)
      rows[m++] = {sys.nbW[k], 2};
    if (sys.nbN[k] != k)
      rows[m++] = {sys.nbN[k], 3};
    if (sys.nbS[k] != k)
      rows[m++] = {sys.nbS[k], 4};
    std::sort(rows.begin(), rows.begin() + m);
    for (int q = 0; q < m; ++q) {
      const int pos = static_cast<int>(rowIdx.size());
      rowIdx.push_back(rows[q].first);
      switch (rows[q].second) {
        case 0:
          posSelf[k] = pos;
          break;
        case 1:
          posE[k] = pos;
          break;
        case 2:
          posW[k] = pos;
          break;
        case 3:
          posN[k] = pos;
          break;
        default:
          posS[k] = pos;
          break;
      }
    }
    colPtr[k + 1] = static_cast<int>(rowIdx.size());
  }
  values.assign(rowIdx.size(), 0.0);
}

// ---------------------------------------------------------------------------------------------
// CHOLMOD

namespace {

cholmod_sparse viewUpper(int n, std::vector<int>& colPtr, std::vector<int>& rowIdx,
                         std::vector<double>& values) {
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<size_t>(n);
  A.nzmax = rowIdx.size();
  A.p = colPtr.data();
  A.i = rowIdx.data();
  A.nz = nullptr;
  A.x = values.data();
  A.z = nullptr;
  A.stype = 1;  // symmetric, upper triangle used (lower entries ignored)
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_REAL;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}

}  // namespace

CholmodLdl::CholmodLdl() {
  c_ = new cholmod_common;
  cholmod_start(c_);
  // Simplicial LDL': the film matrices are small 2-D stencils for which the supernodal
  // (BLAS-based) path costs more than it gains (see BENCHMARKS.md).
  c_->supernodal = CHOLMOD_SIMPLICIAL;
  c_->final_ll = 0;
  c_->print = 0;
  c_->error_handler = nullptr;
}

CholmodLdl::~CholmodLdl() {
  release();
  cholmod_finish(c_);
  delete c_;
}

void CholmodLdl::release() {
  if (L_)
    cholmod_free_factor(&L_, c_);
}

// Two analyses. The first chooses the fill-reducing permutation P (AMD; once per grid shape). The
// second analyses the explicitly permuted upper triangle of P A P' with the natural ordering and no
// post-ordering; factorising that matrix needs no internal transposes, so repeated
// factorisations allocate nothing (cholmod_factorize with a permutation builds two temporary
// copies of A every time).
void CholmodLdl::analyze(StencilPattern& pat) {
  release();
  n_ = pat.n;
  work_.assign(static_cast<size_t>(n_), 0.0);
  solveStructure_ = false;
  cholmod_sparse A = viewUpper(n_, pat.colPtr, pat.rowIdx, pat.values);
  // AMD only: CHOLMOD's nested dissection calls METIS, whose random-number state is
  // process-global, so concurrent analyses on several threads race (and may pick different
  // orderings). AMD is deterministic and re-entrant; it fills ~10 % more at 128 x 96.
  c_->nmethods = 1;
  c_->method[0].ordering = CHOLMOD_AMD;
  c_->postorder = 1;
  cholmod_factor* ordering = cholmod_analyze(&A, c_);
  if (!ordering)
    throw std::runtime_error("FilmSolver: CHOLMOD symbolic analysis failed");
  // Flops of the LDL' factorisation vs. one solve (4 lnz) plus a stencil product and the CG
  // vector updates (~20 n). The simplicial factorisation runs about 2.8x fewer flops per second
  // than the streaming triangular solves (1.7 vs 4.8 GFlop/s measured, BENCHMARKS.md).
  costRatio_ = 2.8 * c_->fl / (4.0 * c_->lnz + 20.0 * n_);
  perm_.assign(static_cast<const int*>(ordering->Perm),
               static_cast<const int*>(ordering->Perm) + n_);
  cholmod_free_factor(&ordering, c_);

  // Upper triangle of P A P': entry (i, j), i <= j, of A goes to (min, max)(pinv[i], pinv[j]).
  std::vector<int> pinv(static_cast<size_t>(n_));
  for (int k = 0; k < n_; ++k)
    pinv[static_cast<size_t>(perm_[static_cast<size_t>(k)])] = k;
  std::vector<std::array<int, 3>> entries;  // (column, row, position in pat.values)
  for (int j = 0; j < n_; ++j)
    for (int q = pat.colPtr[j]; q < pat.colPtr[j + 1]; ++q) {
      const int i = pat.rowIdx[q];
      if (i > j)
        continue;
      const int a = pinv[static_cast<size_t>(i)], b = pinv[static_cast<size_t>(j)];
      entries.push_back({std::max(a, b), std::min(a, b), q});
    }
  std::sort(entries.begin(), entries.end());
  permColPtr_.assign(static_cast<size_t>(n_) + 1, 0);
  permRowIdx_.resize(entries.size());
  permValues_.assign(entries.size(), 0.0);
  valueMap_.resize(entries.size());
  for (size_t e = 0; e < entries.size(); ++e) {
    ++permColPtr_[static_cast<size_t>(entries[e][0]) + 1];
    permRowIdx_[e] = entries[e][1];
    valueMap_[e] = entries[e][2];
  }
  for (int k = 0; k < n_; ++k)
    permColPtr_[static_cast<size_t>(k) + 1] += permColPtr_[static_cast<size_t>(k)];
  cholmod_sparse B = viewUpper(n_, permColPtr_, permRowIdx_, permValues_);
  c_->nmethods = 1;
  c_->method[0].ordering = CHOLMOD_NATURAL;
  c_->postorder = 0;
  L_ = cholmod_analyze(&B, c_);
  if (!L_)
    throw std::runtime_error("FilmSolver: CHOLMOD symbolic analysis failed");
}

bool CholmodLdl::factorize(StencilPattern& pat) {
  for (size_t e = 0; e < valueMap_.size(); ++e)
    permValues_[e] = pat.values[static_cast<size_t>(valueMap_[e])];
  cholmod_sparse A = viewUpper(n_, permColPtr_, permRowIdx_, permValues_);
  const int ok = cholmod_factorize(&A, L_, c_);
  // solve() relies on a simplicial LDL' factor with int indices.
  const bool good = ok && c_->status == CHOLMOD_OK && L_->minor == L_->n && !L_->is_ll &&
                    !L_->is_super && L_->itype == CHOLMOD_INT && L_->xtype == CHOLMOD_REAL;
  if (good)
    refreshSolveCopies();
  return good;
}

// Copies of the simplicial LDL' factor for the triangular solves (column j of CHOLMOD's L holds
// D(j,j) first, then the strictly lower part of L(:,j)): the strictly lower part by columns
// (backward sweep, a gather) and by rows (forward sweep, a gather instead of a scatter), and
// 1/D. The index structure is built after the first factorisation of an analysis (the
// simplicial pattern is fixed by the symbolic analysis); values are re-gathered after every
// factorisation.
void CholmodLdl::refreshSolveCopies() {
  const int* Lp = static_cast<const int*>(L_->p);
  const int* Li = static_cast<const int*>(L_->i);
  const int* Lnz = static_cast<const int*>(L_->nz);
  const double* Lx = static_cast<const double*>(L_->x);
  if (!solveStructure_) {
    colStart_.assign(static_cast<size_t>(n_) + 1, 0);
    rowStart_.assign(static_cast<size_t>(n_) + 1, 0);
    for (int j = 0; j < n_; ++j) {
      colStart_[static_cast<size_t>(j) + 1] = colStart_[static_cast<size_t>(j)] + Lnz[j] - 1;
      for (int q = Lp[j] + 1; q < Lp[j] + Lnz[j]; ++q)
        ++rowStart_[static_cast<size_t>(Li[q]) + 1];
    }
    for (int i = 0; i < n_; ++i)
      rowStart_[static_cast<size_t>(i) + 1] += rowStart_[static_cast<size_t>(i)];
    const size_t nnz = static_cast<size_t>(colStart_.back());
    colRow_.resize(nnz);
    colSrc_.resize(nnz);
    rowCol_.resize(nnz);
    rowSrc_.resize(nnz);
    std::vector<int> fill(rowStart_.begin(), rowStart_.end() - 1);
    for (int j = 0; j < n_; ++j)
      for (int q = Lp[j] + 1, c = colStart_[static_cast<size_t>(j)]; q < Lp[j] + Lnz[j]; ++q, ++c) {
        colRow_[static_cast<size_t>(c)] = Li[q];
        colSrc_[static_cast<size_t>(c)] = q;
        const int r = fill[static_cast<size_t>(Li[q])]++;
        rowCol_[static_cast<size_t>(r)] = j;
        rowSrc_[static_cast<size_t>(r)] = q;
      }
    colVal_.resize(nnz);
    rowVal_.resize(nnz);
    dinv_.resize(static_cast<size_t>(n_));
    diagPos_.assign(Lp, Lp + n_);
    solveStructure_ = true;
  }
  for (size_t c = 0; c < colVal_.size(); ++c)
    colVal_[c] = Lx[colSrc_[c]];
  for (size_t r = 0; r < rowVal_.size(); ++r)
    rowVal_[r] = Lx[rowSrc_[r]];
  for (int j = 0; j < n_; ++j)
    dinv_[static_cast<size_t>(j)] = 1.0 / Lx[diagPos_[static_cast<size_t>(j)]];
}

// x = P' L'^-1 D^-1 L^-1 P b. Done here instead of cholmod_solve2, which reallocates its dense
// workspaces on every call; both sweeps are gathers over contiguous copies of L.
void CholmodLdl::solve(const double* b, double* x, int nrhs) {
  const int* perm = perm_.data();  // L_ is of P A P' in natural order
  double* y = work_.data();
  const int* rs = rowStart_.data();
  const int* rc = rowCol_.data();
  const double* rv = rowVal_.data();
  const int* cs = colStart_.data();
  const int* cr = colRow_.data();
  const double* cv = colVal_.data();
  for (int c = 0; c < nrhs; ++c) {
    const double* bc = b + static_cast<size_t>(c) * n_;
    double* xc = x + static_cast<size_t>(c) * n_;
    for (int i = 0; i < n_; ++i) {  // forward: L y = P b, row by row
      double t = bc[perm[i]];
      for (int q = rs[i]; q < rs[i + 1]; ++q)
        t -= rv[q] * y[rc[q]];
      y[i] = t;
    }
    for (int j = n_ - 1; j >= 0; --j) {  // diagonal and backward: L' z = D^-1 y
      double t = y[j] * dinv_[static_cast<size_t>(j)];
      for (int q = cs[j]; q < cs[j + 1]; ++q)
        t -= cv[q] * y[cr[q]];
      y[j] = t;
    }
    for (int k = 0; k < n_; ++k)
      xc[perm[k]] = y[k];
  }
}

// ---------------------------------------------------------------------------------------------
// KLU

namespace {
// A refactorisation whose pivots grew the entries of U by more than 1e8 (eight digits) against
// those of the matrix is redone with fresh pivots.
constexpr double kMinReciprocalPivotGrowth = 1e-8;
}  // namespace

struct KluLu::Handles {
  klu_common common{};
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
};

KluLu::KluLu() : h_(new Handles) {
  klu_defaults(&h_->common);
  // No block-triangular form and no row scaling: the film Jacobians are Z-matrices that are
  // (nearly) column diagonally dominant, so diagonal pivots are chosen and stay valid when the
  // matrix is refactored with the same pivot sequence.
  h_->common.btf = 0;
  h_->common.scale = 0;
}

KluLu::~KluLu() {
  release();
  delete h_;
}

void KluLu::release() {
  if (h_->numeric)
    klu_free_numeric(&h_->numeric, &h_->common);
  if (h_->symbolic)
    klu_free_symbolic(&h_->symbolic, &h_->common);
}

void KluLu::analyze(StencilPattern& pat) {
  release();
  n_ = pat.n;
  h_->symbolic = klu_analyze(n_, pat.colPtr.data(), pat.rowIdx.data(), &h_->common);
  if (!h_->symbolic)
    throw std::runtime_error("FilmSolver: KLU symbolic analysis failed");
}

bool KluLu::factorize(StencilPattern& pat, bool fresh) {
  if (h_->numeric && !fresh) {
    const int ok = klu_refactor(pat.colPtr.data(), pat.rowIdx.data(), pat.values.data(),
                                h_->symbolic, h_->numeric, &h_->common);
    // Keep the old pivot sequence unless it lets the entries of U grow (reciprocal pivot
    // growth, the test KLU's authors give for a refactorisation), or U has a zero pivot. Not
    // the diagonal ratio of U: it measures the matrix' scaling (conductances h^3 over orders
    // of magnitude, pressure and fill-fraction columns in different units), which a fresh
    // factorisation does not change, and threw away half the refactorisations of an elastic
    // cycle (BENCHMARKS.md).
    if (ok && klu_rcond(h_->symbolic, h_->numeric, &h_->common) && h_->common.rcond > 0.0 &&
        klu_rgrowth(pat.colPtr.data(), pat.rowIdx.data(), pat.values.data(), h_->symbolic,
                    h_->numeric, &h_->common) &&
        h_->common.rgrowth > kMinReciprocalPivotGrowth)
      return true;
  }
  if (h_->numeric)
    klu_free_numeric(&h_->numeric, &h_->common);
  h_->numeric = klu_factor(pat.colPtr.data(), pat.rowIdx.data(), pat.values.data(), h_->symbolic,
                           &h_->common);
  const bool ok = h_->numeric != nullptr && h_->common.status == KLU_OK;
  if (ok && klu_flops(h_->symbolic, h_->numeric, &h_->common)) {
    // GMRES iteration: a solve (2 (lnz + unz) flops), a product and ~5 Gram-Schmidt passes
    // (~40 n); same flop-rate correction as for CHOLMOD.
    const double nz = static_cast<double>(h_->numeric->lnz) + h_->numeric->unz;
    costRatio_ = 2.8 * h_->common.flops / (2.0 * nz + 40.0 * n_);
  }
  return ok;
}

void KluLu::solve(double* b, int nrhs) {
  if (!klu_solve(h_->symbolic, h_->numeric, n_, nrhs, b, &h_->common))
    throw std::runtime_error("FilmSolver: KLU solve failed");
}

}  // namespace pistondyn::lubrication::detail
