// A lower-detail caster for a small projective map (the article's third enhancement): vertex clustering on a
// world-space grid whose cell is a fraction of one map texel. Vertices in one cell merge into their mean;
// triangles that collapse are dropped. Detail finer than a texel cannot show in the map, so the silhouette
// moves by less than a texel while the triangle count drops to what the map's resolution can show.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

struct DecimatedMesh {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
};

// Clusters `positions` (world space) on a grid of `cell` units. cell <= 0 (or not finite) returns the input.
// Deterministic: clusters are numbered in order of first use, each merged position is the mean of its members
// summed in vertex order.
DecimatedMesh cluster_vertices(std::span<const glm::vec3> positions, std::span<const uint32_t> indices, float cell);

SHADOWLAB_ISA_END
}  // namespace shading::tech
