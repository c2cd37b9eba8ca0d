// Mip generation: GL's level sizes and the box filter, with hand-computed means for even and odd sizes, in
// linear space for sRGB, and on views of render targets.
#include <gtest/gtest.h>

#include <vector>

#include "raster/target.h"
#include "shading/mip_chain.h"
#include "shading/texture.h"

namespace {

using shading::TexelFormat;
using shading::Texture2D;

TEST(MipChain, LevelSizesHalveWithFloorDownToOne) {
  EXPECT_EQ(shading::mip_level_count(8, 2), 4);
  EXPECT_EQ(shading::mip_level_count(5, 3), 3);
  EXPECT_EQ(shading::mip_level_count(1, 1), 1);
  EXPECT_EQ(shading::mip_level_count(16384, 1), 15);
  const Texture2D t(8, 2, TexelFormat::r32f, true);
  ASSERT_EQ(t.levels(), 4);
  const int w[] = {8, 4, 2, 1}, h[] = {2, 1, 1, 1};
  for (int l = 0; l < 4; ++l) {
    EXPECT_EQ(t.width(l), w[l]);
    EXPECT_EQ(t.height(l), h[l]);
  }
  const Texture2D odd(5, 3, TexelFormat::r32f, true);
  EXPECT_EQ(odd.width(1), 2);
  EXPECT_EQ(odd.height(1), 1);
}

TEST(MipChain, EvenSizesAverageTwoByTwoBlocks) {
  // 4 × 2, rows bottom first: (1 2 3 4), (5 6 7 8) → level 1: (1+2+5+6)/4 = 3.5, (3+4+7+8)/4 = 5.5.
  const Texture2D t =
      Texture2D::from_floats(4, 2, TexelFormat::r32f, 1, std::vector<float>{1, 2, 3, 4, 5, 6, 7, 8}, true);
  EXPECT_EQ(t.texel(0, 0, 1).r, 3.5f);
  EXPECT_EQ(t.texel(1, 0, 1).r, 5.5f);
  EXPECT_EQ(t.texel(0, 0, 2).r, 4.5f);
}

TEST(MipChain, OddSizesWeighPartlyCoveredTexels) {
  // 5 → 2: texel 0 covers source [0, 2.5): weights 0.4, 0.4, 0.2; texel 1 covers [2.5, 5): 0.2, 0.4, 0.4.
  const Texture2D t = Texture2D::from_floats(5, 1, TexelFormat::r32f, 1, std::vector<float>{1, 2, 4, 8, 16}, true);
  EXPECT_FLOAT_EQ(t.texel(0, 0, 1).r, 0.4f * 1 + 0.4f * 2 + 0.2f * 4);   // 2.0
  EXPECT_FLOAT_EQ(t.texel(1, 0, 1).r, 0.2f * 4 + 0.4f * 8 + 0.4f * 16);  // 10.4
  // 3 → 1: the plain mean.
  const Texture2D u = Texture2D::from_floats(3, 1, TexelFormat::r32f, 1, std::vector<float>{3, 6, 12}, true);
  EXPECT_FLOAT_EQ(u.texel(0, 0, 1).r, 7.0f);
}

TEST(MipChain, EncodedFormatsAverageDecodedValues) {
  // rgba8: bytes 10 and 14 → 12.
  Texture2D a(2, 1, TexelFormat::rgba8);
  a.set_texel(0, 0, glm::vec4(10 / 255.0f));
  a.set_texel(1, 0, glm::vec4(14 / 255.0f));
  a.generate_mips();
  EXPECT_EQ(a.texel(0, 0, 1).r, 12 / 255.0f);
  // sRGB: black and white average to linear 0.5, stored as sRGB byte 188 (0.7354 · 255 = 187.5).
  Texture2D s(2, 1, TexelFormat::rgba8_srgb);
  s.set_texel(0, 0, glm::vec4(0.0f));
  s.set_texel(1, 0, glm::vec4(1.0f));
  s.generate_mips();
  EXPECT_EQ(s.level(1).data[0], std::byte{188});
  EXPECT_EQ(s.level(1).data[3], std::byte{128});  // alpha 0.5 linear: 127.5 → 128
  // d16: codes 0 and 65535 → 0.5 → code 32768 (32767.5 to even).
  Texture2D d(2, 1, TexelFormat::d16);
  d.set_texel(0, 0, glm::vec4(0.0f));
  d.set_texel(1, 0, glm::vec4(1.0f));
  d.generate_mips();
  EXPECT_EQ(d.texel(0, 0, 1).r, 32768 / 65535.0f);
}

TEST(MipChain, ViewsOfTargetsGetMipsThatFollowTheTarget) {
  raster::DepthTarget target(2, 2, raster::DepthFormat::d32f);
  target.clear(0.5f);
  Texture2D v = Texture2D::view(target);
  v.generate_mips();
  ASSERT_EQ(v.levels(), 2);
  EXPECT_FALSE(v.owns_level(0));
  EXPECT_TRUE(v.owns_level(1));
  EXPECT_EQ(v.texel(0, 0, 1).r, 0.5f);
  target.row<float>(0)[0] = 0.0f;  // mean becomes (0 + 0.5·3)/4 = 0.375
  v.generate_mips();
  EXPECT_EQ(v.texel(0, 0, 1).r, 0.375f);
  EXPECT_EQ(v.level(0).data, reinterpret_cast<const std::byte*>(target.row<float>(0)));  // still the target
}

}  // namespace
