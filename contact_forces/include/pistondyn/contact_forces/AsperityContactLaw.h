#pragma once
/// \file
/// Strategy interface for asperity (solid-to-solid) contact laws.
///
/// A law maps the nominal gap h between the two surfaces (mean-plane separation, m; h < 0
/// means the mean planes overlap) to the asperity contact pressure, its slope with respect
/// to the gap (for implicit and Newton-type solvers), the real-contact area fraction and
/// the lubrication regime. The film solver and the skirt–liner force element hold a
/// `std::shared_ptr<const AsperityContactLaw>` and never know which law is behind it, so a
/// user swaps Greenwood–Tripp for a dry penalty law (or their own) without touching them.
///
/// Laws are immutable after construction: every method is const and touches no shared
/// mutable state, so one law object may be used by any number of threads at once.
///
/// Calls come in two shapes:
///   - per node:  calcPressure(h), calcPressureAndSlope(h), calcNode(h) — for loops
///                inside solvers;
///   - per field: calcField(gap, out) over a whole grid (any shape; Eigen array), filling
///                a reusable ContactField (no allocation after the first call at a size).
/// Inputs are checked here (non-virtual interface); implementations override the eval*
/// hooks, which may assume a gap that is not NaN and not −inf. Outputs are checked here too:
/// a finite gap whose pressure or slope is not finite (an overlap so deep that a power of it
/// overflows the double range — e.g. gap −1e300 m — or a law that fails) throws
/// std::invalid_argument naming the gap; no call ever returns inf or NaN.

#include <Eigen/Core>
#include <limits>

#include "pistondyn/contact_forces/LubricationRegime.h"

namespace pistondyn::contact_forces {

/// Everything a law says about one node.
struct ContactNodeState {
  double pressure_Pa = 0.0;            ///< asperity contact pressure p_c ≥ 0 [Pa]
  double dPressure_dGap_PaPerM = 0.0;  ///< ∂p_c/∂h ≤ 0 [Pa/m]
  double realAreaFraction = 0.0;       ///< A_c/A in [0, 1] [-]
  double filmRatio = std::numeric_limits<double>::infinity();  ///< h/σ [-]
  LubricationRegime regime = LubricationRegime::Hydrodynamic;  ///< regime of h/σ
};

/// Per-node results on a grid, same shape as the gap field. Keep one per solver and pass
/// it to every call: it is resized only when the grid size changes.
struct ContactField {
  Eigen::ArrayXXd pressure_Pa;                                             ///< [Pa]
  Eigen::ArrayXXd dPressure_dGap_PaPerM;                                   ///< [Pa/m]
  Eigen::ArrayXXd realAreaFraction;                                        ///< [-]
  Eigen::ArrayXXd filmRatio;                                               ///< h/σ [-]
  Eigen::Array<LubricationRegime, Eigen::Dynamic, Eigen::Dynamic> regime;  ///< regime of h/σ

  /// Resize all members to rows × cols (no-op when already that size).
  void resize(Eigen::Index rows, Eigen::Index cols);
};

/// Pressure and its slope at one node.
struct PressureAndSlope {
  double pressure_Pa = 0.0;            ///< [Pa]
  double dPressure_dGap_PaPerM = 0.0;  ///< [Pa/m]
};

/// Asperity contact law: pressure, its slope, real-contact area fraction and regime against
/// the nominal gap (the strategy interface described in the documentation of AsperityContactLaw.h).
class AsperityContactLaw {
 public:
  virtual ~AsperityContactLaw() = default;

  /// Short name of the law, e.g. "GreenwoodTripp".
  virtual const char* name() const = 0;

  /// Composite RMS roughness σ used for h/σ and the regime [m] (> 0).
  virtual double compositeSigma_m() const = 0;

  /// Asperity pressure at gap h.
  /// Inputs:  gap_m  nominal gap h [m]; NaN and −inf throw std::invalid_argument,
  ///                 +inf means "far apart" (no contact)
  /// Outputs: p_c [Pa] ≥ 0 and finite (an overflowing overlap throws, see above)
  double calcPressure(double gap_m) const;

  /// Pressure and ∂p_c/∂h at gap h (same inputs as calcPressure).
  PressureAndSlope calcPressureAndSlope(double gap_m) const;

  /// Pressure, slope, area fraction, h/σ and regime at gap h (same inputs).
  ContactNodeState calcNode(double gap_m) const;

  /// All of calcNode over a gap field of any shape (a column ArrayXd binds too).
  /// Inputs:  gap_m  nominal gap per node [m]; a NaN or −inf entry throws
  ///                 std::invalid_argument naming its index, before `out` is touched; an
  ///                 overflowing overlap throws naming its index too (`out` is then
  ///                 partly overwritten)
  /// Outputs: out    resized to the shape of gap_m and filled
  void calcField(const Eigen::Ref<const Eigen::ArrayXXd>& gap_m, ContactField& out) const;

  /// Regime at gap h (h/σ with this law's σ). Same domain as calcPressure: NaN and −inf
  /// throw std::invalid_argument, +inf is hydrodynamic. (classifyRegime() on a film ratio
  /// accepts −inf as boundary; a gap of −inf has no pressure, so the law rejects it.)
  LubricationRegime classify(double gap_m) const;

 protected:
  /// Hooks: gap_m is never NaN or −inf here. Pressure p_c ≥ 0 [Pa].
  virtual double evalPressure(double gap_m) const = 0;
  /// Pressure and its slope ∂p_c/∂h [Pa, Pa/m].
  virtual PressureAndSlope evalPressureAndSlope(double gap_m) const = 0;
  /// Real-contact area fraction in [0, 1].
  virtual double evalAreaFraction(double gap_m) const = 0;
  /// Default: evalPressureAndSlope + evalAreaFraction + regime. Override when the three can
  /// share work.
  virtual ContactNodeState evalNode(double gap_m) const;
};

}  // namespace pistondyn::contact_forces
