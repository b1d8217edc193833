#pragma once
// Internal: thin RAII wrappers of CHOLMOD (symmetric positive definite) and KLU (unsymmetric)
// that keep the symbolic analysis and all workspaces between factorisations, so that repeated
// solves with an unchanged sparsity pattern do not allocate. Not installed.

#include <vector>

#include "FilmSystem.h"

struct cholmod_common_struct;
struct cholmod_factor_struct;

namespace pistondyn::lubrication::detail {

// Compressed-column pattern of the 5-point stencil over all nodes (periodic wrap included).
// Entry (row = neighbour d of node k, column = k) sits at pos{E,W,N,S}[k]; the diagonal at
// posSelf[k]; -1 where the neighbour is missing.
struct StencilPattern {
  int n = 0;
  std::vector<int> colPtr, rowIdx;
  std::vector<int> posSelf, posE, posW, posN, posS;
  std::vector<double> values;
  void build(const FilmSystem& sys);
};

class CholmodLdl {
 public:
  CholmodLdl();
  ~CholmodLdl();
  CholmodLdl(const CholmodLdl&) = delete;
  CholmodLdl& operator=(const CholmodLdl&) = delete;

  // Symbolic analysis of the (upper triangle of the) pattern; call when the pattern changes.
  void analyze(StencilPattern& pat);
  // Numeric factorisation of pat.values; false if the matrix is not positive definite.
  bool factorize(StencilPattern& pat);
  // x = A^{-1} b for nrhs column-major right-hand sides of length n.
  void solve(const double* b, double* x, int nrhs);
  // Cost of one numeric factorisation in units of one preconditioned Krylov iteration (a solve
  // with the factor plus a stencil product), from the flop and nonzero counts of the analysis.
  double factorCostInIterations() const { return costRatio_; }

 private:
  void release();
  void refreshSolveCopies();
  cholmod_common_struct* c_ = nullptr;
  cholmod_factor_struct* L_ = nullptr;
  std::vector<double> work_;                             // permuted right-hand side of solve()
  std::vector<int> perm_;                                // fill-reducing permutation P
  std::vector<int> permColPtr_, permRowIdx_, valueMap_;  // upper triangle of P A P'
  std::vector<double> permValues_;
  // Gather-friendly copies of L for solve() (see refreshSolveCopies).
  bool solveStructure_ = false;
  std::vector<int> colStart_, colRow_, colSrc_, rowStart_, rowCol_, rowSrc_, diagPos_;
  std::vector<double> colVal_, rowVal_, dinv_;
  int n_ = 0;
  double costRatio_ = 20.0;
};

class KluLu {
 public:
  KluLu();
  ~KluLu();
  KluLu(const KluLu&) = delete;
  KluLu& operator=(const KluLu&) = delete;

  void analyze(StencilPattern& pat);
  // Numeric factorisation. With fresh = false an existing factorisation is refactored with its
  // pivot sequence (no allocation); a poor reciprocal pivot ratio triggers a fresh one.
  bool factorize(StencilPattern& pat, bool fresh);
  // In place: b <- A^{-1} b for nrhs column-major right-hand sides.
  void solve(double* b, int nrhs);
  // As CholmodLdl::factorCostInIterations, for a GMRES iteration.
  double factorCostInIterations() const { return costRatio_; }

 private:
  void release();
  struct Handles;
  Handles* h_ = nullptr;
  int n_ = 0;
  double costRatio_ = 20.0;
};

}  // namespace pistondyn::lubrication::detail
