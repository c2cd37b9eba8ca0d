// Conformance against a real GL: the same clip-space triangles rendered by Mesa llvmpipe (raster/reference/) and
// by shadowlab must cover exactly the same pixels, with the same depth: setup.cpp and clip.h reproduce llvmpipe's
// float arithmetic (depth plane, polygon offset, clipping), see tolerance() for what is measured.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "bench/triangle_soup.h"
#include "raster/renderer.h"
#include "scenes/gltf_import.h"
#include "scenes/scene_queries.h"
#include "tests/raster/raster_test_util.h"
#include "tests/raster/reference/gl_test_support.h"

using namespace raster;

namespace {

struct Comparison {
  size_t covered_gl = 0, covered_sl = 0;
  size_t coverage_mismatch = 0;  // covered by one and not the other
  double max_depth_diff = 0;     // in codes for d16/d24, in depth for d32f
};

struct Draw {
  int width = 128, height = 96;
  DepthFormat format = DepthFormat::d32f;
  DrawState state;
  std::vector<glm::vec4> positions;
  std::vector<uint32_t> indices;
};

class Conformance : public testing::Test {
 protected:
  static void SetUpTestSuite() { gl_ = glref::Context::create(testsupport::glref_threads(), &why_).release(); }
  static void TearDownTestSuite() { delete gl_, gl_ = nullptr; }
  void SetUp() override {
    if (!gl_) GTEST_SKIP() << "skipped: " << why_;
  }

  Comparison compare(const Draw& d) {
    glref::Context::DepthDraw g;
    g.width = d.width, g.height = d.height, g.format = d.format;
    g.viewport = d.state.viewport, g.scissor = d.state.scissor;
    g.cull = d.state.cull, g.front_face = d.state.front_face, g.depth_func = d.state.depth_func;
    g.polygon_offset = d.state.polygon_offset, g.depth_clamp = d.state.depth_clamp;
    g.clip_positions = d.positions, g.indices = d.indices;
    const std::vector<uint32_t> ref = gl_->render_depth(g);

    Renderer r(testsupport::test_threads());
    DepthTarget t(d.width, d.height, d.format);
    r.draw(RenderTargets{&t}, d.state, ClipSpaceDepthShader{}, std::span<const glm::vec4>(d.positions), d.indices);

    const uint32_t clear = d.format == DepthFormat::d32f ? 0x3F800000u : depth_max_code(d.format);
    Comparison c;
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x < d.width; ++x) {
        const uint32_t a = ref[size_t(y) * d.width + x], b = t.raw(x, y);
        const bool ca = a != clear, cb = b != clear;
        c.covered_gl += ca, c.covered_sl += cb;
        if (ca != cb) {
          ++c.coverage_mismatch;
          continue;
        }
        const double diff = d.format == DepthFormat::d32f
                                ? std::abs(double(std::bit_cast<float>(a)) - double(std::bit_cast<float>(b)))
                                : std::abs(double(a) - double(b));
        c.max_depth_diff = std::max(c.max_depth_diff, diff);
      }
    return c;
  }

  // Depth tolerance: the issue allows 1 code (d16), 2 codes (d24) and 2e-6 (d32f); we ask for bit-identical
  // depth. setup.cpp computes the depth plane and polygon offset in llvmpipe's own float operation order, clip.h
  // clips as llvmpipe's draw module does (frustum planes, its interpolation, its fan order), so depth matches
  // exactly on unclipped and clipped triangles alike (measured: 0 codes and 0.0 in every case here).
  enum class Kind { plain, clipped, asset };
  static double tolerance(DepthFormat, Kind) { return 0.0; }

  static void expect_conformant(const Comparison& c, DepthFormat f, const std::string& what, Kind k = Kind::plain) {
    EXPECT_GT(c.covered_gl, 0u) << what;
    EXPECT_EQ(c.coverage_mismatch, 0u) << what << ": pixels covered by one renderer only (llvmpipe covers "
                                       << c.covered_gl << ", shadowlab " << c.covered_sl << ")";
    EXPECT_LE(c.max_depth_diff, tolerance(f, k)) << what << " (" << to_string(f) << ")";
  }

  static glref::Context* gl_;
  static std::string why_;
};

glref::Context* Conformance::gl_ = nullptr;
std::string Conformance::why_;

// Random triangles in clip space with random w (perspective), random orientation, sizes from slivers to
// larger than the target.
std::vector<glm::vec4> random_clip_soup(size_t n, double max_size, uint32_t seed, bool clipping = false,
                                        bool inside_viewport = true) {
  std::mt19937 rng(seed);
  const double reach = inside_viewport ? 0.9 : 1.1;
  std::uniform_real_distribution<double> u(-reach, reach), s(-1, 1), wz(0.5, 3.0), z(-0.9, 0.9);
  std::vector<glm::vec4> v;
  for (size_t i = 0; i < n; ++i) {
    double size = std::pow(max_size, std::uniform_real_distribution<double>(0, 1)(rng)) / 64.0;
    const double cx = u(rng), cy = u(rng), cz = z(rng);
    // Keep every vertex inside the viewport when asked (see ViewportEdgeCrossings for the others).
    if (inside_viewport) size = std::min(size, 0.999 - std::max(std::abs(cx), std::abs(cy)));
    for (int k = 0; k < 3; ++k) {
      const double w = wz(rng);
      double zz = cz + s(rng) * 0.05;
      if (clipping && k == 0 && i % 3 == 0) zz = (i % 2 ? -1.6 : 1.6);   // crosses near or far
      if (clipping && k == 1 && i % 7 == 0) {                            // behind the eye: w < 0
        v.emplace_back(float((cx + s(rng) * size) * -0.5), float((cy + s(rng) * size) * -0.5), float(zz * -0.5), -0.5f);
        continue;
      }
      v.emplace_back(float((cx + s(rng) * size) * w), float((cy + s(rng) * size) * w), float(zz * w), float(w));
    }
  }
  return v;
}

}  // namespace

TEST_F(Conformance, RandomSoupsEveryFormat) {
  for (DepthFormat f : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f}) {
    for (double max_size : {4.0, 64.0, 4000.0}) {
      Draw d;
      d.format = f;
      d.positions = random_clip_soup(400, max_size, 17 + uint32_t(max_size));
      expect_conformant(compare(d), f, "soup up to " + std::to_string(max_size) + " px");
    }
  }
}

TEST_F(Conformance, GridOnPixelCentres) {
  const int W = 150, H = 100, N = 10;
  Draw d;
  d.width = W, d.height = H;
  for (int gy = 0; gy <= N; ++gy)
    for (int gx = 0; gx <= N; ++gx)
      d.positions.push_back(rtest::win_to_clip(std::floor(gx * (W - 1.0) / N) + 0.5, std::floor(gy * (H - 1.0) / N) + 0.5,
                                               W, H, 0.3 * std::sin(gx + gy)));
  for (int gy = 0; gy < N; ++gy)
    for (int gx = 0; gx < N; ++gx) {
      const uint32_t a = gy * (N + 1) + gx, b = a + 1, c = a + N + 1, e = c + 1;
      d.indices.insert(d.indices.end(), {a, b, e, a, e, c});
    }
  for (DepthFormat f : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f}) {
    d.format = f;
    expect_conformant(compare(d), f, "grid");
  }
}

TEST_F(Conformance, CullModesAndFrontFaces) {
  for (CullMode cm : {CullMode::none, CullMode::back, CullMode::front})
    for (FrontFace ff : {FrontFace::ccw, FrontFace::cw}) {
      Draw d;
      d.state.cull = cm, d.state.front_face = ff;
      d.positions = random_clip_soup(300, 200.0, 5);
      expect_conformant(compare(d), d.format, "cull " + std::to_string(int(cm)) + " front " + std::to_string(int(ff)));
    }
}

TEST_F(Conformance, PolygonOffset) {
  for (DepthFormat f : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f})
    for (PolygonOffset o : {PolygonOffset{1.0f, 1.0f}, PolygonOffset{2.5f, 4.0f}, PolygonOffset{-1.0f, -2.0f}}) {
      Draw d;
      d.format = f;
      d.state.polygon_offset = o;
      d.positions = random_clip_soup(300, 300.0, 9);
      expect_conformant(compare(d), f, "offset " + std::to_string(o.factor) + "," + std::to_string(o.units));
    }
}

TEST_F(Conformance, TrianglesNeedingClipping) {
  for (bool clamp : {false, true}) {
    Draw d;
    d.state.depth_clamp = clamp;
    d.positions = random_clip_soup(300, 3000.0, 23, true);
    expect_conformant(compare(d), d.format, clamp ? "clipping with depth clamp" : "clipping", Kind::clipped);
  }
}

// Triangles reaching past the viewport edges (and, some, past near or far or behind the eye), one per draw so
// that a difference is not hidden under another triangle: llvmpipe clips them to the view frustum in x and y
// (no guard band), and the pixels they cover must be exactly the same.
TEST_F(Conformance, ViewportEdgeCrossingsOneAtATime) {
  for (DepthFormat f : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f})
    for (bool clamp : {false, true}) {
      const std::vector<glm::vec4> soup =
          random_clip_soup(40, 3000.0, 41 + uint32_t(f) + (clamp ? 7u : 0u), /*clipping=*/true, /*inside_viewport=*/false);
      size_t drawn = 0;
      for (size_t i = 0; i + 3 <= soup.size(); i += 3) {
        Draw d;
        d.format = f;
        d.state.depth_clamp = clamp;
        d.positions.assign(soup.begin() + ptrdiff_t(i), soup.begin() + ptrdiff_t(i + 3));
        const Comparison c = compare(d);
        if (c.covered_gl == 0 && c.covered_sl == 0) continue;
        ++drawn;
        const std::string what = "triangle " + std::to_string(i / 3) + (clamp ? " with depth clamp" : "");
        EXPECT_EQ(c.coverage_mismatch, 0u) << what << ": llvmpipe covers " << c.covered_gl << ", shadowlab "
                                           << c.covered_sl;
        EXPECT_LE(c.max_depth_diff, tolerance(f, Kind::clipped)) << what << " (" << to_string(f) << ")";
      }
      EXPECT_GT(drawn, 10u);
    }
}

TEST_F(Conformance, ViewportAndScissor) {
  Draw d;
  d.state.viewport = Rect{10, 5, 90, 70};
  d.state.scissor = Rect{20, 12, 60, 40};
  d.positions = random_clip_soup(300, 500.0, 31);
  expect_conformant(compare(d), d.format, "viewport and scissor");
}

// Real meshes seen through light matrices: the vertex transform happens here in float, once, and both
// renderers get the same clip-space positions, so coverage must still match exactly.
TEST_F(Conformance, AssetMeshesThroughLightMatrices) {
  SHADOWLAB_REQUIRE_ASSETS();
  for (const char* file : {"suzanne/Suzanne.gltf", "duck/Duck.gltf", "kenney_tree/tree.glb"}) {
    const scenes::Scene scene = scenes::import_gltf(testsupport::assets_dir() / file);
    const scenes::TriangleSoup soup = scenes::flatten(scene);
    const scenes::Aabb box = scenes::scene_bounds(scene);
    const glm::vec3 c = (box.min + box.max) * 0.5f;
    const float r = glm::length(box.max - box.min) * 0.5f;
    for (glm::vec3 dir : {glm::vec3(0.5f, 2, 2), glm::vec3(-1, 0.3f, 0.2f), glm::vec3(0.1f, -1, 0.7f)}) {
      const glm::vec3 eye = c + glm::normalize(dir) * r * 2.0f;
      const glm::mat4 view = glm::lookAt(eye, c, glm::vec3(0, 1, 0.01f));
      for (bool persp : {false, true}) {
        const glm::mat4 proj = persp ? glm::perspective(glm::radians(50.0f), 1.0f, r * 0.5f, r * 4.0f)
                                     : glm::ortho(-r, r, -r, r, r * 0.5f, r * 4.0f);
        Draw d;
        d.width = d.height = 256;
        for (const glm::vec3& p : soup.positions) d.positions.push_back(proj * view * glm::vec4(p, 1));
        d.indices = soup.indices;
        expect_conformant(compare(d), d.format, std::string(file) + (persp ? " perspective" : " ortho"), Kind::asset);
      }
    }
  }
}
