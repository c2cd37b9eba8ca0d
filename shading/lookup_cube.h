// GLSL's lookups on a TextureCube: texture, textureLod, textureGrad, per lane and per quad. A vec3 is a
// direction (colour), a vec4 a direction plus compare reference (samplerCubeShadow). With seamless filtering
// (the sampler's seamless_cube, GL_TEXTURE_CUBE_MAP_SEAMLESS) LINEAR taps that fall off a face are read from
// the adjacent face, and at a cube corner the tap with no texel is the mean of the other three (GL's
// recommendation; for compares, the mean of the three 0/1 results). Without it each face is a 2D texture with
// the sampler's wrap modes.
#pragma once
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/cube_face.h"
#include "shading/filter.h"
#include "shading/fragment.h"
#include "shading/lod.h"
#include "shading/texture_cube.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

// The footprint of face coordinates (c.s, c.t) on `level` of the cube.
inline Footprint footprint_cube(const TextureCube& cube, int level, const Sampler& s, Filter filter,
                                const CubeCoord& c) {
  const TextureLevel& L = cube.face(c.face).level(level);
  if (!s.seamless_cube) return footprint_2d(L, s, filter, {c.s, c.t});
  const int n = L.width;
  Footprint f;
  if (filter == Filter::nearest) {
    // Seamless cube maps ignore the wrap modes and clamp to the face's edge.
    const int i = nearest_index(Wrap::clamp_to_edge, c.s, L.fwidth, n);
    const int j = nearest_index(Wrap::clamp_to_edge, c.t, L.fheight, n);
    f.row[0] = L.row(j);
    f.i[0] = i;
    f.count = 1;
    return f;
  }
  // s, t lie in [0, 1] (up to a rounding step), so i0 and j0 lie in [−1, n − 1]; the clamp makes that certain.
  auto axis = [n](float st, float size, int& i0, float& frac) {
    float u = st * size - 0.5f;
    u = u > -1.0f ? u : -1.0f;
    u = u < float(n) ? u : float(n);
    const float fl = std::floor(u);
    i0 = int(fl) < n ? int(fl) : n - 1;
    frac = u - fl;
  };
  int i0, j0;
  axis(c.s, L.fwidth, i0, f.a);
  axis(c.t, L.fheight, j0, f.b);
  f.count = 4;
  for (int k = 0; k < 4; ++k) {
    const int i = i0 + (k & 1), j = j0 + (k >> 1);
    const bool out_i = i < 0 || i >= n, out_j = j < 0 || j >= n;
    if (out_i && out_j) {
      f.missing = k;  // a corner: no face holds this texel
      f.row[k] = L.row(0);
      f.i[k] = 0;
    } else if (out_i || out_j) {
      const FaceTexel t = cube_neighbor(c.face, i, j, n);
      f.row[k] = cube.face(t.face).level(level).row(t.j);
      f.i[k] = t.i;
    } else {
      f.row[k] = L.row(j);
      f.i[k] = i;
    }
  }
  return f;
}

namespace detail {

template <TexelFormat F>
inline glm::vec4 cube_color(const TextureCube& cube, const Sampler& s, const LevelChoice& lc, const CubeCoord& c) {
  const glm::vec4 border = border_texel(F, s.border_color);
  const glm::vec4 v0 = reduce_color<F>(footprint_cube(cube, lc.level0, s, lc.filter, c), border);
  if (lc.level1 == lc.level0) return v0;
  return lerp(lc.weight, v0, reduce_color<F>(footprint_cube(cube, lc.level1, s, lc.filter, c), border));
}

template <TexelFormat F>
inline float cube_shadow(const TextureCube& cube, const Sampler& s, const LevelChoice& lc, const CubeCoord& c,
                         float ref) {
  const float border = border_red(F, s.border_color);
  if (s.compare_mode == CompareMode::ref_to_texture) {
    const float r = compare_reference(F, ref);
    auto level = [&](int l) {
      return reduce_compare<F>(footprint_cube(cube, l, s, lc.filter, c), r, s.compare_func, border);
    };
    const float r0 = level(lc.level0);
    return lc.level1 == lc.level0 ? r0 : lerp(lc.weight, r0, level(lc.level1));
  }
  auto level = [&](int l) { return reduce_red<F>(footprint_cube(cube, l, s, lc.filter, c), border); };
  float d = level(lc.level0);
  if (lc.level1 != lc.level0) d = lerp(lc.weight, d, level(lc.level1));
  return compare_ref(s.compare_func, ref, d);
}

inline float cube_lod(const TextureCube& cube, const CubeCoord& c, glm::vec3 ddx, glm::vec3 ddy) {
  const float n = cube.face(0).level(0).fwidth;
  return lod_from_gradients(cube_face_derivative(c, ddx), cube_face_derivative(c, ddy), n, n);
}

}  // namespace detail

// ---- The core: a lookup at a given λ_base ----------------------------------------------------------------------

inline glm::vec4 texture_at(const TextureCube& cube, const Sampler& s, glm::vec3 dir, float lambda_base) {
  const LevelChoice lc = choose_levels(lambda_base, s, cube.levels());
  const CubeCoord c = cube_coord(dir);
  return visit_format(cube.format(), [&](auto f) { return detail::cube_color<decltype(f)::value>(cube, s, lc, c); });
}

inline float texture_at(const TextureCube& cube, const Sampler& s, glm::vec4 dir_ref, float lambda_base) {
  const LevelChoice lc = choose_levels(lambda_base, s, cube.levels());
  const CubeCoord c = cube_coord(glm::vec3(dir_ref));
  return visit_format(cube.format(),
                      [&](auto f) { return detail::cube_shadow<decltype(f)::value>(cube, s, lc, c, dir_ref.w); });
}

// ---- Per-lane lookups (λ_base = 0 unless given) ---------------------------------------------------------------

inline glm::vec4 texture(const TextureCube& cube, const Sampler& s, glm::vec3 dir) {
  return texture_at(cube, s, dir, 0.0f);
}
inline float texture(const TextureCube& cube, const Sampler& s, glm::vec4 dir_ref) {
  return texture_at(cube, s, dir_ref, 0.0f);
}
inline glm::vec4 texture_lod(const TextureCube& cube, const Sampler& s, glm::vec3 dir, float lod) {
  return texture_at(cube, s, dir, lod);
}
inline float texture_lod(const TextureCube& cube, const Sampler& s, glm::vec4 dir_ref, float lod) {
  return texture_at(cube, s, dir_ref, lod);
}
// textureGrad: derivatives of the direction; the face derivatives follow from the quotient rule.
inline glm::vec4 texture_grad(const TextureCube& cube, const Sampler& s, glm::vec3 dir, glm::vec3 ddx, glm::vec3 ddy) {
  return texture_at(cube, s, dir, detail::cube_lod(cube, cube_coord(dir), ddx, ddy));
}
inline float texture_grad(const TextureCube& cube, const Sampler& s, glm::vec4 dir_ref, glm::vec3 ddx, glm::vec3 ddy) {
  return texture_at(cube, s, dir_ref, detail::cube_lod(cube, cube_coord(glm::vec3(dir_ref)), ddx, ddy));
}

// ---- Quad lookups: implicit derivatives of the direction, per lane on each lane's own face -------------------

inline Quad<float> quad_lod(const TextureCube& cube, const Quad<glm::vec3>& dir, Derivative d = Derivative::coarse) {
  const Quad<glm::vec3> dx = dfdx(dir, d), dy = dfdy(dir, d);
  Quad<float> r;
  for (size_t l = 0; l < 4; ++l) r[l] = detail::cube_lod(cube, cube_coord(dir[l]), dx[l], dy[l]);
  return r;
}

inline Quad<glm::vec4> texture(const TextureCube& cube, const Sampler& s, const Quad<glm::vec3>& dir,
                               Derivative d = Derivative::coarse) {
  const bool need_lod = s.mag_filter != s.min_filter || (s.mip_filter != MipFilter::none && cube.levels() > 1);
  const Quad<float> lod = need_lod ? quad_lod(cube, dir, d) : Quad<float>{0.0f, 0.0f, 0.0f, 0.0f};
  Quad<glm::vec4> r;
  for (size_t l = 0; l < 4; ++l) r[l] = texture_at(cube, s, dir[l], lod[l]);
  return r;
}

inline Quad<float> texture(const TextureCube& cube, const Sampler& s, const Quad<glm::vec4>& dir_ref,
                           Derivative d = Derivative::coarse) {
  const bool need_lod = s.mag_filter != s.min_filter || (s.mip_filter != MipFilter::none && cube.levels() > 1);
  Quad<float> lod{0.0f, 0.0f, 0.0f, 0.0f};
  if (need_lod) {
    lod =
        quad_lod(cube, {glm::vec3(dir_ref[0]), glm::vec3(dir_ref[1]), glm::vec3(dir_ref[2]), glm::vec3(dir_ref[3])}, d);
  }
  Quad<float> r;
  for (size_t l = 0; l < 4; ++l) r[l] = texture_at(cube, s, dir_ref[l], lod[l]);
  return r;
}

SHADOWLAB_ISA_END
}  // namespace shading
