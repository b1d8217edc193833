// The explicit second-order fill-fraction flux of FillFractionFlux::LimitedSecondOrder
// (FilmProblem.h). Why: the implicit upwind transport of the oil content is first order, and
// on a starved skirt that error, along the sliding direction, is what keeps the whole-cycle
// friction from converging in the grid at a usable size (plugin/README.md, "Known
// limitations"). A fully implicit limited flux would make the fill-fraction block non-linear
// and non-monotone inside every active-set step; taking the correction to the upwind face
// value from the fill fraction at the start of the step keeps the linear systems the solvers
// already have and adds one constant flux per face.

#include <algorithm>
#include <cmath>

#include "FilmSystem.h"

namespace pistondyn::lubrication::detail {
namespace {

// minmod(a, b): the smaller slope when both have the same sign, else 0 (TVD limiter).
double minmod(double a, double b) {
  if (a * b <= 0.0)
    return 0.0;
  return std::abs(a) < std::abs(b) ? a : b;
}

}  // namespace

void FilmSystem::assembleFillFractionCorrection(const FilmGrid& grid, const FilmProblem& pr) {
  fillCorrE.setZero();
  fillCorrN.setZero();
  fillCorrOut.setZero();
  const bool use = jfo && std::isfinite(pr.timeStep_s) && pr.history.last.fillFraction.size() == n &&
                   pr.fillFractionFlux == FillFractionFlux::LimitedSecondOrder;
  if (!use)
    return;
  const Eigen::ArrayXd& th = pr.history.last.fillFraction;

  // Raw correction of one face with signed full-film Couette flux F from node `lo` to node
  // `hi` (+x or +y): with u the upwind node, d the downwind one and uu the node upwind of u,
  // the face value theta_u + (1/2) minmod(s_uu, theta_d - theta_u), where s_uu is the
  // upwind difference scaled to the face's spacing (d_ud / d_uuu), so that on a graded grid
  // both slopes extrapolate over the same distance. Returns F times the correction.
  auto faceCorrection = [&](double F, int lo, int hi, int loUp, int hiUp, double dFace,
                            double dLoUp, double dHiUp) {
    if (F == 0.0)
      return 0.0;
    const bool forward = F > 0.0;
    const int u = forward ? lo : hi, d = forward ? hi : lo;
    const int uu = forward ? loUp : hiUp;
    const double dUp = forward ? dLoUp : dHiUp;
    if (uu == u || !(dUp > 0.0) || !(dFace > 0.0))
      return 0.0;
    const double m = minmod((th[u] - th[uu]) * dFace / dUp, th[d] - th[u]);
    return F * 0.5 * m;
  };
  for (int k = 0; k < n; ++k) {
    const int i = k % nx, j = k / nx;
    const int e = nbE[k], no = nbN[k];
    if (e != k) {
      const int iw = i > 0 ? i - 1 : nx - 1;  // the west spacing wraps only when periodic
      const double dWest = nbW[k] != k ? grid.dxEast_m(iw) : 0.0;
      const double dEast2 = nbE[e] != e ? grid.dxEast_m((i + 1) % nx) : 0.0;
      fillCorrE[k] = faceCorrection(couE[k], k, e, nbW[k], nbE[e], grid.dxEast_m(i), dWest,
                                    dEast2);
    }
    if (no != k) {
      const double dSouth = j > 0 ? grid.dyNorth_m(j - 1) : 0.0;
      const double dNorth2 = grid.dyNorth_m(j + 1);
      fillCorrN[k] = faceCorrection(couN[k], k, no, nbS[k], nbN[no], grid.dyNorth_m(j), dSouth,
                                    dNorth2);
    }
  }

  if (freezeFillLimiter) {
    // The derivative assemblies (FilmSolver.cpp): the factors of the solve's own assembly,
    // so that a node's balance depends on the gaps of its five-point stencil only.
    fillCorrE *= fillLimitE;
    fillCorrN *= fillLimitN;
  } else {
    calcFillLimiter(th);
  }
  fillCorrOut.setZero();
  for (int k = 0; k < n; ++k) {
    fillCorrOut[k] += fillCorrE[k] + fillCorrN[k];
    if (fillCorrE[k] != 0.0)
      fillCorrOut[nbE[k]] -= fillCorrE[k];
    if (fillCorrN[k] != 0.0)
      fillCorrOut[nbN[k]] -= fillCorrN[k];
  }
}

void FilmSystem::calcFillLimiter(const Eigen::ArrayXd& th) {
  // Zalesak's limiter on the correction fluxes: per unknown node, the total the corrections
  // would take out of (put into) its oil content over the step must not move its reference
  // fill fraction below (above) the smallest (largest) of its neighbourhood at the start of
  // the step; each face is scaled by the smaller factor of its two nodes. Fixed nodes (edges,
  // dry zones) have no balance and no bound.
  Eigen::ArrayXd& takeOut = fillCorrOut;  // scratch: sums of positive / negative outflows
  Eigen::ArrayXd& putIn = fillCorrScratch;
  putIn.setZero();
  auto addOutflow = [&](int k, double out) {
    if (out > 0.0)
      takeOut[k] += out;
    else
      putIn[k] -= out;
  };
  for (int k = 0; k < n; ++k) {
    if (fillCorrE[k] != 0.0) {
      addOutflow(k, fillCorrE[k]);
      addOutflow(nbE[k], -fillCorrE[k]);
    }
    if (fillCorrN[k] != 0.0) {
      addOutflow(k, fillCorrN[k]);
      addOutflow(nbN[k], -fillCorrN[k]);
    }
  }
  // Reuse the sums in place as the factors: takeOut -> factor for losing oil, putIn -> for
  // gaining it.
  for (int k = 0; k < n; ++k) {
    double down = 1.0, up = 1.0;
    if (status[k] != kFixed) {
      // Local bounds: the fill fractions of the node and its four neighbours at the start of
      // the step; the reference the correction moves is the storage term's (thetaPrev: theta_n,
      // or the BDF2 combination, which may already lie outside them).
      double lo = th[k], hi = th[k];
      for (int m : {nbE[k], nbW[k], nbN[k], nbS[k]}) {
        lo = std::min(lo, th[m]);
        hi = std::max(hi, th[m]);
      }
      const double ref = thetaPrev[k];
      const double room = capacity[k] * std::max(0.0, ref - std::max(lo, 0.0));
      const double space = capacity[k] * std::max(0.0, std::min(hi, 1.0) - ref);
      if (takeOut[k] > room)
        down = room / takeOut[k];
      if (putIn[k] > space)
        up = space / putIn[k];
    }
    takeOut[k] = down;
    putIn[k] = up;
  }
  // A positive flux takes oil out of lo and puts it into hi.
  auto factor = [&](double flux, int lo, int hi) {
    if (flux == 0.0)
      return 1.0;
    return flux > 0.0 ? std::min(takeOut[lo], putIn[hi]) : std::min(putIn[lo], takeOut[hi]);
  };
  for (int k = 0; k < n; ++k) {
    fillLimitE[k] = factor(fillCorrE[k], k, nbE[k]);
    fillLimitN[k] = factor(fillCorrN[k], k, nbN[k]);
  }
  fillCorrE *= fillLimitE;
  fillCorrN *= fillLimitN;
}

}  // namespace pistondyn::lubrication::detail
