// Tests of the llvmpipe reference's context and depth draws: that it really is llvmpipe with the asked thread
// count, that depth codes come back exact, and what llvmpipe does on the cases CONVENTIONS pins down (the
// tie rule on edges through pixel centres, polygon offset's r). Skipped with the reason when EGL is missing.
#include <algorithm>
#include <bit>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/raster/reference/gl_test_support.h"

namespace {

using glref::Context;
using raster::DepthFormat;

// Clip-space vertex at window position (x, y) of a size×size target, z = 0 (window depth 0.5).
glm::vec4 at_window(float x, float y, float size) { return {x / size * 2.0f - 1.0f, y / size * 2.0f - 1.0f, 0.0f, 1.0f}; }

// The coverage of a draw into a 4×4 d16 target as text, top row first: '#' written, '.' untouched.
std::string coverage4x4(Context& gl, const std::vector<glm::vec4>& positions) {
  Context::DepthDraw d;
  d.width = d.height = 4;
  d.format = DepthFormat::d16;
  d.clip_positions = positions;
  const std::vector<uint32_t> z = gl.render_depth(d);
  std::string s;
  for (int y = 3; y >= 0; --y) {
    for (int x = 0; x < 4; ++x) s += z[size_t(y * 4 + x)] == 32768 ? '#' : z[size_t(y * 4 + x)] == 65535 ? '.' : '?';
    s += y ? "/" : "";
  }
  return s;
}

std::vector<glm::vec4> full_quad(float z) {
  return {{-1, -1, z, 1}, {1, -1, z, 1}, {1, 1, z, 1}, {-1, -1, z, 1}, {1, 1, z, 1}, {-1, 1, z, 1}};
}

TEST(GlReference, RendererIsLlvmpipe) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  EXPECT_NE(gl->renderer().find("llvmpipe"), std::string::npos) << gl->renderer();
  EXPECT_NE(gl->version().find("Core Profile"), std::string::npos) << gl->version();
}

TEST(GlReference, ThreadCountReachesLlvmpipe) {
  for (int threads : {0, 3, 1}) {
    GLREF_CONTEXT_OR_SKIP(gl, threads);
    EXPECT_EQ(testsupport::llvmpipe_thread_count_settled(threads), threads);
  }
  EXPECT_EQ(testsupport::llvmpipe_thread_count_settled(0), 0) << "destroying the Context stops llvmpipe's threads";
}

TEST(GlReference, SecondLiveContextIsAnError) {
  GLREF_CONTEXT_OR_SKIP(gl, 1);
  std::string why;
  EXPECT_THROW(Context::create(1, &why), std::runtime_error);
}

TEST(GlReference, ConstantDepthHalfGivesExactCodes) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  const std::vector<glm::vec4> quad = full_quad(0.0f);
  for (auto [format, expect] : {std::pair{DepthFormat::d16, 32768u}, std::pair{DepthFormat::d24, 8388608u},
                                std::pair{DepthFormat::d32f, std::bit_cast<uint32_t>(0.5f)}}) {
    Context::DepthDraw d;
    d.width = 13;
    d.height = 7;
    d.format = format;
    d.clip_positions = quad;
    const std::vector<uint32_t> z = gl->render_depth(d);
    ASSERT_EQ(z.size(), 13u * 7u);
    for (size_t i = 0; i < z.size(); ++i) ASSERT_EQ(z[i], expect) << raster::to_string(format) << " pixel " << i;
  }
}

TEST(GlReference, ViewportScissorAndClearValues) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  const std::vector<glm::vec4> quad = full_quad(0.0f);
  for (auto [format, cleared] : {std::pair{DepthFormat::d16, 65535u}, std::pair{DepthFormat::d24, 16777215u},
                                 std::pair{DepthFormat::d32f, std::bit_cast<uint32_t>(1.0f)}}) {
    Context::DepthDraw d;
    d.width = d.height = 8;
    d.format = format;
    d.clip_positions = quad;
    d.viewport = raster::Rect{1, 2, 5, 4};  // x 1..5, y 2..5
    d.scissor = raster::Rect{0, 0, 4, 8};   // x 0..3
    const std::vector<uint32_t> z = gl->render_depth(d);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) {
        const bool inside = x >= 1 && x <= 3 && y >= 2 && y <= 5;
        EXPECT_EQ(z[size_t(y * 8 + x)] != cleared, inside) << raster::to_string(format) << " " << x << "," << y;
      }
  }
}

// What llvmpipe does with pixel centres exactly on an edge, rendering into an FBO (window y up). Observed:
//  - lower-left half (0,0)(4,0)(0,4): the diagonal runs through the centres with i + j = 3; they are NOT
//    covered (the interior lies to the diagonal's left, so it is a right edge). Both windings alike.
//  - the upper-right half (4,4)(0,4)(4,0): the same centres ARE covered (there the diagonal is a left edge).
//  - a triangle with its legs on the centre lines x = 0.5 and y = 0.5: the left edge (x = 0.5) and the bottom
//    edge (y = 0.5, interior above) are covered; its mirror with legs on x = 3.5 and y = 3.5 covers neither
//    the right edge nor the top edge (interior below).
//  - the square [1.5, 2.5]² covers exactly pixel (1, 1).
// That is CONVENTIONS' rule: a centre on an edge is inside when the edge is a left edge, or a horizontal edge
// with the interior above it.
TEST(GlReference, TieRuleOnEdgesThroughPixelCentres) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  auto w = [](float x, float y) { return at_window(x, y, 4.0f); };
  const std::string lower_left = "..../#.../##../###.";
  EXPECT_EQ(coverage4x4(*gl, {w(0, 0), w(4, 0), w(0, 4)}), lower_left);
  EXPECT_EQ(coverage4x4(*gl, {w(0, 0), w(0, 4), w(4, 0)}), lower_left);
  EXPECT_EQ(coverage4x4(*gl, {w(4, 4), w(0, 4), w(4, 0)}), "####/.###/..##/...#");
  EXPECT_EQ(coverage4x4(*gl, {w(4, 4), w(4, 0), w(0, 4)}), "####/.###/..##/...#");
  EXPECT_EQ(coverage4x4(*gl, {w(0.5f, 0.5f), w(3.5f, 0.5f), w(0.5f, 3.5f)}), lower_left);
  EXPECT_EQ(coverage4x4(*gl, {w(0.5f, 0.5f), w(0.5f, 3.5f), w(3.5f, 0.5f)}), lower_left);
  EXPECT_EQ(coverage4x4(*gl, {w(3.5f, 3.5f), w(0.5f, 3.5f), w(3.5f, 0.5f)}), "..../.##./..#./....");
  EXPECT_EQ(coverage4x4(*gl, {w(1.5f, 1.5f), w(2.5f, 1.5f), w(2.5f, 2.5f), w(1.5f, 1.5f), w(2.5f, 2.5f),
                              w(1.5f, 2.5f)}),
            "..../..../.#../....");
}

// Upload and readback never lose a code: every d16 and d24 code, and d32f bit patterns, come back unchanged.
TEST(GlReference, DepthEncodingsRoundTripExactly) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  std::vector<uint32_t> all(size_t(4096) * 4096);
  for (size_t i = 0; i < all.size(); ++i) all[i] = uint32_t(i);
  EXPECT_TRUE(gl->roundtrip_depth(DepthFormat::d24, 4096, 4096, all) == all) << "some d24 code changed";
  const std::span<const uint32_t> d16(all.data(), 65536);
  const std::vector<uint32_t> back16 = gl->roundtrip_depth(DepthFormat::d16, 256, 256, d16);
  EXPECT_TRUE(std::equal(back16.begin(), back16.end(), d16.begin())) << "some d16 code changed";
  std::vector<uint32_t> floats;
  for (float f : {0.0f, 1.0f, 0.5f, 0.1f, 1e-30f, 0.99999994f, 0.33333334f, 2.5e-8f})
    floats.push_back(std::bit_cast<uint32_t>(f));
  EXPECT_EQ(gl->roundtrip_depth(DepthFormat::d32f, 8, 1, floats), floats);
}

// Polygon offset units on a constant-depth quad: llvmpipe's r is 2 codes for d16 and d24 and 2^(E - 23) for
// d32f, E the IEEE exponent of the depth (0.5: 2^-24; 0.25: 2^-25). d24 at z = 0.5 (code 8388607.5 rounds
// to 8388608) plus two codes lands on 8388609: its rounding of ties is not to nearest-up everywhere.
TEST(GlReference, PolygonOffsetUnits) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  auto offset_depth = [&](DepthFormat f, float z, float units) {
    const std::vector<glm::vec4> quad = full_quad(z);
    Context::DepthDraw d;
    d.width = d.height = 4;
    d.format = f;
    d.clip_positions = quad;
    d.polygon_offset.units = units;
    return gl->render_depth(d)[5];
  };
  EXPECT_EQ(offset_depth(DepthFormat::d16, 0.2f, 1.0f), 39321u + 2u);
  EXPECT_EQ(offset_depth(DepthFormat::d16, 0.2f, -3.0f), 39321u - 6u);
  EXPECT_EQ(offset_depth(DepthFormat::d24, -0.5f, 1.0f), 4194304u + 2u);
  EXPECT_EQ(offset_depth(DepthFormat::d24, 0.0f, 1.0f), 8388609u);
  EXPECT_EQ(offset_depth(DepthFormat::d32f, 0.0f, 1.0f), std::bit_cast<uint32_t>(0.5f + 0x1p-24f));
  EXPECT_EQ(offset_depth(DepthFormat::d32f, -0.5f, -1.0f), std::bit_cast<uint32_t>(0.25f - 0x1p-25f));
}

TEST(GlReference, TimeDepthReturnsPositiveTimes) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  const std::vector<glm::vec4> positions = {{-1, -1, 0.1f, 1}, {1, -1, 0.2f, 1}, {0, 1, 0.3f, 1}};
  const std::vector<uint32_t> indices = {0, 1, 2};
  Context::DepthDraw d;
  d.width = d.height = 64;
  d.clip_positions = positions;
  d.indices = indices;
  const std::vector<double> ms = gl->time_depth(d, 4);
  ASSERT_EQ(ms.size(), 4u);
  for (double t : ms) EXPECT_GT(t, 0.0);
  for (double t : gl->time_depth_clear(d, 2)) EXPECT_GT(t, 0.0);
}

}  // namespace
