// Name tables for the shadow-settings enums, the technique/light compatibility rule and per-light defaults.
// The tables are indexed by the enum value, so their order must follow the enum declarations.
#include "scenes/shadow_settings.h"

#include <array>

namespace scenes {
namespace {

constexpr std::array kLightTypes = {
    NamedEntry{"directional", "parallel rays from a direction (the sun)"},
    NamedEntry{"spot", "a cone from a position: direction, inner and outer half-angles, range"},
    NamedEntry{"point", "all directions from a position, up to a range"},
    NamedEntry{"hemispherical", "a point light shining into the half-space it faces (180°)"},
};

constexpr std::array kTechniques = {
    NamedEntry{"none", "the light casts no shadows"},
    NamedEntry{"shadowmap", "classic shadow map: orthographic for directional, perspective for spot lights"},
    NamedEntry{"cube", "cube shadow map: six 90° faces around a point light"},
    NamedEntry{"paraboloid", "dual-paraboloid shadow map (one paraboloid for a hemispherical light)"},
    NamedEntry{"pyramid", "pyramid shadow map: a 180° light in one square map split into four triangles"},
    NamedEntry{"projective", "per-caster projective shadow textures (black on white) cast onto receivers"},
    NamedEntry{"cascades", "cascaded shadow maps along the view frustum (reserved)"},
    NamedEntry{"lispsm", "light-space perspective shadow maps (reserved)"},
    NamedEntry{"frustum-faces", "perspective maps from the light-facing faces of the view frustum (reserved)"},
};

constexpr std::array kFilters = {
    NamedEntry{"hard", "one nearest-texel comparison"},
    NamedEntry{"pcf", "hardware PCF: four comparisons blended bilinearly"},
    NamedEntry{"poisson", "PCF at poisson_taps points of a Poisson disc"},
    NamedEntry{"stratified", "Poisson taps chosen per pixel from the 16-point disc"},
    NamedEntry{"rotated", "the Poisson disc rotated per pixel"},
    NamedEntry{"early-bail", "four distant taps first, all 16 only on shadow edges"},
};

constexpr std::array kBiasModes = {
    NamedEntry{"none", "no bias"},
    NamedEntry{"constant", "constant depth bias (0.005)"},
    NamedEntry{"slope", "0.005 * tan(acos(N.L)) clamped to [0, 0.01]"},
    NamedEntry{"offset", "polygon offset (factor, units) while building the map"},
    NamedEntry{"normal", "normal offset: the receiver moves along its normal before the lookup"},
};

constexpr std::array kDepthFormats = {
    NamedEntry{"d16", "16-bit unorm depth"},
    NamedEntry{"d24", "24-bit unorm depth"},
    NamedEntry{"d32f", "32-bit float depth"},
};

template <typename Enum, size_t N>
std::optional<Enum> parse_in(const std::array<NamedEntry, N>& table, std::string_view s) {
  for (size_t i = 0; i < N; ++i)
    if (table[i].name == s) return Enum(i);
  return std::nullopt;
}

template <size_t N>
std::string_view name_in(const std::array<NamedEntry, N>& table, size_t i) {
  return i < N ? table[i].name : std::string_view("?");
}

}  // namespace

std::string_view to_string(LightType v) { return name_in(kLightTypes, size_t(v)); }
std::string_view to_string(ShadowTechnique v) { return name_in(kTechniques, size_t(v)); }
std::string_view to_string(ShadowFilter v) { return name_in(kFilters, size_t(v)); }
std::string_view to_string(BiasMode v) { return name_in(kBiasModes, size_t(v)); }

std::optional<LightType> parse_light_type(std::string_view s) { return parse_in<LightType>(kLightTypes, s); }
std::optional<ShadowTechnique> parse_technique(std::string_view s) {
  return parse_in<ShadowTechnique>(kTechniques, s);
}
std::optional<ShadowFilter> parse_filter(std::string_view s) { return parse_in<ShadowFilter>(kFilters, s); }
std::optional<BiasMode> parse_bias_mode(std::string_view s) { return parse_in<BiasMode>(kBiasModes, s); }
std::optional<DepthFormat> parse_depth_format(std::string_view s) { return raster::parse_depth_format(s); }

std::span<const NamedEntry> light_type_names() { return kLightTypes; }
std::span<const NamedEntry> technique_names() { return kTechniques; }
std::span<const NamedEntry> filter_names() { return kFilters; }
std::span<const NamedEntry> bias_mode_names() { return kBiasModes; }
std::span<const NamedEntry> depth_format_names() { return kDepthFormats; }

std::string join_names(std::span<const NamedEntry> table) {
  std::string out;
  for (const NamedEntry& e : table) {
    if (!out.empty()) out += ", ";
    out += e.name;
  }
  return out;
}

bool technique_supports(ShadowTechnique technique, LightType light) {
  using T = ShadowTechnique;
  using L = LightType;
  switch (technique) {
    case T::none: return true;
    case T::shadowmap: return light == L::directional || light == L::spot;
    case T::cube: return light == L::point || light == L::hemispherical;
    case T::paraboloid: return light == L::point || light == L::hemispherical;
    case T::pyramid: return light == L::hemispherical;
    case T::projective: return light == L::directional || light == L::spot || light == L::point;
    case T::cascades:
    case T::lispsm:
    case T::frustum_faces: return light == L::directional;
  }
  return false;
}

ShadowSettings default_shadow_settings(LightType light) {
  ShadowSettings s;
  switch (light) {
    case LightType::directional:
    case LightType::spot: s.technique = ShadowTechnique::shadowmap; break;
    case LightType::point: s.technique = ShadowTechnique::cube; break;
    case LightType::hemispherical: s.technique = ShadowTechnique::pyramid; break;
  }
  return s;
}

uint32_t default_map_size(ShadowTechnique technique) {
  return technique == ShadowTechnique::projective ? 128u : 1024u;
}

}  // namespace scenes
