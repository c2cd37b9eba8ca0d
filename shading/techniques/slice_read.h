// Reading one map of a view-following technique (a cascade, a LiSPSM map, a frustum-face map) for a directional
// light: the bias moves the receiver towards the light by a world distance (the bias in map depth units times
// the map's depth extent, view_fit.h), so one bias setting means the same on orthographic and warped maps; then
// the projection (divided by q where the map is perspective) and the light's filter. Outside its map a point
// reads as lit (border depth 1), as the classic directional map.
#pragma once
#include <span>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "shading/techniques/classic.h"
#include "shading/techniques/shadow_filters.h"
#include "shading/techniques/shadow_map_set.h"

namespace shading::tech {

// One map as a fragment reads it; snapshotted once per frame.
struct SliceMap {
  glm::mat4 shadow{1.0f};  // bias × proj × view of its pass (viewport-relative: the lookups view the pass region)
  bool perspective = false;
  float depth_extent = 1.0f;
  glm::vec2 size{1.0f};    // texels of its pass (viewport)
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
  m.maps = map_lookups(Texture2D::view(*set.targets.at(p.target), p.viewport), Wrap::clamp_to_border);
  return m;
}

// Where point p with unit normal n reads map s: false (lit, no lookup) when p lies behind a perspective map's
// projection centre.
inline bool slice_context(const SliceMap& s, const SliceLight& l, glm::vec3 p, glm::vec3 n, glm::vec2 frag,
                          SampleContext& ctx) {
  glm::vec3 q = p;
  if (l.bias.mode == BiasMode::normal) q += n * l.bias.normal_offset;
  q -= l.direction * (depth_bias(l.bias, glm::dot(n, -l.direction)) * s.depth_extent);
  const glm::vec4 c = s.shadow * glm::vec4(q, 1.0f);
  if (!s.perspective) {
    ctx = SampleContext{glm::vec2(c.x, c.y), c.z, frag, p};
    return true;
  }
  if (!(c.w > 0.0f)) return false;
  const float w = 1.0f / c.w;
  ctx = SampleContext{glm::vec2(c.x * w, c.y * w), c.z * w, frag, p};
  return true;
}

// The continuous texel coordinates of p in map s (for the aliasing measure); false behind a perspective map's
// centre of projection.
inline bool slice_texel(const SliceMap& s, glm::vec3 p, glm::vec2& texel) {
  const glm::vec4 c = s.shadow * glm::vec4(p, 1.0f);
  if (!s.perspective) return texel = glm::vec2(c.x, c.y) * s.size, true;
  if (!(c.w > 0.0f)) return false;
  texel = glm::vec2(c.x, c.y) / c.w * s.size;
  return true;
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
float slice_visibility(const SliceMap& s, const SliceLight& l, glm::vec3 p, glm::vec3 n, glm::vec2 frag) {
  SampleContext ctx;
  if (!slice_context(s, l, p, n, frag, ctx)) return 1.0f;
  return Filter{}(Taps<kPcfTaps>{&s.maps}, ctx, l.filter);
}

}  // namespace shading::tech
