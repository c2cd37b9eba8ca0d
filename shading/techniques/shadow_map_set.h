// How a light's shadow map is laid out: a ShadowMapSet of one or more passes, each a viewport with view and
// projection matrices inside one of the set's depth targets. The classic technique has one pass; cascades or
// cube faces would have several, chosen per pixel when reading. Building (depth_pass.h) and reading
// (classic.h, omni_read.h and the other readers) both work from this plain description.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/state.h"
#include "raster/target.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

struct ShadowPass {
  std::string label;        // "main", "cascade0", "+X", ...
  size_t target = 0;        // index into ShadowMapSet::targets
  raster::Rect viewport;    // where the pass renders inside its target (lower-left origin)
  glm::mat4 view{1.0f};
  glm::mat4 proj{1.0f};
  bool perspective = false; // read with textureProj (divide by q)
};

struct ShadowMapSet {
  // Targets are held by pointer so that texture views over them stay valid when the set is moved.
  std::vector<std::unique_ptr<raster::DepthTarget>> targets;
  // Optional colour targets beside the depth targets (colors[i] goes with targets[i]; null or absent: none),
  // for maps that store their depth in colour, e.g. the dual paraboloid's RGBA8 packing.
  std::vector<std::unique_ptr<raster::ColorTarget>> colors;
  std::vector<ShadowPass> passes;
};

// The tutorial's bias matrix: clip space [-1, 1] to texture space [0, 1] on x, y and z (scale and offset 0.5).
inline glm::mat4 bias_matrix() {
  glm::mat4 b(0.5f);
  b[3] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
  return b;
}

// World to texture space (s, t, r, q) of a pass whose viewport covers its whole target: bias × proj × view.
inline glm::mat4 shadow_matrix(const ShadowPass& p) { return bias_matrix() * p.proj * p.view; }

// The continuous texel coordinates of world point p in a pass `size` texels wide read through `shadow`
// (shadow_matrix), divided by q where the pass is perspective; false behind its centre of projection. For the
// aliasing measure (LightShadow::texel_coords).
inline bool map_texel(const glm::mat4& shadow, bool perspective, glm::vec2 size, glm::vec3 p, glm::vec2& texel) {
  const glm::vec4 c = shadow * glm::vec4(p, 1.0f);
  if (!perspective) return texel = glm::vec2(c.x, c.y) * size, true;
  if (!(c.w > 0.0f)) return false;
  texel = glm::vec2(c.x, c.y) / c.w * size;
  return true;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
