// The frame side of per-caster projective shadows (the registry's receiver_passes technique): for every light
// whose technique is `projective`, one map per
// caster (a top-level scene object with shadow-casting instances) taken from the cache or rebuilt, each
// receiver instance's list of overlapping casters (its box against every caster's frustum), and the maps as
// EXR. The camera pass then draws receivers through draw_receiver (projective_shaders.h).
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "raster/renderer.h"
#include "scenes/io/exr_map.h"
#include "scenes/scene.h"
#include "shading/techniques/projective_cache.h"
#include "shading/techniques/projective_lookup.h"
#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

// What the projective technique did in one frame.
struct ProjectiveStats {
  bool active = false;                     // some light uses the projective technique
  size_t maps_rebuilt = 0, maps_reused = 0;
  size_t maps_skipped = 0;                 // casters whose shadow cannot reach the view (caster_reach)
  size_t shadow_passes = 0;                // multiply passes drawn (multipass, or single-pass overflow)
  std::vector<uint32_t> receiver_draws;    // per scene instance: draw calls of the camera pass
};

// State that lives across frames of one scene sequence: the projective maps and their keys, and per light the
// box a fit that smooths over time (fit = tutorial) chose in the previous frame.
struct FrameCache {
  shading::tech::ProjectiveCache projective;
  std::map<size_t, shading::tech::FitMemory> fits;  // by light index
  // The camera pass's targets, reused by the next frame of the same size instead of allocated again (fresh pages
  // are zeroed by the kernel, which cost as much as the shading at 1280×720): its depth buffer, and the radiance
  // and picture of a frame handed back with recycle() (frame.h).
  std::optional<raster::DepthTarget> camera_depth;
  std::optional<raster::ColorTarget> radiance, picture;
};

// One caster's map as the camera pass applies it.
struct AppliedCaster {
  std::shared_ptr<const shading::tech::CasterMap> map;  // keeps the reader's texture alive
  shading::tech::ProjectiveReader reader;
  size_t light = 0;
  uint32_t object = 0;
};

// A caster overlapping a receiver, and the window rectangle its shadow on that receiver can reach (the
// receiver's box and the caster's frustum cut at the box's far side, both projected): multiply passes are
// scissored to it, since outside it the map reads white and multiplies by exactly 1.
struct Overlap {
  uint32_t caster = 0;  // index into ProjectiveFrame::casters
  raster::Rect scissor;
};

// The camera the frame is seen through, for the overlaps' window rectangles.
struct ProjectiveView {
  glm::mat4 view_proj{1.0f};
  int width = 1, height = 1;
};

struct ProjectiveFrame {
  std::vector<AppliedCaster> casters;
  std::vector<std::vector<Overlap>> overlaps;  // per scene instance, in caster order
  shading::tech::ProjectiveMode mode = shading::tech::ProjectiveMode::multipass;
  int max_textures = 4;
  ProjectiveStats stats;
  std::vector<scenes::io::ExrMap> maps;  // one per caster (when export_maps)
  std::vector<std::string> map_names;
};

// The upper bound of single-pass textures per draw (the shader's fixed array of samplers).
inline constexpr int kMaxProjectiveTextures = 8;

// A light's projective settings from its merged configuration (map_size, and the parameters projective_mode,
// max_textures, caster_shade, lod_bias, blur_passes, blur_offset, fade_start, fade_end, fade_lookup,
// fade_table, decimate, caster_reach). Throws FrameError naming the parameter.
shading::tech::ProjectiveSettings resolve_projective(const shading::tech::ShadowConfig& config);

// The projective lights of a frame: their index in the scene and merged configuration.
struct ProjectiveLight {
  size_t index = 0;
  shading::tech::ShadowConfig config;
};

// Builds or reuses every projective light's caster maps (cache.begin_frame() … end_frame() inside) and the
// overlap lists; the maps become EXR records when `export_maps`. No projective light: empty lists (every
// instance drawn once). `surfaces` (per material, scenes/io/scene_textures.h): masked casters are drawn with
// their alpha test, invisible ones left out; empty: every caster opaque.
ProjectiveFrame prepare_projective(const scenes::Scene& scene, std::span<const ProjectiveLight> lights,
                                   bool export_maps, const ProjectiveView& view, raster::Renderer& renderer,
                                   shading::tech::ProjectiveCache& cache,
                                   std::span<const shading::SurfaceTexture> surfaces = {});

// The window rectangle (whole pixels, clamped to the viewport) holding every point of `box` that lies in the
// frustum; the whole viewport when a corner is behind the camera; empty (width 0) when there is none.
raster::Rect shadow_scissor(const shading::tech::CasterFrustum& f, const shading::tech::Box& box,
                            const ProjectiveView& view);

SHADOWLAB_ISA_END
}  // namespace frame
