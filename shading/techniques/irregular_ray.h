// The irregular z-buffer's exact test (irregular.h): does one caster triangle block the shadow ray of one camera
// sample? The ray leaves the sample's origin (its surface point moved ε along the geometric normal, as the
// ray-cast reference does) towards the light; the triangle blocks it when the ray passes inside or on its three
// edges (the sample lies in the triangle's shadow volume) and meets its plane strictly in front of the origin and
// before the light. Computed in double precision on the float inputs, in the Plücker form of the test (three
// signed volumes of the ray with the edges), which decides a ray through an edge or a vertex the same way for
// both triangles that share it.
#pragma once
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// One shadow ray: origin + t · dir for 0 < t < t_max. Directional light: dir the unit vector towards the light,
// t_max infinite. Spot light: dir = light position − origin, t_max = 1 − 10⁻⁵ (the reference stops that short of
// the light, whose own position is no occluder).
struct ShadowRay {
  glm::dvec3 origin{0.0}, dir{0.0, 1.0, 0.0};
  double t_max = 0.0;
};

// The edge rule: the triangle is closed. A ray through an edge or a vertex is blocked (Embree's watertight test,
// which the reference uses, counts those hits too); a ray in the triangle's plane is not (no volume: all three
// signed volumes are zero). Triangles block from both sides.
// With `bary`, a blocking hit's barycentric coordinates (of a, b, c) are written there, for a masked triangle's
// alpha test.
inline bool blocks(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const ShadowRay& r,
                   glm::dvec3* bary = nullptr) {
  const glm::dvec3 A = a - r.origin, B = b - r.origin, C = c - r.origin;
  const double wab = glm::dot(r.dir, glm::cross(A, B));
  const double wbc = glm::dot(r.dir, glm::cross(B, C));
  const double wca = glm::dot(r.dir, glm::cross(C, A));
  const bool inside = (wab >= 0.0 && wbc >= 0.0 && wca >= 0.0) || (wab <= 0.0 && wbc <= 0.0 && wca <= 0.0);
  const double den = wab + wbc + wca;  // dot(dir, the triangle's unnormalised normal)
  if (!inside || den == 0.0) return false;
  // The plane is met at t = det(A, B, C) / den.
  const double t = glm::dot(A, glm::cross(B, C)) / den;
  if (!(t > 0.0 && t < r.t_max)) return false;
  // Each corner's weight is the volume of the ray with the opposite edge.
  if (bary) *bary = glm::dvec3(wbc, wca, wab) / den;
  return true;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
