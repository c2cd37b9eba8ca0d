// Cascaded shadow maps and LiSPSM: planning the slices, reading them per pixel (see cascades.h).
#include "shading/techniques/cascades.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "shading/lookup.h"
#include "shading/techniques/filtered.h"
#include "shading/techniques/moment_lod.h"
#include "shading/techniques/pcss.h"
#include "shading/techniques/slice_set.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

Box merged(const Box& a, const Box& b) { return Box{glm::min(a.min, b.min), glm::max(a.max, b.max)}; }

// Rounds x > 0 up to a multiple of 1/64 of the power of two below it: small changes of x (a camera moving by a
// fraction of a texel) leave it unchanged, so a stabilised map keeps its size.
float quantize_up(float x) {
  if (!(x > 0.0f)) return x;
  const float step = std::exp2(std::floor(std::log2(x))) / 64.0f;
  return std::ceil(x / step) * step;
}

// Centre (world) and radius of a slice's bounding sphere, the radius from view-space corners only (so it does not
// change as the camera moves or turns) and quantised up.
void slice_sphere(const CameraView& cam, float a, float b, glm::vec3& centre, float& radius) {
  CameraView local = cam;
  local.view = glm::mat4(1.0f);
  const auto corners = slice_corners(local, a, b);
  glm::vec3 c(0.0f);
  for (const glm::vec3& p : corners) c += p / 8.0f;
  float r = 0.0f;
  for (const glm::vec3& p : corners) r = std::max(r, glm::length(p - c));
  radius = quantize_up(r);
  centre = glm::vec3(glm::inverse(cam.view) * glm::vec4(c, 1.0f));
}

}  // namespace

CascadePlan plan_cascade_fits(const LightDesc& light, const CascadeSettings& s, int map_size, const PlanInputs& in) {
  const CameraView& cam = in.camera;
  const VisibleSamples* visible = nullptr;
  ViewRange range;
  if (s.visible) {
    if (!in.visible) throw std::logic_error("plan_cascade_fits: visible fitting without visible samples");
    visible = &in.visible();
    range = visible_view_range(cam, *visible);
  } else {
    range = receiver_view_range(cam, in.receivers);
  }
  if (s.stabilize && !s.visible) range = ViewRange{cam.near, std::min(cam.far, quantize_up(range.far))};

  CascadePlan plan;
  plan.splits = practical_splits(range.near, range.far, s.count, s.lambda);
  const Box scene = merged(in.casters, in.scene_receivers);
  std::vector<glm::vec3> points;
  for (int k = 0; k < s.count; ++k) {
    const float a = plan.splits[size_t(k)], b = plan.splits[size_t(k) + 1];
    const auto corners = slice_corners(cam, a, b);
    // The slice's receivers: the slice clipped to the receivers' bounds (its corners when they do not meet).
    const std::vector<glm::vec3> clipped = clip_slice_to_box(corners, in.scene_receivers);
    std::span<const glm::vec3> body = corners;
    if (!clipped.empty()) body = clipped;
    if (visible) {
      points.clear();
      visible_body(cam, *visible, a, b, points);
      if (!points.empty()) body = points;
    }
    if (s.lispsm) {
      plan.fits.push_back(fit_lispsm(light.direction, body, in.casters, cam, a, b));
    } else if (s.stabilize) {
      glm::vec3 centre;
      float radius;
      slice_sphere(cam, a, b, centre, radius);
      plan.fits.push_back(fit_stable(light.direction, centre, radius, map_size, scene));
    } else {
      plan.fits.push_back(fit_ortho(light.direction, body, in.casters));
    }
  }
  return plan;
}

SliceChoice choose_slice(std::span<const float> splits, float blend, float distance) {
  const size_t m = splits.size() - 1;
  SliceChoice c;
  while (c.slice + 1 < m && distance >= splits[c.slice + 1]) ++c.slice;
  if (blend > 0.0f && c.slice + 1 < m) {
    const float end = splits[c.slice + 1], band = blend * (end - splits[c.slice]);
    if (distance > end - band) c.next_weight = std::min(1.0f, (distance - (end - band)) / band);
  }
  return c;
}

namespace {

// Moment maps of the slices (the cascades' `moments` parameter): each slice's depth map encoded and blurred on
// its own, read with one bilinear lookup and the kind's visibility formula instead of the light's filter.
struct SliceMoments {
  MomentParams params;
  int blur_radius = 2;
  std::vector<MomentMap> maps;  // one per slice, after build, with their mip chains
  Sampler sampler = moment_sampler(MipFilter::linear);  // moment_sampler(params.mips)
};

// PCSS on the slices (`soft_shadows = pcss`): one reader per slice over its own pass (make_pcss_reader), so the
// light's angular diameter is turned into each slice's map coordinates with that slice's projection and the
// penumbra in metres does not depend on which slice a point falls in. The slices are orthographic with the
// classic depth-pass state, and a constant or slope bias in window depth there is the slices' own bias (depth
// units times the slice's depth extent, as a world distance along the light).
struct SlicePcss {
  ClassicLight light;
  ClassicSettings settings;
  float angle = 1.0f;  // degrees
  std::vector<PcssReader> readers;  // one per slice, after build
};

class CascadeShadow final : public LightShadow {
 public:
  CascadeShadow(Technique t, CascadePlan plan, const CascadeSettings& s, const LightDesc& light,
                const ShadowConfig& c, const CameraView& camera, std::optional<SliceMoments> moments,
                std::optional<SlicePcss> pcss = std::nullopt)
      : splits_(std::move(plan.splits)), blend_(s.blend), camera_(camera),
        set_(t, plan.fits, labels(t, plan.fits.size()), light, c, s.atlas), moments_(std::move(moments)),
        pcss_(std::move(pcss)) {}

  raster::DrawStats build(raster::Renderer& renderer, const CasterGeometry& c) override {
    raster::DrawStats stats = set_.build(renderer, c);
    if (moments_) {
      moments_->maps.resize(set_.size());
      for (size_t k = 0; k < set_.size(); ++k)
        stats += filter_pass(renderer, set_.set(), k, moments_->params, moments_->blur_radius, moments_->maps[k]);
    }
    if (pcss_) {
      pcss_->readers.clear();
      for (size_t k = 0; k < set_.size(); ++k)
        pcss_->readers.push_back(make_pcss_reader(set_.set(), pcss_->light, pcss_->settings, pcss_->angle, k));
    }
    return stats;
  }

  void visibility(std::span<const ShadowQuery> q, std::span<float> vis) const override {
    if (moments_ || pcss_) {
      for (size_t i = 0; i < q.size(); ++i) {
        const SliceChoice c = choose_slice(splits_, blend_, view_distance(camera_, q[i].p));
        float v = own_slice_visibility(c.slice, q[i]);
        if (c.next_weight > 0.0f) v += c.next_weight * (own_slice_visibility(c.slice + 1, q[i]) - v);
        vis[i] = v;
      }
      return;
    }
    const SliceLight& l = set_.light();
    dispatch_filter(l.filter_kind, l.filter.pcf_taps, [&]<class F, bool kPcf>() {
      for (size_t i = 0; i < q.size(); ++i) {
        const SliceChoice c = choose_slice(splits_, blend_, view_distance(camera_, q[i].p));
        float v = slice_visibility<F, kPcf>(set_.map(c.slice), l, q[i]);
        if (c.next_weight > 0.0f)
          v += c.next_weight * (slice_visibility<F, kPcf>(set_.map(c.slice + 1), l, q[i]) - v);
        vis[i] = v;
      }
    });
  }

  // Eight wide: the points of the pair grouped by slice; points in a blend band read their next slice too.
  // Moment maps and PCSS are read point by point.
  void visibility_x8(std::span<const ShadowQuery> q, std::span<float> vis) const override {
    if (moments_ || pcss_) return visibility(q, vis);
    const SliceLight& l = set_.light();
    std::array<SliceChoice, 8> c;
    bool blends = false;
    for (size_t i = 0; i < q.size(); ++i) {
      c[i] = choose_slice(splits_, blend_, view_distance(camera_, q[i].p));
      blends |= c[i].next_weight > 0.0f;
    }
    dispatch_filter(l.filter_kind, l.filter.pcf_taps, [&]<class F, bool kPcf>() {
      slices_visibility_x8<F, kPcf>(set_.maps(), l, q, [&](size_t i) { return c[i].slice; }, vis);
      if (!blends) return;
      std::array<float, 8> next{};
      slices_visibility_x8<F, kPcf>(set_.maps(), l, q,
                                    [&](size_t i) { return std::min(c[i].slice + 1, splits_.size() - 2); },
                                    std::span<float>(next.data(), q.size()));
      for (size_t i = 0; i < q.size(); ++i)
        if (c[i].next_weight > 0.0f) vis[i] += c[i].next_weight * (next[i] - vis[i]);
    });
  }

  std::vector<MapRecord> maps() const override { return set_.records(); }

  bool texel_coords(glm::vec3 p, std::span<const glm::vec3> others, std::span<glm::vec2> out) const override {
    const SliceChoice c = choose_slice(splits_, 0.0f, view_distance(camera_, p));
    return slice_texels(set_.map(c.slice), p, others, out);
  }

 private:
  static std::vector<std::string> labels(Technique t, size_t n) {
    std::vector<std::string> out;
    for (size_t k = 0; k < n; ++k) out.push_back(t == Technique::lispsm ? "lispsm" : "cascade" + std::to_string(k));
    return out;
  }

  // Slice k's own reading where the slices are not read through the light's filter: PCSS or the moments.
  float own_slice_visibility(size_t k, const ShadowQuery& q) const {
    if (pcss_) return pcss_visibility(pcss_->readers[k], q.p, q.n, q.frag);
    return moment_slice_visibility(k, q);
  }

  // Slice k's moment map at the point: the depth slice_context gives (bias applied as for the depth maps) against
  // the filtered moments, read at the level of detail of the point's derivatives in that slice's map (each slice
  // has its own texel size, so its own level); lit outside the map, as the depth maps' border.
  float moment_slice_visibility(size_t k, const ShadowQuery& q) const {
    const SliceMap& s = set_.map(k);
    SampleContext ctx;
    if (!slice_context(s, set_.light(), q, ctx)) return 1.0f;
    if (!(ctx.st.x >= 0.0f && ctx.st.x <= 1.0f && ctx.st.y >= 0.0f && ctx.st.y <= 1.0f)) return 1.0f;
    const glm::vec4 m = read_moments(moments_->maps[k].view, moments_->sampler, ctx.st, q.p, q, [&](glm::vec3 x) {
      const glm::vec4 c = s.shadow * glm::vec4(x, 1.0f);  // orthographic: moments refuse LiSPSM slices
      return glm::vec2(c.x, c.y);
    });
    return moment_visibility(moments_->params, m, std::min(ctx.ref, 1.0f));
  }

  std::vector<float> splits_;
  float blend_;
  CameraView camera_;
  SliceSet set_;
  std::optional<SliceMoments> moments_;
  std::optional<SlicePcss> pcss_;
};

}  // namespace

std::unique_ptr<LightShadow> plan_cascades(const LightDesc& light, const ShadowConfig& c, const PlanInputs& in) {
  const Params p(c);
  CascadeSettings s;
  s.count = int(p.number("cascades"));
  s.lambda = float(p.number("split_lambda"));
  s.stabilize = p.flag("stabilize");
  s.blend = float(p.number("cascade_blend"));
  s.atlas = p.text("map_layout") == "atlas";
  s.visible = p.text("view_range") == "visible";
  s.lispsm = p.text("cascade_warp") == "lispsm";
  if (s.visible && !in.visible) throw TechniqueError(p.where("view_range") + ": visible needs the camera's depth pre-pass");
  if (s.stabilize && s.visible)
    throw TechniqueError(p.where("stabilize") + ": a visible view range (view_range = visible) follows what the "
                                                "camera sees from frame to frame and cannot be stabilised");
  if (s.stabilize && s.lispsm)
    throw TechniqueError(p.where("stabilize") + ": a LiSPSM warp (cascade_warp = lispsm) changes with every view "
                                                "and cannot be stabilised");
  std::optional<SliceMoments> moments;
  if (const std::string kind = p.text("moments"); kind != "none" && s.lispsm)
    throw TechniqueError(p.where("moments") + ": " + kind + " needs orthographic slices; a LiSPSM warp "
                         "(cascade_warp = lispsm) stores a depth that is not linear along the light");
  if (const std::optional<MomentKind> k = moments_param(c)) {
    moments.emplace();
    moments->params = moment_params(*k, c);
    moments->sampler = moment_sampler(moments->params.mips);
    moments->blur_radius = int(p.number("blur_radius"));
  }
  std::optional<SlicePcss> pcss;
  if (p.text("soft_shadows") == "pcss") {
    if (moments)
      throw TechniqueError(p.where("soft_shadows") + ": pcss and moments = " + p.text("moments") +
                           " both replace the filter; choose one");
    if (s.lispsm)
      throw TechniqueError(p.where("soft_shadows") + ": pcss needs orthographic slices; a LiSPSM warp "
                           "(cascade_warp = lispsm) has no single texel size or depth scale per slice");
    if (c.filter != FilterKind::pcf || c.filter_params.pcf_taps)
      throw TechniqueError(c.where.substr(0, c.where.size() - std::string_view("params.").size()) + "filter: " +
                           std::string(to_string(c.filter)) +
                           " is not used with soft_shadows = pcss (PCSS filters with its own kernel)");
    pcss.emplace();
    pcss->light = classic_light(light);
    pcss->settings = classic_settings(c);
    pcss->angle = float(p.number("light_angle"));
  }
  CascadePlan plan = plan_cascade_fits(light, s, c.map_size, in);
  return std::make_unique<CascadeShadow>(Technique::cascades, std::move(plan), s, light, c, in.camera,
                                         std::move(moments), std::move(pcss));
}

std::unique_ptr<LightShadow> plan_lispsm(const LightDesc& light, const ShadowConfig& c, const PlanInputs& in) {
  CascadeSettings s;
  s.count = 1;
  s.lispsm = true;
  const Params p(c);
  s.visible = p.text("view_range") == "visible";
  if (s.visible && !in.visible) throw TechniqueError(p.where("view_range") + ": visible needs the camera's depth pre-pass");
  CascadePlan plan = plan_cascade_fits(light, s, c.map_size, in);
  return std::make_unique<CascadeShadow>(Technique::lispsm, std::move(plan), s, light, c, in.camera, std::nullopt);
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
