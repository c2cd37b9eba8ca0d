// Temporal stability: how many pixels change between shadowed and lit when the view or the light moves a little,
// where the exact shadow does not change. Two frames are rendered and ray-cast: the configuration as given, and
// the same scene with the camera slid sideways by a fraction of a pixel, or with the light turned by a small angle
// (directional and spot: the direction about a perpendicular axis; point and hemispherical: the position and
// direction about the x axis through the scene's centre). A pixel shimmers when it is lit-facing in both frames, the
// technique's verdict (S < 0.5) differs between them and the exact one does not.
#pragma once
#include <vector>

#include "raster/renderer.h"
#include "scenes/frame/frame.h"
#include "scenes/reference/exact_visibility.h"
#include "scenes/reference/shadow_score.h"
#include "scenes/scene.h"
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

struct Motion {
  float camera_pixels = 0.0f;  // sideways, in pixels at the camera's target
  float light_degrees = 0.0f;
};

// The scene moved by `motion` (camera `camera`, every light).
scenes::Scene moved(const scenes::Scene& scene, size_t camera, int frame_height, const Motion& motion);

struct LightShimmer {
  size_t compared = 0;       // lit-facing in both frames
  size_t flips = 0;          // the technique's verdict changed
  size_t exact_flips = 0;    // the exact verdict changed (the geometry really moved under the pixel)
  size_t shimmering = 0;     // the technique's changed and the exact one did not
  double percent() const { return compared ? 100.0 * double(shimmering) / double(compared) : 0.0; }
};

// Compares two scored frames of the same configuration light by light, each with its own reference.
std::vector<LightShimmer> compare_frames(const frame::SurfaceRecord& first, const ExactVisibility& first_exact,
                                         const frame::SurfaceRecord& second, const ExactVisibility& second_exact,
                                         float shadow_below = 0.5f);

// Renders `config` on `scene` and on moved(scene), with their references, and compares them light by light.
std::vector<LightShimmer> shimmer(const scenes::Scene& scene, const frame::FrameConfig& config,
                                  raster::Renderer& renderer, const Motion& motion, const ScoreOptions& options = {});

SHADOWLAB_ISA_END
}  // namespace reference
