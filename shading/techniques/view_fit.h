// Fitting a directional light's map to a body: the points of the view a map must cover (a frustum slice's
// corners or the camera's visible samples). Three fits: orthographic and tight, orthographic and stabilised
// (texel-snapped, camera-rotation invariant), and LiSPSM (Wimmer, Scherzer and Purgathofer 2004: a perspective
// warp along the view direction as the light sees it). Each also gives the world distance its depth range spans,
// which turns a depth bias in map units into a distance (slice_read.h), so one bias setting means the same on
// every map, warped or not.
#pragma once
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "shading/techniques/light_frustum.h"
#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

struct FittedMap {
  glm::mat4 view{1.0f}, proj{1.0f};
  bool perspective = false;   // read with textureProj (LiSPSM)
  float depth_extent = 1.0f;  // world distance along the light from depth 0 to depth 1 of an orthographic map
  float n_opt = 0.0f;         // LiSPSM: the projection centre's distance before the body; 0 for a uniform map
};

// Light view space with the origin at the world origin (so that texel snapping does not depend on the camera):
// the light travels along −z, `up` is y.
glm::mat4 light_view(glm::vec3 direction, glm::vec3 up);

// Orthographic and tight: x, y bound the body's points; depth runs from the nearest-to-light point of the
// casters' box or the body to the body's point farthest from the light.
FittedMap fit_ortho(glm::vec3 direction, std::span<const glm::vec3> body, const Box& casters);

// Orthographic and stabilised: a square of side 2·radius around `center`, its centre snapped to whole texels of
// a map_size² map in a light view fixed in the world; depth over `depth_box` (the whole scene, so it does not
// move with the camera).
FittedMap fit_stable(glm::vec3 direction, glm::vec3 center, float radius, int map_size, const Box& depth_box);

// LiSPSM: light view with y along the view direction projected perpendicular to the light; a perspective
// projection along y whose centre lies n_opt = (z_n + √(z_n·z_f)) / sin γ before the body (γ: the angle
// between the view and light directions); then x, y and depth cropped tight to the body and, towards the
// light, to the casters. When sin γ < kLispsmMinSin (the view looks along the light) the warp is undefined and
// the uniform fit_ortho is returned, as the method prescribes.
inline constexpr float kLispsmMinSin = 1e-3f;
FittedMap fit_lispsm(glm::vec3 direction, std::span<const glm::vec3> body, const Box& casters,
                     const CameraView& camera, float z_n, float z_f);

SHADOWLAB_ISA_END
}  // namespace shading::tech
