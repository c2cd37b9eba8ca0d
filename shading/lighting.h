// The shading model of the shadow demos, in one place, in glTF KHR_lights_punctual units: a light's intensity is
// in candela (point, spot) or lux (directional); what the camera pass computes is luminance (cd/m²), which the
// frame's exposure and tone map (tone_map.h) turn into a picture. Lambert diffuse + Blinn-Phong specular, both
// divided by π (a white Lambertian surface facing E lux has luminance E / π), attenuated by distance (inverse
// square with glTF's range window) and by the spot cone (glTF's recommended falloff), plus an ambient term, an
// illuminance taken as arriving at every point from every direction (no cone, no n·l, no distance, no shadow):
// for a point or spot light its flux spread over the scene (Light::ambient, set by the frame:
// scenes/frame/frame_lights.h), for a directional light a fraction of its own (Material::ambient). The shadow
// term scales only the direct light, never the ambient.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

enum class LightType : uint8_t { directional, point, spot };

// Scene units are metres (CONVENTIONS). Angles are cone half-angles in radians.
struct Light {
  LightType type = LightType::spot;
  glm::vec3 position{0.0f};                // point and spot
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // where the light points (directional and spot), normalised
  glm::vec3 color{1.0f};
  float intensity = 1.0f;    // candela (point, spot: illuminance I / d² at d metres) or lux (directional)
  float range = 0.0f;        // distance where the light has faded to 0; 0 means unlimited
  float inner_angle = 0.5f;  // spot: full intensity inside this half-angle
  float outer_angle = 0.6f;  // spot: no light beyond this half-angle
  // Point and spot: the ambient illuminance (lux), the same at every point; a frame sets it to the light's flux
  // spread over the surface of the scene's bounds (frame::ambient_illuminance). 0: none. Unused by directional
  // lights, whose ambient is Material::ambient of their illuminance.
  float ambient = 0.0f;
};

struct Material {
  glm::vec3 albedo{0.8f};
  float ambient = 0.1f;     // a directional light's ambient: this fraction of its illuminance (sky and bounce)
  float specular = 0.25f;   // Blinn-Phong specular strength (white highlights)
  float shininess = 32.0f;  // Blinn-Phong exponent
};

inline constexpr float kInvPi = std::numbers::inv_pi_v<float>;

// Distance attenuation, glTF's recommended one: 1 / max(d², 0.01²) (inverse square, capped at 1 cm so it stays
// finite) times the range window (1 − (d / range)⁴)² clamped to [0, 1], which reaches 0 smoothly at `range`;
// range 0: no window.
inline float distance_attenuation(float d, float range) {
  const float inv_sq = 1.0f / std::max(d * d, 1e-4f);
  if (range <= 0.0f) return inv_sq;
  const float x = d / range, x2 = x * x;
  const float w = std::clamp(1.0f - x2 * x2, 0.0f, 1.0f);
  return inv_sq * w * w;
}

// Spot cone, glTF's recommended falloff: t = clamp((cos − cos outer) / (cos inner − cos outer), 0, 1), then t².
// 1 inside the inner angle, 0 beyond the outer one. `cos_angle` is the cosine of the angle between the spot
// direction and the direction to the lit point.
inline float spot_attenuation(float cos_angle, float inner_angle, float outer_angle) {
  const float ci = std::cos(inner_angle), co = std::cos(outer_angle);
  if (ci <= co) return cos_angle >= co ? 1.0f : 0.0f;  // degenerate cone: a hard edge
  const float t = std::clamp((cos_angle - co) / (ci - co), 0.0f, 1.0f);
  return t * t;
}

// The light reaching point p: unit direction towards the light (L), the illuminance on a surface facing the light
// (colour · intensity · distance and cone attenuation, lux) and the ambient's illuminance: colour · Light::ambient
// for point and spot lights, the light's whole illuminance for a directional one (Material::ambient of it counts).
struct LightSample {
  glm::vec3 to_light{0.0f, 1.0f, 0.0f};
  glm::vec3 illuminance{0.0f};
  glm::vec3 ambient{0.0f};
  bool directional = false;
};

inline LightSample sample_light(const Light& light, glm::vec3 p) {
  LightSample s;
  if (light.type == LightType::directional) {
    s.to_light = -light.direction;
    s.illuminance = s.ambient = light.color * light.intensity;
    s.directional = true;
    return s;
  }
  const glm::vec3 d = light.position - p;
  const float dist = glm::length(d);
  s.to_light = dist > 0.0f ? d / dist : glm::vec3(0.0f, 1.0f, 0.0f);
  const float att = light.intensity * distance_attenuation(dist, light.range);
  s.ambient = light.color * light.ambient;
  float cone = 1.0f;
  if (light.type == LightType::spot)
    cone = spot_attenuation(glm::dot(-s.to_light, light.direction), light.inner_angle, light.outer_angle);
  s.illuminance = light.color * (att * cone);
  return s;
}

// Diffuse and specular luminance of one light at a point, before the shadow term.
struct DirectLight {
  glm::vec3 diffuse{0.0f};
  glm::vec3 specular{0.0f};
};

// n: unit surface normal, v: unit direction from the point towards the eye. Lambert: albedo / π · E · max(n·l, 0);
// Blinn-Phong: E / π · specular · max(n·h, 0)^shininess with h = normalize(l + v), only where n·l > 0.
inline DirectLight direct_light(const Material& m, const LightSample& light, glm::vec3 n, glm::vec3 v) {
  DirectLight out;
  const float ndotl = glm::dot(n, light.to_light);
  if (ndotl <= 0.0f) return out;
  out.diffuse = m.albedo * light.illuminance * (ndotl * kInvPi);
  const glm::vec3 hv = light.to_light + v;
  const float len = glm::length(hv);
  if (len > 0.0f) {
    const float ndoth = std::max(glm::dot(n, hv / len), 0.0f);
    out.specular = light.illuminance * (m.specular * std::pow(ndoth, m.shininess) * kInvPi);
  }
  return out;
}

// The ambient luminance one light adds: albedo / π · its ambient illuminance (Material::ambient of it for a
// directional light).
inline glm::vec3 ambient_light(const Material& m, const LightSample& light) {
  return m.albedo * light.ambient * ((light.directional ? m.ambient : 1.0f) * kInvPi);
}

// The luminance of a point: ambient + shadow · (diffuse + specular). `shadow` is the visibility a shadow lookup
// returns: 1 lit, 0 in shadow.
inline glm::vec3 shade(const Material& m, const Light& light, glm::vec3 p, glm::vec3 n, glm::vec3 eye, float shadow) {
  const LightSample ls = sample_light(light, p);
  const glm::vec3 v = glm::normalize(eye - p);
  const DirectLight d = direct_light(m, ls, n, v);
  return ambient_light(m, ls) + shadow * (d.diffuse + d.specular);
}

SHADOWLAB_ISA_END
}  // namespace shading
