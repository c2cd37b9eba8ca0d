// PCSS on the cube map (see cube_pcss.h).
#include "shading/techniques/cube_pcss.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "shading/lookup_cube.h"
#include "shading/techniques/poisson.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

float cube_pcss_search_angle(const CubePcss& c, float d_r) {
  const float zs = std::max(c.near, 0.25f * d_r);
  return c.radius * std::max(d_r - zs, 0.0f) / (d_r * zs);
}

float cube_pcss_filter_angle(const CubePcss& c, float d_r, float d_b, float texel_angle) {
  return std::max(c.radius * (d_r - d_b) / (d_r * d_b), texel_angle);
}

namespace {

// Two unit vectors perpendicular to the unit direction d and to each other (d's tangent plane on the sphere).
void tangent_frame(glm::vec3 d, glm::vec3& t, glm::vec3& b) {
  const glm::vec3 helper = std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  t = glm::normalize(glm::cross(helper, d));
  b = glm::cross(d, t);
}

}  // namespace

float cube_pcss_visibility(const OmniReader& r, const CubePcss& c, glm::vec3 p, glm::vec3 n, glm::vec2 frag) {
  const OmniRef o = omni_ref(r, p, n);
  const glm::vec3 rel = o.q - r.position;
  if (r.hemispherical && glm::dot(rel, r.direction) < 0.0f) return 0.0f;
  const float d_r = glm::length(rel);
  if (!(d_r > 0.0f)) return 1.0f;
  const glm::vec3 dir = rel / d_r;
  const float ref = d_r / r.range - o.bias;
  glm::vec3 t, b;
  tangent_frame(dir, t, b);
  const float texel = 2.0f / float(r.cube.size());
  // The receiver's plane (through the looked-up point, normal n) along a tap's direction, as a reference: its
  // distance / range minus the bias, its rise from ref held to 0.01 per texel of the tap's offset.
  const float plane_offset = glm::dot(n, rel);  // the plane's n · (x − light), the same for every tap
  auto plane_ref = [&](glm::vec3 tap_dir, float offset_angle) {
    const float den = glm::dot(n, tap_dir);
    if (!(std::abs(den) > 1e-6f)) return ref;
    const float dist = plane_offset / den;
    if (!(dist > 0.0f) || !std::isfinite(dist)) return ref;
    const float lim = 0.01f * offset_angle / texel;
    return ref + std::clamp(dist / r.range - o.bias - ref, -lim, lim);
  };
  // A hardware PCF lookup compares the four texels around it, up to a texel from the tap: the plane's rise over
  // one texel is allowed on top, so a surface at a slant to the light does not shadow itself between them.
  const float slack = std::abs(plane_ref(glm::normalize(dir + texel * t), texel) - ref) +
                      std::abs(plane_ref(glm::normalize(dir + texel * b), texel) - ref);
  const glm::vec2 rot = rotation_of(pixel_seed(frag));
  auto tap = [&](int i, float radius, float& angle) {
    const glm::vec2 d = kPoissonDisk[size_t(i)];
    const glm::vec2 off = glm::vec2(rot.x * d.x - rot.y * d.y, rot.y * d.x + rot.x * d.y) * radius;
    angle = glm::length(off);
    // The point at tangent offset `off` of the unit sphere's tangent plane: at these angles (well under a
    // radian) its direction is the offset's to within a fraction of a per cent.
    return glm::normalize(dir + off.x * t + off.y * b);
  };
  // Blocker search: texels nearer to the light than the receiver's plane, nearest texel per tap.
  const Sampler nearest = Sampler::plain(Filter::nearest, Wrap::clamp_to_edge);
  const float search = cube_pcss_search_angle(c, d_r);
  float sum = 0.0f;
  int blockers = 0;
  for (int i = 0; i < 16; ++i) {
    float angle = 0.0f;
    const glm::vec3 td = tap(i, search, angle);
    const float z = texture_at(r.cube, nearest, td, 0.0f).r;
    if (z < plane_ref(td, angle) - slack) sum += z, ++blockers;
  }
  if (blockers == 0) return 1.0f;  // early exit: nothing can hide the light
  const float d_b = std::max(sum / float(blockers) * r.range, c.near);
  const float kernel = cube_pcss_filter_angle(c, d_r, d_b, texel);
  float vis = 0.0f;
  for (int i = 0; i < 16; ++i) {
    float angle = 0.0f;
    const glm::vec3 td = tap(i, kernel, angle);
    vis += texture_at(r.cube, r.cube_linear, glm::vec4(td, plane_ref(td, angle) - slack), 0.0f);
  }
  return vis / 16.0f;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
