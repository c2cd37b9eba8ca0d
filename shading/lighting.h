// The shading model of the shadow demos, in one place: ambient + Lambert diffuse + Blinn-Phong specular, one
// light with colour and power, attenuated by distance (inverse square, windowed to the light's range) and by a
// spot cone with inner and outer angles. The shadow term scales only the direct light, never the ambient.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace shading {

enum class LightType : uint8_t { directional, point, spot };

// Scene units are metres (CONVENTIONS). Angles are cone half-angles in radians.
struct Light {
  LightType type = LightType::spot;
  glm::vec3 position{0.0f};                // point and spot
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // where the light points (directional and spot), normalised
  glm::vec3 color{1.0f};
  float power = 1.0f;        // intensity multiplier: at 1 m from a point or spot light, radiance = colour · power
  float range = 0.0f;        // distance where the light has faded to 0; 0 means unlimited
  float inner_angle = 0.5f;  // spot: full intensity inside this half-angle
  float outer_angle = 0.6f;  // spot: no light beyond this half-angle
};

struct Material {
  glm::vec3 albedo{0.8f};
  float ambient = 0.1f;     // fraction of the albedo lit by ambient light
  float specular = 0.25f;   // Blinn-Phong specular strength (white highlights)
  float shininess = 32.0f;  // Blinn-Phong exponent
};

// Distance attenuation: 1 / max(d², 0.01²) (inverse square, capped at 1 cm so it stays finite) times the range
// window (1 − (d / range)⁴)² clamped to [0, 1], which reaches 0 smoothly at `range`; range 0: no window.
inline float distance_attenuation(float d, float range) {
  const float inv_sq = 1.0f / std::max(d * d, 1e-4f);
  if (range <= 0.0f) return inv_sq;
  const float x = d / range, x2 = x * x;
  const float w = std::clamp(1.0f - x2 * x2, 0.0f, 1.0f);
  return inv_sq * w * w;
}

// Spot cone: 1 inside the inner angle, 0 beyond the outer one, smoothstep between (in cos angle).
// `cos_angle` is the cosine of the angle between the spot direction and the direction to the lit point.
inline float spot_attenuation(float cos_angle, float inner_angle, float outer_angle) {
  const float ci = std::cos(inner_angle), co = std::cos(outer_angle);
  if (ci <= co) return cos_angle >= co ? 1.0f : 0.0f;  // degenerate cone: a hard edge
  const float x = std::clamp((cos_angle - co) / (ci - co), 0.0f, 1.0f);
  return x * x * (3.0f - 2.0f * x);
}

// The light reaching point p: unit direction towards the light (L) and radiance (colour · power · attenuation).
struct LightSample {
  glm::vec3 to_light{0.0f, 1.0f, 0.0f};
  glm::vec3 radiance{0.0f};
};

inline LightSample sample_light(const Light& light, glm::vec3 p) {
  LightSample s;
  if (light.type == LightType::directional) {
    s.to_light = -light.direction;
    s.radiance = light.color * light.power;
    return s;
  }
  const glm::vec3 d = light.position - p;
  const float dist = glm::length(d);
  s.to_light = dist > 0.0f ? d / dist : glm::vec3(0.0f, 1.0f, 0.0f);
  float att = distance_attenuation(dist, light.range);
  if (light.type == LightType::spot)
    att *= spot_attenuation(glm::dot(-s.to_light, light.direction), light.inner_angle, light.outer_angle);
  s.radiance = light.color * (light.power * att);
  return s;
}

// Diffuse and specular of one light at a point, before the shadow term.
struct DirectLight {
  glm::vec3 diffuse{0.0f};
  glm::vec3 specular{0.0f};
};

// n: unit surface normal, v: unit direction from the point towards the eye. Lambert: albedo · max(n·l, 0);
// Blinn-Phong: specular · max(n·h, 0)^shininess with h = normalize(l + v), only where n·l > 0.
inline DirectLight direct_light(const Material& m, const LightSample& light, glm::vec3 n, glm::vec3 v) {
  DirectLight out;
  const float ndotl = glm::dot(n, light.to_light);
  if (ndotl <= 0.0f) return out;
  out.diffuse = m.albedo * light.radiance * ndotl;
  const glm::vec3 hv = light.to_light + v;
  const float len = glm::length(hv);
  if (len > 0.0f) {
    const float ndoth = std::max(glm::dot(n, hv / len), 0.0f);
    out.specular = light.radiance * (m.specular * std::pow(ndoth, m.shininess));
  }
  return out;
}

// The final colour: ambient (albedo · ambient · light colour) + shadow · (diffuse + specular). `shadow` is the
// visibility a shadow lookup returns: 1 lit, 0 in shadow.
inline glm::vec3 shade(const Material& m, const Light& light, glm::vec3 p, glm::vec3 n, glm::vec3 eye, float shadow) {
  const LightSample ls = sample_light(light, p);
  const glm::vec3 v = glm::normalize(eye - p);
  const DirectLight d = direct_light(m, ls, n, v);
  return m.albedo * light.color * m.ambient + shadow * (d.diffuse + d.specular);
}

}  // namespace shading
