// Perspective-correct interpolation for shaded draws: per triangle, the screen-space planes of λk / wk (linear in
// window space), and per pixel the barycentrics b_k = (λk/wk) / Σ(λj/wj) that weight the vertices' varyings.
// interpolate() does one pixel; PairInterp the eight pixels of a quad pair in SIMD lanes, with the same
// operations in the same order, so both give the same bits.
#pragma once
#include <array>
#include <cstring>

#include <glm/vec4.hpp>

#include "raster/primitive.h"
#include "raster/shader.h"
#include "raster/simd/vec.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

template <class V>
struct TriangleInterp {
  float x0, y0;                 // window position of vertex 0 (snapped), the planes' origin
  float g[3], gdx[3], gdy[3];   // plane of λk/wk: g + gdx·(x − x0) + gdy·(y − y0)
  V v0, d1, d2;                 // varyings of vertex 0 and differences v1 − v0, v2 − v0
};

template <class V>
TriangleInterp<V> make_interp(const WindowVertex* w[3], const V* var[3]) {
  TriangleInterp<V> r;
  const double s = 1.0 / 256.0;
  const double x0 = w[0]->sx * s, y0 = w[0]->sy * s;
  const double x1 = w[1]->sx * s - x0, y1 = w[1]->sy * s - y0;
  const double x2 = w[2]->sx * s - x0, y2 = w[2]->sy * s - y0;
  const double det = x1 * y2 - x2 * y1;
  r.x0 = float(x0), r.y0 = float(y0);
  for (int k = 0; k < 3; ++k) {
    // Values of λk/wk at the three vertices: 1/wk at vertex k, 0 elsewhere.
    const double f0 = k == 0 ? w[0]->inv_w : 0.0, f1 = k == 1 ? w[1]->inv_w : 0.0, f2 = k == 2 ? w[2]->inv_w : 0.0;
    r.g[k] = float(f0);
    r.gdx[k] = float(((f1 - f0) * y2 - (f2 - f0) * y1) / det);
    r.gdy[k] = float(((f2 - f0) * x1 - (f1 - f0) * x2) / det);
  }
  if constexpr (kVaryingFloats<V> > 0) {
    constexpr int n = kVaryingFloats<V>;
    std::array<float, n> a, b, c;
    std::memcpy(a.data(), var[0], sizeof(V));
    std::memcpy(b.data(), var[1], sizeof(V));
    std::memcpy(c.data(), var[2], sizeof(V));
    for (int i = 0; i < n; ++i) b[i] -= a[i], c[i] -= a[i];
    std::memcpy(&r.v0, a.data(), sizeof(V));
    std::memcpy(&r.d1, b.data(), sizeof(V));
    std::memcpy(&r.d2, c.data(), sizeof(V));
  }
  return r;
}

// Interpolates the varyings at window position (px, py) (a pixel centre) and returns 1/w there.
template <class V>
float interpolate(const TriangleInterp<V>& t, float px, float py, V& out) {
  const float dx = px - t.x0, dy = py - t.y0;
  float gk[3];
  for (int k = 0; k < 3; ++k) gk[k] = t.g[k] + t.gdx[k] * dx + t.gdy[k] * dy;
  const float sum = gk[0] + gk[1] + gk[2];
  if constexpr (kVaryingFloats<V> > 0) {
    constexpr int n = kVaryingFloats<V>;
    const float b1 = gk[1] / sum, b2 = gk[2] / sum;
    std::array<float, n> v0, d1, d2, r;
    std::memcpy(v0.data(), &t.v0, sizeof(V));
    std::memcpy(d1.data(), &t.d1, sizeof(V));
    std::memcpy(d2.data(), &t.d2, sizeof(V));
    for (int i = 0; i < n; ++i) r[i] = v0[i] + b1 * d1[i] + b2 * d2[i];
    std::memcpy(&out, r.data(), sizeof(V));
  }
  return sum;
}

// A triangle's interpolation record as splatted SIMD constants, made once per triangle and block.
template <class V>
struct PairInterp {
  static constexpr int kN = kVaryingFloats<V>;
  simd::VecF32 x0, y0, g[3], gdx[3], gdy[3];
  std::array<simd::VecF32, size_t(kN)> v0, d1, d2;

  explicit PairInterp(const TriangleInterp<V>& t) {
    using simd::VecF32;
    x0 = VecF32::splat(t.x0), y0 = VecF32::splat(t.y0);
    for (int k = 0; k < 3; ++k) g[k] = VecF32::splat(t.g[k]), gdx[k] = VecF32::splat(t.gdx[k]), gdy[k] = VecF32::splat(t.gdy[k]);
    if constexpr (kN > 0) {
      float a[kN], b[kN], c[kN];
      std::memcpy(a, &t.v0, sizeof(V));
      std::memcpy(b, &t.d1, sizeof(V));
      std::memcpy(c, &t.d2, sizeof(V));
      for (int i = 0; i < kN; ++i) v0[i] = VecF32::splat(a[i]), d1[i] = VecF32::splat(b[i]), d2[i] = VecF32::splat(c[i]);
    }
  }

  // interpolate() at pixel centres (px, py), split as it associates: g + gdx·(px − x0) depends on the column
  // only, gdy·(py − y0) on the row only, so each is computed once per block and shared by its groups.
  struct Columns {
    simd::VecF32 g[3];
  };
  struct Rows {
    simd::VecF32 g[3];
  };
  Columns columns(simd::VecF32 px) const {
    const simd::VecF32 dx = px - x0;
    Columns c;
    for (int k = 0; k < 3; ++k) c.g[k] = g[k] + gdx[k] * dx;
    return c;
  }
  Rows rows(simd::VecF32 py) const {
    const simd::VecF32 dy = py - y0;
    Rows r;
    for (int k = 0; k < 3; ++k) r.g[k] = gdy[k] * dy;
    return r;
  }
  // The varyings into `out`; returns 1/w.
  simd::VecF32 operator()(const Columns& c, const Rows& r, std::array<simd::VecF32, size_t(kN)>& out) const {
    simd::VecF32 gk[3];
    for (int k = 0; k < 3; ++k) gk[k] = c.g[k] + r.g[k];
    const simd::VecF32 sum = gk[0] + gk[1] + gk[2];
    if constexpr (kN > 0) {
      const simd::VecF32 b1 = simd::div(gk[1], sum), b2 = simd::div(gk[2], sum);
      for (int i = 0; i < kN; ++i) out[i] = v0[i] + b1 * d1[i] + b2 * d2[i];
    }
    return sum;
  }
};

SHADOWLAB_ISA_END
}  // namespace raster
