#pragma once
// Internal: the discrete film balance shared by the reference and the fast solver, so that
// both solve exactly the same equations (FilmProblem.h, "Discrete equation"). Not installed.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "pistondyn/lubrication/FilmGrid.h"
#include "pistondyn/lubrication/FilmProblem.h"
#include "pistondyn/lubrication/FlowFactorModel.h"

namespace pistondyn::lubrication::detail {

// Role of a node in a solve.
enum NodeStatus : std::uint8_t {
  kFixed = 0,  // prescribed pressure (open edge, starved edge, dry inlet zone)
  kFull = 1,   // unknown pressure, full film (theta = 1)
  kCav = 2,    // at the cavitation pressure; JFO: unknown fill fraction
};

struct FilmSystem {
  // ---- shape (depends on the grid only) ----
  int nx = 0, ny = 0, n = 0;
  bool periodicX = false;
  // Neighbours; a missing neighbour is the node itself with a zero coefficient (branch-free).
  std::vector<int> nbE, nbW, nbN, nbS;
  // The non-fixed nodes in Gauss-Seidel sweep order (lexicographic, following the sliding
  // direction; rebuilt by assemble).
  std::vector<int> order;

  // ---- per-solve coefficients ----
  CavitationModel model = CavitationModel::Reynolds;
  bool jfo = false;
  double pCav = 0.0;
  Eigen::ArrayXd tE, tW, tN, tS;  // face transmissibilities K L / d, [m^3 / (Pa s)]
  Eigen::ArrayXd diagP;           // tE + tW + tN + tS
  Eigen::ArrayXd couE, couN;    // signed full-film Couette flux through east / north face, [m^3/s]
  Eigen::ArrayXd aOut;          // sum of |Couette| through faces where the node is upwind
  Eigen::ArrayXd inCx, inCy;    // Couette inflow coefficient from the upwind x / y neighbour
  std::vector<int> inIx, inIy;  // index of that upwind neighbour
  Eigen::ArrayXd squeeze;       // A dhT/dt, [m^3/s]
  Eigen::ArrayXd capacity;      // A hT / dt, [m^3/s] (0 when steady or not JFO)
  Eigen::ArrayXd thetaPrev;     // fill fraction at the start of the step (JFO)
  Eigen::ArrayXd thetaCoef;     // aOut + squeeze + capacity: coefficient of the own theta
  // FillFractionFlux::LimitedSecondOrder: the explicit correction flux through the east /
  // north face (signed along +x / +y, [m^3/s]) and its net outflow per node; zero otherwise.
  Eigen::ArrayXd fillCorrE, fillCorrN, fillCorrOut;
  Eigen::ArrayXd fillCorrScratch;  // the limiter's per-node sums (no allocation per solve)
  // The limiter's factor per east / north face (in [0, 1]).
  // With freezeFillLimiter the assembly applies fillLimitE / fillLimitN as they are instead
  // of recomputing them: the gap-derivative assemblies copy them from the solve's system, so
  // that the derivative of a node's balance stays within its five-point stencil (the
  // limiter's own dependence on the gaps two nodes away is left out, a frozen-limiter
  // Jacobian).
  Eigen::ArrayXd fillLimitE, fillLimitN;
  bool freezeFillLimiter = false;
  Eigen::ArrayXd src;           // Reynolds-mode constant part: aOut - inflow(theta=1) + squeeze
  double residualScale = 1.0;   // F of the residual definition
  // Mean diagP over the non-fixed nodes (1 when there is none or it is not positive): the
  // diagonal of the Jacobian's identity rows at nodes whose own diagP is not positive.
  double meanFreeDiagP = 1.0;

  std::vector<std::uint8_t> status;  // NodeStatus per node
  std::vector<std::uint8_t> dry;     // 1: dry node of the Reynolds partial-flooding heuristic
  // 1: mass-conserving model, a fixed edge node that no oil enters through (an outflow edge, or
  // one the sliding runs along) at or below p_cav: it holds the oil the film brings, so its
  // reported fill fraction is that of the node inside it (FilmPostprocess), not a full film.
  std::vector<std::uint8_t> fillFromInterior;
  Eigen::ArrayXd fixedPressure;      // pressure of fixed nodes
  Eigen::ArrayXd fixedTheta;         // fill fraction of fixed nodes (JFO inflow content)

  // Nodal quantities kept for post-processing.
  Eigen::ArrayXd hT, dhTdh, eta, phiF, phiFs, phiFp;
  // Nodal factors of the face values along x and y (assembleFaces): the conductance
  // phi_p h^3 / (12 eta) [m^3/(Pa s)] (FaceValues::NodalMean), or phi_p / (12 eta) [1/(Pa s)]
  // without the h^3 (FaceValues::LinearGap, which weighs the gaps itself), and the Couette
  // content hT (+ sigma phi_s along the sliding direction) [m].
  Eigen::ArrayXd nodeConductanceX, nodeConductanceY, couetteContentX, couetteContentY;

  // ---- current iterate ----
  Eigen::ArrayXd p, theta;

  void resizeFor(const FilmGrid& grid);  // allocates only when the shape changes

  // Assembles all coefficients for the problem; classifies fixed nodes. Validated input only.
  // = calcNodeFactors at the problem's gap, then assembleFromNodeFactors.
  void assemble(const FilmGrid& grid, const FilmProblem& problem);
  // The flow-factor model's factors at each node's gap (the expensive, purely nodal part of
  // an assembly) into `out` (resized to n: no allocation after the first call).
  void calcNodeFactors(const FilmProblem& problem, const Eigen::ArrayXd& gap_m,
                       std::vector<NodeFlowFactors>& out) const;
  // The rest of assemble from nodeFactors (which must belong to problem.gap_m): lets a caller
  // swap in the factors of some nodes without re-evaluating all of them.
  void assembleFromNodeFactors(const FilmGrid& grid, const FilmProblem& problem);
  // The parts of assembleFromNodeFactors, in the order it calls them: the nodal factors from
  // nodeFactors (conductances, contents, expected gaps, viscosity, shear factors); the face
  // transmissibilities tE / tN and Couette fluxes couE / couN (FilmSystem.cpp: the face
  // values); tW / tS, diagP and the upwind Couette terms (inCx / inIx, inCy / inIy, aOut);
  // the storage terms (squeeze, capacity, thetaPrev, thetaCoef: backward Euler or BDF2); the
  // fixed nodes (status, fixedPressure, fixedTheta, dry, fillFromInterior); src,
  // meanFreeDiagP and residualScale; the Gauss-Seidel order.
  void calcNodeConductances(const FilmProblem& problem, bool slideY);
  void assembleFaces(const FilmGrid& grid, const FilmProblem& problem, bool slideY);
  void assembleUpwindCouette(double Ux_mps, double Uy_mps);
  void assembleStorage(const FilmGrid& grid, const FilmProblem& problem);
  void classifyFixedNodes(const FilmGrid& grid, const FilmProblem& problem);
  void calcResidualScale();
  void buildSweepOrder(double Ux_mps, double Uy_mps);
  // Parts of the above: the knee factors for the problem's model and floor; the open edges'
  // nodes (one node: fixEdgeNode, FilmSystem.cpp); the dry inlet nodes of the
  // non-conservative models' partial-flooding march.
  void updateKneeFactors(const FilmProblem& problem, double floor_m);
  void fixEdgeNodes(const FilmGrid& grid, const FilmProblem& problem);
  void fixEdgeNode(int k, const FilmEdge& edge, int along, double inflowCouette, double normalSpeed,
                   double edgeLength);
  void markDryInlets(const FilmProblem& problem);
  // The explicit second-order fill-fraction correction (FillFractionFlux::LimitedSecondOrder,
  // FillFractionFlux.cpp) into fillCorrE / fillCorrN / fillCorrOut, from the assembled
  // Couette fluxes, capacities and fixed-node status.
  void assembleFillFractionCorrection(const FilmGrid& grid, const FilmProblem& problem);
  // Zalesak's limiter: the face factors fillLimitE / fillLimitN from the fill fraction at
  // the start of the step (theta_n), applied to the raw fluxes.
  void calcFillLimiter(const Eigen::ArrayXd& theta_n);
  std::vector<NodeFlowFactors> nodeFactors;  // of the last assembly

  // Floored gaps (FilmProblem::gapFloor_m): the flow factors at the knee's breakpoints
  // (kKneeBreakpoints in FilmSystem.cpp, multiples of the floor), for the model and the
  // floor they belong to (recomputed when either changes; a model is immutable).
  std::vector<NodeFlowFactors> kneeFactors;
  const FlowFactorModel* kneeModel = nullptr;
  double kneeFloor_m = 0.0;

  // Five-point Poiseuille product at node k: net Poiseuille outflow of the nodal field x.
  double poiseuilleAt(int k, const double* x) const {
    return diagP[k] * x[k] -
           (tE[k] * x[nbE[k]] + tW[k] * x[nbW[k]] + tN[k] * x[nbN[k]] + tS[k] * x[nbS[k]]);
  }

  // Net outflow R_k of node k at the current iterate (FilmProblem.h).
  double residualAt(int k) const {
    const double P = poiseuilleAt(k, p.data());
    const double in = inCx[k] * theta[inIx[k]] + inCy[k] * theta[inIy[k]];
    return P + theta[k] * thetaCoef[k] - in - capacity[k] * thetaPrev[k] + fillCorrOut[k];
  }

  // Relative residual of the current iterate (definition in FilmProblem.h).
  double relativeResidual() const;

  // Boundary flux and storage diagnostics at the current iterate.
  void fluxDiagnostics(double& inflow, double& outflow, double& storage) const;

  // Net flow out of the film across the edge lines at the current iterate, per edge node
  // (FilmResult::edgeOutflowYMin_m3ps ... : the face flow from the node inside, minus what the
  // edge node's own control volume takes up as its gap changes, theta A dhT/dt).
  void calcEdgeOutflows(FilmResult& result) const;
  // Net outflow [m^3/s] from unknown node k into its neighbour e through their common face.
  double faceOutflow(int k, int e) const;
};

}  // namespace pistondyn::lubrication::detail
