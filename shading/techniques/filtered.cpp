// The filterable maps' planning, passes and reading (see filtered.h).
#include "shading/techniques/filtered.h"

#include <algorithm>
#include <string>
#include <string_view>

#include "shading/lookup.h"
#include "shading/techniques/blur_pass.h"
#include "shading/techniques/depth_pass.h"
#include "shading/techniques/moment_lod.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

// The point the map is read at: p moved along its normal by the `normal` bias.
glm::vec3 read_point(const FilteredReader& r, glm::vec3 p, glm::vec3 n) {
  return r.bias.mode == BiasMode::normal ? p + n * r.bias.normal_offset : p;
}

// Map coordinates of world point x (a perspective map's divided by w, as the lookup's).
glm::vec2 map_st(const FilteredReader& r, glm::vec3 x) {
  const glm::vec4 c = r.shadow * glm::vec4(x, 1.0f);
  if (!r.depth.perspective) return glm::vec2(c.x, c.y);
  const float w = 1.0f / c.w;
  return glm::vec2(c.x * w, c.y * w);
}

}  // namespace

bool filtered_context(const FilteredReader& r, glm::vec3 p, glm::vec3 n, glm::vec2& st, float& depth, bool& lit) {
  lit = false;
  const glm::vec3 to_light = r.kind == LightKind::spot ? glm::normalize(r.position - p) : -r.direction;
  const glm::vec3 q = read_point(r, p, n);
  const float b = depth_bias(r.bias, glm::dot(n, to_light));
  const glm::vec4 c = r.shadow * glm::vec4(q, 1.0f);
  if (r.depth.perspective) {
    if (!(c.w > 0.0f)) return false;
    st = map_st(r, q);
    if (!(st.x >= 0.0f && st.x <= 1.0f && st.y >= 0.0f && st.y <= 1.0f)) return false;
    depth = r.depth.of_view(r.view * glm::vec4(q, 1.0f)) - b;
  } else {
    st = glm::vec2(c.x, c.y);
    depth = c.z - b;
    if (!(st.x >= 0.0f && st.x <= 1.0f && st.y >= 0.0f && st.y <= 1.0f)) return lit = true, false;
  }
  // Beyond the far plane the map holds 1 (cleared): compare there, as a receiver on the far plane would.
  depth = std::min(depth, 1.0f);
  return true;
}

float filtered_visibility(const FilteredReader& r, const ShadowQuery& q) {
  glm::vec2 st;
  float d;
  bool lit;
  if (!filtered_context(r, q.p, q.n, st, d, lit)) return lit ? 1.0f : 0.0f;
  const glm::vec4 m =
      read_moments(r.moments, r.sampler, st, read_point(r, q.p, q.n), q, [&](glm::vec3 x) { return map_st(r, x); });
  return moment_visibility(r.params, m, d);
}

float filtered_visibility(const FilteredReader& r, glm::vec3 p, glm::vec3 n) {
  return filtered_visibility(r, ShadowQuery{p, n, glm::vec2(0.0f)});
}

raster::DrawStats filter_pass(raster::Renderer& renderer, const ShadowMapSet& set, size_t pass,
                              const MomentParams& params, int blur_radius, MomentMap& out) {
  const ShadowPass& p = set.passes.at(pass);
  return filter_pass(renderer, set, pass, LightDepth::of(p.proj, p.perspective), params, blur_radius, out);
}

raster::DrawStats filter_pass(raster::Renderer& renderer, const ShadowMapSet& set, size_t pass,
                              const LightDepth& light_depth, const MomentParams& params, int blur_radius,
                              MomentMap& out) {
  const ShadowPass& p = set.passes.at(pass);
  const raster::DepthTarget& depth = *set.targets.at(p.target);
  const int w = p.viewport.width, h = p.viewport.height;
  const raster::ColorFormat format = moment_format(params.kind);
  if (!out.map || out.map->width() != w || out.map->height() != h || out.map->format() != format) {
    out.map = std::make_unique<raster::ColorTarget>(w, h, format);
    out.scratch = std::make_unique<raster::ColorTarget>(w, h, format);
  }
  raster::DrawStats stats =
      encode_moments(renderer, depth, p.viewport, light_depth, params, *out.map);
  stats += blur_map(renderer, *out.map, *out.scratch, blur_radius);
  out.view = Texture2D::view(*out.map);
  // The mip chain of the blurred map (moment_lod.h): level 0 stays the target, levels 1.. are box-filtered
  // copies, each texel the mean of its four parents (mip_chain.h), built in one order whatever the threads.
  if (params.mips != MipFilter::none) out.view.generate_mips();
  return stats;
}

raster::DrawStats filter_classic_map(raster::Renderer& renderer, const ShadowMapSet& set, const ClassicLight& light,
                                     const BiasParams& bias, const MomentParams& params, int blur_radius,
                                     FilteredMap& out) {
  const ShadowPass& p = set.passes.at(0);
  FilteredReader& r = out.reader;
  r.shadow = shadow_matrix(p);
  r.view = p.view;
  r.depth = LightDepth::of(p.proj, p.perspective);
  r.kind = light.kind;
  r.position = light.position;
  r.direction = light.direction;
  r.bias = bias;
  r.params = params;
  r.sampler = moment_sampler(params.mips);
  const raster::DrawStats stats = filter_pass(renderer, set, 0, params, blur_radius, out.moments);
  r.moments = out.moments.view;
  return stats;
}

MomentParams moment_params(const ShadowConfig& c) {
  switch (c.technique) {
    case Technique::esm: return moment_params(MomentKind::esm, c);
    case Technique::evsm2: return moment_params(MomentKind::evsm2, c);
    case Technique::evsm4: return moment_params(MomentKind::evsm4, c);
    default: return moment_params(MomentKind::vsm, c);
  }
}

MomentParams moment_params(MomentKind kind, const ShadowConfig& c) {
  const Params p(c);
  MomentParams m;
  m.kind = kind;
  const std::string mips = p.text("moment_mips");
  m.mips = mips == "none" ? MipFilter::none : mips == "nearest" ? MipFilter::nearest : MipFilter::linear;
  if (m.kind == MomentKind::esm) {
    m.esm_c = float(p.number("esm_c"));
  } else if (m.kind == MomentKind::vsm) {
    m.light_bleed = float(p.number("light_bleed"));
    m.min_variance = float(p.number("min_variance"));
  } else {
    m.light_bleed = float(p.number("light_bleed"));
    m.min_variance = float(p.number("evsm_min_variance"));
    m.positive = float(p.number("evsm_positive"));
    if (m.kind == MomentKind::evsm4) m.negative = float(p.number("evsm_negative"));
  }
  return m;
}

std::optional<MomentKind> moments_param(const ShadowConfig& c) {
  const std::string kind = Params(c).text("moments");
  if (kind == "none") return std::nullopt;
  if (c.filter != FilterKind::pcf || c.filter_params.pcf_taps)
    throw TechniqueError(c.where.substr(0, c.where.size() - std::string_view("params.").size()) + "filter: " +
                         std::string(to_string(c.filter)) + " is not used with moments = " + kind +
                         " (the blurred moments are read with one bilinear lookup)");
  return kind == "esm" ? MomentKind::esm
       : kind == "vsm" ? MomentKind::vsm
       : kind == "evsm2" ? MomentKind::evsm2 : MomentKind::evsm4;
}

namespace {

class FilteredShadow final : public LightShadow {
 public:
  FilteredShadow(Technique id, const ClassicLight& light, const ClassicSettings& settings, const ClassicFit& fit,
                 const MomentParams& params, int radius)
      : id_(id), light_(light), settings_(settings), set_(plan_classic_map(light, settings, fit)), params_(params),
        radius_(radius) {}

  raster::DrawStats build(raster::Renderer& renderer, const CasterGeometry& c) override {
    raster::DrawStats stats = build_maps(renderer, set_, c, classic_depth_options(settings_));
    stats += filter_classic_map(renderer, set_, light_, settings_.bias, params_, radius_, filtered_);
    return stats;
  }
  void visibility(std::span<const ShadowQuery> q, std::span<float> vis) const override {
    for (size_t i = 0; i < q.size(); ++i) vis[i] = filtered_visibility(filtered_.reader, q[i]);
  }
  bool texel_coords(glm::vec3 p, std::span<const glm::vec3> others, std::span<glm::vec2> out) const override {
    return one_pass_texels(set_, filtered_.reader.shadow, p, others, out);
  }
  std::vector<MapRecord> maps() const override { return {one_pass_record(set_, id_)}; }

 private:
  Technique id_;
  ClassicLight light_;
  ClassicSettings settings_;
  ShadowMapSet set_;
  MomentParams params_;
  int radius_;
  FilteredMap filtered_;
};

std::unique_ptr<LightShadow> plan_filtered(const LightDesc& light, const ShadowConfig& c, const PlanInputs& in) {
  const ClassicLight l = classic_light(light);
  const ClassicSettings s = classic_settings(c);
  const ClassicFit fit{in.receivers, in.casters, std::nullopt};
  const MomentParams m = moment_params(c);
  const int radius = int(Params(c).number("blur_radius"));
  return std::make_unique<FilteredShadow>(c.technique, l, s, fit, m, radius);
}

}  // namespace

std::unique_ptr<LightShadow> plan_esm(const LightDesc& l, const ShadowConfig& c, const PlanInputs& in) {
  return plan_filtered(l, c, in);
}
std::unique_ptr<LightShadow> plan_vsm(const LightDesc& l, const ShadowConfig& c, const PlanInputs& in) {
  return plan_filtered(l, c, in);
}
std::unique_ptr<LightShadow> plan_evsm2(const LightDesc& l, const ShadowConfig& c, const PlanInputs& in) {
  return plan_filtered(l, c, in);
}
std::unique_ptr<LightShadow> plan_evsm4(const LightDesc& l, const ShadowConfig& c, const PlanInputs& in) {
  return plan_filtered(l, c, in);
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
