#pragma once
// The liner's oil film along the bore over the last cycle (plugin/LinerOilSource.h: the
// lubricated skirt with liner.oil_supply.liner_transport), and its oil balance over that
// cycle. Internal to pistondyn::io (RunDeck).
//
// File <dir>/liner_film.csv: '#' comment lines, then the columns crank_angle_deg,
// height_above_crank_mm, film_thrust_um, film_antithrust_um: at every output row of the last
// cycle, one row per liner row along the bore (mean film over each side's arc, 0 where the
// skirt covers the liner). Staged in a ResultFileSet (all-or-nothing with cycle.csv) and
// written when the run ends.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/LinerOilSource.h"

namespace pistondyn::io::detail {

class LinerFilmSink final : public plugin::RowSink {
 public:
  // `source` and `files` (null: no file, the balance only) must outlive the sink.
  LinerFilmSink(const plugin::LinerOilSource& source, long rowsPerCycle,
                std::vector<std::string> commentLines, ResultFileSet* files);
  void beginRun(const std::vector<std::string>& columns) override;
  void beginCycle(int cycle) override;
  void consumeRow(const SimTK::State& state, const std::vector<double>& values) override;
  void discardRows() override;
  void endRun() override;

  // The balance over the last complete cycle: the counters' changes from its first row to
  // the next cycle's first (stored_m3 at its end, initial_m3 at its start); nullopt before a
  // cycle completed.
  const std::optional<plugin::LinerOilBalance>& getLastCycleBalance() const { return last_; }

 private:
  const plugin::LinerOilSource& source_;
  ResultFileSet* files_;
  long perCycle_;
  std::vector<std::string> comments_;
  std::string path_;
  Eigen::VectorXd heights_m_;
  long rowInCycle_ = -1;
  std::vector<double> angles_deg_;         // per row of the current cycle
  std::vector<Eigen::VectorXd> films_m_;   // per row: thrust then anti-thrust rows
  std::optional<plugin::LinerOilBalance> cycleStart_, previousStart_, last_;
  plugin::LinerOilBalance latest_;         // at the last row consumed
};

}  // namespace pistondyn::io::detail
