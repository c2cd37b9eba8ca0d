// The world-space casters a technique draws into its maps: the opaque triangles in one list for the depth-only
// path, and the alpha-masked ones per material with their texture coordinates and alpha test
// (shading/surface_texture.h), drawn by a depth pass that discards (masked_depth.h). Plain data; the frame
// (scenes/frame) owns what the spans point at for the whole frame.
#pragma once
#include <cstdint>
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shading/surface_texture.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

struct MaskedVertex {
  glm::vec3 position;  // world
  glm::vec2 st;        // texture coordinates, before SurfaceTexture::transform
};

// The masked triangles of one material.
struct MaskedCasters {
  std::span<const MaskedVertex> vertices;
  std::span<const uint32_t> indices;
  const SurfaceTexture* alpha = nullptr;  // the material's base colour and cutoff
};

struct CasterGeometry {
  std::span<const glm::vec3> positions;  // opaque triangles
  std::span<const uint32_t> indices;
  std::span<const MaskedCasters> masked;
};

SHADOWLAB_ISA_END
}  // namespace shading::tech
