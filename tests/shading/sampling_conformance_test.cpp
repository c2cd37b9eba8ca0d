// Sampling conformance against llvmpipe: the same depth texture and (s, t, ref) coordinates through GLSL
// texture(sampler2DShadow, …) with LINEAR (hardware PCF) and NEAREST, CLAMP_TO_EDGE, and through shadowlab.
// Measured on 20,000 random lookups per format (a third of them fractional): NEAREST agrees exactly and LINEAR
// within 6e-8, one float rounding of the blend — llvmpipe's filter weights are floats, not fixed point, and
// shading/ computes them from u = s·W − 0.5 as CONVENTIONS says. The test allows 1e-6.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "raster/target.h"
#include "shading/shadow_lookup.h"
#include "shading/texture.h"
#include "tests/raster/reference/gl_test_support.h"

namespace {

struct Case {
  std::vector<uint32_t> texels;  // encoded like DepthTarget::raw
  raster::DepthTarget target;
};

Case random_depth_texture(int w, int h, raster::DepthFormat f, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.2f, 0.8f);
  Case c{{}, raster::DepthTarget(w, h, f)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float z = u(rng);
      uint32_t raw;
      if (f == raster::DepthFormat::d32f) {
        raw = std::bit_cast<uint32_t>(z);
        c.target.row<float>(y)[x] = z;
      } else if (f == raster::DepthFormat::d16) {
        raw = uint32_t(std::nearbyint(z * 65535.0f));
        c.target.row<uint16_t>(y)[x] = uint16_t(raw);
      } else {
        raw = uint32_t(std::nearbyint(double(z) * 16777215.0));
        c.target.row<uint32_t>(y)[x] = raw;
      }
      c.texels.push_back(raw);
    }
  return c;
}

double max_difference(glref::Context& gl, const Case& c, bool linear, const std::vector<glm::vec3>& coords) {
  glref::Context::ShadowSampleQuery q;
  q.tex_width = c.target.width(), q.tex_height = c.target.height(), q.format = c.target.format();
  q.texels = c.texels, q.linear = linear, q.coords = coords;
  const std::vector<float> ref = gl.sample_shadow(q);
  shading::Sampler s = shading::Sampler::pcf();
  if (!linear) s.mag_filter = s.min_filter = shading::Filter::nearest;
  const shading::ShadowLookup2D lookup(shading::Texture2D::view(c.target), s);
  double worst = 0;
  size_t fractional = 0;
  for (size_t i = 0; i < coords.size(); ++i) {
    worst = std::max(worst, double(std::abs(lookup(coords[i]) - ref[i])));
    fractional += ref[i] > 0.0f && ref[i] < 1.0f;
  }
  // The coordinates must exercise the filter: many results strictly between 0 and 1 when LINEAR.
  if (linear) {
    EXPECT_GT(fractional, coords.size() / 4) << to_string(c.target.format());
  }
  return worst;
}

}  // namespace

TEST(SamplingConformance, ShadowLookupsMatchLlvmpipe) {
  GLREF_CONTEXT_OR_SKIP(gl, testsupport::glref_threads());
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> st(-0.1f, 1.1f), ref(0.15f, 0.85f);
  std::vector<glm::vec3> coords(20000);
  for (auto& c : coords) c = {st(rng), st(rng), ref(rng)};
  for (raster::DepthFormat f : {raster::DepthFormat::d16, raster::DepthFormat::d24, raster::DepthFormat::d32f}) {
    const Case c = random_depth_texture(37, 29, f, 9);
    EXPECT_EQ(max_difference(*gl, c, false, coords), 0.0) << "NEAREST " << to_string(f);
    const double linear = max_difference(*gl, c, true, coords);
    EXPECT_LE(linear, 1e-6) << "LINEAR " << to_string(f);
    RecordProperty("max_linear_difference_" + std::string(to_string(f)), std::to_string(linear));
    std::printf("%s: LINEAR max difference %.3g, NEAREST exact\n", std::string(to_string(f)).c_str(), linear);
  }
}
