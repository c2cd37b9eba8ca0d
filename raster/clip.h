// Homogeneous clipping of one triangle against near and far (or w > 0 under depth clamp) and the x/y guard band,
// Sutherland–Hodgman in clip space with varyings interpolated linearly there. The result is a convex polygon
// emitted as a fan in the original vertex order, so primitive order and winding are preserved.
#pragma once
#include <array>
#include <cstring>

#include <glm/vec4.hpp>

#include "raster/limits.h"
#include "raster/shader.h"

namespace raster {

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

// Under depth clamp, vertices are kept only where w >= kMinClipW (clip-space units), so 1/w stays finite.
inline constexpr float kMinClipW = 1e-6f;

// The planes a draw clips against, derived once per draw from the viewport (guard band in window space).
struct ClipPlanes {
  std::array<ClipPlane, 7> planes;
  int count = 0;
};

inline ClipPlanes make_clip_planes(bool depth_clamp, float vp_half_w, float vp_center_x, float vp_half_h,
                                   float vp_center_y) {
  ClipPlanes cp;
  if (depth_clamp) {
    cp.planes[cp.count++] = {{0, 0, 0, 1}, -kMinClipW};  // w >= kMinClipW
  } else {
    cp.planes[cp.count++] = {{0, 0, 1, 1}};   // near: z + w >= 0
    cp.planes[cp.count++] = {{0, 0, -1, 1}};  // far: w − z >= 0
  }
  // Guard band: −G <= x_w <= G with x_w = (x/w)·hw + cx  ⇔  x·hw + (cx + G)·w >= 0 and −x·hw + (G − cx)·w >= 0.
  const float G = kGuardBandClip;
  cp.planes[cp.count++] = {{vp_half_w, 0, 0, vp_center_x + G}};
  cp.planes[cp.count++] = {{-vp_half_w, 0, 0, G - vp_center_x}};
  cp.planes[cp.count++] = {{0, vp_half_h, 0, vp_center_y + G}};
  cp.planes[cp.count++] = {{0, -vp_half_h, 0, G - vp_center_y}};
  return cp;
}

inline float plane_distance(const ClipPlane& p, const glm::vec4& v) {
  return p.n.x * v.x + p.n.y * v.y + p.n.z * v.z + p.n.w * v.w + p.bias;
}

// Bit k set when the vertex is outside plane k (or, for the w plane, not strictly in front of the eye).
inline unsigned outcode(const ClipPlanes& cp, const glm::vec4& v) {
  unsigned code = 0;
  for (int k = 0; k < cp.count; ++k) {
    const float d = plane_distance(cp.planes[k], v);
    if (!(d >= 0.0f)) code |= 1u << k;  // NaN counts as outside
  }
  if (!(v.w > 0.0f)) code |= 1u << cp.count;
  return code;
}

template <class V>
ClipVertex<V> lerp_clip_vertex(const ClipVertex<V>& a, const ClipVertex<V>& b, float t) {
  ClipVertex<V> r;
  r.pos = a.pos + (b.pos - a.pos) * t;
  if constexpr (kVaryingFloats<V> > 0) {
    constexpr int n = kVaryingFloats<V>;
    std::array<float, n> fa, fb, fr;
    std::memcpy(fa.data(), &a.var, sizeof(V));
    std::memcpy(fb.data(), &b.var, sizeof(V));
    for (int i = 0; i < n; ++i) fr[i] = fa[i] + (fb[i] - fa[i]) * t;
    std::memcpy(&r.var, fr.data(), sizeof(V));
  }
  return r;
}

// Clips the triangle against the planes whose bits are set in `planes_mask` (the union of the outcodes) and
// returns the number of polygon vertices written to `out` (0 when nothing remains). The intersection with an
// edge is always computed from the inside vertex towards the outside one, so a shared edge of two triangles
// gets the same new vertex from both and no cracks appear.
template <class V, size_t N>
int clip_polygon(const ClipPlanes& cp, unsigned planes_mask, std::array<ClipVertex<V>, N>& out,
                 const ClipVertex<V>& v0, const ClipVertex<V>& v1, const ClipVertex<V>& v2) {
  static_assert(N >= 12, "a triangle clipped by 7 planes has at most 10 vertices");
  std::array<ClipVertex<V>, N> tmp;
  auto* src = &out;
  auto* dst = &tmp;
  (*src)[0] = v0, (*src)[1] = v1, (*src)[2] = v2;
  int n = 3;
  for (int k = 0; k < cp.count && n > 0; ++k) {
    if (!(planes_mask >> k & 1u)) continue;
    const ClipPlane& pl = cp.planes[k];
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const ClipVertex<V>& a = (*src)[i];
      const ClipVertex<V>& b = (*src)[(i + 1) % n];
      const float da = plane_distance(pl, a.pos), db = plane_distance(pl, b.pos);
      const bool ina = da >= 0.0f, inb = db >= 0.0f;
      if (ina) (*dst)[m++] = a;
      if (ina != inb) {
        (*dst)[m++] = ina ? lerp_clip_vertex(a, b, da / (da - db)) : lerp_clip_vertex(b, a, db / (db - da));
      }
    }
    n = m;
    std::swap(src, dst);
  }
  if (src != &out)
    for (int i = 0; i < n; ++i) out[i] = (*src)[i];
  return n;
}

}  // namespace raster
