#pragma once
// Film and asperity contact on one skirt side for one force evaluation: the gap fields of a
// GapAssembly go in, the film (lubrication::FilmSolver), the asperity contact
// (contact_forces::AsperityContactLaw) and the boundary friction
// (contact_forces::BoundaryFriction) are evaluated on the side's grid, and the loads on the
// piston come out with their derivatives with respect to the pose and its rates.
//
// Surfaces and velocities (FilmProblem.h, SurfacePair.h): the grid is attached to the skirt
// (surface 2); the liner (surface 1) moves with U relative to it. U along the film grid's
// axes: U_y (axial, +y) = -v_y of the piston; U_x (circumferential, along +e_phi = the film
// grid's +x) = minus the skirt's tangential velocity at the side's centre line.
//
// Per node (k = i + nPhi j, SkirtSideGrid.h):
//   film gap       h_f = (h + h_c + sqrt((h - h_c)^2 + h_c^2)) / 2 of the nominal gap h, a
//                  smooth clamp >= h_c = max(clampFraction * sigma, minimumClampGap_m),
//                  sigma = getCompositeSigma_m() (PatirChengFlowFactors.h: it changes the
//                  film gap by < 1.2 % at h/sigma >= 0.5); the gap rate and the squeeze
//                  basis are multiplied by dh_f/dh (lubrication::calcFlooredGap); with
//                  faceValues = LinearGap the film also solves with FilmProblem::gapFloor_m
//                  = h_c, so its faces follow the nominal gap through the clamp's knee at a
//                  contact's rim
//   film           lubrication::FilmSolver on SkirtSideGrid::getFilmGrid(), all four edges
//                  open at edgePressure_Pa, the inlet supply film on both axial edges (it
//                  matters only where the liner slides in), the flow-factor model of the
//                  side (Patir & Cheng; smooth when sigma = 0)
//   contact        p_c(h) of the asperity law on the NOMINAL gap (it carries the load where
//                  the clamp holds the film open), its slope dp_c/dh; its loads are those
//                  of the nodal interpolant except in cells whose smallest corner gap is
//                  below 4.5 sigma, where p_c(h) is integrated at 6 x 6 Gauss points of the
//                  gap interpolated bicubically from the 4 x 4 nearest nodes (a contact at an
//                  edge is often narrower than a cell: the interpolant alone overestimated an
//                  edge contact 4.8-fold at 64 x 48; and the bilinear gap of a barrel lies
//                  above it between the nodes: 7 % of a mid-skirt contact's load)
//   boundary shear tau_b = BoundaryFriction::calcShearStress_Pa(p_c, -U) on the skirt
// Tractions on the skirt: normal p = p_film + p_c (minus edgePressure_Pa, see below), axial
// tau_y = film shear on surface 2 along y - (p_film - edgePressure) s + tau_b,y, circumferential
// tau_phi = film shear on surface 2 along x + tau_b,x. s = GapFields::skirtGapSlope is the axial
// slope of the skirt surface's own gap terms (profile, thermal, elastic): the film pressure acts
// normal to the skirt surface r_s = R - h_s, whose normal has the axial component -dr_s/dy = s,
// so the pressure pushes the skirt along -s p per area. With it the film's force on the skirt
// is minus its force on the (straight) liner, and U . F of the film equals the power it
// dissipates, int [eta U^2 / h + h^3 |grad p|^2 / (12 eta)] dA for a smooth film (the
// tilt's part of that balance is the rotation of the loads into the bore frame, the element's).
// The circumferential slope of an oval skirt is left out, as the linear gap model leaves it out
// of the gap rate. Loads by SkirtSideGrid::calcLoadsOnPiston (exact for the bilinear fields),
// split into the hydrodynamic part (film pressure and film shear) and the asperity part
// (contact pressure, normal to the liner, and boundary shear).
//
// Derivatives (for the implicit time stepper; pose order kLateral, kTilt, kTertiary):
//   dLoads_dPoseRate  6 x 3: (force; moment) per unit pose rate, from the film's squeeze
//                     derivatives (FilmResult::dPressure_dVelocity; exact for the final
//                     cavitation set), pressure part only (the film shear's part is
//                     ~h/L and h/(2R) of it); columns beyond
//                     squeezeColumns are zero
//   dLoads_dPose      6 x 3: the derivative of asperityLoads (contact pressure AND the
//                     boundary shear it carries, for the fixed sliding velocity) from the
//                     asperity law's exact slope, dp_c/dh * dh/dpose: of the nodal
//                     interpolant plus the Gauss correction (above), i.e. exact for the
//                     loads as computed while the set of Gauss-corrected cells stays. The
//                     boundary shear is f g(|U|) p_c: its stiffness is all of dF_y and, with
//                     the arm R against the pressure's y, ~R f / |y| (15..20 % on a skirt) of
//                     the tilt moment's. The film's own stiffness (the change of the wedge
//                     pressure with the pose) is NOT included: it is not stiff (the film is
//                     overdamped: K/C is slow), LinearlyImplicitStepper.h explains why that
//                     is enough.
//
// Cost and state: one film solve per call (with squeezeColumns extra back-substitutions),
// one contact field, a few weighted sums. No allocation after the first call at a size. The
// object keeps the film solver's workspace and the last film state as the warm start of the
// next call (a mutable workspace in the sense of ForceElement.h: results depend on it only
// within the solver tolerance). History that matters (the mass-conserving model's fill
// fraction) is NOT kept here: the caller passes the previous fill fraction and the time step
// and stores the result's fill fraction in its own State.
//
// Errors: std::invalid_argument for inputs of the wrong size or not finite (naming them: the
// GapFields members gap_m, gapRate_mps, dGap_dPose (nodeCount x 3), squeezeBasis (nodeCount x
// at least squeezeColumns), every SkirtSideInputs member, with the value and unit); a
// film solve that does not converge (after the solver's own fallback) throws
// std::runtime_error naming the side, the residual and the iterations, never returns NaN.

#include <limits>
#include <memory>

#include <Eigen/Core>

#include "pistondyn/contact_forces/AsperityContactLaw.h"
#include "pistondyn/contact_forces/BoundaryFriction.h"
#include "pistondyn/lubrication/FilmSolver.h"
#include "pistondyn/lubrication/FlowFactorModel.h"
#include "pistondyn/skirt/GapFields.h"
#include "pistondyn/skirt/SkirtSideGrid.h"

namespace pistondyn::skirt {

struct SkirtLubricationParameters {
  lubrication::CavitationModel cavitation = lubrication::CavitationModel::Reynolds;
  double cavitationPressure_Pa = 0.0;     // p_cav, gauge [Pa], default 0
  double edgePressure_Pa = 0.0;           // pressure on all four edges, gauge [Pa], default 0
  lubrication::FilmSolverOptions solver;  // fast active-set solver by default
  // The film-gap clamp h_c = max(clampFraction * sigma, minimumClampGap_m), sigma the
  // composite roughness of getCompositeSigma_m() (the flow factors', or the contact law's
  // when the flow factors are smooth: the contact law always has one).
  double clampFraction = 0.1;       // [-], > 0, default 0.1
  double minimumClampGap_m = 1e-8;  // floor of h_c [m], > 0, default 10 nm
  // The film's face values (lubrication::FaceValues): the nodal means by default; LinearGap
  // (with the clamp as the film's gap floor) converges faster in the grid on a rigid starved
  // skirt but is not the default: on the coarse elastic skirt the coupling failed with it (and
  // without the floor, fmep rose 2.2 to 3.6 fold with 6 to 30 times the failed trial steps;
  // plugin/README.md, "Face values").
  lubrication::FaceValues faceValues = lubrication::FaceValues::NodalMean;
  // How the film's Couette faces take the fill fraction (lubrication::FillFractionFlux,
  // mass-conserving model with the fill history only): the implicit upwind value by default,
  // or the limited second-order value (plugin/README.md, "Known limitations": the starved
  // skirt's grid error along the sliding direction).
  lubrication::FillFractionFlux fillFractionFlux = lubrication::FillFractionFlux::Upwind;
  // Archard wear coefficient k/H of the liner-skirt pair, wear volume per (normal force x
  // sliding distance) [m^2/N] = [1/Pa], >= 0, default 0 (no wear reported).
  double wearCoefficient_m2pN = 0.0;
};

// Extra derivative bases of one film solve beyond the pose's squeeze columns, e.g. an elastic
// coupling's modal shapes (ElasticCoupling.h: each scheme says which it needs). Each is
// optional (nullptr = none) and, when given, has one finite row per node.
struct FilmSensitivityRequest {
  // Further squeeze-basis columns: the film returns their pressure derivatives in
  // film.dPressure_dVelocity after the squeezeColumns pose columns. They enter no load
  // derivative (dLoads_dPoseRate stays the pose's).
  const Eigen::MatrixXd* squeezeBasis = nullptr;
  // Gap-basis columns d(nominal gap)/d(u_g): the film returns dp/du_g on its final active set in
  // film.dPressure_dGap (lubrication::FilmProblem::gapBasis; the film-gap clamp's slope applied
  // here, and its curvature times the gap rate added to the columns' rate part: the film's rate
  // slope(h) dh/dt moves with the gap too).
  const Eigen::MatrixXd* gapBasis = nullptr;
  // With gapBasis (same shape): each column also moves the gap rate by this much per unit
  // (FilmProblem::gapRateBasis), e.g. -Psi_j / dt for a backward-Euler elastic rate:
  // film.dPressure_dGap is then the total derivative, static and squeeze parts.
  const Eigen::MatrixXd* gapRateBasis = nullptr;
};

// What one call needs besides the gap fields.
struct SkirtSideInputs {
  double slidingVelocityAxial_mps = 0.0;            // U_y, liner relative to skirt [m/s]
  double slidingVelocityCircumferential_mps = 0.0;  // U_x [m/s]
  double viscosity_Pas = 0.0;                       // dynamic viscosity [Pa s], > 0
  // Oil layer on the liner ahead of the skirt (both axial edges) [m], > 0; +inf = fully
  // flooded (FilmEdge::supplyFilm_m).
  double supplyFilm_m = std::numeric_limits<double>::infinity();
  // Optional: the supply per column at the skirt's bottom (yMin) and top (yMax) edges [m]
  // (nPhi entries each, >= 0, finite; FilmEdge::supplyFilmPerNode_m), instead of supplyFilm_m
  // (a liner oil film, LinerOilFilm.h). Both or neither.
  const Eigen::ArrayXd* supplyBottom_m = nullptr;
  const Eigen::ArrayXd* supplyTop_m = nullptr;
  // Squeeze derivatives wanted: the first squeezeColumns columns of the gap's squeeze basis
  // (0..3; 2 = lateral and tilt, 3 with the tertiary motion).
  int squeezeColumns = 2;
  FilmSensitivityRequest extraBases;  // optional further derivative bases
  // Mass-conserving model only: the film's history (lubrication::FilmHistory.h; nullptr or
  // empty = a full film at rest), passed to the film solver as it is and checked there, and
  // the step since its last point [s] (> 0; +inf or <= 0 = steady state; NaN is rejected).
  const lubrication::FilmHistory* history = nullptr;
  double timeStep_s = std::numeric_limits<double>::infinity();
};

// The figures of one side's evaluation (all SI, finite): its loads and what a designer reads.
struct SkirtSideFigures {
  PistonLoads hydrodynamicLoads;  // film pressure + film shear (piston frame, about origin)
  PistonLoads asperityLoads;      // contact pressure + boundary shear
  PistonLoads totalLoads;
  double hydrodynamicNormalForce_N = 0.0;  // load the film carries, along the side's normal
  double asperityNormalForce_N = 0.0;      // load the asperities carry, >= 0
  // Film force on the piston along +y [N]: the shear and the film pressure's axial component
  // on the sloped skirt surface (pressureFrictionAxial_N, also part of it). With it the film's
  // friction power equals the power it dissipates (the file comment).
  double hydrodynamicFrictionAxial_N = 0.0;
  double pressureFrictionAxial_N = 0.0;      // the film pressure's part of it [N]
  double asperityFrictionAxial_N = 0.0;      // boundary friction force on the piston along +y
  // Power the shear dissipates, U . (integral of tau on the skirt) [W], split into the film
  // (Couette + Poiseuille shear) and the boundary (asperity) part; frictionPower_W is the sum.
  double frictionPower_W = 0.0;
  double hydrodynamicFrictionPower_W = 0.0, asperityFrictionPower_W = 0.0;
  // Power dissipated on the side [W], >= 0 by construction: the film's viscous dissipation
  // (lubrication::FilmResult::viscousDissipation_W) plus the asperity friction power.
  double filmDissipation_W = 0.0;
  double dissipatedPower_W = 0.0;
  double minFilmThickness_m = 0.0;  // smallest NOMINAL gap on the side (may be < 0: overlap)
  double minFilmPhi_rad = 0.0, minFilmY_m = 0.0;  // where
  double minGapOverSigma = 0.0;                   // smallest h / sigma (nominal gap)
  // Shares of the side's area by regime of the nominal gap (contact_forces' classification:
  // hydrodynamic h/sigma > 3, mixed 1 < h/sigma <= 3, boundary <= 1); they sum to 1.
  double hydrodynamicShare = 0.0, mixedShare = 0.0, boundaryShare = 0.0;
  double wettedShare = 0.0;  // share of the area with oil (fill fraction > 0)
  // Oil held in the film on the side, sum of area x fill fraction x film gap [m^3].
  double filmOilVolume_m3 = 0.0;
  double wearRate_m3ps = 0.0;         // Archard wear volume rate k/H * integral p_c |U| dA [m^3/s]
  double maxWearDepthRate_mps = 0.0;  // k/H * max p_c |U| [m/s]
};

// One evaluation: the figures, the nodal fields and the load derivatives.
struct SkirtSideResults : SkirtSideFigures {
  lubrication::FilmResult film;          // pressure, fill fraction, film shear, diagnostics
  contact_forces::ContactField contact;  // p_c, dp_c/dh, area fraction, h/sigma, regime
  Eigen::ArrayXd filmGap_m;              // clamped film gap h_f [m]
  Eigen::ArrayXd boundaryShearAxial_Pa, boundaryShearCircumferential_Pa;  // tau_b [Pa]
  Eigen::ArrayXd normalPressure_Pa;  // p_film + p_c - edgePressure [Pa] (total traction)
  Eigen::Matrix<double, 6, 3> dLoads_dPoseRate = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix<double, 6, 3> dLoads_dPose = Eigen::Matrix<double, 6, 3>::Zero();
  // Wall time of this call's phases [s] (diagnostics for benchmarks; results never depend
  // on them): the film solve, the asperity contact with boundary friction, and the loads
  // with their derivatives and the figures.
  double filmTime_s = 0.0, contactTime_s = 0.0, loadsTime_s = 0.0;
};

class SkirtSideLubrication {
 public:
  // Inputs:
  //   grid         the side (copied)
  //   flowFactors  film flow-factor model (Patir & Cheng with the pair's Rq), shared, immutable
  //   contactLaw   asperity law with the same roughness, shared, immutable
  //   friction     boundary friction (Coulomb, f_dry)
  //   parameters   see SkirtLubricationParameters
  // Throws std::invalid_argument naming the member for bad parameters or a null model.
  SkirtSideLubrication(const SkirtSideGrid& grid,
                       std::shared_ptr<const lubrication::FlowFactorModel> flowFactors,
                       std::shared_ptr<const contact_forces::AsperityContactLaw> contactLaw,
                       const contact_forces::BoundaryFriction& friction,
                       const SkirtLubricationParameters& parameters);
  ~SkirtSideLubrication();
  SkirtSideLubrication(SkirtSideLubrication&&) noexcept;
  SkirtSideLubrication& operator=(SkirtSideLubrication&&) noexcept;

  const SkirtSideGrid& getGrid() const;
  const SkirtLubricationParameters& getParameters() const;
  // Composite roughness sigma of the pair [m] (the flow factors'; the contact law's when the
  // flow factors are smooth) and the clamp gap h_c in use [m].
  double getCompositeSigma_m() const;
  double getClampGap_m() const;

  // One evaluation (see the file comment). `out` is reused between calls (no allocation
  // at a fixed grid size). The film's warm start is the last call's solution.
  void solve(const GapFields& gap, const SkirtSideInputs& inputs, SkirtSideResults& out);

  // Forgets the warm start (e.g. before a run restarted from another state).
  void resetWarmStart();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pistondyn::skirt
