#pragma once
// The data of the report's animated map: a run's field_frames_<region>.csv (the liner's
// nodal fields every few degrees of the last cycle on a decimated grid, io/src/CycleMaps.h)
// packed for the page's script. Each field in its display unit (DisplayUnits.h), one colour
// scale per field shared by the regions (its top as the cycle maps choose it:
// plot::chooseColourTop), each value quantised to one of 256 colours and the bytes base64
// encoded: frames x heights x angles per region, angle fastest. At 16 x 12 nodes, 72 frames,
// two regions and three fields about 110 kB of the page.

#include <string>

#include "pistondyn/io/ResultFolder.h"

namespace pistondyn::app {

// The JSON the page's script reads:
//   {"frames_deg": [0, 10, ...],
//    "regions": [{"name": "thrust", "title": "thrust side", "phi_deg": [...], "y_mm": [...]}],
//    "fields": [{"name": "film_pressure", "label": "film pressure (gauge)", "unit": "MPa",
//                "lo": 0, "top": 24.1, "peak": 652, "blues": false,
//                "data": ["<base64 of region 0>", ...]}]}
// "" when the folder has no field frames. Throws io::ResultFolderError naming the file when
// a frame file has no rows, its grid is not complete (every frame the same nodes, each
// once), a value is not finite, or the regions' frames differ (io::DeckError from
// io::readCsvTable for a file that is not a numeric CSV with crank_angle_deg, phi_deg and
// y_mm).
std::string makeFieldAnimationJson(const io::ResultFolder& folder);

}  // namespace pistondyn::app
