// Render targets' memory layout (raster/target.cpp, row_pitch): every row holds the tile-multiple width and one
// cache line more, an odd number of 64-byte lines, so that the 64 rows of a tile start in 64 different sets of a
// 64-set L1 cache; rows stay 64-byte aligned. For every depth and colour format, at widths that are powers of two
// (where a tile-multiple pitch alone would put every row of a tile in the same sets), and at others.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>

#include "raster/limits.h"
#include "raster/target.h"

using namespace raster;

namespace {

constexpr int kWidths[] = {1, 63, 64, 65, 300, 512, 1024, 1920, 2048};

// The L1 set (64-byte lines, 64 sets) of the first byte of each of a tile's rows.
size_t distinct_sets(const std::byte* row0, size_t row_bytes) {
  std::set<uintptr_t> sets;
  for (int r = 0; r < kTileSize; ++r) sets.insert((reinterpret_cast<uintptr_t>(row0) + r * row_bytes) / 64 % 64);
  return sets.size();
}

}  // namespace

TEST(Target, DepthRowsAreAnOddNumberOfCacheLines) {
  for (DepthFormat f : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f})
    for (int w : kWidths) {
      const DepthTarget d(w, 70, f);
      const size_t row_bytes = size_t(d.pitch()) * d.bytes_per_texel();
      EXPECT_GE(d.pitch(), (w + kTileSize - 1) / kTileSize * kTileSize) << "width " << w;
      EXPECT_EQ(row_bytes % 64, 0u) << "width " << w;
      EXPECT_EQ(row_bytes / 64 % 2, 1u) << "width " << w << ", format " << int(f);
      // row<T> steps by pitch elements of T: the format's own texel type.
      const auto* row0 = f == DepthFormat::d16 ? reinterpret_cast<const std::byte*>(d.row<uint16_t>(0))
                                               : reinterpret_cast<const std::byte*>(d.row<uint32_t>(0));
      const auto* row1 = f == DepthFormat::d16 ? reinterpret_cast<const std::byte*>(d.row<uint16_t>(1))
                                               : reinterpret_cast<const std::byte*>(d.row<uint32_t>(1));
      EXPECT_EQ(size_t(row1 - row0), row_bytes);
      EXPECT_EQ(reinterpret_cast<uintptr_t>(row0) % 64, 0u);
      EXPECT_EQ(distinct_sets(row0, row_bytes), 64u) << "width " << w << ", format " << int(f);
    }
}

TEST(Target, ColourRowsAreAnOddNumberOfCacheLines) {
  for (ColorFormat f : {ColorFormat::rgba8, ColorFormat::rgba32f, ColorFormat::rg32f, ColorFormat::r32f})
    for (int w : kWidths) {
      ColorTarget c(w, 70, f);
      const size_t row_bytes = size_t(c.pitch()) * bytes_per_texel(f);
      const std::byte* row0 = c.channels() > 0 ? reinterpret_cast<const std::byte*>(c.row32f(0))
                                               : reinterpret_cast<const std::byte*>(c.row8(0));
      const std::byte* row1 = c.channels() > 0 ? reinterpret_cast<const std::byte*>(c.row32f(1))
                                               : reinterpret_cast<const std::byte*>(c.row8(1));
      EXPECT_EQ(size_t(row1 - row0), row_bytes);
      EXPECT_GE(c.pitch(), (w + kTileSize - 1) / kTileSize * kTileSize) << "width " << w;
      EXPECT_EQ(row_bytes / 64 % 2, 1u) << "width " << w << ", format " << int(f);
      EXPECT_EQ(distinct_sets(row0, row_bytes), 64u) << "width " << w << ", format " << int(f);
    }
}
