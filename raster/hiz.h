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
  // Rows past the target's height are padding at the clear value or written by nobody: reading them only makes
  // the bound more conservative.
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

  float farthest(int32_t bx, int32_t by) const {
    return zmax_[(by - y0_) >> kBlockSizeLog2][(bx - x0_) >> kBlockSizeLog2];
  }

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
  float zmax_[kBlocks][kBlocks];
};

// A lower bound of the triangle's clamped depth over any 8×8 block at (bx, by) of a rectangle: the plane at the
// block's corner where it is smallest, less a margin for the rounding of the per-pixel evaluation (two fused
// multiply-adds and an add whose operands are bounded by `scale`, so each rounds by at most scale · 2^-24; 2^-21
// covers them). `scale` is taken at the rectangle's far corner, which bounds it for every block inside, so the
// per-block work is two multiply-adds; the double arithmetic's own rounding (2^-53 relative) is far inside the
// margin's slack.
struct HiZPlane {
  double z0 = 0.0, dx = 0.0, dy = 0.0;
  float min_depth(int32_t bx, int32_t by) const {
    return float(std::clamp(z0 + dx * double(bx) + dy * double(by), 0.0, 1.0));
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
  return p;
}

SHADOWLAB_ISA_END
}  // namespace raster
