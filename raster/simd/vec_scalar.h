// Portable scalar twin of vec_avx2.h: the same eight-lane types and functions on plain arrays, bit-identical
// results (IEEE float operations, std::fma, round-to-nearest-even).
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include "raster/simd/isa.h"

namespace raster::simd {
SHADOWLAB_ISA_BEGIN

struct VecI32 {
  alignas(32) int32_t v[8];
  static VecI32 splat(int32_t x) { VecI32 r; for (int i = 0; i < 8; ++i) r.v[i] = x; return r; }
  static VecI32 iota() { VecI32 r; for (int i = 0; i < 8; ++i) r.v[i] = i; return r; }
  static VecI32 load(const int32_t* p) { VecI32 r; std::memcpy(r.v, p, 32); return r; }
  static VecI32 load_u32(const uint32_t* p) { VecI32 r; std::memcpy(r.v, p, 32); return r; }
  static VecI32 load_u16(const uint16_t* p) { VecI32 r; for (int i = 0; i < 8; ++i) r.v[i] = p[i]; return r; }
  void store_u32(uint32_t* p) const { std::memcpy(p, v, 32); }
  void store_u16(uint16_t* p) const { for (int i = 0; i < 8; ++i) p[i] = uint16_t(v[i]); }
  template <class F> static VecI32 map(VecI32 a, VecI32 b, F f) { VecI32 r; for (int i = 0; i < 8; ++i) r.v[i] = f(a.v[i], b.v[i]); return r; }
  friend VecI32 operator+(VecI32 a, VecI32 b) { return map(a, b, [](int32_t x, int32_t y) { return int32_t(uint32_t(x) + uint32_t(y)); }); }
  friend VecI32 operator-(VecI32 a, VecI32 b) { return map(a, b, [](int32_t x, int32_t y) { return int32_t(uint32_t(x) - uint32_t(y)); }); }
  friend VecI32 operator*(VecI32 a, VecI32 b) { return map(a, b, [](int32_t x, int32_t y) { return int32_t(uint32_t(x) * uint32_t(y)); }); }
  friend VecI32 operator|(VecI32 a, VecI32 b) { return map(a, b, [](int32_t x, int32_t y) { return x | y; }); }
  friend VecI32 operator&(VecI32 a, VecI32 b) { return map(a, b, [](int32_t x, int32_t y) { return x & y; }); }
};

struct VecF32 {
  alignas(32) float v[8];
  static VecF32 splat(float x) { VecF32 r; for (int i = 0; i < 8; ++i) r.v[i] = x; return r; }
  static VecF32 iota() { VecF32 r; for (int i = 0; i < 8; ++i) r.v[i] = float(i); return r; }
  static VecF32 load(const float* p) { VecF32 r; std::memcpy(r.v, p, 32); return r; }
  void store(float* p) const { std::memcpy(p, v, 32); }
  template <class F> static VecF32 map(VecF32 a, VecF32 b, F f) { VecF32 r; for (int i = 0; i < 8; ++i) r.v[i] = f(a.v[i], b.v[i]); return r; }
  friend VecF32 operator+(VecF32 a, VecF32 b) { return map(a, b, [](float x, float y) { return x + y; }); }
  friend VecF32 operator-(VecF32 a, VecF32 b) { return map(a, b, [](float x, float y) { return x - y; }); }
  friend VecF32 operator*(VecF32 a, VecF32 b) { return map(a, b, [](float x, float y) { return x * y; }); }
};

inline VecF32 fma(VecF32 a, VecF32 b, VecF32 c) { VecF32 r; for (int i = 0; i < 8; ++i) r.v[i] = std::fma(a.v[i], b.v[i], c.v[i]); return r; }
// Matches minps/maxps: the second operand is returned when either is NaN.
inline VecF32 min(VecF32 a, VecF32 b) { return VecF32::map(a, b, [](float x, float y) { return x < y ? x : y; }); }
inline VecF32 max(VecF32 a, VecF32 b) { return VecF32::map(a, b, [](float x, float y) { return x > y ? x : y; }); }
inline VecF32 to_float(VecI32 a) { VecF32 r; for (int i = 0; i < 8; ++i) r.v[i] = float(a.v[i]); return r; }
inline VecI32 round_to_int(VecF32 a) { VecI32 r; for (int i = 0; i < 8; ++i) r.v[i] = int32_t(std::nearbyint(a.v[i])); return r; }
inline VecF32 bitcast_f32(VecI32 a) { VecF32 r; std::memcpy(r.v, a.v, 32); return r; }
inline VecI32 bitcast_i32(VecF32 a) { VecI32 r; std::memcpy(r.v, a.v, 32); return r; }

struct Mask {
  unsigned m;  // bit l: lane l
  static Mask all() { return {0xFFu}; }
  static Mask from_bits(unsigned b) { return {b & 0xFFu}; }
  unsigned bits() const { return m; }
  bool any() const { return m != 0; }
  friend Mask operator&(Mask a, Mask b) { return {a.m & b.m}; }
  friend Mask operator|(Mask a, Mask b) { return {a.m | b.m}; }
  friend Mask and_not(Mask a, Mask b) { return {a.m & ~b.m & 0xFFu}; }
};

template <class T, class F>
inline Mask lanes_where(const T& a, const T& b, F f) { unsigned m = 0; for (int i = 0; i < 8; ++i) m |= unsigned(f(a.v[i], b.v[i])) << i; return {m}; }

inline Mask negative(VecI32 a) { return lanes_where(a, a, [](int32_t x, int32_t) { return x < 0; }); }
inline Mask non_negative(VecI32 a) { return lanes_where(a, a, [](int32_t x, int32_t) { return x >= 0; }); }
inline Mask cmp_lt(VecF32 a, VecF32 b) { return lanes_where(a, b, [](float x, float y) { return x < y; }); }
inline Mask cmp_le(VecF32 a, VecF32 b) { return lanes_where(a, b, [](float x, float y) { return x <= y; }); }
inline Mask cmp_eq(VecF32 a, VecF32 b) { return lanes_where(a, b, [](float x, float y) { return x == y; }); }
inline Mask cmp_neq(VecF32 a, VecF32 b) { return lanes_where(a, b, [](float x, float y) { return !(x == y); }); }
inline Mask cmp_lt(VecI32 a, VecI32 b) { return lanes_where(a, b, [](int32_t x, int32_t y) { return x < y; }); }
inline Mask cmp_le(VecI32 a, VecI32 b) { return lanes_where(a, b, [](int32_t x, int32_t y) { return x <= y; }); }
inline Mask cmp_eq(VecI32 a, VecI32 b) { return lanes_where(a, b, [](int32_t x, int32_t y) { return x == y; }); }
inline Mask cmp_neq(VecI32 a, VecI32 b) { return lanes_where(a, b, [](int32_t x, int32_t y) { return x != y; }); }

inline VecF32 select(Mask m, VecF32 a, VecF32 b) { VecF32 r; for (int i = 0; i < 8; ++i) r.v[i] = (m.m >> i & 1) ? b.v[i] : a.v[i]; return r; }
inline VecI32 select(Mask m, VecI32 a, VecI32 b) { VecI32 r; for (int i = 0; i < 8; ++i) r.v[i] = (m.m >> i & 1) ? b.v[i] : a.v[i]; return r; }
// Writes select(m, a, b) to p, a being what p holds (see vec_avx2.h): only m's lanes change.
inline void store_select(Mask m, VecF32 a, VecF32 b, float* p) { (void)a; for (int i = 0; i < 8; ++i) if (m.m >> i & 1) p[i] = b.v[i]; }

// ---- For the shaded back end's 4×2 pixel groups and its colour writes (see vec_avx2.h).
inline VecF32 permute(VecF32 a, VecI32 idx) { VecF32 r; for (int i = 0; i < 8; ++i) r.v[i] = a.v[idx.v[i] & 7]; return r; }
template <int N>
inline VecI32 shift_left(VecI32 a) { VecI32 r; for (int i = 0; i < 8; ++i) r.v[i] = int32_t(uint32_t(a.v[i]) << N); return r; }
inline VecF32 load_rows4(const float* r0, const float* r1) { VecF32 r; std::memcpy(r.v, r0, 16); std::memcpy(r.v + 4, r1, 16); return r; }
inline void store_rows4(VecF32 a, float* r0, float* r1) { std::memcpy(r0, a.v, 16); std::memcpy(r1, a.v + 4, 16); }
inline VecI32 load_rows4(const uint32_t* r0, const uint32_t* r1) { VecI32 r; std::memcpy(r.v, r0, 16); std::memcpy(r.v + 4, r1, 16); return r; }
inline void store_rows4(VecI32 a, uint32_t* r0, uint32_t* r1) { std::memcpy(r0, a.v, 16); std::memcpy(r1, a.v + 4, 16); }
inline VecI32 load_rows4(const uint16_t* r0, const uint16_t* r1) { VecI32 r; for (int i = 0; i < 4; ++i) r.v[i] = r0[i], r.v[i + 4] = r1[i]; return r; }
inline void store_rows4(VecI32 a, uint16_t* r0, uint16_t* r1) { for (int i = 0; i < 4; ++i) r0[i] = uint16_t(a.v[i]), r1[i] = uint16_t(a.v[i + 4]); }
// Interleaved two- and four-channel rows and their inverse (see vec_avx2.h).
inline void store_rows4_interleaved(VecF32 a, VecF32 b, float* r0, float* r1) {
  for (int i = 0; i < 4; ++i) r0[2 * i] = a.v[i], r0[2 * i + 1] = b.v[i], r1[2 * i] = a.v[i + 4], r1[2 * i + 1] = b.v[i + 4];
}
inline void store_rows4_interleaved(VecF32 a, VecF32 b, VecF32 c, VecF32 d, float* r0, float* r1) {
  for (int i = 0; i < 4; ++i) {
    r0[4 * i] = a.v[i], r0[4 * i + 1] = b.v[i], r0[4 * i + 2] = c.v[i], r0[4 * i + 3] = d.v[i];
    r1[4 * i] = a.v[i + 4], r1[4 * i + 1] = b.v[i + 4], r1[4 * i + 2] = c.v[i + 4], r1[4 * i + 3] = d.v[i + 4];
  }
}

// Eight records of three split into lanes: a[l] = p[3l], b[l] = p[3l + 1], c[l] = p[3l + 2].
inline void load_stride3(const uint32_t* p, VecI32& a, VecI32& b, VecI32& c) {
  for (int l = 0; l < 8; ++l)
    a.v[l] = int32_t(p[3 * l]), b.v[l] = int32_t(p[3 * l + 1]), c.v[l] = int32_t(p[3 * l + 2]);
}
inline void deinterleave_rows4(VecF32 s0, VecF32 s1, VecF32& a, VecF32& b) {
  for (int i = 0; i < 4; ++i) a.v[i] = s0.v[2 * i], b.v[i] = s0.v[2 * i + 1], a.v[i + 4] = s1.v[2 * i], b.v[i + 4] = s1.v[2 * i + 1];
}
inline void deinterleave_rows4(VecF32 s0, VecF32 t0, VecF32 s1, VecF32 t1, VecF32& a, VecF32& b, VecF32& c,
                               VecF32& d) {
  VecF32* out[4] = {&a, &b, &c, &d};
  for (int ch = 0; ch < 4; ++ch)
    for (int i = 0; i < 2; ++i) {
      out[ch]->v[i] = s0.v[4 * i + ch], out[ch]->v[i + 2] = t0.v[4 * i + ch];
      out[ch]->v[i + 4] = s1.v[4 * i + ch], out[ch]->v[i + 6] = t1.v[4 * i + ch];
    }
}
// a / b, IEEE division per lane.
inline VecF32 div(VecF32 a, VecF32 b) { return VecF32::map(a, b, [](float x, float y) { return x / y; }); }

// ---- For the depth-only back end and the SIMD triangle setup (see vec_avx2.h).
inline float reduce_max(VecF32 a) { float m = a.v[0]; for (int i = 1; i < 8; ++i) m = a.v[i] > m ? a.v[i] : m; return m; }

inline VecI32 min(VecI32 a, VecI32 b) { return VecI32::map(a, b, [](int32_t x, int32_t y) { return x < y ? x : y; }); }
inline VecI32 max(VecI32 a, VecI32 b) { return VecI32::map(a, b, [](int32_t x, int32_t y) { return x > y ? x : y; }); }
template <int N>
inline VecI32 shift_right(VecI32 a) { VecI32 r; for (int i = 0; i < 8; ++i) r.v[i] = a.v[i] >> N; return r; }
inline VecI32 gather(const int32_t* base, VecI32 idx) { VecI32 r; for (int i = 0; i < 8; ++i) r.v[i] = base[idx.v[i]]; return r; }
inline VecF32 gather(const float* base, VecI32 idx) { VecF32 r; for (int i = 0; i < 8; ++i) r.v[i] = base[idx.v[i]]; return r; }

// Eight records of six 32-bit fields (see vec_avx2.h).
inline void load_records6(const float* base, const int32_t* idx, VecF32& f0, VecF32& f1, VecF32& f2, VecI32& i4,
                          VecI32& i5) {
  for (int l = 0; l < 8; ++l) {
    const float* p = base + 6 * std::ptrdiff_t(idx[l]);
    f0.v[l] = p[0], f1.v[l] = p[1], f2.v[l] = p[2];
    std::memcpy(&i4.v[l], p + 4, 4), std::memcpy(&i5.v[l], p + 5, 4);
  }
}
inline void transpose8(VecF32 (&r)[8]) {
  VecF32 o[8];
  for (int i = 0; i < 8; ++i) for (int j = 0; j < 8; ++j) o[i].v[j] = r[j].v[i];
  for (int i = 0; i < 8; ++i) r[i] = o[i];
}

inline void store_interleaved6(void* out, VecF32 f0, VecF32 f1, VecF32 f2, VecF32 f3, VecF32 f4, VecF32 f5) {
  const VecF32* f[6] = {&f0, &f1, &f2, &f3, &f4, &f5};
  for (int l = 0; l < 8; ++l)
    for (int j = 0; j < 6; ++j) std::memcpy(static_cast<char*>(out) + 4 * (6 * l + j), &f[j]->v[l], 4);
}

// Plain copies: ordinary stores need no fence.
inline void stream_line(void* dst, const void* src) { std::memcpy(dst, src, 64); }
inline void stream_fence() {}

SHADOWLAB_ISA_END
}  // namespace raster::simd
