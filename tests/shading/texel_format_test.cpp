// Texel decoding and encoding: depth codes as the raster stores them, half floats, unorm and sRGB rounding.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <vector>

#include "raster/target.h"
#include "shading/half.h"
#include "shading/texel_format.h"

namespace {

using shading::TexelFormat;

TEST(TexelFormat, D16DecodesEveryCodeAsTheDepthTargetDoes) {
  // DepthTarget::value divides in double; the texel decoder divides in float. Every code must agree.
  for (uint32_t code = 0; code <= 0xFFFFu; ++code) {
    const uint16_t c = uint16_t(code);
    std::byte row[2];
    std::memcpy(row, &c, 2);
    ASSERT_EQ(shading::Texel<TexelFormat::d16>::red(row, 0), float(double(code) / 65535.0)) << code;
  }
}

TEST(TexelFormat, D24DecodesEveryCodeAsTheDepthTargetDoesAndIgnoresTheTopByte) {
  for (uint32_t code = 0; code <= 0xFFFFFFu; ++code) {
    const uint32_t c = code | (code % 7 == 0 ? 0xAB000000u : 0u);  // stencil-like bits above the depth
    std::byte row[4];
    std::memcpy(row, &c, 4);
    const float got = shading::Texel<TexelFormat::d24>::red(row, 0);
    if (got != float(double(code) / 16777215.0)) FAIL() << "code " << code;
  }
}

TEST(TexelFormat, DepthEncodingRoundsToNearestCodeAndClamps) {
  std::byte row[4];
  shading::encode_texel(TexelFormat::d16, row, 0, glm::vec4(0.5f));
  uint16_t c16;
  std::memcpy(&c16, row, 2);
  EXPECT_EQ(c16, 32768u);  // 0.5 · 65535 = 32767.5, ties to even
  shading::encode_texel(TexelFormat::d16, row, 0, glm::vec4(-3.0f));
  std::memcpy(&c16, row, 2);
  EXPECT_EQ(c16, 0u);
  shading::encode_texel(TexelFormat::d24, row, 0, glm::vec4(0.25f));
  uint32_t c24;
  std::memcpy(&c24, row, 4);
  EXPECT_EQ(c24, 4194304u);  // 0.25 · 16777215 = 4194303.75
  shading::encode_texel(TexelFormat::d32f, row, 0, glm::vec4(1.5f));
  float f;
  std::memcpy(&f, row, 4);
  EXPECT_EQ(f, 1.0f);
}

TEST(TexelFormat, ColourFormatsReadMissingComponentsAsGLDoes) {
  std::byte row[16];
  shading::encode_texel(TexelFormat::r32f, row, 0, glm::vec4(7.0f, 8.0f, 9.0f, 10.0f));
  EXPECT_EQ(shading::decode_texel(TexelFormat::r32f, row, 0), glm::vec4(7.0f, 0.0f, 0.0f, 1.0f));
  shading::encode_texel(TexelFormat::rg32f, row, 0, glm::vec4(7.0f, 8.0f, 9.0f, 10.0f));
  EXPECT_EQ(shading::decode_texel(TexelFormat::rg32f, row, 0), glm::vec4(7.0f, 8.0f, 0.0f, 1.0f));
  shading::encode_texel(TexelFormat::d32f, row, 0, glm::vec4(0.25f, 8.0f, 9.0f, 10.0f));
  EXPECT_EQ(shading::decode_texel(TexelFormat::d32f, row, 0), glm::vec4(0.25f, 0.0f, 0.0f, 1.0f));
  shading::encode_texel(TexelFormat::rgba32f, row, 0, glm::vec4(-7.0f, 8.0f, 9.0f, 10.0f));
  EXPECT_EQ(shading::decode_texel(TexelFormat::rgba32f, row, 0), glm::vec4(-7.0f, 8.0f, 9.0f, 10.0f));
}

TEST(TexelFormat, Rgba8RoundsAndClamps) {
  std::byte row[4];
  shading::encode_texel(TexelFormat::rgba8, row, 0, glm::vec4(0.5f, 2.0f, -1.0f, 0.2f));
  EXPECT_EQ(uint8_t(row[0]), 128u);  // 127.5 rounds to even: 128
  EXPECT_EQ(uint8_t(row[1]), 255u);
  EXPECT_EQ(uint8_t(row[2]), 0u);
  EXPECT_EQ(uint8_t(row[3]), 51u);  // 0.2 · 255 = 51
  EXPECT_EQ(shading::decode_texel(TexelFormat::rgba8, row, 0), glm::vec4(128 / 255.0f, 1.0f, 0.0f, 51 / 255.0f));
}

TEST(TexelFormat, Rgba8SrgbEncodesColourNotAlphaAndDecodesWithTheSrgbCurve) {
  std::byte row[4];
  shading::encode_texel(TexelFormat::rgba8_srgb, row, 0, glm::vec4(0.5f, 0.0f, 1.0f, 0.5f));
  // sRGB(0.5) = 1.055 · 0.5^(1/2.4) − 0.055 = 0.7353569…, · 255 = 187.52 → 188.
  EXPECT_EQ(uint8_t(row[0]), 188u);
  EXPECT_EQ(uint8_t(row[1]), 0u);
  EXPECT_EQ(uint8_t(row[2]), 255u);
  EXPECT_EQ(uint8_t(row[3]), 128u);  // alpha is linear
  const glm::vec4 v = shading::decode_texel(TexelFormat::rgba8_srgb, row, 0);
  const double e = 188.0 / 255.0;
  EXPECT_NEAR(v.r, std::pow((e + 0.055) / 1.055, 2.4), 1e-6);
  EXPECT_EQ(v.a, 128 / 255.0f);
}

TEST(Half, KnownValuesAndTiesToEven) {
  EXPECT_EQ(shading::float_to_half(1.0f), 0x3C00u);
  EXPECT_EQ(shading::float_to_half(-2.0f), 0xC000u);
  EXPECT_EQ(shading::float_to_half(0.1f), 0x2E66u);  // 1.599609375 · 2^-4
  EXPECT_EQ(shading::half_to_float(0x2E66u), 0.0999755859375f);
  EXPECT_EQ(shading::half_to_float(shading::float_to_half(2049.0f)), 2048.0f);  // tie, even mantissa below
  EXPECT_EQ(shading::half_to_float(shading::float_to_half(2051.0f)), 2052.0f);  // tie, even mantissa above
  EXPECT_EQ(shading::half_to_float(shading::float_to_half(65519.0f)), 65504.0f);
  EXPECT_TRUE(std::isinf(shading::half_to_float(shading::float_to_half(65520.0f))));
  EXPECT_EQ(shading::float_to_half(0x1p-24f), 0x0001u);      // smallest subnormal
  EXPECT_EQ(shading::float_to_half(0x1p-25f), 0x0000u);      // tie between 0 and 2^-24: even is 0
  EXPECT_EQ(shading::float_to_half(3 * 0x1p-25f), 0x0002u);  // tie between 1 and 2 (· 2^-24): 2
  EXPECT_EQ(shading::half_to_float(0x0001u), 0x1p-24f);
}

TEST(Half, ScalarTwinMatchesTheHardwareConversion) {
  for (uint32_t h = 0; h <= 0xFFFFu; ++h) {
    const float a = shading::half_to_float(uint16_t(h)), b = shading::half_to_float_soft(uint16_t(h));
    if (std::isnan(a)) {
      ASSERT_TRUE(std::isnan(b)) << h;
    } else {
      ASSERT_EQ(std::bit_cast<uint32_t>(a), std::bit_cast<uint32_t>(b)) << h;
    }
  }
  // Every float whose low 10 bits are zero (4M values spanning all exponents and the rounding cases).
  for (uint32_t x = 0; x < (1u << 22); ++x) {
    const float f = std::bit_cast<float>(x << 10);
    if (std::isnan(f)) continue;
    ASSERT_EQ(shading::float_to_half(f), shading::float_to_half_soft(f)) << f;
  }
}

}  // namespace
