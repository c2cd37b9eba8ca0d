// The depth the filterable maps store and compare: a light's linear depth in [0, 1]. For an orthographic
// (directional) map it is the window depth itself; for a perspective (spot) map the window depth is undone to
// the view distance along the light's axis and divided by the far plane's, so that exponents and variances
// mean the same everywhere in the map (a window depth crowds most of the range next to the far plane).
#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

struct LightDepth {
  bool perspective = false;
  float p22 = 0.0f, p32 = 0.0f;  // the projection's z row: clip z = p22 · z_view + p32 (GL, z_view < 0 in front)
  float far = 1.0f;              // view distance of the far plane

  static LightDepth of(const glm::mat4& proj, bool perspective) {
    LightDepth l;
    l.perspective = perspective;
    if (perspective) {
      l.p22 = proj[2][2], l.p32 = proj[3][2];
      l.far = l.p32 / (1.0f + l.p22);  // the distance where z_ndc = 1
    }
    return l;
  }
  // The view distance of window depth zw in [0, 1]: z_ndc = 2 zw − 1 = −p22 − p32 / z_view.
  float distance(float zw) const { return p32 / ((2.0f * zw - 1.0f) + p22); }
  // Linear depth in [0, 1] of a stored window depth.
  float from_window(float zw) const { return perspective ? distance(zw) / far : zw; }
  // Linear depth of view-space point v (perspective maps; orthographic ones read the window depth directly).
  float of_view(const glm::vec4& v) const { return -v.z / far; }
};

SHADOWLAB_ISA_END
}  // namespace shading::tech
