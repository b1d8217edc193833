#pragma once
// The progress line of `pistondyn run` on stderr: cycle, crank angle, share done and the
// estimated time left, shown once the run has taken a second. On a terminal one line
// rewritten in place (carriage return); otherwise (a log file, a pipe) a plain line at most
// every 15 s and no carriage returns. A row sink: it sees the rows the simulation produces.

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "pistondyn/plugin/CycleSimulation.h"

namespace pistondyn::app {

class ProgressLine final : public plugin::RowSink {
 public:
  // `rowsAtMost`: rows of the longest run the settings allow (cycles x rows per cycle + 1;
  // a run to periodic steady state may stop earlier, and the estimate says "at most").
  // `terminal`: `out` is a terminal.
  ProgressLine(std::FILE* out, bool terminal, long rowsPerCycle, int cycles, bool upperBound);
  void beginRun(const std::vector<std::string>& columns) override;
  void beginCycle(int cycle) override;
  void consumeRow(const SimTK::State& state, const std::vector<double>& values) override;
  // A run to periodic steady state dropping a cycle: the run goes on, so does the count.
  void discardRows() override {}
  // Clears the line on a terminal (before the summary is printed); finish() also after a
  // failed run.
  void endRun() override;
  void finish();

  // "1 h 02 min", "3 min 05 s", "12 s".
  static std::string formatDuration(double seconds);

 private:
  using Clock = std::chrono::steady_clock;
  std::FILE* out_;
  bool terminal_;
  long perCycle_;
  int cycles_;
  bool upperBound_;
  std::size_t angleColumn_ = 1;
  long rows_ = 0;
  int cycle_ = 0;
  Clock::time_point start_, lastPrint_;
  bool printed_ = false;
  std::size_t width_ = 0;  // of the line on the terminal
};

}  // namespace pistondyn::app
