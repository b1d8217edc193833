#include "LinerFilmDump.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "pistondyn/common/CrankAngle.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/plugin/LinerElement.h"

namespace pistondyn::io::detail {
namespace {

// The change of the counters from `a` to `b`, stored at b and initial at a.
plugin::LinerOilBalance change(const plugin::LinerOilBalance& a, const plugin::LinerOilBalance& b) {
  plugin::LinerOilBalance d;
  d.initial_m3 = a.stored_m3;
  d.stored_m3 = b.stored_m3;
  d.flows = b.flows - a.flows;
  return d;
}

}  // namespace

LinerFilmSink::LinerFilmSink(const plugin::LinerOilSource& source, long rowsPerCycle,
                             std::vector<std::string> commentLines, ResultFileSet* files)
    : source_(source), files_(files), perCycle_(rowsPerCycle), comments_(std::move(commentLines)) {}

void LinerFilmSink::beginRun(const std::vector<std::string>&) {
  heights_m_ = source_.getLinerOilRowHeights_m();  // the element is in a built model now
  if (files_)
    path_ = files_->stage("liner_film.csv");
}

void LinerFilmSink::beginCycle(int) {
  // The row that opens this cycle closes the one before (consumeRow).
  previousStart_ = cycleStart_;
  rowInCycle_ = 0;
  angles_deg_.clear();
  films_m_.clear();
  cycleStart_.reset();
}

void LinerFilmSink::discardRows() {
  angles_deg_.clear();
  films_m_.clear();
  rowInCycle_ = -1;
  cycleStart_.reset();
  previousStart_.reset();
  last_.reset();
}

void LinerFilmSink::consumeRow(const SimTK::State& state, const std::vector<double>& values) {
  latest_ = source_.calcLinerOilBalance(state);
  if (rowInCycle_ < 0)
    return;
  const long k = rowInCycle_++;
  if (k == 0) {
    cycleStart_ = latest_;
    if (previousStart_)
      last_ = change(*previousStart_, latest_);
  }
  if (k >= perCycle_) {  // the run's last row closes its last cycle
    if (k == perCycle_ && cycleStart_)
      last_ = change(*cycleStart_, latest_);
    return;
  }
  const Eigen::Index n = heights_m_.size();
  Eigen::VectorXd both(2 * n), side;
  source_.calcLinerOilFilm(state, plugin::SkirtSide::Thrust, side);
  both.head(n) = side;
  source_.calcLinerOilFilm(state, plugin::SkirtSide::AntiThrust, side);
  both.tail(n) = side;
  if (!both.allFinite())
    throw std::runtime_error("liner film: a non-finite film at crank angle " +
                             common::formatNumber(values.at(1)) + " deg");
  angles_deg_.push_back(common::wrapCrankAngle_deg(values.at(1)));  // crank_angle_deg
  films_m_.push_back(std::move(both));
}

void LinerFilmSink::endRun() {
  if (!files_)
    return;
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  std::vector<std::string> comments = comments_;
  comments.push_back(
      "oil film on the liner along the bore over the last cycle: per output row, one row per "
      "liner row (bore height above the crank axis), the mean film over each side's arc; 0 "
      "where the skirt covers the liner (its film holds the oil there)");
  writeCsvHeader(out, {"crank_angle_deg", "height_above_crank_mm", "film_thrust_um",
                       "film_antithrust_um"},
                 comments);
  const Eigen::Index n = heights_m_.size();
  std::vector<double> row(4);
  for (std::size_t r = 0; r < angles_deg_.size(); ++r) {
    for (Eigen::Index m = 0; m < n; ++m) {
      row = {angles_deg_[r], 1e3 * heights_m_[m], 1e6 * films_m_[r][m], 1e6 * films_m_[r][n + m]};
      writeCsvRow(out, row);
    }
  }
  out.close();
  if (!out)
    throw std::runtime_error(path_ + ": write failed");
}

}  // namespace pistondyn::io::detail
