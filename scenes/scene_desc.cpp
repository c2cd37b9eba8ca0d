// Name tables of the scene document (primitives, room sides) and the transform rule T · R · S.
#include "scenes/scene_desc.h"

#include <array>
#include <cmath>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

namespace scenes {
namespace {

constexpr std::array kPrimitives = {
    NamedEntry{"plane", "XZ plane at y = 0 facing +Y: size [x, z], segments"},
    NamedEntry{"box", "box centred on the origin: size [x, y, z]"},
    NamedEntry{"sphere", "UV sphere centred on the origin: radius, segments, rings"},
    NamedEntry{"cylinder", "cylinder along Y centred on the origin: radius, height, segments, caps"},
    NamedEntry{"cone", "cone along Y centred on the origin, apex up: radius, height, segments, cap"},
    NamedEntry{"room", "thick-walled room, floor at y = 0: size [x, y, z] inside, wall, sides"},
    NamedEntry{"terrain", "sum-of-sines heightfield in XZ: size, resolution, amplitude, wavelength, seed"},
};
static_assert(kPrimitives.size() == std::variant_size_v<Shape>);

constexpr std::array kRoomSides = {
    NamedEntry{"floor", "slab under y = 0"},      NamedEntry{"ceiling", "slab over y = size.y"},
    NamedEntry{"-x", "wall at x = -size.x / 2"},  NamedEntry{"+x", "wall at x = +size.x / 2"},
    NamedEntry{"-z", "wall at z = -size.z / 2"},  NamedEntry{"+z", "wall at z = +size.z / 2"},
};

}  // namespace

std::span<const NamedEntry> primitive_names() { return kPrimitives; }
std::span<const NamedEntry> room_side_names() { return kRoomSides; }
std::string_view shape_name(const Shape& shape) { return kPrimitives[shape.index()].name; }

glm::mat4 transform_matrix(const TransformDesc& t) {
  if (t.matrix) return *t.matrix;
  glm::mat4 m = glm::translate(glm::mat4(1.0f), t.translate);
  if (t.quaternion) {
    m = m * glm::mat4_cast(glm::normalize(*t.quaternion));
  } else {
    m = glm::rotate(m, glm::radians(t.rotate_deg.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(t.rotate_deg.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(t.rotate_deg.x), glm::vec3(1, 0, 0));
  }
  return glm::scale(m, t.scale);
}

std::optional<Problem> camera_problem(const Camera& c) {
  // In double: a camera 1e20 m from its target is fine, but float's squares of that distance overflow.
  const glm::dvec3 forward = glm::dvec3(c.target) - glm::dvec3(c.position);
  if (!(glm::dot(forward, forward) > 0.0)) return Problem{"target", "same as position"};
  if (!(glm::length(glm::cross(glm::normalize(forward), glm::dvec3(c.up))) > 1e-6))
    return Problem{"up", "zero or parallel to the view direction"};
  if (const auto* p = std::get_if<Perspective>(&c.projection)) {
    if (!(p->fovy_deg > 0.0f && p->fovy_deg < 180.0f))
      return Problem{"perspective.fovy", "must be between 0 and 180 degrees"};
    if (p->aspect && !(*p->aspect > 0.0f)) return Problem{"perspective.aspect", "must be positive"};
    if (!(p->near > 0.0f && p->near < p->far)) return Problem{"perspective", "needs 0 < near < far"};
  } else {
    const auto& o = std::get<Orthographic>(c.projection);
    if (!(o.left < o.right && o.bottom < o.top)) return Problem{"orthographic", "needs left < right and bottom < top"};
    if (!(o.near < o.far)) return Problem{"orthographic", "needs near < far"};
  }
  return std::nullopt;
}

std::optional<Problem> light_problem(const Light& l) {
  if (l.type != LightType::point && !(glm::dot(l.direction, l.direction) > 0.0f))
    return Problem{"direction", "must not be zero"};
  if (!(l.inner_cone_deg >= 0.0f && l.inner_cone_deg <= l.outer_cone_deg && l.outer_cone_deg < 90.0f))
    return Problem{"", "needs 0 <= inner_cone <= outer_cone < 90 degrees"};
  if (!(l.range >= 0.0f)) return Problem{"range", "must not be negative"};
  for (int i = 0; i < 3; ++i)
    if (!(std::isfinite(l.color[i]) && l.color[i] >= 0.0f))
      return Problem{"color", "needs three finite components of 0 or more"};
  if (!(l.intensity >= 0.0f) || !std::isfinite(l.intensity))
    return Problem{"intensity", "must be a finite number of 0 or more (candela, or lux for a directional light)"};
  if (const std::string why = shading::tech::refusal(l.shadow.technique, l.type); !why.empty()) {
    std::string ok;
    for (const shading::tech::TechniqueInfo& t : shading::tech::kTechniques) {
      if (!t.built || !technique_supports(t.id, l.type)) continue;
      if (!ok.empty()) ok += ", ";
      ok += t.name;
    }
    return Problem{"shadow.technique", why + " (use: " + ok + ")"};
  }
  for (const auto& [key, value] : l.shadow.params)
    if (auto why = param_problem(l.shadow.technique, key, value)) return Problem{"shadow.params." + key, *why};
  const ShadowSettings& s = l.shadow;
  if (s.map_size > 16384) return Problem{"shadow.map_size", "must be between 1 and 16384"};
  if (auto why = shading::tech::map_size_problem(s.technique, int(s.map_size))) return Problem{"shadow.map_size", *why};
  if (s.poisson_taps != 4 && s.poisson_taps != 16) return Problem{"shadow.poisson_taps", "expected 4 or 16"};
  if (!(s.poisson_spread > 0.0f && s.poisson_spread <= 1.0f))
    return Problem{"shadow.poisson_spread", "must be above 0 and at most 1 (the disc's radius in map coordinates)"};
  // Bias values are checked here, where the file is known, not first by the frame (issue 23: a scene's
  // bias_slope_max of -1 was reported as the --bias-slope-max option).
  const std::pair<const char*, float> non_negative[] = {{"shadow.bias.constant", s.bias.constant},
                                                        {"shadow.bias.slope", s.bias.slope},
                                                        {"shadow.bias.slope_max", s.bias.slope_max},
                                                        {"shadow.bias.normal_offset", s.bias.normal_offset}};
  for (const auto& [field, v] : non_negative)
    if (!(std::isfinite(v) && v >= 0.0f)) return Problem{field, "must be a finite number of 0 or more"};
  for (const auto& [field, v] : {std::pair{"shadow.bias.offset_factor", s.bias.offset_factor},
                                 std::pair{"shadow.bias.offset_units", s.bias.offset_units}})
    if (!std::isfinite(v)) return Problem{field, "must be a finite number"};
  return std::nullopt;
}

}  // namespace scenes
