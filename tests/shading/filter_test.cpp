// NEAREST and LINEAR on one level: u = s·W − 0.5, floor, fractional weights (CONVENTIONS), checked with
// delta textures so each tap's weight is read off directly.
#include <gtest/gtest.h>

#include <vector>

#include "shading/lookup.h"

namespace {

using shading::Filter;
using shading::Sampler;
using shading::TexelFormat;
using shading::Texture2D;

// A W × H r32f texture that is 1 at (i, j) and 0 elsewhere.
Texture2D delta(int w, int h, int i, int j) {
  std::vector<float> v(size_t(w) * size_t(h), 0.0f);
  v[size_t(j) * size_t(w) + size_t(i)] = 1.0f;
  return Texture2D::from_floats(w, h, TexelFormat::r32f, 1, v);
}

TEST(Filter, BilinearWeightsAtAChosenCoordinate) {
  // 4 × 2 texture, s = 0.4375: u = 1.75 − 0.5 = 1.25, taps i = 1, 2 with weights 0.75, 0.25.
  //                t = 0.625:  v = 1.25 − 0.5 = 0.75, taps j = 0, 1 with weights 0.25, 0.75.
  const Sampler s = Sampler::plain(Filter::linear);
  const glm::vec2 st(0.4375f, 0.625f);
  struct Case {
    int i, j;
    float weight;
  };
  const Case cases[] = {{1, 0, 0.75f * 0.25f}, {2, 0, 0.25f * 0.25f}, {1, 1, 0.75f * 0.75f}, {2, 1, 0.25f * 0.75f}};
  for (const Case& c : cases) EXPECT_EQ(shading::texture(delta(4, 2, c.i, c.j), s, st).r, c.weight) << c.i << c.j;
  // Texels outside the footprint get no weight.
  EXPECT_EQ(shading::texture(delta(4, 2, 0, 0), s, st).r, 0.0f);
  EXPECT_EQ(shading::texture(delta(4, 2, 3, 1), s, st).r, 0.0f);
}

TEST(Filter, TexelCentresReadOneTexelAndEdgesBetweenTexelsReadTheMean) {
  const std::vector<float> v = {1, 2, 4, 8};  // 4 × 1
  const Texture2D t = Texture2D::from_floats(4, 1, TexelFormat::r32f, 1, v);
  const Sampler s = Sampler::plain(Filter::linear);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(shading::texture(t, s, glm::vec2((i + 0.5f) / 4, 0.5f)).r, v[size_t(i)]);
  EXPECT_EQ(shading::texture(t, s, glm::vec2(0.5f, 0.5f)).r, 3.0f);   // between texels 1 and 2
  EXPECT_EQ(shading::texture(t, s, glm::vec2(0.75f, 0.5f)).r, 6.0f);  // between texels 2 and 3
}

TEST(Filter, NearestTakesFloorOfSW) {
  const std::vector<float> v = {1, 2, 4, 8};
  const Texture2D t = Texture2D::from_floats(4, 1, TexelFormat::r32f, 1, v);
  const Sampler s = Sampler::plain(Filter::nearest);
  EXPECT_EQ(shading::texture(t, s, glm::vec2(0.2499f, 0.5f)).r, 1.0f);
  EXPECT_EQ(shading::texture(t, s, glm::vec2(0.25f, 0.5f)).r, 2.0f);  // exactly on the boundary: floor(1.0) = 1
  EXPECT_EQ(shading::texture(t, s, glm::vec2(0.7499f, 0.5f)).r, 4.0f);
  EXPECT_EQ(shading::texture(t, s, glm::vec2(0.75f, 0.5f)).r, 8.0f);
}

TEST(Filter, SrgbTexelsAreDecodedBeforeFiltering) {
  // Bytes 0 and 255: linear 0 and 1. Halfway the result is linear 0.5, not the decoding of byte 127.5.
  Texture2D t(2, 1, TexelFormat::rgba8_srgb);
  t.set_texel(0, 0, glm::vec4(0.0f, 0.0f, 0.0f, 0.0f));
  t.set_texel(1, 0, glm::vec4(1.0f, 1.0f, 1.0f, 1.0f));
  const glm::vec4 v = shading::texture(t, Sampler::plain(Filter::linear), glm::vec2(0.5f, 0.5f));
  EXPECT_EQ(v, glm::vec4(0.5f));
}

TEST(Filter, DepthTexturesReadAsDepthZeroZeroOne) {
  const Texture2D t = Texture2D::from_floats(2, 1, TexelFormat::d32f, 1, std::vector<float>{0.25f, 0.75f});
  const glm::vec4 v = shading::texture(t, Sampler::plain(Filter::linear), glm::vec2(0.5f, 0.5f));
  EXPECT_EQ(v, glm::vec4(0.5f, 0.0f, 0.0f, 1.0f));
}

TEST(Filter, TextureOffsetShiftsIntegerTexelCoordinates) {
  const std::vector<float> v = {1, 2, 4, 8};
  const Texture2D t = Texture2D::from_floats(4, 1, TexelFormat::r32f, 1, v);
  const Sampler s = Sampler::plain(Filter::linear);
  // s = 0.4375: taps 1, 2 weights 0.75, 0.25 → with offset +1: taps 2, 3 → 0.75·4 + 0.25·8 = 5.
  EXPECT_EQ(shading::texture_offset(t, s, glm::vec2(0.4375f, 0.5f), {1, 0}).r, 5.0f);
  // NEAREST at texel 3 with offset −2 reads texel 1.
  EXPECT_EQ(shading::texture_offset(t, Sampler::plain(Filter::nearest), glm::vec2(0.9f, 0.5f), {-2, 0}).r, 2.0f);
}

}  // namespace
