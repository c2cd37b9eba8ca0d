// Where a light's map looks: view and projection matrices for the classic technique. Directional lights get an
// orthographic box, either fitted automatically (potential receivers = the camera frustum intersected with the
// scene bounds, extended towards the light to every potential caster) or a fixed box as in the tutorial; spot
// lights get a perspective frustum around their cone.
#pragma once
#include <array>
#include <limits>
#include <optional>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// An axis-aligned box in world space; empty when min > max.
struct Box {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};
  bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
};

// The box's eight corners, corner i taking max on axis k where bit k of i is set (x: 1, y: 2, z: 4).
inline std::array<glm::vec3, 8> box_corners(const Box& b) {
  std::array<glm::vec3, 8> c;
  for (int i = 0; i < 8; ++i)
    c[size_t(i)] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
  return c;
}

// One scene object (an instance) as the tutorial's automatic frustum sees it: its world box and whether it casts
// and receives shadows.
struct ObjectBounds {
  Box box;
  bool caster = true, receiver = true;
};

// A directional light's box in the light's rotated frame (light_rotation: x, y across the light, z towards it):
// what a fit that smooths over time keeps from one frame to the next.
struct LightBox {
  glm::vec3 direction{0.0f};  // the light direction it was fitted for
  glm::vec3 lo{0.0f}, hi{0.0f};
};
struct FitMemory {
  std::optional<LightBox> box;  // the previous frame's box, if any
};

struct LightMatrices {
  glm::mat4 view{1.0f};
  glm::mat4 proj{1.0f};
};

// The eight corners of the frustum of a camera's projection × view, bounded by a box, then intersected with
// `scene`: the potential receivers at box granularity. Empty when they do not overlap.
Box camera_receiver_box(const glm::mat4& camera_view_proj, const Box& scene);

// Orthographic light looking along `direction` (the way light travels): x, y bound the receivers, the depth
// range runs from the caster (or receiver) point nearest the light to the receiver point farthest from it,
// widened by `margin` (relative) on every side.
LightMatrices fit_directional(glm::vec3 direction, const Box& receivers, const Box& casters, float margin = 0.01f);

// The tutorial's hand-made box: lookAt(center − direction, center, up) and ortho(−half.x, half.x, −half.y,
// half.y, near, far); the tutorial itself is half = (10, 10), near = −10, far = 20 around the origin.
LightMatrices fixed_directional(glm::vec3 direction, glm::vec3 center, glm::vec2 half, float near, float far);

// Perspective light at `position` looking along `direction`, square, with full field of view twice the cone's
// outer half-angle; near = range / 25 (the tutorial's 2 for its range 50), far = range.
LightMatrices spot_frustum(glm::vec3 position, glm::vec3 direction, float outer_half_angle, float range);

// An up vector for lookAt that is not parallel to `direction`.
glm::vec3 light_up(glm::vec3 direction);

SHADOWLAB_ISA_END
}  // namespace shading::tech
