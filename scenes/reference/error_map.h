// The error map of a scored frame: the frame in grey at 15 % of its linear luminance, false-shadowed pixels red,
// false-lit pixels blue (magenta where one light is each); and the contact sheet `shadowlab eval` writes per
// combination, the frame beside its error map.
#pragma once
#include <cstdint>
#include <vector>

#include "raster/target.h"
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

// `errors`: FrameScore::errors (ErrorBits per pixel, GL row order), one per pixel of `frame`.
raster::ColorTarget error_map(const raster::ColorTarget& frame, const std::vector<uint8_t>& errors);

// The contact sheet of one combination: the frame on the left, its error map beside it, then `extra` when given
// (an aliasing heat map of the same size).
raster::ColorTarget contact_sheet(const raster::ColorTarget& frame, const std::vector<uint8_t>& errors,
                                  const raster::ColorTarget* extra = nullptr);

SHADOWLAB_ISA_END
}  // namespace reference
