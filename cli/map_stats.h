// Summaries of a depth map shared by `inspect` and `diff`: value range, coverage (texels < 1, i.e. something
// was drawn there), and a false-colour rendering for a quick look at a map.
#pragma once
#include <cstddef>

#include "raster/target.h"
#include "scenes/io/exr_map.h"

namespace cli {

struct MapStats {
  float min = 1.0f, max = 0.0f;                  // over every texel
  float covered_min = 1.0f, covered_max = 0.0f;  // over covered texels only (min > max when none)
  size_t covered = 0, texels = 0;
  double coverage() const { return texels ? double(covered) / double(texels) : 0.0; }
};

MapStats map_stats(const scenes::io::ExrMap& map);

// A false-colour picture of the map: covered texels ramp from dark blue (nearest covered depth) through green
// to yellow (farthest), uncovered ones (depth 1) are black. An sRGB RGBA8 target, ready for write_png.
raster::ColorTarget false_colour(const scenes::io::ExrMap& map, const MapStats& stats);

}  // namespace cli
