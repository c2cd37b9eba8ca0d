// The randomness of the OpenGL tutorial's stratified Poisson sampling (seed 001, tutorial16's fragment shader),
// to the letter: random(seed, i) = fract(sin(dot(vec4(seed, i), vec4(12.9898, 78.233, 45.164, 94.673))) *
// 43758.5453), computed in float as GLSL computes it, and the disc index int(16.0 * random(seed, i)) % 16. The
// seed is gl_FragCoord.xyy or the world position floored to the millimetre. Pure float operations in a fixed
// order (the build has -ffp-contract=off), so a value depends only on its seed, never on a thread or a lane.
#pragma once
#include <cmath>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// GLSL's fract: x - floor(x). In float it can round up to 1.0 (x a tiny negative number), which is why the
// tutorial takes its index modulo 16.
inline float glsl_fract(float x) { return x - std::floor(x); }

// The tutorial's random(seed, i), in [0, 1]. dot() is summed left to right, each product and sum rounded to
// float, as GLSL's definition of dot writes it; sin is the C library's float sine.
inline float tutorial_random(glm::vec3 seed, int i) {
  const float d = ((seed.x * 12.9898f + seed.y * 78.233f) + seed.z * 45.164f) + float(i) * 94.673f;
  return glsl_fract(std::sin(d) * 43758.5453f);
}

// The stratified disc index of tap i: int(16.0 * random(seed, i)) % 16, in [0, 16).
inline int tutorial_index(glm::vec3 seed, int i) { return int(16.0f * tutorial_random(seed, i)) % 16; }

// The seeds the tutorial offers: gl_FragCoord.xyy (the pixel centre; the pattern moves with the camera), or
// floor(Position_worldspace * 1000.0) (the world position to the millimetre; the pattern stays on the surface).
inline glm::vec3 tutorial_pixel_seed(glm::vec2 frag_xy) { return {frag_xy.x, frag_xy.y, frag_xy.y}; }
inline glm::vec3 tutorial_world_seed(glm::vec3 p) {
  return {std::floor(p.x * 1000.0f), std::floor(p.y * 1000.0f), std::floor(p.z * 1000.0f)};
}

// The tutorial describes no rotated variant; shadowlab's `tutorial` rotated filter turns the disc by the angle
// 2π · random(seed, 0), as (cos, sin).
inline glm::vec2 tutorial_rotation(glm::vec3 seed) {
  const float a = 6.28318530718f * tutorial_random(seed, 0);
  return {std::cos(a), std::sin(a)};
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
