// Per-light shadow settings as the scene model stores them: which technique builds the map, how it is filtered
// and biased, the map's size and depth format, and the technique's own parameters. The names, enums and
// defaults are the technique layer's vocabulary (shading/techniques/vocabulary.h), used here as they are.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "shading/techniques/vocabulary.h"

namespace scenes {

using shading::tech::LightType;
using ShadowTechnique = shading::tech::Technique;
using ShadowFilter = shading::tech::FilterKind;
using shading::tech::BiasMode;
using BiasSettings = shading::tech::BiasParams;
using raster::DepthFormat;
using shading::tech::NamedEntry;

// A technique parameter's value (see vocabulary.h's ParamSpec for the keys each technique takes).
using TechniqueParam = shading::tech::ParamValue;

struct ShadowSettings {
  ShadowTechnique technique = ShadowTechnique::shadowmap;
  ShadowFilter filter = ShadowFilter::pcf;
  BiasSettings bias;
  bool cull_front = false;                        // build the map from back faces (glCullFace(GL_FRONT))
  uint32_t map_size = 1024;                       // texels per side (per face / per caster)
  DepthFormat depth_format = DepthFormat::d16;
  uint32_t poisson_taps = 4;                      // 4 or 16
  float poisson_spread = 1.0f / 700.0f;           // disc radius in shadow-map texture coordinates
  std::map<std::string, TechniqueParam> params;   // technique-specific extras (vocabulary.h's ParamSpec keys)
  bool operator==(const ShadowSettings&) const = default;
};

using shading::tech::parse_bias_mode;
using shading::tech::parse_depth_format;
using shading::tech::parse_light_type;
using shading::tech::parse_technique;
using shading::tech::to_string;
inline std::optional<ShadowFilter> parse_filter(std::string_view s) { return shading::tech::parse_filter(s); }

// The vocabulary's name tables, as spans for messages such as "unknown filter 'x' (known: ...)".
std::span<const NamedEntry> light_type_names();
std::span<const NamedEntry> technique_names();
std::span<const NamedEntry> filter_names();
std::span<const NamedEntry> bias_mode_names();
std::span<const NamedEntry> depth_format_names();

// "a, b, c": the names of a table.
std::string join_names(std::span<const NamedEntry> table);

// Whether a technique can serve a light type (the vocabulary's table; unbuilt techniques included).
inline bool technique_supports(ShadowTechnique technique, LightType light) {
  return shading::tech::supports(technique, light);
}

using shading::tech::param_problem;

// Defaults for a light type: classic map for directional and spot, cube for point, pyramid for hemispherical;
// PCF, slope-scaled bias, and the technique's map size and depth format from the defaults table.
ShadowSettings default_shadow_settings(LightType light);

// The map side and depth format a technique uses when a scene does not give them (the defaults table's).
inline uint32_t default_map_size(ShadowTechnique technique) { return shading::tech::info(technique).map_size; }
inline DepthFormat default_depth_format(ShadowTechnique technique) {
  return shading::tech::info(technique).depth_format;
}

}  // namespace scenes
