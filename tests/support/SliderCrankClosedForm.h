#pragma once
// Closed-form slider-crank kinematics and free-body loads, written for the tests
// independently of the library: kinematics by implicit differentiation of the loop closure
// |P - C| = L (the library uses the rod angle instead), TDC as the root of dy/dphi, side
// force / conrod force / crank torque from a Newton-Euler balance of piston+pin and rod.
// Used by the crank-train tests (ideal guide) and the lubricated-skirt force balance.

#include <cmath>

#include "pistondyn/mbd_models/EngineDescription.h"

namespace pistondyn::testsupport {

struct V2 {
  double x, y;
};
inline V2 operator-(V2 a, V2 b) {
  return {a.x - b.x, a.y - b.y};
}
inline V2 operator+(V2 a, V2 b) {
  return {a.x + b.x, a.y + b.y};
}
inline V2 operator*(double k, V2 a) {
  return {k * a.x, k * a.y};
}
inline double cross(V2 a, V2 b) {
  return a.x * b.y - a.y * b.x;
}
inline double dot(V2 a, V2 b) {
  return a.x * b.x + a.y * b.y;
}

// Slider-crank with the pin on the line x = e, crank pin C = r(-sin phi, cos phi),
// crank turning at constant omega. Everything from the loop closure
// f = (e - Cx)^2 + (y - Cy)^2 - L^2 = 0 and its time derivatives.
struct ClosedForm {
  double r, L, e, omega;

  struct Kin {
    V2 C, Cd, Cdd, P, Pd, Pdd;
  };
  Kin at(double phi) const {
    Kin k;
    const double s = std::sin(phi), c = std::cos(phi), w = omega;
    k.C = {-r * s, r * c};
    k.Cd = {-r * c * w, -r * s * w};
    k.Cdd = {r * s * w * w, -r * c * w * w};
    const double y = k.C.y + std::sqrt(L * L - (e - k.C.x) * (e - k.C.x));
    const double yd = k.Cd.y + (e - k.C.x) * k.Cd.x / (y - k.C.y);
    const double ydd =
        k.Cdd.y +
        ((e - k.C.x) * k.Cdd.x - k.Cd.x * k.Cd.x - (yd - k.Cd.y) * (yd - k.Cd.y)) / (y - k.C.y);
    k.P = {e, y};
    k.Pd = {0, yd};
    k.Pdd = {0, ydd};
    return k;
  }
  // TDC: root of dy/dphi (= yd / omega) near phi = 0, by bisection to machine precision.
  double tdcPhi() const {
    auto slope = [&](double phi) { return at(phi).Pd.y; };
    double lo = -0.3, hi = 0.3;  // y rises before TDC (slope > 0) and falls after
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (slope(mid) > 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
  static ClosedForm of(const mbd::EngineDescription& e) {
    return {e.geometry.crankRadius_m, e.geometry.conrodLength_m,
            e.geometry.pinOffset_m + e.geometry.crankOffset_m, e.drive.speed_radps};
  }
};

// Newton-Euler balance at constant crank speed, piston upright and centred (ideal
// guide). Piston side: the piston and, unless it is clamped in the rod, the pin; it
// translates with the pin centre P. Rod side: the rod and, when clamped in it, the pin
// (mass at P, turning with the rod). F = force of the rod side on the piston side at P.
//   piston side, y:   m_ps y'' = F_y - F_axial - m_ps g   (F_axial: gas force + any other
//                     axial load pushing the piston towards the crank)
//   rod side, moments about the crank pin C (eliminates the crank force):
//     sum_k (r_k - C) x m_k (a_k - g) + sum_k I_k alpha_rod = -(P - C) x F
//   piston side, x:   0 = F_x + N  (N: liner on piston)
//   piston side, moments about P (translating body):
//     pinOffset F_gas - d m_p g + M_guide = d m_p y'',  d = comX - pinOffset
struct Loads {
  double sideForceOnLiner_N, conrodCompression_N, rodTorqueOnCrank_Nm, driveTorque_Nm,
      guideMomentOnLiner_Nm;
};
inline Loads freeBody(const mbd::EngineDescription& engine, const ClosedForm::Kin& k,
                      double axialForce_N) {
  const auto& m = engine.mass;
  const double g = engine.gravity_mps2, L = engine.geometry.conrodLength_m;
  const V2 grav{0, -g};
  const bool pinWithRod = engine.pinJoint == mbd::PinJoint::FixedInRod;
  const double mps = m.piston.mass_kg + (pinWithRod ? 0.0 : m.pin.mass_kg);
  const double mr = m.conrod.mass_kg, lG = m.conrod.comY_m;  // rod COM on its axis
  const V2 G = k.C + (lG / L) * (k.P - k.C);
  const V2 aG = k.Cdd + (lG / L) * (k.Pdd - k.Cdd);
  const double alphaRod = cross(k.P - k.C, k.Pdd - k.Cdd) / (L * L);

  const double Y = mps * k.Pdd.y + axialForce_N + mps * g;
  double S = cross(G - k.C, mr * (aG - grav)) + m.conrod.inertiaZZ_kgm2 * alphaRod;
  V2 rodSideMassAcc = mr * (aG - grav);
  if (pinWithRod) {
    S += cross(k.P - k.C, m.pin.mass_kg * (k.Pdd - grav)) + m.pin.inertiaZZ_kgm2 * alphaRod;
    rodSideMassAcc = rodSideMassAcc + m.pin.mass_kg * (k.Pdd - grav);
  }
  const V2 PC = k.P - k.C;
  const double X = (S + PC.x * Y) / PC.y;
  const V2 F{X, Y};
  const V2 Fcr = rodSideMassAcc + F;  // crank on rod side
  Loads out;
  out.sideForceOnLiner_N = X;
  out.conrodCompression_N = dot(F, (1.0 / L) * PC);
  out.rodTorqueOnCrank_Nm = cross(k.C, -1.0 * Fcr);
  const V2 throwDir = (1.0 / engine.geometry.crankRadius_m) * k.C;
  const V2 Gc = m.crank.comY_m * throwDir;  // crank COM on the throw (comX = 0)
  out.driveTorque_Nm = -out.rodTorqueOnCrank_Nm - cross(Gc, m.crank.mass_kg * grav);
  const double pinOffset = engine.geometry.pinOffset_m;
  const double dx = m.piston.comX_m - pinOffset;
  out.guideMomentOnLiner_Nm = -(dx * m.piston.mass_kg * (k.Pdd.y + g) - pinOffset * axialForce_N);
  return out;
}

}  // namespace pistondyn::testsupport
