// Texel encoding: the slow, exact path used to fill textures, build mip levels and load files.
#include "shading/texel_format.h"

#include <bit>
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

namespace {
float clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }  // NaN -> 0
// As raster::ColorTarget::write rounds: round(clamp(v) · 255) in float.
uint8_t unorm8(float v) { return uint8_t(std::nearbyint(clamp01(v) * 255.0f)); }
}  // namespace

void encode_texel(TexelFormat f, std::byte* row, int i, const glm::vec4& v) {
  using detail::store;
  switch (f) {
    case TexelFormat::d16:
      store<uint16_t>(row + size_t(i) * 2, uint16_t(std::nearbyint(double(clamp01(v.r)) * 65535.0)));
      return;
    case TexelFormat::d24:
      store<uint32_t>(row + size_t(i) * 4, uint32_t(std::nearbyint(double(clamp01(v.r)) * 16777215.0)));
      return;
    case TexelFormat::d32f: store<float>(row + size_t(i) * 4, clamp01(v.r)); return;
    case TexelFormat::r32f: store<float>(row + size_t(i) * 4, v.r); return;
    case TexelFormat::rg32f:
      store<float>(row + size_t(i) * 8, v.r);
      store<float>(row + size_t(i) * 8 + 4, v.g);
      return;
    case TexelFormat::rgba8:
    case TexelFormat::rgba8_srgb: {
      const bool srgb = f == TexelFormat::rgba8_srgb;
      std::byte* p = row + size_t(i) * 4;
      for (int c = 0; c < 4; ++c) {
        const float x = (srgb && c < 3) ? raster::srgb_encode(v[c]) : v[c];
        p[c] = std::byte(unorm8(x));
      }
      return;
    }
    case TexelFormat::rgba16f:
      for (int c = 0; c < 4; ++c) store<uint16_t>(row + size_t(i) * 8 + size_t(c) * 2, float_to_half(v[c]));
      return;
    case TexelFormat::rgba32f:
      for (int c = 0; c < 4; ++c) store<float>(row + size_t(i) * 16 + size_t(c) * 4, v[c]);
      return;
  }
}

SHADOWLAB_ISA_END
}  // namespace shading
