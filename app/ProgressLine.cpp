#include "ProgressLine.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace pistondyn::app {
namespace {

constexpr double kQuiet_s = 1.0;          // nothing for runs shorter than this
// PISTONDYN_PROGRESS_AFTER_S (seconds, >= 0) replaces the one second, so that a test can see
// the line on a run of any length; unset or unreadable: one second.
double quietTime_s() {
  static const double t = [] {
    const char* v = std::getenv("PISTONDYN_PROGRESS_AFTER_S");
    if (v == nullptr)
      return kQuiet_s;
    char* end = nullptr;
    const double d = std::strtod(v, &end);
    return (end != v && *end == '\0' && d >= 0.0 && std::isfinite(d)) ? d : kQuiet_s;
  }();
  return t;
}
constexpr double kTerminalEvery_s = 0.2;  // redraws on a terminal
constexpr double kPlainEvery_s = 15.0;    // plain lines elsewhere

}  // namespace

ProgressLine::ProgressLine(std::FILE* out, bool terminal, long rowsPerCycle, int cycles,
                           bool upperBound)
    : out_(out),
      terminal_(terminal),
      perCycle_(std::max(1L, rowsPerCycle)),
      cycles_(std::max(1, cycles)),
      upperBound_(upperBound) {}

std::string ProgressLine::formatDuration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[64];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  else if (s >= 60)
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld s", s);
  return text;
}

void ProgressLine::beginRun(const std::vector<std::string>& columns) {
  const auto it = std::find(columns.begin(), columns.end(), "crank_angle_deg");
  angleColumn_ = it == columns.end() ? 1 : static_cast<std::size_t>(it - columns.begin());
  start_ = lastPrint_ = Clock::now();
  rows_ = 0;
}

void ProgressLine::beginCycle(int cycle) { cycle_ = cycle; }

void ProgressLine::consumeRow(const SimTK::State&, const std::vector<double>& values) {
  ++rows_;
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double sinceLast = std::chrono::duration<double>(now - lastPrint_).count();
  if (elapsed < quietTime_s() || sinceLast < (terminal_ ? kTerminalEvery_s : kPlainEvery_s))
    return;
  lastPrint_ = now;
  const long total = perCycle_ * cycles_ + 1;
  const double done = std::min(1.0, static_cast<double>(rows_) / static_cast<double>(total));
  const double left = done > 0.0 ? elapsed * (1.0 - done) / done : 0.0;
  const double angle = values.size() > angleColumn_ ? values[angleColumn_] : 0.0;
  const double inCycle = angle - 720.0 * std::floor(angle / 720.0);
  char line[200];
  std::snprintf(line, sizeof line,
                "pistondyn: cycle %d of %s%d, crank angle %5.1f deg, %3.0f %% done, %s%s left",
                cycle_ + 1, upperBound_ ? "at most " : "", cycles_, inCycle, 100.0 * done,
                upperBound_ ? "at most " : "about ", formatDuration(left).c_str());
  std::string text(line);
  if (terminal_) {
    const std::size_t w = text.size();
    text.resize(std::max(width_, w), ' ');  // blank out a longer earlier line
    width_ = w;
    std::fprintf(out_, "\r%s", text.c_str());
  } else {
    std::fprintf(out_, "%s\n", text.c_str());
  }
  std::fflush(out_);
  printed_ = true;
}

void ProgressLine::endRun() { finish(); }

void ProgressLine::finish() {
  if (terminal_ && printed_)
    std::fprintf(out_, "\r%s\r", std::string(width_, ' ').c_str());
  printed_ = false;
  std::fflush(out_);
}

}  // namespace pistondyn::app
