// Tests of the llvmpipe reference's shadow sampling: hand-computed hardware PCF on a 2×2 map, and the exact
// float model of llvmpipe's sampler2DShadow that measurement found, written down here for shading/ to match:
//   u = fl(fl(s·W) − 0.5), i = floor(u), a = u − i (likewise v, j, b from t and H); no weight quantisation.
//   Each of the four texels is compared with ref first; unorm texels become float(code) · float(1/max) and
//   ref is clamped to [0, 1] first (d32f texels compare as stored); denormal refs count as 0.
//   Blend: top = fma(a, c11 − c01, c01), bottom = fma(a, c10 − c00, c00), result = fma(b, top − bottom, bottom).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "tests/raster/reference/gl_test_support.h"

namespace {

using glref::Context;
using raster::DepthFormat;

std::vector<uint32_t> as_bits(std::initializer_list<float> values) {
  std::vector<uint32_t> v;
  for (float f : values) v.push_back(std::bit_cast<uint32_t>(f));
  return v;
}

// The model above for clamp-to-edge LINEAR with compare LEQUAL, over a d32f or unorm map.
float model_pcf(std::span<const uint32_t> texels, int w, int h, DepthFormat f, glm::vec3 c) {
  auto texel_value = [&](int i, int j) {
    const uint32_t raw = texels[size_t(std::clamp(j, 0, h - 1) * w + std::clamp(i, 0, w - 1))];
    if (f == DepthFormat::d32f) return std::bit_cast<float>(raw);
    return float(raw) * float(1.0 / double(raster::depth_max_code(f)));
  };
  const float ref = f == DepthFormat::d32f ? c.z : std::clamp(c.z, 0.0f, 1.0f);
  auto pass = [&](int i, int j) { return ref <= texel_value(i, j) ? 1.0f : 0.0f; };
  const float u = c.x * float(w) - 0.5f, v = c.y * float(h) - 0.5f;
  const float fi = std::floor(u), fj = std::floor(v);
  const float a = u - fi, b = v - fj;
  const int i = int(fi), j = int(fj);
  const float bottom = std::fma(a, pass(i + 1, j) - pass(i, j), pass(i, j));
  const float top = std::fma(a, pass(i + 1, j + 1) - pass(i, j + 1), pass(i, j + 1));
  return std::fma(b, top - bottom, bottom);
}

// A 2×2 d32f map (row 0 at the bottom):  0.6 0.8 / 0.6 0.4 ; ref 0.5 LEQUAL passes everywhere except texel
// (1, 0). All weights below are dyadic, so the expected values are exact and compared exactly.
TEST(GlSampling, HardwarePcfOnTwoByTwoMap) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  const std::vector<uint32_t> texels = as_bits({0.6f, 0.4f, 0.6f, 0.8f});
  const std::vector<glm::vec3> coords = {
      {0.25f, 0.25f, 0.5f},    // centre of texel (0, 0): passes -> 1
      {0.75f, 0.25f, 0.5f},    // centre of texel (1, 0): fails -> 0
      {0.5f, 0.5f, 0.5f},      // middle: a = b = 0.5 -> 3/4
      {0.375f, 0.375f, 0.5f},  // a = b = 0.25: bottom = 0.75, top = 1 -> 0.8125
      {0.625f, 0.375f, 0.5f},  // a = 0.75, b = 0.25: bottom = 0.25, top = 1 -> 0.4375
      {0.75f, 0.5f, 0.5f},     // a = 1 clamps to edge column 1, b = 0.5 -> 0.5
      {0.9f, 0.1f, 0.5f},      // beyond the centres: clamp to edge -> texel (1, 0) -> 0
      {0.5f, 0.5f, 0.9f},      // ref above every texel -> 0
      {0.5f, 0.5f, 0.1f},      // ref below every texel -> 1
  };
  const std::vector<float> expected = {1.0f, 0.0f, 0.75f, 0.8125f, 0.4375f, 0.5f, 0.0f, 0.0f, 1.0f};
  Context::ShadowSampleQuery q;
  q.tex_width = q.tex_height = 2;
  q.format = DepthFormat::d32f;
  q.texels = texels;
  q.coords = coords;
  EXPECT_EQ(gl->sample_shadow(q), expected);

  q.linear = false;  // NEAREST: the texel containing (s, t)
  const std::vector<float> nearest = gl->sample_shadow(q);
  EXPECT_EQ(nearest, (std::vector<float>{1, 0, 1, 1, 0, 1, 0, 0, 1}));

  q.linear = true;
  q.compare = raster::DepthFunc::greater;  // passes when ref > texel: the complement here
  const std::vector<float> greater = gl->sample_shadow(q);
  for (size_t k = 0; k < coords.size(); ++k) EXPECT_EQ(greater[k], 1.0f - expected[k]) << k;
}

TEST(GlSampling, ClampToBorderUsesTheBorderDepth) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  const std::vector<uint32_t> texels = as_bits({0.6f, 0.6f, 0.6f, 0.6f});
  const std::vector<glm::vec3> coords = {{0.5f, 0.5f, 0.5f}, {1.5f, 0.5f, 0.5f}, {1.0f, 0.25f, 0.5f}};
  Context::ShadowSampleQuery q;
  q.tex_width = q.tex_height = 2;
  q.texels = texels;
  q.coords = coords;
  q.wrap_s = q.wrap_t = glref::Wrap::clamp_to_border;
  q.border = 0.0f;  // border texels fail the LEQUAL test against ref 0.5
  EXPECT_EQ(gl->sample_shadow(q), (std::vector<float>{1.0f, 0.0f, 0.5f}));
  q.wrap_s = q.wrap_t = glref::Wrap::clamp;
  EXPECT_THROW(gl->sample_shadow(q), std::runtime_error) << "GL_CLAMP needs a compatibility context";
}

// Legacy GL_CLAMP (compatibility profile only): s is clamped to [0, 1] and LINEAR at the edge then mixes the
// edge texel with the border, so s = 1 and s = 1.25 both give half a pass, where clamp_to_edge gives 1.
TEST(GlSampling, LegacyClampMixesEdgeAndBorder) {
  std::string why;
  auto gl = Context::create(testsupport::glref_threads(), &why, glref::Profile::compatibility);
  if (!gl) GTEST_SKIP() << "skipped: " << why;
  const std::vector<uint32_t> texels = as_bits({0.6f, 0.6f, 0.6f, 0.6f});
  const std::vector<glm::vec3> coords = {{1.0f, 0.25f, 0.5f}, {1.25f, 0.25f, 0.5f}, {0.5f, 0.25f, 0.5f}};
  Context::ShadowSampleQuery q;
  q.tex_width = q.tex_height = 2;
  q.texels = texels;
  q.coords = coords;
  q.wrap_s = q.wrap_t = glref::Wrap::clamp;
  EXPECT_EQ(gl->sample_shadow(q), (std::vector<float>{0.5f, 0.5f, 1.0f}));
  q.wrap_s = q.wrap_t = glref::Wrap::clamp_to_edge;
  EXPECT_EQ(gl->sample_shadow(q), (std::vector<float>{1.0f, 1.0f, 1.0f}));
}

// llvmpipe against the model on random lookups over a random map (coordinates spill past the edges):
// bit-exact for d32f, d24 and d16. Measured on 2^20 lookups; 4096 kept here.
TEST(GlSampling, PcfMatchesTheFloatModelBitExactly) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  const int w = 37, h = 23;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (DepthFormat f : {DepthFormat::d32f, DepthFormat::d24, DepthFormat::d16}) {
    std::vector<uint32_t> texels(size_t(w * h));
    for (uint32_t& t : texels)
      t = f == DepthFormat::d32f ? std::bit_cast<uint32_t>(unit(rng)) : uint32_t(rng() % (raster::depth_max_code(f) + 1));
    std::vector<glm::vec3> coords(4096);
    for (glm::vec3& c : coords) c = {unit(rng) * 1.2f - 0.1f, unit(rng) * 1.2f - 0.1f, unit(rng)};
    Context::ShadowSampleQuery q;
    q.tex_width = w;
    q.tex_height = h;
    q.format = f;
    q.texels = texels;
    q.coords = coords;
    const std::vector<float> got = gl->sample_shadow(q);
    int mismatches = 0;
    for (size_t k = 0; k < coords.size(); ++k) mismatches += got[k] != model_pcf(texels, w, h, f, coords[k]);
    EXPECT_EQ(mismatches, 0) << raster::to_string(f);
  }
}

// A unorm texel compares as float(code) · float(1/max): the largest passing ref is exactly that float, for
// codes at both ends and in the middle. A ref past 1.0 is clamped to 1.0, so it passes where the texel is 1.0:
// code max, and for d24 also code max − 1 (float(1/16777215) rounds up to 2^-24·(1 + 2^-23), and
// 16777214 times that rounds to 1.0).
TEST(GlSampling, UnormTexelsCompareAsFloatProduct) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  for (DepthFormat f : {DepthFormat::d16, DepthFormat::d24}) {
    const uint32_t max = raster::depth_max_code(f);
    const std::vector<uint32_t> codes = {1, 2, 3, 7, 257, max / 3, max / 2, max / 2 + 1, max - 2, max - 1, max};
    std::vector<uint32_t> texels;
    std::vector<glm::vec3> coords;
    const int w = int(codes.size());
    for (int i = 0; i < w; ++i) {
      texels.push_back(codes[size_t(i)]);
      const float value = float(codes[size_t(i)]) * float(1.0 / double(max));
      const float s = (float(i) + 0.5f) / float(w);
      coords.push_back({s, 0.5f, value});                           // passes
      coords.push_back({s, 0.5f, std::nextafter(value, 2.0f)});     // fails, unless clamped to 1
    }
    Context::ShadowSampleQuery q;
    q.tex_width = w;
    q.tex_height = 1;
    q.format = f;
    q.texels = texels;
    q.coords = coords;
    q.linear = false;
    const std::vector<float> got = gl->sample_shadow(q);
    for (int i = 0; i < w; ++i) {
      EXPECT_EQ(got[size_t(2 * i)], 1.0f) << raster::to_string(f) << " code " << codes[size_t(i)];
      const bool is_one = float(codes[size_t(i)]) * float(1.0 / double(max)) == 1.0f;
      EXPECT_EQ(is_one, codes[size_t(i)] >= (f == DepthFormat::d24 ? max - 1 : max));
      EXPECT_EQ(got[size_t(2 * i + 1)], is_one ? 1.0f : 0.0f)
          << raster::to_string(f) << " code " << codes[size_t(i)];
    }
  }
}

TEST(GlSampling, PcfPassTimesArePositive) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  std::vector<uint32_t> texels(64 * 64);
  for (size_t i = 0; i < texels.size(); ++i) texels[i] = std::bit_cast<uint32_t>(float(i % 64) / 64.0f);
  Context::ShadowSampleQuery map;
  map.tex_width = map.tex_height = 64;
  map.texels = texels;
  for (int taps : {1, 16}) {
    const std::vector<double> ms = gl->time_pcf_pass(128, 96, map, taps, 3);
    ASSERT_EQ(ms.size(), 3u);
    for (double t : ms) EXPECT_GT(t, 0.0) << taps << " taps";
  }
  EXPECT_EQ(glref::poisson_disk16().size(), 32u);
}

}  // namespace
