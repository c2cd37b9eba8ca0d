// Sampler state: GL's sampler object as a small plain struct (filters, wrap modes, border colour, compare
// mode and function, LOD clamps and bias, seamless cube filtering). A shader holds one per texture it reads,
// set once per draw; lookups read it by reference and branch on its fields, never through a virtual call.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

#include <glm/vec4.hpp>

#include "raster/state.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

enum class Filter : uint8_t { nearest, linear };
// none: only level 0 (GL's NEAREST / LINEAR minification); nearest, linear: GL's *_MIPMAP_NEAREST / _LINEAR.
enum class MipFilter : uint8_t { none, nearest, linear };

// The wrap modes of CONVENTIONS. `clamp` is legacy GL_CLAMP: the coordinate is clamped to [0, 1], so LINEAR at
// the edge mixes the edge texel with the border colour half and half; NEAREST behaves as clamp_to_edge.
enum class Wrap : uint8_t { clamp_to_edge, clamp_to_border, clamp, repeat, mirrored_repeat };

// GL's eight compare functions: the result is 1 when `reference OP texel` holds (LEQUAL: ref <= texel).
using CompareFunc = raster::DepthFunc;

// none: lookups return the texel values (a depth texture reads as (d, 0, 0, 1)); a shadow lookup through such a
// sampler filters the depth first and compares the filtered value once: the common mistake, kept on purpose.
// ref_to_texture: GL_COMPARE_REF_TO_TEXTURE: every texel of the footprint is compared, then the 0/1 results are
// filtered (with LINEAR: hardware PCF).
enum class CompareMode : uint8_t { none, ref_to_texture };

struct Sampler {
  Filter mag_filter = Filter::linear;
  Filter min_filter = Filter::linear;
  MipFilter mip_filter = MipFilter::none;
  Wrap wrap_s = Wrap::clamp_to_edge;
  Wrap wrap_t = Wrap::clamp_to_edge;
  // Linear values; for depth formats the red component is the border depth. Clamped to [0, 1] for unorm
  // formats when read, as GL does.
  glm::vec4 border_color{0.0f, 0.0f, 0.0f, 0.0f};
  CompareMode compare_mode = CompareMode::none;
  CompareFunc compare_func = CompareFunc::lequal;
  float min_lod = -1000.0f, max_lod = 1000.0f, lod_bias = 0.0f;  // GL's defaults
  bool seamless_cube = true;                                     // GL_TEXTURE_CUBE_MAP_SEAMLESS

  // A hardware-PCF shadow sampler: LINEAR, compare `func`, the given wrap on both axes.
  static constexpr Sampler pcf(CompareFunc func = CompareFunc::lequal, Wrap wrap = Wrap::clamp_to_edge,
                               float border_depth = 1.0f) {
    Sampler s;
    s.wrap_s = s.wrap_t = wrap;
    s.border_color = {border_depth, border_depth, border_depth, border_depth};
    s.compare_mode = CompareMode::ref_to_texture;
    s.compare_func = func;
    return s;
  }
  // A plain sampler with one filter for magnification and minification, no mips unless asked.
  static constexpr Sampler plain(Filter filter, Wrap wrap = Wrap::clamp_to_edge, MipFilter mip = MipFilter::none) {
    Sampler s;
    s.mag_filter = s.min_filter = filter;
    s.mip_filter = mip;
    s.wrap_s = s.wrap_t = wrap;
    return s;
  }
};

constexpr std::string_view to_string(Wrap w) {
  constexpr std::string_view names[] = {"clamp_to_edge", "clamp_to_border", "clamp", "repeat", "mirrored_repeat"};
  return names[int(w)];
}

constexpr std::optional<Wrap> parse_wrap(std::string_view s) {
  for (int i = 0; i < 5; ++i)
    if (to_string(Wrap(i)) == s) return Wrap(i);
  return std::nullopt;
}

constexpr std::optional<Filter> parse_filter(std::string_view s) {
  if (s == "nearest") return Filter::nearest;
  if (s == "linear") return Filter::linear;
  return std::nullopt;
}

// GL's comparison of a reference with a texel: 1 if `ref OP texel`, else 0.
inline float compare_ref(CompareFunc f, float ref, float texel) {
  bool r = false;
  switch (f) {
    case CompareFunc::never: r = false; break;
    case CompareFunc::less: r = ref < texel; break;
    case CompareFunc::equal: r = ref == texel; break;
    case CompareFunc::lequal: r = ref <= texel; break;
    case CompareFunc::greater: r = ref > texel; break;
    case CompareFunc::notequal: r = ref != texel; break;
    case CompareFunc::gequal: r = ref >= texel; break;
    case CompareFunc::always: r = true; break;
  }
  return r ? 1.0f : 0.0f;
}

SHADOWLAB_ISA_END
}  // namespace shading
