// Depth-map statistics and the false-colour preview (see map_stats.h).
#include "cli/map_stats.h"

#include <algorithm>
#include <array>
#include <cmath>
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

MapStats map_stats(const scenes::io::ExrMap& map) {
  MapStats s;
  s.texels = map.z.size();
  bool any = false, any_covered = false;
  for (const float v : map.z) {
    if (std::isnan(v)) {
      ++s.nan;
      continue;
    }
    s.min = any ? std::min(s.min, v) : v;
    s.max = any ? std::max(s.max, v) : v;
    any = true;
    if (v < 1.0f) {
      ++s.covered;
      s.covered_min = any_covered ? std::min(s.covered_min, v) : v;
      s.covered_max = any_covered ? std::max(s.covered_max, v) : v;
      any_covered = true;
    }
  }
  return s;
}

raster::ColorTarget false_colour(const scenes::io::ExrMap& map, float lo, float hi) {
  // Piecewise-linear ramp through a few perceptually ordered sRGB colours (a viridis-like sequence).
  static constexpr std::array<std::array<float, 3>, 5> kRamp = {{{68, 1, 84},
                                                                  {59, 82, 139},
                                                                  {33, 145, 140},
                                                                  {94, 201, 98},
                                                                  {253, 231, 37}}};
  raster::ColorTarget out(map.width, map.height, raster::ColorFormat::rgba8, /*srgb=*/true);
  const float range = hi > lo ? hi - lo : 1.0f;
  for (int y = 0; y < map.height; ++y) {
    uint8_t* row = out.row8(y);
    for (int x = 0; x < map.width; ++x) {
      const float v = map.at(x, y);
      uint8_t* px = row + 4 * x;
      px[3] = 255;
      if (std::isnan(v)) {
        px[0] = 255, px[1] = 0, px[2] = 255;
        continue;
      }
      if (!(v < 1.0f)) {
        px[0] = px[1] = px[2] = 0;
        continue;
      }
      const float t = std::clamp((v - lo) / range, 0.0f, 1.0f) * float(kRamp.size() - 1);
      const size_t i = std::min(size_t(t), kRamp.size() - 2);
      const float f = t - float(i);
      for (int c = 0; c < 3; ++c)
        px[c] = uint8_t(std::lround(kRamp[i][size_t(c)] + f * (kRamp[i + 1][size_t(c)] - kRamp[i][size_t(c)])));
    }
  }
  return out;
}

SHADOWLAB_ISA_END
}  // namespace cli
