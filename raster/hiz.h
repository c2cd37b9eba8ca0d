// Hierarchical depth for the depth-only back end: per tile, the farthest stored depth of each 8×8 block, so a
// block the triangle cannot pass (LESS / LEQUAL into d32f) is skipped whole before any per-pixel work. Skipped
// blocks are ones that would write nothing, so the output is unchanged. Tile-scoped, owned by one worker.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "raster/limits.h"
#include "raster/primitive.h"
#include "raster/simd/vec.h"
#include "raster/target.h"

namespace raster {

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

  float farthest(int32_t bx, int32_t by) const { return zmax_[(by - y0_) / kBlockSize][(bx - x0_) / kBlockSize]; }

  // Recomputes one block's bound after writes.
  void refresh(const DepthTarget& d, int32_t bx, int32_t by) {
    const int rows = std::min(kBlockSize, d.padded_height() - by);
    simd::VecF32 m = simd::VecF32::splat(0.0f);
    for (int r = 0; r < rows; ++r) m = simd::max(m, simd::VecF32::load(d.row<float>(by + r) + bx));
    alignas(32) float lanes[8];
    m.store(lanes);
    zmax_[(by - y0_) / kBlockSize][(bx - x0_) / kBlockSize] = *std::max_element(lanes, lanes + 8);
  }

 private:
  int32_t x0_ = 0, y0_ = 0;
  float zmax_[kBlocks][kBlocks];
};

// A lower bound of the triangle's clamped depth over the 8×8 block at (bx, by): the plane at the block's corner
// where it is smallest, less a margin for the rounding of the per-pixel evaluation (two fused multiply-adds and an
// add whose operands are bounded by `scale`, so each rounds by at most scale · 2^-24; 2^-21 covers them).
inline float block_min_depth(const TriangleSetup& t, int32_t bx, int32_t by) {
  const double x = t.dzdx > 0 ? bx : bx + kBlockSize - 1;
  const double y = t.dzdy > 0 ? by : by + kBlockSize - 1;
  const double z = double(t.z_a0) + double(t.dzdx) * x + double(t.dzdy) * y + double(t.z_offset);
  const double scale = std::abs(double(t.z_a0)) + std::abs(double(t.dzdx)) * (bx + kBlockSize) +
                       std::abs(double(t.dzdy)) * (by + kBlockSize) + std::abs(double(t.z_offset)) + 1.0;
  return float(std::clamp(z - scale * 0x1p-21, 0.0, 1.0));
}

}  // namespace raster
