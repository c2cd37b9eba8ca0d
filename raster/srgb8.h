// The 8-bit sRGB store without a pow per channel: GL's conversion into an sRGB RGBA8 target (clamp to [0, 1],
// srgb_encode, round(c · 255); ColorTarget::write) as 255 thresholds on the linear value, found once by bisection
// over the float bit patterns with srgb_encode itself, so a code is exactly the one write() stores (tested at
// every threshold's neighbours and over the whole of [0, 1]). The frame's development (scenes/frame/develop.h)
// encodes a million pixels with it; building the table costs about 7,000 srgb_encode calls.
#pragma once
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

class Srgb8Encoder {
 public:
  Srgb8Encoder();
  // write()'s byte for a linear value: 0 below the first threshold and for NaN, 255 from the last one up. The
  // value's top 16 bits pick the code at the start of their range of floats, and the thresholds inside that
  // range (rarely more than one) are stepped over.
  uint8_t operator()(float linear) const {
    if (!(linear > 0.0f)) return 0;
    if (linear >= 1.0f) return 255;
    unsigned c = start_[std::bit_cast<uint32_t>(linear) >> 16];
    while (c < 255 && linear >= threshold_[c + 1]) ++c;
    return uint8_t(c);
  }
  // The smallest float that write() stores as `code` or more (code 1..255).
  float threshold(unsigned code) const { return threshold_[code]; }

 private:
  static constexpr size_t kStarts = (0x3F800000u >> 16) + 1;  // the top 16 bits of the floats in [0, 1]
  std::array<float, 256> threshold_{};   // [0] unused
  std::array<uint8_t, kStarts> start_{};  // the code of the smallest float with those top bits
};

// write()'s byte for one channel of an sRGB target, computed as write() does (srgb_encode and round).
uint8_t srgb8_reference(float linear);

SHADOWLAB_ISA_END
}  // namespace raster
