// A whole frame as a library call: every light's shadow through the technique registry
// (shading/techniques/technique.h), then the camera pass with Blinn-Phong shading that reads them, in float, then
// the picture developed from it with the scene's exposure, tone map and background (develop.h). The
// configuration is typed (the vocabulary's enums and numbers); map export to EXR is a separate step
// (export_maps). `shadowlab render`, the golden-image tests and the frame benchmarks all call render_frame.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/renderer.h"
#include "raster/target.h"
#include "scenes/frame/aliasing.h"
#include "scenes/frame/frame_projective.h"
#include "scenes/frame/surface_record.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/scene_textures.h"
#include "scenes/look.h"
#include "scenes/scene.h"
#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

namespace tech = shading::tech;

// A configuration a frame cannot be rendered with; what() starts with the field (`map_size: ...`,
// `lights[1].shadow.params.split_plane: ...`).
struct FrameError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// What to render. The shadow fields override every light's own settings where set.
struct FrameConfig {
  int width = 1280, height = 720;
  size_t camera = 0;  // index into Scene::cameras
  // How the frame is shown (scenes/look.h); unset: the scene's own.
  std::optional<scenes::Exposure> exposure;
  std::optional<shading::ToneMap> tone_map;
  std::optional<scenes::Background> background;

  std::optional<tech::Technique> technique;
  std::optional<tech::FilterKind> filter;
  std::optional<tech::BiasMode> bias;
  std::optional<int> map_size;                 // texels per side: 16..16384 (1..16384 for projective)
  std::optional<tech::DepthFormat> depth_format;
  std::optional<bool> cull_front;              // back faces only into the maps
  std::optional<int> poisson_taps;             // 4 or 16
  std::optional<float> poisson_spread;         // > 0
  // Bias values (the mode is `bias`): finite and >= 0; offset factor and units: finite.
  std::optional<float> bias_constant, bias_slope, bias_slope_max, offset_factor, offset_units, normal_offset;
  // Technique parameters (vocabulary.h's ParamSpec keys), for every light whose technique takes them; a key no
  // light's technique takes is an error.
  std::map<std::string, tech::ParamValue> params;

  bool aliasing = false;        // measure each light's aliasing (Frame::aliasing, scenes/frame/aliasing.h)
  bool export_maps = true;      // keep what export_maps needs (projective: the per-caster maps)
  bool quad_fragments = false;  // camera pass on the quad path only (fragment()), for tests of the wide path
  // Keep the camera pass's per-pixel record of the visible surface (Frame::surface, surface_record.h). Lights
  // applied as receiver passes (projective) record the product of the factors those passes multiplied in.
  bool surface_record = false;
};

struct FrameStats {
  double shadow_ms = 0, camera_ms = 0;  // wall time of the map passes and of the camera pass
  size_t maps_rendered = 0;
  raster::DrawStats draws;
  ProjectiveStats projective;           // per-caster projective maps: cache use, draws per instance
};

// One light's shadow in a frame: its technique's LightShadow (null for none and projective).
struct LightResult {
  std::string name;  // file stem of its maps, "light0-sun"
  tech::Technique technique = tech::Technique::none;
  std::unique_ptr<tech::LightShadow> shadow;
};

struct Frame {
  raster::ColorTarget color;        // the picture: sRGB RGBA8, developed from `radiance` (develop.h)
  raster::ColorTarget radiance;     // the camera pass: luminance in cd/m² (RGBA32F), alpha 1 where drawn
  float ev100 = 0.0f;               // the exposure the picture was developed with (given or metered)
  std::vector<LightResult> lights;  // per scene light
  ProjectiveFrame projective;       // the per-caster projective maps
  FrameStats stats;
  std::vector<AliasingImage> aliasing;  // per scene light, with FrameConfig::aliasing
  std::optional<SurfaceRecord> surface;  // with FrameConfig::surface_record
  glm::mat4 view_proj{1.0f};             // the camera's projection · view
  glm::vec3 eye{0.0f};                   // the camera's position
  // Settings that render but likely not as meant (frame_lights.h: moment_receiver_warning), for the caller to
  // show once.
  std::vector<std::string> warnings;
};

// Throws FrameError naming the field for a bad configuration or light setting. `cache` (optional) keeps
// per-caster projective maps across frames: only those whose light or caster changed are rebuilt. `textures`
// (optional): the scene's material textures, loaded once per scene (scenes/io/scene_textures.h) by a caller
// that renders several frames; without them the frame loads its own, and a missing or unreadable texture
// throws scenes::io::IoError naming the file and the material before anything is drawn.
Frame render_frame(const scenes::Scene& scene, const FrameConfig& config, raster::Renderer& renderer,
                   FrameCache* cache = nullptr, const scenes::io::SceneTextures* textures = nullptr);

// Hands a frame's radiance and picture to `cache` once the caller is done with it, for the next render_frame
// with that cache to reuse (see FrameCache); the rest of the frame is released.
void recycle(Frame&& frame, FrameCache& cache);

// A shadow map ready for write_exr_map, with its file stem ("light0-sun", "light2-lamp-caster1-box").
struct NamedMap {
  std::string name;
  scenes::io::ExrMap map;
};
// Every map of every light, in light order (the projective casters last).
std::vector<NamedMap> export_maps(const Frame& frame);

SHADOWLAB_ISA_END
}  // namespace frame
