// The omnidirectional techniques (cube, paraboloid, pyramid) as registry entries: their parameters read and
// checked, their maps planned, built, read through omni_visibility and exported as one record holding every
// face, hemisphere or region with its pass matrices.
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "shading/techniques/cube_pcss.h"
#include "shading/techniques/omni_read.h"
#include "shading/techniques/param_use.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

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

namespace {

Technique technique_of(OmniKind k) {
  switch (k) {
    case OmniKind::cube: return Technique::cube;
    case OmniKind::paraboloid: return Technique::paraboloid;
    case OmniKind::pyramid: return Technique::pyramid;
  }
  return Technique::cube;
}

class OmniShadow final : public LightShadow {
 public:
  OmniShadow(OmniKind kind, const OmniLight& light, const OmniSettings& s, std::optional<CubeMoments> moments,
             std::optional<CubePcss> pcss)
      : kind_(kind), light_(light), s_(s), moments_(std::move(moments)), pcss_(pcss) {
    switch (kind_) {
      case OmniKind::cube: set_ = plan_cube_map(light_, s_); break;
      case OmniKind::paraboloid: set_ = plan_paraboloid_map(light_, s_); break;
      case OmniKind::pyramid: set_ = plan_pyramid_map(light_, s_); break;
    }
  }

  raster::DrawStats build(raster::Renderer& renderer, const CasterGeometry& c) override {
    raster::DrawStats stats;
    switch (kind_) {
      case OmniKind::cube:
        stats = build_cube_map(renderer, set_, light_, s_, c);
        reader_ = make_cube_reader(set_, light_, s_);
        if (moments_) stats += build_cube_moments(renderer, set_, s_.seamless, *moments_);
        break;
      case OmniKind::paraboloid:
        stats = build_paraboloid_map(renderer, set_, light_, s_, c);
        reader_ = make_paraboloid_reader(set_, light_, s_);
        break;
      case OmniKind::pyramid:
        stats = build_pyramid_map(renderer, set_, light_, s_, c);
        reader_ = make_pyramid_reader(set_, light_, s_);
        break;
    }
    return stats;
  }

  void visibility(std::span<const ShadowQuery> q, std::span<float> vis) const override {
    if (moments_) {
      for (size_t i = 0; i < q.size(); ++i) vis[i] = cube_moment_visibility(reader_, *moments_, q[i]);
      return;
    }
    if (pcss_) {
      for (size_t i = 0; i < q.size(); ++i) vis[i] = cube_pcss_visibility(reader_, *pcss_, q[i].p, q[i].n, q[i].frag);
      return;
    }
    omni_visibility(reader_, q, vis);
  }

  std::vector<MapRecord> maps() const override {
    MapRecord m;
    const raster::DepthTarget& target = *set_.targets.at(0);
    m.target = &target;
    if (kind_ == OmniKind::paraboloid && s_.packing == DepthPacking::rgba8) {
      // What the lookups compare with: the colour target unpacked.
      m.values.resize(size_t(target.width()) * size_t(target.height()));
      for (int y = 0; y < target.height(); ++y)
        for (int x = 0; x < target.width(); ++x) m.values[size_t(y) * size_t(target.width()) + size_t(x)] = target.value(x, y);
      for (size_t k = 0; k < set_.passes.size(); ++k) {
        const Texture2D t = paraboloid_depth_texture(set_, k, s_);
        const raster::Rect& v = set_.passes[k].viewport;
        for (int j = 0; j < v.height; ++j)
          for (int i = 0; i < v.width; ++i)
            m.values[size_t(v.y + j) * size_t(target.width()) + size_t(v.x + i)] = t.texel(i, j).r;
      }
    }
    m.technique = to_string(technique_of(kind_));
    m.encoding = info(technique_of(kind_)).encoding;
    // The light's own frame: world axes at the light for the cube (its lookups use world directions), the split
    // plane's frame for the paraboloid, the pyramid's frame (z = the light's direction) for the pyramid.
    glm::mat4 to_light(1.0f);
    to_light[3] = glm::vec4(-light_.position, 1.0f);
    if (kind_ == OmniKind::paraboloid) to_light = paraboloid_frame(light_, s_).matrix();
    if (kind_ == OmniKind::pyramid) to_light = light_frame(light_.position, light_.direction).matrix();
    m.world_to_camera = to_light;
    m.world_to_ndc = set_.passes.at(0).proj * set_.passes.at(0).view;
    for (const ShadowPass& p : set_.passes) m.passes.push_back(MapPassRecord{p.label, p.viewport, p.view, p.proj * p.view});
    return {m};
  }

 private:
  OmniKind kind_;
  OmniLight light_;
  OmniSettings s_;
  ShadowMapSet set_;
  OmniReader reader_;
  std::optional<CubeMoments> moments_;  // cube with `moments`
  std::optional<CubePcss> pcss_;        // cube with `soft_shadows = pcss`
};

std::unique_ptr<LightShadow> plan_omni(OmniKind kind, const LightDesc& light, const ShadowConfig& c) {
  const Technique t = technique_of(kind);
  const std::string name(to_string(t));
  OmniLight l;
  l.position = light.position;
  l.direction = light.direction;
  l.range = light.range;
  l.hemispherical = light.type == LightType::hemispherical;
  if (!(l.range > 0.0f) || !std::isfinite(l.range))
    throw TechniqueError("range: must be above 0 for technique " + name);
  if (!(glm::length(l.direction) > 0.5f)) throw TechniqueError("direction: must not be zero for technique " + name);

  OmniSettings s;
  s.filter = c.filter;
  s.filter_params = c.filter_params;
  s.bias = c.bias;
  s.cull_front = c.cull_front;
  s.map_size = c.map_size;
  s.depth_format = c.depth_format;
  if (s.bias.mode == BiasMode::offset)
    throw TechniqueError("bias: offset does not apply to technique " + name +
                         " (the distance is written by the fragment shader); use none, constant, slope or normal");
  if (kind == OmniKind::pyramid && s.map_size % 2 != 0)
    throw TechniqueError("map_size: the pyramid map side " + std::to_string(s.map_size) +
                         " must be even (two halves per axis)");
  const Params p(c);
  std::optional<CubeMoments> moments;
  std::optional<CubePcss> pcss;
  if (kind == OmniKind::cube) {
    s.seamless = p.flag("seamless");
    if (const std::optional<MomentKind> k = moments_param(c)) {
      moments.emplace();
      moments->params = moment_params(*k, c);
      moments->blur_radius = int(p.number("blur_radius"));
    }
    if (p.text("soft_shadows") == "pcss") {
      if (moments)
        throw TechniqueError(p.where("soft_shadows") + ": pcss and moments = " + p.text("moments") +
                             " both replace the filter; choose one");
      if (c.filter != FilterKind::pcf || c.filter_params.pcf_taps)
        throw TechniqueError(c.where.substr(0, c.where.size() - std::string_view("params.").size()) + "filter: " +
                             std::string(to_string(c.filter)) +
                             " is not used with soft_shadows = pcss (PCSS filters with its own kernel)");
      pcss = CubePcss{float(p.number("light_radius")), s.near_plane};
    } else if (p.given("light_radius")) {
      throw TechniqueError(p.where("light_radius") + ": " + *unread_param(c, light.type, "light_radius"));
    }
  }
  if (kind == OmniKind::paraboloid) {
    if (p.text("paraboloid_pack") == "rgba8") s.packing = DepthPacking::rgba8;
    const std::string split = p.text("split_plane");
    if (split != "light") {
      s.split_normal = parse_split_plane(split);
      if (!s.split_normal)
        throw TechniqueError(p.where("split_plane") + ": '" + split +
                             "' is not light, x, y, z, -x, -y, -z or a non-zero normal a,b,c");
    }
  }
  return std::make_unique<OmniShadow>(kind, l, s, std::move(moments), pcss);
}

}  // namespace

std::unique_ptr<LightShadow> plan_cube(const LightDesc& l, const ShadowConfig& c, const PlanInputs&) {
  return plan_omni(OmniKind::cube, l, c);
}
std::unique_ptr<LightShadow> plan_paraboloid(const LightDesc& l, const ShadowConfig& c, const PlanInputs&) {
  return plan_omni(OmniKind::paraboloid, l, c);
}
std::unique_ptr<LightShadow> plan_pyramid(const LightDesc& l, const ShadowConfig& c, const PlanInputs&) {
  return plan_omni(OmniKind::pyramid, l, c);
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
