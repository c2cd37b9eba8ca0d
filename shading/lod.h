// Level-of-detail: λ from the derivatives of the texture coordinates (GL 4.6 §8.14, isotropic), then the
// sampler's bias and clamps, the magnification / minification switch and the mip level(s) to read. Quad
// lookups (lookup.h) take the derivatives from the 2×2 quad (fragment.h).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/vec2.hpp>

#include "shading/sampler.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

// λ_base = log2(ρ), ρ = max(|(∂u/∂x, ∂v/∂x)|, |(∂u/∂y, ∂v/∂y)|) with u = s · W, v = t · H at level 0.
// A zero gradient gives −∞ (magnification); an infinite or NaN ρ is taken as 0, as llvmpipe does.
inline float lod_from_gradients(glm::vec2 dx, glm::vec2 dy, float width, float height) {
  const float ux = dx.x * width, vx = dx.y * height, uy = dy.x * width, vy = dy.y * height;
  float rho = std::max(std::sqrt(ux * ux + vx * vx), std::sqrt(uy * uy + vy * vy));
  if (!(rho <= 3.4e38f)) rho = 0.0f;
  return std::log2(rho);
}

// What to read: level0 alone (weight 0) or level0 and level1 blended with `weight` on level1, with `filter`.
struct LevelChoice {
  int level0 = 0, level1 = 0;
  float weight = 0.0f;
  Filter filter = Filter::linear;
};

// λ = clamp(λ_base + bias, min_lod, max_lod). λ <= 0 is magnification (c = 0, as in GL 4.x and llvmpipe):
// level 0 with the mag filter. Otherwise the min filter, on: level 0 without mips; with MIPMAP_NEAREST level
// ceil(λ + 1/2) − 1 (λ <= 1/2: level 0), clamped to the last level q; with MIPMAP_LINEAR levels floor(λ) and
// floor(λ) + 1 weighted by frac(λ), or q alone once λ >= q.
inline LevelChoice choose_levels(float lambda_base, const Sampler& s, int levels) {
  float lambda = lambda_base + s.lod_bias;
  lambda = lambda > s.min_lod ? lambda : s.min_lod;  // NaN -> min_lod
  lambda = lambda < s.max_lod ? lambda : s.max_lod;
  if (lambda <= 0.0f) return {0, 0, 0.0f, s.mag_filter};
  const int q = levels - 1;
  if (s.mip_filter == MipFilter::none || q == 0) return {0, 0, 0.0f, s.min_filter};
  if (s.mip_filter == MipFilter::nearest) {
    const int d = lambda <= 0.5f ? 0 : std::min(q, int(std::ceil(lambda + 0.5f)) - 1);
    return {d, d, 0.0f, s.min_filter};
  }
  if (lambda >= float(q)) return {q, q, 0.0f, s.min_filter};
  const float fl = std::floor(lambda), frac = lambda - fl;
  if (frac == 0.0f) return {int(fl), int(fl), 0.0f, s.min_filter};  // exactly on a level: read it alone
  return {int(fl), int(fl) + 1, frac, s.min_filter};
}

SHADOWLAB_ISA_END
}  // namespace shading
