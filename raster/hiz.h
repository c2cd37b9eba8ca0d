// Hierarchical depth for the depth-only back end: per tile, the farthest stored depth of each 8×8 block, so a
// block the triangle cannot pass (LESS / LEQUAL into d32f) is skipped whole before any per-pixel work. Skipped
// blocks are ones that would write nothing, so the output is unchanged. Tile-scoped, owned by one worker.
#pragma once
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "raster/limits.h"
#include "raster/primitive.h"
#include "raster/simd/vec.h"
#include "raster/target.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

class TileHiZ {
 public:
  static constexpr int kBlocks = kTileSize / kBlockSize;  // per side

  // Reads the farthest depth of every block of the tile at (x0, y0) (pixels, tile-aligned) from a d32f target.
  // Rows past the target's height are padding at the clear value or changed by nobody (the depth-only stage
  // writes back what it read there): reading them only makes the bound more conservative.
  void load(const DepthTarget& d, int32_t x0, int32_t y0) {
    x0_ = x0, y0_ = y0;
    for (int j = 0; j < kBlocks; ++j)
      for (int i = 0; i < kBlocks; ++i) refresh(d, x0 + i * kBlockSize, y0 + j * kBlockSize);
  }

  // The bounds of a tile just cleared to `z`, without reading it back.
  void set_all(int32_t x0, int32_t y0, float z) {
    x0_ = x0, y0_ = y0;
    for (auto& row : zmax_)
      for (float& v : row) v = z;
  }

  // The blocks of the block row at `by` that a triangle with lower bounds `lower` (HiZPlane::row at the tile's
  // x0) cannot pass, bit i for the block at x0 + 8·i: with LESS (kStrict) where the bound is not nearer than the
  // block's farthest depth, with LEQUAL where it is farther. A NaN on either side hides nothing.
  template <bool kStrict>
  unsigned hidden(simd::VecF32 lower, int32_t by) const {
    static_assert(kBlocks == simd::kLanes);
    const simd::VecF32 far = simd::VecF32::load(zmax_[(by - y0_) >> kBlockSizeLog2]);
    return (kStrict ? simd::cmp_le(far, lower) : simd::cmp_lt(far, lower)).bits();
  }
  int32_t x0() const { return x0_; }

  // Recomputes one block's bound after writes.
  void refresh(const DepthTarget& d, int32_t bx, int32_t by) { update(d, bx, by, simd::VecF32::splat(0.0f), 0u); }

  // The block's bound after writes, from `written` (the lane-wise maximum of what rows in `rows_done`, bit r for
  // row by + r, now hold) and the rows not in `rows_done`, read back. Tiles lie inside the padded target, so
  // all eight rows exist.
  void update(const DepthTarget& d, int32_t bx, int32_t by, simd::VecF32 written, unsigned rows_done) {
    simd::VecF32 m = written;
    for (unsigned rest = ~rows_done & 0xFFu; rest != 0; rest &= rest - 1)
      m = simd::max(m, simd::VecF32::load(d.row<float>(by + std::countr_zero(rest)) + bx));
    zmax_[(by - y0_) >> kBlockSizeLog2][(bx - x0_) >> kBlockSizeLog2] = simd::reduce_max(m);
  }

 private:
  int32_t x0_ = 0, y0_ = 0;
  alignas(32) float zmax_[kBlocks][kBlocks];
};

// A lower bound of the triangle's clamped depth over every 8×8 block of one block row of a rectangle, eight
// blocks at a time: the plane at each block's corner where it is smallest, less a margin for rounding. The
// margin covers two things, each bounded through `scale`, which bounds |z| and every partial sum at any pixel
// of a block inside the rectangle (taken at its far corner): the per-pixel evaluation of the stage (two fused
// multiply-adds and an add, each rounding by at most scale · 2^-24, so 3 · 2^-24 in all), and this bound's own
// float evaluation (the row's start rounded from double to float and one fused multiply-add per lane: 2 · 2^-24;
// the double arithmetic before it rounds by 2^-53 relative). 2^-21 = 8 · 2^-24 covers both with room. Lanes for
// block columns outside the rectangle hold values nobody reads.
struct HiZPlane {
  double z0 = 0.0, dx = 0.0, dy = 0.0;  // the bound at block (0, 0) and its slopes per pixel
  float dx_block = 0.0f;                // the bound's step from one block column to the next (exact: 8 · a float)

  // The lower bounds of the blocks (x0 + 8·l, by), lane l.
  simd::VecF32 row(int32_t x0, int32_t by) const {
    const float start = float(z0 + dx * double(x0) + dy * double(by));
    const simd::VecF32 z = simd::fma(simd::VecF32::splat(dx_block), simd::VecF32::iota(), simd::VecF32::splat(start));
    return simd::min(simd::max(z, simd::VecF32::splat(0.0f)), simd::VecF32::splat(1.0f));
  }
};

template <class Tri>  // TriangleSetup or DepthSetup
inline HiZPlane make_hiz_plane(const Tri& t, const PixelRect& r) {
  const double cx = t.dzdx > 0 ? 0.0 : double(kBlockSize - 1);
  const double cy = t.dzdy > 0 ? 0.0 : double(kBlockSize - 1);
  const double scale = std::abs(double(t.z_a0)) + std::abs(double(t.dzdx)) * (double(r.x1) + kBlockSize) +
                       std::abs(double(t.dzdy)) * (double(r.y1) + kBlockSize) + std::abs(double(t.z_offset)) + 1.0;
  HiZPlane p;
  p.dx = double(t.dzdx);
  p.dy = double(t.dzdy);
  p.z0 = double(t.z_a0) + double(t.z_offset) + p.dx * cx + p.dy * cy - scale * 0x1p-21;
  p.dx_block = t.dzdx * float(kBlockSize);
  return p;
}

SHADOWLAB_ISA_END
}  // namespace raster
