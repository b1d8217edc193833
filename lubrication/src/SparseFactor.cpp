#include "SparseFactor.h"

#include <cholmod.h>
#include <klu.h>

#include <algorithm>
#include <array>
#include <stdexcept>

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

cholmod_sparse viewUpper(StencilPattern& pat) {
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<size_t>(pat.n);
  A.nzmax = pat.rowIdx.size();
  A.p = pat.colPtr.data();
  A.i = pat.rowIdx.data();
  A.nz = nullptr;
  A.x = pat.values.data();
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
  // Try AMD and CHOLMOD's nested dissection, keep the ordering with less fill: the analysis
  // runs once per grid shape, the factorisation many times.
  c_->nmethods = 2;
  c_->method[0].ordering = CHOLMOD_AMD;
  c_->method[1].ordering = CHOLMOD_NESDIS;
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
  for (cholmod_dense** d : {&X1_, &Y1_, &E1_, &Xm_, &Ym_, &Em_})
    if (*d)
      cholmod_free_dense(d, c_);
}

void CholmodLdl::analyze(StencilPattern& pat) {
  release();
  n_ = pat.n;
  cholmod_sparse A = viewUpper(pat);
  L_ = cholmod_analyze(&A, c_);
  if (!L_)
    throw std::runtime_error("FilmSolver: CHOLMOD symbolic analysis failed");
  // Flops of the LDL' factorisation vs. one solve (4 lnz) plus a stencil product and the CG
  // vector updates (~20 n). The simplicial factorisation runs about 2.8x fewer flops per second
  // than the streaming triangular solves (1.7 vs 4.8 GFlop/s measured, BENCHMARKS.md).
  costRatio_ = 2.8 * c_->fl / (4.0 * c_->lnz + 20.0 * n_);
}

bool CholmodLdl::factorize(StencilPattern& pat) {
  cholmod_sparse A = viewUpper(pat);
  const int ok = cholmod_factorize(&A, L_, c_);
  return ok && c_->status == CHOLMOD_OK && L_->minor == L_->n;
}

void CholmodLdl::solve(const double* b, double* x, int nrhs) {
  cholmod_dense B{};
  B.nrow = static_cast<size_t>(n_);
  B.ncol = static_cast<size_t>(nrhs);
  B.nzmax = B.nrow * B.ncol;
  B.d = B.nrow;
  B.x = const_cast<double*>(b);
  B.z = nullptr;
  B.xtype = CHOLMOD_REAL;
  B.dtype = CHOLMOD_DOUBLE;
  cholmod_dense** X = nrhs == 1 ? &X1_ : &Xm_;
  cholmod_dense** Y = nrhs == 1 ? &Y1_ : &Ym_;
  cholmod_dense** E = nrhs == 1 ? &E1_ : &Em_;
  if (!cholmod_solve2(CHOLMOD_A, L_, &B, nullptr, X, nullptr, Y, E, c_))
    throw std::runtime_error("FilmSolver: CHOLMOD solve failed");
  std::copy_n(static_cast<const double*>((*X)->x), static_cast<size_t>(n_) * nrhs, x);
}

// ---------------------------------------------------------------------------------------------
// KLU

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
    if (ok && klu_rcond(h_->symbolic, h_->numeric, &h_->common) && h_->common.rcond > 1e-13)
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
