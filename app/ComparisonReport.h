#pragma once
// comparison.html of `pistondyn study` and `pistondyn sweep`: the cases side by side in one
// self-contained page (no network: figures embedded as base64, style inline) - a column per
// case with its swept values and its headline figures (ReportSummary.h: fmep, friction
// power, min h/σ per side with crank angle, slap, tilt, clearance, convergence ... in
// engineering units), a row per figure, then the comparison figures (ComparisonPlots.h),
// the curves of every case on common axes.

#include <string>
#include <vector>

#include "ComparisonPlots.h"

namespace pistondyn::app {

// The page's text. `cases`: the finished cases, their folders read; `pngPaths`: the
// comparison figures to embed; `plotNote`: shown instead of them when empty (why there are
// none); `title`: the study's name or deck.
std::string makeComparisonHtml(const std::string& title, const std::vector<ComparisonCase>& cases,
                               const std::vector<std::string>& pngPaths,
                               const std::string& plotNote);

}  // namespace pistondyn::app
