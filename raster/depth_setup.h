// The one-cache-line record of depth-only draws (primitive.h, DepthSetup): packing a TriangleSetup with narrow
// edges into it after setup, and expanding it back, exactly, before tile execution. Expanding recovers the
// integer edge constants from the stored values at the box's first pixel (limits.h), so coverage and depth are
// computed from the very same record a shaded draw would use.
#pragma once
#include <cstdint>

#include "raster/primitive.h"
#include "raster/simd/vec.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// Whether setup's record fits a DepthSetup (its edges are narrow).
inline bool fits_depth_setup(const TriangleSetup& t) { return (t.flags & kNarrowEdges) != 0; }

// The compact record of a triangle with fits_depth_setup(t).
inline DepthSetup pack_depth_setup(const TriangleSetup& t) {
  DepthSetup d;
  for (int k = 0; k < 3; ++k) {
    d.a[k] = t.a[k];
    d.b[k] = t.b[k];
    d.f0[k] = int32_t(int64_t(t.a[k]) * t.min_x + int64_t(t.b[k]) * t.min_y - t.t[k]);  // fits: limits.h
  }
  d.min_x = int16_t(t.min_x), d.min_y = int16_t(t.min_y);
  d.max_x = int16_t(t.max_x), d.max_y = int16_t(t.max_y);
  d.z_a0 = t.z_a0, d.dzdx = t.dzdx, d.dzdy = t.dzdy, d.z_offset = t.z_offset;
  d.full = kNoFullSetup;
  return d;
}

// The edge values of coverage.h (edge_value, narrow_edge_lanes) and its narrow test, on the compact record:
// F(x, y) = f0 + a·(x − min_x) + b·(y − min_y), which is a·x + b·y − t exactly (int64), or modulo 2^32.
inline bool is_narrow(const DepthSetup&) { return true; }
inline int64_t edge_value(const DepthSetup& d, int k, int64_t x, int64_t y) {
  return d.f0[k] + d.a[k] * (x - d.min_x) + d.b[k] * (y - d.min_y);
}
inline simd::VecI32 narrow_edge_lanes(const DepthSetup& d, int k, simd::VecI32 x, simd::VecI32 y) {
  using simd::VecI32;
  return VecI32::splat(d.f0[k]) + VecI32::splat(d.a[k]) * (x - VecI32::splat(d.min_x)) +
         VecI32::splat(d.b[k]) * (y - VecI32::splat(d.min_y));
}

// The full record of a packed triangle: every field as setup made it, except the back-facing bit (prim is 0).
[[gnu::always_inline]] inline TriangleSetup expand_depth_setup(const DepthSetup& d) {
  TriangleSetup t;
  for (int k = 0; k < 3; ++k) {
    t.a[k] = d.a[k];
    t.b[k] = d.b[k];
    t.t[k] = int64_t(d.a[k]) * d.min_x + int64_t(d.b[k]) * d.min_y - d.f0[k];
  }
  t.min_x = d.min_x, t.min_y = d.min_y, t.max_x = d.max_x, t.max_y = d.max_y;
  t.z_a0 = d.z_a0, t.dzdx = d.dzdx, t.dzdy = d.dzdy, t.z_offset = d.z_offset;
  t.prim = 0;
  t.flags = kNarrowEdges;
  return t;
}

SHADOWLAB_ISA_END
}  // namespace raster
