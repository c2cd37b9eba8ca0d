// From a normalised coordinate to texel indices and weights along one axis, with GL's wrap modes applied to
// the integer indices (GL 4.6 §8.14.2, table 8.20). NEAREST takes floor(s · W); LINEAR takes u = s · W − 0.5,
// i0 = floor(u), i1 = i0 + 1 and the weight of i1 is frac(u) (CONVENTIONS). An index that the wrap mode sends
// to the border comes back as kBorder.
#pragma once
#include <cmath>

#include "shading/sampler.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

inline constexpr int kBorder = -1;

// Coordinates in texel units are kept within ±2^30 before they become integers, so index arithmetic cannot
// overflow; beyond 2^24 floats have no fraction left anyway. NaN is taken as −2^30 (the low edge).
inline constexpr float kMaxTexelCoord = 1073741824.0f;  // 2^30

inline float clamp_texel_coord(float u) {
  u = u > -kMaxTexelCoord ? u : -kMaxTexelCoord;  // also catches NaN
  return u < kMaxTexelCoord ? u : kMaxTexelCoord;
}

// GL's wrap of an integer texel coordinate into [0, n), or kBorder.
inline int wrap_index(Wrap w, int i, int n) {
  switch (w) {
    case Wrap::clamp_to_edge: return i < 0 ? 0 : (i >= n ? n - 1 : i);
    case Wrap::clamp_to_border:
    case Wrap::clamp: return (i < 0 || i >= n) ? kBorder : i;
    case Wrap::repeat: {
      const int m = i % n;
      return m < 0 ? m + n : m;
    }
    case Wrap::mirrored_repeat: {
      // (n − 1) − mirror((i mod 2n) − n), mirror(a) = a for a >= 0, else −(1 + a).
      int m = i % (2 * n);
      if (m < 0) m += 2 * n;
      const int a = m - n;
      return (n - 1) - (a >= 0 ? a : -(1 + a));
    }
  }
  return kBorder;
}

// Legacy GL_CLAMP clamps the coordinate itself to [0, 1] before it is scaled.
inline float prewrap_coord(Wrap w, float s) {
  if (w != Wrap::clamp) return s;
  return s > 0.0f ? (s < 1.0f ? s : 1.0f) : 0.0f;  // NaN -> 0
}

// int(floor(u)) for u through clamp_texel_coord (|u| <= 2^30, never NaN): truncated, then one less where that
// rounded a negative u up. Exact there, and no call: GCC does not inline floorf under the project's flags, and
// a NEAREST lookup's two floors were a call each.
inline int floor_index(float u) {
  const int i = int(u);
  return float(i) > u ? i - 1 : i;
}

// NEAREST along one axis: the texel index (or kBorder). `offset` is textureOffset's integer offset.
inline int nearest_index(Wrap w, float s, float size, int n, int offset = 0) {
  const float u = clamp_texel_coord(prewrap_coord(w, s) * size);
  // Legacy clamp under NEAREST reads the edge texel at s = 1 (u = n), as clamp_to_edge does.
  const Wrap eff = w == Wrap::clamp ? Wrap::clamp_to_edge : w;
  return wrap_index(eff, floor_index(u) + offset, n);
}

// LINEAR along one axis: the two indices (each possibly kBorder) and the weight of the second.
struct LinearAxis {
  int i0, i1;
  float frac;
};

inline LinearAxis linear_axis(Wrap w, float s, float size, int n, int offset = 0) {
  const float u = clamp_texel_coord(prewrap_coord(w, s) * size - 0.5f);
  const float fl = std::floor(u);
  const int i = int(fl) + offset;
  return {wrap_index(w, i, n), wrap_index(w, i + 1, n), u - fl};
}

SHADOWLAB_ISA_END
}  // namespace shading
