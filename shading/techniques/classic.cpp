// The classic technique's planning and reader setup (see classic.h).
#include "shading/techniques/classic.h"

#include <string>

#include "shading/techniques/param_use.h"
#include "shading/techniques/tutorial_fit.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

ShadowMapSet plan_classic_map(const ClassicLight& light, const ClassicSettings& s, const ClassicFit& fit) {
  ShadowMapSet set = single_map_layout(s.map_size, s.depth_format);
  ShadowPass& p = set.passes[0];
  LightMatrices m;
  if (light.kind == LightKind::spot) {
    m = spot_frustum(light.position, light.direction, light.outer_angle, light.range);
    p.perspective = true;
  } else {
    m = fit.fixed ? *fit.fixed : fit_directional(light.direction, fit.receivers, fit.casters);
  }
  p.view = m.view;
  p.proj = m.proj;
  return set;
}

DepthPassOptions classic_depth_options(const ClassicSettings& s) {
  DepthPassOptions o;
  o.cull_front = s.cull_front;
  if (s.bias.mode == BiasMode::offset) o.offset = raster::PolygonOffset{s.bias.offset_factor, s.bias.offset_units};
  return o;
}

ClassicReader make_classic_reader(const ShadowMapSet& set, const ClassicLight& light, const ClassicSettings& s,
                                  size_t pass) {
  const ShadowPass& p = set.passes.at(pass);
  const raster::DepthTarget& target = *set.targets.at(p.target);
  const Texture2D tex = Texture2D::view(target, p.viewport);
  ClassicReader r;
  r.shadow = shadow_matrix(p);
  r.perspective = p.perspective;
  r.kind = light.kind;
  r.position = light.position;
  r.direction = light.direction;
  r.bias = s.bias;
  r.filter_kind = s.filter;
  r.filter = s.filter_params;
  r.maps = map_lookups(tex, Wrap::clamp_to_border);  // outside a directional map: border depth 1, lit
  return r;
}

namespace {

// The classic map as a LightShadow: planned at construction, its reader made once the map is built.
class ClassicShadow final : public LightShadow {
 public:
  ClassicShadow(const ClassicLight& light, const ClassicSettings& settings, const ClassicFit& fit)
      : light_(light), settings_(settings), set_(plan_classic_map(light, settings, fit)) {}

  raster::DrawStats build(raster::Renderer& renderer, const CasterGeometry& c) override {
    const raster::DrawStats stats =
        build_maps(renderer, set_, c, classic_depth_options(settings_));
    reader_ = make_classic_reader(set_, light_, settings_);
    return stats;
  }
  void visibility(std::span<const ShadowQuery> q, std::span<float> vis) const override {
    classic_visibility(reader_, q, vis);
  }
  void visibility_x8(std::span<const ShadowQuery> q, std::span<float> vis) const override {
    classic_visibility_x8(reader_, q, vis);
  }
  bool texel_coords(glm::vec3 p, std::span<const glm::vec3> others, std::span<glm::vec2> out) const override {
    return one_pass_texels(set_, reader_.shadow, p, others, out);
  }
  std::vector<MapRecord> maps() const override { return {one_pass_record(set_, Technique::shadowmap)}; }

 private:
  ClassicLight light_;
  ClassicSettings settings_;
  ShadowMapSet set_;
  ClassicReader reader_;
};

}  // namespace

ClassicLight classic_light(const LightDesc& light) {
  ClassicLight l;
  l.kind = light.type == LightType::spot ? LightKind::spot : LightKind::directional;
  l.position = light.position;
  l.direction = light.direction;
  l.outer_angle = light.outer_angle;
  l.range = light.range;
  return l;
}

ClassicSettings classic_settings(const ShadowConfig& c) {
  return {c.filter, c.filter_params, c.bias, c.cull_front, c.map_size, c.depth_format};
}

bool one_pass_texels(const ShadowMapSet& set, const glm::mat4& shadow, glm::vec3 p, std::span<const glm::vec3> others,
                     std::span<glm::vec2> out) {
  const ShadowPass& pass = set.passes.at(0);
  const glm::vec2 size(float(pass.viewport.width), float(pass.viewport.height));
  auto texel = [&](glm::vec3 q, glm::vec2& t) { return map_texel(shadow, pass.perspective, size, q, t); };
  if (!texel(p, out[0])) return false;
  for (size_t i = 0; i < others.size(); ++i)
    if (!texel(others[i], out[i + 1])) return false;
  return true;
}

LightMatrices tutorial_fit(glm::vec3 direction, const Params& p, const PlanInputs& in) {
  TutorialFitInput t;
  t.direction = direction;
  t.camera_view_proj = in.camera_view_proj;
  t.eye = in.camera.eye;
  t.forward = in.camera.forward;
  const float cutoff = float(p.number("fit_cutoff"));
  t.cutoff = cutoff > 0.0f ? cutoff : in.camera.far;
  t.scene = in.scene_receivers;
  t.scene.min = glm::min(t.scene.min, in.casters.min);
  t.scene.max = glm::max(t.scene.max, in.casters.max);
  const TutorialSets sets = tutorial_sets(in.objects, t);
  LightBox box = tutorial_light_box(in.objects, sets, t);
  if (in.fit_memory) {
    box = smooth_light_box(box, in.fit_memory->box, float(p.number("fit_smoothing")));
    in.fit_memory->box = box;
  }
  return light_box_matrices(box);
}

MapRecord one_pass_record(const ShadowMapSet& set, Technique technique) {
  const ShadowPass& p = set.passes.at(0);
  MapRecord m;
  m.target = set.targets.at(p.target).get();
  m.technique = to_string(technique);
  m.encoding = info(technique).encoding;
  m.world_to_camera = p.view;
  m.world_to_ndc = p.proj * p.view;
  return m;
}

std::unique_ptr<LightShadow> plan_classic(const LightDesc& light, const ShadowConfig& c, const PlanInputs& in) {
  const ClassicLight l = classic_light(light);
  const ClassicSettings s = classic_settings(c);
  ClassicFit fit{in.receivers, in.casters, std::nullopt};
  const Params p(c);
  const std::string how = p.text("fit");
  for (const char* key : {"fit_cutoff", "fit_smoothing"})  // the condition and its words: param_use.h
    if (how != "tutorial" && c.params.count(key))
      throw TechniqueError(p.where(key) + ": " + *unread_param(c, light.type, key));
  if (how == "fixed") fit.fixed = fixed_directional(l.direction, glm::vec3(0.0f), {10.0f, 10.0f}, -10.0f, 20.0f);
  if (how == "tutorial" && l.kind == LightKind::directional) fit.fixed = tutorial_fit(l.direction, p, in);
  return std::make_unique<ClassicShadow>(l, s, fit);
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
