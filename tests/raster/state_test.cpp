// Per-draw state: cull modes with both front faces, viewport sub-rectangles and scissor, perspective-correct
// varyings, fragment depth writes and discard, multiply blending, draw validation, and bit-identical output
// at 0, 1, 2, 7 and 16 threads.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "bench/triangle_soup.h"
#include "tests/raster/raster_test_util.h"
#include "tests/support.h"

using namespace raster;

TEST(State, CullModesAndFrontFace) {
  Renderer r(testsupport::test_threads());
  const int W = 16, H = 16;
  // One counter-clockwise and one clockwise triangle side by side.
  std::vector<glm::vec4> v = {rtest::win_to_clip(1, 1, W, H), rtest::win_to_clip(7, 1, W, H), rtest::win_to_clip(1, 7, W, H),
                              rtest::win_to_clip(9, 1, W, H), rtest::win_to_clip(9, 7, W, H), rtest::win_to_clip(15, 1, W, H)};
  for (FrontFace ff : {FrontFace::ccw, FrontFace::cw})
    for (CullMode cm : {CullMode::none, CullMode::back, CullMode::front}) {
      DrawState s;
      s.cull = cm;
      s.front_face = ff;
      const auto c = rtest::count_coverage(r, W, H, v, {0, 1, 2, 3, 4, 5}, s);
      const bool ccw_front = ff == FrontFace::ccw;
      const bool left_drawn = cm == CullMode::none || (cm == CullMode::back) == ccw_front;
      const bool right_drawn = cm == CullMode::none || (cm == CullMode::back) != ccw_front;
      EXPECT_EQ(c[2 * W + 2], left_drawn ? 1u : 0u) << int(ff) << int(cm);
      EXPECT_EQ(c[2 * W + 10], right_drawn ? 1u : 0u) << int(ff) << int(cm);
    }
}

TEST(State, FrontFacingFlagReachesTheShader) {
  struct FacingShader {
    using Vertex = glm::vec4;
    using Varyings = NoVaryings;
    glm::vec4 vertex(const Vertex& v, Varyings&) const { return v; }
    void fragment(const QuadIn<Varyings>& q, QuadOut& o) const {
      for (auto& c : o.color) c = q.front_facing ? glm::vec4(1, 0, 0, 1) : glm::vec4(0, 0, 1, 1);
    }
  };
  Renderer r(0);
  ColorTarget c(16, 8, ColorFormat::rgba8);
  std::vector<glm::vec4> v = {rtest::win_to_clip(0, 0, 16, 8), rtest::win_to_clip(8, 0, 16, 8), rtest::win_to_clip(0, 8, 16, 8),
                              rtest::win_to_clip(8, 0, 16, 8), rtest::win_to_clip(8, 8, 16, 8), rtest::win_to_clip(16, 0, 16, 8)};
  r.draw(RenderTargets{nullptr, &c}, DrawState{}, FacingShader{}, std::span<const glm::vec4>(v));
  EXPECT_EQ(c.read(1, 1), glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(c.read(9, 1), glm::vec4(0, 0, 1, 1));
}

// Several draws into sub-rectangles of one target (how one map holds several views), and a scissor.
TEST(State, ViewportSubRectanglesAndScissor) {
  Renderer r(testsupport::test_threads());
  const int W = 100, H = 80;
  DepthTarget d(W, H, DepthFormat::d16);
  std::vector<glm::vec4> full = {{-1, -1, -0.5f, 1}, {1, -1, -0.5f, 1}, {1, 1, -0.5f, 1}, {-1, -1, -0.5f, 1}, {1, 1, -0.5f, 1}, {-1, 1, -0.5f, 1}};
  DrawState s;
  s.viewport = Rect{10, 20, 30, 40};
  r.draw(RenderTargets{&d}, s, ClipSpaceDepthShader{}, std::span<const glm::vec4>(full));
  s.viewport = Rect{50, 0, 50, 80};
  s.scissor = Rect{60, 10, 5, 7};
  r.draw(RenderTargets{&d}, s, ClipSpaceDepthShader{}, std::span<const glm::vec4>(full));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool in1 = x >= 10 && x < 40 && y >= 20 && y < 60;
      const bool in2 = x >= 60 && x < 65 && y >= 10 && y < 17;
      ASSERT_EQ(d.value(x, y) < 1.0f, in1 || in2) << x << "," << y;
    }
  // The viewport maps NDC to its own rectangle: a triangle at NDC x in [0, 1] lands in the viewport's right half.
  DepthTarget e(W, H, DepthFormat::d32f);
  s = DrawState{};
  s.viewport = Rect{20, 10, 40, 20};
  std::vector<glm::vec4> half = {{0, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1}, {0, -1, 0, 1}, {1, 1, 0, 1}, {0, 1, 0, 1}};
  r.draw(RenderTargets{&e}, s, ClipSpaceDepthShader{}, std::span<const glm::vec4>(half));
  EXPECT_EQ(e.value(40, 15), 0.5f);
  EXPECT_EQ(e.value(59, 29), 0.5f);
  EXPECT_EQ(e.value(39, 15), 1.0f);
  EXPECT_EQ(e.value(60, 15), 1.0f);
}

// Perspective-correct varyings: a textured floor under a perspective camera; the interpolated world position
// must equal the ray/plane intersection at every pixel centre.
TEST(State, PerspectiveCorrectVaryings) {
  struct WorldPosShader {
    struct Vertex { glm::vec3 p; };
    struct Varyings { glm::vec3 world; };
    glm::mat4 vp;
    glm::vec4 vertex(const Vertex& v, Varyings& out) const { out.world = v.p; return vp * glm::vec4(v.p, 1); }
    float* out_x;
    int width;
    void fragment(const QuadIn<Varyings>& q, QuadOut& o) const {
      for (int l = 0; l < 4; ++l) {
        o.color[l] = glm::vec4(1);
        if (q.live >> l & 1) out_x[size_t(q.frag_coord[l].y) * width + size_t(q.frag_coord[l].x)] = q.in[l].world.z;
      }
    }
  };
  const int W = 64, H = 48;
  const glm::mat4 proj = glm::perspective(glm::radians(70.0f), float(W) / H, 0.1f, 100.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 2, 0), glm::vec3(0, 0, -10), glm::vec3(0, 1, 0));
  std::vector<WorldPosShader::Vertex> v = {{{-20, 0, -1}}, {{20, 0, -1}}, {{20, 0, -60}}, {{-20, 0, -1}}, {{20, 0, -60}}, {{-20, 0, -60}}};
  std::vector<float> zs(size_t(W) * H, 0.0f);
  Renderer r(testsupport::test_threads());
  ColorTarget c(W, H, ColorFormat::rgba8);
  r.draw(RenderTargets{nullptr, &c}, DrawState{}, WorldPosShader{proj * view, zs.data(), W},
         std::span<const WorldPosShader::Vertex>(v));
  const glm::mat4 inv = glm::inverse(proj * view);
  int checked = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      if (zs[size_t(y) * W + x] == 0.0f) continue;
      const glm::vec4 a = inv * glm::vec4((x + 0.5f) / W * 2 - 1, (y + 0.5f) / H * 2 - 1, -1, 1);
      const glm::vec4 b = inv * glm::vec4((x + 0.5f) / W * 2 - 1, (y + 0.5f) / H * 2 - 1, 1, 1);
      const glm::vec3 pa = glm::vec3(a) / a.w, pb = glm::vec3(b) / b.w;
      const float t = pa.y / (pa.y - pb.y);
      const float z = pa.z + (pb.z - pa.z) * t;
      // Snapping moves vertices by up to 1/512 pixel; far down the floor that is ~1e-4 of the distance. Affine
      // (not perspective-correct) interpolation would be off by tens of percent here.
      ASSERT_NEAR(zs[size_t(y) * W + x], z, std::abs(z) * 1e-3f) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, W * H / 3);
}

namespace {
struct DiscardingDepthShader {
  using Vertex = glm::vec4;
  using Varyings = NoVaryings;
  static constexpr bool kDiscards = true;
  static constexpr bool kWritesDepth = true;
  glm::vec4 vertex(const Vertex& v, Varyings&) const { return v; }
  void fragment(const QuadIn<Varyings>& q, QuadOut& o) const {
    for (int l = 0; l < 4; ++l) {
      o.color[l] = glm::vec4(0.5f, 0.25f, 1.0f, 1.0f);
      o.depth[l] = q.frag_coord[l].x / 100.0f;
      if (int(q.frag_coord[l].x) % 2) o.discard |= uint8_t(1u << l);
    }
  }
};
}  // namespace

TEST(State, DiscardDepthWriteAndMultiplyBlend) {
  Renderer r(0);
  DepthTarget d(16, 4, DepthFormat::d32f);
  ColorTarget c(16, 4, ColorFormat::rgba32f);
  c.clear(glm::vec4(0.5f, 1.0f, 1.0f, 1.0f));
  DrawState s;
  s.blend = BlendMode::multiply;
  std::vector<glm::vec4> quad = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1}, {-1, -1, 0, 1}, {1, 1, 0, 1}, {-1, 1, 0, 1}};
  r.draw(RenderTargets{&d, &c}, s, DiscardingDepthShader{}, std::span<const glm::vec4>(quad));
  EXPECT_EQ(d.value(4, 1), 4.5f / 100.0f);
  EXPECT_EQ(d.value(5, 1), 1.0f);  // discarded
  EXPECT_EQ(c.read(4, 1), glm::vec4(0.25f, 0.25f, 1.0f, 1.0f));
  EXPECT_EQ(c.read(5, 1), glm::vec4(0.5f, 1.0f, 1.0f, 1.0f));
}

TEST(State, InvalidDrawsAreRefused) {
  Renderer r(0);
  DepthTarget d(8, 8, DepthFormat::d32f);
  std::vector<glm::vec4> v = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}};
  std::vector<uint32_t> bad = {0, 1, 3};
  EXPECT_THROW(r.draw(RenderTargets{&d}, DrawState{}, ClipSpaceDepthShader{}, std::span<const glm::vec4>(v), bad), DrawError);
  std::vector<uint32_t> two = {0, 1};
  EXPECT_THROW(r.draw(RenderTargets{&d}, DrawState{}, ClipSpaceDepthShader{}, std::span<const glm::vec4>(v), two), DrawError);
  EXPECT_THROW(r.draw(RenderTargets{}, DrawState{}, ClipSpaceDepthShader{}, std::span<const glm::vec4>(v)), DrawError);
  EXPECT_THROW(DepthTarget(0, 8, DepthFormat::d16), TargetSizeError);
  EXPECT_THROW(DepthTarget(8, 16385, DepthFormat::d16), TargetSizeError);
}

// A soup's chunks each shade their own vertices and skip the per-index test (renderer.h): an index out of range in
// any chunk, first, middle or last, must still send the draw the checked way, which names the index and its
// position, at any thread count; the soup itself draws.
TEST(State, OutOfRangeIndexOfAManyChunkDrawIsRefused) {
  const auto soup = bench::make_soup(60000, 30.0, 512, 11);
  const std::span<const glm::vec4> positions(soup.positions);
  const uint32_t nv = uint32_t(soup.positions.size());
  for (int threads : {0, 2, 7}) {
    Renderer r(threads);
    for (size_t at : {size_t(0), soup.indices.size() / 2 + 1, soup.indices.size() - 1}) {
      for (uint32_t bad : {nv, ~0u}) {
        std::vector<uint32_t> indices = soup.indices;
        indices[at] = bad;
        DepthTarget d(512, 512, DepthFormat::d32f);
        try {
          r.draw(RenderTargets{&d}, DrawState{}, ClipSpaceDepthShader{}, positions, indices);
          ADD_FAILURE() << "index " << bad << " at " << at << " drew, threads " << threads;
        } catch (const DrawError& e) {
          const std::string expected = "index " + std::to_string(bad) + " at position " + std::to_string(at) + " ";
          EXPECT_EQ(std::string(e.what()).rfind(expected, 0), 0u) << e.what();
        }
      }
    }
    DepthTarget d(512, 512, DepthFormat::d32f);
    EXPECT_NO_THROW(r.draw(RenderTargets{&d}, DrawState{}, ClipSpaceDepthShader{}, positions, soup.indices));
  }
}

// The same soup, drawn at 0, 1, 2, 7 and 16 threads (so in 4 to 64 front-end chunks), gives bit-identical depth in every format.
TEST(State, BitIdenticalAcrossThreadCounts) {
  auto soup = bench::make_soup(60000, 30.0, 512, 11);
  auto big = bench::make_soup(300, 5000.0, 512, 12);
  soup.positions.insert(soup.positions.end(), big.positions.begin(), big.positions.end());
  for (uint32_t i : big.indices) soup.indices.push_back(i + uint32_t(soup.positions.size() - big.positions.size()));
  for (DepthFormat fmt : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f}) {
    uint64_t first = 0;
    for (int threads : {0, 1, 2, 7, 16}) {
      Renderer r(threads);
      DepthTarget d(512, 512, fmt);
      DrawState s;
      s.polygon_offset = {1.0f, 2.0f};
      r.draw(RenderTargets{&d}, s, ClipSpaceDepthShader{}, std::span<const glm::vec4>(soup.positions), soup.indices);
      const uint64_t h = rtest::hash_depth(d);
      if (threads == 0) first = h;
      EXPECT_EQ(h, first) << to_string(fmt) << " threads " << threads;
    }
  }
}
