// Texture2D: owned storage, views over depth and colour targets (no copy, GL row order), region views.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "raster/target.h"
#include "shading/lookup.h"
#include "shading/texture.h"

namespace {

using shading::Sampler;
using shading::TexelFormat;
using shading::Texture2D;

// Texel centre of (i, j) in normalised coordinates.
glm::vec2 centre(int i, int j, int w, int h) { return {(float(i) + 0.5f) / float(w), (float(j) + 0.5f) / float(h)}; }

TEST(Texture2D, ViewOfD32fTargetReadsTheTargetInGLRowOrder) {
  raster::DepthTarget target(3, 2, raster::DepthFormat::d32f);
  // Bottom row (y = 0): 0.125, 0.25, 0.375; top row (y = 1): 0.5, 0.625, 0.75.
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) target.row<float>(y)[x] = 0.125f * float(1 + x + 3 * y);
  const Texture2D tex = Texture2D::view(target);
  EXPECT_EQ(tex.format(), TexelFormat::d32f);
  EXPECT_EQ(tex.width(), 3);
  EXPECT_EQ(tex.height(), 2);
  EXPECT_FALSE(tex.owns_level(0));
  const Sampler nearest = Sampler::plain(shading::Filter::nearest);
  // t = 0 is the first row in memory, the bottom row.
  EXPECT_EQ(shading::texture(tex, nearest, glm::vec2(0.1f, 0.1f)), glm::vec4(0.125f, 0, 0, 1));
  EXPECT_EQ(shading::texture(tex, nearest, glm::vec2(0.9f, 0.9f)), glm::vec4(0.75f, 0, 0, 1));
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      EXPECT_EQ(shading::texture(tex, nearest, centre(x, y, 3, 2)).r, target.value(x, y));
      EXPECT_EQ(shading::texel_fetch(tex, {x, y}).r, target.value(x, y));
    }
}

TEST(Texture2D, ViewIsNotACopy) {
  raster::DepthTarget target(4, 4, raster::DepthFormat::d32f);
  const Texture2D tex = Texture2D::view(target);
  EXPECT_EQ(shading::texel_fetch(tex, {2, 3}).r, 1.0f);  // cleared to 1
  target.row<float>(3)[2] = 0.25f;
  EXPECT_EQ(shading::texel_fetch(tex, {2, 3}).r, 0.25f);
}

TEST(Texture2D, ViewOfUnormDepthTargetsDecodesCodes) {
  raster::DepthTarget t16(2, 1, raster::DepthFormat::d16);
  t16.row<uint16_t>(0)[0] = 0;
  t16.row<uint16_t>(0)[1] = 13107;  // 13107 / 65535 = 0.2
  const Texture2D v16 = Texture2D::view(t16);
  EXPECT_EQ(v16.format(), TexelFormat::d16);
  EXPECT_EQ(shading::texel_fetch(v16, {1, 0}).r, 0.2f);
  EXPECT_EQ(shading::texel_fetch(v16, {1, 0}).r, t16.value(1, 0));

  raster::DepthTarget t24(2, 1, raster::DepthFormat::d24);
  t24.row<uint32_t>(0)[1] = 0xFF000000u | 8388608u;  // bits above 24 are not depth
  const Texture2D v24 = Texture2D::view(t24);
  EXPECT_EQ(shading::texel_fetch(v24, {1, 0}).r, float(8388608.0 / 16777215.0));
}

TEST(Texture2D, RegionViewIsATextureOfItsOwn) {
  raster::DepthTarget target(8, 8, raster::DepthFormat::d32f);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) target.row<float>(y)[x] = float(x + 8 * y) / 64.0f;
  const Texture2D region = Texture2D::view(target, raster::Rect{2, 3, 4, 2});
  EXPECT_EQ(region.width(), 4);
  EXPECT_EQ(region.height(), 2);
  EXPECT_EQ(shading::texel_fetch(region, {0, 0}).r, target.value(2, 3));
  EXPECT_EQ(shading::texel_fetch(region, {3, 1}).r, target.value(5, 4));
  EXPECT_EQ(shading::texel_fetch(region, {4, 0}), glm::vec4(0.0f));  // outside the region: robust zero
  // clamp_to_edge stops at the region's edge, not the target's.
  const Sampler linear = Sampler::plain(shading::Filter::linear);
  EXPECT_EQ(shading::texture(region, linear, glm::vec2(1.5f, 0.25f)).r, target.value(5, 3));
  EXPECT_EQ(shading::texture(region, linear, glm::vec2(-0.5f, 0.75f)).r, target.value(2, 4));
  EXPECT_THROW(Texture2D::view(target, raster::Rect{6, 0, 4, 2}), std::invalid_argument);
}

TEST(Texture2D, ViewOfColourTargetsReadsWhatTheTargetReads) {
  raster::ColorTarget srgb(2, 2, raster::ColorFormat::rgba8, true);
  srgb.write(1, 0, glm::vec4(0.5f, 0.25f, 1.0f, 0.5f));
  const Texture2D v = Texture2D::view(srgb);
  EXPECT_EQ(v.format(), TexelFormat::rgba8_srgb);
  const glm::vec4 got = shading::texel_fetch(v, {1, 0});
  const glm::vec4 want = srgb.read(1, 0);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(got[c], want[c]) << c;

  raster::ColorTarget f32(3, 1, raster::ColorFormat::rgba32f);
  f32.write(2, 0, glm::vec4(-1.0f, 2.0f, 3.5f, 0.25f));
  const Texture2D vf = Texture2D::view(f32);
  EXPECT_EQ(vf.format(), TexelFormat::rgba32f);
  EXPECT_EQ(shading::texel_fetch(vf, {2, 0}), glm::vec4(-1.0f, 2.0f, 3.5f, 0.25f));
}

TEST(Texture2D, OwnedTexturesAreFilledBottomRowFirst) {
  const std::vector<float> v = {1, 2, 3, 4, 5, 6};  // rows bottom first: (1 2 3), (4 5 6)
  const Texture2D t = Texture2D::from_floats(3, 2, TexelFormat::r32f, 1, v);
  EXPECT_TRUE(t.owns_level(0));
  EXPECT_EQ(t.texel(0, 0).r, 1.0f);
  EXPECT_EQ(t.texel(2, 1).r, 6.0f);
  const Texture2D rg = Texture2D::from_floats(1, 1, TexelFormat::rgba32f, 2, std::vector<float>{0.5f, 0.75f});
  EXPECT_EQ(rg.texel(0, 0), glm::vec4(0.5f, 0.75f, 0.0f, 1.0f));
}

TEST(Texture2D, RejectsBadSizesAndWritesThroughViews) {
  EXPECT_THROW(Texture2D(0, 4, TexelFormat::r32f), std::invalid_argument);
  EXPECT_THROW(Texture2D(4, 16385, TexelFormat::r32f), std::invalid_argument);
  EXPECT_THROW(Texture2D::from_floats(2, 2, TexelFormat::r32f, 1, std::vector<float>(3)), std::invalid_argument);
  raster::DepthTarget target(4, 4, raster::DepthFormat::d32f);
  Texture2D view = Texture2D::view(target);
  EXPECT_THROW(view.set_texel(0, 0, glm::vec4(0.0f)), std::logic_error);
}

TEST(Texture2D, CopiesShareTexels) {
  Texture2D a(2, 2, TexelFormat::r32f);
  const Texture2D b = a;
  a.set_texel(1, 1, glm::vec4(9.0f));
  EXPECT_EQ(b.texel(1, 1).r, 9.0f);
}

}  // namespace
