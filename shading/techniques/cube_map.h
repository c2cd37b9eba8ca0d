// The cube shadow map of a point light: six 90° passes, one per face in GL's order, laid out side by side in
// one depth target (3 × 2 faces, face f at column f % 3, row f / 3), each storing the radial distance
// |P − light| / range written by the fragment shader. Read by the light-to-fragment direction with GL's face
// selection (shading/cube_face.h), seamless filtering on or off, and an epsilon (the bias) on the compare.
#pragma once
#include <span>

#include "shading/lookup_cube.h"
#include "shading/techniques/filtered.h"
#include "shading/techniques/omni.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// Layout and matrices: a 3N × 2N target, six passes labelled +X, −X, +Y, −Y, +Z, −Z with
// view = cube_face_view(face, light) and proj = perspective(90°, 1, near, range).
ShadowMapSet plan_cube_map(const OmniLight& light, const OmniSettings& s);

raster::DrawStats build_cube_map(raster::Renderer& renderer, ShadowMapSet& set, const OmniLight& light,
                                 const OmniSettings& s, const CasterGeometry& casters);

// The faces as a TextureCube of views into the set's target.
TextureCube cube_texture(const ShadowMapSet& set);

OmniReader make_cube_reader(const ShadowMapSet& set, const OmniLight& light, const OmniSettings& s);

// The faces turned filterable (the cube's `moments` parameter): each face's radial distance (already linear,
// distance / range) encoded into its own moment target of the face's size and blurred there, so the blur clamps
// at the face's edges and does not reach into the neighbouring face; read with one bilinear lookup of the cube
// of the six moment maps (seamless across the edges when `seamless` is on, as the depth cube's lookups) and the
// kind's visibility formula against distance / range minus the bias.
struct CubeMoments {
  MomentParams params;
  int blur_radius = 2;
  std::array<MomentMap, 6> faces;
  TextureCube cube;  // views of the six blurred faces and their mips (each face's own), after build
  Sampler sampler = Sampler::plain(Filter::linear, Wrap::clamp_to_edge);
};

// Encodes and blurs the six faces of a built cube map set into m.faces and sets up m.cube.
raster::DrawStats build_cube_moments(raster::Renderer& renderer, const ShadowMapSet& set, bool seamless,
                                     CubeMoments& m);

// Visibility of a query's point from the faces' moments, at the level of detail of its screen derivatives (the
// cube's mips, MomentParams::mips): 0 behind a hemispherical light.
float cube_moment_visibility(const OmniReader& r, const CubeMoments& m, const ShadowQuery& q);

// Taps for the Poisson family on a cube: st are the face coordinates of the query's face; a tap at st + offset
// goes back to a direction on that face's plane and is looked up like any other (a seamless lookup then reads
// across the edge, a non-seamless one clamps to the face).
template <bool kPcf>
struct CubeTaps {
  const OmniReader* r;
  int face;
  glm::vec3 dir;  // the query's own direction (offset 0 reads exactly it)
  float operator()(const SampleContext& c, glm::vec2 offset) const {
    glm::vec3 d = dir;
    if (offset != glm::vec2(0.0f)) {
      const CubeFaceAxes& a = kCubeFaceAxes[face];
      const float u = 2.0f * (c.st.x + offset.x) - 1.0f, v = 2.0f * (c.st.y + offset.y) - 1.0f;
      d = glm::vec3(a.major) + u * glm::vec3(a.s_axis) + v * glm::vec3(a.t_axis);
    }
    return texture_at(r->cube, kPcf ? r->cube_linear : r->cube_nearest, glm::vec4(d, c.ref), 0.0f);
  }
};

// Visibility of world point p (unit normal n) from a cube map: 0 behind a hemispherical light.
template <class Filter, bool kPcfTaps>
float cube_visibility(const OmniReader& r, glm::vec3 p, glm::vec3 n, glm::vec2 frag) {
  const OmniRef o = omni_ref(r, p, n);
  const glm::vec3 d = o.q - r.position;
  if (r.hemispherical && glm::dot(d, r.direction) < 0.0f) return 0.0f;
  const float ref = glm::length(d) / r.range - o.bias;
  if constexpr (std::is_same_v<Filter, PcfFilter>) {
    return texture_at(r.cube, r.cube_linear, glm::vec4(d, ref), 0.0f);
  } else if constexpr (std::is_same_v<Filter, HardFilter>) {
    return texture_at(r.cube, kPcfTaps ? r.cube_linear : r.cube_nearest, glm::vec4(d, ref), 0.0f);
  } else {
    const CubeCoord cc = cube_coord(d);
    const SampleContext ctx{glm::vec2(cc.s, cc.t), ref, frag, p};
    return Filter{}(CubeTaps<kPcfTaps>{&r, cc.face, d}, ctx, r.filter);
  }
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
