// Summaries of a depth map shared by `inspect` and `diff`: value range, coverage (texels < 1, i.e. something
// was drawn there), and a false-colour rendering for a quick look at a map.
#pragma once
#include <cstddef>

#include "raster/target.h"
#include "scenes/io/exr_map.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

struct MapStats {
  // Over every texel that is a number (min > max when there is none): a map of 12.5 everywhere has min 12.5.
  float min = 0.0f, max = 0.0f;
  // Over covered texels only: below 1, the depth clear value (meaningless when covered is 0).
  float covered_min = 0.0f, covered_max = 0.0f;
  size_t covered = 0, texels = 0, nan = 0;
  double coverage() const { return texels ? double(covered) / double(texels) : 0.0; }
};

MapStats map_stats(const scenes::io::ExrMap& map);

// The preview's colour map, for the record: a viridis-like ramp from dark purple (lo) through teal and green
// to yellow (hi); uncovered texels (depth >= 1) black; NaN magenta.
inline constexpr const char* kPreviewColourMap = "viridis (dark purple = low, yellow = high), uncovered black, NaN magenta";

// A false-colour picture of the map over the depth range [lo, hi] (values outside are clamped). An sRGB RGBA8
// target, ready for write_png.
raster::ColorTarget false_colour(const scenes::io::ExrMap& map, float lo, float hi);

SHADOWLAB_ISA_END
}  // namespace cli
