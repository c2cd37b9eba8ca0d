// Reading one map of a view-following technique (a cascade, a LiSPSM map, a frustum-face map) for a directional
// light: the bias moves the receiver towards the light by a world distance (the bias in map depth units times
// the map's depth extent, view_fit.h), so one bias setting means the same on orthographic and warped maps; then
// the projection (divided by q where the map is perspective) and the light's filter. Outside its map a point
// reads as lit (border depth 1), as the classic directional map.
#pragma once
#include <algorithm>
#include <cmath>
#include <span>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "shading/techniques/classic.h"
#include "shading/techniques/shadow_filters.h"
#include "shading/techniques/shadow_filters_x8.h"
#include "shading/techniques/shadow_map_set.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// One map as a fragment reads it; snapshotted once per frame.
struct SliceMap {
  glm::mat4 shadow{1.0f};  // bias × proj × view of its pass (viewport-relative: the lookups view the pass region)
  bool perspective = false;
  float depth_extent = 1.0f;
  glm::vec2 size{1.0f};    // texels of its pass (viewport)
  float depth_quantum = 0.0f;  // one step of its depth format in window depth (d32f: 2^-23)
  MapLookups maps;
};

// What every slice of a light shares.
struct SliceLight {
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way light travels, unit
  BiasParams bias;
  FilterKind filter_kind = FilterKind::pcf;
  FilterParams filter;
};

// The map's view over one pass of a built set, its lookups clamped to the border (lit) outside.
inline SliceMap make_slice_map(const ShadowMapSet& set, size_t pass, float depth_extent) {
  const ShadowPass& p = set.passes.at(pass);
  SliceMap m;
  m.shadow = shadow_matrix(p);
  m.perspective = p.perspective;
  m.depth_extent = depth_extent;
  m.size = glm::vec2(float(p.viewport.width), float(p.viewport.height));
  const uint32_t max_code = raster::depth_max_code(set.targets.at(p.target)->format());
  m.depth_quantum = max_code ? 1.0f / float(max_code) : 1.0f / float(1u << 23);
  m.maps = map_lookups(Texture2D::view(*set.targets.at(p.target), p.viewport), Wrap::clamp_to_border);
  return m;
}

// The plane a receiver's depth in the map follows: its triangle's, spanned by the screen derivatives of the
// position (what the map holds is the rasterized facet, not the smooth shading normal's tangent plane: on a
// tessellated sphere the two differ by a few degrees, which is the whole gradient where the facet nearly faces
// the map's depth axis), or the shading normal's where the derivatives are degenerate (a query built without
// them). Unit length.
inline glm::vec3 receiver_plane_normal(const ShadowQuery& q) {
  const glm::vec3 c = glm::cross(q.dpdx, q.dpdy);
  const float len = glm::length(c);
  return len > 1e-6f * glm::length(q.dpdx) * glm::length(q.dpdy) && std::isfinite(len) && len > 0.0f ? c / len : q.n;
}

// The slope bias on a perspective map, in its window depth: the receiver's own depth gradient in the map (the
// plane through p with normal n, receiver_plane_normal, taken through the map's projection at two points one
// hundredth of the map's depth extent away along the plane), over slope / 0.005 texels along each axis, clamped
// to slope_max, and at least two steps of the map's depth format (where texels are tiny, quantisation is all
// that is left). A warp tilts in the map a surface that faces the light in the world, so the classic
// tan(acos(N·L)) term, zero there, would leave it to acne (the receiver-plane depth bias of Isidoro, 2006).
inline float receiver_plane_bias(const SliceMap& s, const BiasParams& b, glm::vec3 p, glm::vec3 n,
                                 glm::vec3 mapped) {
  const glm::vec3 t1 = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  const glm::vec3 t2 = glm::cross(n, t1);
  const float e = 0.01f * s.depth_extent;
  auto map = [&](glm::vec3 q) {
    const glm::vec4 c = s.shadow * glm::vec4(q, 1.0f);
    return glm::vec3(c.x / c.w * s.size.x, c.y / c.w * s.size.y, c.z / c.w);
  };
  const glm::vec3 d1 = map(p + t1 * e) - mapped, d2 = map(p + t2 * e) - mapped;
  // Solve [d1.xy; d2.xy] · g = [d1.z; d2.z] for the depth gradient g per texel.
  const float det = d1.x * d2.y - d1.y * d2.x;
  if (!(std::abs(det) > 1e-12f)) return b.slope_max;
  const glm::vec2 g((d1.z * d2.y - d2.z * d1.y) / det, (d1.x * d2.z - d2.x * d1.z) / det);
  const float v = (b.slope / 0.005f) * (std::abs(g.x) + std::abs(g.y));
  return std::isfinite(v) ? std::clamp(v, 2.0f * s.depth_quantum, std::max(b.slope_max, 2.0f * s.depth_quantum))
                          : b.slope_max;
}

// Where the query's point p (unit shading normal n) reads map s: false (lit, no lookup) when p lies behind a
// perspective map's projection centre. Constant (and, on orthographic maps, slope) bias moves p towards the
// light by the bias times the map's depth extent; slope on a perspective map is receiver_plane_bias, on the
// query's triangle plane (receiver_plane_normal).
inline bool slice_context(const SliceMap& s, const SliceLight& l, const ShadowQuery& query, SampleContext& ctx) {
  const glm::vec3 p = query.p, n = query.n;
  const glm::vec2 frag = query.frag;
  glm::vec3 q = p;
  if (l.bias.mode == BiasMode::normal) q += n * l.bias.normal_offset;
  const bool plane_bias = s.perspective && l.bias.mode == BiasMode::slope;
  if (!plane_bias) q -= l.direction * (depth_bias(l.bias, glm::dot(n, -l.direction)) * s.depth_extent);
  const glm::vec4 c = s.shadow * glm::vec4(q, 1.0f);
  if (!s.perspective) {
    ctx = SampleContext{glm::vec2(c.x, c.y), c.z, frag, p};
    return true;
  }
  if (!(c.w > 0.0f)) return false;
  const float w = 1.0f / c.w;
  ctx = SampleContext{glm::vec2(c.x * w, c.y * w), c.z * w, frag, p};
  if (plane_bias)
    ctx.ref -= receiver_plane_bias(s, l.bias, p, receiver_plane_normal(query), glm::vec3(ctx.st * s.size, ctx.ref));
  return true;
}

// The continuous texel coordinates of p in map s (for the aliasing measure).
inline bool slice_texel(const SliceMap& s, glm::vec3 p, glm::vec2& texel) {
  return map_texel(s.shadow, s.perspective, s.size, p, texel);
}

// The texel coordinates of p and of `others` in map s.
inline bool slice_texels(const SliceMap& s, glm::vec3 p, std::span<const glm::vec3> others, std::span<glm::vec2> out) {
  if (!slice_texel(s, p, out[0])) return false;
  for (size_t i = 0; i < others.size(); ++i)
    if (!slice_texel(s, others[i], out[i + 1])) return false;
  return true;
}

// Visibility of p in map s with the light's filter F (dispatch_filter picks F once per batch).
template <class Filter, bool kPcfTaps>
float slice_visibility(const SliceMap& s, const SliceLight& l, const ShadowQuery& q) {
  SampleContext ctx;
  if (!slice_context(s, l, q, ctx)) return 1.0f;
  return Filter{}(Taps<kPcfTaps>{&s.maps}, ctx, l.filter);
}

// The same for the points q[i], i in `which` (up to eight), all reading map s, eight lanes wide: each point's
// context as above, then every tap of the filter one eight-lane lookup (shadow_filters_x8.h); bit-identical per
// point to slice_visibility. Writes vis[i] for each i in `which`.
template <class Filter, bool kPcfTaps>
void slice_visibility_x8(const SliceMap& s, const SliceLight& l, std::span<const ShadowQuery> q,
                         std::span<const size_t> which, std::span<float> vis) {
  SampleLanes b;
  std::array<size_t, 8> point_of;
  for (const size_t i : which) {
    if (!slice_context(s, l, q[i], b.ctx[size_t(b.count)])) {
      vis[i] = 1.0f;
      continue;
    }
    point_of[size_t(b.count++)] = i;
  }
  if (b.count == 0) return;
  b.finish();
  alignas(32) float out[8];
  filter_lanes<Filter, kPcfTaps>(s.maps, b, l.filter).store(out);
  for (int k = 0; k < b.count; ++k) vis[point_of[size_t(k)]] = out[k];
}

// Eight-wide visibility of a batch whose points each read one map, map_of(i): the points are grouped by map
// (a quad pair rarely spans two) and each group read by slice_visibility_x8.
template <class Filter, bool kPcfTaps, class MapOf>
void slices_visibility_x8(std::span<const SliceMap> maps, const SliceLight& l, std::span<const ShadowQuery> q,
                          MapOf&& map_of, std::span<float> vis) {
  std::array<size_t, 8> map{}, group{};
  for (size_t i = 0; i < q.size(); ++i) map[i] = map_of(i);
  std::array<bool, 8> done{};
  for (size_t i = 0; i < q.size(); ++i) {
    if (done[i]) continue;
    size_t n = 0;
    for (size_t j = i; j < q.size(); ++j)
      if (!done[j] && map[j] == map[i]) group[n++] = j, done[j] = true;
    slice_visibility_x8<Filter, kPcfTaps>(maps[map[i]], l, q, std::span<const size_t>(group.data(), n), vis);
  }
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
