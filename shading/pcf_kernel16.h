// The sixteen-lane PCF kernels: Pcf16Level (a level's constants, splatted once per kernel), pcf_lequal_gather16
// (one AVX-512 register: the short path of pcf_kernel.h's gather8, with the window path), pcf_lequal_gather16_n
// (several at once, stage by stage), and their forms over raster/simd's sixteen-lane type, pcf_lequal_x16 and
// pcf_lequal_x16_n, which in other builds run pcf_kernel.h's eight-lane kernel on each half. Each lane equals
// pcf_lequal (pcf_kernel.h) bit for bit. kLookupsPerBatch and kTapsPerLookup say how multi-tap filters use them.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "raster/simd/vec.h"
#include "shading/mip_chain.h"
#include "shading/pcf_kernel.h"
#include "shading/texel_format.h"
#include "shading/texture.h"

#if defined(SHADOWLAB_SIMD_AVX2)
#include <immintrin.h>
#endif
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN
namespace detail {

// A level's constants for the SIMD forms: the eight-lane ones and, in AVX-512 builds, the same splatted to 512
// bits. Built once per kernel (PcfKernel), not per lookup.
struct Pcf16Level {
  Pcf8Level half;
#if defined(SHADOWLAB_SIMD_AVX512)
  __m512 fwidth, fheight;
  __m512i w2, h2;      // width − 2, height − 2
  __m512i vpitch;      // 32-bit texels from one row to the next
  __m512i vpitch16;    // 16-bit texels from one row to the next
  __m512i wh;          // (width − 8, height − 4) as 16-bit halves: the last column and row a window can start at
  explicit Pcf16Level(const TextureLevel& L)
      : half(L), fwidth(_mm512_set1_ps(L.fwidth)), fheight(_mm512_set1_ps(L.fheight)),
        w2(_mm512_set1_epi32(L.width - 2)), h2(_mm512_set1_epi32(L.height - 2)),
        vpitch(_mm512_set1_epi32(int(L.row_bytes / 4))), vpitch16(_mm512_set1_epi32(int(L.row_bytes / 2))),
        wh(_mm512_set1_epi32(int32_t(uint32_t(L.height - 4) << 16 | (uint32_t(L.width - 8) & 0xFFFFu)))) {}
#else
  explicit Pcf16Level(const TextureLevel& L) : half(L) {}
#endif
};

#if defined(SHADOWLAB_SIMD_AVX512)

// Where an AVX-512 intrinsic has a form with a zeroing mask, the code below takes it with every lane set (as
// raster/simd/vec_avx512.h does): GCC 12's plain forms pass an "undefined" register that -Wuninitialized then
// reports wherever they are inlined. The instructions and results are the same.
inline constexpr __mmask16 kAll16 = 0xFFFF;

// d16 codes (0 .. 65535 in 32-bit lanes) as Texel<d16> decodes them: code / 65535, an exact conversion and a
// correctly rounded division.
inline __m512 decode_d16x16(__m512i code) {
  return _mm512_div_ps(_mm512_maskz_cvtepi32_ps(kAll16, code), _mm512_set1_ps(65535.0f));
}

// The four texels of sixteen footprints whose pairs start at element offset off, as load_pairs8 reads eight:
// d16 pairs gathered as one 32-bit word per lane and row; 32-bit texels read with scalar 8-byte loads, four
// 128-bit pieces per vector. No prefetch here: on the 2-core AMD EPYC (Zen 5) a Poisson pass's sixteen-lane
// lookups ran 1.14× slower with load_pairs8's prefetch (for lanes 0 and 4) than without, and 1.07× faster than
// two eight-lane lookups with it (which measured alike with and without it there).
template <TexelFormat F>
inline void load_pairs16(const Pcf16Level& L, __m512i offv, __m512 tex[4]) {
  if constexpr (F == TexelFormat::d16) {
    const int* base = reinterpret_cast<const int*>(L.half.level.data);
    const __m512i low = _mm512_set1_epi32(0xFFFF);
    for (int r = 0; r < 2; ++r) {
      const __m512i pair = _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), kAll16, r ? _mm512_add_epi32(offv, L.vpitch16) : offv, base, 2);
      tex[2 * r] = decode_d16x16(_mm512_and_si512(pair, low));
      tex[2 * r + 1] = decode_d16x16(_mm512_maskz_srli_epi32(kAll16, pair, 16));
    }
  } else {
    // Offsets to general registers two at a time, as load_pairs8 does; non-negative, so the odd lanes are the
    // upper halves as they stand.
    // The block index is a template argument: Clang wants the extract's immediate a constant where the loop
    // variable is not one (GCC folds it after unrolling), so a Clang build with AVX-512 compiles too.
    uint64_t off[16];
    auto take = [&]<int k>() {
      const __m128i o = _mm512_maskz_extracti32x4_epi32(0xF, offv, k);
      const uint64_t q0 = uint64_t(_mm_cvtsi128_si64(o)), q1 = uint64_t(_mm_extract_epi64(o, 1));
      off[4 * k] = uint32_t(q0), off[4 * k + 1] = q0 >> 32, off[4 * k + 2] = uint32_t(q1), off[4 * k + 3] = q1 >> 32;
    };
    take.template operator()<0>(), take.template operator()<1>(), take.template operator()<2>();
    take.template operator()<3>();
    for (int r = 0; r < 2; ++r) {
      const float* row = L.half.base + r * L.half.pitch;
      auto pair2 = [&](int a, int b) {  // texels (off[a], off[a] + 1, off[b], off[b] + 1) of this row
        const __m128 lo = _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(row + off[a])));
        return _mm_loadh_pi(lo, reinterpret_cast<const __m64*>(row + off[b]));
      };
      // 128-bit block k of each vector serves lanes 4k .. 4k + 3: pairs (4k, 4k + 1) in p01, (4k + 2, 4k + 3)
      // in p23; the even elements are the x texels, the odd ones x + 1.
      __m512 p01 = _mm512_castps128_ps512(pair2(0, 1)), p23 = _mm512_castps128_ps512(pair2(2, 3));
      p01 = _mm512_insertf32x4(p01, pair2(4, 5), 1), p23 = _mm512_insertf32x4(p23, pair2(6, 7), 1);
      p01 = _mm512_insertf32x4(p01, pair2(8, 9), 2), p23 = _mm512_insertf32x4(p23, pair2(10, 11), 2);
      p01 = _mm512_insertf32x4(p01, pair2(12, 13), 3), p23 = _mm512_insertf32x4(p23, pair2(14, 15), 3);
      tex[2 * r] = _mm512_maskz_shuffle_ps(kAll16, p01, p23, _MM_SHUFFLE(2, 0, 2, 0));
      tex[2 * r + 1] = _mm512_maskz_shuffle_ps(kAll16, p01, p23, _MM_SHUFFLE(3, 1, 3, 1));
    }
  }
}

// Each 16-bit half of each lane: the minimum of that half over its group of eight lanes (0–7 or 8–15), unsigned.
inline __m512i group_min8_u16(__m512i v) {
  // Swap the 128-bit blocks within each 256-bit half, then the 64-bit pairs, then neighbouring lanes.
  constexpr auto kPairs = _MM_PERM_ENUM(_MM_SHUFFLE(1, 0, 3, 2)), kLanes = _MM_PERM_ENUM(_MM_SHUFFLE(2, 3, 0, 1));
  v = _mm512_min_epu16(v, _mm512_maskz_shuffle_i64x2(0xFF, v, v, _MM_SHUFFLE(2, 3, 0, 1)));
  v = _mm512_min_epu16(v, _mm512_maskz_shuffle_epi32(kAll16, v, kPairs));
  return _mm512_min_epu16(v, _mm512_maskz_shuffle_epi32(kAll16, v, kLanes));
}

// The window path. A camera pass's sixteen-lane lookup is one tap at a fragment pair's eight points in each group of
// eight lanes, and those points are neighbours: their footprints mostly lie within a few texels of each other. When
// every group's footprints (columns i0 .. i0 + 1, rows j0 .. j0 + 1) lie within the 8 × 4 texels from the group's
// smallest i0 and j0, and that window lies inside the map, window_taps16 reads it as four 8-texel rows per group and
// picks each tap with permutes across two registers, instead of 32 scalar loads, their offsets moved to general
// registers and the vector inserts. window_fits16 says whether every lane fits, and gives each lane's index in its
// group's window (dy · 8 + dx in the index's low five bits, all that the permutes read) and each group's first
// texel as an element offset in texels of the format. It means something only where every lane's i0, j0 lies inside
// the map (0 <= i0 <= W − 2, 0 <= j0 <= H − 2, so no minimum is below 0): pcf_lequal_gather16 tests that first,
// pcf_lequal_gather16_n discards the result otherwise. The taps are the same texels as load_pairs16's, so the results
// are the same bits. The column and row of each lane travel as the two 16-bit halves of one lane (textures have at
// most kMaxTextureSize texels a side), so one minimum across the group serves both, and the differences, the bounds
// and the window's corners are taken on both at once (the corners then in general registers, without a vector
// multiply): on the 2-core AMD EPYC (Zen 4), 2 threads, the PCF bench's Poisson pass went from 19.3–19.5 to 17.5–18.1
// ms (three runs each, alternating) against one minimum per coordinate. Measured on the 2-core AMD EPYC (Zen 5), the
// window path itself: 17.0 → 16.0 ms on its own, and the rest with pcf_lequal_gather16_n (below). For the eight-lane
// lookups of one PCF tap per pixel the same window (one group, four permutes) measured slower, 2.5 → 3.0 ms (four
// runs each): there no other lookup hides the longer chain before the loads (a minimum across lanes, then a scalar
// address), so pcf_lequal_gather8 keeps its pairs.
static_assert(kMaxTextureSize <= 32768, "a texel column or row fits 16 bits (unsigned), a window's corner 15");
struct Window16 {
  __m512i idx;
  ptrdiff_t corner[2];  // groups 0 and 1
};
template <TexelFormat F>
inline bool window_fits16(const Pcf16Level& L, __m512i i0, __m512i j0, Window16& w) {
  const __m512i ij = _mm512_or_si512(i0, _mm512_maskz_slli_epi32(kAll16, j0, 16));  // (i0, j0) as 16-bit halves
  const __m512i m = group_min8_u16(ij);                                             // (x0, y0)
  const __m512i d = _mm512_sub_epi16(ij, m);                                        // (dx, dy)
  // x1 = x0 + dx + 1 within 8 columns, y1 = y0 + dy + 1 within 4 rows, and the window inside the map (signed: a map
  // narrower than 8 or lower than 4 texels has a negative limit).
  const __mmask32 ok = _mm512_cmple_epu16_mask(d, _mm512_set1_epi32(2 << 16 | 6)) & _mm512_cmple_epi16_mask(m, L.wh);
  w.idx = _mm512_add_epi32(d, _mm512_maskz_srli_epi32(kAll16, d, 13));  // dx + 8 · dy in the low bits
  const ptrdiff_t P = F == TexelFormat::d16 ? ptrdiff_t(L.half.level.row_bytes / 2) : L.half.pitch;
  const uint32_t m0 = uint32_t(_mm512_cvtsi512_si32(m));
  const uint32_t m8 = uint32_t(_mm_cvtsi128_si32(_mm512_maskz_extracti32x4_epi32(0xF, m, 2)));
  w.corner[0] = ptrdiff_t(m0 & 0xFFFF) + ptrdiff_t(m0 >> 16) * P;
  w.corner[1] = ptrdiff_t(m8 & 0xFFFF) + ptrdiff_t(m8 >> 16) * P;
  return ok == 0xFFFFFFFFu;
}
// The four taps from each group's window (see window_fits16), as load_pairs16 returns them: d16 decoded, d24 as
// raw bits, d32f as they are.
template <TexelFormat F>
inline void window_taps16(const Pcf16Level& L, const Window16& w, __m512 tex[4]) {
  const ptrdiff_t c0 = w.corner[0], c8 = w.corner[1];
  __m512 a01, a23, b01, b23;  // group 0's rows 0–1 and 2–3 (8 texels each), then group 1's
  if constexpr (F == TexelFormat::d16) {
    // Rows of 8 codes (16 bytes each), two rows widened to the 32-bit lanes of one register.
    const auto* base = reinterpret_cast<const uint16_t*>(L.half.level.data);
    const ptrdiff_t P = ptrdiff_t(L.half.level.row_bytes / 2);
    auto rows2 = [&](const uint16_t* p) {
      const __m256i two = _mm256_inserti128_si256(
          _mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p))),
          _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + P)), 1);
      return _mm512_castsi512_ps(_mm512_maskz_cvtepu16_epi32(kAll16, two));
    };
    a01 = rows2(base + c0), a23 = rows2(base + c0 + 2 * P), b01 = rows2(base + c8), b23 = rows2(base + c8 + 2 * P);
  } else {
    const ptrdiff_t P = L.half.pitch;
    auto rows2 = [&](const float* p) {
      return _mm512_insertf32x8(_mm512_castps256_ps512(_mm256_loadu_ps(p)), _mm256_loadu_ps(p + P), 1);
    };
    a01 = rows2(L.half.base + c0), a23 = rows2(L.half.base + c0 + 2 * P);
    b01 = rows2(L.half.base + c8), b23 = rows2(L.half.base + c8 + 2 * P);
  }
  constexpr int kStep[4] = {0, 1, 8, 9};  // (x0, y0), (x1, y0), (x0, y1), (x1, y1) from (x0, y0)
  for (int k = 0; k < 4; ++k) {
    const __m512i ik = _mm512_add_epi32(w.idx, _mm512_set1_epi32(kStep[k]));
    tex[k] = _mm512_mask_blend_ps(0xFF00, _mm512_maskz_permutex2var_ps(kAll16, a01, ik, a23),
                                  _mm512_maskz_permutex2var_ps(kAll16, b01, ik, b23));
    if constexpr (F == TexelFormat::d16) tex[k] = decode_d16x16(_mm512_castps_si512(tex[k]));
  }
}

// The rest of a sixteen-lane lookup once its taps are loaded (as load_pairs16 returns them): the reference
// clamped for the fixed-point formats, d24 decoded, the compares, and blend_taps8's blend as mask moves.
template <TexelFormat F>
inline __m512 compare_blend16(__m512 ref, __m512 tex[4], __m512 u, __m512 fu, __m512 v, __m512 fv) {
  __m512 r = ref;
  if constexpr (F != TexelFormat::d32f) r = _mm512_maskz_min_ps(kAll16, _mm512_maskz_max_ps(kAll16, ref, _mm512_setzero_ps()), _mm512_set1_ps(1.0f));
  if constexpr (F == TexelFormat::d24) {  // raw bits decoded as compare_taps8 does
    const __m512i mask = _mm512_set1_epi32(0xFFFFFF);
    const __m512 maxcode = _mm512_set1_ps(16777215.0f);
    for (int k = 0; k < 4; ++k)
      tex[k] = _mm512_div_ps(_mm512_maskz_cvtepi32_ps(kAll16, _mm512_and_si512(_mm512_castps_si512(tex[k]), mask)), maxcode);
  }
  __mmask16 pass[4];
  for (int k = 0; k < 4; ++k) pass[k] = _mm512_cmp_ps_mask(r, tex[k], _CMP_LE_OQ);
  // blend_taps8: lerp(a, r0, r1) with r0, r1 in {0, 1} is 0, a, 1 − a or 1, picked by the two masks.
  const __m512 a = _mm512_sub_ps(u, fu), b = _mm512_sub_ps(v, fv);
  const __m512 one = _mm512_set1_ps(1.0f), one_minus_a = _mm512_sub_ps(one, a);
  auto lerp01 = [&](__mmask16 m0, __mmask16 m1) {
    return _mm512_mask_blend_ps(m0, _mm512_maskz_mov_ps(m1, a), _mm512_mask_blend_ps(m1, one_minus_a, one));
  };
  const __m512 xa = lerp01(pass[0], pass[1]), xc = lerp01(pass[2], pass[3]);
  return _mm512_add_ps(xa, _mm512_mul_ps(b, _mm512_sub_ps(xc, xa)));
}

// Texel coordinates of sixteen lookups (texel_coord8), their floors and integer floors.
struct Coords16 {
  __m512 u, v, fu, fv;
  __m512i i0, j0;
  Coords16() = default;
  Coords16(const Pcf16Level& L, __m512 s, __m512 t) {
    const __m512 half = _mm512_set1_ps(0.5f);
    u = _mm512_sub_ps(_mm512_mul_ps(s, L.fwidth), half);
    v = _mm512_sub_ps(_mm512_mul_ps(t, L.fheight), half);
    fu = _mm512_maskz_roundscale_ps(kAll16, u, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    fv = _mm512_maskz_roundscale_ps(kAll16, v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    i0 = _mm512_maskz_cvttps_epi32(kAll16, fu), j0 = _mm512_maskz_cvttps_epi32(kAll16, fv);
  }
  // Lanes whose footprint is not wholly inside the map (i0 > W − 2 or j0 > H − 2 unsigned: a negative, NaN or
  // huge coordinate converts to an index above W − 2).
  __mmask16 outside(const Pcf16Level& L) const {
    return _mm512_cmpgt_epu32_mask(i0, L.w2) | _mm512_cmpgt_epu32_mask(j0, L.h2);
  }
};

inline __m256 lower8(__m512 v) { return _mm512_extractf32x8_ps(v, 0); }
inline __m256 upper8(__m512 v) { return _mm512_extractf32x8_ps(v, 1); }

// Sixteen lookups at (s, t, ref) per lane, each equal to pcf_lequal bit for bit: the short path of
// pcf_lequal_gather8 on sixteen lanes (the same operations: floor by roundscale, the unsigned inside test,
// compares, the mask blends of blend_taps8 as AVX-512 mask moves), its taps from the window path where it fits,
// else from load_pairs16; a group with any footprint not wholly inside the map, or a map one texel wide or high,
// goes to pcf_lequal_x8 as two halves.
template <TexelFormat F, bool kBorderWrap>
inline __m512 pcf_lequal_gather16(const Pcf16Level& L, __m512 s, __m512 t, __m512 ref, float border_depth) {
  static_assert(F == TexelFormat::d16 || F == TexelFormat::d24 || F == TexelFormat::d32f);
  auto halves = [&] {  // pcf_lequal_x8, which also serves d16 maps one texel wide or high (lane by lane)
    using raster::simd::VecF32;
    const VecF32 lo = pcf_lequal_x8<F, kBorderWrap>(L.half, {lower8(s)}, {lower8(t)}, {lower8(ref)}, border_depth);
    const VecF32 hi = pcf_lequal_x8<F, kBorderWrap>(L.half, {upper8(s)}, {upper8(t)}, {upper8(ref)}, border_depth);
    return _mm512_insertf32x8(_mm512_castps256_ps512(lo.v), hi.v, 1);
  };
  if (L.half.tiny) [[unlikely]]
    return halves();
  const Coords16 c(L, s, t);
  if (c.outside(L) != 0) [[unlikely]]
    return halves();
  __m512 tex[4];
  Window16 w;
  if (window_fits16<F>(L, c.i0, c.j0, w))
    window_taps16<F>(L, w, tex);
  else
    load_pairs16<F>(L, _mm512_add_epi32(_mm512_mullo_epi32(c.j0, F == TexelFormat::d16 ? L.vpitch16 : L.vpitch), c.i0),
                    tex);
  return compare_blend16<F>(ref, tex, c.u, c.fu, c.v, c.fv);
}

// N sixteen-lane lookups, lane l of out[n] equal to pcf_lequal_gather16(L, s[n], t[n], ref[n]) bit for bit. The
// work runs stage by stage across the N (coordinates, then the inside and window tests of all, then each one's
// taps, compares and blend) with one branch for the lot, so the out-of-order core overlaps their latency chains
// (an estimated 60 cycles each from the coordinates through the window test and the permutes to the blend) when every
// lookup takes the window path; else each goes through pcf_lequal_gather16. Measured on the 2-core AMD EPYC
// (Zen 5), 2 threads, the PCF bench's Poisson pass (ms per frame, alternating runs): one lookup at a time, before
// the window path, 17.0 / 17.1 / 17.0 / 17.3 / 16.7; N = 2 16.2 / 17.2 / 16.2 / 17.1 / 16.5; N = 4 13.0 / 13.5 /
// 13.0 / 13.2 / 13.7; N = 8 (all sixteen taps in one call) slower than N = 4 (17.9–20.3 against 14.6–16.8 in one
// noisy series): its values no longer fit the 32 vector registers. The loops are unrolled by pragma: left rolled
// by GCC, the last stage ran one lookup after the other (15.8 against 13.8 ms). Out of line, as GCC chose
// for it anyway: the fragment stage around it stays small.
template <TexelFormat F, bool kBorderWrap, int N>
[[gnu::noinline]] void pcf_lequal_gather16_n(const Pcf16Level& L, const __m512* s, const __m512* t,
                                             const __m512* ref, __m512* out, float border_depth) {
  static_assert(F == TexelFormat::d16 || F == TexelFormat::d24 || F == TexelFormat::d32f);
  __mmask16 inside = L.half.tiny ? 0 : kAll16;
  Coords16 c[N];
  Window16 w[N];
#pragma GCC unroll 8
  for (int n = 0; n < N; ++n) {
    c[n] = Coords16(L, s[n], t[n]);
    inside &= ~c[n].outside(L);
  }
  bool fits = true;
#pragma GCC unroll 8
  for (int n = 0; n < N; ++n) fits &= window_fits16<F>(L, c[n].i0, c[n].j0, w[n]);
  if (!(fits && inside == kAll16)) [[unlikely]] {
    for (int n = 0; n < N; ++n) out[n] = pcf_lequal_gather16<F, kBorderWrap>(L, s[n], t[n], ref[n], border_depth);
    return;
  }
#pragma GCC unroll 8
  for (int n = 0; n < N; ++n) {
    __m512 tex[4];
    window_taps16<F>(L, w[n], tex);
    out[n] = compare_blend16<F>(ref[n], tex, c[n].u, c[n].fu, c[n].v, c[n].fv);
  }
}

#endif  // SHADOWLAB_SIMD_AVX512

// Sixteen lookups held in raster/simd's sixteen-lane type: lane l is pcf_lequal(L, (s[l], t[l], ref[l])), bit
// for bit. One AVX-512 kernel where the build has it, else the eight-lane form on each half.
template <TexelFormat F, bool kBorderWrap>
inline raster::simd::VecF32x16 pcf_lequal_x16(const Pcf16Level& L, raster::simd::VecF32x16 s,
                                              raster::simd::VecF32x16 t, raster::simd::VecF32x16 ref,
                                              float border_depth) {
#if defined(SHADOWLAB_SIMD_AVX512)
  return {pcf_lequal_gather16<F, kBorderWrap>(L, s.v, t.v, ref.v, border_depth)};
#else
  return raster::simd::VecF32x16::rows(pcf_lequal_x8<F, kBorderWrap>(L.half, s.row0(), t.row0(), ref.row0(), border_depth),
                                       pcf_lequal_x8<F, kBorderWrap>(L.half, s.row1(), t.row1(), ref.row1(), border_depth));
#endif
}

// N sixteen-lane lookups at once, out[n] equal to pcf_lequal_x16(L, s[n], t[n], ref[n]) bit for bit: one
// pcf_lequal_gather16_n in AVX-512 builds, else one at a time.
template <TexelFormat F, bool kBorderWrap, size_t N>
inline void pcf_lequal_x16_n(const Pcf16Level& L, const std::array<raster::simd::VecF32x16, N>& s,
                             const std::array<raster::simd::VecF32x16, N>& t,
                             const std::array<raster::simd::VecF32x16, N>& ref,
                             std::array<raster::simd::VecF32x16, N>& out, float border_depth) {
#if defined(SHADOWLAB_SIMD_AVX512)
  __m512 ps[N], pt[N], pr[N], po[N];
  for (size_t n = 0; n < N; ++n) ps[n] = s[n].v, pt[n] = t[n].v, pr[n] = ref[n].v;
  pcf_lequal_gather16_n<F, kBorderWrap, int(N)>(L, ps, pt, pr, po, border_depth);
  for (size_t n = 0; n < N; ++n) out[n] = {po[n]};
#else
  for (size_t n = 0; n < N; ++n) out[n] = pcf_lequal_x16<F, kBorderWrap>(L, s[n], t[n], ref[n], border_depth);
#endif
}

// How many sixteen-lane lookups a multi-tap filter hands over at once (pcf_lequal_x16_n): four in AVX-512 builds
// (see pcf_lequal_gather16_n), one elsewhere.
#if defined(SHADOWLAB_SIMD_AVX512)
inline constexpr int kLookupsPerBatch = 4;
#else
inline constexpr int kLookupsPerBatch = 1;
#endif

// How many taps of a fragment pair's eight points a multi-tap filter looks up at once (shadow_filters_x8.h, and
// the PCF bench's Poisson shader): two, as one sixteen-lane lookup, with AVX-512; one elsewhere, where a pair is
// two eight-lane lookups anyway and measured slower (the Poisson pass at 2 threads 19.1 → 21.2 ms with AVX2 on the
// Zen 5 EPYC: the larger loop body no longer inlines into the fragment stage). Either way gives the same bits.
#if defined(SHADOWLAB_SIMD_AVX512)
inline constexpr int kTapsPerLookup = 2;
#else
inline constexpr int kTapsPerLookup = 1;
#endif

}  // namespace detail
SHADOWLAB_ISA_END
}  // namespace shading
