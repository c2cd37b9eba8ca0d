// Sixteen-lane value types built from two eight-lane halves, for the instruction sets without 512-bit vectors
// (AVX2 and the scalar twin): the same interface as vec_avx512.h, each operation applied to both halves, so the
// depth-only back end has one code path whatever the width and every set gives the same bits. Lanes 0–7 are
// one pixel row of a block, lanes 8–15 the row below it (vec.h).
#pragma once
#include <cstdint>
#include "raster/simd/isa.h"

namespace raster::simd {
SHADOWLAB_ISA_BEGIN

struct Mask16 {
  Mask lo, hi;
  static Mask16 from_bits(unsigned m) { return {Mask::from_bits(m & 0xFFu), Mask::from_bits(m >> 8 & 0xFFu)}; }
  static Mask16 rows(Mask lo, Mask hi) { return {lo, hi}; }
  unsigned bits() const { return lo.bits() | hi.bits() << 8; }
  bool any() const { return (lo | hi).any(); }
};
inline Mask16 operator&(Mask16 a, Mask16 b) { return {a.lo & b.lo, a.hi & b.hi}; }
inline Mask16 operator|(Mask16 a, Mask16 b) { return {a.lo | b.lo, a.hi | b.hi}; }
inline Mask16 and_not(Mask16 a, Mask16 b) { return {and_not(a.lo, b.lo), and_not(a.hi, b.hi)}; }

struct VecI32x16 {
  VecI32 lo, hi;
  static VecI32x16 splat(int32_t x) { return {VecI32::splat(x), VecI32::splat(x)}; }
  static VecI32x16 rows(VecI32 lo, VecI32 hi) { return {lo, hi}; }
  static VecI32x16 load_rows_u32(const uint32_t* r0, const uint32_t* r1) {
    return {VecI32::load_u32(r0), VecI32::load_u32(r1)};
  }
  static VecI32x16 load_rows_u16(const uint16_t* r0, const uint16_t* r1) {
    return {VecI32::load_u16(r0), VecI32::load_u16(r1)};
  }
  void store_rows_u32(uint32_t* r0, uint32_t* r1) const { lo.store_u32(r0), hi.store_u32(r1); }
  // Lanes hold values in [0, 65535].
  void store_rows_u16(uint16_t* r0, uint16_t* r1) const { lo.store_u16(r0), hi.store_u16(r1); }
};
inline VecI32x16 operator+(VecI32x16 a, VecI32x16 b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline VecI32x16 operator|(VecI32x16 a, VecI32x16 b) { return {a.lo | b.lo, a.hi | b.hi}; }

struct VecF32x16 {
  VecF32 lo, hi;
  static VecF32x16 splat(float x) { return {VecF32::splat(x), VecF32::splat(x)}; }
  static VecF32x16 rows(VecF32 lo, VecF32 hi) { return {lo, hi}; }
  static VecF32x16 load_rows(const float* r0, const float* r1) { return {VecF32::load(r0), VecF32::load(r1)}; }
  void store_rows(float* r0, float* r1) const { lo.store(r0), hi.store(r1); }
  VecF32 row0() const { return lo; }
  VecF32 row1() const { return hi; }
};
inline VecF32x16 operator+(VecF32x16 a, VecF32x16 b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline VecF32x16 operator*(VecF32x16 a, VecF32x16 b) { return {a.lo * b.lo, a.hi * b.hi}; }
inline VecF32x16 fma(VecF32x16 a, VecF32x16 b, VecF32x16 c) { return {fma(a.lo, b.lo, c.lo), fma(a.hi, b.hi, c.hi)}; }
inline VecF32x16 min(VecF32x16 a, VecF32x16 b) { return {min(a.lo, b.lo), min(a.hi, b.hi)}; }
inline VecF32x16 max(VecF32x16 a, VecF32x16 b) { return {max(a.lo, b.lo), max(a.hi, b.hi)}; }
inline VecI32x16 round_to_int(VecF32x16 a) { return {round_to_int(a.lo), round_to_int(a.hi)}; }

inline Mask16 non_negative(VecI32x16 a) { return {non_negative(a.lo), non_negative(a.hi)}; }
inline Mask16 cmp_lt(VecF32x16 a, VecF32x16 b) { return {cmp_lt(a.lo, b.lo), cmp_lt(a.hi, b.hi)}; }
inline Mask16 cmp_le(VecF32x16 a, VecF32x16 b) { return {cmp_le(a.lo, b.lo), cmp_le(a.hi, b.hi)}; }
inline Mask16 cmp_eq(VecF32x16 a, VecF32x16 b) { return {cmp_eq(a.lo, b.lo), cmp_eq(a.hi, b.hi)}; }
inline Mask16 cmp_neq(VecF32x16 a, VecF32x16 b) { return {cmp_neq(a.lo, b.lo), cmp_neq(a.hi, b.hi)}; }
inline Mask16 cmp_lt(VecI32x16 a, VecI32x16 b) { return {cmp_lt(a.lo, b.lo), cmp_lt(a.hi, b.hi)}; }
inline Mask16 cmp_le(VecI32x16 a, VecI32x16 b) { return {cmp_le(a.lo, b.lo), cmp_le(a.hi, b.hi)}; }
inline Mask16 cmp_eq(VecI32x16 a, VecI32x16 b) { return {cmp_eq(a.lo, b.lo), cmp_eq(a.hi, b.hi)}; }
inline Mask16 cmp_neq(VecI32x16 a, VecI32x16 b) { return {cmp_neq(a.lo, b.lo), cmp_neq(a.hi, b.hi)}; }

inline VecF32x16 select(Mask16 m, VecF32x16 a, VecF32x16 b) { return {select(m.lo, a.lo, b.lo), select(m.hi, a.hi, b.hi)}; }
inline VecI32x16 select(Mask16 m, VecI32x16 a, VecI32x16 b) { return {select(m.lo, a.lo, b.lo), select(m.hi, a.hi, b.hi)}; }

SHADOWLAB_ISA_END
}  // namespace raster::simd
