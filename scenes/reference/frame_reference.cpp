// The reference frame and the scoring of one configuration against it (see frame_reference.h).
#include "scenes/reference/frame_reference.h"

#include <chrono>
#include <optional>
#include <vector>

#include "scenes/scene_queries.h"
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

FrameReference reference_for(const scenes::Scene& scene, frame::FrameConfig config, raster::Renderer& renderer,
                             float epsilon, const scenes::io::SceneTextures* textures) {
  std::optional<scenes::io::SceneTextures> own;
  if (!textures) textures = &own.emplace(scenes::io::load_scene_textures(scene));
  frame::FrameConfig off;
  off.width = config.width, off.height = config.height, off.camera = config.camera;
  off.exposure = config.exposure, off.tone_map = config.tone_map, off.background = config.background;
  off.technique = shading::tech::Technique::none;
  off.surface_record = true;
  off.export_maps = false;
  frame::Frame f = frame::render_frame(scene, off, renderer, nullptr, textures);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<shading::SurfaceTexture> surfaces = scenes::io::surface_textures(scene, *textures);
  const OcclusionScene occluders(scenes::flatten_by_coverage(scene, scenes::InstanceFilter::casters), surfaces);
  const double bvh_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  ExactVisibility exact = cast_shadow_rays(occluders, *f.surface, scene.lights,
                                           epsilon < 0.0f ? default_epsilon(scene) : epsilon, renderer.pool());
  return FrameReference{std::move(f), std::move(exact), occluders.triangles(), bvh_ms};
}

ScoredFrame score_config(const scenes::Scene& scene, frame::FrameConfig config, raster::Renderer& renderer,
                         const FrameReference& ref, const ScoreOptions& options,
                         const scenes::io::SceneTextures* textures) {
  config.surface_record = true;
  frame::Frame f = frame::render_frame(scene, config, renderer, nullptr, textures);
  if (f.surface->covered != ref.shadows_off.surface->covered)
    throw ReferenceError("reference: the frame covers other pixels than the reference (another size or camera)");
  const auto t0 = std::chrono::steady_clock::now();
  FrameScore s = score_frame(*f.surface, ref.exact, options);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return ScoredFrame{std::move(f), std::move(s), ms};
}

SHADOWLAB_ISA_END
}  // namespace reference
