#pragma once
// The figures of a run as `pistondyn report` shows them to a piston engineer: the headline
// block (the handful of figures a run is judged by, each in its display unit with the crank
// angle it occurs at) and the values of the summary table, both from summary.json's flattened
// entries (io::ResultFolder) through the display units of DisplayUnits.h - 31.0 bar, 2.81 kPa,
// 1.23 µm at 382.5°, never 3.10148e+06 Pa.

#include <string>
#include <vector>

#include "pistondyn/io/ResultFolder.h"

namespace pistondyn::app {

struct HeadlineItem {
  std::string label;  // "fmep", "min h/σ thrust side"
  std::string value;  // "2.81 kPa", "2.31 at 382.5°", "not converged (3 cycles run)"
  std::string note;   // what the figure is, for a person ("" for none)
};

// The headline of a run, in this order, each item only when summary.json has its figure:
// fmep, imep, mean friction power, asperity share of the friction work, minimum h/σ and
// minimum film thickness per side (with their crank angles), largest slap energy, max |tilt|,
// max |lateral displacement|, hot running clearance, peak cylinder pressure and largest side
// force on the liner (with their crank angles), and always whether the run converged to a periodic cycle and after how many cycles
// ("not converged" when cycles_to_converge is null or absent).
std::vector<HeadlineItem> makeHeadline(const io::ResultFolder& folder);

// A summary.json value (`jsonText` as io::SummaryEntry holds it) of key `key` in its display
// unit without the unit (getDisplayUnitText gives it): numbers to the significant digits of
// their display format, JSON integers whole (counts), lists of numbers element by element
// ("2.93, 2.85, 2.81"), true / false as yes / no, null as "–" (cycles_to_converge: "not
// converged"), text as written.
std::string formatSummaryValue(const std::string& key, const std::string& jsonText);

}  // namespace pistondyn::app
