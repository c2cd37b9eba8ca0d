// AVX2 implementation of the eight-lane value types (see vec.h). Every function is a thin, named wrapper of
// one or two intrinsics, so the stage code reads like the maths.
#pragma once
#include <immintrin.h>

#include <cstdint>

namespace raster::simd {

struct VecI32 {
  __m256i v;
  static VecI32 splat(int32_t x) { return {_mm256_set1_epi32(x)}; }
  static VecI32 iota() { return {_mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7)}; }
  static VecI32 load(const int32_t* p) { return {_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p))}; }
  static VecI32 load_u32(const uint32_t* p) { return {_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p))}; }
  static VecI32 load_u16(const uint16_t* p) {
    return {_mm256_cvtepu16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)))};
  }
  void store_u32(uint32_t* p) const { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v); }
  // Lanes hold values in [0, 65535]; stores them as eight uint16.
  void store_u16(uint16_t* p) const {
    const __m256i packed = _mm256_packus_epi32(v, v);  // per 128-bit half: [a0..a3 a0..a3 | a4..a7 a4..a7]
    const __m256i ordered = _mm256_permute4x64_epi64(packed, 0x08);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm256_castsi256_si128(ordered));
  }
  friend VecI32 operator+(VecI32 a, VecI32 b) { return {_mm256_add_epi32(a.v, b.v)}; }
  friend VecI32 operator-(VecI32 a, VecI32 b) { return {_mm256_sub_epi32(a.v, b.v)}; }
  friend VecI32 operator*(VecI32 a, VecI32 b) { return {_mm256_mullo_epi32(a.v, b.v)}; }
  friend VecI32 operator|(VecI32 a, VecI32 b) { return {_mm256_or_si256(a.v, b.v)}; }
  friend VecI32 operator&(VecI32 a, VecI32 b) { return {_mm256_and_si256(a.v, b.v)}; }
};

struct VecF32 {
  __m256 v;
  static VecF32 splat(float x) { return {_mm256_set1_ps(x)}; }
  static VecF32 iota() { return {_mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7)}; }
  static VecF32 load(const float* p) { return {_mm256_loadu_ps(p)}; }
  void store(float* p) const { _mm256_storeu_ps(p, v); }
  friend VecF32 operator+(VecF32 a, VecF32 b) { return {_mm256_add_ps(a.v, b.v)}; }
  friend VecF32 operator-(VecF32 a, VecF32 b) { return {_mm256_sub_ps(a.v, b.v)}; }
  friend VecF32 operator*(VecF32 a, VecF32 b) { return {_mm256_mul_ps(a.v, b.v)}; }
};

// a · b + c with a single rounding.
inline VecF32 fma(VecF32 a, VecF32 b, VecF32 c) { return {_mm256_fmadd_ps(a.v, b.v, c.v)}; }
inline VecF32 min(VecF32 a, VecF32 b) { return {_mm256_min_ps(a.v, b.v)}; }
inline VecF32 max(VecF32 a, VecF32 b) { return {_mm256_max_ps(a.v, b.v)}; }
inline VecF32 to_float(VecI32 a) { return {_mm256_cvtepi32_ps(a.v)}; }
// Round to nearest, ties to even (the default rounding mode).
inline VecI32 round_to_int(VecF32 a) { return {_mm256_cvtps_epi32(a.v)}; }
inline VecF32 bitcast_f32(VecI32 a) { return {_mm256_castsi256_ps(a.v)}; }
inline VecI32 bitcast_i32(VecF32 a) { return {_mm256_castps_si256(a.v)}; }

// A lane mask: every bit of a lane set (true) or clear (false).
struct Mask {
  __m256i v;
  static Mask all() { return {_mm256_set1_epi32(-1)}; }
  // Lanes whose bit is set in the low 8 bits of m.
  static Mask from_bits(unsigned m) {
    const __m256i bits = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    return {_mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(int(m)), bits), bits)};
  }
  unsigned bits() const { return unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(v))); }
  bool any() const { return !_mm256_testz_si256(v, v); }
  friend Mask operator&(Mask a, Mask b) { return {_mm256_and_si256(a.v, b.v)}; }
  friend Mask operator|(Mask a, Mask b) { return {_mm256_or_si256(a.v, b.v)}; }
  // a and not b
  friend Mask and_not(Mask a, Mask b) { return {_mm256_andnot_si256(b.v, a.v)}; }
};

// Lanes whose value is negative.
inline Mask negative(VecI32 a) { return {_mm256_srai_epi32(a.v, 31)}; }
// Lanes whose value is >= 0.
inline Mask non_negative(VecI32 a) { return {_mm256_xor_si256(_mm256_srai_epi32(a.v, 31), _mm256_set1_epi32(-1))}; }

inline Mask cmp_lt(VecF32 a, VecF32 b) { return {_mm256_castps_si256(_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ))}; }
inline Mask cmp_le(VecF32 a, VecF32 b) { return {_mm256_castps_si256(_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ))}; }
inline Mask cmp_eq(VecF32 a, VecF32 b) { return {_mm256_castps_si256(_mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ))}; }
inline Mask cmp_neq(VecF32 a, VecF32 b) { return {_mm256_castps_si256(_mm256_cmp_ps(a.v, b.v, _CMP_NEQ_UQ))}; }
inline Mask cmp_lt(VecI32 a, VecI32 b) { return {_mm256_cmpgt_epi32(b.v, a.v)}; }
inline Mask cmp_le(VecI32 a, VecI32 b) { return and_not(Mask::all(), Mask{_mm256_cmpgt_epi32(a.v, b.v)}); }
inline Mask cmp_eq(VecI32 a, VecI32 b) { return {_mm256_cmpeq_epi32(a.v, b.v)}; }
inline Mask cmp_neq(VecI32 a, VecI32 b) { return and_not(Mask::all(), Mask{_mm256_cmpeq_epi32(a.v, b.v)}); }

// Lane l of the result is b where m is true, else a.
inline VecF32 select(Mask m, VecF32 a, VecF32 b) { return {_mm256_blendv_ps(a.v, b.v, _mm256_castsi256_ps(m.v))}; }
inline VecI32 select(Mask m, VecI32 a, VecI32 b) { return {_mm256_blendv_epi8(a.v, b.v, m.v)}; }

}  // namespace raster::simd
