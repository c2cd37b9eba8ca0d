// How a caster's projective map is read: texgen (the light's bias × proj × view applied to the world
// position), textureProj with clamped coordinates so everything outside the map reads its white edge, the mip
// chain read with a LOD bias for blur, a fade with distance behind the caster (a linear ramp, or a LINEAR lookup
// of a 1-D fade table, fade_table.h), and "correct side only" (q <= 0,
// or a point nearer the light than the caster's near side, gets no shadow from it). One ProjectiveReader is
// snapshotted per draw; projective_factors() runs per 2×2 quad (quad derivatives choose the mip level).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "shading/fragment.h"
#include "shading/lookup.h"
#include "shading/techniques/fade_table.h"
#include "shading/techniques/projective_map.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

struct ProjectiveReader {
  glm::mat4 texgen{1.0f};
  glm::vec4 depth_row{0.0f};
  float near_depth = 0.0f;
  float fade_start = 0.0f, fade_end = 0.0f;
  Texture2D fade_table;  // empty: the formula's ramp; else the fade texture (fade_lookup = texture)
  Texture2D texture;  // views the CasterMap's target: the map must outlive the reader
  Sampler sampler;
};

// The map's lookup: LINEAR, clamp to edge (the white ring makes the clamp a no-op outside the map), mipmapped
// LINEAR with the settings' LOD bias when the plan has mip levels, λ clamped to the levels whose edge is white.
// With fade_lookup = texture the reader reads `fade_table` (shared by a light's casters: make it once with
// make_fade_texture), or, when that is empty, a texture of its own made from the settings' table.
inline ProjectiveReader make_projective_reader(const CasterMap& map, const ProjectiveSettings& s,
                                               const Texture2D& fade_table = {}) {
  ProjectiveReader r;
  r.texgen = map.frustum.texgen;
  r.depth_row = map.frustum.depth_row;
  r.near_depth = map.frustum.near_depth;
  r.fade_start = s.fade_start;
  r.fade_end = s.fade_end;
  if (s.fade_lookup == FadeLookup::texture && s.fade_end > s.fade_start)
    r.fade_table = fade_table.empty() ? make_fade_texture(s.fade_table) : fade_table;
  r.texture = map.texture;
  r.sampler = Sampler::plain(Filter::linear, Wrap::clamp_to_edge,
                             map.mips.max_level > 0 ? MipFilter::linear : MipFilter::none);
  r.sampler.lod_bias = map.mips.max_level > 0 ? s.lod_bias : 0.0f;
  r.sampler.max_lod = float(map.mips.max_level);
  return r;
}

// What a frame buffer of 8-bit unorm channels keeps of v: GL's conversion on write (clamp, round to nearest)
// and back on read. Single-pass application runs its texture stages at this precision, as the multi-stage
// combiners of the time did, so it reproduces the multiply-blended passes exactly.
inline float unorm8(float v) {
  const float c = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
  return float(uint8_t(std::nearbyint(c * 255.0f))) / 255.0f;
}

// The factor a receiver's colour is multiplied by at the four lanes of a quad with world positions `p`:
// 1 where the caster does not shadow, the map's grey (faded towards 1 with distance) where it does.
inline Quad<float> projective_factors(const ProjectiveReader& r, const Quad<glm::vec3>& p) {
  Quad<glm::vec3> stq;
  Quad<float> depth;
  for (size_t l = 0; l < 4; ++l) {
    const glm::vec4 w(p[l], 1.0f);
    const glm::vec4 c = r.texgen * w;
    stq[l] = glm::vec3(c.x, c.y, c.w);
    depth[l] = glm::dot(r.depth_row, w);
  }
  // Quick reject: no lane lands inside the map on the shadowed side. Outside the map the clamped lookup reads
  // white edge texels at every level it may use, and LINEAR's v0 + w · (v1 − v0) of equal texels is exactly
  // that texel, so every lane's factor is exactly 1: skipping the lookup changes nothing.
  bool any = false;
  for (size_t l = 0; l < 4; ++l) {
    const float q = stq[l].z;
    any |= q > 0.0f && depth[l] >= r.near_depth && stq[l].x >= 0.0f && stq[l].x <= q && stq[l].y >= 0.0f &&
           stq[l].y <= q;
  }
  if (!any) return {1.0f, 1.0f, 1.0f, 1.0f};
  const Quad<glm::vec4> mask = texture_proj(r.texture, r.sampler, stq, Derivative::coarse);
  Quad<float> f;
  for (size_t l = 0; l < 4; ++l) {
    if (!(stq[l].z > 0.0f) || depth[l] < r.near_depth) {  // behind the projector, or on the light's side
      f[l] = 1.0f;
      continue;
    }
    float v = mask[l].r;
    if (r.fade_end > r.fade_start) {
      const float t = std::clamp((depth[l] - r.near_depth - r.fade_start) / (r.fade_end - r.fade_start), 0.0f, 1.0f);
      v = v + (1.0f - v) * (r.fade_table.empty() ? t : fade_at(r.fade_table, t));
    }
    f[l] = v;
  }
  return f;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
