// The irregular z-buffer for a point light (irregular.h), per cube face: each sample goes to the face of a cube
// around the light that its light-to-sample direction selects (GL's major-axis rule, shading/cube_face.h, as the
// cube map technique reads it), and each face runs the light-space pass (irregular_grid.h) with its own 90°
// central projection: a grid over its own samples, the casters clipped in front of the face's plane and
// rasterized over that grid.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/thread_pool.h"
#include "shading/techniques/irregular_grid.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// The light as face `face`'s grid sees it (GL's face order, CubeFace): the central projection from `position`
// along the face's major axis, with its s and t axes across.
IrregularLight irregular_cube_face(const glm::vec3& position, int face);

// The face each ray origin's direction from the light selects.
int irregular_cube_face_of(const glm::vec3& position, const glm::vec3& origin);

// For each ray origin, whether some caster blocks its segment to the point light at `position`: 1 shadowed,
// 0 lit, in the order of `origins`. Statistics are summed over the faces (the grid's sides: the largest face's).
std::vector<uint8_t> irregular_cube_shadow(const glm::vec3& position, std::span<const glm::vec3> origins,
                                           const CasterGeometry& casters, const GridSettings& settings,
                                           raster::ThreadPool& pool, GridStats& stats);

SHADOWLAB_ISA_END
}  // namespace shading::tech
