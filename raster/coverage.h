// Coverage of one triangle over one 8×8 block: the hierarchical accept/reject test with exact int64 edge
// values at the block, then, only for edges that cross it, per-pixel int32 edge values eight lanes at a time
// (one row), or sixteen (two rows) for the depth-only stage where it works two rows at a time (depth_stage.h).
// Back end of the pipeline; the ranges that make int32 exact are derived in limits.h.
#pragma once
#include <algorithm>
#include <bit>
#include <cstdlib>
#include <cstdint>
#include <type_traits>

#include "raster/depth_setup.h"
#include "raster/limits.h"
#include "raster/primitive.h"
#include "raster/simd/vec.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// Lanes [lo, hi] of an 8-lane row.
inline unsigned lane_range_mask(int lo, int hi) { return ((2u << hi) - 1u) & ~((1u << lo) - 1u); }

// Edge k's F(x, y) = a·x + b·y − t at pixel (x, y), exact in int64 (limits.h); narrow_edge_lanes() gives the same
// for eight pixels (x[l], y[l]) at once, lane by lane and modulo 2^32, which is the value itself where it fits
// int32 (narrow triangles near their box, limits.h). DepthSetup has the same pair (depth_setup.h): the row stage
// below works on either record.
inline int64_t edge_value(const TriangleSetup& t, int k, int64_t x, int64_t y) {
  return t.a[k] * x + t.b[k] * y - t.t[k];
}
inline simd::VecI32 narrow_edge_lanes(const TriangleSetup& t, int k, simd::VecI32 x, simd::VecI32 y) {
  using simd::VecI32;
  return VecI32::splat(t.a[k]) * x + VecI32::splat(t.b[k]) * y - VecI32::splat(int32_t(t.t[k]));
}

// Per-row edge values of the (up to three) edges that cross a region, stepped one row at a time.
struct EdgeRows {
  simd::VecI32 f[3], step[3];

  // Edges with crosses[k] false contribute nothing (they are known to be non-negative everywhere).
  template <class Tri>
  EdgeRows(const Tri& t, const int64_t* f_start, const bool* crosses) {
    using simd::VecI32;
    for (int k = 0; k < 3; ++k) {
      const int32_t on = -int32_t(crosses[k]);  // all ones for a crossing edge: no branch
      f[k] = VecI32::splat(int32_t(f_start[k]) & on) + VecI32::splat(t.a[k] & on) * VecI32::iota();
      step[k] = VecI32::splat(t.b[k] & on);
    }
  }
  // A narrow triangle's edges, every one taken as crossing, from the lanes' pixels (x[l], y[l]) of the first row
  // (narrow_edge_lanes: straight from the record's fields, no scalar edge value first).
  template <class Tri>
  EdgeRows(const Tri& t, simd::VecI32 x, simd::VecI32 y) {
    for (int k = 0; k < 3; ++k) {
      f[k] = narrow_edge_lanes(t, k, x, y);
      step[k] = simd::VecI32::splat(t.b[k]);
    }
  }
  simd::Mask inside() const { return simd::non_negative(f[0] | f[1] | f[2]); }
  void next_rows() {
    f[0] = f[0] + step[0];
    f[1] = f[1] + step[1];
    f[2] = f[2] + step[2];
  }
};

// The same for two rows at a time, sixteen lanes: lanes 0–7 hold the upper row, 8–15 the row below, and each
// step moves down two rows. Values wrap modulo 2^32 like the eight-lane form's, and the rows a stage reads lie
// where limits.h bounds them (inside a crossed block; an edge that does not cross the block is all zeros).
struct EdgeRowPairs {
  simd::VecI32x16 f[3], step[3];

  // f_start: each edge's value at the first pixel of the upper row.
  template <class Tri>
  EdgeRowPairs(const Tri& t, const int64_t* f_start, const bool* crosses) {
    using simd::VecI32;
    using simd::VecI32x16;
    for (int k = 0; k < 3; ++k) {
      const int32_t on = -int32_t(crosses[k]);  // all ones for a crossing edge: no branch
      const int32_t fs = int32_t(f_start[k]) & on, a = t.a[k] & on, b = t.b[k] & on;
      const VecI32 upper = VecI32::splat(fs) + VecI32::splat(a) * VecI32::iota();
      f[k] = VecI32x16::rows(upper, upper + VecI32::splat(b));
      step[k] = VecI32x16::splat(int32_t(uint32_t(b) * 2u));
    }
  }
  simd::Mask16 inside() const { return simd::non_negative(f[0] | f[1] | f[2]); }
  void next_rows() {
    f[0] = f[0] + step[0];
    f[1] = f[1] + step[1];
    f[2] = f[2] + step[2];
  }
};

// The per-pixel edge values and lane masks of a row stage that works kRows rows at a time (Stage::kRows: 1 or 2,
// depth_stage.h) through a block, `lanes` being the block's columns in the rectangle.
template <int kRows>
struct RowGroup {
  using Edges = std::conditional_t<kRows == 1, EdgeRows, EdgeRowPairs>;
  using Mask = std::conditional_t<kRows == 1, simd::Mask, simd::Mask16>;
  const unsigned lanes;
  // The lanes of the group starting at row r (a multiple of kRows) for the rows set in `rows` (bit r: row r),
  // without a branch.
  Mask in_rows(int r, unsigned rows) const {
    const unsigned upper = lanes & (0u - (rows >> r & 1u));
    if constexpr (kRows == 1) return Mask::from_bits(upper);
    else return Mask::from_bits(upper | (lanes & (0u - (rows >> (r + 1) & 1u))) << 8);
  }
};

// Whether every edge coefficient is small enough for the narrow path's int32 edge values (limits.h).
inline bool is_narrow(const TriangleSetup& t) { return t.flags & kNarrowEdges; }

// The block walk shared by both stage kinds over the pixels [x0, x1] × [y0, y1] of one tile. Each edge's exact
// int64 value is stepped from block to block (g = F at the block's corner where F is largest, so the block lies
// outside the edge when g < 0 and the edge crosses it when g < its range over the block); visit(bx, by, row_lo,
// row_hi, block) is called for every block not outside an edge and not skipped, `block` saying which edges cross
// it and giving their exact values at its first row. skip(by) gives the blocks of a block row to leave out, bit i
// for the block at the tile's i-th block column. The rectangle must lie inside one tile (at most eight block
// columns: the bit masks below hold one). A block row's blocks are found as one bit mask first (the edge
// test for each block without a branch), then visited in order, one per set bit: where the test was a branch per
// block, its outcome changed along every row that crosses an edge and was mispredicted there (see
// rasterize_blocks for what that cost).
struct WalkedBlock {
  bool crosses[3];
  int64_t g[3], to_start[3];
  bool accepted() const { return !crosses[0] && !crosses[1] && !crosses[2]; }  // inside every edge
  // F of each edge at pixel (bx, by + row_lo), the block's first pixel on that row.
  template <class Tri>
  void row_start(const Tri& t, int row_lo, int64_t f[3]) const {
    for (int k = 0; k < 3; ++k) f[k] = g[k] + to_start[k] + t.b[k] * int64_t(row_lo);
  }
};

// The block column of the tile that holds pixel column x.
inline unsigned tile_block_column(int32_t x) { return unsigned(x >> kBlockSizeLog2) & (kTileSize / kBlockSize - 1); }

template <class Tri, class Skip, class Visit>
inline void walk_blocks(const Tri& t, int32_t x0, int32_t y0, int32_t x1, int32_t y1, Skip&& skip, Visit&& visit) {
  constexpr int64_t kSpan = kBlockSize - 1;
  const int32_t bx0 = x0 & ~(kBlockSize - 1), by0 = y0 & ~(kBlockSize - 1);
  // The rectangle's block columns, as skip() numbers them.
  const unsigned first_column = tile_block_column(bx0);
  const unsigned columns = lane_range_mask(int(first_column), int(tile_block_column(x1)));
  const int nblocks = ((x1 - bx0) >> kBlockSizeLog2) + 1;
  int64_t g_row[3], range[3], step_x[3], step_y[3];
  WalkedBlock w;
  for (int k = 0; k < 3; ++k) {
    const int64_t a = t.a[k], b = t.b[k];
    const int64_t hi = (std::max<int64_t>(a, 0) + std::max<int64_t>(b, 0)) * kSpan;
    g_row[k] = edge_value(t, k, bx0, by0) + hi;
    range[k] = (std::abs(a) + std::abs(b)) * kSpan;
    w.to_start[k] = -hi;  // g + to_start: F at the block's first pixel
    step_x[k] = a * kBlockSize;
    step_y[k] = b * kBlockSize;
  }
  for (int32_t by = by0; by <= y1; by += kBlockSize, g_row[0] += step_y[0], g_row[1] += step_y[1], g_row[2] += step_y[2]) {
    const unsigned skipped = skip(by) & columns;
    if (skipped == columns) continue;
    const int row_lo = std::max(y0 - by, 0), row_hi = std::min(y1 - by, kBlockSize - 1);
    // The row's blocks not outside an edge, bit j for the j-th from bx0, found without a branch per block.
    unsigned live = 0;
    {
      int64_t g0 = g_row[0], g1 = g_row[1], g2 = g_row[2];
      for (int j = 0; j < nblocks; ++j, g0 += step_x[0], g1 += step_x[1], g2 += step_x[2])
        live |= unsigned((g0 | g1 | g2) >= 0) << j;
    }
    live &= ~(skipped >> first_column);
    for (; live != 0; live &= live - 1) {
      const int j = std::countr_zero(live);
      const int32_t bx = bx0 + j * kBlockSize;
      const int64_t g0 = g_row[0] + step_x[0] * j, g1 = g_row[1] + step_x[1] * j, g2 = g_row[2] + step_x[2] * j;
      w.g[0] = g0, w.g[1] = g1, w.g[2] = g2;
      w.crosses[0] = g0 < range[0], w.crosses[1] = g1 < range[1], w.crosses[2] = g2 < range[2];
      visit(bx, by, row_lo, row_hi, static_cast<const WalkedBlock&>(w));
    }
  }
}

// A row stage's blocks: those hidden by hierarchical depth are skipped; each other block is handed over whole,
// all its rows kRows at a time, with the lanes inside its crossing edges (an edge that does not cross the block
// contributes zeros) and in [row_lo, row_hi]. A group with no lane is handed over all the same (the stage writes
// back what it read), so no step of the loop branches on coverage, and since every row went through the stage
// the block's new bound needs no row read back. With a branch on an accepted block, on an empty group and on the
// rows left for the bound, those mispredicted often enough to cost more than the work they saved: measured on the
// 2-core AMD EPYC (Zen 5), AVX-512 path, 2 threads, without llvmpipe (2026-11-29, three runs each, alternating),
// the draw of 2·10^4 triangles of ~2,000 px took 10.5–10.6 ms before and 8.8–8.9 ms after (back end busy 19.0–19.3
// → 15.6–15.9 ms), together with the block mask of walk_blocks and the narrow path's change below.
template <class Tri, class Stage>
inline void rasterize_blocks(const Tri& t, int32_t x0, int32_t y0, int32_t x1, int32_t y1, const Stage& stage) {
  constexpr int kRows = Stage::kRows;
  const auto hiz = stage.hiz_plane(t, PixelRect{x0, y0, x1, y1});
  auto hidden = [&](int32_t by) { return stage.hidden_blocks(hiz, by); };
  walk_blocks(t, x0, y0, x1, y1, hidden, [&](int32_t bx, int32_t by, int row_lo, int row_hi, const WalkedBlock& blk) {
    const RowGroup<kRows> group{lane_range_mask(std::max(x0 - bx, 0), std::min(x1 - bx, kBlockSize - 1))};
    const unsigned rows_in = lane_range_mask(row_lo, row_hi);
    const auto cols = stage.columns(t, bx);
    typename Stage::BlockMax bm;
    auto at = stage.cursor(bx, by);
    int64_t f_start[3];
    blk.row_start(t, 0, f_start);
    typename RowGroup<kRows>::Edges edges(t, f_start, blk.crosses);
    for (int r = 0; r < kBlockSize; r += kRows) {
      stage.rows(cols, at, group.in_rows(r, rows_in) & edges.inside(), bm);
      edges.next_rows();
      stage.next_rows(at);
    }
    stage.block_done(bx, by, bm, 0xFFu);
  });
}

// Bits [8·row_lo, 8·row_hi + 7] of a block mask, each row holding `lanes`.
inline uint64_t block_rows_mask(unsigned lanes, int row_lo, int row_hi) {
  const uint64_t rows = (~uint64_t(0) >> (8 * (kBlockSize - 1 - row_hi))) & (~uint64_t(0) << (8 * row_lo));
  return (uint64_t(lanes) * 0x0101010101010101ull) & rows;
}

// A block stage's blocks (shaded draws): one 64-bit coverage mask per block (bit 8·r + l for pixel
// (bx + l, by + r)); blocks inside every edge get their mask without per-pixel edge tests.
template <class Stage>
inline void rasterize_block_masks(const TriangleSetup& t, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                                  const Stage& stage) {
  auto none = [](int32_t) { return 0u; };
  walk_blocks(t, x0, y0, x1, y1, none, [&](int32_t bx, int32_t by, int row_lo, int row_hi, const WalkedBlock& blk) {
    const unsigned lanes = lane_range_mask(std::max(x0 - bx, 0), std::min(x1 - bx, kBlockSize - 1));
    if (blk.accepted()) {
      stage.block(t, bx, by, block_rows_mask(lanes, row_lo, row_hi));
      return;
    }
    int64_t f_start[3];
    blk.row_start(t, row_lo, f_start);
    EdgeRows edges(t, f_start, blk.crosses);
    uint64_t mask = 0;
    for (int r = row_lo; r <= row_hi; ++r) {
      mask |= uint64_t(edges.inside().bits() & lanes) << (8 * r);
      edges.next_rows();
    }
    if (mask) stage.block(t, bx, by, mask);
  });
}

// A narrow triangle (at most 8 pixels wide within [x0, x1]) through a row stage working one row at a time: one
// segment column of 8 pixels, placed inside the tile. Every row is handed over, covered or not, as in
// rasterize_blocks. Measured on the 2-core AMD EPYC (Zen 5), 2 threads, without llvmpipe (2026-11-29, three runs
// each, alternating), with the block walk's changes above: the back end of the dragon's 871k triangles (2048²)
// took 20.1–21.1 → 11.8–11.9 ms on the AVX2 path, and of 10^6 triangles of ~10 px 16.6–19.5 → 11.8–12.3 ms. On the
// AVX-512 path, where row stages take two rows a step, narrow triangles take one (DepthOnlyStage::one_row): with
// two, those back ends took 14.4–15.2 and 15.3–17.3 ms, with one 12.5–12.7 and 13.2–13.4 ms. Tried and dropped: a
// fixed count of rows per segment (no branch on the box's height either), measured on the AVX-512 path while
// narrow triangles still took two rows a step: the dragon's back end 15.5 → 18.3 ms.
//
// Only short ones, at most kNarrowMaxRows rows within the tile, take this path: a taller one (in practice a large
// triangle's sliver at a tile's left or right edge) goes through rasterize_blocks, whose hierarchical depth skips
// hidden blocks and whose AVX-512 form takes two rows a step. Measured on a 2-core AMD EPYC of the Zen 4
// generation (family 25), 2 threads, without llvmpipe (2026-11-30, two rounds, alternating, same maps): the back
// end of 2·10^4 triangles of ~2,000 px 8.08–8.14 → 7.46–7.48 ms on the AVX-512 path and 8.95 → 8.46–8.52 ms on
// the AVX2 path; the dragon's and the 10^6 small triangles' unchanged within the noise. With 8 rows the dragon's
// back end lost 20 % (10.3 → 12.3 ms); 24 and 32 measured like 16 on the large triangles.
inline constexpr int kNarrowMaxRows = 16;
template <class Tri, class Stage>
inline void rasterize_narrow(const Tri& t, int32_t x0, int32_t y0, int32_t x1, int32_t y1, const Stage& stage) {
  static_assert(Stage::kRows == 1, "narrow triangles take one row a step (the stage's one_row())");
  const int32_t xs = std::min(x0, (x0 | (kTileSize - 1)) - (kBlockSize - 1));  // segment stays in the tile
  const simd::Mask lanes = simd::Mask::from_bits(lane_range_mask(x0 - xs, x1 - xs));
  // The edge values are exact modulo 2^32, and they fit int32 there (limits.h, kNarrowCoefBits).
  EdgeRows edges(t, simd::VecI32::splat(xs) + simd::VecI32::iota(), simd::VecI32::splat(y0));
  const auto cols = stage.columns(t, xs);
  auto at = stage.cursor(xs, y0);
  for (int32_t y = y0; y <= y1; ++y) {
    stage.row(cols, at, lanes & edges.inside());
    edges.next_rows();
    stage.next_rows(at);
  }
}

// Rasterizes one triangle within `r` (a rectangle inside one tile) and hands covered pixels to the stage.
// A row stage (depth-only) has kRows, columns(t, x), cursor(x, y) / next_rows(cursor), rows(columns, cursor,
// mask, BlockMax&) and, for the narrow path, row(columns, cursor, mask) (no bound kept), hiz_plane / hidden_blocks
// / block_done around each block (hierarchical depth), and one_row() (the same stage with kRows 1), and gets
// one segment of 8 pixels by kRows rows at a time; narrow triangles (at most 8 pixels wide and kNarrowMaxRows
// high within `r`) take one segment column placed inside the tile, one row at a time, others go through 8×8
// blocks. A block stage (shaded) has block(t, bx, by, uint64_t mask) and gets
// whole blocks. A row stage takes either record (TriangleSetup or DepthSetup), a block stage a TriangleSetup.
template <class Tri, class Stage>
inline void rasterize(const Tri& t, const PixelRect& r, const Stage& stage) {
  constexpr bool kRowStage = requires { stage.columns(t, 0); };
  const int32_t x0 = std::max<int32_t>(t.min_x, r.x0), x1 = std::min<int32_t>(t.max_x, r.x1);
  const int32_t y0 = std::max<int32_t>(t.min_y, r.y0), y1 = std::min<int32_t>(t.max_y, r.y1);
  if (x0 > x1 || y0 > y1) return;
  if constexpr (kRowStage) {
    if (x1 - x0 < kBlockSize && y1 - y0 < kNarrowMaxRows && is_narrow(t)) {
      rasterize_narrow(t, x0, y0, x1, y1, stage.one_row());
      return;
    }
    rasterize_blocks(t, x0, y0, x1, y1, stage);
  } else {
    rasterize_block_masks(t, x0, y0, x1, y1, stage);
  }
}

SHADOWLAB_ISA_END
}  // namespace raster
