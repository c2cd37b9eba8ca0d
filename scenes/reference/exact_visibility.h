// The exact hard shadow of a frame: for every covered pixel of the camera pass's surface record and every light,
// one occlusion ray from the pixel's surface point towards the light through the OcclusionScene. Directional
// lights: along −direction, unbounded; point, hemispherical and spot lights: to the light's position, inside the
// spot's outer cone (a hemispherical light's half-space) and the light's range. The origin is moved off the surface
// along the geometric normal (the side the camera sees) by `epsilon`, so the surface does not occlude itself; a
// point, spot or hemispherical light's ray then runs from that origin to the light itself (a directional light's
// keeps its direction). Rows are cast in parallel through
// raster::ThreadPool, each index writing only its own rows, so the result is the same at any thread count.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "raster/thread_pool.h"
#include "scenes/frame/surface_record.h"
#include "scenes/reference/occlusion_scene.h"
#include "scenes/scene.h"
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

struct ExactVisibility {
  int width = 0, height = 0;
  size_t lights = 0;
  // Per pixel and light (index pixel · lights + light). reached: covered, the geometric normal faces the light
  // and the point lies inside its cone and range. visible: reached and the ray met no triangle.
  std::vector<uint8_t> reached, visible;
  float epsilon = 0.0f;  // the origin offset used, in scene units
  size_t rays = 0;       // occlusion rays cast
  double ms = 0.0;       // wall time of the ray casting (the BVH build not included)
};

// The offset this project states: 1e-4 of the diagonal of the scene's bounds (2 mm on a 20 m scene).
float default_epsilon(const scenes::Scene& scene);

// `lights` in the order the record's light channels are (the scene's lights). Throws ReferenceError when the
// record and the light count disagree.
ExactVisibility cast_shadow_rays(const OcclusionScene& occluders, const frame::SurfaceRecord& record,
                                 std::span<const scenes::Light> lights, float epsilon, raster::ThreadPool& pool);

SHADOWLAB_ISA_END
}  // namespace reference
