// Texel formats a shader can sample, and how one texel is decoded to floats (and encoded back). Every lookup
// dispatches on the format once (visit_format) and then runs code specialised for it, so a tap is a load and a
// conversion, never a switch.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>
#include <type_traits>

#include <glm/vec4.hpp>

#include "raster/formats.h"
#include "raster/target.h"
#include "shading/half.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

// d16, d24, d32f: the depth formats of CONVENTIONS, sampled as a float in [0, 1] (code / max code for d16, d24).
// r32f, rg32f, rgba16f, rgba32f: float colour. rgba8: unorm. rgba8_srgb: unorm, sRGB-decoded on every tap
// (before filtering, as GL does for SRGB8_ALPHA8).
enum class TexelFormat : uint8_t { d16, d24, d32f, r32f, rg32f, rgba8, rgba8_srgb, rgba16f, rgba32f };

inline constexpr int kTexelFormatCount = 9;

constexpr std::string_view to_string(TexelFormat f) {
  constexpr std::string_view names[] = {"d16",   "d24",        "d32f",    "r32f",   "rg32f",
                                        "rgba8", "rgba8_srgb", "rgba16f", "rgba32f"};
  return names[int(f)];
}

constexpr std::optional<TexelFormat> parse_texel_format(std::string_view s) {
  for (int i = 0; i < kTexelFormatCount; ++i)
    if (to_string(TexelFormat(i)) == s) return TexelFormat(i);
  return std::nullopt;
}

constexpr bool is_depth(TexelFormat f) { return f <= TexelFormat::d32f; }
// Fixed-point formats: GL clamps the compare reference and the border colour to [0, 1] for these.
constexpr bool is_unorm(TexelFormat f) {
  return f == TexelFormat::d16 || f == TexelFormat::d24 || f == TexelFormat::rgba8 || f == TexelFormat::rgba8_srgb;
}

constexpr size_t bytes_per_texel(TexelFormat f) {
  switch (f) {
    case TexelFormat::d16: return 2;
    case TexelFormat::d24:
    case TexelFormat::d32f:
    case TexelFormat::r32f:
    case TexelFormat::rgba8:
    case TexelFormat::rgba8_srgb: return 4;
    case TexelFormat::rg32f:
    case TexelFormat::rgba16f: return 8;
    case TexelFormat::rgba32f: return 16;
  }
  return 4;
}

constexpr TexelFormat texel_format_of(raster::DepthFormat f) {
  switch (f) {
    case raster::DepthFormat::d16: return TexelFormat::d16;
    case raster::DepthFormat::d24: return TexelFormat::d24;
    case raster::DepthFormat::d32f: return TexelFormat::d32f;
  }
  return TexelFormat::d32f;
}

constexpr TexelFormat texel_format_of(raster::ColorFormat f, bool srgb) {
  switch (f) {
    case raster::ColorFormat::rgba32f: return TexelFormat::rgba32f;
    case raster::ColorFormat::rg32f: return TexelFormat::rg32f;
    case raster::ColorFormat::r32f: return TexelFormat::r32f;
    case raster::ColorFormat::rgba8: break;
  }
  return srgb ? TexelFormat::rgba8_srgb : TexelFormat::rgba8;
}

// sRGB-encoded byte to linear float, the same values raster::srgb_decode gives (so a view of an sRGB colour
// target reads what ColorTarget::read reads).
inline float srgb8_to_linear(uint8_t v) {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[i] = raster::srgb_decode(float(i) / 255.0f);
    return t;
  }();
  return table[v];
}

namespace detail {
template <class T>
T load(const std::byte* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}
template <class T>
void store(std::byte* p, T v) {
  std::memcpy(p, &v, sizeof(T));
}
}  // namespace detail

// Format traits: red() reads the first component (what a compare or a depth read uses), rgba() the texel as GL
// returns it from a lookup ((d, 0, 0, 1) for depth, missing components 0 and alpha 1 for R and RG formats).
template <TexelFormat F>
struct Texel;

template <>
struct Texel<TexelFormat::d16> {
  static constexpr size_t kBytes = 2;
  // code / 65535 correctly rounded: 1/65535 has a 16-bit period in binary, so a float division gives exactly
  // the value the double division of raster::DepthTarget::value rounds to.
  static float red(const std::byte* row, int i) {
    return float(detail::load<uint16_t>(row + size_t(i) * 2)) / 65535.0f;
  }
  static glm::vec4 rgba(const std::byte* row, int i) { return {red(row, i), 0.0f, 0.0f, 1.0f}; }
};

template <>
struct Texel<TexelFormat::d24> {
  static constexpr size_t kBytes = 4;
  // Low 24 bits; same exactness argument as d16 (period 24).
  static float red(const std::byte* row, int i) {
    return float(detail::load<uint32_t>(row + size_t(i) * 4) & 0xFFFFFFu) / 16777215.0f;
  }
  static glm::vec4 rgba(const std::byte* row, int i) { return {red(row, i), 0.0f, 0.0f, 1.0f}; }
};

template <>
struct Texel<TexelFormat::d32f> {
  static constexpr size_t kBytes = 4;
  static float red(const std::byte* row, int i) { return detail::load<float>(row + size_t(i) * 4); }
  static glm::vec4 rgba(const std::byte* row, int i) { return {red(row, i), 0.0f, 0.0f, 1.0f}; }
};

template <>
struct Texel<TexelFormat::r32f> {
  static constexpr size_t kBytes = 4;
  static float red(const std::byte* row, int i) { return detail::load<float>(row + size_t(i) * 4); }
  static glm::vec4 rgba(const std::byte* row, int i) { return {red(row, i), 0.0f, 0.0f, 1.0f}; }
};

template <>
struct Texel<TexelFormat::rg32f> {
  static constexpr size_t kBytes = 8;
  static float red(const std::byte* row, int i) { return detail::load<float>(row + size_t(i) * 8); }
  static glm::vec4 rgba(const std::byte* row, int i) {
    const std::byte* p = row + size_t(i) * 8;
    return {detail::load<float>(p), detail::load<float>(p + 4), 0.0f, 1.0f};
  }
};

template <>
struct Texel<TexelFormat::rgba8> {
  static constexpr size_t kBytes = 4;
  static float red(const std::byte* row, int i) { return float(uint8_t(row[size_t(i) * 4])) / 255.0f; }
  static glm::vec4 rgba(const std::byte* row, int i) {
    const std::byte* p = row + size_t(i) * 4;
    return {float(uint8_t(p[0])) / 255.0f, float(uint8_t(p[1])) / 255.0f, float(uint8_t(p[2])) / 255.0f,
            float(uint8_t(p[3])) / 255.0f};
  }
};

template <>
struct Texel<TexelFormat::rgba8_srgb> {
  static constexpr size_t kBytes = 4;
  static float red(const std::byte* row, int i) { return srgb8_to_linear(uint8_t(row[size_t(i) * 4])); }
  static glm::vec4 rgba(const std::byte* row, int i) {
    const std::byte* p = row + size_t(i) * 4;
    return {srgb8_to_linear(uint8_t(p[0])), srgb8_to_linear(uint8_t(p[1])), srgb8_to_linear(uint8_t(p[2])),
            float(uint8_t(p[3])) / 255.0f};
  }
};

template <>
struct Texel<TexelFormat::rgba16f> {
  static constexpr size_t kBytes = 8;
  static float red(const std::byte* row, int i) { return half_to_float(detail::load<uint16_t>(row + size_t(i) * 8)); }
  static glm::vec4 rgba(const std::byte* row, int i) {
    const std::byte* p = row + size_t(i) * 8;
    return {half_to_float(detail::load<uint16_t>(p)), half_to_float(detail::load<uint16_t>(p + 2)),
            half_to_float(detail::load<uint16_t>(p + 4)), half_to_float(detail::load<uint16_t>(p + 6))};
  }
};

template <>
struct Texel<TexelFormat::rgba32f> {
  static constexpr size_t kBytes = 16;
  static float red(const std::byte* row, int i) { return detail::load<float>(row + size_t(i) * 16); }
  static glm::vec4 rgba(const std::byte* row, int i) {
    const std::byte* p = row + size_t(i) * 16;
    return {detail::load<float>(p), detail::load<float>(p + 4), detail::load<float>(p + 8),
            detail::load<float>(p + 12)};
  }
};

// Calls fn(std::integral_constant<TexelFormat, F>{}) for the run-time format f: the one switch of a lookup.
template <class Fn>
decltype(auto) visit_format(TexelFormat f, Fn&& fn) {
  using TF = TexelFormat;
  switch (f) {
    case TF::d16: return fn(std::integral_constant<TF, TF::d16>{});
    case TF::d24: return fn(std::integral_constant<TF, TF::d24>{});
    case TF::d32f: return fn(std::integral_constant<TF, TF::d32f>{});
    case TF::r32f: return fn(std::integral_constant<TF, TF::r32f>{});
    case TF::rg32f: return fn(std::integral_constant<TF, TF::rg32f>{});
    case TF::rgba8: return fn(std::integral_constant<TF, TF::rgba8>{});
    case TF::rgba8_srgb: return fn(std::integral_constant<TF, TF::rgba8_srgb>{});
    case TF::rgba16f: return fn(std::integral_constant<TF, TF::rgba16f>{});
    case TF::rgba32f: break;
  }
  return fn(std::integral_constant<TF, TF::rgba32f>{});
}

// Decodes one texel (slow path: tests, mip generation, files).
inline glm::vec4 decode_texel(TexelFormat f, const std::byte* row, int i) {
  return visit_format(f, [&](auto tag) { return Texel<decltype(tag)::value>::rgba(row, i); });
}

// Encodes a linear value with GL's conversions: depth clamped to [0, 1] (unorm codes rounded to nearest), unorm
// colour clamped and rounded (sRGB-encoded first for rgb8_srgb's colour channels), halves rounded to nearest
// even, floats stored as they are.
void encode_texel(TexelFormat f, std::byte* row, int i, const glm::vec4& v);

SHADOWLAB_ISA_END
}  // namespace shading
