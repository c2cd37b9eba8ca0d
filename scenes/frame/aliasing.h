// The aliasing measure of a frame, per light: at every covered pixel that faces the light, how many screen
// pixels one shadow-map texel spans along its worse axis, 1 / σ_min(J), where J is the 2×2 Jacobian of the
// map's texel coordinates over window x and y, taken from the 2×2 quad's differences (fine derivatives, in the
// map the pixel itself reads: LightShadow::texel_coords). Above 1 a texel covers several pixels (stair-steps);
// at or below 1 the map resolves the pixel. Measured in a second pass over the camera pass's depth buffer
// (depth test EQUAL, no depth writes), so only the visible surface is measured, the same at any thread count.
// Summaries: max, 95th percentile and mean; the storage factor p95² is how much more map memory the
// technique would need for its 95th percentile to reach one texel per pixel.
#pragma once
#include <string>
#include <vector>

#include "raster/renderer.h"
#include "raster/target.h"
#include "scenes/frame/camera_shader.h"
#include "scenes/scene.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

// One light's measure over the frame: `ratio` per pixel (row-major, row 0 at the bottom); kUnmeasured where
// the pixel faces away from the light or the technique has no measure there, kEmpty where nothing is drawn.
inline constexpr float kUnmeasured = -1.0f, kEmpty = -2.0f;
// The largest ratio recorded: a surface that contains the light direction (lit only through its interpolated
// normal) has texels of infinite length on screen; it reads as this cap, so means stay meaningful.
inline constexpr float kRatioCap = 1000.0f;
struct AliasingImage {
  int width = 0, height = 0;
  std::vector<float> ratio;
  size_t measured = 0;               // pixels with a ratio
  float max = 0, p95 = 0, mean = 0;  // over the measured pixels
  float storage_factor() const { return p95 * p95; }
};

// Measures every light of `records` that has a LightShadow (others get an empty image, measured = 0).
// `camera_depth` is the camera pass's depth buffer: tested (EQUAL), never written.
// `mesh_vertices` are the camera pass's vertices per mesh (index as Scene::meshes).
std::vector<AliasingImage> measure_aliasing(const scenes::Scene& scene, const glm::mat4& view_proj,
                                            std::span<const LightRecord> records,
                                            std::span<const std::vector<CameraVertex>> mesh_vertices,
                                            raster::DepthTarget& camera_depth, raster::Renderer& renderer);

// The false-colour heat map of an image: log2 of the ratio from blue (1/4 and below) through green (1) and
// yellow (2) to red (8 and above); dark grey where nothing was measured, black where the frame is empty.
raster::ColorTarget aliasing_heat_map(const AliasingImage& image);

SHADOWLAB_ISA_END
}  // namespace frame
