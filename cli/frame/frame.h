// Rendering a whole scene frame: every light's shadow maps (through the technique layer in shading/techniques),
// then the camera pass with Blinn-Phong shading that reads them. The one entry point `shadowlab render`, the
// golden-image tests and the frame benchmarks share.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "cli/frame/frame_projective.h"
#include "raster/renderer.h"
#include "raster/target.h"
#include "scenes/io/exr_map.h"
#include "scenes/scene.h"

namespace frame {

// Overrides from the command line; unset fields keep what each light's ShadowSettings say.
struct FrameOptions {
  int width = 1280, height = 720;
  std::optional<std::string> technique;  // e.g. "shadowmap"
  std::optional<std::string> filter;     // hard | pcf | poisson | stratified | rotated | early-bail
  std::optional<std::string> bias;       // none | constant | slope | offset | normal
  std::optional<int> shadow_size;        // map side in texels
  size_t camera = 0;                     // index into Scene::cameras
  std::optional<bool> cull_front;        // back faces only into the map
  std::optional<int> poisson_taps;       // 4 or 16
  std::optional<bool> pcf_taps;          // Poisson taps are hardware 2×2 PCF lookups
  std::optional<float> poisson_spread;   // Poisson disc radius in map texture coordinates (> 0)
  std::optional<std::string> stratify;   // stratified seed: "pixel" or "world" (world position rounded to 1 mm)
  std::optional<std::string> fit;        // directional light box: "auto" (fitted) or "fixed" (the tutorial's box)
  // Bias values (the mode is `bias`); each must be finite and >= 0 (offset factor/units: finite).
  std::optional<float> bias_constant, bias_slope, bias_slope_max, offset_factor, offset_units, normal_offset;
  // Omnidirectional techniques (frame_omni.h): cube seamless filtering, the paraboloid's depth packing
  // ("float" | "rgba8") and split plane ("light", "x", "-y", ... or a normal "a,b,c").
  std::optional<bool> seamless;
  std::optional<std::string> paraboloid_pack, split_plane;
  std::optional<std::string> projective_mode;  // projective lights: multipass | single-pass
  std::optional<int> projective_textures;      // projective single-pass: shadow textures per draw (1..8)
  bool export_maps = true;                     // projective: one EXR record per caster in Frame::maps
  glm::vec4 clear_color{0.0f, 0.0f, 0.4f, 1.0f};  // the tutorial's glClearColor (alpha 1)
  bool quad_fragments = false;  // camera pass on the quad path only (fragment()), for tests of the wide path
};

struct FrameStats {
  double shadow_ms = 0, camera_ms = 0;  // wall time of the map passes and of the camera pass
  size_t maps_rendered = 0;
  raster::DrawStats draws;
  ProjectiveStats projective;           // per-caster projective maps: cache use, draws per instance
};

struct Frame {
  raster::ColorTarget color;                  // linear RGBA8 (PNG writing encodes to sRGB)
  std::vector<scenes::io::ExrMap> maps;       // every shadow map of every light, ready for write_exr_map
  std::vector<std::string> map_names;         // file stem per map, e.g. "light0-sun" or "light1-spot"
  FrameStats stats;
  std::vector<std::string> notes;             // e.g. lights drawn unshadowed because their technique is not built
};

// Throws std::invalid_argument with a message naming the option when an override is unknown or out of range.
// `cache` (optional) keeps per-caster projective maps across frames: only those whose light or caster
// changed are rebuilt. Without it every map is built for this frame alone.
Frame render_frame(const scenes::Scene& scene, const FrameOptions& options, raster::Renderer& renderer,
                   FrameCache* cache = nullptr);

}  // namespace frame
