// simd::store_select (raster/simd/vec_avx2.h, vec_scalar.h; the set the tests are built for, see CMakeLists.txt;
// the AVX-512 masked form runs in tests/cli/isa_dispatch_test.cpp's paths and in an SHADOWLAB_ISAS=avx512 build):
// for every one of the 256 lane masks, the lanes in the mask get the new value bit for bit (NaN payloads and
// negative zero included), the others keep what the row held, and nothing either side of the eight floats changes.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>

#include "raster/simd/vec.h"

using namespace raster;

TEST(SimdStore, StoreSelectWritesExactlyTheMaskedLanes) {
  const uint32_t kSentinel = 0x7fc0beefu;  // a quiet NaN with a payload, unlikely to be written by chance
  const float fresh[8] = {0.25f, -0.0f, 1.0f, std::bit_cast<float>(0x7fc01234u), 1e-40f, 0.5f, 3.0f, -2.0f};
  const float held[8] = {1.0f, 0.0f, std::bit_cast<float>(0x7fa00001u), 0.75f, -1e-40f, 0.125f, 1.0f, 0.0f};
  for (unsigned m = 0; m < 256; ++m) {
    alignas(32) float row[10];
    row[0] = row[9] = std::bit_cast<float>(kSentinel);
    std::memcpy(row + 1, held, sizeof held);
    const simd::VecF32 a = simd::VecF32::load(row + 1), b = simd::VecF32::load(fresh);
    simd::store_select(simd::Mask::from_bits(m), a, b, row + 1);
    SCOPED_TRACE(testing::Message() << "mask " << m);
    EXPECT_EQ(std::bit_cast<uint32_t>(row[0]), kSentinel);
    EXPECT_EQ(std::bit_cast<uint32_t>(row[9]), kSentinel);
    for (int l = 0; l < 8; ++l) {
      const float want = (m >> l & 1) ? fresh[l] : held[l];
      EXPECT_EQ(std::bit_cast<uint32_t>(row[1 + l]), std::bit_cast<uint32_t>(want)) << "lane " << l;
    }
  }
}
