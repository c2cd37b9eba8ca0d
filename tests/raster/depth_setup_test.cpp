// The compact record of depth-only draws (raster/depth_setup.h) and the eight-wide vertex stage
// (raster/vertex_batch.h) against the one-at-a-time code they replace: packing then expanding gives setup's record
// field for field, and the edge values coverage reads agree, for triangles at the extremes of the supported range
// (largest target, edges just inside the narrow bound, boxes at the far corners and clamped by the draw's
// rectangle); the vertex batch gives the outcodes and window vertices of OutcodeTester and to_window().
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "raster/coverage.h"
#include "raster/depth_setup.h"
#include "raster/outcode.h"
#include "raster/setup.h"
#include "raster/vertex_batch.h"
#include "tests/raster/raster_test_util.h"

using namespace raster;
using rtest::snapped_vertex;

namespace {

// Checks pack/expand and the edge values over the box widened by one block, where rasterize() evaluates them.
void expect_round_trip(const TriangleSetup& t, const std::string& what) {
  ASSERT_TRUE(fits_depth_setup(t)) << what;
  const DepthSetup d = pack_depth_setup(t);
  const TriangleSetup e = expand_depth_setup(d);
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(e.a[k], t.a[k]) << what;
    ASSERT_EQ(e.b[k], t.b[k]) << what;
    ASSERT_EQ(e.t[k], t.t[k]) << what << ", edge " << k;
  }
  ASSERT_EQ(e.min_x, t.min_x) << what;
  ASSERT_EQ(e.min_y, t.min_y) << what;
  ASSERT_EQ(e.max_x, t.max_x) << what;
  ASSERT_EQ(e.max_y, t.max_y) << what;
  ASSERT_EQ(std::memcmp(&e.z_a0, &t.z_a0, 4 * sizeof(float)), 0) << what;
  ASSERT_EQ(e.flags, t.flags) << what;
  const int32_t ys[] = {t.min_y - kBlockSize, t.min_y, t.max_y, t.max_y + kBlockSize};
  // Eight-pixel rows as the narrow path takes them (x .. x + 7), reaching the box's corners and one block past.
  const int32_t xs[] = {t.min_x - kBlockSize, t.min_x, t.max_x - (kBlockSize - 1), t.max_x + 1};
  using simd::VecI32;
  for (int k = 0; k < 3; ++k)
    for (int32_t x : xs)
      for (int32_t y : ys) {
        const VecI32 lane_x = VecI32::splat(x) + VecI32::iota(), lane_y = VecI32::splat(y);
        alignas(32) uint32_t from_d[8], from_t[8];
        narrow_edge_lanes(d, k, lane_x, lane_y).store_u32(from_d);
        narrow_edge_lanes(t, k, lane_x, lane_y).store_u32(from_t);
        for (int l = 0; l < 8; ++l) {
          const int64_t f = edge_value(t, k, x + l, y);
          ASSERT_EQ(edge_value(d, k, x + l, y), f) << what;
          ASSERT_LT(std::abs(f), int64_t(1) << 31) << what;  // limits.h: narrow edge values fit int32 there
          ASSERT_EQ(int32_t(from_d[l]), int32_t(f)) << what << ", edge " << k << ", lane " << l;
          ASSERT_EQ(int32_t(from_t[l]), int32_t(f)) << what << ", edge " << k << ", lane " << l;
        }
      }
}

}  // namespace

TEST(DepthSetup, CompactRecordReproducesSetupAtTheExtremes) {
  const SetupParams sp = make_setup_params(DrawState{}, kMaxTargetSize, kMaxTargetSize, DepthFormat::d32f);
  const int32_t kMax = (int32_t(1) << kNarrowCoefBits) - 1;  // the widest narrow extent, sub-pixel units
  const int32_t far = kMaxTargetSize * kSubpixelScale;       // the target's far edge, sub-pixel units
  std::mt19937 rng(7);
  std::uniform_int_distribution<int32_t> extent(1, kMax), anywhere(-kMax, far + kMax), depth(0, 1000);
  size_t checked = 0;
  auto check = [&](const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, const std::string& what) {
    TriangleSetup t{};
    if (setup_triangle(a, b, c, sp, t) != SetupResult::visible) return;
    if (!fits_depth_setup(t)) return;
    expect_round_trip(t, what);
    ++checked;
  };
  // Right triangles with legs of the widest narrow extent, in both orientations, at every corner of the target
  // (boxes clamped by the draw's rectangle when they stick out) and in the middle.
  const int32_t corners[][2] = {{0, 0}, {far, 0}, {0, far}, {far, far}, {far / 2, far / 2}, {-kMax / 2, far - 100}};
  for (const auto& o : corners)
    for (int sx : {-1, 1})
      for (int sy : {-1, 1}) {
        const WindowVertex a = snapped_vertex(o[0], o[1], 0.25f);
        const WindowVertex b = snapped_vertex(o[0] + sx * kMax, o[1], 0.5f);
        const WindowVertex c = snapped_vertex(o[0], o[1] + sy * kMax, 0.75f);
        check(a, b, c, "corner triangle");
        check(a, c, b, "corner triangle, other winding");
      }
  // One unit past the bound: not narrow, so it keeps its full record.
  {
    TriangleSetup t{};
    ASSERT_EQ(setup_triangle(snapped_vertex(1000, 1000, 0.5f), snapped_vertex(1000 + kMax + 1, 1000, 0.5f),
                             snapped_vertex(1000, 2000, 0.5f), sp, t),
              SetupResult::visible);
    EXPECT_FALSE(fits_depth_setup(t));
  }
  // Random narrow triangles anywhere, of any extent up to the bound.
  for (int i = 0; i < 20000; ++i) {
    const int32_t x0 = anywhere(rng), y0 = anywhere(rng), w = extent(rng), h = extent(rng);
    std::uniform_int_distribution<int32_t> dx(0, w), dy(0, h);
    const WindowVertex a = snapped_vertex(x0 + dx(rng), y0, float(depth(rng)) / 1000.0f);
    const WindowVertex b = snapped_vertex(x0 + w, y0 + dy(rng), float(depth(rng)) / 1000.0f);
    const WindowVertex c = snapped_vertex(x0, y0 + h, float(depth(rng)) / 1000.0f);
    check(a, b, c, "random triangle " + std::to_string(i));
  }
  EXPECT_GT(checked, size_t(5000));
}

// The batch's clip test takes the frustum planes' distances directly (w − x, …); any other planes go through the
// general dot product. Both must give OutcodeTester's codes, on the planes themselves and at signed zeros too.
TEST(DepthSetup, VertexBatchMatchesOneVertexAtATime) {
  constexpr unsigned kInvalid = 1u << 31;
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.6f, 1.6f), w_dist(-0.2f, 2.0f);
  std::uniform_int_distribution<int> special(0, 19);
  // Not the frustum: the same six half-spaces with scaled normals and reordered, and a plane with a bias.
  ClipPlanes other;
  other.planes = {ClipPlane{{0, 2, 0, 2}}, ClipPlane{{-1, 0, 0, 1}}, ClipPlane{{0, 0, -3, 3}},
                  ClipPlane{{1, 0, 0, 1}}, ClipPlane{{0, -1, 0, 1}}, ClipPlane{{0, 0, 1, 1}},
                  ClipPlane{{0.5f, 0.25f, 0, 1}, 0.125f}};
  other.count = 7;
  for (int variant = 0; variant < 4; ++variant) {
    const bool clamp = variant == 1;
    DrawState s;
    s.depth_clamp = clamp;
    s.viewport = Rect{-30, 17, 901, 555};
    const SetupParams sp = make_setup_params(s, 800, 600, DepthFormat::d24);
    ClipPlanes planes = make_clip_planes(clamp, sp.vp_half_w, sp.vp_center_x, sp.vp_half_h, sp.vp_center_y);
    // Variant 0 and 1: the frustum, with and without the depth planes, which take the direct distances.
    // Variant 2: seven planes. Variant 3: the frustum's six with near and far swapped (still six, so only the
    // normals tell it apart); both take the general path.
    if (variant == 2) planes = other;
    if (variant == 3) std::swap(planes.planes[4], planes.planes[5]);
    ASSERT_EQ(VertexBatch::is_frustum(planes), variant < 2) << "variant " << variant;
    const OutcodeTester outcode_of(planes);
    const VertexBatch batch(planes, sp, kInvalid);
    for (int round = 0; round < 4000; ++round) {
      // Every fourth round: eight vertices inside the view volume, which the batch writes all at once.
      const bool all_inside = round % 4 == 3;
      const int n = all_inside ? 8 : 1 + round % 8;
      alignas(32) float x[8], y[8], z[8], w[8];
      for (int l = 0; l < 8; ++l) {
        const float pw = all_inside ? 0.1f + std::abs(w_dist(rng)) : w_dist(rng);
        const float reach = all_inside ? 0.6f : 1.0f;  // u spans ±1.6: inside the clip volume once scaled
        x[l] = u(rng) * reach * pw, y[l] = u(rng) * reach * pw, z[l] = u(rng) * reach * pw, w[l] = pw;
        if (all_inside) continue;
        switch (special(rng)) {
          case 0: x[l] = nan; break;
          case 1: w[l] = inf; break;
          case 2: w[l] = 0.0f; break;
          case 3: z[l] = -inf; break;
          // On a plane (distance ±0), and signed zeros.
          case 4: x[l] = w[l]; break;
          case 5: x[l] = -w[l]; break;
          case 6: y[l] = w[l], z[l] = -w[l]; break;
          case 7: y[l] = -w[l], z[l] = w[l]; break;
          case 8: x[l] = -0.0f, y[l] = 0.0f, z[l] = -0.0f, w[l] = 0.0f; break;
          case 9: x[l] = 0.0f, w[l] = -0.0f; break;
          // Distances that overflow to ±infinity.
          case 10: x[l] = 3e38f, y[l] = -3e38f, w[l] = 3e38f; break;
          case 11: z[l] = -3e38f, w[l] = 2e38f; break;
          default: break;
        }
      }
      unsigned codes[8];
      WindowVertex win[8] = {};
      using simd::VecF32;
      batch.run(VecF32::load(x), VecF32::load(y), VecF32::load(z), VecF32::load(w), n, codes, win);
      int inside = 0;
      for (int l = 0; l < n; ++l) {
        const glm::vec4 p(x[l], y[l], z[l], w[l]);
        const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
        const unsigned code = finite ? outcode_of(p) : kInvalid;
        ASSERT_EQ(codes[l], code) << "round " << round << ", lane " << l;
        if (code != 0) continue;
        ++inside;
        const WindowVertex one = to_window(p, sp);
        ASSERT_EQ(std::memcmp(&win[l], &one, sizeof(WindowVertex)), 0) << "round " << round << ", lane " << l;
      }
      if (all_inside) {
        ASSERT_EQ(inside, 8) << "round " << round;
      }
    }
  }
}
