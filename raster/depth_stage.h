// The lean back end of a depth-only draw: for each 8-pixel row of a visited block or a narrow triangle's segment
// (or pair of rows, sixteen lanes, where the CPU has 512-bit vectors: kDepthRows), covered or not, the
// interpolated depth, clamp, conversion to the format, depth test and masked write. No varyings, no colour, no
// quads.
#pragma once
#include <cstdint>
#include <type_traits>

#include "raster/depth_test.h"
#include "raster/hiz.h"
#include "raster/primitive.h"
#include "raster/simd/vec.h"
#include "raster/target.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// Depth of the eight pixels (bx + l, y) on the triangle's plane, clamped to [0, 1]. Shared by every back end so
// that a triangle gets the same depth whichever path draws it. llvmpipe's operation order (setup.cpp): with x and
// y the absolute pixel indices as floats, z = fma(dzdy, y, fma(dzdx, x, z_a0)) + z_offset, then the clamp. The
// column part (first fused multiply-add) is computed once per segment, the rest per row.
template <class Tri>  // TriangleSetup or DepthSetup
inline simd::VecF32 plane_depth_columns(const Tri& t, int32_t bx) {
  using simd::VecF32;
  const VecF32 x = VecF32::splat(float(bx)) + VecF32::iota();  // exact: pixel indices are below 2^24
  return simd::fma(VecF32::splat(t.dzdx), x, VecF32::splat(t.z_a0));
}

template <class Vec>  // VecF32 or VecF32x16: the same operations lane by lane
inline Vec plane_depth_clamped(Vec zcol, Vec dzdy, Vec z_offset, Vec y) {
  const Vec z = simd::fma(dzdy, y, zcol) + z_offset;
  return simd::min(simd::max(z, Vec::splat(0.0f)), Vec::splat(1.0f));
}
inline simd::VecF32 plane_depth_clamped(simd::VecF32 zcol, simd::VecF32 dzdy, simd::VecF32 z_offset, int32_t y) {
  return plane_depth_clamped(zcol, dzdy, z_offset, simd::VecF32::splat(float(y)));
}

// Whether a depth-only stage's test is one hierarchical depth can skip blocks for: LESS or LEQUAL fixed at
// compile time (a run-time DepthCompare never is).
template <class Compare>
inline constexpr bool kHiZCompare = false;
template <>
inline constexpr bool kHiZCompare<FixedDepthFunc<DepthFunc::less>> = true;
template <>
inline constexpr bool kHiZCompare<FixedDepthFunc<DepthFunc::lequal>> = true;

// How many rows the depth-only stage works on at a time: two (sixteen lanes, one zmm register) with AVX-512;
// one elsewhere, where the same sixteen lanes as two halves were measured slower (27 % more instructions per
// draw of small triangles with AVX2: the doubled row state no longer fits the sixteen ymm registers). Both forms
// give the same bits: tests/raster/depth_stage_test.cpp compares them on every machine (with the two-halves
// sixteen lanes there, and with the zmm ones where the tests are built for AVX-512). Narrow triangles take one
// row a step in every build (one_row below, rasterize_narrow in coverage.h).
#if defined(SHADOWLAB_SIMD_AVX512)
inline constexpr int kDepthRows = 2;
#else
inline constexpr int kDepthRows = 1;
#endif

// Compare: FixedDepthFunc<LESS or LEQUAL> or DepthCompare (see dispatch_depth_only_func, depth_test.h). Rows: 1
// (eight lanes, one row at a time) or 2 (sixteen lanes: the upper row in lanes 0–7, the row below in 8–15).
template <DepthFormat Format, class Compare, bool Write, int Rows = kDepthRows>
struct DepthOnlyStage {
  static_assert(Rows == 1 || Rows == 2);
  static constexpr int kRows = Rows;
  using Traits = DepthTraits<Format>;
  using Storage = typename Traits::Storage;
  using Vec = std::conditional_t<Rows == 1, simd::VecF32, simd::VecF32x16>;
  using Mask = std::conditional_t<Rows == 1, simd::Mask, simd::Mask16>;
  // Hierarchical depth applies to LESS and LEQUAL into d32f: a block whose farthest stored depth is nearer
  // than everything the triangle has there cannot pass.
  static constexpr bool kHiZ = Format == DepthFormat::d32f && kHiZCompare<Compare>;

  DepthOnlyStage(DepthTarget* d, TileHiZ* h, Compare c)
      : depth(d), hiz(h), base(d->row<Storage>(0)), pitch(size_t(d->pitch())), compare(c) {}
  DepthOnlyStage(DepthTarget* d, TileHiZ* h, Storage* b, size_t p, Compare c)
      : depth(d), hiz(h), base(b), pitch(p), compare(c) {}

  // The same stage one row at a time, for narrow triangles (rasterize, coverage.h): most are a few pixels
  // high, and eight lanes a step waste less on them than sixteen (kDepthRows).
  DepthOnlyStage<Format, Compare, Write, 1> one_row() const { return {depth, hiz, base, pitch, compare}; }

  DepthTarget* depth;
  TileHiZ* hiz = nullptr;  // the tile's bounds, when kHiZ
  Storage* base;           // the target's row 0, and the elements between two rows: no reload per row
  size_t pitch;
  [[no_unique_address]] Compare compare;

  // The triangle's per-segment constants: the column part of the depth plane (see plane_depth_columns) in every
  // row's lanes, and the row slope and polygon offset, splatted once.
  struct Columns {
    Vec zcol, dzdy, z_offset;
  };
  // The farthest depth written to the rows of the current block, for the hierarchical bound (kHiZ only).
  struct BlockMax {
    Vec z = Vec::splat(0.0f);
  };

  // The per-triangle part of the hierarchical test (see hiz.h), for blocks inside `r`.
  template <class Tri>
  HiZPlane hiz_plane(const Tri& t, const PixelRect& r) const {
    if constexpr (kHiZ) return make_hiz_plane(t, r);
    return {};
  }
  // The blocks of the tile's block row at `by` the triangle cannot pass (TileHiZ::hidden), bit i for the
  // block at the tile's x0 + 8·i.
  unsigned hidden_blocks(const HiZPlane& hp, int32_t by) const {
    if constexpr (kHiZ) {
      constexpr bool kStrict = std::is_same_v<Compare, FixedDepthFunc<DepthFunc::less>>;
      return hiz->template hidden<kStrict>(hp.row(hiz->x0(), by), by);
    }
    return 0;
  }

  // After the rows in `rows_done` (bit r: row by + r) of a block were handed to rows() with `bm`: the block's
  // new bound, from what was written and the rows left untouched.
  void block_done(int32_t bx, int32_t by, const BlockMax& bm, unsigned rows_done) const {
    if constexpr (kHiZ && Write) {
      if constexpr (Rows == 1) hiz->update(*depth, bx, by, bm.z, rows_done);
      else hiz->update(*depth, bx, by, simd::max(bm.z.row0(), bm.z.row1()), rows_done);
    }
  }

  // The column part of the depth plane for the segment starting at x, computed once per segment.
  template <class Tri>
  Columns columns(const Tri& t, int32_t x) const {
    const simd::VecF32 zcol = plane_depth_columns(t, x);
    if constexpr (Rows == 1) return {zcol, Vec::splat(t.dzdy), Vec::splat(t.z_offset)};
    else return {Vec::rows(zcol, zcol), Vec::splat(t.dzdy), Vec::splat(t.z_offset)};
  }

  // Where a segment's rows are: the first pixel in the target and each row's y as a float in its lanes (exact:
  // pixel indices are below 2^24), stepped Rows rows at a time.
  struct Cursor {
    Storage* p;
    Vec y;
  };
  Cursor cursor(int32_t x, int32_t y) const {
    Storage* p = base + size_t(y) * pitch + x;
    if constexpr (Rows == 1) return {p, Vec::splat(float(y))};
    else return {p, Vec::rows(simd::VecF32::splat(float(y)), simd::VecF32::splat(float(y + 1)))};
  }
  void next_rows(Cursor& c) const {
    c.p += Rows * pitch;
    c.y = c.y + Vec::splat(float(Rows));
  }

  // The pixels at the cursor (eight of its row, and eight of the next when Rows is 2) for the lanes set in
  // `covered`, which may be none. Every row is read and written back whole, so every row must lie in the worker's
  // tile.
  [[gnu::always_inline]] void rows(const Columns& c, const Cursor& at, Mask covered, BlockMax& bm) const {
    Storage* p = at.p;
    const auto frag = Traits::from_depth(plane_depth_clamped(c.zcol, c.dzdy, c.z_offset, at.y));
    const auto stored = load(p);
    const Mask pass = compare(frag, stored) & covered;
    if constexpr (Write) {
      const auto next = simd::select(pass, stored, frag);
      store(p, next);
      if constexpr (kHiZ) bm.z = simd::max(bm.z, next);
    }
  }

  // One row at the cursor for the lanes set in `covered`, keeping no block bound: the narrow path's rows
  // (rasterize_narrow, coverage.h), which leave the hierarchical bounds as they were (still at or above what the
  // blocks hold, as LESS and LEQUAL only bring depths nearer). On d32f only the passing lanes are written
  // (simd::store_select: a masked store with AVX-512); the other formats go through rows().
  [[gnu::always_inline]] void row(const Columns& c, const Cursor& at, Mask covered) const {
    static_assert(Rows == 1, "the narrow path takes one row a step (one_row())");
    if constexpr (Format == DepthFormat::d32f && Write) {
      const simd::VecF32 frag = Traits::from_depth(plane_depth_clamped(c.zcol, c.dzdy, c.z_offset, at.y));
      const simd::VecF32 stored = Traits::load(at.p);
      simd::store_select(compare(frag, stored) & covered, stored, frag, at.p);
    } else {
      BlockMax unused;
      rows(c, at, covered, unused);
    }
  }

 private:
  auto load(const Storage* p) const {
    if constexpr (Rows == 1) return Traits::load(p);
    else return Traits::load_rows(p, p + pitch);
  }
  template <class Value>
  void store(Storage* p, Value v) const {
    if constexpr (Rows == 1) Traits::store(p, v);
    else Traits::store_rows(p, p + pitch, v);
  }
};

SHADOWLAB_ISA_END
}  // namespace raster
