// The classic shadow map of the tutorial: one pass per light, orthographic for a directional light and
// perspective for a spot. Three steps, each on plain data: plan (layout + light matrices), build (the depth
// pass, with the `offset` bias and the back-face option as its draw state), read (a ClassicReader snapshotted
// once per draw and classic_visibility per fragment, per quad or, eight lanes wide, per quad pair: bias,
// projection, filter).
#pragma once
#include <array>
#include <cmath>
#include <optional>
#include <span>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "raster/renderer.h"
#include "shading/techniques/depth_pass.h"
#include "shading/techniques/light_frustum.h"
#include "shading/techniques/shadow_filters.h"
#include "shading/techniques/shadow_filters_x8.h"
#include "shading/techniques/shadow_map_set.h"
#include "shading/techniques/technique.h"
#include "shading/techniques/vocabulary.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// The projection a classic map is built with: orthographic (directional) or perspective (spot).
enum class LightKind : uint8_t { directional, spot };

// Everything the classic technique needs from a light's settings.
struct ClassicSettings {
  FilterKind filter = FilterKind::pcf;
  FilterParams filter_params;
  BiasParams bias;
  bool cull_front = false;  // render back faces only into the map (glCullFace(GL_FRONT))
  int map_size = 1024;
  raster::DepthFormat depth_format = raster::DepthFormat::d16;
};

// The light as the technique sees it.
struct ClassicLight {
  LightKind kind = LightKind::directional;
  glm::vec3 position{0.0f};                // spot
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way light travels, unit length
  float outer_angle = 0.4f;                // spot: cone half-angle, radians
  float range = 50.0f;                     // spot: far plane
};

// What a directional light's box is fitted to; `fixed` replaces the fit with given matrices (the tutorial's
// hand-made box, or its automatic frustum).
struct ClassicFit {
  Box receivers;  // e.g. camera_receiver_box(camera view-proj, scene bounds)
  Box casters;    // bounds of every shadow caster
  std::optional<LightMatrices> fixed;
};

// The light and settings of a classic map from a light's description and merged configuration: shared by every
// technique built on one classic map (shadowmap, the filtered maps, PCSS).
ClassicLight classic_light(const LightDesc& light);
ClassicSettings classic_settings(const ShadowConfig& config);

// For techniques whose set is one pass: LightShadow::texel_coords through the map matrix `shadow`, and the
// map's EXR record labelled `technique`.
bool one_pass_texels(const ShadowMapSet& set, const glm::mat4& shadow, glm::vec3 p, std::span<const glm::vec3> others,
                     std::span<glm::vec2> out);
MapRecord one_pass_record(const ShadowMapSet& set, Technique technique);

// Layout and matrices: one map of settings.map_size² in settings.depth_format.
ShadowMapSet plan_classic_map(const ClassicLight& light, const ClassicSettings& settings, const ClassicFit& fit);

// The depth pass state the settings ask for: front faces culled for `cull_front`, polygon offset for `offset`.
DepthPassOptions classic_depth_options(const ClassicSettings& settings);

// Everything a fragment needs to read a light's classic map, copied once per draw.
struct ClassicReader {
  glm::mat4 shadow{1.0f};  // bias × proj × view
  bool perspective = false;
  LightKind kind = LightKind::directional;
  glm::vec3 position{0.0f}, direction{0.0f, -1.0f, 0.0f};
  BiasParams bias;
  FilterKind filter_kind = FilterKind::pcf;
  FilterParams filter;
  MapLookups maps;
};

// The set must outlive the reader (lookups view its targets). `pass`: which of the set's passes (a cascade's
// slice); the classic map has one.
ClassicReader make_classic_reader(const ShadowMapSet& set, const ClassicLight& light, const ClassicSettings& s,
                                  size_t pass = 0);

// The depth bias subtracted from the reference for a receiver with cos(angle to the light) = ndotl.
inline float depth_bias(const BiasParams& b, float ndotl) {
  switch (b.mode) {
    case BiasMode::constant: return b.constant;
    case BiasMode::slope: {
      const float c = ndotl < 0.0f ? 0.0f : (ndotl > 1.0f ? 1.0f : ndotl);
      const float v = b.slope * std::tan(std::acos(c));
      return v < 0.0f ? 0.0f : (v > b.slope_max ? b.slope_max : v);
    }
    default: return 0.0f;
  }
}

// Where world point p with unit normal n, seen at window position frag, reads the map: its SampleContext, or
// false where a spot light leaves it unlit without a lookup (behind the light or outside its map).
inline bool classic_context(const ClassicReader& r, glm::vec3 p, glm::vec3 n, glm::vec2 frag, SampleContext& ctx) {
  const glm::vec3 to_light = r.kind == LightKind::spot ? glm::normalize(r.position - p) : -r.direction;
  const float ndotl = glm::dot(n, to_light);
  glm::vec3 q = p;
  if (r.bias.mode == BiasMode::normal) q = p + n * r.bias.normal_offset;
  const glm::vec4 c = r.shadow * glm::vec4(q, 1.0f);
  const float b = depth_bias(r.bias, ndotl);
  ctx = SampleContext{glm::vec2(c.x, c.y), c.z - b, frag, p};
  if (r.perspective) {
    // textureProj: (s, t, r − bias) · (1/q), as the tutorial's (ShadowCoord.z − bias) / ShadowCoord.w.
    if (!(c.w > 0.0f)) return false;
    const float w = 1.0f / c.w;
    ctx.st = glm::vec2(c.x * w, c.y * w);
    ctx.ref = (c.z - b) * w;
    if (!(ctx.st.x >= 0.0f && ctx.st.x <= 1.0f && ctx.st.y >= 0.0f && ctx.st.y <= 1.0f)) return false;
  }
  return true;
}

// Visibility in [0, 1] of world point p with unit normal n, seen at window position frag. A spot light leaves
// everything outside its map (and behind it) unlit; a directional map's outside reads as lit (border depth 1).
template <class Filter, bool kPcfTaps>
float classic_visibility(const ClassicReader& r, glm::vec3 p, glm::vec3 n, glm::vec2 frag) {
  SampleContext ctx;
  if (!classic_context(r, p, n, frag, ctx)) return 0.0f;
  return Filter{}(Taps<kPcfTaps>{&r.maps}, ctx, r.filter);
}

// The reader's own filter for a batch of points (a quad): the run-time choice is made once for the batch.
inline void classic_visibility(const ClassicReader& r, std::span<const ShadowQuery> q, std::span<float> vis) {
  dispatch_filter(r.filter_kind, r.filter.pcf_taps, [&]<class F, bool kPcf>() {
    for (size_t i = 0; i < q.size(); ++i) vis[i] = classic_visibility<F, kPcf>(r, q[i].p, q[i].n, q[i].frag);
  });
}

// The same for up to eight points (a quad pair), bit-identical per point: each point's context as above, then
// every tap of the filter one eight-lane lookup over the points that need one (shadow_filters_x8.h).
inline void classic_visibility_x8(const ClassicReader& r, std::span<const ShadowQuery> q, std::span<float> vis) {
  SampleLanes b;
  std::array<size_t, 8> point_of;
  for (size_t i = 0; i < q.size(); ++i) {
    if (!classic_context(r, q[i].p, q[i].n, q[i].frag, b.ctx[size_t(b.count)])) {
      vis[i] = 0.0f;
      continue;
    }
    point_of[size_t(b.count++)] = i;
  }
  if (b.count == 0) return;
  b.finish();
  alignas(32) float out[8];
  dispatch_filter(r.filter_kind, r.filter.pcf_taps,
                  [&]<class F, bool kPcf>() { filter_lanes<F, kPcf>(r.maps, b, r.filter).store(out); });
  for (int l = 0; l < b.count; ++l) vis[point_of[size_t(l)]] = out[l];
}

// The tutorial's automatic light frustum (tutorial_fit.h) over in.objects, with the parameters fit_cutoff and
// fit_smoothing (the latter through in.fit_memory, across the frames of a sequence).
LightMatrices tutorial_fit(glm::vec3 direction, const Params& p, const PlanInputs& in);

// The registry's factory (technique.h): a directional light's box is fitted to in.receivers and in.casters
// (fit = auto), is the tutorial's fixed box around the origin (fit = fixed), or is the tutorial's automatic
// light frustum (fit = tutorial).
std::unique_ptr<LightShadow> plan_classic(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);

SHADOWLAB_ISA_END
}  // namespace shading::tech
