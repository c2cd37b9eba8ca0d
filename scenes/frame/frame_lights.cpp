// Light and shadow-setting resolution for the frame renderer (see frame_lights.h).
#include "scenes/frame/frame_lights.h"

#include <cstdio>
#include <cctype>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include "raster/simd/isa.h"
#include "shading/techniques/filtered.h"
#include "shading/techniques/param_use.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

std::string name_stem(const std::string& prefix, const std::string& name) {
  std::string part;
  for (char c : name) part += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '-';
  while (!part.empty() && part.back() == '-') part.pop_back();
  while (!part.empty() && part.front() == '-') part.erase(part.begin());
  return part.empty() ? prefix : prefix + "-" + part;
}

float ambient_illuminance(const scenes::Light& light, const scenes::Aabb& bounds) {
  if (light.type == tech::LightType::directional) return 0.0f;  // its ambient is Material::ambient of its lux
  const glm::vec3 e = bounds.max - bounds.min;
  if (!(e.x >= 0.0f && e.y >= 0.0f && e.z >= 0.0f) || !std::isfinite(e.x + e.y + e.z)) return 0.0f;
  const double area = std::max(2.0 * (double(e.x) * e.y + double(e.y) * e.z + double(e.z) * e.x), 1e-4);
  double solid_angle = 4.0 * std::numbers::pi;  // steradians the light shines into
  if (light.type == tech::LightType::hemispherical) solid_angle = 2.0 * std::numbers::pi;
  if (light.type == tech::LightType::spot)
    solid_angle = 2.0 * std::numbers::pi * (1.0 - std::cos(double(glm::radians(light.outer_cone_deg))));
  constexpr double kBounce = 0.5;  // the share of the flux the scene's surfaces reflect once
  return float(kBounce * solid_angle * double(light.intensity) / area);
}

namespace {

shading::Light lighting_light(const scenes::Light& l) {
  shading::Light s;
  switch (l.type) {
    case tech::LightType::directional: s.type = shading::LightType::directional; break;
    case tech::LightType::spot: s.type = shading::LightType::spot; break;
    case tech::LightType::point:
    case tech::LightType::hemispherical: s.type = shading::LightType::point; break;
  }
  s.position = l.position;
  s.direction = glm::normalize(l.direction);
  s.color = l.color;
  s.intensity = l.intensity;
  s.range = l.range;
  s.inner_angle = glm::radians(l.inner_cone_deg);
  s.outer_angle = glm::radians(l.outer_cone_deg);
  return s;
}

// A value as a message quotes it (%g: 1e+30, not thirty-one digits and six decimals).
std::string shown(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", double(v));
  return buf;
}

// An override if given, else the light's value; finite and >= 0 (> 0 with `positive`) unless `signed_ok`. A bad
// value is named where it came from: the override's field, or the light's (`at` + ".shadow." + field).
float checked_value(std::optional<float> given, float light_value, const std::string& at, const char* field,
                    bool positive = false, bool signed_ok = false) {
  const float v = given.value_or(light_value);
  if (!std::isfinite(v) || (!signed_ok && (positive ? !(v > 0.0f) : v < 0.0f)))
    throw FrameError((given ? std::string(field) : at + ".shadow." + field) + ": " + shown(v) +
                     " must be a finite number" + (signed_ok ? "" : positive ? " above 0" : " of 0 or more"));
  return v;
}

}  // namespace

ResolvedLight resolve_light(const scenes::Light& light, size_t index, const FrameConfig& o) {
  ResolvedLight r;
  r.light = lighting_light(light);
  const std::string at = "lights[" + std::to_string(index) + "]";
  const scenes::ShadowSettings& s = light.shadow;
  tech::ShadowConfig& c = r.config;
  c.technique = o.technique.value_or(s.technique);
  if (const std::string why = tech::refusal(c.technique, light.type); !why.empty())
    throw FrameError((o.technique ? std::string("technique") : at + ".shadow.technique") + ": " + why);
  const tech::TechniqueInfo& info = tech::info(c.technique);

  c.filter = o.filter.value_or(s.filter);
  c.bias = s.bias;
  if (o.bias) c.bias.mode = *o.bias;
  c.cull_front = o.cull_front.value_or(s.cull_front);
  // A light whose map size or depth format is its own technique's default takes the overriding technique's
  // (--technique esm on a classic d16 light builds ESM's d32f map); a value of its own it keeps, and so does
  // every light under `none`, which builds no map.
  const bool switched = o.technique && *o.technique != s.technique && scenes::default_map_size(c.technique) > 0;
  const int light_size = switched && s.map_size == scenes::default_map_size(s.technique)
                             ? int(scenes::default_map_size(c.technique))
                             : int(s.map_size);
  const raster::DepthFormat light_format = switched && s.depth_format == scenes::default_depth_format(s.technique)
                                               ? scenes::default_depth_format(c.technique)
                                               : s.depth_format;
  c.map_size = o.map_size.value_or(light_size);
  // Checked before anything is allocated (issue 23: a 16384 cube map failed in the target's constructor, as
  // "target size: width 49152"), named where the value came from.
  if (auto why = tech::map_size_problem(c.technique, c.map_size))
    throw FrameError(std::string(o.map_size ? "map_size" : at + ".shadow.map_size") + ": " + *why);
  c.depth_format = o.depth_format.value_or(light_format);
  c.filter_params.taps = o.poisson_taps.value_or(int(s.poisson_taps));
  if (c.filter_params.taps != 4 && c.filter_params.taps != 16)
    throw FrameError((o.poisson_taps ? std::string("poisson_taps") : at + ".shadow.poisson_taps") + ": " +
                     std::to_string(c.filter_params.taps) + " is not 4 or 16");
  c.filter_params.spread = checked_value(o.poisson_spread, s.poisson_spread, at, "poisson_spread", true);
  if (c.filter_params.spread > 1.0f)  // a radius beyond the whole map: every tap clamped to its edges
    throw FrameError((o.poisson_spread ? std::string("poisson_spread") : at + ".shadow.poisson_spread") + ": " +
                     shown(c.filter_params.spread) + " is above 1, the whole map's width");
  c.bias.constant = checked_value(o.bias_constant, c.bias.constant, at, "bias.constant");
  c.bias.slope = checked_value(o.bias_slope, c.bias.slope, at, "bias.slope");
  c.bias.slope_max = checked_value(o.bias_slope_max, c.bias.slope_max, at, "bias.slope_max");
  c.bias.offset_factor = checked_value(o.offset_factor, c.bias.offset_factor, at, "bias.offset_factor", false, true);
  c.bias.offset_units = checked_value(o.offset_units, c.bias.offset_units, at, "bias.offset_units", false, true);
  c.bias.normal_offset = checked_value(o.normal_offset, c.bias.normal_offset, at, "bias.normal_offset");

  // The technique's parameters: the light's own (those its technique takes: a --technique override may have
  // changed it), then the frame's.
  c.where = at + ".shadow.params.";
  for (const auto& [key, value] : s.params)
    if (tech::find_param(c.technique, key)) c.params[key] = value;
  for (const auto& [key, value] : o.params)
    if (tech::find_param(c.technique, key)) c.params[key] = value, c.overridden.insert(key);
  // A light's own setting that its own settings leave unread would do nothing (tech::unread_param): refused,
  // named in the scene; not under a --technique that replaces them. The frame's overrides are checked across
  // all lights (frame.cpp).
  if (!o.technique || *o.technique == s.technique) {
    tech::ShadowConfig own;
    own.technique = s.technique;
    own.where = c.where;
    for (const auto& [key, value] : s.params)
      if (tech::find_param(s.technique, key)) own.params[key] = value;
    try {
      for (const auto& [key, value] : own.params)
        if (const auto why = tech::unread_param(own, light.type, key)) throw FrameError(c.where + key + ": " + *why);
    } catch (const tech::TechniqueError& e) {
      throw FrameError(e.what());
    }
  }
  if (info.reads_filter) {
    try {
      const tech::Params p(c);
      c.filter_params.pcf_taps = p.flag("pcf_taps");
      c.filter_params.stratify_world = p.text("stratify") == "world";
      c.filter_params.tutorial = p.text("poisson_variant") == "tutorial";
      const bool poisson = c.filter == tech::FilterKind::poisson || c.filter == tech::FilterKind::stratified ||
                           c.filter == tech::FilterKind::rotated;
      const bool hashed = c.filter == tech::FilterKind::stratified || c.filter == tech::FilterKind::rotated;
      // A Poisson filter's setting beside a filter that has no taps to apply it to does nothing, which is an
      // error, named where it was given; except a light's own setting under a command-line --filter, which
      // replaces the light's filter and so the settings that belong to it.
      auto unused = [&](const char* key, const std::string& why) {
        if (o.filter && !o.params.count(key)) return;
        throw tech::TechniqueError((o.params.count(key) ? "params." + std::string(key) : p.where(key)) + ": " + why +
                                   ", not " + std::string(tech::to_string(c.filter)));
      };
      if (c.filter_params.pcf_taps && !poisson && c.filter != tech::FilterKind::early_bail)
        unused("pcf_taps", "makes the taps of the poisson, stratified, rotated and early-bail filters PCF lookups");
      if (c.filter_params.stratify_world && !hashed)
        unused("stratify", "world seeds the stratified and rotated filters");
      c.filter_params.pcf_taps &= poisson || c.filter == tech::FilterKind::early_bail;
      c.filter_params.stratify_world &= hashed;
      // Named as the command line's field when it gave the variant (the CLI shows its option), else the light's.
      if (c.filter_params.tutorial && !poisson)
        throw tech::TechniqueError((o.params.count("poisson_variant") ? "params.poisson_variant"
                                                                      : p.where("poisson_variant")) +
                                   ": tutorial is a variant of the poisson, stratified and rotated filters, not " +
                                   std::string(tech::to_string(c.filter)));
    } catch (const tech::TechniqueError& e) {
      throw FrameError(e.what());
    }
  }

  r.desc.type = light.type;
  r.desc.position = light.position;
  r.desc.direction = r.light.direction;
  r.desc.range = light.range;
  r.desc.outer_angle = r.light.outer_angle;
  return r;
}


std::optional<std::string> unread_override(const std::vector<ResolvedLight>& lights, const std::string& key,
                                           const tech::ParamValue& value) {
  std::optional<std::string> unread;  // why the first light that takes it does not read it
  for (const ResolvedLight& r : lights)
    if (const tech::ParamSpec* spec = tech::find_param(r.config.technique, key)) {
      if (auto why = tech::value_problem(*spec, value)) throw FrameError("params." + key + ": " + *why);
      std::optional<std::string> why;
      try {
        why = tech::unread_param(r.config, r.desc.type, key);
      } catch (const tech::TechniqueError& e) {
        throw FrameError(e.what());
      }
      if (!why) return std::nullopt;
      if (!unread) unread = why;
    }
  if (unread) return "params." + key + ": " + *unread;
  std::string takers;
  for (const tech::TechniqueInfo& t : tech::kTechniques)
    if (t.built && tech::find_param(t.id, key)) takers += (takers.empty() ? "" : ", ") + std::string(t.name);
  return "params." + key + ": no light of this frame uses a technique that takes it" +
         (takers.empty() ? std::string(" (no technique does)") : " (taken by: " + takers + ")");
}

std::optional<std::string> moment_receiver_warning(const ResolvedLight& light, size_t index, const scenes::Scene& scene) {
  using shading::tech::Technique;
  const Technique t = light.config.technique;
  bool moments = t == Technique::esm || t == Technique::vsm || t == Technique::evsm2 || t == Technique::evsm4;
  if (t == Technique::cascades || t == Technique::cube) {
    try {
      moments = shading::tech::moments_param(light.config).has_value();
    } catch (const shading::tech::TechniqueError&) {
      return std::nullopt;  // a bad `moments` setting: the technique's planning says so, as a FrameError
    }
  }
  if (!moments) return std::nullopt;
  // An object counts when some instance of it receives and none of it casts.
  std::vector<char> casts(scene.objects.size(), 0), receives(scene.objects.size(), 0);
  for (const scenes::Instance& inst : scene.instances) {
    if (inst.object >= scene.objects.size()) continue;
    casts[inst.object] |= char(inst.casts_shadows);
    receives[inst.object] |= char(inst.receives_shadows);
  }
  std::string names;
  size_t count = 0;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    if (!receives[k] || casts[k]) continue;
    if (count < 3) names += std::string(count ? ", " : "") + "objects[" + std::to_string(k) + "]" +
                            (scene.objects[k].empty() ? std::string() : " (" + scene.objects[k] + ")");
    ++count;
  }
  if (count == 0) return std::nullopt;
  if (count > 3) names += " and " + std::to_string(count - 3) + " more";
  const std::string& name = scene.lights[index].name;
  return "lights[" + std::to_string(index) + "]" + (name.empty() ? std::string() : " (" + name + ")") + ": " +
         std::string(shading::tech::to_string(t)) + " reads its map's moments around each receiver, and " + names +
         (count == 1 ? " receives shadows without casting: it is not in the map, and the shadows on it"
                     : " receive shadows without casting: they are not in the map, and the shadows on them") +
         " fade or vanish (let " + (count == 1 ? "it" : "them") + " cast, or use shadowmap or pcss)";
}

SHADOWLAB_ISA_END
}  // namespace frame
