// The error map of a scored frame: the frame in grey at 40 % of its luminance, false-shadowed pixels red, false-lit
// pixels blue (magenta where one light is each). Written as a PNG next to the report (`shadowlab eval`).
#pragma once
#include <cstdint>
#include <vector>

#include "raster/target.h"

namespace reference {

// `errors`: FrameScore::errors (ErrorBits per pixel, GL row order), one per pixel of `frame`.
raster::ColorTarget error_map(const raster::ColorTarget& frame, const std::vector<uint8_t>& errors);

}  // namespace reference
