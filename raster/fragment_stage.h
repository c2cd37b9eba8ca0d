// The back end of a shaded draw: covered pixels of a block grouped into 2×2 quads, early depth test when the
// shader allows it, the shader run on the quad (helper lanes included), late depth test, depth write, and the
// colour write with blending. A shader with the wide form (fragment_pair, shader.h) runs on two quads at once
// in SIMD lanes instead, with the depth test, depth write and the colour write of linear RGBA8 and of the
// float formats eight pixels at a time; both paths give the same bits.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "raster/depth_test.h"
#include "raster/interpolation.h"
#include "raster/limits.h"
#include "raster/quad.h"
#include "raster/shader.h"
#include "raster/simd/vec.h"
#include "raster/state.h"
#include "raster/target.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// Scalar depth conversion and load of one pixel, the same as the SIMD path's (the comparison: DepthCompare::test).
template <DepthFormat Format>
struct ScalarDepth {
  using Storage = typename DepthTraits<Format>::Storage;
  static auto convert(float z) {
    if constexpr (Format == DepthFormat::d16) return int32_t(std::nearbyint(z * 65535.0f));
    else if constexpr (Format == DepthFormat::d24) return int32_t(std::nearbyint(z * 16777215.0f));
    else return z;
  }
  static decltype(convert(0.0f)) load(const Storage* p) {
    if constexpr (Format == DepthFormat::d32f) return *p;
    else return int32_t(*p);
  }
};

inline float clamp01(float z) { return z < 0.0f ? 0.0f : (z > 1.0f ? 1.0f : z); }

// Same operation order as plane_depth_columns + plane_depth_clamped (depth_stage.h), one pixel.
inline float plane_depth(const TriangleSetup& t, int32_t x, int32_t y) {
  const float zcol = std::fma(t.dzdx, float(x), t.z_a0);
  return clamp01(std::fma(t.dzdy, float(y), zcol) + t.z_offset);
}

// clamp01 on eight lanes, NaN kept as clamp01 keeps it (maxps and minps return their second operand then).
inline simd::VecF32 clamp01(simd::VecF32 z) {
  return simd::min(simd::VecF32::splat(1.0f), simd::max(simd::VecF32::splat(0.0f), z));
}

// One instantiation per shader and depth format; the depth function is a run-time DepthCompare chosen per draw.
template <class Shader, DepthFormat Format>
struct ShadedStage {
  using V = typename Shader::Varyings;
  using SD = ScalarDepth<Format>;
  using Traits = DepthTraits<Format>;
  static constexpr bool kEarlyZ = !shader_discards<Shader>() && !shader_writes_depth<Shader>();
  static constexpr bool kPair = HasPairFragmentStage<Shader>;

  const Shader* shader;
  const TriangleInterp<V>* interps;  // of the chunk being executed
  DepthTarget* depth;                // may be null (no depth buffer: test always passes, nothing written)
  ColorTarget* color;                // may be null
  DepthCompare depth_test;           // the draw's function (ALWAYS without a depth test)
  bool depth_write, color_write;     // depth_write is false for NEVER, which writes nothing
  BlendMode blend;

  void block(const TriangleSetup& t, int32_t bx, int32_t by, uint64_t mask) const {
    if constexpr (kPair) {
      pair_block(t, bx, by, mask);
      return;
    }
    for (int p = 0; p < 4; ++p) {
      const unsigned m0 = unsigned(mask >> (16 * p)) & 0xFFu, m1 = unsigned(mask >> (16 * p + 8)) & 0xFFu;
      if (!(m0 | m1)) continue;
      for (int q = 0; q < 4; ++q) {
        const unsigned live = ((m0 >> (2 * q)) & 3u) | (((m1 >> (2 * q)) & 3u) << 2);
        if (live) quad(t, bx + 2 * q, by + 2 * p, live);
      }
    }
  }

  void quad(const TriangleSetup& t, int32_t x, int32_t y, unsigned live) const {
    using Storage = typename SD::Storage;
    float z[4];
    for (int l = 0; l < 4; ++l) z[l] = plane_depth(t, x + (l & 1), y + (l >> 1));
    if constexpr (kEarlyZ) {
      if (depth) live &= depth_mask(x, y, z, live);
      if (!live) return;
    }
    QuadIn<V> in;
    in.live = uint8_t(live);
    in.front_facing = !(t.prim & kBackFacingBit);
    const TriangleInterp<V>& ti = interps[t.prim & ~kBackFacingBit];
    for (int l = 0; l < 4; ++l) {
      const float px = float(x + (l & 1)) + 0.5f, py = float(y + (l >> 1)) + 0.5f;
      const float inv_w = interpolate(ti, px, py, in.in[l]);
      in.frag_coord[l] = glm::vec4(px, py, z[l], inv_w);
    }
    QuadOut out;
    shader->fragment(in, out);
    if constexpr (shader_discards<Shader>()) live &= ~unsigned(out.discard);
    if constexpr (shader_writes_depth<Shader>()) {
      for (int l = 0; l < 4; ++l) z[l] = clamp01(out.depth[l]);
    }
    if constexpr (!kEarlyZ) {
      if (depth) live &= depth_mask(x, y, z, live);
    }
    if (!live) return;
    for (int l = 0; l < 4; ++l) {
      if (!(live >> l & 1u)) continue;
      const int32_t px = x + (l & 1), py = y + (l >> 1);
      if (depth && depth_write) {
        Storage* d = depth->row<Storage>(py) + px;
        *d = Storage(SD::convert(z[l]));
      }
      if (color && color_write) write_color(px, py, out.color[l]);
    }
  }

  unsigned depth_mask(int32_t x, int32_t y, const float* z, unsigned live) const {
    unsigned pass = 0;
    for (int l = 0; l < 4; ++l) {
      if (!(live >> l & 1u)) continue;
      const auto* d = depth->row<typename SD::Storage>(y + (l >> 1)) + x + (l & 1);
      if (depth_test.test(SD::convert(z[l]), SD::load(d))) pass |= 1u << l;
    }
    return pass;
  }

  // ---- The wide path: the block as eight 4×2 groups (two quads each), rows of quads bottom to top. What
  // depends only on the column (left or right half) or only on the row pair is computed once per block.
  struct PairColumn {
    simd::VecF32 x, zcol;  // pixel indices; fma(dzdx, x, z_a0)
    typename PairInterp<V>::Columns interp;
  };
  struct PairRow {
    simd::VecF32 y;
    typename PairInterp<V>::Rows interp;
    typename Traits::Storage *d0, *d1;  // the depth rows y, y + 1 (null without a depth target)
    uint32_t *c0, *c1;                  // the RGBA8 colour rows, when the colour write takes the fast path
    float *f0, *f1;                     // the float colour rows, when their colour write takes the fast path
  };

  // Blocks are walked left to right, so the colour line 16 pixels to the right of this block, in each of its
  // rows, is written next or next but one: asked for now, its read from memory (a write needs the line first)
  // overlaps this block's shading. Measured in the full-screen pass of bench/pcf_pass_bench.cpp: 1.09x without
  // a lookup, 1.06x with one PCF tap. A prefetch never faults, so the address past a row's end needs no test.
  static void prefetch_next_colour_lines(const uint32_t* c, ptrdiff_t pitch) {
    for (int r = 0; r < kBlockSize; ++r)
      __builtin_prefetch(reinterpret_cast<const void*>(reinterpret_cast<uintptr_t>(c + r * pitch) + 64), 1, 3);
  }

  // The colour write packs eight RGBA8 pixels at once: linear RGBA8, no blending.
  bool packed_color() const {
    return color && color_write && color->format() == ColorFormat::rgba8 && !color->srgb() &&
           blend == BlendMode::replace;
  }

  // The same for a float target, whose block row is one line (RG32F) or more: the lines right of the block.
  static void prefetch_next_float_lines(const float* f, ptrdiff_t pitch) {
    for (int r = 0; r < kBlockSize; ++r) __builtin_prefetch(f + r * pitch, 1, 3);
  }

  // The float formats store the channels unchanged, so with no blending eight pixels go out as whole rows.
  bool float_color() const {
    return color && color_write && color->channels() > 0 && blend == BlendMode::replace;
  }

  void pair_block(const TriangleSetup& t, int32_t bx, int32_t by, uint64_t mask) const {
    using simd::VecF32;
    alignas(32) static constexpr float kLaneX[8] = {0, 1, 2, 3, 0, 1, 2, 3};
    const PairInterp<V> interp(interps[t.prim & ~kBackFacingBit]);
    const VecF32 half = VecF32::splat(0.5f);
    const bool packed = packed_color();
    PairColumn cols[2];
    for (int h = 0; h < 2; ++h) {
      cols[h].x = VecF32::splat(float(bx + 4 * h)) + VecF32::load(kLaneX);  // exact: indices below 2^24
      cols[h].zcol = simd::fma(VecF32::splat(t.dzdx), cols[h].x, VecF32::splat(t.z_a0));
      cols[h].interp = interp.columns(cols[h].x + half);
    }
    // A fully covered block (the inside of large triangles) runs with its coverage known at compile time.
    if (mask == ~uint64_t(0)) pair_rows<true>(t, interp, cols, bx, by, mask, packed);
    else pair_rows<false>(t, interp, cols, bx, by, mask, packed);
  }

  template <bool kFull>
  [[gnu::always_inline]] void pair_rows(const TriangleSetup& t, const PairInterp<V>& interp, const PairColumn* cols,
                                        int32_t bx, int32_t by, uint64_t mask, bool packed) const {
    using simd::VecF32;
    alignas(32) static constexpr float kLaneY[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    const VecF32 half = VecF32::splat(0.5f), dzdy = VecF32::splat(t.dzdy), z_offset = VecF32::splat(t.z_offset);
    // The block's row pointers, stepped by the pitch (null without a depth target or the packed colour write).
    using Storage = typename Traits::Storage;
    Storage* const d = depth ? depth->row<Storage>(by) + bx : nullptr;
    uint32_t* const c = packed ? reinterpret_cast<uint32_t*>(color->row8(by)) + bx : nullptr;
    const ptrdiff_t dpitch = depth ? depth->pitch() : 0, cpitch = packed ? color->pitch() : 0;
    if (c) prefetch_next_colour_lines(c, cpitch);
    const int channels = float_color() ? color->channels() : 0;
    float* const f = channels ? color->row32f(by) + ptrdiff_t(bx) * channels : nullptr;
    const ptrdiff_t fpitch = ptrdiff_t(channels) * color->pitch();
    if (f) prefetch_next_float_lines(f + kBlockSize * channels, fpitch);
    for (int p = 0; p < 4; ++p) {
      const unsigned rows = kFull ? 0xFFFFu : unsigned(mask >> (16 * p)) & 0xFFFFu;
      if (!rows) continue;
      const int32_t y = by + 2 * p;
      PairRow row;
      row.y = VecF32::splat(float(y)) + VecF32::load(kLaneY);
      row.interp = interp.rows(row.y + half);
      row.d0 = d ? d + 2 * p * dpitch : nullptr;
      row.d1 = d ? row.d0 + dpitch : nullptr;
      row.c0 = c ? c + 2 * p * cpitch : nullptr;
      row.c1 = c ? row.c0 + cpitch : nullptr;
      row.f0 = f ? f + 2 * p * fpitch : nullptr;
      row.f1 = f ? row.f0 + fpitch : nullptr;
      for (int h = 0; h < 2; ++h) {
        const unsigned live = kFull ? 0xFFu : ((rows >> (4 * h)) & 0xFu) | (((rows >> (8 + 4 * h)) & 0xFu) << 4);
        if (!live) continue;
        // plane_depth's operations: fma(dzdy, y, fma(dzdx, x, z_a0)) + z_offset, clamped.
        const VecF32 z = clamp01(simd::fma(dzdy, row.y, cols[h].zcol) + z_offset);
        pair(t, interp, cols[h], row, z, 4 * h, bx + 4 * h, y, live, channels);
      }
    }
  }

  // Lanes as QuadPairIn says: lane i at (x + (i & 3), y + (i >> 2)); the same steps as quad(), eight at a time.
  // `dx` is x's offset from the block's left edge (the row pointers' origin).
  [[gnu::always_inline]] void pair(const TriangleSetup& t, const PairInterp<V>& interp, const PairColumn& col,
                                   const PairRow& row, simd::VecF32 z, int dx, int32_t x, int32_t y,
                                   unsigned live, int channels) const {
    using simd::VecF32;
    typename Traits::Value stored{};
    if (row.d0) stored = simd::load_rows4(row.d0 + dx, row.d1 + dx);
    if constexpr (kEarlyZ) {
      if (row.d0) live &= depth_test(Traits::from_depth(z), stored).bits();
      if (!live) return;
    }
    QuadPairIn<V> in;
    in.live = uint8_t(live);
    in.front_facing = !(t.prim & kBackFacingBit);
    in.frag_x = col.x + VecF32::splat(0.5f), in.frag_y = row.y + VecF32::splat(0.5f), in.frag_z = z;
    in.frag_w = interp(col.interp, row.interp, in.in);
    QuadPairOut out;
    shader->fragment_pair(in, out);
    if constexpr (shader_discards<Shader>()) live &= ~unsigned(out.discard);
    if constexpr (shader_writes_depth<Shader>()) z = clamp01(out.depth);
    const auto frag = Traits::from_depth(z);
    if constexpr (!kEarlyZ) {
      if (row.d0) live &= depth_test(frag, stored).bits();
    }
    if (!live) return;
    if (row.d0 && depth_write)
      simd::store_rows4(simd::select(simd::Mask::from_bits(live), stored, frag), row.d0 + dx, row.d1 + dx);
    if (row.c0) write_packed_color(row.c0 + dx, row.c1 + dx, out, live);
    else if (row.f0 && live == 0xFFu) write_float_color(row.f0 + dx * channels, row.f1 + dx * channels, out, channels);
    else if (color && color_write) write_pair_color(x, y, out, live);
  }

  // ColorTarget::write's conversion, eight pixels at once: clamp to [0, 1] (NaN to 0, what its cast gives on
  // x86), round(c · 255), packed RGBA8. This and write_float_color are always inlined: GCC kept the float one out
  // of line (shared by every shader's stage), and the address of `out` it takes made every pair store its four
  // colour registers to the stack. Measured on the 2-core AMD EPYC (Zen 4), AVX-512 path, 2 threads, shadowlab
  // alone, four rounds alternating (bench/pcf_pass_bench.cpp): the pass without lookup 0.74–0.84 → 0.69–0.72 ms,
  // one PCF lookup 2.08–2.38 → 2.04–2.08 ms, 16 Poisson taps unchanged (16.9–17.4 ms).
  [[gnu::always_inline]] static void write_packed_color(uint32_t* r0, uint32_t* r1, const QuadPairOut& out, unsigned live) {
    using simd::VecF32, simd::VecI32;
    VecI32 ch[4];
    for (int i = 0; i < 4; ++i)
      ch[i] = simd::round_to_int(simd::min(simd::max(out.color[i], VecF32::splat(0.0f)), VecF32::splat(1.0f)) *
                                 VecF32::splat(255.0f));
    VecI32 packed = ch[0] | simd::shift_left<8>(ch[1]) | simd::shift_left<16>(ch[2]) | simd::shift_left<24>(ch[3]);
    if (live != 0xFFu) packed = simd::select(simd::Mask::from_bits(live), simd::load_rows4(r0, r1), packed);
    simd::store_rows4(packed, r0, r1);
  }

  // ColorTarget::write of a float target, eight covered pixels at once: the first `channels` channels stored
  // unchanged, interleaved texel by texel.
  [[gnu::always_inline]] static void write_float_color(float* r0, float* r1, const QuadPairOut& out, int channels) {
    const auto& c = out.color;
    if (channels == 1) simd::store_rows4(c[0], r0, r1);
    else if (channels == 2) simd::store_rows4_interleaved(c[0], c[1], r0, r1);
    else simd::store_rows4_interleaved(c[0], c[1], c[2], c[3], r0, r1);
  }

  // Any other colour target or blend, and float targets' partly covered pairs: pixel by pixel through
  // write_color.
  void write_pair_color(int32_t x, int32_t y, const QuadPairOut& out, unsigned live) const {
    alignas(32) float ch[4][8];
    for (int i = 0; i < 4; ++i) out.color[i].store(ch[i]);
    for (int l = 0; l < 8; ++l)
      if (live >> l & 1u) write_color(x + (l & 3), y + (l >> 2), glm::vec4(ch[0][l], ch[1][l], ch[2][l], ch[3][l]));
  }

  void write_color(int32_t x, int32_t y, const glm::vec4& c) const {
    if (blend == BlendMode::multiply) {
      color->write(x, y, c * color->read(x, y));
    } else {
      color->write(x, y, c);
    }
  }
};

SHADOWLAB_ISA_END
}  // namespace raster
