// Level of detail: λ from derivatives (GL's isotropic ρ), bias and clamps, the mag/min switch, mip level
// selection (NEAREST: ceil(λ + ½) − 1, LINEAR: floor(λ) and the next, weighted by frac(λ)), and quad lookups
// taking fine or coarse derivatives.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "shading/lookup.h"

namespace {

using shading::Derivative;
using shading::Filter;
using shading::MipFilter;
using shading::Quad;
using shading::Sampler;
using shading::TexelFormat;
using shading::Texture2D;

// An 8 × 8 r32f texture with mips 8, 4, 2, 1 whose level k holds the value k everywhere.
Texture2D levels_texture() {
  Texture2D t(8, 8, TexelFormat::r32f, true);
  for (int l = 0; l < t.levels(); ++l)
    for (int j = 0; j < t.height(l); ++j)
      for (int i = 0; i < t.width(l); ++i) t.set_texel(i, j, glm::vec4(float(l)), l);
  return t;
}

TEST(Lod, LambdaFromGradients) {
  // 64 × 64: one texel per pixel is ρ = 1, λ = 0.
  EXPECT_EQ(shading::lod_from_gradients({1 / 64.0f, 0}, {0, 1 / 64.0f}, 64, 64), 0.0f);
  EXPECT_EQ(shading::lod_from_gradients({2 / 64.0f, 0}, {0, 2 / 64.0f}, 64, 64), 1.0f);
  // ρ is the larger of the two lengths.
  EXPECT_EQ(shading::lod_from_gradients({4 / 64.0f, 0}, {0, 1 / 64.0f}, 64, 64), 2.0f);
  EXPECT_EQ(shading::lod_from_gradients({0, 1 / 64.0f}, {0, 8 / 64.0f}, 64, 64), 3.0f);
  // Lengths, not components: (3, 4) texels per pixel is ρ = 5.
  EXPECT_FLOAT_EQ(shading::lod_from_gradients({3 / 64.0f, 4 / 64.0f}, {0, 0}, 64, 64), std::log2(5.0f));
  // Sizes scale each axis: on a 64 × 16 texture ∂t = 1/16 per pixel is one texel.
  EXPECT_EQ(shading::lod_from_gradients({0, 0}, {0, 1 / 16.0f}, 64, 16), 0.0f);
  EXPECT_TRUE(std::isinf(shading::lod_from_gradients({0, 0}, {0, 0}, 64, 64)));
}

TEST(Lod, ChooseLevels) {
  Sampler s = Sampler::plain(Filter::linear, shading::Wrap::clamp_to_edge, MipFilter::nearest);
  s.mag_filter = Filter::nearest;
  s.min_filter = Filter::linear;
  auto c = shading::choose_levels(0.0f, s, 4);
  EXPECT_EQ(c.filter, Filter::nearest);  // λ <= 0 magnifies
  EXPECT_EQ(c.level0, 0);
  c = shading::choose_levels(0.01f, s, 4);
  EXPECT_EQ(c.filter, Filter::linear);
  EXPECT_EQ(c.level0, 0);
  // MIPMAP_NEAREST: ceil(λ + ½) − 1, i.e. round half down.
  EXPECT_EQ(shading::choose_levels(0.5f, s, 4).level0, 0);
  EXPECT_EQ(shading::choose_levels(0.51f, s, 4).level0, 1);
  EXPECT_EQ(shading::choose_levels(1.5f, s, 4).level0, 1);
  EXPECT_EQ(shading::choose_levels(1.6f, s, 4).level0, 2);
  EXPECT_EQ(shading::choose_levels(9.0f, s, 4).level0, 3);
  // MIPMAP_LINEAR: floor(λ), floor(λ) + 1, weight frac(λ); the last level alone from λ = q on.
  s.mip_filter = MipFilter::linear;
  c = shading::choose_levels(1.25f, s, 4);
  EXPECT_EQ(c.level0, 1);
  EXPECT_EQ(c.level1, 2);
  EXPECT_EQ(c.weight, 0.25f);
  c = shading::choose_levels(3.0f, s, 4);
  EXPECT_EQ(c.level0, 3);
  EXPECT_EQ(c.level1, 3);
  // Bias and clamps.
  s.lod_bias = 1.0f;
  EXPECT_EQ(shading::choose_levels(0.5f, s, 4).level0, 1);
  EXPECT_EQ(shading::choose_levels(0.5f, s, 4).weight, 0.5f);
  s.lod_bias = 0.0f;
  s.min_lod = 2.0f;
  EXPECT_EQ(shading::choose_levels(-5.0f, s, 4).level0, 2);
  s.min_lod = -1000.0f;
  s.max_lod = 1.0f;
  EXPECT_EQ(shading::choose_levels(5.0f, s, 4).level0, 1);
  EXPECT_EQ(shading::choose_levels(5.0f, s, 4).level1, 1);
  // Without a mip filter minification reads level 0.
  s.mip_filter = MipFilter::none;
  s.max_lod = 1000.0f;
  EXPECT_EQ(shading::choose_levels(5.0f, s, 4).level0, 0);
}

TEST(Lod, TextureLodAndGradReadTheChosenLevels) {
  const Texture2D t = levels_texture();
  Sampler s = Sampler::plain(Filter::linear, shading::Wrap::repeat, MipFilter::linear);
  const glm::vec2 st(0.3f, 0.6f);
  EXPECT_EQ(shading::texture_lod(t, s, st, 0.0f).r, 0.0f);
  EXPECT_EQ(shading::texture_lod(t, s, st, 1.25f).r, 1.25f);
  EXPECT_EQ(shading::texture_lod(t, s, st, 2.5f).r, 2.5f);
  EXPECT_EQ(shading::texture_lod(t, s, st, 7.0f).r, 3.0f);
  // Gradients of 2 texels per pixel: λ = 1.
  EXPECT_EQ(shading::texture_grad(t, s, st, {2 / 8.0f, 0}, {0, 2 / 8.0f}).r, 1.0f);
  // ρ = 4·√2 texels per pixel along a diagonal: λ = 2.5.
  EXPECT_FLOAT_EQ(shading::texture_grad(t, s, st, {4 / 8.0f, 4 / 8.0f}, {0, 0}).r, 2.5f);
  s.mip_filter = MipFilter::nearest;
  EXPECT_EQ(shading::texture_grad(t, s, st, {3 / 8.0f, 0}, {0, 0}).r, 2.0f);  // λ = log2 3 = 1.58 → 2
}

TEST(Lod, QuadLookupsTakeFineOrCoarseDerivatives) {
  const Texture2D t = levels_texture();
  const Sampler s = Sampler::plain(Filter::linear, shading::Wrap::repeat, MipFilter::nearest);
  // Lanes 0 = (x, y), 1 = (x+1, y), 2 = (x, y+1), 3 = (x+1, y+1). One texel (1/8) per pixel along the bottom
  // row and the left column, four texels along the top row.
  const glm::vec2 p0(0.5f, 0.5f);
  const Quad<glm::vec2> st = {p0, p0 + glm::vec2(1 / 8.0f, 0), p0 + glm::vec2(0, 1 / 8.0f),
                              p0 + glm::vec2(4 / 8.0f, 1 / 8.0f)};
  // Coarse: one difference per quad (lane 1 − lane 0, lane 2 − lane 0): ρ = 1 everywhere → level 0.
  const Quad<glm::vec4> coarse = shading::texture(t, s, st, Derivative::coarse);
  for (int l = 0; l < 4; ++l) EXPECT_EQ(coarse[size_t(l)].r, 0.0f) << l;
  // Fine: lane 0: dx = 1, dy = 1 texel → λ 0 → level 0. lane 1: dx = 1, dy = lane 3 − lane 1 = (3, 1)
  // → ρ = √10, λ = 1.66 → level 2. lanes 2, 3: dx = lane 3 − lane 2 = 4 → λ = 2 → level 2 (ceil(2.5) − 1).
  const Quad<glm::vec4> fine = shading::texture(t, s, st, Derivative::fine);
  EXPECT_EQ(fine[0].r, 0.0f);
  EXPECT_EQ(fine[1].r, 2.0f);
  EXPECT_EQ(fine[2].r, 2.0f);
  EXPECT_EQ(fine[3].r, 2.0f);
  const Quad<float> lod = shading::quad_lod(t, st, Derivative::fine);
  EXPECT_EQ(lod[0], 0.0f);
  EXPECT_FLOAT_EQ(lod[1], std::log2(std::sqrt(10.0f)));
  EXPECT_EQ(lod[2], 2.0f);
}

TEST(Lod, PerLaneTextureUsesLevelZero) {
  const Texture2D t = levels_texture();
  const Sampler s = Sampler::plain(Filter::linear, shading::Wrap::repeat, MipFilter::linear);
  EXPECT_EQ(shading::texture(t, s, glm::vec2(0.3f, 0.3f)).r, 0.0f);
}

}  // namespace
