// Triangle setup: from clip-space positions to window space (CONVENTIONS' exact float sequence), snapping to
// the 8-bit sub-pixel grid, culling, the integer edge functions with the tie rule, the bounding box and the
// depth plane with polygon offset. Front end of the pipeline, one triangle at a time.
#pragma once
#include <cmath>
#include <cstdint>

#include <glm/vec4.hpp>

#include "raster/formats.h"
#include "raster/limits.h"
#include "raster/primitive.h"
#include "raster/state.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// The per-draw constants setup needs, derived once from the DrawState snapshot.
struct SetupParams {
  float vp_half_w, vp_center_x;  // x_w = fma(ndc_x, vp_half_w, vp_center_x)
  float vp_half_h, vp_center_y;
  PixelRect clip;                // viewport ∩ scissor ∩ target
  CullMode cull;
  FrontFace front_face;
  PolygonOffset offset;
  DepthFormat format;
  bool depth_clamp;
};

SetupParams make_setup_params(const DrawState& state, int target_width, int target_height, DepthFormat format);

// Viewport transform of one clip-space position whose w > 0 (the clipper guarantees it). CONVENTIONS: ndc =
// clip · (1/w) with an IEEE division and float products, then one fused multiply-add; snapping rounds x · 256
// (exact in float) to the nearest integer, ties to even (lrint in the default rounding mode).
inline WindowVertex to_window(const glm::vec4& c, const SetupParams& p) {
  const float inv_w = 1.0f / c.w;
  const float nx = c.x * inv_w, ny = c.y * inv_w, nz = c.z * inv_w;
  WindowVertex v;
  v.x = std::fma(nx, p.vp_half_w, p.vp_center_x);
  v.y = std::fma(ny, p.vp_half_h, p.vp_center_y);
  v.z = std::fma(nz, 0.5f, 0.5f);
  v.inv_w = inv_w;
  v.sx = int32_t(std::lrint(v.x * float(kSubpixelScale)));
  v.sy = int32_t(std::lrint(v.y * float(kSubpixelScale)));
  return v;
}

enum class SetupResult { visible, culled, degenerate, outside };

// Fills `out` for the triangle (v0, v1, v2) as submitted. Returns visible when it may cover pixels.
// `out.prim` is left for the caller except for the back-facing bit.
SetupResult setup_triangle(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                           const SetupParams& p, TriangleSetup& out);

// The minimum resolvable depth difference r used by polygon offset units, as llvmpipe takes it (CONVENTIONS):
// 2 codes for d16 and d24; for d32f 2^(e − 23) with e the exponent of the largest depth of the triangle.
float polygon_offset_r(DepthFormat format, float max_depth);

SHADOWLAB_ISA_END
}  // namespace raster
