// Triangle setup eight at a time (raster/setup_batch.h) against setup_triangle() one at a time: the same outcome
// and the same record, bit for bit, for random triangles of every size (the wide ones take the scalar fallback),
// degenerate and outside ones, every cull mode and front face, and polygon offset in every format. The batch's
// compact records (DepthSetup) must be exactly what packing setup_triangle()'s record gives, and expand back to it;
// a sink that takes whole batches (SetupLanes) must see the same outcomes and records as one taking lanes.
#include <gtest/gtest.h>

#include <bit>
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

// Every field of two full records, the floats as bits.
bool same_fields(const TriangleSetup& x, const TriangleSetup& y) {
  for (int k = 0; k < 3; ++k)
    if (x.t[k] != y.t[k] || x.a[k] != y.a[k] || x.b[k] != y.b[k]) return false;
  return x.min_x == y.min_x && x.min_y == y.min_y && x.max_x == y.max_x && x.max_y == y.max_y &&
         std::memcmp(&x.z_a0, &y.z_a0, 4 * sizeof(float)) == 0 && x.prim == y.prim && x.flags == y.flags;
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

  // The same batches taken by a sink that also accepts a whole batch at once (SetupLanes, as the depth-only front
  // end takes them): the same outcomes in the same order and the same records, batches without a wide lane handed
  // over whole.
  struct BothSink {
    std::vector<Outcome>* out;
    size_t batches = 0, lanes = 0;
    void operator()(SetupResult r, const DepthSetup& t) { out->push_back({r, expand_depth_setup(t), true, t}); }
    void operator()(SetupResult r, const TriangleSetup& t) { out->push_back({r, t}); }
    void operator()(const SetupLanes& s) {
      ++batches;
      const unsigned all = s.visible | s.culled | s.degenerate | s.outside;
      ASSERT_EQ(std::popcount(s.visible) + std::popcount(s.culled) + std::popcount(s.degenerate) +
                    std::popcount(s.outside),
                std::popcount(all));  // one outcome per lane
      ASSERT_EQ(all & (all + 1), 0u);  // lanes 0 .. n − 1
      for (int l = 0; l < std::popcount(all); ++l, ++lanes) {
        const unsigned bit = 1u << l;
        const SetupResult r = s.visible & bit   ? SetupResult::visible
                              : s.culled & bit  ? SetupResult::culled
                              : s.degenerate & bit ? SetupResult::degenerate
                                                   : SetupResult::outside;
        out->push_back({r, expand_depth_setup(s.record[l]), true, s.record[l]});
      }
    }
  };
  std::vector<Outcome> whole;
  BothSink both{&whole};
  SetupBatch batch2(sp, v.data());
  for (size_t i = 0; i < n; ++i) {
    batch2.push(uint32_t(3 * i), uint32_t(3 * i + 1), uint32_t(3 * i + 2), both);
    if (i % 37 == 36) batch2.flush(both);
  }
  batch2.flush(both);
  ASSERT_EQ(whole.size(), n) << what;
  EXPECT_GT(both.batches, 0u) << what;  // some batches have no wide lane (small triangles only)
  EXPECT_LT(both.lanes, n) << what;     // and some do
  for (size_t i = 0; i < n; ++i) {
    ASSERT_EQ(int(whole[i].result), int(batched[i].result)) << what << ", triangle " << i;
    if (whole[i].result != SetupResult::visible) continue;
    ASSERT_EQ(whole[i].compact, batched[i].compact) << what << ", triangle " << i;
    if (whole[i].compact)
      ASSERT_EQ(std::memcmp(&whole[i].packed, &batched[i].packed, sizeof(DepthSetup)), 0) << what << ", triangle " << i;
    else  // field by field: the record's padding is not set
      ASSERT_TRUE(same_fields(whole[i].setup, batched[i].setup)) << what << ", triangle " << i;
  }
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
