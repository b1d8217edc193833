#pragma once
// The liner element's nodal fields (plugin/NodalFields.h) over the last simulated cycle, for
// maps: `pistondyn plot` and `report` draw them as crank angle x height heat maps and as an
// animated map of the unwrapped region. Internal to pistondyn::io (RunDeck). Two files per
// region (its name, e.g. thrust, antithrust):
//
//   cycle_map_<region>.csv     at every output row of the last cycle, each row of nodes (one
//                              height) reduced over the arc: columns crank_angle_deg, y_mm,
//                              then per mapped field its reduction, the unit last:
//                                gap_min_um                     smallest nominal gap
//                                h_over_sigma_min               smallest h / sigma
//                                film_pressure_max_Pa           largest film pressure
//                                fill_fraction_mean             mean over the arc
//                                contact_pressure_max_Pa        largest asperity pressure
//                                wear_depth_rate_max_um_per_h   largest Archard wear depth rate
//                              (a field the element does not declare is left out; the mean
//                              is the trapezoidal mean in phi, so that clustered nodes do not
//                              weigh more). One line per angle and height, heights fastest
//                              and ascending, angles ascending in [0, 720): nAngles x nY lines.
//   field_frames_<region>.csv  every kFrameStep_deg of crank angle (the nearest whole number
//                              of output rows), the fields film_pressure_Pa, fill_fraction,
//                              contact_pressure_Pa on every k-th node around and along, at
//                              most kFrameNodesAround x kFrameNodesAlong nodes (first and last
//                              node kept): columns crank_angle_deg, phi_deg, y_mm and the
//                              fields; phi fastest, then y, then the angle.
//
// Field values are written to 4 significant digits (what a colour map resolves), angles and
// coordinates to 1e-6 deg / mm. y is the height the region gives (NodalFieldRegion::y_m);
// the maps take each row's height from its first node.
//
// The files are staged in a ResultFileSet (all-or-nothing with cycle.csv) and written at the
// end of the run from the rows of the last cycle only (a run to periodic steady state drops
// the earlier ones). A source that declares none of the mapped fields gets no files; endRun()
// throws if the last cycle has fewer output rows than a cycle has.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/NodalFields.h"

namespace pistondyn::io::detail {

class CycleMapSink final : public plugin::RowSink {
 public:
  static constexpr double kFrameStep_deg = 10.0;
  static constexpr int kFrameNodesAround = 16;
  static constexpr int kFrameNodesAlong = 12;

  // `source` and `files` must outlive the sink.
  CycleMapSink(const plugin::NodalFieldSource& source, long rowsPerCycle,
               std::vector<std::string> commentLines, ResultFileSet& files);
  void beginRun(const std::vector<std::string>& columns) override;  // stages the files
  void beginCycle(int cycle) override;
  void consumeRow(const SimTK::State& state, const std::vector<double>& values) override;
  void discardRows() override;
  void endRun() override;  // writes the last cycle's files

  // The file names of a region ("cycle_map_thrust.csv", "field_frames_thrust.csv").
  static std::string mapFileName(const std::string& region);
  static std::string frameFileName(const std::string& region);

 private:
  enum class Reduction { Min, Max, Mean };
  struct Mapped {
    int field;  // column of calcNodalFields' values
    Reduction reduction;
    std::string column;
  };
  struct Region {
    plugin::NodalFieldRegion nodes;
    Eigen::MatrixXd arcWeights;     // nPhi x nY, each column sums to 1 (the trapezoidal mean)
    std::vector<int> frameNodes;    // node indices of the frames, phi fastest
    std::string mapPath, framePath;
    std::vector<double> mapRows;    // per row kept: nY x (2 + mapped) values
    std::vector<double> frameRows;  // per frame: frameNodes x (3 + framed) values
  };

  void keepRow(std::size_t r, const Eigen::MatrixXd& values, double angle_deg, bool frame);
  void writeMap(const Region& region) const;
  void writeFrames(const Region& region) const;

  const plugin::NodalFieldSource& source_;
  ResultFileSet& files_;
  long perCycle_;
  long frameStride_;
  std::vector<std::string> comments_;
  std::vector<Mapped> mapped_;
  std::vector<std::pair<int, std::string>> framed_;  // field column, file column
  std::vector<Region> regions_;
  long rowInCycle_ = -1;
  long rowsKept_ = 0;
  Eigen::MatrixXd values_;  // scratch
};

}  // namespace pistondyn::io::detail
