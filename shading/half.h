// IEEE binary16 ("half") conversions for RGBA16F textures: decode on every tap, encode when a texture is filled
// or a mip level is generated. Uses F16C on the AVX2 path (raster/simd/isa.h), with an exact scalar twin otherwise.
#pragma once
#include <bit>
#include <cstdint>

#if defined(SHADOWLAB_SIMD_AVX2)
#include <immintrin.h>
#endif
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

// The scalar twins, always compiled (tests hold them to the F16C instructions).
// Exact: every half value is a float value.
inline float half_to_float_soft(uint16_t h) {
  const uint32_t sign = uint32_t(h & 0x8000u) << 16;
  const uint32_t exp = (h >> 10) & 0x1Fu;
  const uint32_t man = h & 0x3FFu;
  if (exp == 0x1F) return std::bit_cast<float>(sign | 0x7F800000u | (man << 13));  // inf, NaN
  if (exp != 0) return std::bit_cast<float>(sign | ((exp + 112u) << 23) | (man << 13));
  // Zero or subnormal: man · 2^-24, exact in float.
  const float v = float(man) * 0x1p-24f;
  return sign ? -v : v;
}

// Rounds to nearest, ties to even, as GL does when it converts a float to a half-float texel. NaN stays NaN.
inline uint16_t float_to_half_soft(float f) {
  const uint32_t x = std::bit_cast<uint32_t>(f);
  const uint16_t sign = uint16_t((x >> 16) & 0x8000u);
  const uint32_t ax = x & 0x7FFFFFFFu;
  if (ax >= 0x7F800000u) return uint16_t(sign | 0x7C00u | (ax > 0x7F800000u ? 0x200u : 0u));  // inf, NaN
  if (ax >= 0x477FF000u) return uint16_t(sign | 0x7C00u);  // rounds beyond 65504: infinity
  if (ax < 0x38800000u) {
    // Result is subnormal (or zero): round |f| · 2^24 to an integer, ties to even, by adding 2^23 in float
    // arithmetic (exact rounding mode of the FPU, which is round-to-nearest-even).
    const float scaled = std::bit_cast<float>(ax) * 0x1p24f;  // exact: a power-of-two scale
    const float rounded = (scaled + 0x1p23f) - 0x1p23f;
    return uint16_t(sign | uint16_t(rounded));
  }
  // Normal: drop 13 mantissa bits with round-to-nearest-even; a carry into the exponent is what we want.
  uint32_t h = ((ax - 0x38000000u) >> 13);
  const uint32_t rest = ax & 0x1FFFu;
  if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) ++h;
  return uint16_t(sign | h);
}

inline float half_to_float(uint16_t h) {
#if defined(SHADOWLAB_SIMD_AVX2)
  return _cvtsh_ss(h);
#else
  return half_to_float_soft(h);
#endif
}

inline uint16_t float_to_half(float f) {
#if defined(SHADOWLAB_SIMD_AVX2)
  return uint16_t(_cvtss_sh(f, _MM_FROUND_TO_NEAREST_INT));
#else
  return float_to_half_soft(f);
#endif
}

SHADOWLAB_ISA_END
}  // namespace shading
