// clear_on_workers (see parallel_clear.h).
#include "raster/parallel_clear.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

#include "raster/formats.h"
#include "raster/limits.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

void clear_on_workers(ColorTarget& target, const glm::vec4& color, ThreadPool& pool) {
  // The texel exactly as write() stores it (conversion, sRGB, rounding), made in a target of its own so that
  // the tasks below are the only writers of `target`.
  ColorTarget one(1, 1, target.format(), target.srgb());
  one.write(0, 0, color);
  const size_t texel = bytes_per_texel(target.format());
  const std::byte* texel_bytes = target.channels() > 0 ? reinterpret_cast<const std::byte*>(one.row32f(0))
                                                       : reinterpret_cast<const std::byte*>(one.row8(0));
  const size_t row_bytes = size_t(target.pitch()) * texel;
  const bool zero = std::all_of(texel_bytes, texel_bytes + texel, [](std::byte b) { return b == std::byte{0}; });
  std::vector<std::byte> pattern;  // one whole row of the texel, copied into every row
  if (!zero) {
    pattern.resize(row_bytes);
    for (size_t i = 0; i < row_bytes; i += texel) std::memcpy(pattern.data() + i, texel_bytes, texel);
  }
  auto row = [&](int y) {
    return target.channels() > 0 ? reinterpret_cast<std::byte*>(target.row32f(y))
                                 : reinterpret_cast<std::byte*>(target.row8(y));
  };
  // Bands of a quarter tile's rows: a 1080p target makes 68 tasks, enough to spread over 16 workers.
  constexpr int kBand = kTileSize / 4;
  const int rows = target.padded_height();
  pool.parallel_for(size_t((rows + kBand - 1) / kBand), [&](size_t band) {
    const int y0 = int(band) * kBand, y1 = std::min(rows, y0 + kBand);
    for (int y = y0; y < y1; ++y) {
      if (zero) std::memset(row(y), 0, row_bytes);
      else std::memcpy(row(y), pattern.data(), row_bytes);
    }
  });
}

SHADOWLAB_ISA_END
}  // namespace raster
