// Camera matrices and the default framing camera (see camera_math.h).
#include "scenes/camera_math.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace scenes {

glm::mat4 view_matrix(const Camera& camera) { return glm::lookAt(camera.position, camera.target, camera.up); }

float camera_aspect(const Camera& camera, float viewport_aspect) {
  if (const auto* p = std::get_if<Perspective>(&camera.projection))
    if (p->aspect) return *p->aspect;
  return viewport_aspect;
}

glm::mat4 projection_matrix(const Camera& camera, float viewport_aspect) {
  if (const auto* p = std::get_if<Perspective>(&camera.projection))
    return glm::perspective(glm::radians(p->fovy_deg), camera_aspect(camera, viewport_aspect), p->near, p->far);
  const auto& o = std::get<Orthographic>(camera.projection);
  return glm::ortho(o.left, o.right, o.bottom, o.top, o.near, o.far);
}

Camera frame_camera(const Aabb& bounds, std::string name) {
  Camera c;
  c.name = std::move(name);
  const glm::vec3 centre = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  const float radius = bounds.empty() ? 1.0f : std::max(0.5f * glm::length(bounds.size()), 1e-3f);
  Perspective p;
  p.fovy_deg = 45.0f;
  const float distance = 1.1f * radius / std::sin(glm::radians(0.5f * p.fovy_deg));
  c.target = centre;
  c.position = centre + distance * glm::normalize(glm::vec3(0.6f, 0.5f, 1.0f));
  p.near = std::max(distance - 1.5f * radius, 1e-3f * distance);
  p.far = distance + 1.5f * radius;
  c.projection = p;
  return c;
}

}  // namespace scenes
