// GLSL's lookups on a Texture2D: texture, textureLod, textureGrad, textureOffset, textureProj, texelFetch,
// textureSize. As in GLSL the coordinate says what is asked: (s, t) reads a colour, (s, t, ref) is a shadow
// lookup returning the compare result; textureProj adds q. Per-lane forms have no derivatives and use
// λ_base = 0 (as GLSL outside a fragment shader); quad forms (Quad<...> coordinates) take implicit derivatives
// from the quad like a fragment shader's texture(). All inline, no allocation, one format switch per lookup.
#pragma once
#include <cmath>
#include <type_traits>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/filter.h"
#include "shading/fragment.h"
#include "shading/lod.h"
#include "shading/pcf_kernel.h"
#include "shading/sampler.h"
#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

namespace detail {

template <TexelFormat F>
inline glm::vec4 sample_color(const Texture2D& t, const Sampler& s, const LevelChoice& c, glm::vec2 st,
                              glm::ivec2 off) {
  const glm::vec4 border = border_texel(F, s.border_color);
  const glm::vec4 v0 = reduce_color<F>(footprint_2d(t.level(c.level0), s, c.filter, st, off), border);
  if (c.level1 == c.level0) return v0;
  return lerp(c.weight, v0, reduce_color<F>(footprint_2d(t.level(c.level1), s, c.filter, st, off), border));
}

template <TexelFormat F>
inline float sample_shadow(const Texture2D& t, const Sampler& s, const LevelChoice& c, glm::vec3 str, glm::ivec2 off) {
  const glm::vec2 st(str.x, str.y);
  const float border = border_red(F, s.border_color);
  if (s.compare_mode == CompareMode::ref_to_texture) {
    const float ref = compare_reference(F, str.z);
    const float r0 =
        reduce_compare<F>(footprint_2d(t.level(c.level0), s, c.filter, st, off), ref, s.compare_func, border);
    if (c.level1 == c.level0) return r0;
    return lerp(c.weight, r0,
                reduce_compare<F>(footprint_2d(t.level(c.level1), s, c.filter, st, off), ref, s.compare_func, border));
  }
  // Compare mode none: what a shader does with a plain sampler: filter the depth, then compare it once, with
  // the reference as given (no clamping: the comparison is the shader's own code).
  float d = reduce_red<F>(footprint_2d(t.level(c.level0), s, c.filter, st, off), border);
  if (c.level1 != c.level0)
    d = lerp(c.weight, d, reduce_red<F>(footprint_2d(t.level(c.level1), s, c.filter, st, off), border));
  return compare_ref(s.compare_func, str.z, d);
}

// True when λ cannot change what is read (one filter, one level), so quad lookups may skip the LOD maths.
inline bool lod_irrelevant(const Texture2D& t, const Sampler& s) {
  return s.mag_filter == s.min_filter && (s.mip_filter == MipFilter::none || t.levels() == 1);
}

}  // namespace detail

// ---- The core: a lookup at a given λ_base (before the sampler's bias and clamps) -------------------------------

inline glm::vec4 texture_at(const Texture2D& t, const Sampler& s, glm::vec2 st, float lambda_base,
                            glm::ivec2 offset = glm::ivec2(0)) {
  const LevelChoice c = choose_levels(lambda_base, s, t.levels());
  return visit_format(t.format(),
                      [&](auto f) { return detail::sample_color<decltype(f)::value>(t, s, c, st, offset); });
}

inline float texture_at(const Texture2D& t, const Sampler& s, glm::vec3 str, float lambda_base,
                        glm::ivec2 offset = glm::ivec2(0)) {
  const LevelChoice c = choose_levels(lambda_base, s, t.levels());
  return visit_format(t.format(),
                      [&](auto f) { return detail::sample_shadow<decltype(f)::value>(t, s, c, str, offset); });
}

namespace detail {

// The NEAREST shadow case: compare mode on, NEAREST for both filters without mips (or with one level, so λ cannot
// matter), clamp_to_edge or clamp_to_border on both axes, a depth format.
inline bool nearest_fast_path_applies(const Texture2D& t, const Sampler& s) {
  return s.compare_mode == CompareMode::ref_to_texture && s.mag_filter == Filter::nearest &&
         s.min_filter == Filter::nearest && (s.mip_filter == MipFilter::none || t.levels() == 1) &&
         s.wrap_s == s.wrap_t && (s.wrap_s == Wrap::clamp_to_edge || s.wrap_s == Wrap::clamp_to_border) &&
         is_depth(t.format());
}

// visit_format for the three depth formats nearest_fast_path_applies admits (any other format is taken as d32f).
template <class Fn>
decltype(auto) visit_depth_format(TexelFormat f, Fn&& fn) {
  using TF = TexelFormat;
  if (f == TF::d16) return fn(std::integral_constant<TF, TF::d16>{});
  if (f == TF::d24) return fn(std::integral_constant<TF, TF::d24>{});
  return fn(std::integral_constant<TF, TF::d32f>{});
}

// texture_at(t, s, str, λ) for level 0 of a texture and sampler nearest_fast_path_applies to, bit for bit:
// footprint_2d's NEAREST texel (or the border) and reduce_compare's comparison of it, without the general path's
// level choice, footprint record and blend.
template <TexelFormat F>
inline float nearest_compare(const TextureLevel& L, Wrap wrap, CompareFunc func, float border_depth, glm::vec3 str) {
  const int i = nearest_index(wrap, str.x, L.fwidth, L.width), j = nearest_index(wrap, str.y, L.fheight, L.height);
  const float texel = i != kBorder && j != kBorder ? Texel<F>::red(L.row(j), i) : border_depth;
  return compare_ref(func, compare_reference(F, str.z), texel);
}

}  // namespace detail

// ---- Per-lane lookups ------------------------------------------------------------------------------------------

// texture(sampler2D, st) / texture(sampler2DShadow, str) with λ_base = 0.
inline glm::vec4 texture(const Texture2D& t, const Sampler& s, glm::vec2 st) { return texture_at(t, s, st, 0.0f); }
// The shadow form recognises the common shadow case and runs the PCF kernel (pcf_kernel.h; identical results).
// ShadowLookup2D makes that choice once per draw instead of per call.
inline float texture(const Texture2D& t, const Sampler& s, glm::vec3 str) {
  if (detail::pcf_fast_path_applies(t, s)) return detail::pcf_fast(t, s, str);
  return texture_at(t, s, str, 0.0f);
}

// textureOffset: `offset` texels added to the integer texel coordinates, at every level.
inline glm::vec4 texture_offset(const Texture2D& t, const Sampler& s, glm::vec2 st, glm::ivec2 offset) {
  return texture_at(t, s, st, 0.0f, offset);
}
inline float texture_offset(const Texture2D& t, const Sampler& s, glm::vec3 str, glm::ivec2 offset) {
  return texture_at(t, s, str, 0.0f, offset);
}

// textureLod: λ_base = lod (the sampler's bias and clamps still apply, as in GL).
inline glm::vec4 texture_lod(const Texture2D& t, const Sampler& s, glm::vec2 st, float lod,
                             glm::ivec2 offset = glm::ivec2(0)) {
  return texture_at(t, s, st, lod, offset);
}
inline float texture_lod(const Texture2D& t, const Sampler& s, glm::vec3 str, float lod,
                         glm::ivec2 offset = glm::ivec2(0)) {
  return texture_at(t, s, str, lod, offset);
}

// textureGrad: λ_base from explicit derivatives of (s, t) with respect to window x and y.
inline glm::vec4 texture_grad(const Texture2D& t, const Sampler& s, glm::vec2 st, glm::vec2 dx, glm::vec2 dy,
                              glm::ivec2 offset = glm::ivec2(0)) {
  return texture_at(t, s, st, lod_from_gradients(dx, dy, t.level(0).fwidth, t.level(0).fheight), offset);
}
inline float texture_grad(const Texture2D& t, const Sampler& s, glm::vec3 str, glm::vec2 dx, glm::vec2 dy,
                          glm::ivec2 offset = glm::ivec2(0)) {
  return texture_at(t, s, str, lod_from_gradients(dx, dy, t.level(0).fwidth, t.level(0).fheight), offset);
}

// textureProj: the coordinates are multiplied by 1/q (as GL implementations, llvmpipe included, compute it).
// q < 0 is divided like any other q, exactly as a GPU does: a point behind the projector lands mirrored inside
// the map, which is the classic "back projection" false shadow; shaders that do not want it test q themselves.
// q = 0 (either sign) or NaN is a point at infinity that no texel covers: the colour form returns (0, 0, 0, 0)
// and the shadow form 0 (in shadow), without reading the texture.
inline bool projectable(float q) { return q != 0.0f && !std::isnan(q); }

inline glm::vec4 texture_proj(const Texture2D& t, const Sampler& s, glm::vec3 stq) {
  if (!projectable(stq.z)) return glm::vec4(0.0f);
  const float w = 1.0f / stq.z;
  return texture(t, s, glm::vec2(stq.x * w, stq.y * w));
}
inline float texture_proj(const Texture2D& t, const Sampler& s, glm::vec4 strq) {
  if (!projectable(strq.w)) return 0.0f;
  const float w = 1.0f / strq.w;
  return texture(t, s, glm::vec3(strq.x * w, strq.y * w, strq.z * w));
}

// The mistake, explicitly: whatever the sampler's compare mode, filter the depth and compare the result once.
inline float filter_then_compare(const Texture2D& t, const Sampler& s, glm::vec3 str) {
  Sampler plain = s;
  plain.compare_mode = CompareMode::none;
  return texture(t, plain, str);
}

// texelFetch: the texel (i, j) of `level`, decoded, no filtering or sampler. Out of range (GL: undefined) it
// returns (0, 0, 0, 0), as robust buffer access does.
inline glm::vec4 texel_fetch(const Texture2D& t, glm::ivec2 ij, int level = 0) {
  if (level < 0 || level >= t.levels()) return glm::vec4(0.0f);
  const TextureLevel& L = t.level(level);
  if (ij.x < 0 || ij.y < 0 || ij.x >= L.width || ij.y >= L.height) return glm::vec4(0.0f);
  return decode_texel(t.format(), L.row(ij.y), ij.x);
}

inline glm::ivec2 texture_size(const Texture2D& t, int level = 0) { return {t.width(level), t.height(level)}; }

// ---- Quad lookups: implicit derivatives, like texture() in a fragment shader ---------------------------------

// λ_base per lane from the quad's (s, t).
inline Quad<float> quad_lod(const Texture2D& t, const Quad<glm::vec2>& st, Derivative d = Derivative::coarse) {
  const float w = t.level(0).fwidth, h = t.level(0).fheight;
  if (d == Derivative::coarse) {
    const float l = lod_from_gradients(st[1] - st[0], st[2] - st[0], w, h);
    return {l, l, l, l};
  }
  const Quad<glm::vec2> dx = dfdx(st, d), dy = dfdy(st, d);
  Quad<float> r;
  for (int l = 0; l < 4; ++l) r[size_t(l)] = lod_from_gradients(dx[size_t(l)], dy[size_t(l)], w, h);
  return r;
}

namespace detail {
inline Quad<float> quad_lod_if_needed(const Texture2D& t, const Sampler& s, const Quad<glm::vec2>& st, Derivative d) {
  if (lod_irrelevant(t, s)) return {0.0f, 0.0f, 0.0f, 0.0f};
  return quad_lod(t, st, d);
}
inline Quad<glm::vec2> xy(const Quad<glm::vec3>& v) {
  return {glm::vec2(v[0]), glm::vec2(v[1]), glm::vec2(v[2]), glm::vec2(v[3])};
}
}  // namespace detail

inline Quad<glm::vec4> texture(const Texture2D& t, const Sampler& s, const Quad<glm::vec2>& st,
                               Derivative d = Derivative::coarse, glm::ivec2 offset = glm::ivec2(0)) {
  const Quad<float> lod = detail::quad_lod_if_needed(t, s, st, d);
  Quad<glm::vec4> r;
  for (size_t l = 0; l < 4; ++l) r[l] = texture_at(t, s, st[l], lod[l], offset);
  return r;
}

inline Quad<float> texture(const Texture2D& t, const Sampler& s, const Quad<glm::vec3>& str,
                           Derivative d = Derivative::coarse, glm::ivec2 offset = glm::ivec2(0)) {
  Quad<float> r;
  if (offset == glm::ivec2(0) && detail::pcf_fast_path_applies(t, s)) {
    for (size_t l = 0; l < 4; ++l) r[l] = detail::pcf_fast(t, s, str[l]);
    return r;
  }
  const Quad<float> lod = detail::quad_lod_if_needed(t, s, detail::xy(str), d);
  for (size_t l = 0; l < 4; ++l) r[l] = texture_at(t, s, str[l], lod[l], offset);
  return r;
}

// textureProj on a quad: derivatives of the projected coordinates; each lane's q handled as texture_proj does.
inline Quad<glm::vec4> texture_proj(const Texture2D& t, const Sampler& s, const Quad<glm::vec3>& stq,
                                    Derivative d = Derivative::coarse) {
  Quad<glm::vec2> st;
  for (size_t l = 0; l < 4; ++l) {
    const float w = 1.0f / stq[l].z;
    st[l] = {stq[l].x * w, stq[l].y * w};
  }
  const Quad<float> lod = detail::quad_lod_if_needed(t, s, st, d);
  Quad<glm::vec4> r;
  for (size_t l = 0; l < 4; ++l) r[l] = projectable(stq[l].z) ? texture_at(t, s, st[l], lod[l]) : glm::vec4(0.0f);
  return r;
}

inline Quad<float> texture_proj(const Texture2D& t, const Sampler& s, const Quad<glm::vec4>& strq,
                                Derivative d = Derivative::coarse) {
  Quad<glm::vec3> str;
  for (size_t l = 0; l < 4; ++l) {
    const float w = 1.0f / strq[l].w;
    str[l] = {strq[l].x * w, strq[l].y * w, strq[l].z * w};
  }
  const Quad<float> lod = detail::quad_lod_if_needed(t, s, detail::xy(str), d);
  Quad<float> r;
  for (size_t l = 0; l < 4; ++l) r[l] = projectable(strq[l].w) ? texture_at(t, s, str[l], lod[l]) : 0.0f;
  return r;
}

SHADOWLAB_ISA_END
}  // namespace shading
