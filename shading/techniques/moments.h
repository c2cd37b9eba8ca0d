// What the filterable shadow maps store per texel and how a filtered texel becomes visibility: exponential
// (ESM), variance (VSM) and exponential variance (EVSM, two or four moments). Plain functions of a depth
// d in [0, 1] (the light's linear depth, light_depth.h); the encode pass (blur_pass.h) writes moments(), the
// blur averages them, and the camera pass reads moment_visibility() of the bilinearly filtered texel.
// Formulas and their limits: docs/filtered-shadows.md.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/vec4.hpp>

#include "shading/sampler.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

enum class MomentKind : uint8_t { esm, vsm, evsm2, evsm4 };

// Channels a kind stores, as many as its target has (R32F, RG32F, RGBA32F): ESM 1, VSM and EVSM2 2, EVSM4 4.
constexpr int moment_channels(MomentKind k) {
  return k == MomentKind::esm ? 1 : (k == MomentKind::evsm4 ? 4 : 2);
}

struct MomentParams {
  MomentKind kind = MomentKind::vsm;
  float esm_c = 80.0f;          // ESM exponent
  float positive = 40.0f;       // EVSM positive warp exponent
  float negative = 5.0f;        // EVSM negative warp exponent
  float light_bleed = 0.2f;     // VSM, EVSM: linstep(light_bleed, 1, p)
  float min_variance = 2e-5f;   // in depth units squared (EVSM: scaled by the warp's slope squared; 1e-7 there)
  // The blurred map's mip chain and how it is read (`moment_mips`): none (level 0 only, bilinear), nearest (the
  // nearer level, GL's LINEAR_MIPMAP_NEAREST) or linear (trilinear, LINEAR_MIPMAP_LINEAR). moment_lod.h.
  MipFilter mips = MipFilter::linear;
};

// EVSM's warps of a depth d in [0, 1], taken to x = 2d − 1 in [−1, 1] first so that both exponents reach
// their full range: positive exp(c⁺ x), negative −exp(−c⁻ x).
inline float evsm_positive(float d, float c) { return std::exp(c * (2.0f * d - 1.0f)); }
inline float evsm_negative(float d, float c) { return -std::exp(-c * (2.0f * d - 1.0f)); }

// The texel written for depth d.
inline glm::vec4 moments(const MomentParams& p, float d) {
  switch (p.kind) {
    case MomentKind::esm: return {std::exp(p.esm_c * d), 0.0f, 0.0f, 0.0f};
    case MomentKind::vsm: return {d, d * d, 0.0f, 0.0f};
    case MomentKind::evsm2: {
      const float e = evsm_positive(d, p.positive);
      return {e, e * e, 0.0f, 0.0f};
    }
    case MomentKind::evsm4: {
      const float e = evsm_positive(d, p.positive), f = evsm_negative(d, p.negative);
      return {e, e * e, f, f * f};
    }
  }
  return {};
}

// linstep(lo, 1, v): the light-bleeding reduction, v below lo goes to 0, the rest stretched back to [0, 1].
inline float linstep_bleed(float lo, float v) {
  if (!(lo > 0.0f)) return v;
  return std::clamp((v - lo) / (1.0f - lo), 0.0f, 1.0f);
}

// Chebyshev's one-tailed bound: P(depth >= t) <= σ² / (σ² + (t − μ)²) for t > μ, 1 otherwise.
inline float chebyshev(float m1, float m2, float t, float min_variance) {
  if (t <= m1) return 1.0f;
  const float variance = std::max(m2 - m1 * m1, min_variance);
  const float d = t - m1;
  return variance / (variance + d * d);
}

// Visibility in [0, 1] of a receiver at depth d from the filtered texel m.
inline float moment_visibility(const MomentParams& p, const glm::vec4& m, float d) {
  switch (p.kind) {
    case MomentKind::esm:
      // exp(c (z_occ − d)) = E[exp(c z_occ)] · exp(−c d), clamped: lit where the occluder is not in front.
      return std::clamp(m.x * std::exp(-p.esm_c * d), 0.0f, 1.0f);
    case MomentKind::vsm:
      return linstep_bleed(p.light_bleed, chebyshev(m.x, m.y, d, p.min_variance));
    case MomentKind::evsm2:
    case MomentKind::evsm4: {
      // The minimum variance is given in depth units; a warp w(d) stretches it by w'(d)² = (2 c w)².
      const float e = evsm_positive(d, p.positive);
      const float de = 2.0f * p.positive * e;
      float v = chebyshev(m.x, m.y, e, p.min_variance * de * de);
      if (p.kind == MomentKind::evsm4) {
        const float f = evsm_negative(d, p.negative);
        const float df = 2.0f * p.negative * f;
        v = std::min(v, chebyshev(m.z, m.w, f, p.min_variance * df * df));
      }
      return linstep_bleed(p.light_bleed, v);
    }
  }
  return 1.0f;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
