// The depth-only stage one row at a time (eight lanes) and two rows at a time (sixteen lanes, the form AVX-512
// machines run: raster/depth_stage.h, kDepthRows) leave the same bits in the target, for every depth format, for
// the compile-time LESS and LEQUAL (with hierarchical depth on d32f) and the run-time functions, with and
// without depth writes, on rectangles that start and end on odd rows (pairs with one row outside). The one-row
// form goes through rasterize(), which sends narrow triangles down the narrow path (rasterize_narrow, one row a
// step in every build); the two-row form walks every triangle's blocks (rasterize_blocks), narrow ones too, so
// the narrow path is held to the block walk as well; slivers higher than kNarrowMaxRows, which rasterize() sends
// to the block walk, are drawn too. And the hierarchical bounds each form keeps over the draw
// stay at or above every block's content. Here the sixteen lanes are two halves unless the build is the AVX-512
// one; the instruction-set test (tests/cli/isa_dispatch_test.cpp) compares the 512-bit form where the CPU has it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "raster/coverage.h"
#include "raster/depth_stage.h"
#include "raster/hiz.h"
#include "raster/setup.h"
#include "tests/raster/raster_test_util.h"

using namespace raster;

namespace {

constexpr int W = 301, H = 203;  // tiles cut by the target's edges

// Random stored depths: codes of the format, with a run of one value so that EQUAL-like functions pass somewhere.
void fill_random(DepthTarget& d, std::mt19937& rng) {
  std::uniform_real_distribution<float> z(0.0f, 1.0f);
  for (int y = 0; y < d.padded_height(); ++y)
    for (int x = 0; x < d.pitch(); ++x) {
      const float v = (x / 16 + y / 16) % 5 == 0 ? 0.5f : z(rng);
      if (d.format() == DepthFormat::d32f) d.row<float>(y)[x] = v;
      else if (d.format() == DepthFormat::d24) d.row<uint32_t>(y)[x] = uint32_t(std::nearbyint(v * 16777215.0f));
      else d.row<uint16_t>(y)[x] = uint16_t(std::nearbyint(v * 65535.0f));
    }
}

struct Counts {
  size_t differ = 0, changed = 0, low_bounds = 0;
  // Boxes (a triangle's within one tile's rectangle) at most 8 pixels wide, at most kNarrowMaxRows high (the
  // narrow path) and higher (rasterize() sends those through the block walk): both must occur.
  size_t short_narrow = 0, tall_narrow = 0;
};

// The blocks of `d` whose hierarchical bound in `tiles` (one TileHiZ per tile, row-major) is below the block's
// largest stored depth: a bound that low would let a triangle skip a block it can pass.
size_t bounds_below_content(const DepthTarget& d, const std::vector<TileHiZ>& tiles, int tiles_x) {
  size_t low = 0;
  for (int by = 0; by < d.padded_height(); by += kBlockSize)
    for (int bx = 0; bx < tiles_x << kTileSizeLog2; bx += kBlockSize) {  // the tiles' columns, not the row's end
      float m = 0.0f;
      for (int r = 0; r < kBlockSize; ++r)
        for (int l = 0; l < kBlockSize; ++l) m = std::max(m, d.row<float>(by + r)[bx + l]);
      const TileHiZ& h = tiles[size_t(by >> kTileSizeLog2) * size_t(tiles_x) + size_t(bx >> kTileSizeLog2)];
      // LEQUAL hides the block from a triangle whose lower bound is m exactly when the bound is below m.
      low += h.hidden<false>(simd::VecF32::splat(m), by) >> tile_block_column(bx) & 1u;
    }
  return low;
}

// rasterize()'s clamp of the triangle's box to `r`, then the block walk whatever the triangle's width.
template <class Stage>
void rasterize_blocks_only(const TriangleSetup& t, const PixelRect& r, const Stage& stage) {
  const int32_t x0 = std::max<int32_t>(t.min_x, r.x0), x1 = std::min<int32_t>(t.max_x, r.x1);
  const int32_t y0 = std::max<int32_t>(t.min_y, r.y0), y1 = std::min<int32_t>(t.max_y, r.y1);
  if (x0 <= x1 && y0 <= y1) rasterize_blocks(t, x0, y0, x1, y1, stage);
}

// Draws `n` random triangles through both forms of the stage into copies of one random target and counts the
// texels (padding included) where the copies differ, and where the one-row copy differs from the start.
template <DepthFormat F, class Compare, bool Write>
Counts draw_both(Compare compare, unsigned seed, int n) {
  std::mt19937 rng(seed);
  DepthTarget one(W, H, F);
  fill_random(one, rng);
  const DepthTarget start = one;
  DepthTarget two = one;
  using Stage1 = DepthOnlyStage<F, Compare, Write, 1>;
  using Stage2 = DepthOnlyStage<F, Compare, Write, 2>;
  static_assert(Stage1::kHiZ == Stage2::kHiZ);
  // One hierarchical bound per tile for each form, kept from triangle to triangle as the renderer keeps it over a
  // draw, so the bounds each form leaves behind decide what the next triangles skip.
  const int tiles_x = (W + kTileSize - 1) >> kTileSizeLog2, tiles_y = one.padded_height() >> kTileSizeLog2;
  std::vector<TileHiZ> hiz1(size_t(tiles_x) * size_t(tiles_y)), hiz2(hiz1.size());
  if constexpr (Stage1::kHiZ)
    for (int ty = 0; ty < tiles_y; ++ty)
      for (int tx = 0; tx < tiles_x; ++tx) {
        hiz1[size_t(ty) * size_t(tiles_x) + size_t(tx)].load(one, tx << kTileSizeLog2, ty << kTileSizeLog2);
        hiz2[size_t(ty) * size_t(tiles_x) + size_t(tx)].load(two, tx << kTileSizeLog2, ty << kTileSizeLog2);
      }
  Counts c;
  std::uniform_int_distribution<int32_t> pos(-16 * kSubpixelScale, (W + 16) * kSubpixelScale);
  std::uniform_int_distribution<int32_t> small(1, 12 * kSubpixelScale), large(1, 260 * kSubpixelScale);
  // Slivers: up to 8 pixels wide and 10 to 70 high, on both sides of kNarrowMaxRows.
  std::uniform_int_distribution<int32_t> thin(1, 8 * kSubpixelScale), tall(10 * kSubpixelScale, 70 * kSubpixelScale);
  std::uniform_real_distribution<float> z(-0.2f, 1.2f);
  std::uniform_int_distribution<int> edge(0, 5);
  for (int i = 0; i < n; ++i) {
    DrawState s;
    if (i % 3 == 1) s.polygon_offset = {float(i % 5) - 2.0f, float(i % 7) * 20.0f - 60.0f};
    const SetupParams sp = make_setup_params(s, W, H, F);
    std::uniform_int_distribution<int32_t>& reach = i % 4 == 0 ? large : small;
    const int32_t x = pos(rng), y = pos(rng);
    const bool sliver = i % 4 == 2;
    const int32_t dx1 = sliver ? thin(rng) : reach(rng), dy1 = sliver ? tall(rng) / 3 : reach(rng) / 3;
    const int32_t dx2 = sliver ? thin(rng) / 2 : reach(rng) / 4, dy2 = sliver ? tall(rng) : reach(rng);
    const WindowVertex v[3] = {rtest::snapped_vertex(x, y, z(rng)), rtest::snapped_vertex(x + dx1, y + dy1, z(rng)),
                               rtest::snapped_vertex(x + dx2, y + dy2, z(rng))};
    TriangleSetup t{};
    if (setup_triangle(v[0], v[1], v[2], sp, t) != SetupResult::visible &&
        setup_triangle(v[0], v[2], v[1], sp, t) != SetupResult::visible)
      continue;
    // A scissor-like rectangle that trims each tile by a few pixels, so the rows a block or a narrow segment
    // covers start and end anywhere.
    const int ex0 = edge(rng), ey0 = edge(rng), ex1 = edge(rng), ey1 = edge(rng);
    for (int32_t ty = t.min_y >> kTileSizeLog2; ty <= t.max_y >> kTileSizeLog2; ++ty)
      for (int32_t tx = t.min_x >> kTileSizeLog2; tx <= t.max_x >> kTileSizeLog2; ++tx) {
        const int32_t tx0 = tx << kTileSizeLog2, ty0 = ty << kTileSizeLog2;
        const PixelRect r{tx0 + ex0, ty0 + ey0, std::min(tx0 + kTileSize - 1 - ex1, W - 1),
                          std::min(ty0 + kTileSize - 1 - ey1, H - 1)};
        const size_t tile = size_t(ty) * size_t(tiles_x) + size_t(tx);
        const int32_t bw = std::min<int32_t>(t.max_x, r.x1) - std::max<int32_t>(t.min_x, r.x0);
        const int32_t bh = std::min<int32_t>(t.max_y, r.y1) - std::max<int32_t>(t.min_y, r.y0);
        if (bw >= 0 && bw < kBlockSize && bh >= 0) (bh < kNarrowMaxRows ? c.short_narrow : c.tall_narrow)++;
        rasterize(t, r, Stage1{&one, &hiz1[tile], compare});
        rasterize_blocks_only(t, r, Stage2{&two, &hiz2[tile], compare});
      }
  }
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      c.differ += one.raw(x, y) != two.raw(x, y);
      c.changed += one.raw(x, y) != start.raw(x, y);
    }
  if constexpr (Stage1::kHiZ && Write)
    c.low_bounds = bounds_below_content(one, hiz1, tiles_x) + bounds_below_content(two, hiz2, tiles_x);
  // Padding rows and columns are never drawn: both forms leave them as they were.
  for (int y = 0; y < one.padded_height(); ++y)
    for (int x = 0; x < one.pitch(); ++x) {
      const size_t at = (size_t(y) * size_t(one.pitch()) + size_t(x)) * one.bytes_per_texel();
      const auto* a = one.row<std::byte>(0) + at;
      c.differ += std::memcmp(a, two.row<std::byte>(0) + at, one.bytes_per_texel()) != 0;
      if (x >= W || y >= H) c.differ += std::memcmp(a, start.row<std::byte>(0) + at, one.bytes_per_texel()) != 0;
    }
  return c;
}

template <DepthFormat F>
void check_format(const char* name) {
  const std::string f = name;
  Counts c = draw_both<F, FixedDepthFunc<DepthFunc::less>, true>({}, 1, 600);
  EXPECT_EQ(c.differ, 0u) << f << " LESS";
  EXPECT_EQ(c.low_bounds, 0u) << f << " LESS";
  EXPECT_GT(c.changed, size_t(W) * H / 4) << f << " LESS";
  EXPECT_GT(c.short_narrow, 50u) << f << " LESS";  // the narrow path against the block walk
  EXPECT_GT(c.tall_narrow, 50u) << f << " LESS";   // slivers rasterize() sends to the block walk
  c = draw_both<F, FixedDepthFunc<DepthFunc::lequal>, true>({}, 2, 600);
  EXPECT_EQ(c.differ, 0u) << f << " LEQUAL";
  EXPECT_EQ(c.low_bounds, 0u) << f << " LEQUAL";
  EXPECT_GT(c.changed, size_t(W) * H / 4) << f << " LEQUAL";
  for (DepthFunc func : {DepthFunc::greater, DepthFunc::notequal, DepthFunc::equal, DepthFunc::gequal}) {
    c = draw_both<F, DepthCompare, true>(DepthCompare(func), 3 + unsigned(func), 300);
    EXPECT_EQ(c.differ, 0u) << f << " function " << int(func);
    if (func != DepthFunc::equal) {  // EQUAL passes only where it writes the value already there
      EXPECT_GT(c.changed, 0u) << f << " function " << int(func);
    }
  }
  c = draw_both<F, FixedDepthFunc<DepthFunc::less>, false>({}, 4, 200);  // no writes: nothing moves
  EXPECT_EQ(c.differ, 0u) << f << " LESS, no writes";
  EXPECT_EQ(c.changed, 0u) << f << " LESS, no writes";
}

}  // namespace

TEST(DepthStage, OneRowAndTwoRowFormsWriteTheSameBits) {
  check_format<DepthFormat::d32f>("d32f");
  check_format<DepthFormat::d24>("d24");
  check_format<DepthFormat::d16>("d16");
}
