// How a ShadowMapSet is built: every pass draws world-space triangles into its viewport of its target with a
// depth-only shader (the lean path of the pipeline: no varyings, no colour); alpha-masked casters go through the
// same shader with their alpha test (masked_depth.h). Culling and polygon offset are
// the per-draw state of the depth pass; the classic technique's `offset` bias and back-face option live here.
#pragma once
#include <cstdint>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raster/renderer.h"
#include "shading/techniques/caster_geometry.h"
#include "shading/techniques/shadow_map_set.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// world position → clip space of one pass; depth only.
struct WorldDepthShader {
  using Vertex = glm::vec3;
  using Varyings = raster::NoVaryings;
  glm::mat4 view_proj{1.0f};
  glm::vec4 vertex(const Vertex& v, Varyings&) const { return view_proj * glm::vec4(v, 1.0f); }
};

struct DepthPassOptions {
  bool cull_front = false;             // draw back faces only (glCullFace(GL_FRONT))
  raster::PolygonOffset offset{};      // glPolygonOffset while drawing the map
};

// Allocates one width × height target of `format` with a single full-target pass (view and proj unset).
ShadowMapSet single_map_layout(int size, raster::DepthFormat format, const char* label = "main");

// Clears every target to 1.0 and draws every pass. Returns the summed draw statistics.
raster::DrawStats build_maps(raster::Renderer& renderer, ShadowMapSet& set, const CasterGeometry& casters,
                             const DepthPassOptions& options);

SHADOWLAB_ISA_END
}  // namespace shading::tech
