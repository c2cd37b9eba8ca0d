// Triangle setup: from clip-space positions to window space (CONVENTIONS' exact float sequence), snapping to
// the 8-bit sub-pixel grid, culling, the integer edge functions with the tie rule, the bounding box and the
// depth plane with polygon offset. Front end of the pipeline, one triangle at a time.
#pragma once
#include <glm/vec4.hpp>

#include "raster/formats.h"
#include "raster/primitive.h"
#include "raster/state.h"

namespace raster {

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

// Viewport transform of one clip-space position whose w > 0 (the clipper guarantees it).
WindowVertex to_window(const glm::vec4& clip, const SetupParams& p);

enum class SetupResult { visible, culled, degenerate, outside };

// Fills `out` for the triangle (v0, v1, v2) as submitted. Returns visible when it may cover pixels.
// `out.prim` is left for the caller except for the back-facing bit.
SetupResult setup_triangle(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                           const SetupParams& p, TriangleSetup& out);

// The minimum resolvable depth difference r used by polygon offset units, as llvmpipe takes it (CONVENTIONS):
// 2 codes for d16 and d24; for d32f 2^(e − 23) with e the exponent of the largest depth of the triangle.
float polygon_offset_r(DepthFormat format, float max_depth);

}  // namespace raster
