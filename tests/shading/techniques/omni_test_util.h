// Helpers for the omnidirectional technique tests: a map of one technique planned, built and wrapped in a
// reader in one call (the set heap-held so the reader's views stay valid), and a small billboard caster.
#pragma once
#include <memory>

#include <glm/geometric.hpp>

#include "shading/techniques/omni_read.h"
#include "tests/shading/techniques/technique_test_util.h"

namespace omnitest {

namespace tech = shading::tech;

struct BuiltOmni {
  std::unique_ptr<tech::ShadowMapSet> set;
  tech::OmniReader reader;
};

inline BuiltOmni build_omni(raster::Renderer& r, tech::OmniKind kind, const techtest::Soup& soup,
                            const tech::OmniLight& light, const tech::OmniSettings& s) {
  BuiltOmni b;
  b.set = std::make_unique<tech::ShadowMapSet>();
  switch (kind) {
    case tech::OmniKind::cube:
      *b.set = tech::plan_cube_map(light, s);
      tech::build_cube_map(r, *b.set, light, s, tech::CasterGeometry{soup.positions, soup.indices, {}});
      b.reader = tech::make_cube_reader(*b.set, light, s);
      break;
    case tech::OmniKind::paraboloid:
      *b.set = tech::plan_paraboloid_map(light, s);
      tech::build_paraboloid_map(r, *b.set, light, s, tech::CasterGeometry{soup.positions, soup.indices, {}});
      b.reader = tech::make_paraboloid_reader(*b.set, light, s);
      break;
    case tech::OmniKind::pyramid:
      *b.set = tech::plan_pyramid_map(light, s);
      tech::build_pyramid_map(r, *b.set, light, s, tech::CasterGeometry{soup.positions, soup.indices, {}});
      b.reader = tech::make_pyramid_reader(*b.set, light, s);
      break;
  }
  return b;
}

// A small square facing the light at `center` (half-size `h`), double-sided for the depth pass (no culling).
inline void billboard(techtest::Soup& soup, glm::vec3 light, glm::vec3 center, float h) {
  const glm::vec3 n = glm::normalize(center - light);
  const glm::vec3 ref = std::fabs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(n, ref)) * h, v = glm::normalize(glm::cross(n, u)) * h;
  soup.quad(center - u - v, center + u - v, center + u + v, center - u + v);
}

// Visibility of one point with normal n through the reader's own filter; without n the normal faces the
// light (so a slope bias is 0).
inline float hard_visibility(const tech::OmniReader& r, glm::vec3 p, glm::vec3 n) {
  const tech::ShadowQuery q{p, n, glm::vec2(0.0f)};
  float v = -1.0f;
  tech::omni_visibility(r, std::span(&q, 1), std::span(&v, 1));
  return v;
}
inline float hard_visibility(const tech::OmniReader& r, glm::vec3 p) {
  return hard_visibility(r, p, glm::normalize(r.position - p));
}

}  // namespace omnitest
