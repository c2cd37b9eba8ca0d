// AVX2 implementation of the eight-lane value types (see vec.h). Every function is a thin, named wrapper of
// one or two intrinsics, so the stage code reads like the maths. The operators are free functions, not friends
// defined in the class: GCC does not apply raster/simd/isa.h's target pragma to a friend defined in a class.
#pragma once
#include <immintrin.h>

#include <cstddef>
#include <cstdint>
#include "raster/simd/isa.h"

namespace raster::simd {
SHADOWLAB_ISA_BEGIN

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
};
inline VecI32 operator+(VecI32 a, VecI32 b) { return {_mm256_add_epi32(a.v, b.v)}; }
inline VecI32 operator-(VecI32 a, VecI32 b) { return {_mm256_sub_epi32(a.v, b.v)}; }
inline VecI32 operator*(VecI32 a, VecI32 b) { return {_mm256_mullo_epi32(a.v, b.v)}; }
inline VecI32 operator|(VecI32 a, VecI32 b) { return {_mm256_or_si256(a.v, b.v)}; }
inline VecI32 operator&(VecI32 a, VecI32 b) { return {_mm256_and_si256(a.v, b.v)}; }

struct VecF32 {
  __m256 v;
  static VecF32 splat(float x) { return {_mm256_set1_ps(x)}; }
  static VecF32 iota() { return {_mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7)}; }
  static VecF32 load(const float* p) { return {_mm256_loadu_ps(p)}; }
  void store(float* p) const { _mm256_storeu_ps(p, v); }
};
inline VecF32 operator+(VecF32 a, VecF32 b) { return {_mm256_add_ps(a.v, b.v)}; }
inline VecF32 operator-(VecF32 a, VecF32 b) { return {_mm256_sub_ps(a.v, b.v)}; }
inline VecF32 operator*(VecF32 a, VecF32 b) { return {_mm256_mul_ps(a.v, b.v)}; }

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
};
inline Mask operator&(Mask a, Mask b) { return {_mm256_and_si256(a.v, b.v)}; }
inline Mask operator|(Mask a, Mask b) { return {_mm256_or_si256(a.v, b.v)}; }
// a and not b
inline Mask and_not(Mask a, Mask b) { return {_mm256_andnot_si256(b.v, a.v)}; }

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
// Writes select(m, a, b) to p, where a is what p already holds (the caller has read it): lanes outside m keep
// their value. AVX-512 builds write only m's lanes, with a masked store (mask register, no three-micro-op
// vblendvps); AVX2 ones blend and write all eight. In the narrow triangles' rows (depth_stage.h,
// DepthOnlyStage::row), measured on the 2-core KVM Xeon (family 6, model 167), 2 threads, without llvmpipe, noisy:
// the dragon's back end faster in 18 of 25 paired rounds, median ratio about 0.92 (docs/performance-log.md,
// 2026-12-03).
inline void store_select(Mask m, VecF32 a, VecF32 b, float* p) {
#if defined(SHADOWLAB_SIMD_AVX512)
  (void)a;
  _mm256_mask_storeu_ps(p, _mm256_movepi32_mask(m.v), b.v);
#else
  _mm256_storeu_ps(p, _mm256_blendv_ps(a.v, b.v, _mm256_castsi256_ps(m.v)));
#endif
}

// ---- For the shaded back end's 4×2 pixel groups (lanes 0–3 one row, 4–7 the next) and its colour writes.
// Lane l of the result is a's lane idx[l] (idx in 0..7).
inline VecF32 permute(VecF32 a, VecI32 idx) { return {_mm256_permutevar8x32_ps(a.v, idx.v)}; }
template <int N>
inline VecI32 shift_left(VecI32 a) { return {_mm256_slli_epi32(a.v, N)}; }
// Lanes 0–3 from four values at r0, lanes 4–7 from four at r1, and the reverse.
inline VecF32 load_rows4(const float* r0, const float* r1) {
  return {_mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(r0)), _mm_loadu_ps(r1), 1)};
}
inline void store_rows4(VecF32 a, float* r0, float* r1) {
  _mm_storeu_ps(r0, _mm256_castps256_ps128(a.v));
  _mm_storeu_ps(r1, _mm256_extractf128_ps(a.v, 1));
}
inline VecI32 load_rows4(const uint32_t* r0, const uint32_t* r1) {
  return {_mm256_inserti128_si256(_mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(r0))),
                                  _mm_loadu_si128(reinterpret_cast<const __m128i*>(r1)), 1)};
}
inline void store_rows4(VecI32 a, uint32_t* r0, uint32_t* r1) {
  _mm_storeu_si128(reinterpret_cast<__m128i*>(r0), _mm256_castsi256_si128(a.v));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(r1), _mm256_extracti128_si256(a.v, 1));
}
inline VecI32 load_rows4(const uint16_t* r0, const uint16_t* r1) {
  const __m128i lo = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(r0));
  const __m128i hi = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(r1));
  return {_mm256_cvtepu16_epi32(_mm_unpacklo_epi64(lo, hi))};
}
// Lanes hold values in [0, 65535].
inline void store_rows4(VecI32 a, uint16_t* r0, uint16_t* r1) {
  const __m128i packed = _mm_packus_epi32(_mm256_castsi256_si128(a.v), _mm256_extracti128_si256(a.v, 1));
  _mm_storel_epi64(reinterpret_cast<__m128i*>(r0), packed);
  _mm_storel_epi64(reinterpret_cast<__m128i*>(r1), _mm_unpackhi_epi64(packed, packed));
}
// a / b, IEEE division per lane.
inline VecF32 div(VecF32 a, VecF32 b) { return {_mm256_div_ps(a.v, b.v)}; }
// Float colour targets with two or four channels per texel: eight lanes of each channel (lanes 0–3 one row of
// four texels, 4–7 the row above) stored interleaved (r g r g …, or r g b a …) at r0 and r1.
inline void store_rows4_interleaved(VecF32 a, VecF32 b, float* r0, float* r1) {
  const __m256 lo = _mm256_unpacklo_ps(a.v, b.v), hi = _mm256_unpackhi_ps(a.v, b.v);
  _mm256_storeu_ps(r0, _mm256_permute2f128_ps(lo, hi, 0x20));
  _mm256_storeu_ps(r1, _mm256_permute2f128_ps(lo, hi, 0x31));
}
inline void store_rows4_interleaved(VecF32 a, VecF32 b, VecF32 c, VecF32 d, float* r0, float* r1) {
  const __m256 ab0 = _mm256_unpacklo_ps(a.v, b.v), ab1 = _mm256_unpackhi_ps(a.v, b.v);
  const __m256 cd0 = _mm256_unpacklo_ps(c.v, d.v), cd1 = _mm256_unpackhi_ps(c.v, d.v);
  const __m256 p0 = _mm256_shuffle_ps(ab0, cd0, 0x44), p1 = _mm256_shuffle_ps(ab0, cd0, 0xEE);
  const __m256 p2 = _mm256_shuffle_ps(ab1, cd1, 0x44), p3 = _mm256_shuffle_ps(ab1, cd1, 0xEE);
  _mm256_storeu_ps(r0, _mm256_permute2f128_ps(p0, p1, 0x20));
  _mm256_storeu_ps(r0 + 8, _mm256_permute2f128_ps(p2, p3, 0x20));
  _mm256_storeu_ps(r1, _mm256_permute2f128_ps(p0, p1, 0x31));
  _mm256_storeu_ps(r1 + 8, _mm256_permute2f128_ps(p2, p3, 0x31));
}
// The inverse of the stores above: s0 holds four texels of a row interleaved (r g r g …), s1 four of the row
// above; a and b get their channels, lanes 0–3 from s0 and 4–7 from s1.
inline void deinterleave_rows4(VecF32 s0, VecF32 s1, VecF32& a, VecF32& b) {
  a.v = _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(_mm256_shuffle_ps(s0.v, s1.v, 0x88)), 0xD8));
  b.v = _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(_mm256_shuffle_ps(s0.v, s1.v, 0xDD)), 0xD8));
}
// Four channels: s0 and t0 hold texels 0–1 and 2–3 of a row (r g b a r g b a), s1 and t1 those of the row above.
inline void deinterleave_rows4(VecF32 s0, VecF32 t0, VecF32 s1, VecF32 t1, VecF32& a, VecF32& b, VecF32& c,
                               VecF32& d) {
  const __m256 x0 = _mm256_permute2f128_ps(s0.v, s1.v, 0x20), x1 = _mm256_permute2f128_ps(s0.v, s1.v, 0x31);
  const __m256 x2 = _mm256_permute2f128_ps(t0.v, t1.v, 0x20), x3 = _mm256_permute2f128_ps(t0.v, t1.v, 0x31);
  const __m256 u0 = _mm256_unpacklo_ps(x0, x1), u1 = _mm256_unpackhi_ps(x0, x1);
  const __m256 u2 = _mm256_unpacklo_ps(x2, x3), u3 = _mm256_unpackhi_ps(x2, x3);
  a.v = _mm256_shuffle_ps(u0, u2, 0x44), b.v = _mm256_shuffle_ps(u0, u2, 0xEE);
  c.v = _mm256_shuffle_ps(u1, u3, 0x44), d.v = _mm256_shuffle_ps(u1, u3, 0xEE);
}

// Eight records of three (p[3l], p[3l + 1], p[3l + 2], a triangle's indices) split into lanes: a[l] = p[3l],
// b[l] = p[3l + 1], c[l] = p[3l + 2]. Three loads, each lane blended from the load that holds its element, and
// one permute per result.
inline void load_stride3(const uint32_t* p, VecI32& a, VecI32& b, VecI32& c) {
  const __m256i x = VecI32::load_u32(p).v, y = VecI32::load_u32(p + 8).v, z = VecI32::load_u32(p + 16).v;
  const __m256i ta = _mm256_blend_epi32(_mm256_blend_epi32(x, y, 0x92), z, 0x24);  // 0 9 18 3 12 21 6 15
  const __m256i tb = _mm256_blend_epi32(_mm256_blend_epi32(x, y, 0x24), z, 0x49);  // 16 1 10 19 4 13 22 7
  const __m256i tc = _mm256_blend_epi32(_mm256_blend_epi32(x, y, 0x49), z, 0x92);  // 8 17 2 11 20 5 14 23
  a.v = _mm256_permutevar8x32_epi32(ta, _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5));
  b.v = _mm256_permutevar8x32_epi32(tb, _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6));
  c.v = _mm256_permutevar8x32_epi32(tc, _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7));
}

// ---- For the depth-only back end and the SIMD triangle setup.
// The largest lane (lanes are not NaN).
inline float reduce_max(VecF32 a) {
  __m128 m = _mm_max_ps(_mm256_castps256_ps128(a.v), _mm256_extractf128_ps(a.v, 1));
  m = _mm_max_ps(m, _mm_movehl_ps(m, m));
  m = _mm_max_ss(m, _mm_shuffle_ps(m, m, 1));
  return _mm_cvtss_f32(m);
}

inline VecI32 min(VecI32 a, VecI32 b) { return {_mm256_min_epi32(a.v, b.v)}; }
inline VecI32 max(VecI32 a, VecI32 b) { return {_mm256_max_epi32(a.v, b.v)}; }
// Arithmetic shift right (floor division by 2^N).
template <int N>
inline VecI32 shift_right(VecI32 a) { return {_mm256_srai_epi32(a.v, N)}; }
// Lane l of the result is base[idx[l]].
inline VecI32 gather(const int32_t* base, VecI32 idx) { return {_mm256_i32gather_epi32(base, idx.v, 4)}; }
inline VecF32 gather(const float* base, VecI32 idx) { return {_mm256_i32gather_ps(base, idx.v, 4)}; }

// Eight records of six 32-bit fields, record l at base + 6 · idx[l] (the layout of WindowVertex): fields 0, 1
// and 2 as floats and fields 4 and 5 as integers, lane l from record l, as gather() of each field gives them.
// Two loads per record (bytes 0–15 and 16–23, nothing outside it) and a 4 × 4 transpose instead of five gathers:
// in the dragon's depth pass on the 2-core AMD EPYC (Zen 5, AVX-512 path) the triangle setup of setup_batch.h
// spent 70 % of its time in its gathers.
inline void load_records6(const float* base, const int32_t* idx, VecF32& f0, VecF32& f1, VecF32& f2, VecI32& i4,
                          VecI32& i5) {
  const float* p[8];
  for (int l = 0; l < 8; ++l) p[l] = base + 6 * std::ptrdiff_t(idx[l]);
  auto fields03 = [&](int a, int b) {  // fields 0–3 of records a (lanes 0–3) and b (lanes 4–7)
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p[a])), _mm_loadu_ps(p[b]), 1);
  };
  const __m256 r0 = fields03(0, 4), r1 = fields03(1, 5), r2 = fields03(2, 6), r3 = fields03(3, 7);
  const __m256 t0 = _mm256_unpacklo_ps(r0, r1), t1 = _mm256_unpacklo_ps(r2, r3);  // f0 f0 f1 f1 of records 0 1, 2 3
  const __m256 t2 = _mm256_unpackhi_ps(r0, r1), t3 = _mm256_unpackhi_ps(r2, r3);  // f2 f2 f3 f3
  f0.v = _mm256_shuffle_ps(t0, t1, 0x44), f1.v = _mm256_shuffle_ps(t0, t1, 0xEE);
  f2.v = _mm256_shuffle_ps(t2, t3, 0x44);
  auto fields45 = [&](int a, int b) {  // fields 4 and 5 of records a and b
    return _mm_loadh_pi(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p[a] + 4))),
                        reinterpret_cast<const __m64*>(p[b] + 4));
  };
  const __m256 q01 = _mm256_insertf128_ps(_mm256_castps128_ps256(fields45(0, 1)), fields45(4, 5), 1);
  const __m256 q23 = _mm256_insertf128_ps(_mm256_castps128_ps256(fields45(2, 3)), fields45(6, 7), 1);
  i4.v = _mm256_castps_si256(_mm256_shuffle_ps(q01, q23, _MM_SHUFFLE(2, 0, 2, 0)));
  i5.v = _mm256_castps_si256(_mm256_shuffle_ps(q01, q23, _MM_SHUFFLE(3, 1, 3, 1)));
}

// Transposes eight vectors in place: afterwards r[l] holds lane l of the eight inputs, in order.
inline void transpose8(VecF32 (&r)[8]) {
  __m256 t[8], s[8];
  for (int i = 0; i < 4; ++i) {
    t[2 * i] = _mm256_unpacklo_ps(r[2 * i].v, r[2 * i + 1].v);
    t[2 * i + 1] = _mm256_unpackhi_ps(r[2 * i].v, r[2 * i + 1].v);
  }
  for (int h = 0; h < 2; ++h) {
    s[4 * h + 0] = _mm256_shuffle_ps(t[4 * h + 0], t[4 * h + 2], 0x44);
    s[4 * h + 1] = _mm256_shuffle_ps(t[4 * h + 0], t[4 * h + 2], 0xEE);
    s[4 * h + 2] = _mm256_shuffle_ps(t[4 * h + 1], t[4 * h + 3], 0x44);
    s[4 * h + 3] = _mm256_shuffle_ps(t[4 * h + 1], t[4 * h + 3], 0xEE);
  }
  for (int i = 0; i < 4; ++i) {
    r[i].v = _mm256_permute2f128_ps(s[i], s[i + 4], 0x20);
    r[i + 4].v = _mm256_permute2f128_ps(s[i], s[i + 4], 0x31);
  }
}

// ---- For the vertex stage (vertex_batch.h). Writes lane l of the six vectors to out[6·l + j], j = 0…5: eight
// consecutive records of six 32-bit fields, 48 floats in six stores. The records' 4-lane halves are transposed
// as 4×4 blocks (fields 0–3) plus pairs (fields 4–5), then the halves of lanes 0–3 and 4–7 are stored in turn.
inline void store_interleaved6(void* dst, VecF32 f0, VecF32 f1, VecF32 f2, VecF32 f3, VecF32 f4, VecF32 f5) {
  float* out = static_cast<float*>(dst);  // written through __m256 stores, which may alias anything
  auto lo = [](__m256 a, __m256 b) { return _mm256_castpd_ps(_mm256_unpacklo_pd(_mm256_castps_pd(a), _mm256_castps_pd(b))); };
  auto hi = [](__m256 a, __m256 b) { return _mm256_castpd_ps(_mm256_unpackhi_pd(_mm256_castps_pd(a), _mm256_castps_pd(b))); };
  const __m256 t0 = _mm256_unpacklo_ps(f0.v, f1.v), t1 = _mm256_unpackhi_ps(f0.v, f1.v);  // per half: a0 b0 a1 b1 | a2 b2 a3 b3
  const __m256 t2 = _mm256_unpacklo_ps(f2.v, f3.v), t3 = _mm256_unpackhi_ps(f2.v, f3.v);
  const __m256 e0 = _mm256_unpacklo_ps(f4.v, f5.v), e1 = _mm256_unpackhi_ps(f4.v, f5.v);  // e0 f0 e1 f1 | e2 f2 e3 f3
  const __m256 r0 = lo(t0, t2), r1 = hi(t0, t2), r2 = lo(t1, t3), r3 = hi(t1, t3);          // record k's fields 0–3
  // Per half, 24 floats in six groups of four: r0 | e0 f0 r1.01 | r1.23 e1 f1 | r2 | e2 f2 r3.01 | r3.23 e3 f3.
  const __m256 x0 = r0, x1 = lo(e0, r1), x2 = hi(r1, e0), x3 = r2, x4 = lo(e1, r3), x5 = hi(r3, e1);
  _mm256_storeu_ps(out, _mm256_permute2f128_ps(x0, x1, 0x20));
  _mm256_storeu_ps(out + 8, _mm256_permute2f128_ps(x2, x3, 0x20));
  _mm256_storeu_ps(out + 16, _mm256_permute2f128_ps(x4, x5, 0x20));
  _mm256_storeu_ps(out + 24, _mm256_permute2f128_ps(x0, x1, 0x31));
  _mm256_storeu_ps(out + 32, _mm256_permute2f128_ps(x2, x3, 0x31));
  _mm256_storeu_ps(out + 40, _mm256_permute2f128_ps(x4, x5, 0x31));
}

// ---- For the binning of large draws (bins.h). One 64-byte record, 64-byte aligned at both ends, copied with
// non-temporal stores: the line goes to memory without being read first (no read for ownership) and without
// evicting what the caches hold. Such stores are weakly ordered: stream_fence() before another thread reads them.
// AVX-512 builds write the line with one store: measured on the 2-core AMD EPYC (Zen 4), 2 threads, shadowlab
// alone, alternating with two 32-byte halves, the dragon's front end (bench/depth_pass_bench.cpp) 8.7–9.5 →
// 8.5–8.6 ms in four rounds and 8.9–9.2 → 8.8–9.2 ms in five more (medians 9.10 → 8.92, the draw 18.30 → 18.05).
inline void stream_line(void* dst, const void* src) {
#if defined(SHADOWLAB_SIMD_AVX512)
  _mm512_stream_si512(static_cast<__m512i*>(dst), _mm512_load_si512(src));
#else
  const __m256i* s = static_cast<const __m256i*>(src);
  __m256i* d = static_cast<__m256i*>(dst);
  _mm256_stream_si256(d, _mm256_load_si256(s));
  _mm256_stream_si256(d + 1, _mm256_load_si256(s + 1));
#endif
}
inline void stream_fence() { _mm_sfence(); }

SHADOWLAB_ISA_END
}  // namespace raster::simd
