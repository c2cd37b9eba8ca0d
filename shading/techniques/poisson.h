// The Poisson disc of the tutorial (its 16 points; the first 4 are its 4-tap disc) and the per-pixel
// randomness of stratified and rotated sampling: integer hashes of the pixel or of the world position rounded
// to 1 mm, so a result depends on where it is computed, never on which thread computed it.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

inline constexpr std::array<glm::vec2, 16> kPoissonDisk = {{
    {-0.94201624f, -0.39906216f}, {0.94558609f, -0.76890725f}, {-0.094184101f, -0.92938870f},
    {0.34495938f, 0.29387760f},   {-0.91588581f, 0.45771432f}, {-0.81544232f, -0.87912464f},
    {-0.38277543f, 0.27676845f},  {0.97484398f, 0.75648379f},  {0.44323325f, -0.97511554f},
    {0.53742981f, -0.47373420f},  {-0.26496911f, -0.41893023f}, {0.79197514f, 0.19090188f},
    {-0.24188840f, 0.99706507f},  {-0.81409955f, 0.91437590f}, {0.19984126f, 0.78641367f},
    {0.14383161f, -0.14100790f},
}};

// The four points of the disc farthest from its centre, one per quadrant: early bailing's outer taps.
inline constexpr std::array<int, 4> kOuterTaps = {7, 1, 13, 5};

// A 32-bit integer mixer (xor-shift and odd multipliers): every input bit affects every output bit.
constexpr uint32_t mix32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// A seed per pixel (window position) or per world point rounded to the millimetre.
inline uint32_t pixel_seed(glm::vec2 frag_xy) {
  const uint32_t x = uint32_t(int32_t(std::floor(frag_xy.x))), y = uint32_t(int32_t(std::floor(frag_xy.y)));
  return mix32(x * 0x9E3779B1U ^ mix32(y + 0x632BE5ABU));
}
inline uint32_t world_seed(glm::vec3 p) {
  const auto mm = [](float v) { return uint32_t(int32_t(std::floor(v * 1000.0f))); };
  return mix32(mm(p.x) ^ mix32(mm(p.y) ^ mix32(mm(p.z) + 0x85EBCA77U)));
}

// Stratified sampling: the disc index of tap i, in [0, 16).
inline int stratified_index(uint32_t seed, int i) { return int(mix32(seed + uint32_t(i) * 0x27D4EB2FU) >> 28); }

// Rotated sampling: one rotation per pixel, as (cos, sin).
inline glm::vec2 rotation_of(uint32_t seed) {
  const float a = float(seed >> 8) * (6.28318530718f / 16777216.0f);
  return {std::cos(a), std::sin(a)};
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
