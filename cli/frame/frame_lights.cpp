// Light and shadow-setting resolution for the frame renderer (see frame_lights.h).
#include "cli/frame/frame_lights.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string_view>

#include <glm/trigonometric.hpp>

namespace frame {

namespace tech = shading::tech;

namespace {

shading::Light lighting_light(const scenes::Light& l) {
  shading::Light s;
  switch (l.type) {
    case scenes::LightType::directional: s.type = shading::LightType::directional; break;
    case scenes::LightType::spot: s.type = shading::LightType::spot; break;
    default: s.type = shading::LightType::point; break;  // point and hemispherical: unshadowed point lights
  }
  s.position = l.position;
  s.direction = glm::normalize(l.direction);
  s.color = l.color;
  s.power = l.intensity;
  s.range = l.range;
  s.inner_angle = glm::radians(l.inner_cone_deg);
  s.outer_angle = glm::radians(l.outer_cone_deg);
  return s;
}

bool param_is(const scenes::ShadowSettings& s, const std::string& key, std::string_view value) {
  const auto it = s.params.find(key);
  if (it == s.params.end()) return false;
  if (const auto* str = std::get_if<std::string>(&it->second)) return *str == value;
  if (const auto* b = std::get_if<bool>(&it->second)) return *b == (value == "true");
  return false;
}

// An override if given, else the light's value; checked finite and >= 0 (> 0 with `positive`) unless `signed_ok`.
float override_value(std::optional<float> given, float light_value, const char* option, bool positive = false,
                     bool signed_ok = false) {
  const float v = given.value_or(light_value);
  if (!std::isfinite(v) || (!signed_ok && (positive ? !(v > 0.0f) : v < 0.0f)))
    throw std::invalid_argument(std::string(option) + ": " + std::to_string(v) + " must be a finite number" +
                                (signed_ok ? "" : positive ? " above 0" : " of 0 or more"));
  return v;
}

// A two-way choice: false for `first`, true for `second`.
bool choice(const std::string& value, const char* option, std::string_view first, std::string_view second) {
  if (value == first) return false;
  if (value == second) return true;
  throw std::invalid_argument(std::string(option) + ": unknown value '" + value + "' (known: " + std::string(first) +
                              ", " + std::string(second) + ")");
}

}  // namespace

ResolvedLight resolve_light(const scenes::Light& light, const FrameOptions& o) {
  ResolvedLight r;
  r.light = lighting_light(light);
  const scenes::ShadowSettings& s = light.shadow;
  r.technique = o.technique ? *o.technique : std::string(scenes::to_string(s.technique));
  if (!scenes::parse_technique(r.technique))
    throw std::invalid_argument("--technique: unknown technique '" + r.technique + "' (known: " +
                                scenes::join_names(scenes::technique_names()) + ")");

  tech::ClassicSettings& c = r.settings;
  if (const auto d = tech::find_technique_defaults("shadowmap")) c = d->settings;
  c.filter = tech::FilterKind(int(s.filter));
  if (o.filter) {
    const auto f = tech::parse_filter_kind(*o.filter == "early_bail" ? "early-bail" : *o.filter);
    if (!f) throw std::invalid_argument("--filter: unknown filter '" + *o.filter +
                                        "' (known: hard, pcf, poisson, stratified, rotated, early-bail)");
    c.filter = *f;
  }
  c.bias = tech::BiasParams{tech::BiasKind(int(s.bias.mode)), s.bias.constant, s.bias.slope, s.bias.slope_max,
                            s.bias.offset_factor, s.bias.offset_units, s.bias.normal_offset};
  if (o.bias) {
    const auto b = tech::parse_bias_kind(*o.bias);
    if (!b) throw std::invalid_argument("--bias: unknown bias '" + *o.bias + "' (known: none, constant, slope, offset, normal)");
    c.bias.kind = *b;
  }
  c.cull_front = o.cull_front.value_or(s.cull_front);
  c.map_size = o.shadow_size ? *o.shadow_size : int(s.map_size);
  if (c.map_size < 16 || c.map_size > 16384)
    throw std::invalid_argument("--shadow-size: " + std::to_string(c.map_size) + " is outside 16..16384");
  c.depth_format = s.depth_format;
  c.filter_params.taps = o.poisson_taps.value_or(int(s.poisson_taps));
  if (c.filter_params.taps != 4 && c.filter_params.taps != 16)
    throw std::invalid_argument("--poisson-taps: " + std::to_string(c.filter_params.taps) + " is not 4 or 16");
  c.filter_params.spread = override_value(o.poisson_spread, s.poisson_spread, "--poisson-spread", true);
  c.filter_params.pcf_taps = o.pcf_taps.value_or(param_is(s, "pcf_taps", "true"));
  c.filter_params.stratify_world = o.stratify ? choice(*o.stratify, "--stratify", "pixel", "world")
                                              : param_is(s, "stratify", "world");
  r.fixed_box = o.fit ? choice(*o.fit, "--fit", "auto", "fixed") : param_is(s, "fit", "fixed");
  c.bias.constant = override_value(o.bias_constant, c.bias.constant, "--bias-constant");
  c.bias.slope = override_value(o.bias_slope, c.bias.slope, "--bias-slope");
  c.bias.slope_max = override_value(o.bias_slope_max, c.bias.slope_max, "--bias-slope-max");
  c.bias.offset_factor = override_value(o.offset_factor, c.bias.offset_factor, "--offset-factor", false, true);
  c.bias.offset_units = override_value(o.offset_units, c.bias.offset_units, "--offset-units", false, true);
  c.bias.normal_offset = override_value(o.normal_offset, c.bias.normal_offset, "--normal-offset");

  const bool classic_light = light.type == scenes::LightType::directional || light.type == scenes::LightType::spot;
  r.shadowed = r.technique == "shadowmap" && classic_light;
  r.classic.kind = light.type == scenes::LightType::spot ? tech::LightKind::spot : tech::LightKind::directional;
  r.classic.position = light.position;
  r.classic.direction = r.light.direction;
  r.classic.outer_angle = r.light.outer_angle;
  r.classic.range = light.range;
  return r;
}

}  // namespace frame
