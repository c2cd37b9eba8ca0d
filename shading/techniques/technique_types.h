// The vocabulary of the technique layer: light kinds, filters, bias modes and their parameters as plain data,
// plus the one table of per-technique defaults. Independent of scenes/: the frame renderer translates a
// scene's ShadowSettings into these structs once per frame.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "raster/formats.h"

namespace shading::tech {

// The projection a classic map is built with: orthographic (directional) or perspective (spot).
enum class LightKind : uint8_t { directional, spot };

// How a map is read. Each is a compile-time filter type (shadow_filters.h); the choice is made once per draw.
enum class FilterKind : uint8_t { hard, pcf, poisson, stratified, rotated, early_bail };

enum class BiasKind : uint8_t { none, constant, slope, offset, normal };

// All bias values; `kind` picks the one used. Depth values are window depth (the map's [0, 1] scale).
struct BiasParams {
  BiasKind kind = BiasKind::slope;
  float constant = 0.005f;      // constant: ref -= constant
  float slope = 0.005f;         // slope: ref -= clamp(slope · tan(acos(N·L)), 0, slope_max)
  float slope_max = 0.01f;
  float offset_factor = 1.1f;   // offset: glPolygonOffset(factor, units) in the depth pass, no shader bias
  float offset_units = 4.0f;
  float normal_offset = 0.02f;  // normal: receiver moved this far (metres) along its normal, no depth bias
};

// Reading parameters shared by the Poisson family.
struct FilterParams {
  int taps = 4;                      // 4 or 16 (early-bail always takes 4 outer taps, then `taps`... see filters)
  float spread = 1.0f / 700.0f;      // disc radius in shadow-map texture coordinates
  bool pcf_taps = false;             // each Poisson tap is a hardware 2×2 PCF lookup instead of one compare
  bool stratify_world = false;       // stratified: hash world position rounded to 1 mm instead of the pixel
};

// Everything the classic technique needs from a light's settings.
struct ClassicSettings {
  FilterKind filter = FilterKind::pcf;
  FilterParams filter_params;
  BiasParams bias;
  bool cull_front = false;  // render back faces only into the map (glCullFace(GL_FRONT))
  int map_size = 1024;
  raster::DepthFormat depth_format = raster::DepthFormat::d16;
};

// The table of per-technique defaults (STYLE point 8): one row per technique this layer implements.
struct TechniqueDefaults {
  std::string_view technique;  // name as in scenes' technique table
  std::string_view encoding;   // what the map stores (EXR `shadowlab:encoding`)
  ClassicSettings settings;
};
std::span<const TechniqueDefaults> technique_defaults();
// The row for a technique name, or none when this layer does not implement it.
std::optional<TechniqueDefaults> find_technique_defaults(std::string_view technique);

std::string_view to_string(FilterKind f);
std::string_view to_string(BiasKind b);
std::optional<FilterKind> parse_filter_kind(std::string_view s);
std::optional<BiasKind> parse_bias_kind(std::string_view s);

}  // namespace shading::tech
