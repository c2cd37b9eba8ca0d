// AVX-512 implementation of the sixteen-lane value types (see vec.h): one zmm register per value, two pixel rows
// of a block (lanes 0–7 the upper row at r0, 8–15 the lower at r1), and Mask16 as an opmask register. Each
// operation is the 512-bit form of its AVX2 twin in vec_avx2.h, with the same IEEE results: min/max return the
// second operand when either is NaN, conversion rounds to nearest even, compares are the same predicates. The
// reference for every function is vec16_halves.h, which the AVX2 and scalar sets use; the instruction-set
// comparison test (tests/cli/isa_dispatch_test.cpp) checks the two give the same bytes.
//
// GCC 12's plain forms of min, max and the conversions pass an undefined vector as the unused source of an
// all-lanes mask, and -Wmaybe-uninitialized reports it at every inlined use; their zero-masking forms with all
// sixteen lanes selected are the same instructions without that source, so those are used. For the same
// reason the lower half is taken with an extract of half 0 (no instruction) rather than a 512-to-256 cast;
// the 256-to-512 casts and the other extracts are warning-free and used as they are.
#pragma once
#include <immintrin.h>

#include <cstdint>
#include "raster/simd/isa.h"

namespace raster::simd {
SHADOWLAB_ISA_BEGIN

inline constexpr __mmask16 kAll = 0xFFFF;  // every lane, for the zero-masking forms (see above)

struct Mask16 {
  __mmask16 m;
  static Mask16 from_bits(unsigned b) { return {__mmask16(b & 0xFFFFu)}; }
  static Mask16 rows(Mask lo, Mask hi) { return {__mmask16(lo.bits() | hi.bits() << 8)}; }
  unsigned bits() const { return unsigned(m); }
  bool any() const { return m != 0; }
};
inline Mask16 operator&(Mask16 a, Mask16 b) { return {__mmask16(a.m & b.m)}; }
inline Mask16 operator|(Mask16 a, Mask16 b) { return {__mmask16(a.m | b.m)}; }
inline Mask16 and_not(Mask16 a, Mask16 b) { return {__mmask16(a.m & ~b.m)}; }

struct VecI32x16 {
  __m512i v;
  static VecI32x16 splat(int32_t x) { return {_mm512_set1_epi32(x)}; }
  static VecI32x16 rows(VecI32 lo, VecI32 hi) { return {_mm512_inserti32x8(_mm512_castsi256_si512(lo.v), hi.v, 1)}; }
  static VecI32x16 load_rows_u32(const uint32_t* r0, const uint32_t* r1) {
    return rows(VecI32::load_u32(r0), VecI32::load_u32(r1));
  }
  static VecI32x16 load_rows_u16(const uint16_t* r0, const uint16_t* r1) {
    const __m128i lo = _mm_loadu_si128(reinterpret_cast<const __m128i*>(r0));
    const __m128i hi = _mm_loadu_si128(reinterpret_cast<const __m128i*>(r1));
    return {_mm512_maskz_cvtepu16_epi32(kAll, _mm256_inserti128_si256(_mm256_zextsi128_si256(lo), hi, 1))};
  }
  void store_rows_u32(uint32_t* r0, uint32_t* r1) const {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(r0), _mm512_extracti32x8_epi32(v, 0));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(r1), _mm512_extracti32x8_epi32(v, 1));
  }
  // Lanes hold values in [0, 65535], so the truncating narrowing keeps them as they are.
  void store_rows_u16(uint16_t* r0, uint16_t* r1) const {
    const __m256i packed = _mm512_maskz_cvtepi32_epi16(kAll, v);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(r0), _mm256_castsi256_si128(packed));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(r1), _mm256_extracti128_si256(packed, 1));
  }
};
inline VecI32x16 operator+(VecI32x16 a, VecI32x16 b) { return {_mm512_add_epi32(a.v, b.v)}; }
inline VecI32x16 operator|(VecI32x16 a, VecI32x16 b) { return {_mm512_or_si512(a.v, b.v)}; }

struct VecF32x16 {
  __m512 v;
  static VecF32x16 splat(float x) { return {_mm512_set1_ps(x)}; }
  static VecF32x16 rows(VecF32 lo, VecF32 hi) { return {_mm512_insertf32x8(_mm512_castps256_ps512(lo.v), hi.v, 1)}; }
  static VecF32x16 load_rows(const float* r0, const float* r1) { return rows(VecF32::load(r0), VecF32::load(r1)); }
  void store_rows(float* r0, float* r1) const {
    _mm256_storeu_ps(r0, _mm512_extractf32x8_ps(v, 0));
    _mm256_storeu_ps(r1, _mm512_extractf32x8_ps(v, 1));
  }
  VecF32 row0() const { return {_mm512_extractf32x8_ps(v, 0)}; }
  VecF32 row1() const { return {_mm512_extractf32x8_ps(v, 1)}; }
};
inline VecF32x16 operator+(VecF32x16 a, VecF32x16 b) { return {_mm512_add_ps(a.v, b.v)}; }
inline VecF32x16 operator*(VecF32x16 a, VecF32x16 b) { return {_mm512_mul_ps(a.v, b.v)}; }
inline VecF32x16 fma(VecF32x16 a, VecF32x16 b, VecF32x16 c) { return {_mm512_fmadd_ps(a.v, b.v, c.v)}; }
inline VecF32x16 min(VecF32x16 a, VecF32x16 b) { return {_mm512_maskz_min_ps(kAll, a.v, b.v)}; }
inline VecF32x16 max(VecF32x16 a, VecF32x16 b) { return {_mm512_maskz_max_ps(kAll, a.v, b.v)}; }
// Round to nearest, ties to even (the default rounding mode), as _mm256_cvtps_epi32.
inline VecI32x16 round_to_int(VecF32x16 a) { return {_mm512_maskz_cvtps_epi32(kAll, a.v)}; }

inline Mask16 non_negative(VecI32x16 a) { return {_mm512_cmpge_epi32_mask(a.v, _mm512_setzero_si512())}; }
inline Mask16 cmp_lt(VecF32x16 a, VecF32x16 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ)}; }
inline Mask16 cmp_le(VecF32x16 a, VecF32x16 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LE_OQ)}; }
inline Mask16 cmp_eq(VecF32x16 a, VecF32x16 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_EQ_OQ)}; }
inline Mask16 cmp_neq(VecF32x16 a, VecF32x16 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_NEQ_UQ)}; }
inline Mask16 cmp_lt(VecI32x16 a, VecI32x16 b) { return {_mm512_cmplt_epi32_mask(a.v, b.v)}; }
inline Mask16 cmp_le(VecI32x16 a, VecI32x16 b) { return {_mm512_cmple_epi32_mask(a.v, b.v)}; }
inline Mask16 cmp_eq(VecI32x16 a, VecI32x16 b) { return {_mm512_cmpeq_epi32_mask(a.v, b.v)}; }
inline Mask16 cmp_neq(VecI32x16 a, VecI32x16 b) { return {_mm512_cmpneq_epi32_mask(a.v, b.v)}; }

// Lane l of the result is b where m is true, else a.
inline VecF32x16 select(Mask16 m, VecF32x16 a, VecF32x16 b) { return {_mm512_mask_blend_ps(m.m, a.v, b.v)}; }
inline VecI32x16 select(Mask16 m, VecI32x16 a, VecI32x16 b) { return {_mm512_mask_blend_epi32(m.m, a.v, b.v)}; }

SHADOWLAB_ISA_END
}  // namespace raster::simd
