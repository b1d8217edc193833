#pragma once
// Internal: geometric multigrid V-cycle on the structured film grid, used as the preconditioner
// of PCG for the symmetric Reynolds / full-Sommerfeld Jacobian of the active-set solver. Not
// installed.
//
// The operator is the 5-point Poiseuille stencil of FilmSystem (face transmissibilities tE, tW,
// tN, tS, diagonal diagP) restricted to the equation rows of the active set (full-film nodes):
// prescribed and cavitated nodes are masked, i.e. their rows and columns are removed. Coarse
// levels:
//  * coarsening by two in each grid direction that is long enough (coarse nodes = the even fine
//    indices, plus the last node of an open direction with an even count; a periodic direction
//    stays periodic and keeps at least 3 nodes), so any nx, ny works; where the nodes are
//    coupled much more strongly along one direction (long thin cells), only that direction is
//    coarsened until the couplings are comparable (semi-coarsening: point smoothing leaves the
//    error smooth along the strong direction only);
//  * bilinear (tensor-product linear) interpolation P; on the finest level the interpolation is
//    masked, P~ = D_eq P, so a correction never touches a masked node;
//  * Galerkin coarse operators A_c = P~' A P~ (9-point stencils), formed one direction after the
//    other (P = Px Py). Galerkin products cope with the strongly varying h^3 conductances (about
//    3e5 across the skirt) and with the masked holes of the active set; coarse nodes whose whole
//    support is masked get a decoupled row with the unmasked Galerkin diagonal (so that, used
//    lagged after the mask moved, they act as a Jacobi step of the right scale) and are masked
//    in the transfers to and from the next level the same way;
//  * the coarsest level (at most kMaxCoarsest nodes) is solved by a dense Cholesky factor.
// Smoothing: red-black Gauss-Seidel, nu sweeps red then black before the coarse correction and
// nu sweeps black then red, in exactly the reverse node order, after it (on the 9-point coarse
// levels the colours are not decoupled; the sweeps are still Gauss-Seidel sweeps in a fixed
// order, and the reverse sweep is their adjoint). Red-black ordering has no loop-carried
// dependency, unlike lexicographic sweeps. The fine level always uses the current operator and
// mask (FilmSystem and setFineOperator()); the coarse operators are those of the last
// rebuild(), so they can be reused as the operator drifts. With pre- and post-smoothers
// adjoint to each other, restriction = transpose of prolongation and an exact coarsest solve,
// one cycle from a zero guess is a symmetric positive definite operator M^-1 for any
// symmetric positive definite coarse operators (lagged ones included):
// M^-1 = S_sym + (I - S'A) P (approximate A_c^-1) P' (I - A S) with the symmetrised smoother
// S_sym SPD for Gauss-Seidel on an SPD matrix, which is what CG needs.
//
// Storage is allocated when the grid's shape changes only; rebuild() and apply() allocate
// nothing. No global state.

#include <array>
#include <cstdint>
#include <vector>

#include "FilmSystem.h"

namespace pistondyn::lubrication::detail {

class GridMultigrid {
 public:
  static constexpr int kMaxCoarsest = 40;  // nodes of the coarsest (dense) level, at most
  // Coupling anisotropy beyond which only the strongly coupled direction is coarsened.
  static constexpr double kSemiCoarsening = 2.0;

  // Level shapes and transfer maps for the grid of sys; does nothing when the shape is the same.
  // The coarsening directions follow the coupling anisotropy of sys's operator at the first call
  // for a shape (grid spacing and flow-factor anisotropy), and are kept while the shape is (so
  // that later calls allocate nothing).
  void prepare(const FilmSystem& sys);

  // Galerkin coarse operators and coarsest factor from the current fine operator, with the
  // equation rows eqRow[k] != 0 (others masked). Returns false if the coarsest matrix is not
  // numerically positive definite (then apply() must not be used until a rebuild succeeds).
  bool rebuild(const FilmSystem& sys, const std::uint8_t* eqRow);

  // Takes the current fine operator (its diagonal) and mask; call after every change of either,
  // before apply().
  void setFineOperator(const FilmSystem& sys, const std::uint8_t* eqRow);

  // z = M^-1 r: one V-cycle from a zero guess with the current fine operator and mask. r must
  // vanish on masked rows; z vanishes there on return. r and z may not alias.
  void apply(const FilmSystem& sys, const double* r, double* z);

  int levelCount() const { return static_cast<int>(levels_.size()); }
  int levelNodes(int l) const { return levels_[static_cast<size_t>(l)].n; }
  // Cost of one rebuild() in units of one PCG iteration with this preconditioner (a cycle plus
  // a stencil product and the CG vector updates), from operation counts.
  double rebuildCostInIterations() const { return rebuildCost_; }

  int smoothingSteps = 1;  // nu, sweeps before and after the coarse correction

  // Fine-to-coarse map of one direction: fine index f takes w0 * coarse c0 + w1 * coarse c1.
  struct Map1d {
    int coarseCount = 0;
    std::vector<int> c0, c1;
    std::vector<double> w0, w1;
    // Gather form of the restriction P': coarse node c collects up to 3 fine nodes g[t][c] with
    // weights gw[t][c] (weight 0 pads).
    std::vector<int> g[3];
    std::vector<double> gw[3];
  };

 private:
  struct Level {
    int nx = 0, ny = 0, n = 0;
    bool periodic = false;
    Map1d mx, my;  // from the finer level (unused on level 0)
    // 9-point stencil (levels >= 1): a[9k + s], s = (dx + 1) + 3 (dy + 1), s = 4 the diagonal;
    // nb[9k + s] the neighbour's index (k itself, with a = 0, where there is none).
    std::vector<double> a;
    std::vector<int> nb;
    std::vector<double> invDiag;
    std::vector<std::uint8_t> active;  // 0: masked (decoupled row, no transfers)
    std::vector<double> activeMask;    // 1.0 / 0.0 copy of active
    std::vector<double> x, b, r;       // iterate, right-hand side, residual
  };

  using Pattern = std::array<std::uint8_t, 64>;
  static double couplingRatio(const FilmSystem& sys);
  static void coarseningPattern(const FilmSystem& sys, Pattern& pattern);
  static void buildMap(int fineCount, bool periodic, bool coarsen, Map1d& m);
  static void galerkinStage(const double* in, const double* udIn, const std::uint8_t* active,
                            int nxIn, int nyIn, bool periodic, const Map1d& m, bool alongX,
                            double* out, double* udOut);
  void galerkin(int l, const double* in, const double* udIn, const std::uint8_t* active);
  void fineAsNinePoint(const FilmSystem& sys);
  void finishLevel(Level& c);
  bool factorCoarsest();
  void residualLevel(Level& L) const;
  void restrictTo(Level& c, const double* r, int fnx) const;
  void prolongFrom(const Level& c, double* x, int fnx, int fny, const double* mask);
  // One red-black Gauss-Seidel half sweep (colour 0: i + j even) on the fine level.
  void smoothFineColour(const FilmSystem& sys, double* x, const double* b, int colour,
                        bool descending) const;
  void smoothLevel(Level& L, bool forward) const;
  void coarsestSolve(Level& L);

  std::vector<Level> levels_;
  int shapeN_ = -1, shapeNx_ = -1;
  bool shapePeriodic_ = false;
  Pattern pattern_{};
  double rebuildCost_ = 5.0;
  std::vector<double> fineInvDiag_;       // 1 / diagP on equation rows, 0 on masked ones
  std::vector<double> fineMask_;          // 1 on equation rows, 0 on masked ones
  bool oddSeam_ = false;                  // periodic x with an odd count: red-black colours touch
  std::vector<double> dense_;             // coarsest Cholesky factor (lower triangle, column-major)
  std::vector<double> rowScratch_;        // prolongation: coarse rows interpolated along x
  std::vector<double> unmaskedDiag_;      // scratch: unmasked Galerkin diagonal of a level
  std::vector<double> levelDiag_;         // scratch: diagonal of the finer level
  std::vector<double> fine9_, fineDiag_;  // fine operator as 9-point array, its diagonal
  std::vector<double> stage_, stageDiag_;  // Galerkin product coarsened along x only
};

}  // namespace pistondyn::lubrication::detail
