#pragma once
// `pistondyn report DIR`: one self-contained report.html (no network: images are base64
// data URIs, style and script inline) with the summary table and its units, the plots,
// the inputs (the deck's text and the resolved inputs in SI) and an animation of the
// piston's secondary motion in the bore over the last cycle (inline SVG and JavaScript;
// lateral displacement, clearance and tilt exaggerated by a factor the page states).

#include <string>
#include <vector>

#include "pistondyn/io/ResultFolder.h"

namespace pistondyn::app {

// The page's text. `pngPaths`: the figures to embed; `plotNote`: shown instead of them
// when empty (why there are no plots).
std::string makeHtmlReport(const io::ResultFolder& folder, const std::vector<std::string>& pngPaths,
                           const std::string& plotNote);

// The factor the animation draws lateral displacements and tilt with: a round number
// (1, 2 or 5 x 10^k) that draws `clearance_m` as about 8 % of `bore_m`.
double chooseExaggeration(double bore_m, double clearance_m);

std::string encodeBase64(const std::string& bytes);

}  // namespace pistondyn::app
