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
