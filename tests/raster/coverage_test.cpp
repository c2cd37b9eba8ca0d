// Coverage: watertight meshes (every pixel exactly once), the tie rule on constructed edges, and random
// triangles of every size against the brute-force reference of raster_test_util.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "tests/raster/raster_test_util.h"
#include "tests/support.h"

using namespace raster;
using rtest::win_to_clip;

TEST(Coverage, FullScreenQuadCoversEveryPixelOnce) {
  Renderer r(testsupport::test_threads());
  std::vector<glm::vec4> v = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1}, {-1, 1, 0, 1}};
  std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};
  const auto counts = rtest::count_coverage(r, 37, 23, v, idx);
  for (uint32_t c : counts) ASSERT_EQ(c, 1u);
}

// A grid mesh whose vertices lie exactly on pixel centres (the hardest case for the tie rule), split into
// triangles along alternating diagonals, plus a jittered grid: every pixel inside is covered exactly once.
TEST(Coverage, WatertightGridOnPixelCentres) {
  Renderer r(testsupport::test_threads());
  const int W = 97, H = 71, N = 12;
  for (int jitter = 0; jitter < 2; ++jitter) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> j(-100, 100);
    std::vector<glm::vec4> v;
    std::vector<uint32_t> idx;
    for (int gy = 0; gy <= N; ++gy)
      for (int gx = 0; gx <= N; ++gx) {
        double x = 0.5 + gx * (W - 1) / double(N), y = 0.5 + gy * (H - 1) / double(N);
        if (jitter && gx > 0 && gx < N && gy > 0 && gy < N) x += j(rng) / 64.0, y += j(rng) / 64.0;
        if (!jitter) x = std::floor(x) + 0.5, y = std::floor(y) + 0.5;  // exactly on centres
        v.push_back(win_to_clip(x, y, W, H));
      }
    for (int gy = 0; gy < N; ++gy)
      for (int gx = 0; gx < N; ++gx) {
        const uint32_t a = gy * (N + 1) + gx, b = a + 1, c = a + N + 1, d = c + 1;
        if ((gx + gy) % 2) idx.insert(idx.end(), {a, b, d, a, d, c});
        else idx.insert(idx.end(), {a, b, c, b, d, c});
      }
    const auto counts = rtest::count_coverage(r, W, H, v, idx);
    // The mesh spans centres 0.5 .. W−0.5: the outer boundary is inclusive on the left and bottom and
    // exclusive on the right and top, so the last column and row are left out.
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const uint32_t expected = (x < W - 1 && y < H - 1) ? 1u : 0u;
        ASSERT_EQ(counts[size_t(y) * W + x], expected) << "pixel " << x << "," << y << " jitter " << jitter;
      }
  }
}

// The tie rule of CONVENTIONS on axis-aligned and diagonal edges through pixel centres.
TEST(Coverage, TieRuleOnConstructedEdges) {
  Renderer r(0);
  const int W = 16, H = 16;
  // Rectangle with edges through centres: x from 2.5 to 6.5, y from 3.5 to 8.5.
  std::vector<glm::vec4> v = {win_to_clip(2.5, 3.5, W, H), win_to_clip(6.5, 3.5, W, H), win_to_clip(6.5, 8.5, W, H),
                              win_to_clip(2.5, 8.5, W, H)};
  for (FrontFace ff : {FrontFace::ccw, FrontFace::cw}) {
    for (bool reversed : {false, true}) {
      std::vector<uint32_t> idx = reversed ? std::vector<uint32_t>{0, 2, 1, 0, 3, 2} : std::vector<uint32_t>{0, 1, 2, 0, 2, 3};
      DrawState s;
      s.front_face = ff;
      const auto counts = rtest::count_coverage(r, W, H, v, idx, s);
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
          // Left edge x = 2.5 inclusive, right edge x = 6.5 exclusive; bottom y = 3.5 inclusive, top exclusive.
          const bool in = x >= 2 && x <= 5 && y >= 3 && y <= 7;
          ASSERT_EQ(counts[size_t(y) * W + x], in ? 1u : 0u) << x << "," << y;
        }
    }
  }
  // A diagonal through centres: for the triangle below-right of the line y = x the interior lies to the right
  // of the diagonal, so it is a left edge and owns the centres on it; for the upper-left triangle it is a right
  // edge and owns none of them.
  std::vector<glm::vec4> t = {win_to_clip(0.5, 0.5, W, H), win_to_clip(12.5, 0.5, W, H), win_to_clip(12.5, 12.5, W, H)};
  const auto counts = rtest::count_coverage(r, W, H, t, {0, 1, 2});
  EXPECT_EQ(counts[size_t(5) * W + 5], 1u) << "centre on the rising diagonal of the lower-right triangle";
  std::vector<glm::vec4> u = {win_to_clip(0.5, 0.5, W, H), win_to_clip(12.5, 12.5, W, H), win_to_clip(0.5, 12.5, W, H)};
  const auto counts2 = rtest::count_coverage(r, W, H, u, {0, 1, 2});
  EXPECT_EQ(counts2[size_t(5) * W + 5], 0u) << "the same centre is not in the upper-left triangle";
}

// Random triangles from sub-pixel slivers to the size of the target, compared pixel by pixel with the reference.
// Vertices stay inside the viewport: triangles that leave it are clipped to the view frustum first, as llvmpipe
// does, which the reference does not model (the conformance tests cover them against llvmpipe itself).
TEST(Coverage, RandomTrianglesMatchReference) {
  Renderer r(testsupport::test_threads());
  const int W = 150, H = 110;
  std::mt19937 rng(42);
  for (int iter = 0; iter < 300; ++iter) {
    const double scale = std::pow(10.0, std::uniform_real_distribution<double>(-0.5, 3.0)(rng));
    std::uniform_real_distribution<double> cx(-20, W + 20), cy(-20, H + 20), off(-scale, scale);
    const double x = cx(rng), y = cy(rng);
    glm::vec4 c[3];
    auto inside_x = [&](double v) { return std::clamp(v, 0.0, double(W)); };
    auto inside_y = [&](double v) { return std::clamp(v, 0.0, double(H)); };
    for (auto& p : c) {
      p = win_to_clip(inside_x(x + off(rng)), inside_y(y + off(rng)), W, H, 0.0, std::uniform_real_distribution<double>(0.5, 4)(rng));
      if (iter % 5 == 0)
        p = win_to_clip(inside_x(std::round((x + off(rng)) * 2) / 2), inside_y(std::round((y + off(rng)) * 2) / 2), W, H);
    }
    const auto expected = rtest::reference_coverage(c, W, H);
    const auto counts = rtest::count_coverage(r, W, H, {c[0], c[1], c[2]}, {0, 1, 2});
    for (size_t i = 0; i < counts.size(); ++i)
      ASSERT_EQ(counts[i], expected[i]) << "triangle " << iter << " pixel " << i % W << "," << i / W;
  }
}

// The depth-only path (narrow rows and blocks) covers exactly what the shaded path covers.
TEST(Coverage, DepthOnlyPathMatchesReference) {
  Renderer r(testsupport::test_threads());
  const int W = 200, H = 130;
  std::mt19937 rng(3);
  for (int iter = 0; iter < 200; ++iter) {
    const double scale = std::pow(10.0, std::uniform_real_distribution<double>(-0.3, 2.5)(rng));
    std::uniform_real_distribution<double> cx(0, W), cy(0, H), off(-scale, scale);
    const double x = cx(rng), y = cy(rng);
    glm::vec4 c[3];
    for (auto& p : c) p = win_to_clip(std::clamp(x + off(rng), 0.0, double(W)), std::clamp(y + off(rng), 0.0, double(H)), W, H, -0.5);
    DepthTarget d(W, H, DepthFormat::d32f);
    r.draw(RenderTargets{&d}, DrawState{}, ClipSpaceDepthShader{}, std::span<const glm::vec4>(c, 3));
    const auto expected = rtest::reference_coverage(c, W, H);
    for (int j = 0; j < H; ++j)
      for (int i = 0; i < W; ++i)
        ASSERT_EQ(d.value(i, j) < 1.0f, expected[size_t(j) * W + i] != 0) << "triangle " << iter << " pixel " << i << "," << j;
  }
}

// From inside a closed, tessellated box every view ray leaves through exactly one face: with no culling each
// pixel is covered exactly once, through perspective, near-plane clipping of the faces beside and behind the
// eye, and frustum clipping of the faces that leave the viewport.
TEST(Coverage, WatertightFromInsideAClosedBox) {
  Renderer r(testsupport::test_threads());
  const int W = 160, H = 90;
  const glm::mat4 proj = glm::perspective(glm::radians(75.0f), float(W) / H, 0.05f, 100.0f);
  std::vector<glm::vec3> pts;
  std::vector<uint32_t> idx;
  const int N = 5;  // each face is an N×N grid of quads
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2) {
      const uint32_t base = uint32_t(pts.size());
      for (int j = 0; j <= N; ++j)
        for (int i = 0; i <= N; ++i) {
          glm::vec3 p;
          p[axis] = float(side);
          p[(axis + 1) % 3] = -1.0f + 2.0f * i / N;
          p[(axis + 2) % 3] = -1.0f + 2.0f * j / N;
          pts.push_back(p * glm::vec3(3.0f, 2.0f, 4.0f));
        }
      for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
          const uint32_t a = base + j * (N + 1) + i, b = a + 1, c = a + N + 1, d = c + 1;
          idx.insert(idx.end(), {a, b, d, a, d, c});
        }
    }
  for (glm::vec3 eye : {glm::vec3(0.3f, 0.2f, 0.1f), glm::vec3(-2.5f, 1.5f, 3.0f), glm::vec3(1.0f, -1.0f, -2.0f)})
    for (glm::vec3 target : {glm::vec3(1, 0.3f, -2), glm::vec3(-1, -1, 1), glm::vec3(0.2f, 5, 0.1f)}) {
      const glm::mat4 vp = proj * glm::lookAt(eye, eye + target, glm::vec3(0, 1, 0.01f));
      std::vector<glm::vec4> clip;
      for (const glm::vec3& p : pts) clip.push_back(vp * glm::vec4(p, 1.0f));
      const auto counts = rtest::count_coverage(r, W, H, clip, idx);
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
          ASSERT_EQ(counts[size_t(y) * W + x], 1u) << "pixel " << x << "," << y << " eye " << eye.x << " target "
                                                    << target.x << "," << target.y;
    }
}
