// The pyramid shadow map of a 180° light: one square depth target split along its diagonals into four
// triangles, each filled by one pass whose camera is the light's frame tilted 45° (about x for passes 1 and 3,
// about y for 2 and 4) with fovY 90° and fovX 2·atan(√2) (swapped for passes 2 and 4), rendering into the
// top, right, bottom or left half. A pass keeps only fragments whose direction's major axis is its own, and
// stores the radial distance / range. Reading maps the light-space position to its region with the
// description's four branches and samples with legacy GL_CLAMP, so every 2D filter works unchanged; a point
// behind the light's hemisphere is unlit.
//
// In every region the four branches reduce to (s, t) = 0.5 + (x, y) / (2 (max(|x|, |y|) + z)): texture
// space is the light-space direction scaled along rays from the centre. The discard test therefore runs on
// the pixel centre's offset from the map's centre, which is exact in floats (half-integers), and the four
// passes partition the texels exactly with the lookup's tie order: no texel is left to no pass (no seams).
#pragma once
#include <cmath>
#include <span>

#include "shading/techniques/omni.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// The region (0..3 for passes 1..4) the lookup's branches give a light-space (x, y); ties go to the first
// branch that accepts them, as in the description's if/else chain.
inline int pyramid_region(float x, float y) {
  if (y >= std::fabs(x)) return 0;
  if (x >= std::fabs(y)) return 1;
  if (-y >= std::fabs(x)) return 2;
  return 3;
}

// The description's lookup: light-space position → map coordinates (s, t), for z > 0.
inline glm::vec2 pyramid_st(glm::vec3 sp) {
  glm::vec2 st;
  if (sp.y >= std::fabs(sp.x)) {
    st = glm::vec2(sp.x, sp.y - sp.z) * (1.0f / (sp.y + sp.z));
    st = st * glm::vec2(0.5f, 0.25f) + glm::vec2(0.5f, 0.75f);
  } else if (sp.x >= std::fabs(sp.y)) {
    st = glm::vec2(sp.x - sp.z, sp.y) * (1.0f / (sp.x + sp.z));
    st = st * glm::vec2(0.25f, 0.5f) + glm::vec2(0.75f, 0.5f);
  } else if (-sp.y >= std::fabs(sp.x)) {
    st = glm::vec2(sp.x, sp.y + sp.z) * (1.0f / (sp.z - sp.y));
    st = st * glm::vec2(0.5f, 0.25f) + glm::vec2(0.5f, 0.25f);
  } else {  // -sp.x >= |sp.y|
    st = glm::vec2(sp.x + sp.z, sp.y) * (1.0f / (sp.z - sp.x));
    st = st * glm::vec2(0.25f, 0.5f) + glm::vec2(0.25f, 0.5f);
  }
  return st;
}

// The pass camera of region k in the light's frame: forward and up directions (light-frame coordinates), the
// vertical fov and aspect (tan(fovX/2) / tan(fovY/2)), and the viewport in a size × size map.
struct PyramidPassCamera {
  glm::vec3 forward, up;
  float fov_y, aspect;
  raster::Rect viewport;
};
PyramidPassCamera pyramid_pass_camera(int region, int size);

// Layout and matrices: one size × size target, passes "1 top", "2 right", "3 bottom", "4 left".
ShadowMapSet plan_pyramid_map(const OmniLight& light, const OmniSettings& s);

// Pass k's radial-distance shader with the major-axis discard.
struct PyramidDepthShader {
  using Vertex = glm::vec3;
  using Varyings = RadialDepthShader::Varyings;
  static constexpr bool kWritesDepth = true;
  static constexpr bool kDiscards = true;
  RadialDepthShader radial;
  int region = 0;
  float center = 0.0f;  // size / 2 in window pixels
  glm::vec4 vertex(const Vertex& v, Varyings& out) const { return radial.vertex(v, out); }
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    radial.fragment(q, out);
    for (size_t l = 0; l < 4; ++l)
      if (pyramid_region(q.frag_coord[l].x - center, q.frag_coord[l].y - center) != region)
        out.discard |= uint8_t(1u << l);
  }
};

raster::DrawStats build_pyramid_map(raster::Renderer& renderer, ShadowMapSet& set, const OmniLight& light,
                                    const OmniSettings& s, const CasterGeometry& casters);

// Samplers with legacy GL_CLAMP on both axes; the border depth is 1 (nothing there: lit).
OmniReader make_pyramid_reader(const ShadowMapSet& set, const OmniLight& light, const OmniSettings& s);

template <class Filter, bool kPcfTaps>
float pyramid_visibility(const OmniReader& r, glm::vec3 p, glm::vec3 n, glm::vec2 frag) {
  const OmniRef o = omni_ref(r, p, n);
  const glm::vec3 sp = r.frame.to_light(o.q);
  if (!(sp.z > 0.0f)) return 0.0f;  // behind the light's hemisphere (or on its plane): unlit
  const float ref = glm::length(sp) / r.range - o.bias;
  const SampleContext ctx{pyramid_st(sp), ref, frag, p};
  return Filter{}(Taps<kPcfTaps>{&r.maps[0]}, ctx, r.filter);
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
