// The lean back end of a depth-only draw: for each covered 8-pixel row of a block, the interpolated depth,
// clamp, conversion to the format, depth test and masked write. No varyings, no colour, no quads.
#pragma once
#include <cstdint>

#include "raster/depth_test.h"
#include "raster/hiz.h"
#include "raster/primitive.h"
#include "raster/simd/vec.h"
#include "raster/target.h"

namespace raster {

// Depth of the eight pixels (bx + l, y) on the triangle's plane, clamped to [0, 1]. Shared by every back end so
// that a triangle gets the same depth whichever path draws it. llvmpipe's operation order (setup.cpp): with x and
// y the absolute pixel indices as floats, z = fma(dzdy, y, fma(dzdx, x, z_a0)) + z_offset, then the clamp. The
// column part (first fused multiply-add) is computed once per segment, the rest per row.
inline simd::VecF32 plane_depth_columns(const TriangleSetup& t, int32_t bx) {
  using simd::VecF32;
  const VecF32 x = VecF32::splat(float(bx)) + VecF32::iota();  // exact: pixel indices are below 2^24
  return simd::fma(VecF32::splat(t.dzdx), x, VecF32::splat(t.z_a0));
}

inline simd::VecF32 plane_depth_clamped(simd::VecF32 zcol, simd::VecF32 dzdy, simd::VecF32 z_offset, int32_t y) {
  using simd::VecF32;
  const VecF32 z = simd::fma(dzdy, VecF32::splat(float(y)), zcol) + z_offset;
  return simd::min(simd::max(z, VecF32::splat(0.0f)), VecF32::splat(1.0f));
}

template <DepthFormat Format, DepthFunc Func, bool Write>
struct DepthOnlyStage {
  using Traits = DepthTraits<Format>;
  // Hierarchical depth applies to LESS and LEQUAL into d32f: a block whose farthest stored depth is nearer
  // than everything the triangle has there cannot pass.
  static constexpr bool kHiZ =
      Format == DepthFormat::d32f && (Func == DepthFunc::less || Func == DepthFunc::lequal);
  DepthTarget* depth;
  TileHiZ* hiz = nullptr;  // the tile's bounds, when kHiZ

  bool block_hidden(const TriangleSetup& t, int32_t bx, int32_t by) const {
    if constexpr (kHiZ) {
      const float zmin = block_min_depth(t, bx, by), zmax = hiz->farthest(bx, by);
      return Func == DepthFunc::less ? zmin >= zmax : zmin > zmax;
    }
    return false;
  }

  void block_done(int32_t bx, int32_t by) const {
    if constexpr (kHiZ && Write) hiz->refresh(*depth, bx, by);
  }

  // The column part of the depth plane for the segment starting at x, computed once per segment.
  simd::VecF32 columns(const TriangleSetup& t, int32_t x) const { return plane_depth_columns(t, x); }

  // Eight pixels (x + l, y) for the lanes set in `covered`.
  [[gnu::always_inline]] void row(const TriangleSetup& t, simd::VecF32 zcol, int32_t x, int32_t y,
                                  simd::Mask covered) const {
    auto* p = depth->row<typename Traits::Storage>(y) + x;
    const auto frag = Traits::from_depth(
        plane_depth_clamped(zcol, simd::VecF32::splat(t.dzdy), simd::VecF32::splat(t.z_offset), y));
    const auto stored = Traits::load(p);
    const simd::Mask pass = depth_compare<Func>(frag, stored) & covered;
    if constexpr (Write) Traits::store(p, simd::select(pass, stored, frag));
  }
};

}  // namespace raster
