// The kernels behind ShadowLookup2D's fast paths: hardware PCF with LEQUAL at level 0 of a d16, d24 or d32f
// map, clamp_to_edge or clamp_to_border. Each does exactly the operations of footprint_2d + reduce_compare in
// the same order (so results are bit-identical to the generic lookups), without switches:
//   pcf_lequal_scalar  the scalar twin, always compiled;
//   pcf_lequal_sse     one lookup, its four taps in one SSE register (AVX2 builds);
//   pcf_lequal_gather8 eight lookups at once in AVX2 lanes (d16, d24, d32f): a short path for groups whose
//                      footprints lie inside the map, pcf_lequal_any8 for the others;
//   pcf_lequal_x8      eight lookups in raster/simd lanes: gather8, or lane by lane (scalar builds, and d16 maps
//                      one texel wide or high);
// The sixteen-lane forms (pcf_lequal_gather16, its window path and batches, pcf_lequal_x16) are in
// pcf_kernel16.h. These two files hold the only intrinsics in shading/: raster/simd's lane types have no floor or
// gather.
#pragma once
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <glm/vec3.hpp>

#include "raster/simd/vec.h"
#include "shading/filter.h"
#include "shading/sampler.h"
#include "shading/texel_format.h"
#include "shading/texture.h"
#include "shading/wrap.h"

#if defined(SHADOWLAB_SIMD_AVX2)
#include <immintrin.h>
#endif
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN
namespace detail {

// 1 where ref <= texel, else 0, without a branch: the same values as compare_ref(lequal, …).
inline float le_one(float ref, float texel) {
  return std::bit_cast<float>(uint32_t(-int32_t(ref <= texel)) & 0x3F800000u);
}
// a where c holds, else b, without a branch.
inline float pick(bool c, float a, float b) {
  const uint32_t m = uint32_t(-int32_t(c));
  return std::bit_cast<float>((std::bit_cast<uint32_t>(a) & m) | (std::bit_cast<uint32_t>(b) & ~m));
}

template <TexelFormat F, bool kBorderWrap>
inline float pcf_lequal_scalar(const TextureLevel& L, glm::vec3 str, float border_depth) {
  const float u = clamp_texel_coord(str.x * L.fwidth - 0.5f);
  const float v = clamp_texel_coord(str.y * L.fheight - 0.5f);
  const float fu = std::floor(u), fv = std::floor(v);
  const float a = u - fu, b = v - fv;
  const int i0 = int(fu), j0 = int(fv);
  const float ref = compare_reference(F, str.z);
  float r[4];
  if constexpr (!kBorderWrap) {
    const int x0 = std::clamp(i0, 0, L.width - 1), x1 = std::clamp(i0 + 1, 0, L.width - 1);
    const std::byte* row0 = L.row(std::clamp(j0, 0, L.height - 1));
    const std::byte* row1 = L.row(std::clamp(j0 + 1, 0, L.height - 1));
    r[0] = le_one(ref, Texel<F>::red(row0, x0));
    r[1] = le_one(ref, Texel<F>::red(row0, x1));
    r[2] = le_one(ref, Texel<F>::red(row1, x0));
    r[3] = le_one(ref, Texel<F>::red(row1, x1));
  } else {
    const float rb = le_one(ref, border_depth);
    const bool in_i0 = unsigned(i0) < unsigned(L.width), in_i1 = unsigned(i0 + 1) < unsigned(L.width);
    const bool in_j0 = unsigned(j0) < unsigned(L.height), in_j1 = unsigned(j0 + 1) < unsigned(L.height);
    const int x0 = in_i0 ? i0 : 0, x1 = in_i1 ? i0 + 1 : 0;
    const std::byte* row0 = L.row(in_j0 ? j0 : 0);
    const std::byte* row1 = L.row(in_j1 ? j0 + 1 : 0);
    r[0] = pick(in_i0 && in_j0, le_one(ref, Texel<F>::red(row0, x0)), rb);
    r[1] = pick(in_i1 && in_j0, le_one(ref, Texel<F>::red(row0, x1)), rb);
    r[2] = pick(in_i0 && in_j1, le_one(ref, Texel<F>::red(row1, x0)), rb);
    r[3] = pick(in_i1 && in_j1, le_one(ref, Texel<F>::red(row1, x1)), rb);
  }
  return lerp(b, lerp(a, r[0], r[1]), lerp(a, r[2], r[3]));
}

#if defined(SHADOWLAB_SIMD_AVX2)

// Lanes (s, t, ·, ·) → u, v as the scalar code computes them: s · size − 0.5, kept within ±2^30 (NaN → −2^30:
// maxps returns its second operand when the first is NaN).
inline __m128 texel_coords(float s, float t, const TextureLevel& L) {
  const __m128 uv = _mm_sub_ps(_mm_mul_ps(_mm_setr_ps(s, t, 0.0f, 0.0f), _mm_setr_ps(L.fwidth, L.fheight, 0.0f, 0.0f)),
                               _mm_set1_ps(0.5f));
  return _mm_min_ps(_mm_max_ps(uv, _mm_set1_ps(-kMaxTexelCoord)), _mm_set1_ps(kMaxTexelCoord));
}

template <TexelFormat F, bool kBorderWrap>
inline float pcf_lequal_sse(const TextureLevel& L, glm::vec3 str, float border_depth) {
  const __m128 uv = texel_coords(str.x, str.y, L);
  const __m128 fl = _mm_floor_ps(uv);
  const __m128 frac = _mm_sub_ps(uv, fl);  // (a, b, ·, ·)
  const __m128i i0 = _mm_cvttps_epi32(fl);
  // (x0, y0, x1, y1) = (i0, j0, i0 + 1, j0 + 1)
  const __m128i ij = _mm_add_epi32(_mm_shuffle_epi32(i0, _MM_SHUFFLE(1, 0, 1, 0)), _mm_setr_epi32(0, 0, 1, 1));
  const __m128i hi = _mm_setr_epi32(L.width - 1, L.height - 1, L.width - 1, L.height - 1);
  const __m128i c = _mm_min_epi32(_mm_max_epi32(ij, _mm_setzero_si128()), hi);
  const int x0 = _mm_cvtsi128_si32(c), y0 = _mm_extract_epi32(c, 1), x1 = _mm_extract_epi32(c, 2),
            y1 = _mm_extract_epi32(c, 3);
  const std::byte* row0 = L.row(y0);
  const std::byte* row1 = L.row(y1);
  // Taps in lanes (x0 y0, x0 y1, x1 y0, x1 y1).
  const __m128 texels =
      _mm_setr_ps(Texel<F>::red(row0, x0), Texel<F>::red(row1, x0), Texel<F>::red(row0, x1), Texel<F>::red(row1, x1));
  const __m128 ref = _mm_set1_ps(compare_reference(F, str.z));
  const __m128 one = _mm_set1_ps(1.0f);
  __m128 r = _mm_and_ps(_mm_cmple_ps(ref, texels), one);
  if constexpr (kBorderWrap) {
    // A tap is inside when both its indices are: (x, y) lane masks before clamping, paired per tap.
    const __m128i in = _mm_and_si128(_mm_cmpgt_epi32(ij, _mm_set1_epi32(-1)),
                                     _mm_cmpgt_epi32(_mm_add_epi32(hi, _mm_set1_epi32(1)), ij));
    const __m128i xs = _mm_shuffle_epi32(in, _MM_SHUFFLE(2, 2, 0, 0));
    const __m128i ys = _mm_shuffle_epi32(in, _MM_SHUFFLE(3, 1, 3, 1));
    const __m128 rb = _mm_and_ps(_mm_cmple_ps(ref, _mm_set1_ps(border_depth)), one);
    r = _mm_blendv_ps(rb, r, _mm_castsi128_ps(_mm_and_si128(xs, ys)));
  }
  // Rows: (r00, r01) + a · ((r10, r11) − (r00, r01)), then along t.
  const __m128 r_hi = _mm_movehl_ps(r, r);
  const __m128 a = _mm_shuffle_ps(frac, frac, 0);
  const __m128 x = _mm_add_ps(r, _mm_mul_ps(a, _mm_sub_ps(r_hi, r)));
  const __m128 x1v = _mm_shuffle_ps(x, x, 1);
  const __m128 b = _mm_shuffle_ps(frac, frac, 1);
  return _mm_cvtss_f32(_mm_add_ss(x, _mm_mul_ss(b, _mm_sub_ss(x1v, x))));
}

// What the eight-lane kernel needs of a texture level, splatted once (per kernel, not per lookup): the sizes as
// floats for coordinate scaling, the clamp limits, the row pitch in texels and the base pointer.
struct Pcf8Level {
  TextureLevel level;
  __m256 fwidth, fheight;
  __m256i wmax, hmax;  // width − 1, height − 1
  __m256i w2, h2;      // width − 2, height − 2: the last column / row a texel pair can start at
  __m256i vpitch;      // 32-bit texels from one row to the next
  __m256i vpitch16;    // 16-bit texels from one row to the next
  __m256i madd, madd16;  // (row pitch, 1) as the 16-bit halves of each lane, in 32- and 16-bit texels (pair_offsets8_madd)
  const float* base;
  int pitch;
  bool tiny;  // one texel wide or high: no pair fits, so the kernel gathers
  bool wide_pitch, wide_pitch16;  // a pitch of 2^15 texels or more, beyond pair_offsets8_madd (no map or target has one)
  explicit Pcf8Level(const TextureLevel& L)
      : level(L), fwidth(_mm256_set1_ps(L.fwidth)), fheight(_mm256_set1_ps(L.fheight)),
        wmax(_mm256_set1_epi32(L.width - 1)), hmax(_mm256_set1_epi32(L.height - 1)),
        w2(_mm256_set1_epi32(L.width - 2)), h2(_mm256_set1_epi32(L.height - 2)),
        // Element offsets fit int32: rows are at most 16384 texels and a target's pitch at most 16384.
        vpitch(_mm256_set1_epi32(int(L.row_bytes / 4))), vpitch16(_mm256_set1_epi32(int(L.row_bytes / 2))),
        base(reinterpret_cast<const float*>(L.data)),
        pitch(int(L.row_bytes / 4)), tiny(L.width < 2 || L.height < 2) {
    auto pair = [](size_t pitch) { return _mm256_set1_epi32(int32_t(1u << 16 | (uint32_t(pitch) & 0x7FFFu))); };
    wide_pitch = L.row_bytes / 4 > 32767, wide_pitch16 = L.row_bytes / 2 > 32767;
    madd = pair(L.row_bytes / 4), madd16 = pair(L.row_bytes / 2);
  }
};

// s · size − 0.5: the texel coordinate of footprint_2d, before clamp_texel_coord.
inline __m256 texel_coord8(__m256 s, __m256 size) { return _mm256_sub_ps(_mm256_mul_ps(s, size), _mm256_set1_ps(0.5f)); }

// Element offsets of the texel pairs starting at column xb of row yb: in 32-bit texels, or 16-bit for d16.
template <TexelFormat F>
inline __m256i pair_offsets8(const Pcf8Level& L, __m256i xb, __m256i yb) {
  return _mm256_add_epi32(_mm256_mullo_epi32(yb, F == TexelFormat::d16 ? L.vpitch16 : L.vpitch), xb);
}

// The same offsets for pair starts known to lie inside the map (0 <= xb <= W − 2, 0 <= yb <= H − 2, so both
// below 2^15), with one vpmaddwd: each lane holds yb and xb as its 16-bit halves, multiplied by (pitch, 1) and
// summed, yb · pitch + xb, the value pair_offsets8 gives. With the shift and the or that takes 7 cycles where
// vpmulld and the add take 11 on recent Intel cores, and the offsets lie on the lookup's longest chain
// (coordinates, offsets, loads, compares, blend). Needs a pitch below 2^15 (Pcf8Level::wide_pitch says where it
// is not).
template <TexelFormat F>
inline __m256i pair_offsets8_madd(const Pcf8Level& L, __m256i xb, __m256i yb) {
  return _mm256_madd_epi16(_mm256_or_si256(yb, _mm256_slli_epi32(xb, 16)), F == TexelFormat::d16 ? L.madd16 : L.madd);
}

// The four texels of eight bilinear footprints whose pairs start at element offset off (see pair_offsets8) of a
// map at least 2 × 2: tex[0..3] at (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1).
//   32-bit texels (d24 as raw bits, d32f): scalar loads of 8-byte pairs, much cheaper than AVX2 gathers on the
//   machines measured; d16: each lane's pair is one 32-bit word, gathered once per row and decoded as
//   Texel<d16> does (code / 65535, an exact conversion and a correctly rounded division).
// A camera pass samples the map in screen order: the next blocks to the right read the texels a little to the
// right of this lookup's. So each eight-lane lookup asks for the line kPrefetchTexels texels right of lanes 0 and
// 4 (its two rows of pixels), in both texel rows of their footprints. Measured on the 2-core AMD EPYC at 2 threads
// (bench/pcf_pass_bench.cpp, 1920×1080 into a 2048² map, four runs each, alternating, medians): one PCF lookup
// per pixel 6.9 → 4.9 ms (d32f) and 8.9 → 5.3 ms (d16); 16 Poisson taps 37.5 → 34.2 ms (d32f) and 53 → 55 ms (d16,
// within that machine's noise). 16 to 64 texels ahead measured alike for d32f. A prefetch never faults, so an
// address past the map needs no test. `off` are element offsets of texel_bytes each.
inline constexpr int kPrefetchTexels = 32;
inline void prefetch_ahead8(const std::byte* base, ptrdiff_t row_bytes, int texel_bytes, int off0, int off4) {
  // Addresses as integers: past the map's end they are no pointers into it.
  const uintptr_t a = reinterpret_cast<uintptr_t>(base) + uintptr_t(ptrdiff_t(off0 + kPrefetchTexels) * texel_bytes);
  const uintptr_t b = reinterpret_cast<uintptr_t>(base) + uintptr_t(ptrdiff_t(off4 + kPrefetchTexels) * texel_bytes);
  const uintptr_t next_row = uintptr_t(row_bytes);
  for (const uintptr_t p : {a, a + next_row, b, b + next_row}) __builtin_prefetch(reinterpret_cast<const void*>(p), 0, 3);
}

template <TexelFormat F>
inline void load_pairs8(const Pcf8Level& L, __m256i offv, __m256 tex[4]) {
  if constexpr (F == TexelFormat::d16) {
    prefetch_ahead8(L.level.data, ptrdiff_t(L.level.row_bytes), 2, _mm256_cvtsi256_si32(offv),
                    _mm_cvtsi128_si32(_mm256_extracti128_si256(offv, 1)));
    const int* base = reinterpret_cast<const int*>(L.level.data);
    const __m256i low = _mm256_set1_epi32(0xFFFF);
    const __m256 maxcode = _mm256_set1_ps(65535.0f);
    for (int r = 0; r < 2; ++r) {
      const __m256i pair = _mm256_i32gather_epi32(base, r ? _mm256_add_epi32(offv, L.vpitch16) : offv, 2);
      tex[2 * r] = _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_and_si256(pair, low)), maxcode);
      tex[2 * r + 1] = _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_srli_epi32(pair, 16)), maxcode);
    }
  } else {
    // The offsets move to general registers two at a time (vmovq / vpextrq, then a shift): storing the vector
    // and loading the eight offsets back was slower on Zen 3 (1.12x to 1.2x on the Poisson pass), the loads
    // waiting on the store rather than being forwarded from it.
    const __m128i olo = _mm256_castsi256_si128(offv), ohi = _mm256_extracti128_si256(offv, 1);
    const uint64_t q0 = uint64_t(_mm_cvtsi128_si64(olo)), q1 = uint64_t(_mm_extract_epi64(olo, 1));
    const uint64_t q2 = uint64_t(_mm_cvtsi128_si64(ohi)), q3 = uint64_t(_mm_extract_epi64(ohi, 1));
    // Offsets are non-negative (clamped to the map), so the upper halves are the odd lanes as they stand.
    const uint64_t off[8] = {uint32_t(q0), q0 >> 32, uint32_t(q1), q1 >> 32,
                             uint32_t(q2), q2 >> 32, uint32_t(q3), q3 >> 32};
    prefetch_ahead8(L.level.data, ptrdiff_t(L.level.row_bytes), 4, int(off[0]), int(off[4]));
    for (int r = 0; r < 2; ++r) {
      const float* row = L.base + r * L.pitch;
      // The pairs of lanes a, b, c, d of this row as the four 64-bit elements of one register: the first loaded
      // alone, the others broadcast and blended in. A broadcast from memory is a load alone and the blend runs on
      // any of three ports, where a load into the upper half (movhps) and the 128-bit insert both need the one
      // shuffle port of Intel cores, which the shuffles below and the shader's own also need: per row 6 blends
      // and 2 shuffles instead of 8 shuffles. With compare_blend_taps8's mask blends, on the 2-core Xeon (family 6
      // model 167, AVX-512 path), the one-lookup pass faster in every round (see there); on its AVX2 path, four
      // rounds, no change out of the noise.
      auto pairs4 = [&](int a, int b, int c, int d) {
        auto pair = [&](int l) {
          uint64_t q;
          std::memcpy(&q, row + off[l], sizeof q);
          return _mm256_set1_epi64x(int64_t(q));
        };
        __m256i v = _mm256_castsi128_si256(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(row + off[a])));
        v = _mm256_blend_epi32(v, pair(b), 0x0C);
        v = _mm256_blend_epi32(v, pair(c), 0x30);
        v = _mm256_blend_epi32(v, pair(d), 0xC0);
        return _mm256_castsi256_ps(v);
      };
      // Pairs of lanes (0 1 | 4 5) and (2 3 | 6 7); the even elements are the x texels, the odd ones x + 1.
      const __m256 p01 = pairs4(0, 1, 4, 5);
      const __m256 p23 = pairs4(2, 3, 6, 7);
      tex[2 * r] = _mm256_shuffle_ps(p01, p23, _MM_SHUFFLE(2, 0, 2, 0));
      tex[2 * r + 1] = _mm256_shuffle_ps(p01, p23, _MM_SHUFFLE(3, 1, 3, 1));
    }
  }
}

// Lanes whose pair start was clamped (i0 < 0 or i0 > W − 2, likewise j0) read the pair next to their footprint:
// there both x taps are the edge texel. xb, yb are the clamped starts the pairs were read at.
inline void fix_edge_taps8(const Pcf8Level& L, __m256i i0, __m256i j0, __m256i xb, __m256i yb, __m256 tex[4]) {
  const __m256i moved = _mm256_or_si256(_mm256_xor_si256(xb, i0), _mm256_xor_si256(yb, j0));
  if (_mm256_testz_si256(moved, moved)) return;
  // i0 < 0: x1 is texel 0 too (the left one); i0 > W − 2: x0 is texel W − 1 too (the right one). Rows alike.
  const __m256i zero = _mm256_setzero_si256();
  const __m256i left = _mm256_cmpgt_epi32(zero, i0), right = _mm256_cmpgt_epi32(i0, L.w2);
  const __m256i below = _mm256_cmpgt_epi32(zero, j0), above = _mm256_cmpgt_epi32(j0, L.h2);
  for (int r = 0; r < 4; r += 2) {
    tex[r + 1] = _mm256_blendv_ps(tex[r + 1], tex[r], _mm256_castsi256_ps(left));
    tex[r] = _mm256_blendv_ps(tex[r], tex[r + 1], _mm256_castsi256_ps(right));
  }
  for (int c = 0; c < 2; ++c) {
    tex[c + 2] = _mm256_blendv_ps(tex[c + 2], tex[c], _mm256_castsi256_ps(below));
    tex[c] = _mm256_blendv_ps(tex[c], tex[c + 2], _mm256_castsi256_ps(above));
  }
}

// The four taps of eight footprints anywhere: x0 = clamp(i0, 0, W − 1), x1 = clamp(i0 + 1, 0, W − 1) and likewise
// y0, y1 from j0 (d24 as raw bits). Where the map is at least 2 × 2 each lane reads its pairs at column
// clamp(i0, 0, W − 2) of rows clamp(j0, 0, H − 2) and the next, and lanes at an edge are fixed afterwards; a map
// one texel wide or high gathers (never d16: pcf_lequal_x8 runs those lane by lane).
template <TexelFormat F>
inline void fetch_taps8(const Pcf8Level& L, __m256i i0, __m256i j0, __m256 tex[4]) {
  const __m256i zero = _mm256_setzero_si256(), one = _mm256_set1_epi32(1);
  if (F != TexelFormat::d16 && L.tiny) {
    auto clamp = [&](__m256i i, __m256i m) { return _mm256_min_epi32(_mm256_max_epi32(i, zero), m); };
    const __m256i x0 = clamp(i0, L.wmax), x1 = clamp(_mm256_add_epi32(i0, one), L.wmax);
    const __m256i o0 = _mm256_mullo_epi32(clamp(j0, L.hmax), L.vpitch);
    const __m256i o1 = _mm256_mullo_epi32(clamp(_mm256_add_epi32(j0, one), L.hmax), L.vpitch);
    tex[0] = _mm256_i32gather_ps(L.base, _mm256_add_epi32(o0, x0), 4);
    tex[1] = _mm256_i32gather_ps(L.base, _mm256_add_epi32(o0, x1), 4);
    tex[2] = _mm256_i32gather_ps(L.base, _mm256_add_epi32(o1, x0), 4);
    tex[3] = _mm256_i32gather_ps(L.base, _mm256_add_epi32(o1, x1), 4);
    return;
  }
  const __m256i xb = _mm256_min_epi32(_mm256_max_epi32(i0, zero), L.w2);
  const __m256i yb = _mm256_min_epi32(_mm256_max_epi32(j0, zero), L.h2);
  load_pairs8<F>(L, pair_offsets8<F>(L, xb, yb), tex);
  fix_edge_taps8(L, i0, j0, xb, yb, tex);
}

// The reference as compare_reference makes it (clamped to [0, 1] for the fixed-point formats), and the taps
// turned into compare masks: all ones where the tap passes (ref <= texel). d24 taps arrive as raw bits and are
// decoded first: the low 24 bits as a float code divided by 2^24 − 1, the same correctly rounded division as
// Texel<d24>.
template <TexelFormat F>
inline __m256 reference8(__m256 ref) {
  if constexpr (F == TexelFormat::d32f) return ref;
  else return _mm256_min_ps(_mm256_max_ps(ref, _mm256_setzero_ps()), _mm256_set1_ps(1.0f));
}
template <TexelFormat F>
inline void decode_taps8(__m256 tex[4]) {
  if constexpr (F == TexelFormat::d24) {
    const __m256i mask = _mm256_set1_epi32(0xFFFFFF);
    const __m256 maxcode = _mm256_set1_ps(16777215.0f);
    for (int k = 0; k < 4; ++k)
      tex[k] = _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_and_si256(_mm256_castps_si256(tex[k]), mask)), maxcode);
  }
}
template <TexelFormat F>
inline void compare_taps8(__m256 ref, __m256 tex[4]) {
  decode_taps8<F>(tex);
  for (int k = 0; k < 4; ++k) tex[k] = _mm256_cmp_ps(ref, tex[k], _CMP_LE_OQ);
}

// The bilinear blend of four compare masks with weights a (along s) and b (along t), as reduce_compare does it.
inline __m256 blend_taps8(const __m256 r[4], __m256 a, __m256 b) {
  // lerp(a, r0, r1) = r0 + a · (r1 − r0) with r0, r1 in {0, 1} is exactly 0, 1, a (r0 = 0, r1 = 1) or
  // 1 + a · (−1) = 1 − a (r0 = 1, r1 = 0): chosen by the masks, the same bits with fewer operations.
  const __m256 onef = _mm256_set1_ps(1.0f);
  const __m256 one_minus_a = _mm256_sub_ps(onef, a);
  auto lerp01 = [&](__m256 m0, __m256 m1) {
    return _mm256_blendv_ps(_mm256_and_ps(m1, a), _mm256_blendv_ps(one_minus_a, onef, m1), m0);
  };
  const __m256 xa = lerp01(r[0], r[1]);
  const __m256 xb = lerp01(r[2], r[3]);
  return _mm256_add_ps(xa, _mm256_mul_ps(b, _mm256_sub_ps(xb, xa)));
}

// compare_taps8 then blend_taps8, the same values. With AVX-512 the compares go to mask registers and the blends
// are mask moves, as in the sixteen-lane kernel (compare_blend16): one micro-op each, where vblendvps on a ymm
// register takes three on recent Intel cores (measured on the 2-core Xeon, family 6 model 167: eight independent
// vblendvps 0.9 cycles each, vblendmps 0.3) and one on AMD's. Eight lookups' compare and blend: 10 micro-ops
// instead of 18, and the blends' latency 1 cycle instead of 3. Measured with the pair loads below (load_pairs8)
// in bench/pcf_pass_bench.cpp on that Xeon, AVX-512 path, 2 threads, shadowlab alone, five rounds alternating
// (medians of 31 frames): one lookup per pixel 5.82 / 5.62 / 5.75 / 5.19 / 5.62 → 4.70 / 5.39 / 4.37 / 5.14 /
// 3.64 ms; see docs/performance-log.md.
template <TexelFormat F>
inline __m256 compare_blend_taps8(__m256 ref, __m256 tex[4], __m256 a, __m256 b) {
#if defined(SHADOWLAB_SIMD_AVX512)
  decode_taps8<F>(tex);
  __mmask8 pass[4];
  for (int k = 0; k < 4; ++k) pass[k] = _mm256_cmp_ps_mask(ref, tex[k], _CMP_LE_OQ);
  const __m256 onef = _mm256_set1_ps(1.0f);
  const __m256 one_minus_a = _mm256_sub_ps(onef, a);
  auto lerp01 = [&](__mmask8 m0, __mmask8 m1) {
    return _mm256_mask_blend_ps(m0, _mm256_maskz_mov_ps(m1, a), _mm256_mask_blend_ps(m1, one_minus_a, onef));
  };
  const __m256 xa = lerp01(pass[0], pass[1]);
  const __m256 xb = lerp01(pass[2], pass[3]);
  return _mm256_add_ps(xa, _mm256_mul_ps(b, _mm256_sub_ps(xb, xa)));
#else
  compare_taps8<F>(ref, tex);
  return blend_taps8(tex, a, b);
#endif
}

// Eight lookups anywhere: coordinates clamped as clamp_texel_coord does, taps at the edges fixed, taps outside
// a border-wrapped map replaced by the border's compare. Out of line: the kernel below only calls it for groups
// with a footprint not wholly inside the map.
template <TexelFormat F, bool kBorderWrap>
[[gnu::noinline]] inline __m256 pcf_lequal_any8(const Pcf8Level& L, __m256 s, __m256 t, __m256 ref,
                                                float border_depth) {
  const __m256 lo = _mm256_set1_ps(-kMaxTexelCoord), hi = _mm256_set1_ps(kMaxTexelCoord);
  const __m256 u = _mm256_min_ps(_mm256_max_ps(texel_coord8(s, L.fwidth), lo), hi);
  const __m256 v = _mm256_min_ps(_mm256_max_ps(texel_coord8(t, L.fheight), lo), hi);
  const __m256 fu = _mm256_floor_ps(u), fv = _mm256_floor_ps(v);
  const __m256 a = _mm256_sub_ps(u, fu), b = _mm256_sub_ps(v, fv);
  const __m256i i0 = _mm256_cvttps_epi32(fu), j0 = _mm256_cvttps_epi32(fv);
  __m256 r[4];
  fetch_taps8<F>(L, i0, j0, r);
  ref = reference8<F>(ref);
  compare_taps8<F>(ref, r);
  if constexpr (kBorderWrap) {
    const __m256 rb = _mm256_cmp_ps(ref, _mm256_set1_ps(border_depth), _CMP_LE_OQ);
    const __m256i one = _mm256_set1_epi32(1);
    const __m256i i1 = _mm256_add_epi32(i0, one), j1 = _mm256_add_epi32(j0, one);
    auto inside = [](__m256i i, __m256i max) {
      return _mm256_andnot_si256(_mm256_cmpgt_epi32(_mm256_setzero_si256(), i),
                                 _mm256_xor_si256(_mm256_cmpgt_epi32(i, max), _mm256_set1_epi32(-1)));
    };
    const __m256i ix0 = inside(i0, L.wmax), ix1 = inside(i1, L.wmax), iy0 = inside(j0, L.hmax),
                  iy1 = inside(j1, L.hmax);
    const __m256i in[4] = {_mm256_and_si256(ix0, iy0), _mm256_and_si256(ix1, iy0), _mm256_and_si256(ix0, iy1),
                           _mm256_and_si256(ix1, iy1)};
    for (int k = 0; k < 4; ++k) r[k] = _mm256_blendv_ps(rb, r[k], _mm256_castsi256_ps(in[k]));
  }
  return blend_taps8(r, a, b);
}

// Eight lookups at (s, t, ref) per lane. The short path covers groups whose footprints all lie inside the map
// (0 <= i0 <= W − 2 and 0 <= j0 <= H − 2): there clamp_texel_coord, the edge clamps and the border cannot change
// a value, so they are skipped; one unsigned min per axis tests it (a negative, NaN or huge coordinate converts
// to an index above W − 2). Any other group takes pcf_lequal_any8. A d16 map must be at least 2 × 2
// (pcf_lequal_x8 sees to it).
template <TexelFormat F, bool kBorderWrap>
inline __m256 pcf_lequal_gather8(const Pcf8Level& L, __m256 s, __m256 t, __m256 ref, float border_depth) {
  static_assert(F == TexelFormat::d16 || F == TexelFormat::d24 || F == TexelFormat::d32f);
  if ((F != TexelFormat::d16 && L.tiny) || (F == TexelFormat::d16 ? L.wide_pitch16 : L.wide_pitch)) [[unlikely]]
    return pcf_lequal_any8<F, kBorderWrap>(L, s, t, ref, border_depth);
  const __m256 u = texel_coord8(s, L.fwidth), v = texel_coord8(t, L.fheight);
  // The integer floors by truncation: where u and v are not negative (not even −0) they are the floors, and a
  // lane with a negative one leaves the short path below with the lanes beyond the map (a NaN or huge value
  // converts to 0x80000000, above W − 2). That takes vroundps (8 cycles on recent Intel cores) off the chain to
  // the loads; the floats of the floors, for the weights, are converted back off that chain (exact: below 2^24).
  const __m256i i0 = _mm256_cvttps_epi32(u), j0 = _mm256_cvttps_epi32(v);
  const __m256i xb = _mm256_min_epu32(i0, L.w2), yb = _mm256_min_epu32(j0, L.h2);
  const __m256i negative = _mm256_srai_epi32(_mm256_castps_si256(_mm256_or_ps(u, v)), 31);
  const __m256i moved = _mm256_or_si256(_mm256_or_si256(_mm256_xor_si256(xb, i0), _mm256_xor_si256(yb, j0)), negative);
  if (!_mm256_testz_si256(moved, moved)) [[unlikely]]
    return pcf_lequal_any8<F, kBorderWrap>(L, s, t, ref, border_depth);
  const __m256 fu = _mm256_cvtepi32_ps(i0), fv = _mm256_cvtepi32_ps(j0);
  __m256 r[4];
  load_pairs8<F>(L, pair_offsets8_madd<F>(L, xb, yb), r);
  return compare_blend_taps8<F>(reference8<F>(ref), r, _mm256_sub_ps(u, fu), _mm256_sub_ps(v, fv));
}

// Eight lookups from an array of (s, t, ref).
template <TexelFormat F, bool kBorderWrap>
inline void pcf_lequal_gather8(const Pcf8Level& L, const glm::vec3* p, float* out, float border_depth) {
  const __m256i stride3 = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
  const float* pf = &p[0].x;
  const __m256 s = _mm256_i32gather_ps(pf, stride3, 4), t = _mm256_i32gather_ps(pf + 1, stride3, 4);
  const __m256 ref = _mm256_i32gather_ps(pf + 2, stride3, 4);
  _mm256_storeu_ps(out, pcf_lequal_gather8<F, kBorderWrap>(L, s, t, ref, border_depth));
}

#endif  // SHADOWLAB_SIMD_AVX2

// One lookup: the SSE kernel where the build has it, else the scalar twin.
template <TexelFormat F, bool kBorderWrap>
inline float pcf_lequal(const TextureLevel& L, glm::vec3 str, float border_depth) {
#if defined(SHADOWLAB_SIMD_AVX2)
  return pcf_lequal_sse<F, kBorderWrap>(L, str, border_depth);
#else
  return pcf_lequal_scalar<F, kBorderWrap>(L, str, border_depth);
#endif
}

#if !defined(SHADOWLAB_SIMD_AVX2)
// Scalar builds: the eight-lane form runs lane by lane on the level itself.
struct Pcf8Level {
  TextureLevel level;
  explicit Pcf8Level(const TextureLevel& L) : level(L) {}
};
#endif

// Eight lookups held in SIMD lanes (a fragment_pair shader's coordinates): lane l is
// pcf_lequal(L, (s[l], t[l], ref[l])), bit for bit. Gathers for d24 and d32f, else lane by lane.
template <TexelFormat F, bool kBorderWrap>
inline raster::simd::VecF32 pcf_lequal_x8(const Pcf8Level& L, raster::simd::VecF32 s, raster::simd::VecF32 t,
                                          raster::simd::VecF32 ref, float border_depth) {
#if defined(SHADOWLAB_SIMD_AVX2)
  if (F != TexelFormat::d16 || !L.tiny) return {pcf_lequal_gather8<F, kBorderWrap>(L, s.v, t.v, ref.v, border_depth)};
#endif
  alignas(32) float ps[8], pt[8], pr[8], out[8];
  s.store(ps), t.store(pt), ref.store(pr);
  for (int l = 0; l < 8; ++l)
    out[l] = pcf_lequal<F, kBorderWrap>(L.level, glm::vec3(ps[l], pt[l], pr[l]), border_depth);
  return raster::simd::VecF32::load(out);
}
template <TexelFormat F, bool kBorderWrap>
inline raster::simd::VecF32 pcf_lequal_x8(const TextureLevel& L, raster::simd::VecF32 s, raster::simd::VecF32 t,
                                          raster::simd::VecF32 ref, float border_depth) {
  return pcf_lequal_x8<F, kBorderWrap>(Pcf8Level(L), s, t, ref, border_depth);
}

// The common shadow case: compare LEQUAL, LINEAR without mips (so λ cannot matter), clamp_to_edge or
// clamp_to_border on both axes, a d16, d24 or d32f texture.
inline bool pcf_fast_path_applies(const Texture2D& t, const Sampler& s) {
  return s.compare_mode == CompareMode::ref_to_texture && s.compare_func == CompareFunc::lequal &&
         s.mag_filter == Filter::linear && s.min_filter == Filter::linear &&
         (s.mip_filter == MipFilter::none || t.levels() == 1) && s.wrap_s == s.wrap_t &&
         (s.wrap_s == Wrap::clamp_to_edge || s.wrap_s == Wrap::clamp_to_border) && is_depth(t.format());
}

// One lookup through the kernels for a texture and sampler pcf_fast_path_applies to.
inline float pcf_fast(const Texture2D& t, const Sampler& s, glm::vec3 str) {
  const TextureLevel& L = t.level(0);
  const float border = border_red(t.format(), s.border_color);
  const bool bw = s.wrap_s == Wrap::clamp_to_border;
  switch (t.format()) {
    case TexelFormat::d16:
      return bw ? pcf_lequal<TexelFormat::d16, true>(L, str, border)
                : pcf_lequal<TexelFormat::d16, false>(L, str, border);
    case TexelFormat::d24:
      return bw ? pcf_lequal<TexelFormat::d24, true>(L, str, border)
                : pcf_lequal<TexelFormat::d24, false>(L, str, border);
    default:
      return bw ? pcf_lequal<TexelFormat::d32f, true>(L, str, border)
                : pcf_lequal<TexelFormat::d32f, false>(L, str, border);
  }
}

// n lookups: eight at a time in AVX2 lanes, the rest one by one.
template <TexelFormat F, bool kBorderWrap>
inline void pcf_lequal_many(const TextureLevel& L, const glm::vec3* p, float* out, size_t n, float border_depth) {
  size_t k = 0;
#if defined(SHADOWLAB_SIMD_AVX2)
  if (n >= 8) {
    const Pcf8Level wide(L);
    if (F != TexelFormat::d16 || !wide.tiny)
      for (; k + 8 <= n; k += 8) pcf_lequal_gather8<F, kBorderWrap>(wide, p + k, out + k, border_depth);
  }
#endif
  for (; k < n; ++k) out[k] = pcf_lequal<F, kBorderWrap>(L, p[k], border_depth);
}

}  // namespace detail
SHADOWLAB_ISA_END
}  // namespace shading
