#include "ReferenceSolver.h"

#include <algorithm>

namespace pistondyn::lubrication::detail {

namespace {

// One sweep of (projected) SOR on the Reynolds balance with theta = 1 everywhere.
template <bool kProject>
void reynoldsSweep(FilmSystem& s, double omega) {
  double* p = s.p.data();
  const double pCav = s.pCav;
  for (const int k : s.order) {
    const double r = s.diagP[k] * p[k] -
                     (s.tE[k] * p[s.nbE[k]] + s.tW[k] * p[s.nbW[k]] + s.tN[k] * p[s.nbN[k]] +
                      s.tS[k] * p[s.nbS[k]]) +
                     s.src[k];
    double pn = p[k] - omega * r / s.diagP[k];
    if (kProject)
      pn = std::max(pn, pCav);
    p[k] = pn;
  }
}

// One Elrod-Adams sweep (mass-conserving model).
void elrodAdamsSweep(FilmSystem& s, double omega, double omegaTheta) {
  double* p = s.p.data();
  double* th = s.theta.data();
  const double pCav = s.pCav;
  for (const int k : s.order) {
    const double P = s.diagP[k] * p[k] - (s.tE[k] * p[s.nbE[k]] + s.tW[k] * p[s.nbW[k]] +
                                          s.tN[k] * p[s.nbN[k]] + s.tS[k] * p[s.nbS[k]]);
    const double G =
        -(s.inCx[k] * th[s.inIx[k]] + s.inCy[k] * th[s.inIy[k]]) - s.capacity[k] * s.thetaPrev[k];
    const double a = s.aOut[k] + s.squeeze[k] + s.capacity[k];
    if (th[k] >= 1.0) {
      const double r = P + a + G;
      const double pn = p[k] - omega * r / s.diagP[k];
      if (pn >= pCav) {
        p[k] = pn;
        continue;
      }
      // Cavitates: pressure to p_cav, fill fraction from the balance.
      const double Pc = P + s.diagP[k] * (pCav - p[k]);
      p[k] = pCav;
      th[k] = a > 0.0 ? std::clamp(-(Pc + G) / a, 0.0, 1.0) : 1.0;
    } else {
      const double r = P + a * th[k] + G;
      const double tn = a > 0.0 ? th[k] - omegaTheta * r / a : 1.0;
      th[k] = tn >= 1.0 ? 1.0 : std::max(tn, 0.0);
    }
  }
}

}  // namespace

IterationReport gaussSeidelSolve(FilmSystem& s, const FilmSolverOptions& opt, int maxSweeps) {
  IterationReport rep;
  const int interval = std::max(1, opt.residualCheckInterval);
  rep.residual = s.relativeResidual();
  if (rep.residual <= opt.tolerance) {
    rep.converged = true;
  } else {
    for (int sweep = 1; sweep <= maxSweeps; ++sweep) {
      switch (s.model) {
        case CavitationModel::None:
          reynoldsSweep<false>(s, opt.overRelaxation);
          break;
        case CavitationModel::Reynolds:
          reynoldsSweep<true>(s, opt.overRelaxation);
          break;
        case CavitationModel::MassConserving:
          elrodAdamsSweep(s, opt.overRelaxation, opt.fillRelaxation);
          break;
      }
      rep.iterations = sweep;
      if (sweep % interval == 0 || sweep == maxSweeps) {
        rep.residual = s.relativeResidual();
        if (rep.residual <= opt.tolerance) {
          rep.converged = true;
          break;
        }
      }
    }
  }
  for (int k = 0; k < s.n; ++k) {
    if (s.status[k] == kFixed)
      continue;
    const bool cav = s.model == CavitationModel::MassConserving
                         ? s.theta[k] < 1.0
                         : (s.model == CavitationModel::Reynolds && s.p[k] <= s.pCav);
    s.status[k] = cav ? kCav : kFull;
  }
  return rep;
}

}  // namespace pistondyn::lubrication::detail
