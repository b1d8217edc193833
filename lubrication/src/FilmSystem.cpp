#include "FilmSystem.h"

#include "pistondyn/lubrication/GapFloor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace pistondyn::lubrication::detail {

namespace {

// Nominal gaps, in units of the floor h_c, at which a face across the knee of a floored gap
// (FilmProblem::gapFloor_m) is split: dense where h_f bends (|h| <= 2 h_c), growing by at
// most 2x beyond, out to +-64 h_c, where h_f - h is 6e-5 of h above and h_f - h_c 4e-3 of h_c
// below (the pieces beyond take h_f linear). Faces whose nominal gaps both lie at or above
// kKneeFaceLimit h_c (h_f within 0.1 % of h) are not split. A face 6 h_c long in nominal gap
// gets its resistance within 4e-5 of the exact integral at any place across the knee.
constexpr double kKneeBreakpoints[] = {-64.0, -48.0, -32.0, -24.0, -16.0, -12.0, -8.0, -4.0,
                                       -2.0,  -1.5,  -1.0,  -0.75, -0.5,  -0.25, 0.0,  0.25,
                                       0.5,   0.75,  1.0,   1.25,  1.5,   2.0,   2.5,  3.0,
                                       4.0,   5.0,   6.0,   8.0,   12.0,  16.0,  24.0, 32.0,
                                       48.0,  64.0};
constexpr int kKneePoints = static_cast<int>(sizeof(kKneeBreakpoints) / sizeof(double));
constexpr double kKneeFaceLimit = 16.0;
// 3-point Gauss-Legendre on [0, 1]: the pieces inside the breakpoints' range integrate
// 1/h_f^3 (and C/h_f^3) with h_f of the nominal gap itself.
constexpr double kKneeGaussT[3] = {0.11270166537925831, 0.5, 0.88729833462074169};
constexpr double kKneeGaussW[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

// Supply film of an edge at position `along` (index along the edge).
double edgeSupply(const FilmEdge& e, int along) {
  return e.supplyFilmPerNode_m.size() > 0 ? e.supplyFilmPerNode_m[along] : e.supplyFilm_m;
}

// What the face values along one grid direction need (FilmSystem::assembleFaces).
struct FaceInputs {
  const FilmProblem& pr;
  const Eigen::ArrayXd& conductance;                // FilmSystem::nodeConductanceX or Y
  const Eigen::ArrayXd& content;                    // FilmSystem::couetteContentX or Y
  const Eigen::ArrayXd& eta;                        // nodal viscosity [Pa s]
  const std::vector<NodeFlowFactors>& kneeFactors;  // FilmSystem::kneeFactors
  bool linearGapFaces;                              // FaceValues::LinearGap
  bool slidingAlong;                                // the direction is the sliding one
  double floor_m;                                   // the gap floor h_c (0: none)
};

// A face across the knee of a floored gap (FilmProblem::gapFloor_m), walked from node a to
// node b in pieces between the knee breakpoints (h is linear along the face, so each
// breakpoint has its place s); f and C are linear between the pieces' ends (the nodes' own
// values, or the model's at the breakpoint's film gap with the viscosity interpolated along
// the face); a piece inside the breakpoints' range integrates 1/(f h_f^3) and C/(f h_f^3) at
// 3 Gauss points with h_f of the nominal gap there, a piece beyond it (a node deep in contact
// or far from it) takes h_f linear (the LinearGap formulas); the pieces' resistances mean(1/K)
// and mean(C/K) add.
class FaceAcrossKnee {
 public:
  // The walk starts at node a: nominal gap, film gap, conductance factor, Couette content.
  FaceAcrossKnee(double na, double ha, double fa, double ca, double floor_m)
      : floor_(floor_m),
        low_(floor_m * kKneeBreakpoints[0]),
        high_(floor_m * kKneeBreakpoints[kKneePoints - 1]),
        n1_(na),
        h1_(ha),
        f1_(fa),
        c1_(ca) {}

  // The piece from the walk's place to place s2 (in [0, 1] along the face), whose end has the
  // nominal gap n2, film gap h2, conductance factor f2 and content c2.
  void addPiece(double s2, double n2, double h2, double f2, double c2) {
    const double len = s2 - s1_;
    if (std::min(n1_, n2) >= high_ || std::max(n1_, n2) <= low_) {
      const double denom = 2.0 * h1_ * h1_ * h2 * h2 * 0.5 * (f1_ + f2);
      resistance_ += len * (h1_ + h2) / denom;
      content_ += len * (c1_ * h2 + c2 * h1_) / denom;
    } else {
      for (int g = 0; g < 3; ++g) {
        const double hf = calcFlooredGap(n1_ + kKneeGaussT[g] * (n2 - n1_), floor_).film_m;
        // f and C linear in h_f between the piece's ends (C = h_f exactly when smooth).
        const double u = h2 != h1_ ? (hf - h1_) / (h2 - h1_) : 0.5;
        const double wk = len * kKneeGaussW[g] / ((f1_ + u * (f2 - f1_)) * hf * hf * hf);
        resistance_ += wk;
        content_ += wk * (c1_ + u * (c2 - c1_));
      }
    }
    s1_ = s2, n1_ = n2, h1_ = h2, f1_ = f2, c1_ = c2;
  }

  // (K_f, C_f) of the pieces so far.
  std::pair<double, double> faceValues() const {
    return {1.0 / resistance_, content_ / resistance_};
  }

 private:
  double floor_, low_, high_;            // h_c, and the breakpoints' range in nominal gap
  double s1_ = 0.0, n1_, h1_, f1_, c1_;  // the walk's place and its values there
  double resistance_ = 0.0, content_ = 0.0;
};

// Face values (K_f, C_f) of the face between nodes a and b (FilmSystem::assembleFaces).
std::pair<double, double> calcFaceValues(const FaceInputs& in, int a, int b) {
  const Eigen::ArrayXd& f = in.conductance;
  const Eigen::ArrayXd& C = in.content;
  if (!in.linearGapFaces)
    return {0.5 * (f[a] + f[b]), 0.5 * (C[a] + C[b])};
  const double floor = in.floor_m;
  const double ha = in.pr.gap_m[a], hb = in.pr.gap_m[b];
  const double na = floor > 0.0 ? calcNominalGap(ha, floor) : ha;
  const double nb = floor > 0.0 ? calcNominalGap(hb, floor) : hb;
  if (!(floor > 0.0) || std::min(na, nb) >= floor * kKneeFaceLimit || na == nb) {
    return {0.5 * (f[a] + f[b]) * 2.0 * ha * ha * hb * hb / (ha + hb),
            (C[a] * hb + C[b] * ha) / (ha + hb)};
  }
  // Walk from a to b through the breakpoints strictly between na and nb.
  const bool up = nb > na;
  FaceAcrossKnee face(na, ha, f[a], C[a], floor);
  for (int q = 0; q < kKneePoints; ++q) {
    const int m = up ? q : kKneePoints - 1 - q;
    const double bp = kKneeBreakpoints[m] * floor;
    if (!(up ? (bp > na && bp < nb) : (bp < na && bp > nb)))
      continue;
    const double s = (bp - na) / (nb - na);
    const NodeFlowFactors& kf = in.kneeFactors[static_cast<std::size_t>(m)];
    const double mu = in.eta[a] + s * (in.eta[b] - in.eta[a]);
    const double phi = in.slidingAlong ? kf.phiPressureSliding : kf.phiPressureCross;
    const double c = kf.expectedGap_m + (in.slidingAlong ? kf.sigmaPhiS_m : 0.0);
    face.addPiece(s, bp, calcFlooredGap(bp, floor).film_m, phi / (12.0 * mu), c);
  }
  face.addPiece(1.0, nb, hb, f[b], C[b]);
  return face.faceValues();
}

}  // namespace

void FilmSystem::resizeFor(const FilmGrid& grid) {
  const bool same = grid.nx() == nx && grid.ny() == ny && grid.isPeriodicX() == periodicX;
  if (same)
    return;
  nx = grid.nx();
  ny = grid.ny();
  n = nx * ny;
  periodicX = grid.isPeriodicX();
  nbE.assign(n, 0);
  nbW.assign(n, 0);
  nbN.assign(n, 0);
  nbS.assign(n, 0);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int k = i + nx * j;
      nbE[k] = (i + 1 < nx) ? k + 1 : (periodicX ? nx * j : k);
      nbW[k] = (i > 0) ? k - 1 : (periodicX ? nx - 1 + nx * j : k);
      nbN[k] = (j + 1 < ny) ? k + nx : k;
      nbS[k] = (j > 0) ? k - nx : k;
    }
  }
  order.reserve(n);
  for (Eigen::ArrayXd* a : {&tE,
                            &tW,
                            &tN,
                            &tS,
                            &diagP,
                            &couE,
                            &couN,
                            &aOut,
                            &inCx,
                            &inCy,
                            &squeeze,
                            &capacity,
                            &thetaPrev,
                            &thetaCoef,
                            &src,
                            &fixedPressure,
                            &fixedTheta,
                            &hT,
                            &dhTdh,
                            &eta,
                            &phiF,
                            &phiFs,
                            &phiFp,
                            &p,
                            &theta,
                            &fillCorrE,
                            &fillCorrN,
                            &fillCorrOut,
                            &fillCorrScratch,
                            &fillLimitE,
                            &fillLimitN,
                            &nodeConductanceX,
                            &nodeConductanceY,
                            &couetteContentX,
                            &couetteContentY}) {
    a->setZero(n);
  }
  inIx.assign(n, 0);
  inIy.assign(n, 0);
  status.assign(n, kFull);
  dry.assign(n, 0);
  fillFromInterior.assign(n, 0);
}

void FilmSystem::calcNodeFactors(const FilmProblem& pr, const Eigen::ArrayXd& gap_m,
                                 std::vector<NodeFlowFactors>& out) const {
  const SmoothFlowFactors smooth;
  const FlowFactorModel& ffm = pr.flowFactors ? *pr.flowFactors : smooth;
  out.resize(static_cast<std::size_t>(gap_m.size()));
  for (Eigen::Index k = 0; k < gap_m.size(); ++k)
    out[static_cast<std::size_t>(k)] = ffm.calcFactors(gap_m[k]);
}

void FilmSystem::assemble(const FilmGrid& grid, const FilmProblem& pr) {
  calcNodeFactors(pr, pr.gap_m, nodeFactors);
  assembleFromNodeFactors(grid, pr);
}

void FilmSystem::assembleFromNodeFactors(const FilmGrid& grid, const FilmProblem& pr) {
  resizeFor(grid);
  model = pr.cavitation;
  jfo = model == CavitationModel::MassConserving;
  pCav = pr.cavitationPressure_Pa;
  const double Ux = pr.slidingVelocity_mps.x();
  const double Uy = pr.slidingVelocity_mps.y();
  const bool slideY = std::abs(Uy) >= std::abs(Ux);
  calcNodeConductances(pr, slideY);
  assembleFaces(grid, pr, slideY);
  assembleUpwindCouette(Ux, Uy);
  assembleStorage(grid, pr);
  classifyFixedNodes(grid, pr);
  calcResidualScale();
  // Needs the capacities and the fixed nodes; its fluxes are bounded by the capacities, so
  // they do not enter the residual's scale.
  assembleFillFractionCorrection(grid, pr);
  buildSweepOrder(Ux, Uy);
}

void FilmSystem::calcNodeConductances(const FilmProblem& pr, bool slideY) {
  const bool perNodeEta = pr.viscosityPerNode_Pas.size() > 0;
  for (int k = 0; k < n; ++k) {
    const NodeFlowFactors& f = nodeFactors[static_cast<std::size_t>(k)];
    const double mu = perNodeEta ? pr.viscosityPerNode_Pas[k] : pr.viscosity_Pas;
    const double h = pr.gap_m[k];
    const double base = pr.faces == FaceValues::LinearGap ? 1.0 / (12.0 * mu)
                                                          : h * h * h / (12.0 * mu);
    const double phiSlide = f.phiPressureSliding, phiCross = f.phiPressureCross;
    nodeConductanceX[k] = base * (slideY ? phiCross : phiSlide);
    nodeConductanceY[k] = base * (slideY ? phiSlide : phiCross);
    couetteContentX[k] = f.expectedGap_m + (slideY ? 0.0 : f.sigmaPhiS_m);
    couetteContentY[k] = f.expectedGap_m + (slideY ? f.sigmaPhiS_m : 0.0);
    hT[k] = f.expectedGap_m;
    dhTdh[k] = f.dExpectedGap_dh;
    eta[k] = mu;
    phiF[k] = f.phiF;
    phiFs[k] = f.phiFs;
    phiFp[k] = f.phiFp;
  }
}

void FilmSystem::updateKneeFactors(const FilmProblem& pr, double floor_m) {
  const FlowFactorModel* factorModel = pr.flowFactors;
  if (kneeFactors.size() == static_cast<std::size_t>(kKneePoints) && kneeModel == factorModel &&
      kneeFloor_m == floor_m)
    return;
  const SmoothFlowFactors smooth;
  const FlowFactorModel& ffm = factorModel ? *factorModel : smooth;
  kneeFactors.resize(kKneePoints);
  for (int m = 0; m < kKneePoints; ++m)
    kneeFactors[m] = ffm.calcFactors(calcFlooredGap(kKneeBreakpoints[m] * floor_m, floor_m).film_m);
  kneeModel = factorModel;
  kneeFloor_m = floor_m;
}

// Face values (FilmProblem.h, "Discrete equation", FaceValues). NodalMean: the means of the
// two nodes' K and C. LinearGap: exact for a gap linear between the two nodes. Along the
// face the flux q = -K dp/ds + U C / 2 is constant, so the face carries
//   K_f = 1 / mean(1/K)  and  C_f = mean(C/K) / mean(1/K),
// which for K = f h^3 (f = phi_p / (12 eta) averaged over the two nodes) and C linear are
//   K_f = f 2 ha^2 hb^2 / (ha + hb),   C_f = (Ca hb + Cb ha) / (ha + hb).
// Both are the arithmetic means where ha = hb; unlike those, they stay accurate where the
// gap changes by a large factor within a cell, as around a small thin-film patch
// (lubrication/README.md, "Face values": a paraboloid patch one cell wide carries its
// closed-form squeeze load within 4.7 %, against -41 % with the nodal means).
//
// Floored gaps (FilmProblem::gapFloor_m): where one of a face's nominal gaps h lies below
// kKneeFaceLimit h_c, the face is split at the knee breakpoints between its two nominal gaps
// (FaceAcrossKnee).
void FilmSystem::assembleFaces(const FilmGrid& grid, const FilmProblem& pr, bool slideY) {
  const bool linearGapFaces = pr.faces == FaceValues::LinearGap;
  const double floor = linearGapFaces ? pr.gapFloor_m : 0.0;
  if (floor > 0.0)
    updateKneeFactors(pr, floor);
  const FaceInputs alongX{pr,          nodeConductanceX, couetteContentX, eta,
                          kneeFactors, linearGapFaces,   !slideY,         floor};
  const FaceInputs alongY{pr,          nodeConductanceY, couetteContentY, eta,
                          kneeFactors, linearGapFaces,   slideY,          floor};
  const Eigen::VectorXd& wx = grid.xWeights_m();
  const Eigen::VectorXd& wy = grid.yWeights_m();
  const double Ux = pr.slidingVelocity_mps.x();
  const double Uy = pr.slidingVelocity_mps.y();
  for (int j = 0; j < ny; ++j) {
    const double dyN = grid.dyNorth_m(j);
    for (int i = 0; i < nx; ++i) {
      const int k = i + nx * j;
      const int e = nbE[k];
      if (e != k) {
        const double dx = grid.dxEast_m(i);
        const auto [K, C] = calcFaceValues(alongX, k, e);
        tE[k] = K * wy[j] / dx;
        couE[k] = 0.5 * Ux * C * wy[j];
      } else {
        tE[k] = 0.0;
        couE[k] = 0.0;
      }
      const int no = nbN[k];
      if (no != k) {
        const auto [K, C] = calcFaceValues(alongY, k, no);
        tN[k] = K * wx[i] / dyN;
        couN[k] = 0.5 * Uy * C * wx[i];
      } else {
        tN[k] = 0.0;
        couN[k] = 0.0;
      }
    }
  }
}

void FilmSystem::assembleUpwindCouette(double Ux, double Uy) {
  // West / south transmissibilities and the upwind Couette coefficients.
  for (int k = 0; k < n; ++k) {
    const int w = nbW[k], s = nbS[k], e = nbE[k], no = nbN[k];
    tW[k] = (w != k) ? tE[w] : 0.0;
    tS[k] = (s != k) ? tN[s] : 0.0;
    diagP[k] = tE[k] + tW[k] + tN[k] + tS[k];
    double out = 0.0;
    inCx[k] = 0.0;
    inIx[k] = k;
    if (Ux > 0.0) {
      out += couE[k];
      if (w != k) {
        inCx[k] = couE[w];
        inIx[k] = w;
      }
    } else if (Ux < 0.0) {
      if (w != k)
        out += -couE[w];
      inCx[k] = -couE[k];
      inIx[k] = e;
    }
    inCy[k] = 0.0;
    inIy[k] = k;
    if (Uy > 0.0) {
      out += couN[k];
      if (s != k) {
        inCy[k] = couN[s];
        inIy[k] = s;
      }
    } else if (Uy < 0.0) {
      if (s != k)
        out += -couN[s];
      inCy[k] = -couN[k];
      inIy[k] = no;
    }
    aOut[k] = out;
  }
}

void FilmSystem::assembleStorage(const FilmGrid& grid, const FilmProblem& pr) {
  const Eigen::ArrayXd& area = grid.areaWeights_m2();
  const bool hasRate = pr.gapRate_mps.size() > 0;
  const bool transient = jfo && std::isfinite(pr.timeStep_s);
  const bool hasPrev = pr.history.last.fillFraction.size() > 0;
  // Backward Euler: capacity = A hT / h, reference theta_n. Variable-step BDF2
  // (FilmProblem::history.earlier.fillFraction): capacity = c0 A hT / h and the reference
  // [(1 + w) theta_n - w^2/(1 + w) theta_{n-1}] / c0, so that capacity (theta - reference) is
  // A hT times the BDF2 derivative. The reference may leave [0, 1]; it only enters here.
  const bool bdf2 = transient && hasPrev && pr.history.earlier.fillFraction.size() == n;
  const double w = bdf2 ? pr.timeStep_s / pr.history.earlierStep_s : 0.0;
  const double c0 = bdf2 ? (1.0 + 2.0 * w) / (1.0 + w) : 1.0;
  const double cn = bdf2 ? (1.0 + w) / c0 : 1.0, cn1 = bdf2 ? -w * w / (1.0 + w) / c0 : 0.0;
  // With the previous expected gaps (FilmProblem::history.last.expectedGap_m) the capacity and the
  // reference take hT_n (and hT_{n-1}) instead of this step's hT, which keeps the oil content
  // of a cavitated node whose gap moves linearly over the step (FilmProblem.h).
  const bool prevGap = transient && hasPrev && pr.history.last.expectedGap_m.size() == n;
  const bool prevGap2 = bdf2 && prevGap && pr.history.earlier.expectedGap_m.size() == n;
  const double wn = 1.0 + w, wn1 = w * w / (1.0 + w);
  for (int k = 0; k < n; ++k) {
    const double rate = hasRate ? pr.gapRate_mps[k] : 0.0;
    squeeze[k] = area[k] * dhTdh[k] * rate;
    capacity[k] = transient ? c0 * area[k] * hT[k] / pr.timeStep_s : 0.0;
    thetaPrev[k] = (jfo && hasPrev) ? pr.history.last.fillFraction[k] : 1.0;
    if (bdf2)
      thetaPrev[k] = cn * pr.history.last.fillFraction[k] + cn1 * pr.history.earlier.fillFraction[k];
    if (prevGap) {
      const double hn = pr.history.last.expectedGap_m[k];
      const double scale = area[k] / pr.timeStep_s;
      const double hn1 = prevGap2 ? pr.history.earlier.expectedGap_m[k] : hn;
      const double cap = bdf2 ? wn * hn - wn1 * hn1 : 0.0;
      if (bdf2 && cap >= 0.5 * c0 * hn) {
        capacity[k] = scale * cap;
        thetaPrev[k] = (wn * hn * pr.history.last.fillFraction[k] -
                        wn1 * hn1 * pr.history.earlier.fillFraction[k]) / cap;
      } else {
        // Backward Euler (also a BDF2 node whose gap shrank too fast for a positive capacity).
        capacity[k] = scale * hn;
        thetaPrev[k] = pr.history.last.fillFraction[k];
      }
    }
    thetaCoef[k] = aOut[k] + squeeze[k] + capacity[k];
  }
}

// ---- fixed nodes: open edges, starved inlets, dry zones ----
void FilmSystem::classifyFixedNodes(const FilmGrid& grid, const FilmProblem& pr) {
  std::fill(status.begin(), status.end(), static_cast<std::uint8_t>(kFull));
  std::fill(dry.begin(), dry.end(), static_cast<std::uint8_t>(0));
  std::fill(fillFromInterior.begin(), fillFromInterior.end(), static_cast<std::uint8_t>(0));
  fixedTheta.setOnes();
  fixedPressure.setZero();
  fixEdgeNodes(grid, pr);
  // Partial-flooding heuristic of the non-conservative models: march inwards from a starved
  // inflow edge until the gap can be filled by the supply.
  if (!jfo)
    markDryInlets(pr);
}

// Edge node k of `edge` (at index `along` along it). inflowCouette: full-film Couette flux
// through the node's face into the region (> 0 when surface 1 slides inwards); supplyFlux =
// U_n * supply * edge length of the node. Starved edge nodes of the non-conservative models
// are marked dry by the partial-flooding march (markDryInlets), which starts at every inflow
// edge node (corners included).
void FilmSystem::fixEdgeNode(int k, const FilmEdge& edge, int along, double inflowCouette,
                             double normalSpeed, double edgeLength) {
  status[k] = kFixed;
  fixedPressure[k] = edge.pressure_Pa;
  fixedTheta[k] = 1.0;
  // An edge above p_cav is the oil bath at that pressure (full); one at p_cav that no oil
  // enters through holds what the film carries there (FilmSystem.h).
  fillFromInterior[k] = jfo && !(normalSpeed > 0.0) && !(edge.pressure_Pa > pCav);
  if (!(normalSpeed > 0.0))
    return;
  const double s = edgeSupply(edge, along);
  if (!std::isfinite(s))
    return;
  if (jfo) {
    // Fill fraction that makes the Couette inflow exactly U_n * supply per edge length.
    const double supplyFlux = normalSpeed * s * edgeLength;
    const double th = inflowCouette > supplyFlux ? supplyFlux / inflowCouette : 1.0;
    fixedTheta[k] = th;
    if (th < 1.0)
      fixedPressure[k] = pCav;
  }
}

void FilmSystem::fixEdgeNodes(const FilmGrid& grid, const FilmProblem& pr) {
  const FilmBoundary& b = pr.boundary;
  const double Ux = pr.slidingVelocity_mps.x();
  const double Uy = pr.slidingVelocity_mps.y();
  const Eigen::VectorXd& wx = grid.xWeights_m();
  const Eigen::VectorXd& wy = grid.yWeights_m();
  // y edges first, then x edges so that corners take the x edge (FilmBoundary comment).
  for (int i = 0; i < nx; ++i) {
    const int kb = i, kt = i + nx * (ny - 1);
    fixEdgeNode(kb, b.yMin, i, couN[kb], Uy, wx[i]);
    fixEdgeNode(kt, b.yMax, i, -couN[nbS[kt]], -Uy, wx[i]);
  }
  if (!periodicX) {
    for (int j = 0; j < ny; ++j) {
      const int kl = nx * j, kr = nx - 1 + nx * j;
      fixEdgeNode(kl, b.xMin, j, couE[kl], Ux, wy[j]);
      fixEdgeNode(kr, b.xMax, j, -couE[nbW[kr]], -Ux, wy[j]);
    }
  }
}

void FilmSystem::markDryInlets(const FilmProblem& pr) {
  const FilmBoundary& b = pr.boundary;
  const double Ux = pr.slidingVelocity_mps.x();
  const double Uy = pr.slidingVelocity_mps.y();
  auto march = [&](const FilmEdge& edge, int along, int start, int step, int count) {
    const double s = edgeSupply(edge, along);
    if (!std::isfinite(s))
      return;
    for (int m = 0, k = start; m < count; ++m, k += step) {
      if (!(pr.gap_m[k] > 2.0 * s))
        break;
      if (status[k] != kFixed) {
        status[k] = kFixed;
        fixedPressure[k] = edge.pressure_Pa;
      }
      dry[k] = 1;
    }
  };
  if (Uy > 0.0)
    for (int i = 0; i < nx; ++i)
      march(b.yMin, i, i, nx, ny);
  if (Uy < 0.0)
    for (int i = 0; i < nx; ++i)
      march(b.yMax, i, i + nx * (ny - 1), -nx, ny);
  if (!periodicX && Ux > 0.0)
    for (int j = 0; j < ny; ++j)
      march(b.xMin, j, nx * j, 1, nx);
  if (!periodicX && Ux < 0.0)
    for (int j = 0; j < ny; ++j)
      march(b.xMax, j, nx - 1 + nx * j, -1, nx);
}

void FilmSystem::calcResidualScale() {
  // Pressure spread that drives Poiseuille flux through the faces (residual scale).
  double pMin = std::numeric_limits<double>::infinity(), pMax = -pMin;
  if (model != CavitationModel::None)
    pMin = pMax = pCav;
  int freeNodes = 0;
  double freeDiagSum = 0.0;
  for (int k = 0; k < n; ++k) {
    if (status[k] == kFixed) {
      pMin = std::min(pMin, fixedPressure[k]);
      pMax = std::max(pMax, fixedPressure[k]);
    } else {
      freeDiagSum += diagP[k];
      ++freeNodes;
    }
  }
  meanFreeDiagP = freeNodes > 0 && freeDiagSum > 0.0 ? freeDiagSum / freeNodes : 1.0;
  const double span = (pMax > pMin) ? pMax - pMin : 0.0;

  residualScale = 0.0;
  for (int k = 0; k < n; ++k) {
    // Reynolds-mode constant part (theta = 1 everywhere).
    src[k] = aOut[k] - inCx[k] - inCy[k] + squeeze[k];
    // Scale of the node's driving fluxes.
    const double fluxScale = aOut[k] + std::abs(inCx[k]) + std::abs(inCy[k]) +
                             std::abs(squeeze[k]) + capacity[k] + diagP[k] * span;
    if (status[k] != kFixed)
      residualScale = std::max(residualScale, fluxScale);
  }
  if (!(residualScale > 0.0))
    residualScale = 1.0;
}

void FilmSystem::buildSweepOrder(double Ux, double Uy) {
  // Sweep order for Gauss-Seidel: lexicographic, following the sliding direction.
  order.clear();
  const bool up = Uy >= 0.0, right = Ux >= 0.0;
  for (int jj = 0; jj < ny; ++jj) {
    const int j = up ? jj : ny - 1 - jj;
    for (int ii = 0; ii < nx; ++ii) {
      const int i = right ? ii : nx - 1 - ii;
      const int k = i + nx * j;
      if (status[k] != kFixed)
        order.push_back(k);
    }
  }
}

double FilmSystem::relativeResidual() const {
  double worst = 0.0;
  const bool reynolds = model == CavitationModel::Reynolds;
  for (int k = 0; k < n; ++k) {
    if (status[k] == kFixed)
      continue;
    const double r = residualAt(k);
    const double v = (reynolds && p[k] <= pCav) ? std::max(0.0, -r) : std::abs(r);
    worst = std::max(worst, v);
  }
  return worst / residualScale;
}

void FilmSystem::fluxDiagnostics(double& inflow, double& outflow, double& storage) const {
  inflow = outflow = storage = 0.0;
  auto add = [&](double out) {
    if (out >= 0.0)
      outflow += out;
    else
      inflow -= out;
  };
  for (int k = 0; k < n; ++k) {
    if (status[k] == kFixed)
      continue;
    storage += theta[k] * (squeeze[k] + capacity[k]) - capacity[k] * thetaPrev[k];
    const int e = nbE[k], w = nbW[k], no = nbN[k], s = nbS[k];
    if (e != k && status[e] == kFixed)
      add(tE[k] * (p[k] - p[e]) + couE[k] * (couE[k] >= 0.0 ? theta[k] : theta[e]) +
          fillCorrE[k]);
    if (w != k && status[w] == kFixed)
      add(tW[k] * (p[k] - p[w]) - couE[w] * (couE[w] >= 0.0 ? theta[w] : theta[k]) -
          fillCorrE[w]);
    if (no != k && status[no] == kFixed)
      add(tN[k] * (p[k] - p[no]) + couN[k] * (couN[k] >= 0.0 ? theta[k] : theta[no]) +
          fillCorrN[k]);
    if (s != k && status[s] == kFixed)
      add(tS[k] * (p[k] - p[s]) - couN[s] * (couN[s] >= 0.0 ? theta[s] : theta[k]) -
          fillCorrN[s]);
  }
}

double FilmSystem::faceOutflow(int k, int e) const {
  if (e == nbE[k] && e != k)
    return tE[k] * (p[k] - p[e]) + couE[k] * (couE[k] >= 0.0 ? theta[k] : theta[e]) + fillCorrE[k];
  if (e == nbW[k] && e != k)
    return tW[k] * (p[k] - p[e]) - couE[e] * (couE[e] >= 0.0 ? theta[e] : theta[k]) - fillCorrE[e];
  if (e == nbN[k] && e != k)
    return tN[k] * (p[k] - p[e]) + couN[k] * (couN[k] >= 0.0 ? theta[k] : theta[e]) + fillCorrN[k];
  if (e == nbS[k] && e != k)
    return tS[k] * (p[k] - p[e]) - couN[e] * (couN[e] >= 0.0 ? theta[e] : theta[k]) - fillCorrN[e];
  return 0.0;
}

void FilmSystem::calcEdgeOutflows(FilmResult& r) const {
  // The flow through the face between edge node e and the node inside. The edge node's own
  // half (quarter) cell is not counted: its fill is prescribed (the supply), so it belongs to
  // the oil outside, and its storage, theta A dhT/dt, would draw or push oil the outside need
  // not hold (a gap opening under a starved edge fills with air, not oil).
  const auto edge = [&](int e, int inside) {
    return (inside >= 0 && status[inside] != kFixed) ? faceOutflow(inside, e) : 0.0;
  };
  r.edgeOutflowYMin_m3ps.resize(nx);
  r.edgeOutflowYMax_m3ps.resize(nx);
  for (int i = 0; i < nx; ++i) {
    r.edgeOutflowYMin_m3ps[i] = edge(i, ny > 1 ? i + nx : -1);
    r.edgeOutflowYMax_m3ps[i] = edge(i + nx * (ny - 1), ny > 1 ? i + nx * (ny - 2) : -1);
  }
  const int rows = periodicX ? 0 : ny;
  r.edgeOutflowXMin_m3ps.setZero(rows);
  r.edgeOutflowXMax_m3ps.setZero(rows);
  for (int j = 1; j + 1 < rows; ++j) {  // corners belong to the y edges
    r.edgeOutflowXMin_m3ps[j] = edge(nx * j, nx > 1 ? 1 + nx * j : -1);
    r.edgeOutflowXMax_m3ps[j] = edge(nx - 1 + nx * j, nx > 1 ? nx - 2 + nx * j : -1);
  }
  double in = 0.0, out = 0.0;
  for (const Eigen::ArrayXd* a : {&r.edgeOutflowYMin_m3ps, &r.edgeOutflowYMax_m3ps,
                                  &r.edgeOutflowXMin_m3ps, &r.edgeOutflowXMax_m3ps})
    for (Eigen::Index k = 0; k < a->size(); ++k)
      ((*a)[k] >= 0.0 ? out : in) += std::abs((*a)[k]);
  r.edgeInflow_m3ps = in;
  r.edgeOutflow_m3ps = out;
}

}  // namespace pistondyn::lubrication::detail
