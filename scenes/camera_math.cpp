// Camera matrices and the default framing camera (see camera_math.h).
#include "scenes/camera_math.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace scenes {

glm::mat4 view_matrix(const Camera& camera) {
  // In float where a float can (every scene's frames as they always were); in double where the view vector's
  // squared length overflows (a model 1e19 m across or more), where float's lookAt normalizes it to zero.
  const glm::vec3 f = camera.target - camera.position;
  if (const float d = glm::dot(f, f); std::isfinite(d) && d > 0.0f)
    return glm::lookAt(camera.position, camera.target, camera.up);
  return glm::mat4(glm::lookAt(glm::dvec3(camera.position), glm::dvec3(camera.target), glm::dvec3(camera.up)));
}

float camera_aspect(const Camera& camera, float viewport_aspect) {
  if (const auto* p = std::get_if<Perspective>(&camera.projection))
    if (p->aspect) return *p->aspect;
  return viewport_aspect;
}

glm::mat4 projection_matrix(const Camera& camera, float viewport_aspect) {
  if (const auto* p = std::get_if<Perspective>(&camera.projection)) {
    // In double where near · far overflows a float (a model 1e19 m across or more): the matrix's 2 n f / (n − f)
    // fits a float, but float's product on the way does not, and an infinite entry drew nothing.
    const float aspect = camera_aspect(camera, viewport_aspect);
    if (std::isfinite(p->near * p->far))
      return glm::perspective(glm::radians(p->fovy_deg), aspect, p->near, p->far);
    return glm::mat4(glm::perspective(glm::radians(double(p->fovy_deg)), double(aspect), double(p->near),
                                      double(p->far)));
  }
  const auto& o = std::get<Orthographic>(camera.projection);
  return glm::ortho(o.left, o.right, o.bottom, o.top, o.near, o.far);
}

Camera frame_camera(const Aabb& bounds, std::string name) {
  Camera c;
  c.name = std::move(name);
  const glm::vec3 centre = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  // The half-diagonal in double: a float's squares overflow for a model 1e19 m across (the radius came out
  // infinite and the camera's up vector NaN). At least a picometre, at most what a float holds.
  const float radius = bounds.empty() ? 1.0f : float(std::clamp(0.5 * glm::length(glm::dvec3(bounds.size())), 1e-12,
                                                                  double(std::numeric_limits<float>::max()) / 4.0));
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
