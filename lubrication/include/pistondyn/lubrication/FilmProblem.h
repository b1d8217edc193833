#pragma once
// Inputs, warm-start state and results of the film solver (FilmSolver.h).
//
// Frame and sign conventions
// --------------------------
// * The grid (FilmGrid.h) is attached to surface 2 (e.g. the piston skirt, a bearing shell).
//   Surface 1 (the liner, a journal) moves with the sliding velocity U = (Ux, Uy) relative to
//   surface 2, as in FlowFactorModel.h. The mean (Couette) velocity of a full film is U/2.
// * gapRate_mps is dh/dt at a fixed grid node (in the frame of surface 2).
// * Nodal fields use the flat index k = i + nx * j of FilmGrid.
//
// Discrete equation (vertex-centred finite volumes; one balance per control volume):
//   net outflow_k = sum_faces [ -K_f (p_nb - p_k) / d_f + (U.n_f / 2) * theta_up * C_f ] * L_f
//                 + A_k * [ theta_k * dhT/dt_k + hT_k * (theta_k - thetaPrev_k) / dt ] = 0
// with K = phi_p * h^3 / (12 eta) (phi_p: pressure flow factor of the face direction),
// C = hT + sigma*phiS (expected gap plus shear-flow term of Patir & Cheng), face values K_f,
// C_f as chosen by FilmProblem::faces (FaceValues below: the arithmetic means of the two nodes
// by default), L_f the face length, d_f the node spacing,
// A_k the control-volume area. theta_up is the fill fraction of the upwind node (mass-conserving
// model only; 1 otherwise): in a full film this is exactly the central second-order Reynolds
// discretisation, in a cavitated zone it is the monotone upwind transport of the oil content.
// FillFractionFlux::LimitedSecondOrder (below) adds a known correction flux per face to it.
// Without a time step (steady state, dt = inf) the last term vanishes.
//
// Residual tolerance (same definition for both solvers)
// ------------------------------------------------------
//   relative residual = max over unknown nodes k of |R_k| / F
// where R_k is the net outflow above (m^3/s), except that at a node held at the cavitation
// pressure by the Reynolds (Swift-Stieber) condition only a mass deficit counts, R_k -> max(0,
// -R_k) (the sign condition of the complementarity problem); and F is the largest over the
// unknown nodes of the sum of the magnitudes of the driving fluxes of that node's balance
// (Couette fluxes through its faces, |A dhT/dt|, A hT / dt, and the Poiseuille flux that the
// spread of the prescribed pressures would drive through its faces). Both solvers enforce
// p >= p_cav, 0 <= theta <= 1 and p (1 - theta) = 0 exactly, so the residual measures only the
// mass balance. A solve is converged when this number is <= FilmSolverOptions::tolerance.

#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "pistondyn/lubrication/FilmHistory.h"
#include "pistondyn/lubrication/FlowFactorModel.h"

namespace pistondyn::lubrication {

enum class CavitationModel {
  None,            // full Sommerfeld: the Reynolds equation everywhere, sub-ambient pressures kept
  Reynolds,        // Swift-Stieber / Reynolds condition p >= p_cav (the thesis' choice)
  MassConserving,  // JFO / Elrod-Adams: p >= p_cav, 0 <= theta <= 1, (p - p_cav)(1 - theta) = 0
};

enum class FilmSolverType {
  ReferenceGaussSeidel,  // the thesis' Gauss-Seidel with over-relaxation (projected / Elrod-Adams)
  FastActiveSet,         // primal-dual active-set iteration; Krylov solves preconditioned by
                         // multigrid or a lagged CHOLMOD / KLU factorisation (FastLinearSolver)
};

// How a face between nodes a and b takes its conductance K_f and Couette content C_f (the
// "Discrete equation" above). Both are second order and agree where ha = hb.
enum class FaceValues {
  // K_f = (Ka + Kb) / 2, C_f = (Ca + Cb) / 2: the default, the scheme every cycle figure in
  // the READMEs and BENCHMARKS.md was computed with.
  NodalMean,
  // The face values of a gap linear between the two nodes (the one-dimensional flux through
  // the face exact): K_f = f_f 2 ha^2 hb^2 / (ha + hb) with f_f the mean of phi_p / (12 eta)
  // of the two nodes, C_f = (Ca hb + Cb ha) / (ha + hb). Accurate also where the gap changes
  // by a large factor within a cell (a thin-film patch near contact; lubrication/README.md,
  // "Face values"), and the only scheme that honours gapFloor_m.
  LinearGap,
};

// How the Couette flux through a face takes the fill fraction theta_up (the "Discrete
// equation" above). Only the mass-conserving model with a time step and history.last
// uses it; everywhere else theta_up is the upwind node's (a full film has theta = 1).
enum class FillFractionFlux {
  // theta_up = the upwind node's fill fraction, implicit: monotone, first order where theta
  // varies (it smears a reformation front and a starved film's oil over a few cells). The
  // default, the scheme every cycle figure before 2026-12-05 was computed with.
  Upwind,
  // theta_up + (1/2) minmod(theta_up - theta_upup (scaled to the face's spacing),
  // theta_down - theta_up), the limited second-order (MUSCL) face value, with the correction
  // to the upwind value taken from history.last: the upwind part stays implicit, the
  // second-order part is an explicit face flux (deferred correction lagged by one step; it
  // adds a known term to the net outflow of the "Discrete equation" above). A face whose
  // upwind node has no upwind neighbour stays first order. The correction fluxes are scaled
  // down (Zalesak's flux limiter) so that alone they would move no unknown node's storage
  // reference outside the range of history.last's fill fraction over the node and its four
  // neighbours (within [0, 1]); they cancel between the two nodes of every face, so the
  // scheme conserves mass exactly. The face value may exceed 1 for one step where its
  // upwind node fills during the step (still conservative). Second order in space (a cavitated
  // film's oil transport: L1 order 1.89 against 0.94 upwind). Bounded (no new extremum at a
  // front) with backward Euler up to Courant numbers |U| dt / (2 d) of 0.9 and with the BDF2
  // history up to 0.25 (the skirt's peak at its largest 0.25 deg steps, 2000 rpm: ~0.14 on
  // 64 x 48, ~0.29 on 128 x 96); beyond that BDF2
  // overshoots (0.3: +8e-5 of a unit front, 0.5: +0.022; BDF2 with the upwind value alone at
  // 0.9: +0.004). test_film_fill_fraction_flux.cpp, lubrication/README.md, "Fill-fraction
  // flux".
  LimitedSecondOrder,
};

// One open edge of the film region. Ignored for x edges of an x-periodic grid.
struct FilmEdge {
  // Pressure on the edge, [Pa], default 0 (gauge ambient). MassConserving: must be >=
  // cavitationPressure_Pa (rejected otherwise: no mass-conserving solution would exist).
  double pressure_Pa = 0.0;
  // Oil layer available on surface 1 ahead of this edge, [m], default +inf (fully flooded).
  // Only used where surface 1 slides into the region through this edge (U . inward normal > 0).
  // The layer moves with surface 1, so the supply is U_n * supplyFilm_m per unit edge length; a
  // full film carries U_n * h / 2, hence the edge is flooded where h <= 2 * supplyFilm_m.
  //  * MassConserving: the edge node gets the fill fraction theta_b <= 1 for which the Couette
  //    inflow through its face equals U_n * supply * (edge length of the node), i.e. about
  //    2 supply / hT, and, when starved (theta_b < 1), the cavitation pressure instead of
  //    pressure_Pa.
  //  * None / Reynolds (heuristic of the thesis' partially flooded skirt, not mass conserving):
  //    along every grid line entering through this edge, the nodes before the first node with
  //    h <= 2 * supply are dry (pressure held at pressure_Pa, fill fraction 0, no shear); the
  //    wetted region starts at that meniscus node.
  double supplyFilm_m = std::numeric_limits<double>::infinity();
  // Optional per-node supply along the edge ([m]; size nx for y edges, ny for x edges);
  // overrides supplyFilm_m when not empty.
  Eigen::ArrayXd supplyFilmPerNode_m;
};

struct FilmBoundary {
  FilmEdge xMin, xMax;  // edges i = 0 and i = nx - 1 (not used when the grid is x-periodic)
  FilmEdge yMin, yMax;  // edges j = 0 and j = ny - 1
  // Corner nodes take the pressure of the x edge when x is open.
};

// Everything a solve needs besides the grid. Keep one object per film region and update its
// arrays in place between calls: no allocation happens at a fixed size.
struct FilmProblem {
  Eigen::ArrayXd gap_m;        // nominal gap h per node, [m], > 0 and finite (required)
  FaceValues faces = FaceValues::NodalMean;  // face conductance and content (FaceValues)
  // Optional floor h_c of the gap [m] (0 = none, the default; else finite and > 0, every gap_m
  // above it, and faces = LinearGap): gap_m are then the film gaps h_f = calcFlooredGap(h,
  // h_c) of a nominal gap h (GapFloor.h) that may be <= 0 where rough surfaces touch. The face values (above)
  // take h linear between the nodes instead of h_f: near a contact the floor's knee, where
  // h_f bends from h to h_c over a nominal range of a few h_c, is far narrower than a cell,
  // and a face across it integrates K and C through it (exactly for h_f; the flow factors and
  // contents linear between points at fixed multiples of h_c, FilmSystem.cpp). Everything
  // else (nodal terms, rates, bases, results) is in terms of gap_m as given.
  double gapFloor_m = 0.0;
  Eigen::ArrayXd gapRate_mps;  // dh/dt per node at a fixed grid point, [m/s]; empty = 0
  Eigen::Vector2d slidingVelocity_mps = Eigen::Vector2d::Zero();  // U of surface 1 rel. to 2
                                                                  // along (x, y), [m/s]
  double viscosity_Pas = 0.0;           // dynamic viscosity, [Pa s], > 0 unless per-node given
  Eigen::ArrayXd viscosityPerNode_Pas;  // optional per-node viscosity, [Pa s]; overrides scalar
  // Flow-factor model (average Reynolds of Patir & Cheng); nullptr = smooth surfaces (plain
  // Reynolds). Pressure flow factors are applied along the grid axis closest to the sliding
  // direction ("sliding") and across it ("cross"); y is taken as sliding when U = 0. The
  // shear-flow term sigma*phiS is transported with U/2 in the sliding direction.
  const FlowFactorModel* flowFactors = nullptr;

  CavitationModel cavitation = CavitationModel::Reynolds;
  double cavitationPressure_Pa = 0.0;  // p_cav, [Pa], default 0 (gauge ambient)
  FilmBoundary boundary;

  // Mass-conserving model only: time step since the state of history.last, [s] (> 0; +inf =
  // steady state, the default), and the film's history (FilmHistory.h: the fill fraction and
  // expected gap at the last one or two accepted steps; empty = a full film at rest).
  // A steady problem needs an oil supply (an edge above p_cav or a flooded inflow edge): on an
  // x-periodic region whose open edges all sit at p_cav, any pure Couette circulation with
  // theta * hT = const solves the steady equations, so the answer is not unique (the fast
  // solver then reports non-convergence and falls back). Use a time step there.
  //
  // Storage term. With history.last alone the fill fraction's time derivative is backward
  // Euler, (theta - theta_n)/h; with history.earlier (theta_{n-1}) and earlierStep_s = h_prev
  // it is variable-step BDF2,
  //   dtheta/dt ~ [c0 theta - (1 + w) theta_n + w^2/(1 + w) theta_{n-1}] / h,
  //   w = h / h_prev, c0 = (1 + 2w)/(1 + w);
  // the storage diagnostics follow the same formula. Use BDF2 when the caller's own time
  // integration is second order, so that the film's history does not limit it to first.
  // With the expected gaps of the history points (recommended whenever the gap moves) the
  // storage term d(theta hT)/dt is split as
  //   theta dhT/dt  +  [hT_n (theta - theta_n)] / h                        (backward Euler)
  //   theta dhT/dt  +  [(1 + w) hT_n (theta - theta_n)
  //                     - w^2/(1 + w) hT_{n-1} (theta - theta_{n-1})] / h   (BDF2)
  // with the instantaneous squeeze rate dhT/dt of gapRate_mps, so a full film still sees the
  // exact squeeze term, while a cavitated node whose gap moves linearly over the step keeps
  // its oil content theta hT exactly. Without them hT of THIS step stands for hT_n (and
  // hT_{n-1}): that form is exact only for a fixed gap and, where the gap closes within a
  // step, creates oil, without bound as the closure approaches the gap (theta_{n+1} =
  // theta_n hT / (hT + dhT/dt h)). A BDF2 node whose capacity (1 + w) hT_n - w^2/(1 + w)
  // hT_{n-1} is not at least half of c0 hT_n (a gap that shrank by more than ~2x in one step)
  // takes the backward-Euler form for that step.
  double timeStep_s = std::numeric_limits<double>::infinity();
  FilmHistory history;
  // How Couette faces take the fill fraction (FillFractionFlux above), default Upwind.
  FillFractionFlux fillFractionFlux = FillFractionFlux::Upwind;

  // Optional squeeze basis: column m is d(gapRate)/d(v_m) per node ([m/s per unit v_m]) for a
  // generalised velocity v_m. The result then holds d(p)/d(v_m) and the derivatives of load and
  // moments, from back-substitutions with the final factorisation and active set (the pressure
  // is linear in the squeeze velocity for a fixed cavitation set).
  Eigen::MatrixXd squeezeBasis;
  // Optional gap basis: column g is d(gap_m)/d(u_g) per node ([m per unit u_g]) for a
  // generalised displacement u_g that changes the gap but not its rate (gapRate_mps and the
  // history stay as given). The result then holds d(p)/d(u_g) on the final active set
  // (FilmResult::dPressure_dGap): the static pressure-gap sensitivity an elastic coupling's
  // Newton iteration needs. Its right-hand side is the derivative of the discrete balance in
  // u_g: the balance's five-point gap Jacobian d R_k / d h_l from five one-sided assemblies,
  // each perturbing the nodes of one colour (i + 2 j) mod 5 by 1e-6 of their gap (no two nodes
  // of a stencil share a colour; a relative error ~2e-6 for the h^3 terms), whatever the
  // number of columns; on a periodic grid whose nx is not a multiple of 5, two assemblies per
  // column instead (central difference, step 1e-4 of the thinnest gap over the column's
  // largest entry, ~1e-8). Then one back-substitution per column, solved with the squeeze
  // columns. A fixed node whose classification or inflow content depends on a gap further
  // than its stencil (an inflow edge) can be misattributed there: the derivative serves
  // Newton iterations, not figures.
  Eigen::MatrixXd gapBasis;
  // Optional, with gapBasis (same columns; empty = none): column g also moves the gap RATE by
  // gapRateBasis(:, g) per unit u_g [m/s per unit u_g], e.g. an elastic deformation whose rate
  // is backward Euler over the step (-Psi / dt). dPressure_dGap is then the total derivative,
  // static and squeeze parts in one back-substitution (instead of a squeeze column more).
  Eigen::MatrixXd gapRateBasis;

  Eigen::Vector2d momentPoint_m = Eigen::Vector2d::Zero();  // (x0, y0) for moments, [m]
  double referencePressure_Pa = 0.0;  // subtracted from p in load and moments, [Pa]
};

// Preconditioner of the fast solver's Krylov iterations. Both run to the same tolerance; they
// differ in cost only.
enum class FastLinearSolver {
  // Multigrid from kMultigridMinNodes grid nodes up, SparseDirect below (BENCHMARKS.md: the
  // lagged factorisation is the cheaper one on small grids, multigrid grows linearly with the
  // grid). Should a multigrid solve fail (it then factorises that matrix), the solver object
  // uses SparseDirect for the next 8 calls (16, 32, ... up to 1024 after further failures) and
  // then tries multigrid again.
  Automatic,
  // Lagged sparse factorisation: CHOLMOD LDL' (AMD ordering, drift-rescaled) for PCG on the
  // symmetric Reynolds / full-Sommerfeld systems, KLU for GMRES on the mass-conserving ones.
  SparseDirect,
  // Geometric multigrid V-cycle on the grid (Galerkin coarse levels, red-black Gauss-Seidel,
  // cavitated nodes masked): the PCG preconditioner of the symmetric systems; for the
  // mass-conserving ones the pressure block of a block-triangular GMRES preconditioner whose
  // fill-fraction block is one upwind sweep.
  Multigrid,
};
// Grid size from which FastLinearSolver::Automatic picks multigrid: on smaller grids the lagged
// factorisation costs less per solve, on larger ones multigrid does (multigrid's cost grows
// linearly with the node count, the factorisation's faster). The crossover measured on the skirt
// benchmark is in BENCHMARKS.md.
constexpr int kMultigridMinNodes = 2000;

// Warm start that the caller keeps between steps (e.g. in the Simbody State cache). Small,
// copyable. Empty arrays (the default) mean "no warm start".
struct FilmState {
  Eigen::ArrayXd pressure_Pa;           // nodal pressure, [Pa]
  Eigen::ArrayXd fillFraction;          // nodal fill fraction theta, [-]
  std::vector<std::uint8_t> cavitated;  // 1 where the node was cavitated (active set)
  bool empty() const { return pressure_Pa.size() == 0; }
};

struct FilmSolverOptions {
  FilmSolverType solver = FilmSolverType::FastActiveSet;  // default: the fast solver
  double tolerance = 1e-8;  // relative residual (see top of file), default 1e-8
  // Relative accuracy of the squeeze-derivative solves (FilmResult::dPressure_dVelocity, each
  // column to this fraction of its right-hand side's largest entry), default 1e-6. They
  // serve the Jacobians of implicit steppers, whose Newton iterations converge with an
  // approximate Jacobian: they need not be as accurate as the film itself (each column is a
  // Krylov solve of its own; BENCHMARKS.md has what the looser default saves).
  double derivativeTolerance = 1e-6;
  // Fast solver, many squeeze-derivative columns (an elastic skirt asks for one per deformation
  // mode): when the first column's Krylov cost says that the rest would cost more than one
  // factorisation of the current Jacobian, factorise it and back-substitute the remaining
  // columns (exact to round-off instead of derivativeTolerance). Default on; off keeps one
  // Krylov solve per column (for comparisons, BENCHMARKS.md).
  bool factoriseForManyDerivativeColumns = true;
  int maxSweeps = 200000;   // Gauss-Seidel sweeps before giving up, default 200000
  // SOR factor of the pressure update, (0, 2), default 1.8. The best value grows with the grid
  // (the best values found on the skirt benchmark are in BENCHMARKS.md).
  double overRelaxation = 1.8;
  double fillRelaxation = 1.0;      // relaxation of the fill-fraction update (JFO GS), (0, 1]
  int maxActiveSetIterations = 40;  // active-set (Newton) steps of the fast solver, default 40
  // Preconditioner of the fast solver's linear solves, default Automatic (see FastLinearSolver).
  FastLinearSolver linearSolver = FastLinearSolver::Automatic;
  // When the active-set iteration does not settle within maxActiveSetIterations, continue from
  // its iterate with the reference Gauss-Seidel (reported in FilmResult::usedFallback).
  bool fallbackToReference = true;
  // Fast solver, cold starts only (no warm start given): start from the same problem solved
  // on every other node (recursively, down to grids of fewer than 9 nodes a direction) and
  // interpolated back, so that the active-set steps on the fine grid do not grow with the grid
  // (a cold start otherwise moves the cavitation front a few cells per step). Its coarser
  // steps are reported in FilmResult::coarseActiveSetIterations. Default on.
  bool gridSequencedColdStart = true;
};

// Shear stress and friction acting on one surface, split into Couette (sliding) and Poiseuille
// (pressure-gradient) parts. Stresses are the force per area the film exerts on the surface,
// along the grid axes x and y.
struct SurfaceShear {
  Eigen::ArrayXd couetteX_Pa, couetteY_Pa;                   // nodal Couette shear stress, [Pa]
  Eigen::ArrayXd poiseuilleX_Pa, poiseuilleY_Pa;             // nodal Poiseuille shear stress, [Pa]
  Eigen::Vector2d couetteForce_N = Eigen::Vector2d::Zero();  // integral over the film, [N]
  Eigen::Vector2d poiseuilleForce_N = Eigen::Vector2d::Zero();  // integral over the film, [N]
  // In-plane moment about momentPoint: integral of (x - x0) tau_y - (y - y0) tau_x dA, [N m].
  double couetteMoment_Nm = 0.0;
  double poiseuilleMoment_Nm = 0.0;
  Eigen::Vector2d force_N() const { return couetteForce_N + poiseuilleForce_N; }
  double moment_Nm() const { return couetteMoment_Nm + poiseuilleMoment_Nm; }
};

struct FilmResult {
  FilmState state;  // pressure [Pa], fill fraction [-], active set: store this as the warm start
  const Eigen::ArrayXd& pressure_Pa() const { return state.pressure_Pa; }
  const Eigen::ArrayXd& fillFraction() const { return state.fillFraction; }

  Eigen::ArrayXd areaWeights_m2;  // nodal area weights (copy of the grid's), [m^2]
  // Expected gap hT per node, [m] (the nominal gap h without a flow-factor model): the oil
  // content of a node is theta hT per area. Pass it as FilmProblem::history.last.expectedGap_m of
  // the next transient step.
  Eigen::ArrayXd expectedGap_m;

  // Load = integral of (p - referencePressure) over the film (exact for the bilinear field), [N]
  double load_N = 0.0;
  // First moments about momentPoint: integral of (x - x0)(p - pref) dA and (y - y0)(p - pref) dA,
  // [N m] (exact for the bilinear field).
  double firstMomentX_Nm = 0.0;
  double firstMomentY_Nm = 0.0;

  // Friction. Couette shear: surface 2 gets +theta eta U / h (phiF - phiFs), surface 1 gets
  // -theta eta U / h (phiF + phiFs); Poiseuille shear on both: -phiFp (h / 2) grad p. The Couette
  // shear is carried by the fill fraction theta: the mass-conserving model's theta in cavitated
  // zones, 1 in the Reynolds / None models (whose cavitated zones are assumed filled) except on
  // dry starved nodes (0). grad p is the nodal gradient (second order, one-sided at open edges).
  SurfaceShear shearOnSurface1;  // e.g. the liner / journal
  SurfaceShear shearOnSurface2;  // the grid's surface, e.g. the skirt / bearing shell

  Eigen::ArrayXd gapOverSigma;  // h / sigma per node; empty when the model's sigma is 0
  double minFilmThickness_m = 0.0;
  int minFilmNode = -1;                                         // flat node index of the minimum
  Eigen::Vector2d minFilmLocation_m = Eigen::Vector2d::Zero();  // (x, y) of the minimum

  // Oil flow diagnostics of the discrete balance (all models; conserved by MassConserving):
  // inflow and outflow through the faces between prescribed (edge, dry) and unknown nodes, and
  // the storage rate sum_k A_k [theta dhT/dt + hT (theta - thetaPrev)/dt] of the unknown nodes.
  double boundaryInflow_m3ps = 0.0;
  double boundaryOutflow_m3ps = 0.0;
  double storageRate_m3ps = 0.0;
  // The same balance at the edge lines themselves: the net flow out of the film across each
  // open edge, per edge node [m^3/s] (+ out): yMin / yMax one entry per column (nx), xMin /
  // xMax one per row (ny; empty on an x-periodic grid; the corner nodes count with the y
  // edges). Each is the flow through the face between the edge node and the node inside
  // it: the edge nodes' half cells, whose fill the boundary prescribes, count as outside (their
  // storage would draw oil the outside need not hold). edgeInflow / edgeOutflow sum the
  // entries' negative and positive parts; with the mass-conserving model edgeInflow -
  // edgeOutflow = storageRate_m3ps (the interior nodes' storage), and oilVolume_m3 is sum over
  // all nodes of A theta hT.
  Eigen::ArrayXd edgeOutflowYMin_m3ps, edgeOutflowYMax_m3ps;
  Eigen::ArrayXd edgeOutflowXMin_m3ps, edgeOutflowXMax_m3ps;
  double edgeInflow_m3ps = 0.0;
  double edgeOutflow_m3ps = 0.0;
  double oilVolume_m3 = 0.0;
  // Power the film dissipates [W], >= 0: the Couette part sum_k A_k theta_k eta_k |U|^2 phiF_k
  // / h_k and the Poiseuille part sum over faces K_f L_f / d_f (p_a - p_b)^2 (the discrete
  // energy of the pressure flux; smooth surfaces: int eta U^2/h + h^3 |grad p|^2 / (12 eta) dA).
  // For a steady full film with the edges at one pressure it equals U . (force of the film on
  // surface 1) = the friction power of the sliding surface.
  double viscousDissipation_W = 0.0;

  // Squeeze derivatives (empty without a squeeze basis): column m is d/d(v_m).
  Eigen::MatrixXd dPressure_dVelocity;  // [Pa per unit v_m], nodeCount x M
  Eigen::VectorXd dLoad_dVelocity;      // [N per unit v_m]
  Eigen::VectorXd dFirstMomentX_dVelocity, dFirstMomentY_dVelocity;  // [N m per unit v_m]
  // Gap derivatives (empty without a gap basis): column g is d(p)/d(u_g) [Pa per unit u_g],
  // nodeCount x G, zero at nodes not in the full film (fixed, cavitated).
  Eigen::MatrixXd dPressure_dGap;

  // Solver report. iterations: Gauss-Seidel sweeps of the reference solver, or active-set steps
  // of the fast solver plus the sweeps of a fallback (activeSetIterations: the steps alone).
  // Not converged means: the residual is above tolerance after the allowed iterations; the
  // fields then hold the last iterate (finite, constraints kept) and the caller decides (e.g.
  // reject the integrator step).
  int iterations = 0;
  int activeSetIterations = 0;
  // Active-set steps on the coarser grids of a grid-sequenced cold start, all levels summed
  // (FilmSolverOptions::gridSequencedColdStart; 0 otherwise). Each coarser level has about a
  // quarter of the nodes of the one above.
  int coarseActiveSetIterations = 0;
  int factorisations = 0;    // numeric sparse factorisations done in this call (fast solver)
  int krylovIterations = 0;  // preconditioned Krylov iterations done in this call (fast solver)
  int multigridBuilds = 0;   // multigrid hierarchies (Galerkin levels) built in this call
  double residual = 0.0;
  bool converged = false;
  bool usedFallback = false;
  // The squeeze- and gap-derivative solve failed (the final active set's Jacobian is singular
  // to the linear solvers, Krylov and sparse-direct): the derivative fields above are all zero,
  // not derivatives. The pressure and loads are unaffected. Callers that steer a Newton
  // iteration with the derivatives count it (the skirt element does).
  bool derivativesFailed = false;
  int cavitatedNodes = 0;  // unknown nodes at the cavitation pressure
};

}  // namespace pistondyn::lubrication
