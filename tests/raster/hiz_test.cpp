// Hierarchical depth (raster/hiz.h): the per-block lower bound of a triangle's depth is below the depth the
// depth-only stage computes at every pixel of the block and close to it; a block is hidden exactly by GL's rule
// for LESS (strict) and LEQUAL; and depth-only draws, which skip hidden blocks, leave the very same buffer as
// shaded draws of the same triangles, which never skip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <array>
#include <random>
#include <string>
#include <vector>

#include "raster/hiz.h"
#include "raster/setup.h"
#include "tests/raster/raster_test_util.h"

using namespace raster;

namespace {

// The lanes of a vector.
std::array<float, 8> lanes(simd::VecF32 v) {
  std::array<float, 8> out;
  v.store(out.data());
  return out;
}

}  // namespace

// Random triangles anywhere on a 2048² target, with steep and shallow depth planes and polygon offset: for each
// tile a triangle's box touches, each block row and block column of the part inside the tile, the bound of
// HiZPlane::row is at or below the clamped depth the stage computes at all 64 pixels of the block, and within
// four times the margin of the smallest of them (so a bound stuck at 0, or a margin grown by mistake, fails).
TEST(HiZ, BlockBoundIsBelowEveryPixelsDepthAndClose) {
  const int kSize = 2048;
  std::mt19937 rng(11);
  std::uniform_int_distribution<int32_t> pos(-64 * kSubpixelScale, (kSize + 64) * kSubpixelScale);
  std::uniform_int_distribution<int32_t> reach(1, 300 * kSubpixelScale);
  std::uniform_real_distribution<float> z01(0.0f, 1.0f), zwide(-0.5f, 1.5f);
  size_t blocks = 0;
  for (int n = 0; n < 400; ++n) {
    DrawState s;
    if (n % 4 == 1) s.polygon_offset = {float(n % 7) - 3.0f, float(n % 5) * 50.0f - 100.0f};
    const SetupParams sp = make_setup_params(s, kSize, kSize, DepthFormat::d32f);
    const int32_t x = pos(rng), y = pos(rng);
    const bool wide = n % 3 == 0;  // depths beyond [0, 1]: the bound is clamped as the pixels are
    WindowVertex v[3] = {rtest::snapped_vertex(x, y, wide ? zwide(rng) : z01(rng)),
                         rtest::snapped_vertex(x + reach(rng), y + reach(rng) / 3, wide ? zwide(rng) : z01(rng)),
                         rtest::snapped_vertex(x + reach(rng) / 4, y + reach(rng), wide ? zwide(rng) : z01(rng))};
    TriangleSetup t{};
    if (setup_triangle(v[0], v[1], v[2], sp, t) != SetupResult::visible &&
        setup_triangle(v[0], v[2], v[1], sp, t) != SetupResult::visible)
      continue;
    for (int32_t ty = t.min_y >> kTileSizeLog2; ty <= t.max_y >> kTileSizeLog2; ++ty)
      for (int32_t tx = t.min_x >> kTileSizeLog2; tx <= t.max_x >> kTileSizeLog2; ++tx) {
        const int32_t x0 = std::max(t.min_x, tx << kTileSizeLog2), x1 = std::min(t.max_x, ((tx + 1) << kTileSizeLog2) - 1);
        const int32_t y0 = std::max(t.min_y, ty << kTileSizeLog2), y1 = std::min(t.max_y, ((ty + 1) << kTileSizeLog2) - 1);
        const HiZPlane hp = make_hiz_plane(t, PixelRect{x0, y0, x1, y1});
        // The margin make_hiz_plane subtracts (hiz.h): 2^-21 of what bounds |z| over the rectangle's blocks.
        const double margin = (std::abs(double(t.z_a0)) + std::abs(double(t.dzdx)) * (x1 + kBlockSize) +
                               std::abs(double(t.dzdy)) * (y1 + kBlockSize) + std::abs(double(t.z_offset)) + 1.0) *
                              0x1p-21;
        for (int32_t by = y0 & ~(kBlockSize - 1); by <= y1; by += kBlockSize) {
          const auto bound = lanes(hp.row(tx << kTileSizeLog2, by));
          for (int32_t bx = x0 & ~(kBlockSize - 1); bx <= x1; bx += kBlockSize) {
            const float lower = bound[size_t(tile_block_column(bx))];
            const simd::VecF32 zcol = plane_depth_columns(t, bx);
            float smallest = 1.0f;
            for (int r = 0; r < kBlockSize; ++r) {
              const auto z = lanes(plane_depth_clamped(zcol, simd::VecF32::splat(t.dzdy),
                                                       simd::VecF32::splat(t.z_offset), by + r));
              for (int l = 0; l < kBlockSize; ++l) {
                ASSERT_LE(lower, z[size_t(l)]) << "triangle " << n << " block " << bx << "," << by << " pixel +" << l
                                               << ",+" << r;
                smallest = std::min(smallest, z[size_t(l)]);
              }
            }
            ASSERT_LE(double(smallest) - double(lower), 4.0 * margin) << "triangle " << n << " block " << bx << "," << by;
            ++blocks;
          }
        }
      }
  }
  EXPECT_GT(blocks, 10000u);
}

// LESS hides a block whose farthest stored depth the triangle cannot get below (equal included), LEQUAL only
// one it stays above; a NaN on either side hides nothing. Bits follow the tile's block columns.
TEST(HiZ, HiddenFollowsTheDepthFunction) {
  TileHiZ h;
  h.set_all(128, 64, 0.5f);
  const float bounds[8] = {0.25f, 0.5f, 0.75f, 0.5f, std::numeric_limits<float>::quiet_NaN(), 1.0f, 0.0f, 0.5f};
  const simd::VecF32 b = simd::VecF32::load(bounds);
  EXPECT_EQ(h.hidden<true>(b, 64), 0b10101110u);   // LESS: 0.5 and above
  EXPECT_EQ(h.hidden<false>(b, 64), 0b00100100u);  // LEQUAL: above 0.5 only
  EXPECT_EQ(h.hidden<true>(b, 120), 0b10101110u);  // any row of the same block row
  h.set_all(128, 64, std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(h.hidden<true>(b, 64), 0u);
  EXPECT_EQ(h.hidden<false>(b, 64), 0u);
}

// Overlapping soups of large and small triangles at random depths, drawn in the order given: the depth-only
// path (which skips hidden blocks for LESS and LEQUAL) and the shaded path (which never does) leave
// bit-identical depth buffers, at 0 and 3 worker threads, into a cleared target and into one already drawn.
TEST(HiZ, DepthOnlyDrawsMatchShadedDrawsThatSkipNothing) {
  const int W = 517, H = 389;  // tiles cut by the target's edges
  for (DepthFunc f : {DepthFunc::less, DepthFunc::lequal})
    for (int threads : {0, 3}) {
      Renderer r(threads);
      std::mt19937 rng(5 + unsigned(threads));
      std::uniform_real_distribution<float> u(-1.1f, 1.1f), zq(-1.0f, 1.0f);
      DepthTarget fast(W, H, DepthFormat::d32f), slow(W, H, DepthFormat::d32f);
      ColorTarget color(W, H, ColorFormat::rgba8);
      DrawState s;
      s.depth_func = f;
      for (int pass = 0; pass < 2; ++pass) {  // the second pass draws over the first's buffer (HiZ loaded, not set)
        std::vector<glm::vec4> v;
        for (int i = 0; i < 3000; ++i) {
          const float cx = u(rng), cy = u(rng), size = i % 10 == 0 ? 0.8f : 0.05f;
          // Equal depths now and then: LESS and LEQUAL differ exactly there.
          const float z = i % 5 == 0 ? 0.25f : zq(rng);
          for (int k = 0; k < 3; ++k)
            v.emplace_back(cx + size * u(rng), cy + size * u(rng), i % 5 == 0 ? z : z + 0.1f * u(rng), 1.0f);
        }
        const std::span<const glm::vec4> vs(v);
        r.draw(RenderTargets{&fast}, s, ClipSpaceDepthShader{}, vs);
        r.draw(RenderTargets{&slow, &color}, s, rtest::WhiteShader{}, vs);
        size_t differ = 0, written = 0;
        for (int y = 0; y < H; ++y)
          for (int x = 0; x < W; ++x) {
            differ += fast.raw(x, y) != slow.raw(x, y);
            written += fast.value(x, y) != 1.0f;
          }
        const std::string what = std::string(f == DepthFunc::less ? "LESS" : "LEQUAL") + ", " +
                                 std::to_string(threads) + " threads, pass " + std::to_string(pass);
        EXPECT_EQ(differ, 0u) << what;
        EXPECT_GT(written, size_t(W) * H / 2) << what;
      }
    }
}
