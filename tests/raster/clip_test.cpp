// Clipping: triangles crossing near, far and w = 0, lying behind the eye, or with huge coordinates; order is kept.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "tests/raster/raster_test_util.h"
#include "tests/support.h"

using namespace raster;

namespace {
// Renders into a d32f target and returns the covered mask.
std::vector<uint8_t> draw_mask(Renderer& r, int W, int H, const std::vector<glm::vec4>& v, DrawState s = {},
                               DrawStats* stats = nullptr) {
  DepthTarget d(W, H, DepthFormat::d32f);
  auto st = r.draw(RenderTargets{&d}, s, ClipSpaceDepthShader{}, std::span<const glm::vec4>(v));
  if (stats) *stats = st;
  std::vector<uint8_t> m(size_t(W) * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) m[size_t(y) * W + x] = d.value(x, y) < 1.0f;
  return m;
}
size_t count(const std::vector<uint8_t>& m) { return size_t(std::count(m.begin(), m.end(), 1)); }
}  // namespace

TEST(Clip, TriangleBehindTheEyeDrawsNothing) {
  Renderer r(testsupport::test_threads());
  DrawStats st;
  auto m = draw_mask(r, 64, 64, {{-1, -1, 0, -1}, {1, -1, 0, -1}, {0, 1, 0, -1}}, {}, &st);
  EXPECT_EQ(count(m), 0u);
  EXPECT_EQ(st.rejected, 1u);
}

// A triangle crossing w = 0 (one vertex behind the eye) under a perspective projection: the visible part is
// exactly the pixels whose view ray hits the triangle in front of the near plane. Compare with a ray cast.
TEST(Clip, CrossingNearAndWZeroMatchesRayCast) {
  Renderer r(testsupport::test_threads());
  const int W = 96, H = 64;
  const glm::mat4 proj = glm::perspective(glm::radians(60.0f), float(W) / H, 0.5f, 50.0f);
  // Eye-space triangle: two vertices in front, one behind the eye (z > 0).
  const glm::vec3 e[3] = {{-3, -1, -6}, {3, -1.5f, -5}, {0.5f, 1, 4}};
  std::vector<glm::vec4> v;
  for (auto p : e) v.push_back(proj * glm::vec4(p, 1));
  DrawStats st;
  auto m = draw_mask(r, W, H, v, {}, &st);
  EXPECT_EQ(st.clipped, 1u);
  // Ray cast every pixel centre through the triangle.
  const glm::mat4 inv = glm::inverse(proj);
  size_t differ = 0, hits = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const glm::vec4 nd((x + 0.5f) / W * 2 - 1, (y + 0.5f) / H * 2 - 1, -1, 1);
      glm::vec4 pe = inv * nd;
      const glm::vec3 dir = glm::normalize(glm::vec3(pe) / pe.w);
      const glm::vec3 n = glm::cross(e[1] - e[0], e[2] - e[0]);
      const float t = glm::dot(e[0], n) / glm::dot(dir, n);
      const glm::vec3 p = dir * t;
      bool inside = t > 0 && p.z <= -0.5f && p.z >= -50.0f;
      for (int k = 0; k < 3 && inside; ++k)
        inside = glm::dot(glm::cross(e[(k + 1) % 3] - e[k], p - e[k]), n) >= 0;
      hits += inside;
      differ += inside != bool(m[size_t(y) * W + x]);
    }
  EXPECT_GT(hits, 500u);
  // Only pixels whose centre lies within float rounding of an edge may differ.
  EXPECT_LE(differ, 3u) << "of " << hits;
}

TEST(Clip, FarPlaneCutsUnlessDepthClamp) {
  Renderer r(0);
  const int W = 32, H = 32;
  // A full-screen quad tilted in depth: z_ndc from -0.5 at the left to 1.5 at the right; x_ndc = 0.5 is the far cut.
  std::vector<glm::vec4> v = {{-1, -1, -0.5f, 1}, {1, -1, 1.5f, 1}, {1, 1, 1.5f, 1},
                              {-1, -1, -0.5f, 1}, {1, 1, 1.5f, 1}, {-1, 1, -0.5f, 1}};
  auto m = draw_mask(r, W, H, v);
  for (int x = 0; x < W; ++x) {
    const double ndc = (x + 0.5) / W * 2 - 1;
    EXPECT_EQ(m[size_t(5) * W + x], ndc < 0.5 ? 1 : 0) << x;
  }
  DrawState s;
  s.depth_clamp = true;
  DepthTarget d(W, H, DepthFormat::d32f);
  d.clear(1.0f);
  s.depth_func = DepthFunc::lequal;
  r.draw(RenderTargets{&d}, s, ClipSpaceDepthShader{}, std::span<const glm::vec4>(v));
  for (int x = 0; x < W; ++x) {
    const double z = std::clamp(((x + 0.5) / W * 2 - 1) * 1.0 + 0.5, -1.0, 1.0) * 0.5 + 0.5;  // z_ndc = x_ndc + 0.5
    EXPECT_NEAR(d.value(x, 5), std::clamp(z, 0.0, 1.0), 1e-6) << x;
  }
}

// Coordinates far beyond the fixed-point range are clipped to the view frustum in x and y (as llvmpipe does).
TEST(Clip, HugeCoordinatesAreClippedToTheFrustum) {
  Renderer r(testsupport::test_threads());
  // A triangle far larger than the fixed-point range that still covers the whole viewport.
  const int W = 80, H = 60;
  std::vector<glm::vec4> v = {{-1e6f, -1e6f, 0, 1}, {1e6f, -1e6f, 0, 1}, {0, 1e6f, 0, 1}};
  DrawStats st;
  auto m = draw_mask(r, W, H, v, {}, &st);
  EXPECT_EQ(count(m), size_t(W) * H);
  EXPECT_EQ(st.clipped, 1u);
  // And one whose edge passes through the viewport: the half-plane x_ndc > 0.25 (edge from far below to far above).
  std::vector<glm::vec4> h = {{0.25f, -1e7f, 0, 1}, {1e7f, 0, 0, 1}, {0.25f, 1e7f, 0, 1}};
  m = draw_mask(r, W, H, h);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const double xw = (x + 0.5);
      const double edge = (0.25 + 1) / 2 * W;  // 50
      ASSERT_EQ(m[size_t(y) * W + x], xw >= edge ? 1 : 0) << x << "," << y;
    }
}

TEST(Clip, NonFiniteVerticesAreDropped) {
  Renderer r(0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  DrawStats st;
  auto m = draw_mask(r, 16, 16, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {nan, 1, 0, 1}}, {}, &st);
  EXPECT_EQ(count(m), 0u);
  EXPECT_EQ(st.rejected, 1u);
}

// Clipping replaces a triangle by a fan in place: with depth test ALWAYS the later triangle wins everywhere.
TEST(Clip, PrimitiveOrderIsKept) {
  Renderer r(testsupport::test_threads());
  const int W = 64, H = 64;
  // First: a clipped triangle at z = 0.25 (crosses near), second: an unclipped quad at z = 0.75 over it.
  std::vector<glm::vec4> v = {{-1, -1, -3, 1}, {3, -1, 0.5f, 1}, {-1, 3, 0.5f, 1},
                              {-1, -1, 0.5f, 1}, {1, -1, 0.5f, 1}, {1, 1, 0.5f, 1}};
  DepthTarget d(W, H, DepthFormat::d32f);
  DrawState s;
  s.depth_func = DepthFunc::always;
  r.draw(RenderTargets{&d}, s, ClipSpaceDepthShader{}, std::span<const glm::vec4>(v));
  // Pixels covered by the second triangle hold its depth 0.75 whatever the first wrote.
  EXPECT_EQ(d.value(60, 10), 0.75f);
  EXPECT_EQ(d.value(40, 20), 0.75f);
}
