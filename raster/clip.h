// Homogeneous clipping of one triangle, as Mesa 22.3's llvmpipe does it (its draw module, draw_pipe_clip.c):
// against the view frustum x and y planes (llvmpipe sets no guard band: lp_context.c calls
// draw_set_driver_clipping(draw, false, false, false, true)), then near and far unless depth clamp is on
// (GL_DEPTH_CLAMP turns llvmpipe's depth clip off, and then nothing clips z or w). Sutherland–Hodgman in clip
// space with llvmpipe's float operations, so that the clipped vertices, their window positions and the fan
// match llvmpipe bit for bit: coverage of triangles crossing the viewport edges is then identical.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <glm/vec4.hpp>

#include "raster/limits.h"
#include "raster/primitive.h"
#include "raster/setup.h"
#include "raster/shader.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

template <class Varyings>
struct ClipVertex {
  glm::vec4 pos;
  Varyings var;
};

// A clip plane as the half-space dot(n, pos) + bias >= 0.
struct ClipPlane {
  glm::vec4 n;
  float bias = 0.0f;
};

// The planes a draw clips against, in llvmpipe's order (draw_context.c plane[]: the clipper takes them lowest
// bit first): x <= w, x >= −w, y <= w, y >= −w, then z >= −w (near) and z <= w (far) without depth clamp.
struct ClipPlanes {
  std::array<ClipPlane, 7> planes;
  int count = 0;
};

// The viewport arguments are unused (no guard band: x and y are clipped to the frustum, the viewport itself);
// they stay in the signature for the callers.
inline ClipPlanes make_clip_planes(bool depth_clamp, [[maybe_unused]] float vp_half_w,
                                   [[maybe_unused]] float vp_center_x, [[maybe_unused]] float vp_half_h,
                                   [[maybe_unused]] float vp_center_y) {
  ClipPlanes cp;
  cp.planes[cp.count++] = {{-1, 0, 0, 1}};  // x <= w
  cp.planes[cp.count++] = {{1, 0, 0, 1}};   // x >= -w
  cp.planes[cp.count++] = {{0, -1, 0, 1}};  // y <= w
  cp.planes[cp.count++] = {{0, 1, 0, 1}};   // y >= -w
  if (!depth_clamp) {
    cp.planes[cp.count++] = {{0, 0, 1, 1}};   // near: z + w >= 0
    cp.planes[cp.count++] = {{0, 0, -1, 1}};  // far: w − z >= 0
  }
  return cp;
}

// llvmpipe's dot4 (draw_pipe_clip.c getclipdist): ((nx·x + ny·y) + nz·z) + nw·w, each operation rounded; for
// these planes that is exactly w − x, x + w, w − y, y + w, z + w, w − z. The bias (zero here) adds nothing.
inline float plane_distance(const ClipPlane& p, const glm::vec4& v) {
  return p.n.x * v.x + p.n.y * v.y + p.n.z * v.z + p.n.w * v.w + p.bias;
}

// llvmpipe's interp() (draw_pipe_clip.c): LINTERP(t, a, b) = a + t·(b − a) for every component of the clip-space
// position and of the varyings, each operation rounded.
template <class V>
ClipVertex<V> lerp_clip_vertex(const ClipVertex<V>& a, const ClipVertex<V>& b, float t) {
  ClipVertex<V> r;
  for (int i = 0; i < 4; ++i) r.pos[i] = a.pos[i] + t * (b.pos[i] - a.pos[i]);
  if constexpr (kVaryingFloats<V> > 0) {
    constexpr int n = kVaryingFloats<V>;
    std::array<float, n> fa, fb, fr;
    std::memcpy(fa.data(), &a.var, sizeof(V));
    std::memcpy(fb.data(), &b.var, sizeof(V));
    for (int i = 0; i < n; ++i) fr[i] = fa[i] + t * (fb[i] - fa[i]);
    std::memcpy(&r.var, fr.data(), sizeof(V));
  }
  return r;
}

// Window position of a vertex the clipper made: llvmpipe computes it in C (draw_pipe_clip.c interp()),
// oow = 1/w, x_w = x·oow·scale + trans with every operation rounded (no fused multiply-add, unlike the JIT
// vertex path that to_window() reproduces).
inline WindowVertex to_window_clipped(const glm::vec4& c, const SetupParams& p) {
  const float oow = 1.0f / c.w;
  WindowVertex v;
  v.x = c.x * oow * p.vp_half_w + p.vp_center_x;
  v.y = c.y * oow * p.vp_half_h + p.vp_center_y;
  v.z = c.z * oow * 0.5f + 0.5f;
  v.inv_w = oow;
  v.sx = int32_t(std::lrint(v.x * float(kSubpixelScale)));
  v.sy = int32_t(std::lrint(v.y * float(kSubpixelScale)));
  return v;
}

// Clips the triangle against the planes whose bits are set in `planes_mask` (the union of the outcodes), as
// llvmpipe's do_clip_tri, and returns the number of polygon vertices written to `out` (0 when nothing remains or
// a distance is not finite, which makes llvmpipe drop the triangle). Bit k of *generated (when given) is set
// when out[k] was made by the clipper rather than being one of the triangle's own vertices. The polygon keeps
// the triangle's vertex order; llvmpipe fans it out as (p[k], p[k+1], p[0]), k = 1 .. n−2 (clip_fan()).
template <class V, size_t N>
int clip_polygon(const ClipPlanes& cp, unsigned planes_mask, std::array<ClipVertex<V>, N>& out,
                 const ClipVertex<V>& v0, const ClipVertex<V>& v1, const ClipVertex<V>& v2,
                 unsigned* generated = nullptr) {
  static_assert(N >= 12, "a triangle clipped by 6 planes has at most 9 vertices, plus the wrap-around slot");
  std::array<ClipVertex<V>, N> tmp;
  auto* src = &out;
  auto* dst = &tmp;
  unsigned gen_src = 0, gen_dst = 0;
  (*src)[0] = v0, (*src)[1] = v1, (*src)[2] = v2;
  int n = 3;
  for (int k = 0; k < cp.count && n >= 3; ++k) {
    if (!(planes_mask >> k & 1u)) continue;
    const ClipPlane& pl = cp.planes[k];
    (*src)[n] = (*src)[0];  // wrap around without rotating the vertices
    gen_src = (gen_src & ((1u << n) - 1u)) | ((gen_src & 1u) << n);
    float dp_prev = plane_distance(pl, (*src)[0].pos);
    if (!std::isfinite(dp_prev)) return 0;
    int m = 0;
    gen_dst = 0;
    for (int i = 1; i <= n; ++i) {
      const ClipVertex<V>& prev = (*src)[i - 1];
      const ClipVertex<V>& cur = (*src)[i];
      const float dp = plane_distance(pl, cur.pos);
      if (!std::isfinite(dp)) return 0;
      bool different_sign;
      if (dp_prev >= 0.0f) {
        gen_dst |= (gen_src >> (i - 1) & 1u) << m;
        (*dst)[m++] = prev;
        different_sign = dp < 0.0f;
      } else {
        different_sign = !(dp < 0.0f);
      }
      if (different_sign) {
        // The new vertex is interpolated from whichever end lies nearer the plane, t = its distance over the
        // distance between the two (dp − dp_prev is not zero: the signs differ).
        gen_dst |= 1u << m;
        const float denom = dp - dp_prev;
        if (dp < 0.0f) {  // going out
          (*dst)[m++] = -dp < dp_prev ? lerp_clip_vertex(cur, prev, dp / denom)
                                      : lerp_clip_vertex(prev, cur, -dp_prev / denom);
        } else {  // coming back in
          (*dst)[m++] = -dp_prev < dp ? lerp_clip_vertex(prev, cur, -dp_prev / denom)
                                      : lerp_clip_vertex(cur, prev, dp / denom);
        }
      }
      dp_prev = dp;
    }
    n = m;
    gen_src = gen_dst;
    std::swap(src, dst);
  }
  if (n < 3) return 0;
  for (int i = 0; i < n; ++i)
    if (!((*src)[i].pos.w > 0.0f)) return 0;
  if (src != &out)
    for (int i = 0; i < n; ++i) out[i] = (*src)[i];
  if (generated) *generated = gen_src;
  return n;
}

// The clipped polygon in window space, each vertex as llvmpipe computes it: the triangle's own vertices through
// to_window() (its JIT vertex path), the clipper's through to_window_clipped(). Returns the vertex count (0 if
// nothing remains).
template <class V, size_t N>
int clip_to_window(const ClipPlanes& cp, unsigned planes_mask, const SetupParams& sp,
                   std::array<ClipVertex<V>, N>& poly, std::array<WindowVertex, N>& win, const ClipVertex<V>& v0,
                   const ClipVertex<V>& v1, const ClipVertex<V>& v2) {
  unsigned generated = 0;
  const int n = clip_polygon(cp, planes_mask, poly, v0, v1, v2, &generated);
  for (int k = 0; k < n; ++k)
    win[k] = (generated >> k & 1u) ? to_window_clipped(poly[k].pos, sp) : to_window(poly[k].pos, sp);
  return n;
}

// Vertex indices of fan triangle k (1 <= k <= n − 2) of a clipped polygon, in llvmpipe's order
// (draw_pipe_clip.c emit_poly with the provoking vertex last): (p[k], p[k+1], p[0]). The order matters for the
// depth plane (setup.cpp), which llvmpipe computes from the vertices in the order it receives them.
inline std::array<int, 3> clip_fan(int k) { return {k, k + 1, 0}; }

SHADOWLAB_ISA_END
}  // namespace raster
