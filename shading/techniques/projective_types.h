// The vocabulary of per-caster projective shadows (the 2000 article): the light as a projector, the settings
// a light's `params` choose, and how the maps are applied. Plain data; the frame renderer fills it once per
// frame from a scene light.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// A projector: orthographic along `direction` for a directional light, perspective from `position` for spot
// and point lights (a point light projects from its position towards each caster).
struct ProjectiveLight {
  bool directional = true;
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way light travels, unit length (directional)
  bool operator==(const ProjectiveLight&) const = default;
};

// multipass: each receiver is drawn, then drawn again once per overlapping caster with that caster's map
// multiplied in. single_pass: up to `max_textures` maps are applied in the receiver's one shaded draw.
enum class ProjectiveMode : uint8_t { multipass, single_pass };

// How the shadow fades with distance behind the caster: today's arithmetic ramp (formula), or the article's
// lookup of a 1-D texture of strengths (texture, fade_table.h).
enum class FadeLookup : uint8_t { formula, texture };

struct ProjectiveSettings {
  int map_size = 128;          // texels per side, per caster
  float caster_shade = 0.0f;   // what an opaque caster is drawn with (0: black); see caster_shade_for()
  float lod_bias = 0.0f;       // blur: mip levels added to the lookup's LOD (0: level 0 only, no mips built)
  int blur_passes = 0;         // blur: times the map is drawn onto itself at ±blur_offset texels (offset_blur.h)
  float blur_offset = 0.5f;    // ... in texels, (0, 1]
  float fade_start = 0.0f;     // distance behind the caster's near side where the shadow starts to fade ...
  float fade_end = 0.0f;       // ... and where it is gone; fade_end <= fade_start: no fade
  FadeLookup fade_lookup = FadeLookup::formula;
  std::vector<float> fade_table{1.0f, 0.0f};  // fade_lookup = texture: strengths from fade_start to fade_end
  bool decimate = true;        // draw the caster's map from a mesh clustered to the map's resolution
  float caster_reach = 0.0f;   // > 0: maps only for casters whose shadow volume, cut this far, meets the view
  ProjectiveMode mode = ProjectiveMode::multipass;
  int max_textures = 4;        // single-pass: shadow textures combined in one draw (more: extra passes)
  bool operator==(const ProjectiveSettings&) const = default;
};

// The grey a caster part is drawn with: `shade` for an opaque part (alpha 1), lighter the more transparent
// it is (alpha 0: white, no shadow): 1 − alpha · (1 − shade).
inline float caster_shade_for(float shade, float alpha) {
  const float a = alpha < 0.0f ? 0.0f : (alpha > 1.0f ? 1.0f : alpha);
  return 1.0f - a * (1.0f - shade);
}

constexpr std::string_view to_string(ProjectiveMode m) {
  return m == ProjectiveMode::multipass ? "multipass" : "single-pass";
}
constexpr std::optional<ProjectiveMode> parse_projective_mode(std::string_view s) {
  if (s == "multipass") return ProjectiveMode::multipass;
  if (s == "single-pass") return ProjectiveMode::single_pass;
  return std::nullopt;
}

constexpr std::string_view to_string(FadeLookup f) { return f == FadeLookup::formula ? "formula" : "texture"; }
constexpr std::optional<FadeLookup> parse_fade_lookup(std::string_view s) {
  if (s == "formula") return FadeLookup::formula;
  if (s == "texture") return FadeLookup::texture;
  return std::nullopt;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
