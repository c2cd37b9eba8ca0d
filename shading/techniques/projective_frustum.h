// Where a caster's projective map looks: a light-view frustum fitted tightly around the caster's world bounds
// (orthographic along a directional light, perspective from a spot or point light's position), widened so that
// a ring of texels at the map's edge stays outside the caster, its texgen matrix (bias × proj × view), and the
// box test that decides which receivers the caster can darken (the article's AABB-against-frusta test).
#pragma once
#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/techniques/light_frustum.h"
#include "shading/techniques/projective_types.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// n · p + d >= 0 on the inside.
struct FrustumPlane {
  glm::vec3 n{0.0f};
  float d = 0.0f;
};

struct CasterFrustum {
  bool valid = false;        // false: nothing to project (empty caster, or a light inside the caster's bounds)
  bool perspective = false;
  glm::mat4 view{1.0f}, proj{1.0f};
  glm::mat4 texgen{1.0f};    // world → (s, t, r, q): bias × proj × view
  glm::vec4 depth_row{0.0f}; // dot(depth_row, (p, 1)): distance of p in front of the projector along its axis
  float near_depth = 0.0f;   // that distance for the caster's point nearest the light
  float texel_world = 0.0f;  // size of one map texel at the caster's centre, in world units
  // left, right, bottom, top, near; no far plane: a shadow reaches any distance behind its caster.
  std::array<FrustumPlane, 5> planes{};
};

// The frustum of a caster with world bounds `caster` in a map of `map_size`² texels whose outer `ring` texels on
// every side are kept free: the caster's projected bounds map exactly onto the inner (map_size − 2·ring)²
// texels. When no inner texel is left the frustum is unwidened (the map stays all white).
CasterFrustum fit_caster_frustum(const ProjectiveLight& light, const Box& caster, int map_size, int ring);

// Whether any point of `box` can lie inside the frustum (conservative: a box outside one plane is out).
bool box_overlaps(const CasterFrustum& f, const Box& box);

SHADOWLAB_ISA_END
}  // namespace shading::tech
