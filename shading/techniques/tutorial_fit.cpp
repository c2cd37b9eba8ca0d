// The tutorial's automatic light frustum, object by object (see tutorial_fit.h).
#include "shading/techniques/tutorial_fit.h"

#include <algorithm>
#include <array>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec4.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

bool box_in_frustum(const glm::mat4& view_proj, const Box& b) {
  if (b.empty()) return false;
  const glm::vec4 r[4] = {glm::vec4(view_proj[0][0], view_proj[1][0], view_proj[2][0], view_proj[3][0]),
                          glm::vec4(view_proj[0][1], view_proj[1][1], view_proj[2][1], view_proj[3][1]),
                          glm::vec4(view_proj[0][2], view_proj[1][2], view_proj[2][2], view_proj[3][2]),
                          glm::vec4(view_proj[0][3], view_proj[1][3], view_proj[2][3], view_proj[3][3])};
  // The six planes w ± x, w ± y, w ± z ≥ 0 (Gribb and Hartmann); the box is outside a plane when its corner
  // farthest along the plane's normal is.
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f}) {
      const glm::vec4 plane = r[3] + sign * r[axis];
      const glm::vec3 far_corner(plane.x > 0.0f ? b.max.x : b.min.x, plane.y > 0.0f ? b.max.y : b.min.y,
                                 plane.z > 0.0f ? b.max.z : b.min.z);
      if (glm::dot(glm::vec3(plane), far_corner) + plane.w < 0.0f) return false;
    }
  return true;
}

float nearest_view_distance(const Box& b, glm::vec3 eye, glm::vec3 forward) {
  const glm::vec3 near_corner(forward.x > 0.0f ? b.min.x : b.max.x, forward.y > 0.0f ? b.min.y : b.max.y,
                              forward.z > 0.0f ? b.min.z : b.max.z);
  return glm::dot(near_corner - eye, forward);
}

bool boxes_overlap(const Box& a, const Box& b) {
  return !a.empty() && !b.empty() && a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
         b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

glm::mat3 light_rotation(glm::vec3 direction) {
  const glm::vec3 d = glm::normalize(direction);
  // lookAt's rotation: rows x, y and −d (view space looks down −z, so +z points towards the light).
  return glm::mat3(glm::lookAt(glm::vec3(0.0f), d, light_up(d)));
}

Box rotated_box(const glm::mat3& rotation, const Box& b) {
  Box r;
  if (b.empty()) return r;
  for (const glm::vec3& p : box_corners(b)) {
    const glm::vec3 q = rotation * p;
    r.min = glm::min(r.min, q);
    r.max = glm::max(r.max, q);
  }
  return r;
}

bool between_box_and_light(const glm::mat3& rotation, const Box& object, const Box& receivers) {
  const Box o = rotated_box(rotation, object), r = rotated_box(rotation, receivers);
  if (o.empty() || r.empty()) return false;
  return o.min.x <= r.max.x && r.min.x <= o.max.x && o.min.y <= r.max.y && r.min.y <= o.max.y &&
         o.max.z >= r.min.z;
}

TutorialSets tutorial_sets(std::span<const ObjectBounds> objects, const TutorialFitInput& in) {
  TutorialSets s;
  // Potential receivers: in the light frustum (a directional light's is all of space), the view frustum and
  // the scene box, and not beyond the cut-off.
  for (size_t i = 0; i < objects.size(); ++i) {
    const ObjectBounds& o = objects[i];
    if (!o.receiver || !box_in_frustum(in.camera_view_proj, o.box) || !boxes_overlap(o.box, in.scene)) continue;
    if (nearest_view_distance(o.box, in.eye, in.forward) > in.cutoff) continue;
    s.receivers.push_back(i);
    s.receiver_box.min = glm::min(s.receiver_box.min, o.box.min);
    s.receiver_box.max = glm::max(s.receiver_box.max, o.box.max);
  }
  if (s.receivers.empty()) return s;
  // Potential casters: the receivers, and every caster between their box and the light.
  const glm::mat3 rotation = light_rotation(in.direction);
  size_t next = 0;  // walks s.receivers, which is ascending
  for (size_t i = 0; i < objects.size(); ++i) {
    const bool receiver = next < s.receivers.size() && s.receivers[next] == i;
    if (receiver) ++next;
    if (receiver || (objects[i].caster && between_box_and_light(rotation, objects[i].box, s.receiver_box)))
      s.casters.push_back(i);
  }
  return s;
}

LightBox tutorial_light_box(std::span<const ObjectBounds> objects, const TutorialSets& sets,
                            const TutorialFitInput& in) {
  const glm::mat3 rotation = light_rotation(in.direction);
  Box b;
  const auto add = [&](const Box& world) {
    const Box r = rotated_box(rotation, world);
    if (r.empty()) return;
    b.min = glm::min(b.min, r.min);
    b.max = glm::max(b.max, r.max);
  };
  if (sets.receivers.empty()) add(in.scene);
  for (size_t i : sets.casters) add(objects[i].box);
  if (b.empty()) b = Box{glm::vec3(-1.0f), glm::vec3(1.0f)};  // nothing at all: a unit box
  return LightBox{glm::normalize(in.direction), b.min, b.max};
}

LightBox smooth_light_box(const LightBox& now, const std::optional<LightBox>& previous, float smoothing) {
  if (!previous || previous->direction != now.direction || smoothing <= 0.0f) return now;
  const float follow = 1.0f - smoothing;
  LightBox b = now;
  b.lo = glm::min(now.lo, previous->lo + (now.lo - previous->lo) * follow);
  b.hi = glm::max(now.hi, previous->hi + (now.hi - previous->hi) * follow);
  return b;
}

LightMatrices light_box_matrices(const LightBox& b, float margin) {
  LightMatrices m;
  const glm::mat3 rotation = light_rotation(b.direction);
  m.view = glm::mat4(rotation);
  const glm::vec3 ext = glm::max(b.hi - b.lo, glm::vec3(1e-3f)) * margin;
  // View space looks down −z: near = −(z nearest the light), far = −(z farthest from it).
  m.proj = glm::ortho(b.lo.x - ext.x, b.hi.x + ext.x, b.lo.y - ext.y, b.hi.y + ext.y, -(b.hi.z + ext.z),
                      -(b.lo.z - ext.z));
  return m;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
