// Omnidirectional lights in the frame renderer (see frame_omni.h).
#include "cli/frame/frame_omni.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace frame {

namespace tech = shading::tech;

namespace {

const std::string* param_string(const scenes::ShadowSettings& s, const std::string& where, const char* key) {
  const auto it = s.params.find(key);
  if (it == s.params.end()) return nullptr;
  const auto* v = std::get_if<std::string>(&it->second);
  if (!v) throw std::invalid_argument(where + key + ": must be a string");
  return v;
}

std::optional<bool> param_bool(const scenes::ShadowSettings& s, const std::string& where, const char* key) {
  const auto it = s.params.find(key);
  if (it == s.params.end()) return std::nullopt;
  const auto* v = std::get_if<bool>(&it->second);
  if (!v) throw std::invalid_argument(where + key + ": must be true or false");
  return *v;
}

}  // namespace

std::optional<glm::vec3> parse_split_plane(const std::string& t) {
  if (t == "x") return glm::vec3(1, 0, 0);
  if (t == "-x") return glm::vec3(-1, 0, 0);
  if (t == "y") return glm::vec3(0, 1, 0);
  if (t == "-y") return glm::vec3(0, -1, 0);
  if (t == "z") return glm::vec3(0, 0, 1);
  if (t == "-z") return glm::vec3(0, 0, -1);
  glm::vec3 v;
  const char* p = t.c_str();
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    v[i] = std::strtof(p, &end);
    if (end == p || !std::isfinite(v[i])) return std::nullopt;
    p = end;
    if (i < 2) {
      if (*p != ',') return std::nullopt;
      ++p;
    }
  }
  if (*p != '\0' || !(glm::length(v) > 1e-6f)) return std::nullopt;
  return glm::normalize(v);
}

std::optional<OmniPlan> resolve_omni(const scenes::Light& light, const ResolvedLight& r, const FrameOptions& o,
                                     size_t index) {
  const std::string where = "lights[" + std::to_string(index) + "].shadow.params.";
  OmniPlan plan;
  if (r.technique == "cube") plan.kind = tech::OmniKind::cube;
  else if (r.technique == "paraboloid") plan.kind = tech::OmniKind::paraboloid;
  else if (r.technique == "pyramid") plan.kind = tech::OmniKind::pyramid;
  else return std::nullopt;
  if (light.type != scenes::LightType::point && light.type != scenes::LightType::hemispherical) return std::nullopt;

  const scenes::ShadowSettings& ss = light.shadow;
  tech::OmniLight& l = plan.light;
  l.position = light.position;
  l.direction = r.light.direction;
  l.range = light.range;
  l.hemispherical = light.type == scenes::LightType::hemispherical;
  if (!(l.range > 0.0f) || !std::isfinite(l.range))
    throw std::invalid_argument("lights[" + std::to_string(index) + "].range: must be above 0 for technique " +
                                r.technique);
  if (!(glm::length(l.direction) > 0.5f))
    throw std::invalid_argument("lights[" + std::to_string(index) + "].direction: must not be zero for technique " +
                                r.technique);

  const tech::ClassicSettings& c = r.settings;
  tech::OmniSettings& s = plan.settings;
  s.filter = c.filter;
  s.filter_params = c.filter_params;
  s.bias = c.bias;
  s.cull_front = c.cull_front;
  s.map_size = c.map_size;
  s.depth_format = c.depth_format;
  if (s.bias.kind == tech::BiasKind::offset)
    throw std::invalid_argument("--bias: offset does not apply to technique " + r.technique +
                                " (the distance is written by the fragment shader); use none, constant, slope or "
                                "normal");
  if (plan.kind == tech::OmniKind::pyramid && s.map_size % 2 != 0)
    throw std::invalid_argument("--shadow-size: the pyramid map side " + std::to_string(s.map_size) +
                                " must be even (two halves per axis)");

  s.seamless = o.seamless ? *o.seamless : param_bool(ss, where, "seamless").value_or(true);

  std::string pack = "float", pack_name = where + "paraboloid_pack";
  if (o.paraboloid_pack) pack = *o.paraboloid_pack, pack_name = "--paraboloid-pack";
  else if (const std::string* v = param_string(ss, where, "paraboloid_pack")) pack = *v;
  if (pack == "rgba8") s.packing = tech::DepthPacking::rgba8;
  else if (pack != "float")
    throw std::invalid_argument(pack_name + ": unknown value '" + pack + "' (known: float, rgba8)");

  std::string split, split_name = where + "split_plane";
  if (o.split_plane) split = *o.split_plane, split_name = "--split-plane";
  else if (const std::string* v = param_string(ss, where, "split_plane")) split = *v;
  if (!split.empty() && split != "light") {
    s.split_normal = parse_split_plane(split);
    if (!s.split_normal)
      throw std::invalid_argument(split_name + ": '" + split +
                                  "' is not light, x, y, z, -x, -y, -z or a non-zero normal a,b,c");
  }
  return plan;
}

OmniMaps plan_omni(const OmniPlan& plan) {
  OmniMaps m;
  m.plan = plan;
  switch (plan.kind) {
    case tech::OmniKind::cube: m.set = tech::plan_cube_map(plan.light, plan.settings); break;
    case tech::OmniKind::paraboloid: m.set = tech::plan_paraboloid_map(plan.light, plan.settings); break;
    case tech::OmniKind::pyramid: m.set = tech::plan_pyramid_map(plan.light, plan.settings); break;
  }
  return m;
}

raster::DrawStats build_omni(raster::Renderer& renderer, OmniMaps& m, std::span<const glm::vec3> positions,
                             std::span<const uint32_t> indices) {
  const OmniPlan& p = m.plan;
  switch (p.kind) {
    case tech::OmniKind::cube:
      return tech::build_cube_map(renderer, m.set, p.light, p.settings, positions, indices);
    case tech::OmniKind::paraboloid:
      return tech::build_paraboloid_map(renderer, m.set, p.light, p.settings, positions, indices);
    case tech::OmniKind::pyramid:
      return tech::build_pyramid_map(renderer, m.set, p.light, p.settings, positions, indices);
  }
  return {};
}

scenes::io::ExrMap omni_exr(const OmniMaps& m) {
  const OmniPlan& p = m.plan;
  scenes::io::ExrMap e = scenes::io::exr_map_from(*m.set.targets.at(0));
  if (p.kind == tech::OmniKind::paraboloid && p.settings.packing == tech::DepthPacking::rgba8) {
    // What the lookups compare with: the colour target unpacked.
    for (size_t k = 0; k < m.set.passes.size(); ++k) {
      const shading::Texture2D t = tech::paraboloid_depth_texture(m.set, k, p.settings);
      const raster::Rect& v = m.set.passes[k].viewport;
      for (int j = 0; j < v.height; ++j)
        for (int i = 0; i < v.width; ++i) e.z[size_t(v.y + j) * size_t(e.width) + size_t(v.x + i)] = t.texel(i, j).r;
    }
  }
  static const char* const kNames[] = {"cube", "paraboloid", "pyramid"};
  e.technique = kNames[int(p.kind)];
  e.encoding = "radial-distance";
  if (const auto d = tech::find_technique_defaults(e.technique)) e.encoding = std::string(d->encoding);
  // The light's own frame: world axes at the light for the cube (its lookups use world directions), the split
  // plane's frame for the paraboloid, the pyramid's frame (z = the light's direction) for the pyramid.
  glm::mat4 to_light(1.0f);
  to_light[3] = glm::vec4(-p.light.position, 1.0f);
  if (p.kind == tech::OmniKind::paraboloid) to_light = tech::paraboloid_frame(p.light, p.settings).matrix();
  if (p.kind == tech::OmniKind::pyramid) to_light = tech::light_frame(p.light.position, p.light.direction).matrix();
  e.world_to_camera = to_light;
  e.world_to_ndc = m.set.passes.at(0).proj * m.set.passes.at(0).view;
  for (const tech::ShadowPass& s : m.set.passes)
    e.passes.push_back(scenes::io::MapPass{s.label, s.viewport, s.view, s.proj * s.view});
  return e;
}

tech::OmniReader omni_reader(const OmniMaps& m) {
  const OmniPlan& p = m.plan;
  switch (p.kind) {
    case tech::OmniKind::cube: return tech::make_cube_reader(m.set, p.light, p.settings);
    case tech::OmniKind::paraboloid: return tech::make_paraboloid_reader(m.set, p.light, p.settings);
    case tech::OmniKind::pyramid: return tech::make_pyramid_reader(m.set, p.light, p.settings);
  }
  return {};
}

}  // namespace frame
