// How a classic map is read: the filters as compile-time types. Each takes a Taps object (one compare per tap,
// or one hardware 2×2 PCF lookup per tap) and a SampleContext (map coordinates, reference depth, pixel and
// world position) and returns the visibility in [0, 1]. The run-time choice (dispatch_filter) is made once per
// batch of points, e.g. per light and 2×2 quad, so each light of a frame can keep its own filter.
// filter_lanes (shadow_filters_x8.h) runs these filters over eight points at once.
#pragma once
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shading/shadow_lookup.h"
#include "shading/techniques/poisson.h"
#include "shading/techniques/tutorial_random.h"
#include "shading/techniques/vocabulary.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// Where and what one lookup compares.
struct SampleContext {
  glm::vec2 st;      // map coordinates in [0, 1]
  float ref;         // reference depth, bias already applied
  glm::vec2 frag;    // gl_FragCoord.xy
  glm::vec3 world;   // world position (before any normal offset)
};

// One point a shader asks a light's visibility for: world position, unit normal and window position, and the
// world position's screen derivatives: its quad's coarse differences, one pixel right (lane 1 − lane 0) and one
// pixel up (lane 2 − lane 0), as llvmpipe takes implicit derivatives. Techniques that read mip-mapped maps derive
// the level of detail from them (moment_lod.h); zero (no quad) means magnification, level 0.
struct ShadowQuery {
  glm::vec3 p;
  glm::vec3 n;
  glm::vec2 frag;
  glm::vec3 dpdx{0.0f}, dpdy{0.0f};
};

// The two lookups a filter can be built from, over the same map: `nearest` (one compare, NEAREST) and
// `linear` (hardware PCF, LINEAR with compare). Snapshotted once per draw.
struct MapLookups {
  ShadowLookup2D nearest, linear;
};

// The pair over one map with LEQUAL compare, the given wrap and border depth 1 (outside reads as lit where the
// wrap uses the border).
inline MapLookups map_lookups(const Texture2D& tex, Wrap wrap) {
  const Sampler linear = Sampler::pcf(CompareFunc::lequal, wrap, 1.0f);
  Sampler nearest = linear;
  nearest.mag_filter = nearest.min_filter = Filter::nearest;
  return MapLookups{ShadowLookup2D(tex, nearest), ShadowLookup2D(tex, linear)};
}

// One tap at st + offset: a single compare, or (kPcf) a bilinear PCF of four compares.
template <bool kPcf>
struct Taps {
  const MapLookups* maps;
  float operator()(const SampleContext& c, glm::vec2 offset) const {
    const glm::vec3 str(c.st.x + offset.x, c.st.y + offset.y, c.ref);
    if constexpr (kPcf) return maps->linear(str);
    else return maps->nearest(str);
  }
};

struct HardFilter {
  template <class T>
  float operator()(const T& taps, const SampleContext& c, const FilterParams&) const {
    return taps(c, glm::vec2(0.0f));
  }
};

// Hardware PCF: one LINEAR compare lookup (the taps' own mode is ignored: this filter is the PCF lookup).
struct PcfFilter {
  template <class T>
  float operator()(const T& taps, const SampleContext& c, const FilterParams&) const {
    return Taps<true>{taps.maps}(c, glm::vec2(0.0f));
  }
};

enum class PoissonMode : uint8_t { fixed, stratified, rotated };

// Where one point's taps lie: its seed and the disc rotation, from shadowlab's integer hash (pixel, or world
// position rounded to 1 mm) or, with FilterParams::tutorial, from the tutorial's GLSL random (tutorial_random.h)
// over gl_FragCoord.xyy or the world position floored to the millimetre.
template <PoissonMode kMode>
struct PoissonTaps {
  bool tutorial = false;
  uint32_t seed = 0;      // shadowlab's hash
  glm::vec3 seed3{0.0f};  // the tutorial's seed
  glm::vec2 rot{1.0f, 0.0f};

  PoissonTaps() = default;
  PoissonTaps(const SampleContext& c, const FilterParams& p) : tutorial(p.tutorial) {
    if constexpr (kMode == PoissonMode::fixed) return;
    if (tutorial) {
      seed3 = p.stratify_world ? tutorial_world_seed(c.world) : tutorial_pixel_seed(c.frag);
      if constexpr (kMode == PoissonMode::rotated) rot = tutorial_rotation(seed3);
    } else {
      seed = p.stratify_world ? world_seed(c.world) : pixel_seed(c.frag);
      if constexpr (kMode == PoissonMode::rotated) rot = rotation_of(seed);
    }
  }

  // The disc point of tap i, before the spread: stratified picks an index per point and tap, rotated turns the
  // disc.
  glm::vec2 disc(int i) const {
    glm::vec2 d;
    if constexpr (kMode == PoissonMode::stratified)
      d = kPoissonDisk[size_t(tutorial ? tutorial_index(seed3, i) : stratified_index(seed, i))];
    else d = kPoissonDisk[size_t(i)];
    if constexpr (kMode == PoissonMode::rotated) d = glm::vec2(rot.x * d.x - rot.y * d.y, rot.y * d.x + rot.x * d.y);
    return d;
  }
};

// The tutorial's accumulation, one tap: visibility -= 0.2 * (1.0 - tap), starting from 1.0. Four shadowed
// taps leave 0.2; sixteen would leave -2.2, so the result is clamped at 0 (tutorial_visibility) as a UNORM
// colour write clamps it: with 16 taps, five or more shadowed taps read as full shadow.
inline constexpr float kTutorialTapWeight = 0.2f;
inline float tutorial_step(float visibility, float tap) { return visibility - kTutorialTapWeight * (1.0f - tap); }
inline float tutorial_visibility(float visibility) { return visibility > 0.0f ? visibility : 0.0f; }

// Poisson disc of `taps` points (4 or 16) scaled by `spread`: fixed (banding), stratified (each tap's disc index
// picked per pixel or world point), rotated (the disc turned per pixel). Visibility = mean of the taps, or with
// FilterParams::tutorial the tutorial's 1 - 0.2 per shadowed tap, clamped at 0.
template <PoissonMode kModeArg>
struct PoissonFilter {
  static constexpr PoissonMode kMode = kModeArg;
  template <class T>
  float operator()(const T& taps, const SampleContext& c, const FilterParams& p) const {
    const int n = p.taps >= 16 ? 16 : 4;
    const PoissonTaps<kMode> at(c, p);
    if (p.tutorial) {
      float visibility = 1.0f;
      for (int i = 0; i < n; ++i) visibility = tutorial_step(visibility, taps(c, at.disc(i) * p.spread));
      return tutorial_visibility(visibility);
    }
    float sum = 0.0f;
    for (int i = 0; i < n; ++i) sum += taps(c, at.disc(i) * p.spread);
    return sum / float(n);
  }
};

// Early bailing: the four outer taps of the 16-point disc; where they agree (all lit or all shadowed) that is
// the answer, elsewhere the full 16-tap kernel is taken.
struct EarlyBailFilter {
  template <class T>
  float operator()(const T& taps, const SampleContext& c, const FilterParams& p) const {
    float outer = 0.0f;
    for (int i : kOuterTaps) outer += taps(c, kPoissonDisk[size_t(i)] * p.spread);
    if (outer == 0.0f || outer == 4.0f) return outer * 0.25f;
    float sum = 0.0f;
    for (const glm::vec2& d : kPoissonDisk) sum += taps(c, d * p.spread);
    return sum / 16.0f;
  }
};

// Calls fn.template operator()<Filter, kPcfTaps>() once for the run-time choice.
template <class Fn>
decltype(auto) dispatch_filter(FilterKind kind, bool pcf_taps, Fn&& fn) {
  auto go = [&]<class F>() -> decltype(auto) {
    if (pcf_taps) return fn.template operator()<F, true>();
    return fn.template operator()<F, false>();
  };
  switch (kind) {
    case FilterKind::hard: return go.template operator()<HardFilter>();
    case FilterKind::pcf: return go.template operator()<PcfFilter>();
    case FilterKind::poisson: return go.template operator()<PoissonFilter<PoissonMode::fixed>>();
    case FilterKind::stratified: return go.template operator()<PoissonFilter<PoissonMode::stratified>>();
    case FilterKind::rotated: return go.template operator()<PoissonFilter<PoissonMode::rotated>>();
    case FilterKind::early_bail: break;
  }
  return go.template operator()<EarlyBailFilter>();
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
