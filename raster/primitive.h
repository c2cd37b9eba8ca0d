// Plain records that cross stage boundaries: the window-space vertex produced by the viewport transform, the
// draw's window-space limits, and the triangle setup records that setup hands through the bins to tile
// execution (the full one, and the one-cache-line one of depth-only draws).
#pragma once
#include <cstdint>
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// A vertex after the perspective divide and viewport transform (CONVENTIONS: float maths, FMA), and its
// position snapped to 1/256 pixel.
struct WindowVertex {
  float x, y, z;   // window coordinates, z in [0, 1] before polygon offset
  float inv_w;     // 1 / w_clip
  int32_t sx, sy;  // snapped: round_half_even(x · 256), round_half_even(y · 256)
};

// The rectangle a draw may touch (viewport ∩ scissor ∩ target), inclusive pixel bounds.
struct PixelRect {
  int32_t x0, y0, x1, y1;
  bool empty() const { return x0 > x1 || y0 > y1; }
};

// One triangle ready for tile execution: three edges as exact integer functions of the pixel index
// (pixel (i, j) is inside edge k iff a[k]·i + b[k]·j >= t[k]; see limits.h for the derivation), its pixel
// bounding box clamped to the draw's rectangle, and its window-space depth plane. Shaded draws store one per
// visible triangle; depth-only draws store a DepthSetup and keep this one only for triangles too wide for it.
struct alignas(16) TriangleSetup {
  int64_t t[3];
  int32_t a[3], b[3];
  int32_t min_x, min_y, max_x, max_y;
  // Depth plane as llvmpipe evaluates it (setup.cpp): z(x, y) = fma(dzdy, y, fma(dzdx, x, z_a0)) + z_offset at
  // pixel (x, y), with x and y the pixel indices as floats, then clamped to [0, 1].
  float z_a0;        // the plane at the centre of pixel (0, 0), without polygon offset
  float dzdx, dzdy;  // window-space depth slopes
  float z_offset;    // polygon offset (0 when the draw has none)
  uint32_t prim;     // shaded draws: index of the triangle's interpolation record; bit 31: back-facing
  uint32_t flags;    // kNarrowEdges when every |a[k]|, |b[k]| < 2^kNarrowCoefBits (limits.h)
};
static_assert(sizeof(TriangleSetup) == 96);

inline constexpr uint32_t kBackFacingBit = 0x80000000u;
inline constexpr uint32_t kNarrowEdges = 1u;

// One triangle of a depth-only draw in one cache line: the same edges, box and depth plane as a TriangleSetup
// with kNarrowEdges, each edge's constant stored as the edge's value at the box's first pixel,
// f0[k] = a[k]·min_x + b[k]·min_y − t[k], and the box as int16; limits.h derives that both fit. A triangle
// whose edges are wider keeps its TriangleSetup in the chunk's side array and `full` holds the index there
// (then the other fields are unused). depth_setup.h converts between the two records. The back-facing bit is
// not kept: no depth-only stage reads it.
struct alignas(64) DepthSetup {
  int32_t a[3], b[3];
  int32_t f0[3];
  int16_t min_x, min_y, max_x, max_y;
  float z_a0, dzdx, dzdy, z_offset;  // as in TriangleSetup
  uint32_t full;                     // kNoFullSetup, or the index of the triangle's TriangleSetup
};
static_assert(sizeof(DepthSetup) == 64);

inline constexpr uint32_t kNoFullSetup = ~0u;

SHADOWLAB_ISA_END
}  // namespace raster
