// What a fragment shader knows about its 2×2 quad beyond its varyings: window position, front-facing flag,
// helper lanes, dFdx / dFdy (fine or coarse, from raster/quad.h), and how it discards or writes depth.
// Shaders call these on raster::QuadIn / QuadOut; quad lookups (lookup.h) use the same derivatives for LOD.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "raster/quad.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

// One value per lane, lanes ordered as in raster/quad.h: 0 = (x, y), 1 = (x+1, y), 2 = (x, y+1), 3 = (x+1, y+1).
template <class T>
using Quad = std::array<T, 4>;

// fine: each row (dFdx) or column (dFdy) of the quad its own difference. coarse: one difference for the quad
// (lane 1 − lane 0, lane 2 − lane 0), as llvmpipe takes implicit derivatives, so one LOD per quad.
enum class Derivative : uint8_t { fine, coarse };

template <class T>
Quad<T> dfdx(const Quad<T>& v, Derivative d = Derivative::fine) {
  return d == Derivative::fine ? raster::dfdx_fine(v) : raster::dfdx_coarse(v);
}
template <class T>
Quad<T> dfdy(const Quad<T>& v, Derivative d = Derivative::fine) {
  return d == Derivative::fine ? raster::dfdy_fine(v) : raster::dfdy_coarse(v);
}
// GLSL's fwidth: |dFdx| + |dFdy|, for scalars and glm vectors.
template <class T>
Quad<T> fwidth(const Quad<T>& v, Derivative d = Derivative::fine) {
  const Quad<T> x = dfdx(v, d), y = dfdy(v, d);
  Quad<T> r;
  for (int l = 0; l < 4; ++l) {
    using glm::abs;
    using std::abs;
    r[l] = abs(x[l]) + abs(y[l]);
  }
  return r;
}

// A varying (a member of the shader's Varyings) gathered over the four lanes: lanes(q, &Varyings::uv).
template <class V, class T>
Quad<T> lanes(const raster::QuadIn<V>& q, T V::*member) {
  return {q.in[0].*member, q.in[1].*member, q.in[2].*member, q.in[3].*member};
}

// gl_FragCoord.xy: the pixel centre in window coordinates, origin lower-left.
template <class V>
glm::vec2 window_position(const raster::QuadIn<V>& q, int lane) {
  return {q.frag_coord[size_t(lane)].x, q.frag_coord[size_t(lane)].y};
}
// gl_FragCoord.z: window depth in [0, 1].
template <class V>
float window_depth(const raster::QuadIn<V>& q, int lane) {
  return q.frag_coord[size_t(lane)].z;
}
// gl_FrontFacing.
template <class V>
bool front_facing(const raster::QuadIn<V>& q) {
  return q.front_facing;
}
// A helper lane is shaded only so that derivatives exist; its outputs are never written.
template <class V>
bool is_helper(const raster::QuadIn<V>& q, int lane) {
  return ((q.live >> lane) & 1u) == 0;
}

// GLSL's discard for one lane (the shader must declare kDiscards).
inline void discard(raster::QuadOut& out, int lane) { out.discard = uint8_t(out.discard | (1u << lane)); }
// gl_FragDepth for one lane (the shader must declare kWritesDepth).
inline void write_depth(raster::QuadOut& out, int lane, float z) { out.depth[size_t(lane)] = z; }

SHADOWLAB_ISA_END
}  // namespace shading
