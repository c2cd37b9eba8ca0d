// Caster frustum fitting and the receiver box test (see projective_frustum.h).
#include "shading/techniques/projective_frustum.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "shading/techniques/shadow_map_set.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

// Widens [lo, hi] about its centre so that it covers the inner `inner` of `size` texels exactly.
void widen(float& lo, float& hi, int size, int ring) {
  const int inner = size - 2 * ring;
  if (inner <= 0) return;
  const float c = 0.5f * (lo + hi), h = 0.5f * (hi - lo) * float(size) / float(inner);
  lo = c - h, hi = c + h;
}

glm::vec4 row(const glm::mat4& m, int i) { return {m[0][i], m[1][i], m[2][i], m[3][i]}; }

FrustumPlane plane_of(glm::vec4 v) { return {glm::vec3(v), v.w}; }

}  // namespace

CasterFrustum fit_caster_frustum(const ProjectiveLight& light, const Box& caster, int map_size, int ring) {
  CasterFrustum f;
  if (caster.empty() || map_size < 1) return f;
  const glm::vec3 centre = 0.5f * (caster.min + caster.max);
  const float extent = std::max(glm::length(caster.max - caster.min), 1e-6f);
  const auto corners = box_corners(caster);
  const int inner = std::max(1, map_size - 2 * ring);

  if (light.directional) {
    const glm::vec3 d = glm::normalize(light.direction);
    f.view = glm::lookAt(centre, centre + d, light_up(d));
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    for (const glm::vec3& p : corners) {
      const glm::vec3 v(f.view * glm::vec4(p, 1.0f));
      lo = glm::min(lo, v), hi = glm::max(hi, v);
    }
    // Flat casters seen edge-on still get a frustum of non-zero size.
    const float eps = extent * 1e-4f;
    if (hi.x - lo.x < eps) lo.x -= eps, hi.x += eps;
    if (hi.y - lo.y < eps) lo.y -= eps, hi.y += eps;
    f.texel_world = std::max(hi.x - lo.x, hi.y - lo.y) / float(inner);
    widen(lo.x, hi.x, map_size, ring);
    widen(lo.y, hi.y, map_size, ring);
    f.near_depth = -hi.z;
    const float far_depth = std::max(-lo.z, f.near_depth + eps);
    f.proj = glm::ortho(lo.x, hi.x, lo.y, hi.y, f.near_depth, far_depth);
  } else {
    const glm::vec3 axis = centre - light.position;
    if (glm::length(axis) <= 1e-6f) return f;
    f.view = glm::lookAt(light.position, centre, light_up(axis));
    glm::vec2 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    float dmin = std::numeric_limits<float>::infinity(), dmax = 0.0f;
    for (const glm::vec3& p : corners) {
      const glm::vec3 v(f.view * glm::vec4(p, 1.0f));
      const float depth = -v.z;
      // The light inside (or level with) the caster's box: no frustum from the light can hold it.
      if (!(depth > extent * 1e-3f)) return f;
      lo = glm::min(lo, glm::vec2(v.x, v.y) / depth), hi = glm::max(hi, glm::vec2(v.x, v.y) / depth);
      dmin = std::min(dmin, depth), dmax = std::max(dmax, depth);
    }
    const float dc = std::max(-(f.view * glm::vec4(centre, 1.0f)).z, dmin);
    f.texel_world = std::max(hi.x - lo.x, hi.y - lo.y) * dc / float(inner);
    widen(lo.x, hi.x, map_size, ring);
    widen(lo.y, hi.y, map_size, ring);
    f.near_depth = dmin;
    f.proj = glm::frustum(lo.x * dmin, hi.x * dmin, lo.y * dmin, hi.y * dmin, dmin, std::max(dmax, dmin * 1.001f));
    f.perspective = true;
  }
  f.texgen = bias_matrix() * f.proj * f.view;
  f.depth_row = -row(f.view, 2);
  const glm::mat4 m = f.proj * f.view;
  const glm::vec4 r0 = row(m, 0), r1 = row(m, 1), r3 = row(m, 3);
  f.planes = {plane_of(r3 + r0), plane_of(r3 - r0), plane_of(r3 + r1), plane_of(r3 - r1),
              plane_of(f.depth_row - glm::vec4(0.0f, 0.0f, 0.0f, f.near_depth))};
  f.valid = true;
  return f;
}

bool box_overlaps(const CasterFrustum& f, const Box& box) {
  if (!f.valid || box.empty()) return false;
  for (const FrustumPlane& p : f.planes) {
    const glm::vec3 v(p.n.x >= 0.0f ? box.max.x : box.min.x, p.n.y >= 0.0f ? box.max.y : box.min.y,
                      p.n.z >= 0.0f ? box.max.z : box.min.z);
    if (glm::dot(p.n, v) + p.d < 0.0f) return false;
  }
  return true;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
