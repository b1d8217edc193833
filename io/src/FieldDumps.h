#pragma once
// Field dumps of a liner element's nodal fields (plugin/NodalFields.h; the lubricated skirt's
// liner.field_dumps.crank_angles_deg): at each listed crank angle of the last simulated cycle,
// one CSV file per region with every declared field. Internal to pistondyn::io (RunDeck).
//
// File <dir>/field_dump_<angle>deg_<region>.csv (angle as the shortest text, e.g. 382.5;
// region e.g. thrust or antithrust): '#' comment lines (program, deck, angle and time,
// frames), then the columns phi_deg, y_mm and one per declared field (its name and unit, e.g.
// gap_um, h_over_sigma, film_pressure_Pa); one row per node, phi fastest (k = i + nPhi j).
// phi is measured from +x (thrust) towards +z (pin axis); y is the height above the pin axis
// in the piston frame.
//
// The files are staged in a ResultFileSet (all-or-nothing with cycle.csv): each is written
// when its row arrives and rewritten in every later cycle of a run to periodic steady state,
// so after the run it holds the last cycle's fields; endRun() throws if one was never
// written in the last cycle.

#include <string>
#include <vector>

#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/NodalFields.h"

namespace pistondyn::io::detail {

class FieldDumpSink final : public plugin::RowSink {
 public:
  // Stages one file per angle and region in `files` when the run begins. `source` and `files`
  // must outlive the sink.
  FieldDumpSink(const plugin::NodalFieldSource& source, std::vector<double> angles_deg,
                long rowsPerCycle, std::vector<std::string> commentLines, ResultFileSet& files);
  void beginRun(const std::vector<std::string>& columns) override;
  void beginCycle(int cycle) override;
  void consumeRow(const SimTK::State& state, const std::vector<double>& values) override;
  void discardRows() override;
  void endRun() override;

  // The file name for an angle and region ("field_dump_360deg_thrust.csv").
  static std::string fileName(double angle_deg, const std::string& region);

 private:
  void write(const SimTK::State& state, std::size_t angleIndex, double time_s);

  const plugin::NodalFieldSource& source_;
  ResultFileSet& files_;
  std::vector<plugin::NodalFieldRegion> regions_;
  std::vector<std::string> columns_;
  std::vector<double> angles_deg_;
  long perCycle_;
  std::vector<std::string> comments_;
  std::vector<std::string> paths_;  // [regions * angle + region]
  std::vector<bool> written_;       // per angle, in the current cycle
  long rowInCycle_ = -1;
  Eigen::MatrixXd values_;          // scratch
};

}  // namespace pistondyn::io::detail
