// The 8-bit sRGB store by thresholds (see srgb8.h).
#include "raster/srgb8.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "raster/target.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

uint8_t srgb8_reference(float linear) {
  const float v = srgb_encode(std::clamp(linear, 0.0f, 1.0f));
  return uint8_t(std::nearbyint(v * 255.0f));
}

Srgb8Encoder::Srgb8Encoder() {
  // Positive floats order as their bit patterns, so each threshold is a bisection over [0, 1]'s patterns.
  const uint32_t one = std::bit_cast<uint32_t>(1.0f);
  for (unsigned code = 1; code < 256; ++code) {
    uint32_t lo = 0, hi = one;  // srgb8_reference(lo) < code <= srgb8_reference(hi)
    while (hi - lo > 1) {
      const uint32_t mid = lo + (hi - lo) / 2;
      (srgb8_reference(std::bit_cast<float>(mid)) >= code ? hi : lo) = mid;
    }
    threshold_[code] = std::bit_cast<float>(hi);
  }
  for (size_t top = 0; top < kStarts; ++top) {
    const float first = std::bit_cast<float>(uint32_t(top << 16));
    unsigned c = 0;
    while (c < 255 && first >= threshold_[c + 1]) ++c;
    start_[top] = uint8_t(c);
  }
}

SHADOWLAB_ISA_END
}  // namespace raster
