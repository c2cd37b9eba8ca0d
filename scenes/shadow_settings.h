// Per-light shadow settings and their name tables: which technique builds the map, how it is filtered and
// biased, and the map's size and depth format. Plain data shared by the scene model, the JSON reader and
// writer, the technique layer and `shadowlab list`; every enum has to_string / parse and a list of all names.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "raster/formats.h"

namespace scenes {

enum class LightType : uint8_t { directional, spot, point, hemispherical };

// How the shadow map of a light is laid out and built. `none`: the light casts no shadows.
enum class ShadowTechnique : uint8_t {
  none,
  shadowmap,      // classic single map: orthographic (directional) or perspective (spot)
  cube,           // six 90° faces around a point light
  paraboloid,     // dual paraboloid (one paraboloid for a hemispherical light)
  pyramid,        // 180° light: one square map split into four triangles
  projective,     // per-caster black-on-white projective textures (2000)
  cascades,       // reserved: cascaded maps for a directional light
  lispsm,         // reserved: light-space perspective shadow maps
  frustum_faces,  // reserved: perspective maps cut from the light-facing faces of the view frustum
};

// How the map is read when shading.
enum class ShadowFilter : uint8_t { hard, pcf, poisson, stratified, rotated, early_bail };

// Which depth bias is applied.
enum class BiasMode : uint8_t { none, constant, slope, offset, normal };

using DepthFormat = raster::DepthFormat;

// Every bias carries all its values; `mode` picks the one that is used.
struct BiasSettings {
  BiasMode mode = BiasMode::slope;
  float constant = 0.005f;       // constant: depth (window z) subtracted before the compare
  float slope = 0.005f;          // slope: slope · tan(acos(N·L)) ...
  float slope_max = 0.01f;       // ... clamped to [0, slope_max]
  float offset_factor = 1.1f;    // offset: glPolygonOffset(factor, units) while building the map
  float offset_units = 4.0f;
  float normal_offset = 0.02f;   // normal: receiver moved this far (metres) along its normal before lookup
  bool operator==(const BiasSettings&) const = default;
};

// A free-form per-technique value (cascade count, split lambda, ...), kept for techniques added later.
using TechniqueParam = std::variant<bool, double, std::string>;

struct ShadowSettings {
  ShadowTechnique technique = ShadowTechnique::shadowmap;
  ShadowFilter filter = ShadowFilter::pcf;
  BiasSettings bias;
  bool cull_front = false;                        // build the map from back faces (glCullFace(GL_FRONT))
  uint32_t map_size = 1024;                       // texels per side (per face / per caster)
  DepthFormat depth_format = DepthFormat::d16;
  uint32_t poisson_taps = 4;                      // 4 or 16
  float poisson_spread = 1.0f / 700.0f;           // disc radius in shadow-map texture coordinates
  std::map<std::string, TechniqueParam> params;   // technique-specific extras
  bool operator==(const ShadowSettings&) const = default;
};

// Name tables: to_string gives the canonical name, parse_* accepts exactly those names.
std::string_view to_string(LightType v);
std::string_view to_string(ShadowTechnique v);
std::string_view to_string(ShadowFilter v);
std::string_view to_string(BiasMode v);
std::optional<LightType> parse_light_type(std::string_view s);
std::optional<ShadowTechnique> parse_technique(std::string_view s);
std::optional<ShadowFilter> parse_filter(std::string_view s);
std::optional<BiasMode> parse_bias_mode(std::string_view s);
std::optional<DepthFormat> parse_depth_format(std::string_view s);

// A name with a one-line description, for `shadowlab list` and error messages.
struct NamedEntry {
  std::string_view name;
  std::string_view description;
};
std::span<const NamedEntry> light_type_names();
std::span<const NamedEntry> technique_names();
std::span<const NamedEntry> filter_names();
std::span<const NamedEntry> bias_mode_names();
std::span<const NamedEntry> depth_format_names();

// "a, b, c": the names of a table, for messages such as "unknown filter 'x' (known: ...)".
std::string join_names(std::span<const NamedEntry> table);

// Whether a technique can serve a light type (cube needs a point light, pyramid a hemispherical one, ...).
bool technique_supports(ShadowTechnique technique, LightType light);

// Sensible defaults for a light type: classic map for directional and spot, cube for point, pyramid for
// hemispherical; PCF, slope-scaled bias, 1024², d16.
ShadowSettings default_shadow_settings(LightType light);

// The map side a technique uses when a scene does not give one: 128 texels per caster for `projective` (the
// article's small per-caster maps), 1024 for every other technique.
uint32_t default_map_size(ShadowTechnique technique);

}  // namespace scenes
