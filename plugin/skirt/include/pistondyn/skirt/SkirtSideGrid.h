#pragma once
/// \file
/// The one description of a skirt side: its nodes, the film and mapping grids built on them, and
/// the exact integration weights that turn nodal tractions into the loads on the piston.
///
/// Piston frame (fixed to the piston; the conventions of the whole skirt module)
/// --------------------------------------------------------------------------------
///   origin  on the piston axis at the pin-axis height
///   y       along the piston axis towards the crown
///   x       towards the THRUST side
///   z       along the pin axis (x, y, z right-handed)
/// A skirt surface point is (phi, y): phi [rad] measured from +x towards +z, y [m] its height in
/// the piston frame. Radial unit vector e_r = (cos phi, 0, sin phi), circumferential unit
/// vector e_phi = (-sin phi, 0, cos phi), axial e_y = (0, 1, 0); the point is
/// r = (R cos phi, y, R sin phi) with the nominal skirt radius R.
/// Sides: Thrust is centred on phi = 0, AntiThrust on phi = pi; each spans phi_c +- Phi/2.
///
/// Nodal fields: nPhi x nY nodes, node (i, j) at phi_i (i along phi, increasing) and y_j
/// (increasing), flat index k = i + nPhi * j (phi fastest) in an Eigen::ArrayXd - the order of
/// lubrication::FilmGrid (x fastest), mapping::CylinderGrid (phi fastest) and of a column-major
/// nPhi x nY Eigen::ArrayXXd, so Eigen::Map<ArrayXXd>(field.data(), nPhi, nY) views a field as
/// a matrix without copying.
///
/// Film grid: x = R (phi - phi_c) is the arc length from the side's centre line, increasing with
/// phi (so the film solver's x direction is +e_phi and its x shear is the circumferential shear
/// below), y the piston-frame height; open edges.
///
/// Loads (calcLoadsOnPiston). The traction on the skirt from the film / contact is
///   t = -p e_r + tau_y e_y + tau_phi e_phi
/// (p: normal pressure pushing the skirt inwards; tau_y: axial shear along +y on the skirt;
/// tau_phi: circumferential shear along +e_phi on the skirt), each read as the bilinear
/// interpolant of its nodal values in (x = R phi, y), dA = R dphi dy. With
///   r x e_r   = y (sin phi, 0, -cos phi)
///   r x e_y   = R (-sin phi, 0, cos phi)
///   r x e_phi = (y cos phi, -R, y sin phi)
/// the resultant on the piston about the piston-frame origin is
///   F_x = -int p cos   - int tau_phi sin           M_x = -int p y sin - R int tau_y sin
///   F_y =  int tau_y                                     + int tau_phi y cos
///   F_z = -int p sin   + int tau_phi cos           M_y = -R int tau_phi
///                                                  M_z =  int p y cos + R int tau_y cos
///                                                        + int tau_phi y sin
/// (cos = cos phi, sin = sin phi, every integral over dA). Each is a sum over the nodes of the
/// nodal value times one of the weights
///   W_k = int N_k dA,  C_k = int N_k cos phi dA,  S_k = int N_k sin phi dA,
///   YC_k = int N_k y cos phi dA,  YS_k = int N_k y sin phi dA,
/// N_k the bilinear hat of node k. They are exact: tensor products of the closed-form 1-D
/// integrals of the phi hats times 1, cos phi, sin phi (cell midpoint m, half width d:
///   int N cos = d cos m (sin d / d) -+ sin m g(d),  int N sin = d sin m (sin d / d) +- cos m g(d)
/// for the rising/falling hat, g(d) = (sin d - d cos d)/d by its series for small d, so no
/// digits cancel) and of the y hats times 1 and y. So a force element takes the piston's
/// resultant here, on the film grid itself (never from forces mapped to another grid; see
/// mapping/include/pistondyn/mapping/ForceMap.h).
///
/// Immutable after construction; copying copies its arrays (a few nodeCount() arrays).

#include <Eigen/Core>

#include "pistondyn/lubrication/FilmGrid.h"
#include "pistondyn/mapping/CylinderGrid.h"

namespace pistondyn::skirt {

/// Which side of the skirt.
enum class SkirtSide {
  Thrust,      ///< centred on phi = 0 (+x)
  AntiThrust,  ///< centred on phi = pi (-x)
};

/// The description of one skirt side's grid.
struct SkirtSideGridParameters {
  SkirtSide side = SkirtSide::Thrust;  ///< which side, default Thrust
  double radius_m = 0.0;               ///< nominal skirt radius R = bore / 2 [m], > 0 (required)
  double arcWidth_rad = 0.0;           ///< arc width Phi of the side [rad], 0 < Phi < pi (required)
  int nPhi = 64;                       ///< nodes around, >= 3, default 64
  int nY = 48;                         ///< nodes along, >= 3, default 48
  double skirtTopHeight_m = 0.0;  ///< skirt top edge above the pin axis [m] (negative if below)
  double skirtLength_m = 0.0;     ///< axial skirt length L [m], > 0 (required)
  /// Clustering of the axial nodes towards the skirt's top and bottom edges (tanh stretching of
  /// lubrication::FilmGrid::clusteredCoordinates), >= 0; default 0 = uniform, 2..3 is strong.
  double axialClustering = 0.0;
  /// Clustering of the circumferential nodes towards the side's centre line, where the ovality
  /// puts the contact (sinh stretching: phi = (Phi/2) sinh(b xi) / sinh(b), xi uniform in
  /// [-1, 1]), >= 0; default 0 = uniform; b = 2 gives 0.55x the uniform spacing on the centre
  /// line and 2.1x at the edges.
  double circumferentialClustering = 0.0;
};

/// Resultant of the skirt tractions on the piston, piston frame, about the piston-frame origin.
struct PistonLoads {
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();    ///< [N]
  Eigen::Vector3d moment_Nm = Eigen::Vector3d::Zero();  ///< [N m]
};

/// One skirt side: its nodes, film grid, mapping grid and exact load weights (this file's
/// documentation gives the frames and the weights).
class SkirtSideGrid {
 public:
  /// Inputs: the side's description (see SkirtSideGridParameters).
  /// Throws std::invalid_argument naming the member (an arc width of pi or more is "a skirt
  /// grid wider than the skirt": the two sides would overlap).
  explicit SkirtSideGrid(const SkirtSideGridParameters& parameters);

  SkirtSide getSide() const { return side_; }                     ///< Thrust or AntiThrust
  double getCentreAngle_rad() const { return centre_rad_; }       ///< 0 (Thrust) or pi (AntiThrust)
  double getRadius_m() const { return radius_m_; }                ///< R [m]
  double getArcWidth_rad() const { return arcWidth_rad_; }        ///< Phi [rad]
  double getSkirtBottomHeight_m() const { return y_m_[0]; }       ///< piston frame [m]
  double getSkirtTopHeight_m() const { return y_m_[nY() - 1]; }   ///< piston frame [m]
  int nPhi() const { return static_cast<int>(phi_rad_.size()); }  ///< nodes around
  int nY() const { return static_cast<int>(y_m_.size()); }        ///< nodes along
  int nodeCount() const { return nPhi() * nY(); }                 ///< nPhi * nY
  int nodeIndex(int i, int j) const { return i + nPhi() * j; }    ///< k = i + nPhi * j

  /// The film grid (x = R (phi - phi_c) [m], y [m], open edges) and the mapping grid (a sector
  /// with the absolute angles phi [rad] and the same y), built once.
  const lubrication::FilmGrid& getFilmGrid() const { return filmGrid_; }
  const mapping::CylinderGrid& getCylinderGrid() const { return cylinderGrid_; }  ///< see above

  /// Node coordinates along each direction: absolute angles [rad] (nPhi) and heights [m] (nY).
  const Eigen::VectorXd& getPhiNodes_rad() const { return phi_rad_; }
  const Eigen::VectorXd& getYNodes_m() const { return y_m_; }  ///< heights [m] (nY)
  /// Per node (nodeCount, k = i + nPhi j): phi_k [rad], y_k [m], cos phi_k, sin phi_k.
  const Eigen::ArrayXd& getNodePhi_rad() const { return nodePhi_rad_; }
  const Eigen::ArrayXd& getNodeY_m() const { return nodeY_m_; }     ///< y_k [m]
  const Eigen::ArrayXd& getNodeCosPhi() const { return nodeCos_; }  ///< cos phi_k
  const Eigen::ArrayXd& getNodeSinPhi() const { return nodeSin_; }  ///< sin phi_k

  /// Exact integration weights of the bilinear interpolant (see the file comment), per node:
  /// int N_k dA [m^2].
  const Eigen::ArrayXd& getAreaWeights_m2() const { return w_; }
  const Eigen::ArrayXd& getCosPhiWeights_m2() const { return wc_; }  ///< int N_k cos phi dA [m^2]
  const Eigen::ArrayXd& getSinPhiWeights_m2() const { return ws_; }  ///< int N_k sin phi dA [m^2]
  /// int N_k y cos phi dA [m^3]
  const Eigen::ArrayXd& getYCosPhiWeights_m3() const { return wyc_; }
  /// int N_k y sin phi dA [m^3]
  const Eigen::ArrayXd& getYSinPhiWeights_m3() const { return wys_; }
  /// d f / dy of a nodal field f at every node (nodeCount() entries each, k = i + nPhi j),
  /// second order along each grid line: central on the interior nodes, one-sided at the skirt's
  /// top and bottom rows (the three-point stencils of the nonuniform grid). `out` is resized;
  /// no other allocation. Throws std::invalid_argument for a field of the wrong size.
  void calcAxialDerivative(const Eigen::Ref<const Eigen::ArrayXd>& field,
                           Eigen::ArrayXd& out) const;
  /// Total surface area of the side, R Phi L [m^2].
  double getArea_m2() const { return radius_m_ * arcWidth_rad_ * (y_m_[nY() - 1] - y_m_[0]); }

  /// Resultant force and moment on the piston (piston frame, about the piston-frame origin) of
  /// the nodal tractions, integrated exactly as their bilinear interpolants (file comment).
  /// Inputs (nodeCount() entries each, finite; the two shears may be empty = zero):
  ///   normalPressure_Pa        p [Pa], > 0 pushes the skirt inwards (force -p e_r dA)
  ///   axialShear_Pa            tau_y [Pa] on the skirt along +y
  ///   circumferentialShear_Pa  tau_phi [Pa] on the skirt along +e_phi (= the film grid's +x)
  /// Outputs: force_N [N] and moment_Nm [N m].
  /// Allocates nothing. Throws std::invalid_argument for a wrong size or a non-finite entry.
  PistonLoads calcLoadsOnPiston(
      const Eigen::Ref<const Eigen::ArrayXd>& normalPressure_Pa,
      const Eigen::Ref<const Eigen::ArrayXd>& axialShear_Pa,
      const Eigen::Ref<const Eigen::ArrayXd>& circumferentialShear_Pa) const;
  /// The same for a normal pressure alone (no shear).
  PistonLoads calcLoadsOnPiston(const Eigen::Ref<const Eigen::ArrayXd>& normalPressure_Pa) const {
    return calcLoadsOnPiston(normalPressure_Pa, Eigen::ArrayXd(), Eigen::ArrayXd());
  }

 private:
  SkirtSide side_;
  double centre_rad_, radius_m_, arcWidth_rad_;
  Eigen::VectorXd phi_rad_, y_m_;
  lubrication::FilmGrid filmGrid_;
  mapping::CylinderGrid cylinderGrid_;
  Eigen::ArrayXd nodePhi_rad_, nodeY_m_, nodeCos_, nodeSin_;
  Eigen::ArrayXd w_, wc_, ws_, wyc_, wys_;
};

}  // namespace pistondyn::skirt
