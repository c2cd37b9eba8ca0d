// Light frustum fitting for the classic technique (see light_frustum.h).
#include "shading/techniques/light_frustum.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

glm::vec3 light_up(glm::vec3 direction) {
  const glm::vec3 d = glm::normalize(direction);
  return std::abs(d.y) > 0.99f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

Box camera_receiver_box(const glm::mat4& camera_view_proj, const Box& scene) {
  const glm::mat4 inv = glm::inverse(camera_view_proj);
  Box f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 ndc((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f, 1.0f);
    const glm::vec4 w = inv * ndc;
    const glm::vec3 p = glm::vec3(w) / w.w;
    f.min = glm::min(f.min, p);
    f.max = glm::max(f.max, p);
  }
  Box r{glm::max(f.min, scene.min), glm::min(f.max, scene.max)};
  return r;
}

LightMatrices fit_directional(glm::vec3 direction, const Box& receivers, const Box& casters, float margin) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 c = receivers.empty() ? glm::vec3(0.0f) : 0.5f * (receivers.min + receivers.max);
  LightMatrices m;
  m.view = glm::lookAt(c, c + d, light_up(d));
  // Light view space looks down −z: larger z is nearer the light.
  glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  if (!receivers.empty())
    for (const glm::vec3& p : box_corners(receivers)) {
      const glm::vec3 v = glm::vec3(m.view * glm::vec4(p, 1.0f));
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  if (receivers.empty()) lo = glm::vec3(-1.0f), hi = glm::vec3(1.0f);
  float znear = hi.z;  // nearest the light
  if (!casters.empty())
    for (const glm::vec3& p : box_corners(casters)) znear = std::max(znear, (m.view * glm::vec4(p, 1.0f)).z);
  const glm::vec2 ext = glm::max(glm::vec2(hi - lo), glm::vec2(1e-3f)) * margin;
  const float zext = std::max(znear - lo.z, 1e-3f) * margin;
  m.proj = glm::ortho(lo.x - ext.x, hi.x + ext.x, lo.y - ext.y, hi.y + ext.y, -(znear + zext), -(lo.z - zext));
  return m;
}

LightMatrices fixed_directional(glm::vec3 direction, glm::vec3 center, glm::vec2 half, float near, float far) {
  const glm::vec3 d = glm::normalize(direction);
  LightMatrices m;
  m.view = glm::lookAt(center - d, center, light_up(d));
  m.proj = glm::ortho(-half.x, half.x, -half.y, half.y, near, far);
  return m;
}

LightMatrices spot_frustum(glm::vec3 position, glm::vec3 direction, float outer_half_angle, float range) {
  const glm::vec3 d = glm::normalize(direction);
  LightMatrices m;
  m.view = glm::lookAt(position, position + d, light_up(d));
  const float far = range > 0.0f ? range : 100.0f;
  m.proj = glm::perspective(2.0f * outer_half_angle, 1.0f, far / 25.0f, far);
  return m;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
