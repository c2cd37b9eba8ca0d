// Orthographic, stabilised and LiSPSM fits of a directional light's map to a body (see view_fit.h).
#include "shading/techniques/view_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Light-space bounds of a point set.
struct Bounds {
  glm::vec3 lo{kInf}, hi{-kInf};
  void add(glm::vec3 v) { lo = glm::min(lo, v), hi = glm::max(hi, v); }
  bool empty() const { return !(lo.x <= hi.x); }
};

Bounds light_bounds(const glm::mat4& view, std::span<const glm::vec3> pts) {
  Bounds b;
  for (const glm::vec3& p : pts) b.add(glm::vec3(view * glm::vec4(p, 1.0f)));
  return b;
}

// The light-space z nearest the light among the casters' box corners (−inf when there are none).
float caster_top(const glm::mat4& view, const Box& casters) {
  float top = -kInf;
  if (!casters.empty())
    for (const glm::vec3& p : box_corners(casters)) top = std::max(top, (view * glm::vec4(p, 1.0f)).z);
  return top;
}

// An orthographic map over light-space x ∈ [lo.x, hi.x], y ∈ [lo.y, hi.y], z from `top` (nearest the light)
// down to lo.z, each widened by `margin` of its extent.
FittedMap ortho_map(const glm::mat4& view, glm::vec3 lo, glm::vec3 hi, float top, float margin) {
  const glm::vec2 ext = glm::max(glm::vec2(hi - lo), glm::vec2(1e-3f)) * margin;
  const float zext = std::max(top - lo.z, 1e-3f) * margin;
  FittedMap m;
  m.view = view;
  m.proj = glm::ortho(lo.x - ext.x, hi.x + ext.x, lo.y - ext.y, hi.y + ext.y, -(top + zext), -(lo.z - zext));
  m.depth_extent = (top + zext) - (lo.z - zext);
  return m;
}

}  // namespace

glm::mat4 light_view(glm::vec3 direction, glm::vec3 up) {
  const glm::vec3 d = glm::normalize(direction);
  return glm::lookAt(glm::vec3(0.0f), d, up);
}

FittedMap fit_ortho(glm::vec3 direction, std::span<const glm::vec3> body, const Box& casters) {
  const glm::mat4 view = light_view(direction, light_up(direction));
  Bounds b = light_bounds(view, body);
  if (b.empty()) b.lo = glm::vec3(-1.0f), b.hi = glm::vec3(1.0f);
  return ortho_map(view, b.lo, b.hi, std::max(b.hi.z, caster_top(view, casters)), 0.005f);
}

FittedMap fit_stable(glm::vec3 direction, glm::vec3 center, float radius, int map_size, const Box& depth_box) {
  const glm::mat4 view = light_view(direction, light_up(direction));
  glm::vec3 c = glm::vec3(view * glm::vec4(center, 1.0f));
  // Snap the centre to the texel grid of a square of side 2·radius: moving the camera moves the map by whole
  // texels only, so a static shadow does not crawl.
  const float texel = 2.0f * radius / float(map_size);
  c.x = std::round(c.x / texel) * texel;
  c.y = std::round(c.y / texel) * texel;
  Bounds z = light_bounds(view, box_corners(depth_box));
  if (z.empty()) z.lo.z = c.z - radius, z.hi.z = c.z + radius;
  FittedMap m;
  m.view = view;
  const float pad = std::max(z.hi.z - z.lo.z, 1e-3f) * 0.005f;
  m.proj = glm::ortho(c.x - radius, c.x + radius, c.y - radius, c.y + radius, -(z.hi.z + pad), -(z.lo.z - pad));
  m.depth_extent = (z.hi.z - z.lo.z) + 2.0f * pad;
  return m;
}

FittedMap fit_lispsm(glm::vec3 direction, std::span<const glm::vec3> body, const Box& casters,
                     const CameraView& camera, float z_n, float z_f) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 v = glm::normalize(camera.forward);
  const float sin_gamma = glm::length(glm::cross(v, d));
  if (!(sin_gamma >= kLispsmMinSin) || body.empty()) return fit_ortho(direction, body, casters);

  // Light view with y along the view direction as the light sees it: the warp runs along y.
  const glm::vec3 up = glm::normalize(v - glm::dot(v, d) * d);
  const glm::mat4 view = light_view(d, up);
  const Bounds b = light_bounds(view, body);
  const float top = std::max(b.hi.z, caster_top(view, casters));
  const float n_opt = (z_n + std::sqrt(z_n * z_f)) / sin_gamma;
  const glm::vec3 eye = glm::vec3(view * glm::vec4(camera.eye, 1.0f));
  // Projection centre: n_opt before the body's near side (smallest y), level with the eye across.
  const glm::vec3 centre(eye.x, b.lo.y - n_opt, top);
  const float n = n_opt, f = n_opt + std::max(b.hi.y - b.lo.y, 1e-4f);

  // Homogeneous post-perspective coordinates of a light-space point q:
  //   w' = q.y − C.y (> 0 over the body), x' = q.x − C.x, depth' = top − q.z (≥ 0 below the casters' top),
  //   y' = ((f + n)·w' − 2fn) / (f − n), so that y'/w' runs from −1 at the near side to 1 at the far side.
  // Light rays (varying z) keep x'/w' and y'/w': the light stays directional after the warp.
  float x_lo = kInf, x_hi = -kInf, depth_hi = 0.0f;
  for (const glm::vec3& p : body) {
    const glm::vec3 q = glm::vec3(view * glm::vec4(p, 1.0f));
    const float w = q.y - centre.y;
    x_lo = std::min(x_lo, (q.x - centre.x) / w);
    x_hi = std::max(x_hi, (q.x - centre.x) / w);
    depth_hi = std::max(depth_hi, (top - q.z) / w);
  }
  const float x_pad = std::max(x_hi - x_lo, 1e-6f) * 0.005f;
  x_lo -= x_pad, x_hi += x_pad;
  depth_hi = std::max(depth_hi, 1e-6f) * 1.01f;
  const float sx = 2.0f / (x_hi - x_lo), ox = -(x_hi + x_lo) / (x_hi - x_lo);
  const float ay = (f + n) / (f - n) * 0.999f, by = -2.0f * f * n / (f - n) * 0.999f;  // a hair of y margin
  const float kz = 2.0f / depth_hi;
  // clip = P · (q.x, q.y, q.z, 1), rows written out (glm is column-major: P[column][row]).
  glm::mat4 P(0.0f);
  // x: sx·(q.x − C.x) + ox·(q.y − C.y)
  P[0][0] = sx, P[1][0] = ox, P[3][0] = -sx * centre.x - ox * centre.y;
  // y: ay·(q.y − C.y) + by
  P[1][1] = ay, P[3][1] = -ay * centre.y + by;
  // z: kz·(top − q.z) − (q.y − C.y): window depth 0 at the casters' top, 1 at the body's farthest point
  P[2][2] = -kz, P[1][2] = -1.0f, P[3][2] = kz * top + centre.y;
  // w: q.y − C.y
  P[1][3] = 1.0f, P[3][3] = -centre.y;
  FittedMap m;
  m.view = view;
  m.proj = P;
  m.perspective = true;
  m.n_opt = n_opt;
  m.depth_extent = top - b.lo.z;
  return m;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
