// Percentage-closer soft shadows (Fernando 2005) on a point light's cube map, for a spherical light of radius R
// (the cube's `soft_shadows = pcss`, `light_radius`). The cube stores radial distances, so the blocker search
// and the filter work in directions around the receiver's own: 16 taps of the Poisson disc (turned per pixel)
// laid on the unit sphere around it, each looked up by direction, so a kernel crosses face edges the way the
// cube's lookups do (seamless or clamped per face). Angles here are radians as seen from the light's centre.
//  - Search: the blockers that can hide part of the light from a receiver at distance d_r lie within the
//    light's disc seen from the receiver, R (d_r − z) / (d_r z) at distance z from the light; the search takes
//    z = max(near plane, d_r / 4), as the spot light's PCSS does (pcss.cpp).
//  - Penumbra: mean blocker distance d_b; the light's disc through the blocker's edge spreads over
//    R (d_r − d_b) / (d_r d_b) on either side (similar triangles, R (d_r − d_b) / d_b metres on the receiver);
//    never below one texel at the face's centre (2 / face size).
//  - Filter: 16 hardware 2×2 PCF lookups of the cube at the kernel's taps, each compared with the receiver's
//    own tangent plane where the tap's ray meets it (receiver-plane depth bias; the rise is held to 0.01 of the
//    range per texel at grazing angles), early exit when no blocker was found.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shading/techniques/omni.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

struct CubePcss {
  float radius = 0.1f;  // the light's radius, metres
  float near = 0.01f;   // the cube passes' near plane, metres
};

// The search region's angular radius for a receiver at distance d_r from the light.
float cube_pcss_search_angle(const CubePcss& c, float d_r);
// The filter kernel's angular radius for a receiver at distance d_r and a mean blocker distance d_b; never
// below texel_angle.
float cube_pcss_filter_angle(const CubePcss& c, float d_r, float d_b, float texel_angle);

// Visibility in [0, 1] of world point p with unit normal n, seen at window position frag (the disc's turn): 0
// behind a hemispherical light.
float cube_pcss_visibility(const OmniReader& r, const CubePcss& c, glm::vec3 p, glm::vec3 n, glm::vec2 frag);

SHADOWLAB_ISA_END
}  // namespace shading::tech
