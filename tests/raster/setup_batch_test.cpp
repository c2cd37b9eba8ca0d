// Triangle setup eight at a time (raster/setup_batch.h) against setup_triangle() one at a time: the same outcome
// and the same record, bit for bit, for random triangles of every size (the wide ones take the scalar fallback),
// degenerate and outside ones, every cull mode and front face, and polygon offset in every format. The batch's
// compact records (DepthSetup) must be exactly what packing setup_triangle()'s record gives, and expand back to it.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <type_traits>
#include <vector>

#include "raster/depth_setup.h"
#include "raster/setup.h"
#include "raster/setup_batch.h"

using namespace raster;

namespace {

struct Outcome {
  SetupResult result;
  TriangleSetup setup;  // the batch's record, expanded when it was a DepthSetup
  bool compact = false;
  DepthSetup packed{};
};

// Random window vertices: clusters of three around a random centre, of a random size from sub-pixel to the whole
// viewport and beyond it (boxes clamped by the draw's rectangle, triangles outside it), some snapped onto each
// other or onto one line (degenerate).
std::vector<WindowVertex> random_vertices(const SetupParams& sp, size_t triangles, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), centre(-1.3f, 1.3f), depth(-1.0f, 1.0f);
  std::uniform_int_distribution<int> size_class(0, 5), special(0, 15);
  const float sizes[] = {0.001f, 0.01f, 0.03f, 0.06f, 0.3f, 1.5f};
  std::vector<WindowVertex> v;
  for (size_t i = 0; i < triangles; ++i) {
    const float cx = centre(rng), cy = centre(rng), s = sizes[size_class(rng)];
    glm::vec4 p[3];
    for (auto& q : p) q = glm::vec4(cx + s * u(rng), cy + s * u(rng), depth(rng), 1.0f);
    const int sp_case = special(rng);
    if (sp_case == 0) p[2] = p[1];                                  // two vertices equal
    if (sp_case == 1) p[2] = p[0] + 2.0f * (p[1] - p[0]);           // on one line
    if (sp_case == 2) p[1].w = 1.5f, p[1] *= 1.5f;                  // another w, same position
    for (const auto& q : p) v.push_back(to_window(q, sp));
  }
  return v;
}

void expect_same(const SetupParams& sp, const std::vector<WindowVertex>& v, const std::string& what) {
  const size_t n = v.size() / 3;
  std::vector<Outcome> batched;
  SetupBatch batch(sp, v.data());
  auto sink = [&](SetupResult r, const auto& t) {
    if constexpr (std::is_same_v<std::decay_t<decltype(t)>, DepthSetup>) {
      batched.push_back({r, expand_depth_setup(t), true, t});
    } else {
      batched.push_back({r, t});
    }
  };
  for (size_t i = 0; i < n; ++i) {
    batch.push(uint32_t(3 * i), uint32_t(3 * i + 1), uint32_t(3 * i + 2), sink);
    if (i % 37 == 36) batch.flush(sink);  // partial batches, as before a clipped triangle
  }
  batch.flush(sink);
  ASSERT_EQ(batched.size(), n) << what;
  size_t visible = 0;
  for (size_t i = 0; i < n; ++i) {
    TriangleSetup one{};
    const SetupResult r = setup_triangle(v[3 * i], v[3 * i + 1], v[3 * i + 2], sp, one);
    ASSERT_EQ(int(batched[i].result), int(r)) << what << ", triangle " << i;
    if (r != SetupResult::visible) continue;
    ++visible;
    const TriangleSetup& b = batched[i].setup;
    if (batched[i].compact) {  // every field of the packed record, and what expanding it gives
      ASSERT_TRUE(fits_depth_setup(one)) << what << ", triangle " << i;
      const DepthSetup p = pack_depth_setup(one);
      ASSERT_EQ(std::memcmp(&p, &batched[i].packed, sizeof(DepthSetup)), 0) << what << ", triangle " << i;
      one.prim = 0;  // the compact record does not keep the back-facing bit
    }
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(b.t[k], one.t[k]) << what << ", triangle " << i << ", edge " << k;
      ASSERT_EQ(b.a[k], one.a[k]) << what << ", triangle " << i;
      ASSERT_EQ(b.b[k], one.b[k]) << what << ", triangle " << i;
    }
    ASSERT_EQ(b.min_x, one.min_x);
    ASSERT_EQ(b.min_y, one.min_y);
    ASSERT_EQ(b.max_x, one.max_x);
    ASSERT_EQ(b.max_y, one.max_y);
    ASSERT_EQ(std::memcmp(&b.z_a0, &one.z_a0, 4 * sizeof(float)), 0) << what << ", triangle " << i;
    ASSERT_EQ(b.prim, one.prim);
    ASSERT_EQ(b.flags, one.flags) << what << ", triangle " << i;
  }
  EXPECT_GT(visible, n / 10) << what;  // culling takes about half, the scissor more
}

}  // namespace

TEST(SetupBatch, SameRecordsAsOneAtATime) {
  const CullMode culls[] = {CullMode::none, CullMode::back, CullMode::front};
  const FrontFace faces[] = {FrontFace::ccw, FrontFace::cw};
  const DepthFormat formats[] = {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f};
  const PolygonOffset offsets[] = {{0.0f, 0.0f}, {1.1f, 4.0f}, {-2.0f, 0.0f}, {0.0f, -1.0f}};
  uint32_t seed = 1;
  for (CullMode cull : culls)
    for (FrontFace face : faces)
      for (DepthFormat format : formats)
        for (const PolygonOffset& offset : offsets) {
          DrawState s;
          s.cull = cull;
          s.front_face = face;
          s.polygon_offset = offset;
          if (seed % 3 == 0) s.viewport = Rect{-40, 25, 700, 500};
          if (seed % 4 == 1) s.scissor = Rect{30, 10, 400, 300};
          const SetupParams sp = make_setup_params(s, 640, 480, format);
          const auto v = random_vertices(sp, 3000, seed);
          expect_same(sp, v, "case " + std::to_string(seed));
          ++seed;
        }
}
