// The scene model's view of the shadow vocabulary: name tables as spans and per-light-type defaults.
#include "scenes/shadow_settings.h"

#include <array>

namespace scenes {
namespace {

// The technique rows of the defaults table as name + description.
constexpr auto kTechniqueNames = [] {
  std::array<NamedEntry, std::size(shading::tech::kTechniques)> out{};
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = {shading::tech::kTechniques[i].name, shading::tech::kTechniques[i].description};
  return out;
}();

}  // namespace

std::span<const NamedEntry> light_type_names() { return shading::tech::kLightTypeNames; }
std::span<const NamedEntry> technique_names() { return kTechniqueNames; }
std::span<const NamedEntry> filter_names() { return shading::tech::kFilterNames; }
std::span<const NamedEntry> bias_mode_names() { return shading::tech::kBiasNames; }
std::span<const NamedEntry> depth_format_names() { return shading::tech::kDepthFormatNames; }

std::string join_names(std::span<const NamedEntry> table) {
  std::string out;
  for (const NamedEntry& e : table) {
    if (!out.empty()) out += ", ";
    out += e.name;
  }
  return out;
}

ShadowSettings default_shadow_settings(LightType light) {
  ShadowSettings s;
  switch (light) {
    case LightType::directional:
    case LightType::spot: s.technique = ShadowTechnique::shadowmap; break;
    case LightType::point: s.technique = ShadowTechnique::cube; break;
    case LightType::hemispherical: s.technique = ShadowTechnique::pyramid; break;
  }
  s.map_size = default_map_size(s.technique);
  s.depth_format = default_depth_format(s.technique);
  return s;
}

}  // namespace scenes
