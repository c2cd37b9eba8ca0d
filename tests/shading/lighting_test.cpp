// The demo shading model in glTF units: Lambert and Blinn-Phong over π, distance and spot attenuation as glTF
// recommends, ambient untouched by shadow.
#include <gtest/gtest.h>

#include <cmath>

#include "shading/lighting.h"

namespace {

using shading::Light;
using shading::LightType;
using shading::Material;

TEST(Lighting, DistanceAttenuationIsInverseSquareWindowedByRange) {
  EXPECT_EQ(shading::distance_attenuation(2.0f, 0.0f), 0.25f);
  // d/range = 0.5: window (1 − 0.5⁴)² = (15/16)².
  EXPECT_EQ(shading::distance_attenuation(2.0f, 4.0f), 0.25f * (15.0f / 16.0f) * (15.0f / 16.0f));
  EXPECT_EQ(shading::distance_attenuation(4.0f, 4.0f), 0.0f);
  EXPECT_EQ(shading::distance_attenuation(5.0f, 4.0f), 0.0f);
  EXPECT_EQ(shading::distance_attenuation(0.0f, 0.0f), 1e4f);  // capped at 1 cm
}

TEST(Lighting, SpotConeIsGltfsSquaredFalloff) {
  const float inner = 0.3f, outer = 0.5f;
  EXPECT_EQ(shading::spot_attenuation(std::cos(0.1f), inner, outer), 1.0f);
  EXPECT_EQ(shading::spot_attenuation(std::cos(0.6f), inner, outer), 0.0f);
  const float mid = 0.5f * (std::cos(inner) + std::cos(outer));  // halfway in cosine: t = ½, t² = ¼
  EXPECT_NEAR(shading::spot_attenuation(mid, inner, outer), 0.25f, 1e-6f);
}

// Units: a white Lambertian surface facing E lux has luminance E / π.
TEST(Lighting, LambertAndBlinnPhongInPhotometricUnits) {
  constexpr float kPi = 3.14159265358979f;
  Light sun;
  sun.type = LightType::directional;
  sun.direction = {0.0f, -1.0f, 0.0f};
  sun.color = {1.0f, 0.5f, 0.25f};
  sun.intensity = 2.0f;  // lux
  Material m;
  m.albedo = {0.5f, 0.5f, 0.5f};
  m.specular = 0.25f;
  m.shininess = 8.0f;
  const glm::vec3 n(0, 1, 0);
  const auto ls = shading::sample_light(sun, glm::vec3(0));
  EXPECT_EQ(ls.to_light, glm::vec3(0, 1, 0));
  EXPECT_EQ(ls.illuminance, glm::vec3(2.0f, 1.0f, 0.5f));
  // Viewed along the light: h = n, n·h = 1: specular = 0.25 · E / π.
  auto d = shading::direct_light(m, ls, n, glm::vec3(0, 1, 0));
  EXPECT_NEAR(d.diffuse.x, 0.5f * 2.0f / kPi, 1e-6f);
  EXPECT_NEAR(d.diffuse.z, 0.5f * 0.5f / kPi, 1e-6f);
  EXPECT_NEAR(d.specular.x, 0.25f * 2.0f / kPi, 1e-6f);
  // Light at 60° from the normal: Lambert halves.
  Light tilted = sun;
  tilted.direction = glm::normalize(glm::vec3(-std::sqrt(3.0f), -1.0f, 0.0f));
  d = shading::direct_light(m, shading::sample_light(tilted, glm::vec3(0)), n, glm::vec3(0, 1, 0));
  EXPECT_NEAR(d.diffuse.x, 0.5f / kPi, 1e-6f);
  // n·h for h halfway between l (60° off) and v (along n): cos 30°; specular 0.25 · 2 · cos(30°)⁸ / π.
  EXPECT_NEAR(d.specular.x, 0.25f * 2.0f * std::pow(std::cos(0.5236f), 8.0f) / kPi, 1e-4f);
  // Light from behind: nothing.
  Light under = sun;
  under.direction = {0.0f, 1.0f, 0.0f};
  d = shading::direct_light(m, shading::sample_light(under, glm::vec3(0)), n, glm::vec3(0, 1, 0));
  EXPECT_EQ(d.diffuse, glm::vec3(0));
  EXPECT_EQ(d.specular, glm::vec3(0));
}

TEST(Lighting, SpotInCandelaAndShadowScaleOnlyTheDirectLight) {
  constexpr float kPi = 3.14159265358979f;
  Light spot;
  spot.type = LightType::spot;
  spot.position = {0.0f, 2.0f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.color = glm::vec3(1.0f);
  spot.intensity = 4.0f;  // candela
  spot.inner_angle = 0.4f;
  spot.outer_angle = 0.5f;
  spot.ambient = 0.5f;  // lux, the same everywhere
  Material m;
  m.albedo = glm::vec3(1.0f);
  m.ambient = 0.1f;
  m.specular = 0.0f;
  const glm::vec3 n(0, 1, 0), eye(0, 2, 0);
  // Straight below at 2 m: 4 cd / (2 m)² = 1 lux; luminance (1 + ½) / π lit, ½ / π in shadow (a spot's ambient
  // is its own Light::ambient, not Material::ambient of anything).
  const glm::vec3 lit = shading::shade(m, spot, glm::vec3(0), n, eye, 1.0f);
  EXPECT_NEAR(lit.x, 1.5f / kPi, 1e-6f);
  EXPECT_NEAR(shading::shade(m, spot, glm::vec3(0), n, eye, 0.0f).x, 0.5f / kPi, 1e-6f);
  // Outside the cone (45° off axis, 2√2 m away) and far off: no direct light, the same ambient.
  EXPECT_NEAR(shading::shade(m, spot, glm::vec3(2.0f, 0.0f, 0.0f), n, eye, 1.0f).x, 0.5f / kPi, 1e-6f);
  EXPECT_NEAR(shading::shade(m, spot, glm::vec3(20.0f, -9.0f, 0.0f), n, eye, 1.0f).x, 0.5f / kPi, 1e-6f);
  // A directional light's ambient is Material::ambient of its illuminance: 0.1 of 3 lux.
  Light sun;
  sun.type = LightType::directional;
  sun.direction = {0.0f, -1.0f, 0.0f};
  sun.intensity = 3.0f;
  sun.ambient = 100.0f;  // unused by directional lights
  EXPECT_NEAR(shading::shade(m, sun, glm::vec3(0), n, eye, 0.0f).x, 0.3f / kPi, 1e-6f);
  EXPECT_NEAR(shading::shade(m, sun, glm::vec3(0), n, eye, 1.0f).x, 3.3f / kPi, 1e-6f);
}

}  // namespace
