// textureProj: coordinates times 1/q; q < 0 divides like any q (the mirrored back projection a GPU shows);
// q = 0 or NaN returns 0 without reading the texture.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "shading/lookup.h"

namespace {

using shading::Filter;
using shading::Quad;
using shading::Sampler;
using shading::TexelFormat;
using shading::Texture2D;

// 2 × 2 depths: bottom 0.2, 0.4; top 0.6, 0.8.
Texture2D depths() {
  return Texture2D::from_floats(2, 2, TexelFormat::d32f, 1, std::vector<float>{0.2f, 0.4f, 0.6f, 0.8f});
}

TEST(TextureProj, PositiveQDividesTheCoordinates) {
  const Texture2D t = depths();
  Sampler s = Sampler::pcf();
  s.mag_filter = s.min_filter = Filter::nearest;
  // (1.5, 0.5, 0.8, 2) → (0.75, 0.25, 0.4): texel (1, 0) = 0.4, 0.4 <= 0.4.
  EXPECT_EQ(shading::texture_proj(t, s, glm::vec4(1.5f, 0.5f, 0.8f, 2.0f)), 1.0f);
  EXPECT_EQ(shading::texture_proj(t, s, glm::vec4(1.5f, 0.5f, 0.82f, 2.0f)), 0.0f);
  const Sampler plain = Sampler::plain(Filter::nearest);
  EXPECT_EQ(shading::texture_proj(t, plain, glm::vec3(0.25f, 1.5f, 2.0f)).r, 0.6f);  // (0.125, 0.75): texel (0, 1)
}

TEST(TextureProj, NegativeQIsDividedLikeAnyOtherAsOnAGpu) {
  const Texture2D t = depths();
  Sampler s = Sampler::pcf();
  s.mag_filter = s.min_filter = Filter::nearest;
  // q = −1 maps (−0.25, −0.75, −0.5) to (0.25, 0.75, 0.5): texel (0, 1) = 0.6 and 0.5 <= 0.6: lit. A point
  // behind the light thus reads the map as if mirrored through the projector: the back-projection artefact.
  EXPECT_EQ(shading::texture_proj(t, s, glm::vec4(-0.25f, -0.75f, -0.5f, -1.0f)), 1.0f);
  EXPECT_EQ(shading::texture_proj(t, s, glm::vec4(-0.25f, -0.75f, -0.7f, -1.0f)), 0.0f);
  // q = −2 and the colour form.
  EXPECT_EQ(shading::texture_proj(t, Sampler::plain(Filter::nearest), glm::vec3(-1.5f, -0.5f, -2.0f)).r, 0.4f);
}

TEST(TextureProj, ZeroOrNaNQReturnsZeroWithoutReading) {
  const Texture2D t = depths();
  const Sampler s = Sampler::pcf(shading::CompareFunc::always);  // would be 1 if anything were read
  EXPECT_EQ(shading::texture_proj(t, s, glm::vec4(0.5f, 0.5f, 0.5f, 0.0f)), 0.0f);
  EXPECT_EQ(shading::texture_proj(t, s, glm::vec4(0.5f, 0.5f, 0.5f, -0.0f)), 0.0f);
  EXPECT_EQ(shading::texture_proj(t, s, glm::vec4(0.5f, 0.5f, 0.5f, std::numeric_limits<float>::quiet_NaN())), 0.0f);
  EXPECT_EQ(shading::texture_proj(t, Sampler::plain(Filter::linear), glm::vec3(0.5f, 0.5f, 0.0f)), glm::vec4(0.0f));
  EXPECT_EQ(shading::texture_proj(t, s, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)), 1.0f);
}

TEST(TextureProj, QuadFormHandlesEachLanesQ) {
  const Texture2D t = depths();
  Sampler s = Sampler::pcf();
  s.mag_filter = s.min_filter = Filter::nearest;
  const Quad<glm::vec4> p = {glm::vec4(1.5f, 0.5f, 0.8f, 2.0f), glm::vec4(-0.25f, -0.75f, -0.5f, -1.0f),
                             glm::vec4(0.5f, 0.5f, 0.5f, 0.0f), glm::vec4(0.25f, 0.25f, 0.9f, 1.0f)};
  const Quad<float> r = shading::texture_proj(t, s, p);
  EXPECT_EQ(r[0], 1.0f);
  EXPECT_EQ(r[1], 1.0f);
  EXPECT_EQ(r[2], 0.0f);
  EXPECT_EQ(r[3], 0.0f);  // texel (0, 0) = 0.2 < 0.9
}

}  // namespace
