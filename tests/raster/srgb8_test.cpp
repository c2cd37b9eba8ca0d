// The 8-bit sRGB store by thresholds (raster/srgb8.h) gives exactly the byte ColorTarget::write stores into an
// sRGB target: around every threshold, over [0, 1] at a stride, and for the values write() clamps.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "raster/srgb8.h"
#include "raster/target.h"

namespace {

// The byte write() stores in an sRGB RGBA8 target's red channel.
uint8_t written(float v) {
  raster::ColorTarget t(1, 1, raster::ColorFormat::rgba8, true);
  t.write(0, 0, glm::vec4(v, 0.0f, 0.0f, 1.0f));
  return t.row8(0)[0];
}

}  // namespace

TEST(Srgb8, ReferenceIsWhatWriteStores) {
  for (float v : {0.0f, 1e-6f, 0.0031308f, 0.01f, 0.2f, 0.5f, 0.999f, 1.0f, 2.0f, -1.0f})
    EXPECT_EQ(raster::srgb8_reference(v), written(v)) << v;
}

TEST(Srgb8, EveryThresholdSplitsTheCodesWhereWriteDoes) {
  const raster::Srgb8Encoder e;
  for (unsigned code = 1; code < 256; ++code) {
    const float t = e.threshold(code);
    ASSERT_GE(raster::srgb8_reference(t), code);
    ASSERT_LT(raster::srgb8_reference(std::nextafter(t, 0.0f)), code);
    // 4096 floats on either side: the same byte as write()'s.
    const uint32_t bits = std::bit_cast<uint32_t>(t);
    for (uint32_t b = bits > 4096 ? bits - 4096 : 0; b <= bits + 4096; ++b) {
      const float v = std::bit_cast<float>(b);
      ASSERT_EQ(e(v), raster::srgb8_reference(v)) << "code " << code << ", value " << v;
    }
  }
}

TEST(Srgb8, AgreesWithWriteOverTheUnitIntervalAndOutside) {
  const raster::Srgb8Encoder e;
  // Every 61st float of [0, 1] (17 million values, each bit pattern's low bits visited).
  for (uint32_t b = 0; b <= std::bit_cast<uint32_t>(1.0f); b += 61) {
    const float v = std::bit_cast<float>(b);
    ASSERT_EQ(e(v), raster::srgb8_reference(v)) << v;
  }
  const float inf = std::numeric_limits<float>::infinity();
  for (float v : {-0.0f, -1e-30f, -1.0f, -inf, 1.0f, 1.0000001f, 7.0f, inf})
    EXPECT_EQ(e(v), raster::srgb8_reference(v)) << v;
  // NaN: 0 (write()'s float-to-byte conversion of a NaN is undefined; on x86 it gives 0 too).
  EXPECT_EQ(e(std::numeric_limits<float>::quiet_NaN()), 0);
}
