// The irregular z-buffer's per-cube-face pass for point lights (see irregular_cube.h).
#include "shading/techniques/irregular_cube.h"

#include <algorithm>

#include "shading/cube_face.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

IrregularLight irregular_cube_face(const glm::vec3& position, int face) {
  const CubeFaceAxes& a = kCubeFaceAxes[face];
  IrregularLight l;
  l.spot = true;  // a central projection from the light, as a spot's
  l.position = glm::dvec3(position);
  l.axis = glm::dvec3(a.major), l.right = glm::dvec3(a.s_axis), l.up = glm::dvec3(a.t_axis);
  return l;
}

int irregular_cube_face_of(const glm::vec3& position, const glm::vec3& origin) {
  return cube_face_of(origin - position);
}

std::vector<uint8_t> irregular_cube_shadow(const glm::vec3& position, std::span<const glm::vec3> origins,
                                           const CasterGeometry& casters, const GridSettings& settings,
                                           raster::ThreadPool& pool, GridStats& stats) {
  stats = GridStats{};
  std::vector<uint8_t> result(origins.size(), 0);
  // Each face's samples in sample order: the faces' answers land back where their samples came from.
  std::vector<uint32_t> face_of(origins.size());
  for (size_t i = 0; i < origins.size(); ++i) face_of[i] = uint32_t(irregular_cube_face_of(position, origins[i]));
  for (int face = 0; face < 6; ++face) {
    std::vector<glm::vec3> mine;
    std::vector<uint32_t> index;
    for (size_t i = 0; i < origins.size(); ++i)
      if (face_of[i] == uint32_t(face)) mine.push_back(origins[i]), index.push_back(uint32_t(i));
    if (mine.empty()) continue;
    GridStats st;
    const std::vector<uint8_t> shadowed =
        irregular_shadow(irregular_cube_face(position, face), mine, casters, settings, pool, st);
    add_grid_stats(stats, st);
    for (size_t k = 0; k < mine.size(); ++k) result[index[k]] = shadowed[k];
  }
  return result;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
