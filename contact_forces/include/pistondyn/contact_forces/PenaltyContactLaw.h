#pragma once
/// \file
/// Dry penalty contact of the skirt against the liner, as commercial dry-skirt models use:
/// a pressure that grows as a power of the penetration δ = h_onset − h once the gap closes
/// below an onset gap, switched on smoothly so that pressure and slope are continuous:
///
///   p(δ) = p_ref · (δ/δ_ref)^e · S(δ/δ_s),    S(x) = 0 (x ≤ 0), 3x² − 2x³ (0 < x < 1), 1 (x ≥ 1)
///
/// S is the cubic step of MSC Adams' STEP/IMPACT functions. For e ≥ 1 the pressure and
/// ∂p/∂h are continuous everywhere (C¹), including at the onset: integrators see no kink.
/// e = 1 is a linear penalty, e = 1.5 mimics Hertz (the exponent of a sphere or of
/// Greenwood–Williamson asperities). The "area fraction" reported is S(δ/δ_s): 0 before
/// contact, 1 once the onset ramp is passed — a contact indicator, since a penalty law has
/// no real-area model.
///
/// The stiffness is given as a pressure at a reference penetration so that its unit does not
/// depend on e. It is a calibration input (e.g. from a skirt FE model's radial compliance),
/// not a material constant; the defaults are a placeholder of the right order for an
/// aluminium skirt on a cast-iron liner.

#include "pistondyn/contact_forces/AsperityContactLaw.h"

namespace pistondyn::contact_forces {

/// Parameters of the penalty (dry skirt) contact law.
struct PenaltyContactParameters {
  double referencePressure_Pa = 10.0e6;    ///< p_ref > 0 [Pa]; default 10 MPa ...
  double referencePenetration_m = 1.0e-6;  ///< ... at δ_ref > 0 [m]; default 1 µm
  double exponent = 1.0;                   ///< e ≥ 1 [-]; default 1 (linear)
  double onsetGap_m = 0.0;                 ///< gap at which contact starts [m]; default 0
  double transitionDepth_m = 0.2e-6;       ///< δ_s > 0, width of the smooth onset [m]
  double compositeRoughness_m = 0.5e-6;    ///< σ > 0 for h/σ and the regime [m]
};

/// A penalty law for a dry skirt contact: p = p_ref·(δ/δ_ref)^e·S(δ/δ_s), δ = onset gap − h,
/// S the cubic step (the documentation of PenaltyContactLaw.h).
class PenaltyContactLaw final : public AsperityContactLaw {
 public:
  /// Checks every parameter; throws std::invalid_argument naming the bad one.
  explicit PenaltyContactLaw(const PenaltyContactParameters& parameters = {});

  const char* name() const override { return "Penalty"; }
  double compositeSigma_m() const override { return parameters_.compositeRoughness_m; }
  /// The parameters as checked.
  const PenaltyContactParameters& getParameters() const { return parameters_; }

 protected:
  double evalPressure(double gap_m) const override;
  PressureAndSlope evalPressureAndSlope(double gap_m) const override;  ///< p and ∂p/∂h
  double evalAreaFraction(double gap_m) const override;

 private:
  PenaltyContactParameters parameters_;
};

}  // namespace pistondyn::contact_forces
