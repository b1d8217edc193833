#pragma once
/// \file
/// h_linerShape (thesis §2.1, h_3): the bore distortion as Fourier orders 0..12 along the bore,
///
///   dr(phi, Y) = sum_n A_n(Y) cos(n (phi - psi_n(Y)))        [m, + = bore larger = opens the gap]
///
/// phi the angle around the bore (as on the skirt, from +x towards +z), Y the height above the
/// crank axis. Each order n is tabulated against the depth below the liner top,
/// depth = Y_top - Y [m] (Y_top = linerTopHeight_m, the liner-top height above the crank axis),
/// as amplitude A_n [m] and phase psi_n [rad] (the angle of the order's first maximum; unused for
/// n = 0). Order 0 is a uniform change of the bore radius, order 1 a shift of the bore axis by
/// A_1 towards psi_1 (to first order in A_1/R), order 2 an oval bore, and so on.
///
/// Interpolation along the depth: the Cartesian coefficients a_n = A_n cos(n psi_n),
/// b_n = A_n sin(n psi_n) are tabulated and read with PCHIP (InterpolatedTable.h), so that
/// dr = sum_n a_n(depth) cos(n phi) + b_n(depth) sin(n phi); interpolating A and psi directly
/// would wrap phases and distort an order whose amplitude passes through zero. The series is
/// evaluated analytically at every skirt node (cos n phi, sin n phi per grid angle are stored;
/// per call each order costs one table lookup per grid row) - never through a coarse liner grid,
/// which would lose high orders (mapping/README.md: a 36-node liner grid is 12.5 % off at order
/// 12). Outside a table's depth range each order keeps its end values (constant extension).
///
/// A skirt node at piston-frame height y is at bore height Y = Y_pin + y (PistonPose.h; the
/// tilt's axial shift of the node, ~R alpha, is neglected - RigidGap.h). The node's bore angle
/// is taken as its piston-frame phi: the lateral and tertiary displacement turn it by at most
/// ~e/R, which changes order n by n A_n e/R (order 12, A = 1 um, e = 50 um, R = 37 mm:
/// 0.016 um) - neglected.
///
/// Rate at a skirt node (the film solver's dh/dt is taken at a fixed point of the skirt): the
/// distortion belongs to the liner, so while the piston moves along the bore with
/// v_y = dY_pin/dt a fixed skirt node sees
///   d h_linerShape / dt = (d dr / dY) v_y = -(d dr / d depth) v_y,
/// because Y = Y_pin + y with y fixed and depth = Y_top - Y. (A skirt node moving up, v_y > 0,
/// into a bore that widens upwards sees its gap open.)

#include <vector>

#include <Eigen/Core>

#include "pistondyn/skirt/InterpolatedTable.h"
#include "pistondyn/skirt/SkirtSideGrid.h"

namespace pistondyn::skirt {

/// Highest Fourier order of the bore distortion accepted.
inline constexpr int kMaxBoreDistortionOrder = 12;

/// One Fourier order of the bore distortion, tabulated along the depth.
struct BoreDistortionOrder {
  int order = 0;                ///< n, 0..kMaxBoreDistortionOrder, each order at most once
  Eigen::VectorXd depth_m;      ///< depth below the liner top [m], strictly increasing, >= 1 row
  Eigen::VectorXd amplitude_m;  ///< A_n [m], finite, same length
  Eigen::VectorXd phase_rad;    ///< psi_n [rad], finite, same length (ignored for n = 0; may be
                                ///< empty for n = 0)
};

/// The bore distortion: Fourier orders tabulated along the depth.
struct BoreDistortionParameters {
  std::vector<BoreDistortionOrder> orders;  ///< empty (default) = ideal cylinder
};

/// Radial deviation of the bore at one point and its derivative along the bore.
struct BoreSample {
  double radialDeviation_m = 0.0;             ///< dr [m]
  double dRadialDeviation_dBoreHeight = 0.0;  ///< d dr / dY [m/m]
};

/// The liner-shape gap term: bore distortion as Fourier orders along the bore (this file's
/// documentation).
class LinerShape {
 public:
  /// Inputs:
  ///   parameters        the orders (empty = ideal cylinder)
  ///   grid              the skirt side it is evaluated on (its angles are stored)
  ///   linerTopHeight_m  Y_top, liner-top height above the crank axis [m], finite (required
  ///                     only when there are orders)
  /// Throws std::invalid_argument naming the member (orders[i].member) and row.
  LinerShape(const BoreDistortionParameters& parameters, const SkirtSideGrid& grid,
             double linerTopHeight_m);

  bool isIdealCylinder() const { return orders_.empty(); }  ///< no orders

  /// dr and d dr/dY at the bore angle phi_rad [rad] and bore height boreHeight_m [m].
  BoreSample calcSample(double phi_rad, double boreHeight_m) const;

  /// h_linerShape and its rate at every node of the grid it was built for.
  /// Inputs: pinHeight_m Y_pin [m], axialVelocity_mps v_y [m/s] (finite; checked by the caller).
  /// Outputs (nodeCount() entries, preallocated): gap_m [m], gapRate_mps [m/s].
  /// Allocates nothing.
  void calcField(double pinHeight_m, double axialVelocity_mps, Eigen::Ref<Eigen::ArrayXd> gap_m,
                 Eigen::Ref<Eigen::ArrayXd> gapRate_mps) const;

 private:
  struct Order {
    int n;
    InterpolatedTable a, b;  ///< a_n, b_n against depth [m]
  };
  std::vector<Order> orders_;
  double linerTop_m_ = 0.0;
  int nPhi_ = 0, nY_ = 0;
  Eigen::VectorXd y_m_;      ///< grid heights
  Eigen::MatrixXd cosNPhi_;  ///< orders x nPhi: cos(n phi_i) (orders contiguous per angle)
  Eigen::MatrixXd sinNPhi_;  ///< orders x nPhi: sin(n phi_i)
};

}  // namespace pistondyn::skirt
