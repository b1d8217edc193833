#pragma once
/// @file
/// The oil film on the liner along one skirt side, carried from step to step: where the
/// skirt's leading edge draws its inlet oil from and where its trailing edge leaves what the
/// film carries out.
///
/// The liner is divided into cells: the side's columns (the skirt film grid's angles, each
/// with the arc length its film nodes stand for) times rows of height dY along the bore (bore
/// heights above the crank axis, from below the skirt's lowest reach to above the oil-control
/// ring's highest). A cell holds an oil volume; its film thickness is volume / (width dY). The
/// skirt covers the rows whose centres lie in [Y_pin + y_bottom, Y_pin + y_top]; a covered
/// row holds no liner oil (the skirt's film has it).
///
/// One accepted step from pin height Y_n to Y over dt (advance()), per column:
///   1. rows the skirt covers newly push their oil to the nearest free row ahead of the edge
///      that covered them (the bow wave the leading edge drives);
///   2. at each of the skirt's axial edges the film's net flow across the edge over the step
///      (lubrication::FilmResult::edgeOutflowYMin/YMax_m3ps x dt) goes to, or comes from, the
///      free row just outside that edge: oil drawn by the film is taken from it (and the rows
///      beyond, should it hold too little; what no row holds is counted as a deficit);
///      oil leaving the film is put there, except at the trailing edge (the one the liner
///      slides away from), where the share skirtShare stays on the skirt and is lost to the
///      crankcase;
///   3. oil the film loses across its circumferential edges (side leakage) leaves the model
///      (the film's first and last columns hold the ambient pressure: the liner cells of
///      those two columns exchange no oil with the film);
///   4. rows the oil-control ring passed (its lower edge at Y_pin + ringHeightAbovePin) are
///      set to the film the ring leaves (the ring meters the film: what it scrapes or adds is
///      the ring's source, of either sign);
///   5. crankcase splash: free rows below floodedBelow_m are kept at maxFilm_m (flooded),
///      and free rows below splashBelow_m gain splashRate_mps dt, up to maxFilm_m;
///   6. free rows thicker than maxFilm_m drain the excess to the crankcase.
/// The supply the film sees at each edge during a step (calcSupply()) is the film of the free
/// row just outside it, with the oil step 1 will push into it.
///
/// Balance: every volume that enters or leaves the liner is counted in LinerOilState, so that
/// storedVolume_m3() changes by exactly ringSource + splashSource + deficitSource - drainLoss
/// - filmIntake - sideLeakage - skirtShareLoss over each step, to round-off (filmIntake is
/// the skirt film's net gain across all its edges: the liner's oil it took less what it put
/// back, less its side leakage and the skirt's share, which leave the model).
///
/// Assumptions: the liner does not move along the circumference (no tertiary convection of the
/// liner film), the piston's lands between the skirt top and the ring leave the liner film as
/// it is, and the film thickness is uniform within a cell.

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "pistondyn/skirt/SkirtSideGrid.h"

namespace pistondyn::skirt {

/// Where the liner's oil comes from and where it goes.
struct LinerOilParameters {
  /// Film the oil-control ring leaves on the liner it passes [m], > 0, as long as the ring
  /// film table below is empty.
  double ringFilm_m = 1.0e-6;
  ///@{
  /// Optional: the ring's film over the 720 deg cycle, crank angles strictly increasing in
  /// [0, 720) [deg] and films > 0 [m] (same size, at least 2 points), periodic linear
  /// interpolation; replaces ringFilm_m when set.
  std::vector<double> ringFilmAngle_deg, ringFilmTable_m;
  ///@}
  /// Height of the oil-control ring's lower edge above the pin axis (piston frame) [m], at
  /// least the skirt's top.
  double ringHeightAbovePin_m = std::numeric_limits<double>::quiet_NaN();
  /// Crankcase splash: the liner below this bore height (above the crank axis) is flooded
  /// [m]; NaN: no flooded region.
  double floodedBelow_m = std::numeric_limits<double>::quiet_NaN();
  ///@{
  /// Crankcase splash as a rate: the free rows below the bore height splashBelow_m (above the
  /// crank axis) [m] gain splashRate_mps [m/s] (>= 0) of film, up to maxFilm_m; NaN height:
  /// none.
  double splashRate_mps = 0.0;
  double splashBelow_m = std::numeric_limits<double>::quiet_NaN();
  ///@}
  /// A liner film thicker than this drains to the crankcase [m], > 0; also the film of the
  /// flooded region.
  double maxFilm_m = 50e-6;
  /// Share of the film's outflow at the trailing edge that leaves on the skirt (and is lost
  /// to the crankcase) [-], in [0, 1]; the rest stays on the liner.
  double skirtShare = 0.5;
  /// The liner's film at the start, outside the skirt [m], >= 0.
  double initialFilm_m = 1.0e-6;
};

/// The oil that entered and left a liner film since the start [m^3] (sums over steps, one
/// side or several): stored volume - initial volume = netSource_m3(), to round-off.
struct LinerOilFlows {
  /// Sources: the ring's net (what it left less what it scraped), the splash, and oil the
  /// skirt's film drew that no liner row held.
  ///@{
  double ringSource_m3 = 0.0;
  double splashSource_m3 = 0.0;
  double deficitSource_m3 = 0.0;
  ///@}
  /// Losses: drained above maxFilm_m, the skirt film's net gain across all its edges, what
  /// the film lost across its circumferential edges and the skirt's share of its trailing-edge
  /// outflow (both to the crankcase).
  ///@{
  double drainLoss_m3 = 0.0;
  double filmIntake_m3 = 0.0;
  double sideLeakage_m3 = 0.0;
  double skirtShareLoss_m3 = 0.0;
  ///@}
  /// Sources less losses [m^3]: the change of the stored oil they account for.
  double netSource_m3() const {
    return ringSource_m3 + splashSource_m3 + deficitSource_m3 - drainLoss_m3 - filmIntake_m3 -
           sideLeakage_m3 - skirtShareLoss_m3;
  }
  /// Adds another film's flows (both sides of a piston).
  LinerOilFlows& operator+=(const LinerOilFlows& o);
  /// The flows between two moments: this (the later) less `earlier`.
  LinerOilFlows operator-(const LinerOilFlows& earlier) const;
};

/// The liner film of one side and its cumulative balance; a value the caller keeps.
struct LinerOilState {
  /// Oil volume per cell [m^3], column fastest (k = i + nPhi m); empty: not started.
  Eigen::ArrayXd volume_m3;
  double pinHeight_m = std::numeric_limits<double>::quiet_NaN();  ///< of this state [m]
  LinerOilFlows flows;  ///< what came and went since the start
  /// True for a state not started yet (no cells: not made by LinerOilFilm::makeInitialState()
  /// or advance()).
  bool empty() const { return volume_m3.size() == 0; }
};

/// The film's net flows out across the side's edges over one evaluation [m^3/s] (+ out), per
/// edge node (lubrication::FilmResult): skirt bottom and top per column, the circumferential
/// edges per row. Non-owning: the arrays must outlive the LinerOilFilm::advance() call they are
/// passed to; a null pointer is an edge without flow.
struct EdgeOutflows {
  const Eigen::ArrayXd* bottom = nullptr;   ///< skirt bottom, per column (edgeOutflowYMin_m3ps)
  const Eigen::ArrayXd* top = nullptr;      ///< skirt top, per column (edgeOutflowYMax_m3ps)
  const Eigen::ArrayXd* sideMin = nullptr;  ///< first column's edge, per row (edgeOutflowXMin_m3ps)
  const Eigen::ArrayXd* sideMax = nullptr;  ///< last column's edge, per row (edgeOutflowXMax_m3ps)
};

/// The liner film along one skirt side (this file's comment). Immutable after construction.
class LinerOilFilm {
 public:
  /// @param side the skirt side (its columns and axial extent)
  /// @param parameters sources, losses and the skirt's share
  /// @param lowestPinHeight_m the pin axis at BDC above the crank axis [m]
  /// @param highestPinHeight_m at TDC [m] (> lowest)
  /// @throws std::invalid_argument naming the member for bad parameters (ring below the
  ///         skirt top, a share outside [0, 1], a table not increasing, films not positive)
  LinerOilFilm(const SkirtSideGrid& side, const LinerOilParameters& parameters,
               double lowestPinHeight_m, double highestPinHeight_m);

  /// The start: the initial film on every free row, the skirt at pinHeight_m.
  LinerOilState makeInitialState(double pinHeight_m) const;
  /// The film each skirt edge draws from during a step to pinHeight_m from `state` [m], per
  /// column (resized).
  void calcSupply(const LinerOilState& state, double pinHeight_m, Eigen::ArrayXd& bottom_m,
                  Eigen::ArrayXd& top_m) const;
  /// The state after a step of dt_s > 0 to pinHeight_m, with the piston's axial velocity then
  /// (its sign tells the trailing edge), the crank angle (the ring's film) and the film's
  /// edge outflows (arrays of the side's sizes).
  LinerOilState advance(const LinerOilState& state, double pinHeight_m,
                        double axialVelocity_mps, double crankAngle_deg, double dt_s,
                        const EdgeOutflows& edgeFlows) const;

  /// The oil on the liner [m^3].
  double storedVolume_m3(const LinerOilState& state) const { return state.volume_m3.sum(); }
  /// Mean film thickness over the columns per row [m] (rows entries; covered rows 0).
  void calcMeanFilmPerRow(const LinerOilState& state, Eigen::ArrayXd& film_m) const;
  /// Film thickness per cell [m] (column fastest).
  void calcFilm(const LinerOilState& state, Eigen::ArrayXd& film_m) const;

  /// Number of columns: the side's film grid angles (SkirtSideGrid::getPhiNodes_rad()).
  int columns() const { return static_cast<int>(width_m_.size()); }
  /// Number of rows along the bore, from below the skirt's lowest reach to above the ring's
  /// highest.
  int rows() const { return rows_; }
  /// Height of a row along the bore, dY [m]: the skirt film grid's mean axial node spacing.
  double rowSpacing_m() const { return dY_; }
  double rowHeight_m(int m) const { return y0_ + m * dY_; }  ///< bore height of row m [m]
  const Eigen::ArrayXd& columnWidth_m() const { return width_m_; }  ///< arc length [m]
  const LinerOilParameters& getParameters() const { return parameters_; }  ///< as constructed
  /// The film the ring leaves at a crank angle [m].
  double calcRingFilm_m(double crankAngle_deg) const;

 private:
  /// Row index of the first free row above height H (may be rows_ when none) and the last
  /// free row below it (may be -1).
  int rowAbove(double height_m) const;
  int rowBelow(double height_m) const;
  bool covered(int m, double pinHeight_m) const;
  double cellCapacity_m3(int i, double film_m) const { return film_m * width_m_[i] * dY_; }

  LinerOilParameters parameters_;
  double yBottom_, yTop_;   ///< the skirt's ends above the pin [m]
  double y0_, dY_;          ///< first row's height, spacing [m]
  int rows_;
  Eigen::ArrayXd width_m_;  ///< per column
};

}  // namespace pistondyn::skirt
