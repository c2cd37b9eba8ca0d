// The filter kernels of one mip level: a footprint of one (NEAREST) or four (LINEAR) taps with weights, and the
// three ways of reducing it: colour (blend the texels), compare (compare each texel with the reference, then
// blend the 0/1 results: hardware PCF) and the mistake (blend the depths, then compare once). 2D textures and
// cube faces (seamless or not) build footprints differently and share the reductions.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "shading/texel_format.h"
#include "shading/texture.h"
#include "shading/wrap.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

// Taps in the order (i0, j0), (i1, j0), (i0, j1), (i1, j1); a null row means the border colour. `a` weights
// taps 1 and 3 against 0 and 2 (along s), `b` taps 2 and 3 against 0 and 1 (along t). `missing` names a tap
// with no texel (a cube corner under seamless filtering), replaced by the mean of the other three.
struct Footprint {
  const std::byte* row[4];
  int i[4];
  float a = 0.0f, b = 0.0f;
  int count = 1;
  int missing = -1;
};

// GL's lerp as llvmpipe writes it: v0 + w · (v1 − v0). Blending is bilinear: along s first, then along t.
template <class T>
inline T lerp(float w, const T& v0, const T& v1) {
  return v0 + w * (v1 - v0);
}

template <class T>
inline T blend(const Footprint& f, const T (&v)[4]) {
  if (f.count == 1) return v[0];
  return lerp(f.b, lerp(f.a, v[0], v[1]), lerp(f.a, v[2], v[3]));
}

// The border colour as the format reads it: depth and R formats (b.r, 0, 0, 1), RG (b.r, b.g, 0, 1); unorm
// formats clamp it to [0, 1]. Always inlined: lookups call it per lookup, and out of line (GCC's choice) its
// vec4 argument arrived in two registers, was stored in two halves and reloaded whole, a store-forwarding stall
// that took 40 % of a Poisson frame's time (the tutorial's NEAREST taps, AVX-512 build on the Zen 5 EPYC).
[[gnu::always_inline]] inline glm::vec4 border_texel(TexelFormat f, const glm::vec4& b) {
  glm::vec4 v = b;
  if (is_unorm(f))
    for (int c = 0; c < 4; ++c) v[c] = v[c] > 0.0f ? (v[c] < 1.0f ? v[c] : 1.0f) : 0.0f;
  if (is_depth(f) || f == TexelFormat::r32f) return {v.r, 0.0f, 0.0f, 1.0f};
  if (f == TexelFormat::rg32f) return {v.r, v.g, 0.0f, 1.0f};
  return v;
}

// The border's red channel as the format reads it (border_texel(f, b).r): what depth lookups compare against.
inline float border_red(TexelFormat f, const glm::vec4& b) {
  return is_unorm(f) ? (b.r > 0.0f ? (b.r < 1.0f ? b.r : 1.0f) : 0.0f) : b.r;
}

// The footprint of (s, t) on a 2D level, wrap modes per axis, textureOffset's offset in texels.
inline Footprint footprint_2d(const TextureLevel& L, const Sampler& s, Filter filter, glm::vec2 st,
                              glm::ivec2 offset = glm::ivec2(0)) {
  Footprint f;
  if (filter == Filter::nearest) {
    const int i = nearest_index(s.wrap_s, st.x, L.fwidth, L.width, offset.x);
    const int j = nearest_index(s.wrap_t, st.y, L.fheight, L.height, offset.y);
    const bool in = i != kBorder && j != kBorder;
    f.row[0] = in ? L.row(j) : nullptr;
    f.i[0] = i;
    f.count = 1;
    return f;
  }
  const LinearAxis x = linear_axis(s.wrap_s, st.x, L.fwidth, L.width, offset.x);
  const LinearAxis y = linear_axis(s.wrap_t, st.y, L.fheight, L.height, offset.y);
  const std::byte* r0 = y.i0 != kBorder ? L.row(y.i0) : nullptr;
  const std::byte* r1 = y.i1 != kBorder ? L.row(y.i1) : nullptr;
  f.row[0] = x.i0 != kBorder ? r0 : nullptr;
  f.row[1] = x.i1 != kBorder ? r0 : nullptr;
  f.row[2] = x.i0 != kBorder ? r1 : nullptr;
  f.row[3] = x.i1 != kBorder ? r1 : nullptr;
  f.i[0] = f.i[2] = x.i0;
  f.i[1] = f.i[3] = x.i1;
  f.a = x.frac;
  f.b = y.frac;
  f.count = 4;
  return f;
}

// Replaces the missing tap of a cube corner by the mean of the other three.
template <class T>
inline void fill_missing(const Footprint& f, T (&v)[4]) {
  if (f.missing < 0) return;
  T sum = T(0.0f);
  for (int k = 0; k < 4; ++k)
    if (k != f.missing) sum = sum + v[k];
  v[f.missing] = sum / 3.0f;
}

// Colour: the blended texels (what a sampler with compare mode none returns).
template <TexelFormat F>
inline glm::vec4 reduce_color(const Footprint& f, const glm::vec4& border) {
  glm::vec4 v[4];
  for (int k = 0; k < f.count; ++k) v[k] = f.row[k] ? Texel<F>::rgba(f.row[k], f.i[k]) : border;
  fill_missing(f, v);
  return blend(f, v);
}

// Hardware PCF: each texel (or the border depth) compared with `ref`, then the 0/1 results blended. The caller
// passes the reference through compare_reference; texels are compared as the floats the format decodes to.
template <TexelFormat F>
inline float reduce_compare(const Footprint& f, float ref, CompareFunc func, float border_depth) {
  float v[4];
  for (int k = 0; k < f.count; ++k)
    v[k] = compare_ref(func, ref, f.row[k] ? Texel<F>::red(f.row[k], f.i[k]) : border_depth);
  fill_missing(f, v);
  return blend(f, v);
}

// The depth (red) blended as a plain sampler would: the first half of "filter, then compare".
template <TexelFormat F>
inline float reduce_red(const Footprint& f, float border_red) {
  float v[4];
  for (int k = 0; k < f.count; ++k) v[k] = f.row[k] ? Texel<F>::red(f.row[k], f.i[k]) : border_red;
  fill_missing(f, v);
  return blend(f, v);
}

// The reference as GL compares it: clamped to [0, 1] for fixed-point formats (d16, d24; llvmpipe does the same
// for any unorm format), unchanged for float ones.
inline float compare_reference(TexelFormat f, float ref) {
  if (!is_unorm(f)) return ref;
  return ref > 0.0f ? (ref < 1.0f ? ref : 1.0f) : 0.0f;
}

SHADOWLAB_ISA_END
}  // namespace shading
