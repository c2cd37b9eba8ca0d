// The irregular z-buffer (Johnson, Mark and Burns 2004; Wyman, Hoetzlein and Lefohn 2015–2016) for directional,
// spot and point lights (point lights per cube face, irregular_cube.h): the hard shadow tested exactly at the
// points the camera shades, with no map and no bias.
// Build: the camera's visible surface (PlanInputs::surface, a camera pre-pass) gives each pixel's point and
// plane; each pixel gets samples_per_pixel shadow samples on its footprint; the light-space pass
// (irregular_grid.h) answers every sample; the answers become a per-pixel visibility buffer. Read: the buffer at
// the fragment's pixel. docs/irregular.md describes the rules and what it measures.
#pragma once
#include <memory>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/thread_pool.h"
#include "shading/techniques/irregular_grid.h"
#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

struct IrregularSettings {
  int samples_per_pixel = 1;  // 1, 8 or 32
  GridSettings grid;
  // At most this many samples are projected, sorted and tested at once (a band of rows, up to 8 samples of each
  // pixel; about 80 bytes a sample): 2^24 keeps the pass near 1.3 GiB for any frame size, and a 1920 x 1080
  // frame at 8 samples a pixel in one batch. Each sample's answer is exact, so it changes statistics only.
  size_t max_batch_samples = size_t(1) << 24;
};

// The sample positions within a pixel, in pixels from its centre: 1 (the centre), 8 (the standard 8× MSAA
// pattern) or 32 (a rank-1 lattice); empty for any other count.
std::span<const glm::vec2> pixel_sample_offsets(int samples_per_pixel);

// Where the camera ray through window point `frag` + `offset` meets the plane through p with normal n (the
// pixel's footprint on its surface); p where that ray runs parallel to the plane or meets it behind the camera.
// `inv_view_proj` is the inverse of the camera's projection · view, `size` the frame's width and height.
glm::vec3 footprint_point(const glm::dmat4& inv_view_proj, glm::vec2 size, glm::vec2 frag, glm::vec2 offset,
                          glm::vec3 p, glm::vec3 n);

// The shadow ray origin of a surface point for a light, as the ray-cast reference makes it (scenes/reference/
// exact_visibility.cpp, in the same float operations): false where the light does not reach the point (outside a
// spot's cone or range, or the plane faces away from the light: it shadows itself); else the point moved
// `epsilon` along n.
bool shadow_origin(const LightDesc& light, glm::vec3 p, glm::vec3 n, float epsilon, glm::vec3& origin);

// Visibility in [0, 1] of every pixel of `surface` (lit samples / samples_per_pixel; 1 where nothing is
// covered), and what the light-space pass did (summed over its sample batches).
struct IrregularBuffer {
  std::vector<float> visibility;
  GridStats stats;
};
IrregularBuffer irregular_visibility(const CameraSurface& surface, const LightDesc& light,
                                     const glm::mat4& camera_view_proj, const IrregularSettings& settings,
                                     const CasterGeometry& casters, raster::ThreadPool& pool);

// The registry's factory (technique.h). Throws TechniqueError for a samples_per_pixel other than 1, 8 or 32, or
// where the caller offers no camera surface.
std::unique_ptr<LightShadow> plan_irregular(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);

SHADOWLAB_ISA_END
}  // namespace shading::tech
