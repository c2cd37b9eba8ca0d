// The dual-paraboloid shadow map: two hemisphere maps side by side in one target (front at the left, back at
// the right; a hemispherical light has the front one only). The projection runs per vertex: for P in the
// light's frame (z = the split plane's normal), L = |P|, p = P / L, (x, y) = p.xy / (1 + p.z) for the front
// map and p.xy / (1 − p.z) for the back map, depth = L / range; the rasterizer interpolates them linearly (so
// a long straight edge comes out as a chord of the curve it should be). Fragments of the other hemisphere are
// discarded by the interpolated ±p.z. Depth is stored as float, or also packed into RGBA8 with the
// description's base-256 four-channel pack (unpacked once after the build; identical to unpacking per fetch).
// The lookup picks the hemisphere by the sign of z and compares with an epsilon; every 2D filter works.
#pragma once
#include <cmath>
#include <span>

#include <glm/vec4.hpp>

#include "shading/techniques/omni.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// The description's mapDepthToARGB32: res = frac(value · (256³, 256², 256, 1)); res −= res.xxyz · (0, 1/256,
// 1/256, 1/256). Channel w holds the most significant digit.
inline glm::vec4 pack_depth_rgba8(float value) {
  const glm::vec4 bit_sh(256.0f * 256.0f * 256.0f, 256.0f * 256.0f, 256.0f, 1.0f);
  const glm::vec4 mask(0.0f, 1.0f / 256.0f, 1.0f / 256.0f, 1.0f / 256.0f);
  const glm::vec4 v = value * bit_sh;
  glm::vec4 res = v - glm::floor(v);
  res -= glm::vec4(res.x, res.x, res.y, res.z) * mask;
  return res;
}
// getDepthFromARGB32: dot(value, (1/256³, 1/256², 1/256, 1)).
inline float unpack_depth_rgba8(glm::vec4 value) {
  const glm::vec4 bit_sh(1.0f / (256.0f * 256.0f * 256.0f), 1.0f / (256.0f * 256.0f), 1.0f / 256.0f, 1.0f);
  return glm::dot(value, bit_sh);
}

// The paraboloid coordinates (x, y in [−1, 1]) of a light-frame position for the hemisphere `side` (+1 front,
// −1 back), and its depth L / range.
struct ParaboloidCoord {
  glm::vec2 xy;
  float depth;
  float pz;  // side · p.z: >= 0 inside this hemisphere
};
inline ParaboloidCoord paraboloid_coord(glm::vec3 P, float side, float inv_range) {
  const float L = glm::length(P);
  const glm::vec3 p = L > 0.0f ? P / L : glm::vec3(0.0f, 0.0f, side);
  const float pz = side * p.z;
  const float denom = std::fmax(1.0f + pz, 1e-6f);  // the opposite pole goes far out, never to infinity
  return {glm::vec2(p.x, p.y) / denom, L * inv_range, pz};
}

// One hemisphere's depth pass: clip position (x, y, 2 · depth − 1, 1), so window z is L / range per vertex.
template <bool kPackRgba8>
struct ParaboloidDepthShader {
  using Vertex = glm::vec3;
  struct Varyings {
    float pz;
  };
  static constexpr bool kDiscards = true;
  glm::mat4 to_light{1.0f};  // world → light frame
  float side = 1.0f, inv_range = 1.0f;
  glm::vec4 vertex(const Vertex& v, Varyings& out) const {
    const ParaboloidCoord c = paraboloid_coord(glm::vec3(to_light * glm::vec4(v, 1.0f)), side, inv_range);
    out.pz = c.pz;
    return glm::vec4(c.xy, 2.0f * c.depth - 1.0f, 1.0f);
  }
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    for (size_t l = 0; l < 4; ++l) {
      if (q.in[l].pz < 0.0f) out.discard |= uint8_t(1u << l);
      if constexpr (kPackRgba8) out.color[l] = pack_depth_rgba8(q.frag_coord[l].z);
    }
  }
};

// The frame whose z is the split plane's normal (s.split_normal, or the light's direction; a hemispherical
// light always uses its direction).
LightFrame paraboloid_frame(const OmniLight& light, const OmniSettings& s);

// Layout: a 2N × N target (N × N for a hemispherical light), passes "front" and "back"; each pass's view is
// the light frame (z mirrored for the back map) and its proj the identity (the projection is not linear).
ShadowMapSet plan_paraboloid_map(const OmniLight& light, const OmniSettings& s);

raster::DrawStats build_paraboloid_map(raster::Renderer& renderer, ShadowMapSet& set, const OmniLight& light,
                                       const OmniSettings& s, const CasterGeometry& casters);

// The stored depth of a pass as a d32f texture: a view of the depth target, or for RGBA8 packing the colour
// target unpacked texel by texel.
Texture2D paraboloid_depth_texture(const ShadowMapSet& set, size_t pass, const OmniSettings& s);

OmniReader make_paraboloid_reader(const ShadowMapSet& set, const OmniLight& light, const OmniSettings& s);

template <class Filter, bool kPcfTaps>
float paraboloid_visibility(const OmniReader& r, glm::vec3 p, glm::vec3 n, glm::vec2 frag) {
  const OmniRef o = omni_ref(r, p, n);
  const glm::vec3 P = r.frame.to_light(o.q);
  // The description's alpha = 0.5 + P.z / range >= 0.5: the front map.
  const bool front = P.z >= 0.0f;
  if (!front && !r.has_back) return 0.0f;  // behind a hemispherical light
  const ParaboloidCoord c = paraboloid_coord(P, front ? 1.0f : -1.0f, 1.0f / r.range);
  // GL's texture t grows with window y, so the description's Direct3D −0.5 on y is +0.5 here.
  const SampleContext ctx{c.xy * 0.5f + glm::vec2(0.5f), c.depth - o.bias, frag, p};
  return Filter{}(Taps<kPcfTaps>{&r.maps[front ? 0 : 1]}, ctx, r.filter);
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
