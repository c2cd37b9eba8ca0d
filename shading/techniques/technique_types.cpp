// Name tables and the per-technique defaults table of the technique layer.
#include "shading/techniques/technique_types.h"

#include <array>

namespace shading::tech {

namespace {
constexpr std::array<std::string_view, 6> kFilterNames = {"hard", "pcf", "poisson", "stratified", "rotated",
                                                          "early-bail"};
constexpr std::array<std::string_view, 5> kBiasNames = {"none", "constant", "slope", "offset", "normal"};

// The classic map of the tutorial: 1024² d16, hardware PCF, slope-scaled bias, front faces drawn.
constexpr TechniqueDefaults kDefaults[] = {
    {"shadowmap", "window-depth", ClassicSettings{}},
    // Per-caster projective maps (2000): 128² per caster, a black-on-white mask (no depth, so no bias).
    {"projective", "caster-mask", ClassicSettings{.bias = {.kind = BiasKind::none}, .map_size = 128}},
    // Omnidirectional maps (omni.h): distance / range written per fragment (cube, pyramid) or per vertex
    // (paraboloid), so no polygon offset; d24 holds the distance to 1/16777215 of the range.
    {"cube", "radial-distance", ClassicSettings{.map_size = 512, .depth_format = raster::DepthFormat::d24}},
    {"paraboloid", "radial-distance", ClassicSettings{.map_size = 1024, .depth_format = raster::DepthFormat::d24}},
    {"pyramid", "radial-distance", ClassicSettings{.map_size = 1024, .depth_format = raster::DepthFormat::d24}},
};
}  // namespace

std::span<const TechniqueDefaults> technique_defaults() { return kDefaults; }

std::optional<TechniqueDefaults> find_technique_defaults(std::string_view technique) {
  for (const TechniqueDefaults& d : kDefaults)
    if (d.technique == technique) return d;
  return std::nullopt;
}

std::string_view to_string(FilterKind f) { return kFilterNames[size_t(f)]; }
std::string_view to_string(BiasKind b) { return kBiasNames[size_t(b)]; }

std::optional<FilterKind> parse_filter_kind(std::string_view s) {
  for (size_t i = 0; i < kFilterNames.size(); ++i)
    if (kFilterNames[i] == s) return FilterKind(i);
  return std::nullopt;
}
std::optional<BiasKind> parse_bias_kind(std::string_view s) {
  for (size_t i = 0; i < kBiasNames.size(); ++i)
    if (kBiasNames[i] == s) return BiasKind(i);
  return std::nullopt;
}

}  // namespace shading::tech
