#pragma once
// Field dumps of the lubricated skirt (liner.field_dumps.crank_angles_deg): at each listed
// crank angle of the last simulated cycle, one CSV file per skirt side with the nodal gap
// (the total and each of its seven terms), the film gap, h/sigma, the film pressure, the
// fill fraction and the asperity contact pressure. Internal to pistondyn::io (RunDeck).
//
// File <dir>/field_dump_<angle>deg_<side>.csv (side thrust or antithrust; angle as the
// shortest text, e.g. 382.5): '#' comment lines (program, deck, angle and time, frames),
// then the columns phi_deg, y_mm, gap_um, rigid_um, skirt_profile_um, liner_shape_um,
// piston_thermal_um, liner_thermal_um, piston_elastic_um, liner_elastic_um, film_gap_um,
// h_over_sigma, film_pressure_Pa, fill_fraction, contact_pressure_Pa; one row per node,
// phi fastest (k = i + nPhi j, SkirtSideGrid.h). phi is measured from +x (thrust) towards
// +z (pin axis): the thrust side is centred on 0 deg, the anti-thrust side on 180 deg; y is
// the height above the pin axis in the piston frame.
//
// The files are staged in a ResultFileSet (all-or-nothing with cycle.csv): each is written
// when its row arrives and rewritten in every later cycle of a run to periodic steady state,
// so after the run it holds the last cycle's fields; endRun() throws if one was never
// written in the last cycle.

#include <string>
#include <vector>

#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/plugin/LubricatedSkirtElement.h"

namespace pistondyn::io::detail {

class SkirtFieldDumpSink final : public plugin::RowSink {
 public:
  // Stages one file per angle and side in `files`. `skirt` must outlive the sink.
  SkirtFieldDumpSink(const plugin::LubricatedSkirtElement& skirt, std::vector<double> angles_deg,
                     long rowsPerCycle, std::vector<std::string> commentLines,
                     ResultFileSet& files);
  void beginCycle(int cycle) override;
  void consumeRow(const SimTK::State& state, const std::vector<double>& values) override;
  void discardRows() override;
  void endRun() override;

  // The file name for an angle and side ("field_dump_360deg_thrust.csv").
  static std::string fileName(double angle_deg, plugin::SkirtSide side);

 private:
  void write(const SimTK::State& state, std::size_t angleIndex, double time_s);

  const plugin::LubricatedSkirtElement& skirt_;
  std::vector<double> angles_deg_;
  long perCycle_;
  std::vector<std::string> comments_;
  std::vector<std::string> paths_;  // [2 * angle + side]
  std::vector<bool> written_;       // per angle, in the current cycle
  long rowInCycle_ = -1;
};

}  // namespace pistondyn::io::detail
