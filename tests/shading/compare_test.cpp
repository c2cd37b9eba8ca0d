// Depth compare: hardware PCF (compare four texels, then blend the 0/1 results with the bilinear weights), the
// eight GL compare functions, GL's clamping of the reference for unorm formats, the border depth, and the
// mistake "filter the depth, then compare" differing from PCF where it should.
#include <gtest/gtest.h>

#include <vector>

#include "shading/lookup.h"

namespace {

using shading::CompareFunc;
using shading::Filter;
using shading::Sampler;
using shading::TexelFormat;
using shading::Texture2D;
using shading::Wrap;

// 2 × 2 depths: bottom row 0.2, 0.4; top row 0.6, 0.8.
Texture2D quad_depths(TexelFormat f = TexelFormat::d32f) {
  return Texture2D::from_floats(2, 2, f, 1, std::vector<float>{0.2f, 0.4f, 0.6f, 0.8f});
}

// At s = 0.625, t = 0.375: u = 0.75, v = 0.25, so the weights of texels (0,0), (1,0), (0,1), (1,1) are
// 0.25·0.75, 0.75·0.75, 0.25·0.25, 0.75·0.25.
constexpr float kWeights[4] = {0.1875f, 0.5625f, 0.0625f, 0.1875f};
const glm::vec2 kSt(0.625f, 0.375f);

// A shadow lookup through texture() (which runs the PCF kernel where it applies) and through the generic core;
// both must give the same value.
float lookup(const Texture2D& t, const Sampler& s, glm::vec3 p) {
  const float a = shading::texture(t, s, p), b = shading::texture_at(t, s, p, 0.0f);
  EXPECT_EQ(a, b) << "kernel and generic lookups differ at " << p.x << ", " << p.y << ", " << p.z;
  return a;
}

float weighted(const int (&results)[4]) {
  float sum = 0.0f;
  for (int k = 0; k < 4; ++k) sum += kWeights[k] * float(results[k]);
  return sum;
}

TEST(Compare, PcfEqualsFourHandComparisonsBlendedWithTheirWeights) {
  const Texture2D t = quad_depths();
  // Reference 0.4 against texels 0.2, 0.4, 0.6, 0.8, by hand for each function.
  struct Case {
    CompareFunc f;
    int results[4];
  };
  const Case cases[] = {
      {CompareFunc::never, {0, 0, 0, 0}},  {CompareFunc::less, {0, 0, 1, 1}},    {CompareFunc::equal, {0, 1, 0, 0}},
      {CompareFunc::lequal, {0, 1, 1, 1}}, {CompareFunc::greater, {1, 0, 0, 0}}, {CompareFunc::notequal, {1, 0, 1, 1}},
      {CompareFunc::gequal, {1, 1, 0, 0}}, {CompareFunc::always, {1, 1, 1, 1}},
  };
  for (const Case& c : cases) {
    const Sampler s = Sampler::pcf(c.f);
    EXPECT_EQ(shading::texture(t, s, glm::vec3(kSt, 0.4f)), weighted(c.results)) << int(c.f);
    // The generic core too (texture() takes the PCF kernel for LEQUAL).
    EXPECT_EQ(shading::texture_at(t, s, glm::vec3(kSt, 0.4f), 0.0f), weighted(c.results)) << int(c.f);
  }
  // LEQUAL at other references.
  EXPECT_EQ(shading::texture(t, Sampler::pcf(), glm::vec3(kSt, 0.5f)), weighted({0, 0, 1, 1}));  // 0.25
  EXPECT_EQ(shading::texture(t, Sampler::pcf(), glm::vec3(kSt, 0.1f)), 1.0f);
  EXPECT_EQ(shading::texture(t, Sampler::pcf(), glm::vec3(kSt, 0.9f)), 0.0f);
}

TEST(Compare, NearestCompareIsOneTexelsZeroOrOne) {
  const Texture2D t = quad_depths();
  Sampler s = Sampler::pcf();
  s.mag_filter = s.min_filter = Filter::nearest;
  EXPECT_EQ(shading::texture(t, s, glm::vec3(0.75f, 0.25f, 0.4f)), 1.0f);  // texel (1, 0) = 0.4
  EXPECT_EQ(shading::texture(t, s, glm::vec3(0.25f, 0.25f, 0.4f)), 0.0f);  // texel (0, 0) = 0.2
}

TEST(Compare, UnormReferenceIsClampedFloatReferenceIsNot) {
  const Texture2D d16 = Texture2D::from_floats(1, 1, TexelFormat::d16, 1, std::vector<float>{1.0f});
  const Texture2D d32 = Texture2D::from_floats(1, 1, TexelFormat::d32f, 1, std::vector<float>{1.0f});
  const glm::vec3 p(0.5f, 0.5f, 1.5f);
  EXPECT_EQ(lookup(d16, Sampler::pcf(CompareFunc::lequal), p), 1.0f);  // clamped 1 <= 1
  EXPECT_EQ(lookup(d32, Sampler::pcf(CompareFunc::lequal), p), 0.0f);  // 1.5 <= 1 fails
  const Texture2D z16 = Texture2D::from_floats(1, 1, TexelFormat::d16, 1, std::vector<float>{0.0f});
  const Texture2D z32 = Texture2D::from_floats(1, 1, TexelFormat::d32f, 1, std::vector<float>{0.0f});
  const glm::vec3 q(0.5f, 0.5f, -0.5f);
  EXPECT_EQ(lookup(z16, Sampler::pcf(CompareFunc::less), q), 0.0f);  // clamped 0 < 0 fails
  EXPECT_EQ(lookup(z32, Sampler::pcf(CompareFunc::less), q), 1.0f);  // −0.5 < 0
}

TEST(Compare, BorderDepthTakesPartInPcf) {
  // All texels 0.5; reference 0.7 fails against them. At s = 0 half of the footprint is border.
  const Texture2D t = Texture2D::from_floats(2, 2, TexelFormat::d32f, 1, std::vector<float>(4, 0.5f));
  const glm::vec3 p(0.0f, 0.5f, 0.7f);
  EXPECT_EQ(lookup(t, Sampler::pcf(CompareFunc::lequal, Wrap::clamp_to_border, 1.0f), p), 0.5f);
  EXPECT_EQ(lookup(t, Sampler::pcf(CompareFunc::lequal, Wrap::clamp_to_border, 0.0f), p), 0.0f);
  EXPECT_EQ(lookup(t, Sampler::pcf(CompareFunc::lequal, Wrap::clamp_to_edge), p), 0.0f);
  // Far outside: only the border.
  EXPECT_EQ(lookup(t, Sampler::pcf(CompareFunc::lequal, Wrap::clamp_to_border, 1.0f), glm::vec3(-3.0f, 4.0f, 0.7f)),
            1.0f);
  // A unorm map clamps the border depth to [0, 1]: border 5 reads as 1, so 1 < border fails (it would pass
  // against an unclamped 5) while 1 <= border passes.
  const Texture2D u = Texture2D::from_floats(2, 2, TexelFormat::d16, 1, std::vector<float>(4, 0.5f));
  EXPECT_EQ(lookup(u, Sampler::pcf(CompareFunc::less, Wrap::clamp_to_border, 5.0f), glm::vec3(-3.0f, 4.0f, 1.0f)),
            0.0f);
  EXPECT_EQ(lookup(u, Sampler::pcf(CompareFunc::lequal, Wrap::clamp_to_border, 5.0f), glm::vec3(-3.0f, 4.0f, 1.0f)),
            1.0f);
}

TEST(Compare, FilterThenCompareDiffersFromPcfAcrossAnEdge) {
  // Depths 0.2 | 0.8 side by side (an occluder edge). Halfway between the texels the filtered depth is 0.5.
  const Texture2D t = Texture2D::from_floats(2, 1, TexelFormat::d32f, 1, std::vector<float>{0.2f, 0.8f});
  Sampler plain = Sampler::plain(Filter::linear);  // compare mode none: the mistake
  const Sampler pcf = Sampler::pcf();
  // ref 0.45: PCF compares 0.45 <= 0.2 (0) and 0.45 <= 0.8 (1) → 0.5; the mistake compares 0.45 <= 0.5 → 1.
  EXPECT_EQ(shading::texture(t, pcf, glm::vec3(0.5f, 0.5f, 0.45f)), 0.5f);
  EXPECT_EQ(shading::texture(t, plain, glm::vec3(0.5f, 0.5f, 0.45f)), 1.0f);
  EXPECT_EQ(shading::filter_then_compare(t, pcf, glm::vec3(0.5f, 0.5f, 0.45f)), 1.0f);
  // ref 0.55: PCF still 0.5, the mistake 0.
  EXPECT_EQ(shading::texture(t, pcf, glm::vec3(0.5f, 0.5f, 0.55f)), 0.5f);
  EXPECT_EQ(shading::texture(t, plain, glm::vec3(0.5f, 0.5f, 0.55f)), 0.0f);
  // At s = 0.375 (u = 0.25): PCF gives the weight of the lit texel, 0.25; filtered depth 0.35 vs 0.45 → 0.
  EXPECT_EQ(shading::texture(t, pcf, glm::vec3(0.375f, 0.5f, 0.45f)), 0.25f);
  EXPECT_EQ(shading::texture(t, plain, glm::vec3(0.375f, 0.5f, 0.45f)), 0.0f);
}

TEST(Compare, FilterThenCompareAgreesWithPcfOnFlatDepthAndIsAlwaysBinary) {
  const Texture2D flat = Texture2D::from_floats(2, 2, TexelFormat::d32f, 1, std::vector<float>(4, 0.5f));
  const Sampler plain = Sampler::plain(Filter::linear);
  for (float ref : {0.25f, 0.5f, 0.75f})
    EXPECT_EQ(shading::texture(flat, plain, glm::vec3(0.3f, 0.6f, ref)),
              shading::texture(flat, Sampler::pcf(), glm::vec3(0.3f, 0.6f, ref)));
  const Texture2D t = quad_depths();
  for (int k = 0; k < 50; ++k) {
    const glm::vec3 p(0.02f * float(k), 0.7f - 0.01f * float(k), 0.3f + 0.01f * float(k));
    const float r = shading::texture(t, plain, p);
    EXPECT_TRUE(r == 0.0f || r == 1.0f) << r;
  }
}

TEST(Compare, MipmappedCompareBlendsTheTwoLevelsResults) {
  // 2 × 2 level 0 all 0.25, level 1 (1 × 1) the mean 0.25 — then overwrite level 1 with 0.75.
  Texture2D t = Texture2D::from_floats(2, 2, TexelFormat::d32f, 1, std::vector<float>(4, 0.25f), true);
  t.set_texel(0, 0, glm::vec4(0.75f), 1);
  Sampler s = Sampler::pcf();
  s.mip_filter = shading::MipFilter::linear;
  // ref 0.5: level 0 fails everywhere (0), level 1 passes (1). λ = 0.25 → 0.25 of level 1.
  EXPECT_EQ(shading::texture_lod(t, s, glm::vec3(0.5f, 0.5f, 0.5f), 0.25f), 0.25f);
  EXPECT_EQ(shading::texture_lod(t, s, glm::vec3(0.5f, 0.5f, 0.5f), 0.0f), 0.0f);
  EXPECT_EQ(shading::texture_lod(t, s, glm::vec3(0.5f, 0.5f, 0.5f), 3.0f), 1.0f);
}

}  // namespace
