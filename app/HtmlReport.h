#pragma once
// `pistondyn report DIR`: one self-contained report.html (no network: images are base64
// data URIs, style and script inline) with the summary table and its units, the plots,
// a headline (ReportSummary.h), the inputs (a table with their sources, ReportInputs.h, and
// the deck's text), an animation of the piston's secondary motion in the bore over the last
// cycle (inline SVG and JavaScript; lateral displacement, clearance and tilt exaggerated by
// a factor the page states) and, with the liner's field frames, an animated map of each
// side's film following it (a canvas per side).

#include <ostream>
#include <string>
#include <vector>

#include "pistondyn/io/ResultFolder.h"

namespace pistondyn::app {

// The page's text. `pngPaths`: the figures to embed; `plotNote`: shown instead of them
// when empty (why there are no plots); `fieldFramesJson`: the animated map's data
// (makeFieldAnimationJson, FieldAnimation.h; "" for none), read by the caller so that a
// malformed frame file is refused before anything is drawn.
std::string makeHtmlReport(const io::ResultFolder& folder, const std::vector<std::string>& pngPaths,
                           const std::string& plotNote, const std::string& fieldFramesJson);

// The factor the animation draws lateral displacements and tilt with: a round number
// (1, 2 or 5 x 10^k) that draws `clearance_m` as about 8 % of `bore_m`.
double chooseExaggeration(double bore_m, double clearance_m);

std::string encodeBase64(const std::string& bytes);

// The PNG figures embedded in a page (base64 <figure>s captioned with their file names), or
// `plotNote` when there are none; the report and the comparison page share it.
void writeEmbeddedFigures(std::ostream& html, const std::vector<std::string>& pngPaths,
                          const std::string& plotNote);

}  // namespace pistondyn::app
