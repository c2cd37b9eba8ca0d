// From luminance to a displayable colour: the camera's exposure in EV100 (the photographic exposure value at ISO
// 100) and the tone-mapping operators that take exposed linear colour to [0, 1] before the one sRGB encode at
// output (scenes/frame/develop.h applies them to a whole frame). Header-only and dependency-free but for GLM, so
// the scene model and the command line read the same names.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace shading {

enum class ToneMap : uint8_t { neutral, aces, clamp };

struct ToneMapName {
  std::string_view name;
  std::string_view description;
};
inline constexpr ToneMapName kToneMapNames[] = {
    {"neutral", "Khronos PBR Neutral: base colours kept up to 0.8, highlights compressed and desaturated"},
    {"aces", "ACES filmic, Stephen Hill's fit of the RRT and sRGB ODT: more contrast, hue shifts in highlights"},
    {"clamp", "no curve: exposed values clamped to [0, 1] (compare raw values)"},
};
static_assert(std::size(kToneMapNames) == size_t(ToneMap::clamp) + 1);

inline std::optional<ToneMap> parse_tone_map(std::string_view name) {
  for (size_t i = 0; i < std::size(kToneMapNames); ++i)
    if (kToneMapNames[i].name == name) return ToneMap(i);
  return std::nullopt;
}
inline std::string_view tone_map_name(ToneMap t) { return kToneMapNames[size_t(t)].name; }

// Exposure from EV100 as in Lagarde and de Rousiers, "Moving Frostbite to PBR" (2014): the luminance that
// saturates the sensor at ISO 100 is L_max = 1.2 · 2^EV100 cd/m² (saturation-based sensitivity, q = 0.65,
// lens and shutter folded into EV), and a pixel's exposed value is L / L_max.
inline float exposure_scale(float ev100) { return float(1.0 / (1.2 * std::exp2(double(ev100)))); }

// The EV100 at which luminance `l` comes out as `value` after exposure (the inverse of exposure_scale).
inline float ev100_mapping(double l, double value) { return float(std::log2(l / (1.2 * value))); }

// Relative luminance of linear Rec. 709 / sRGB primaries.
inline float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// Khronos PBR Neutral (KhronosGroup/ToneMapping, 2024): colours whose largest channel stays under 0.76 pass
// unchanged but for a small toe offset; above, the peak is compressed towards 1 and desaturated towards white.
inline glm::vec3 tone_map_neutral(glm::vec3 c) {
  constexpr float kStart = 0.8f - 0.04f, kDesaturation = 0.15f;
  const float x = std::min(c.r, std::min(c.g, c.b));
  const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
  c -= offset;
  const float peak = std::max(c.r, std::max(c.g, c.b));
  if (peak < kStart) return c;
  constexpr float d = 1.0f - kStart;
  const float new_peak = 1.0f - d * d / (peak + d - kStart);
  c *= new_peak / peak;
  const float g = 1.0f - 1.0f / (kDesaturation * (peak - new_peak) + 1.0f);
  return c * (1.0f - g) + glm::vec3(new_peak * g);
}

// ACES filmic as Stephen Hill's fit (BakingLab, ACES.hlsl): sRGB to the fitted RRT's input space, the rational
// fit of RRT + ODT, back to sRGB, clamped to [0, 1].
inline glm::vec3 tone_map_aces(glm::vec3 c) {
  const glm::vec3 a{0.59719f * c.r + 0.35458f * c.g + 0.04823f * c.b,
                    0.07600f * c.r + 0.90834f * c.g + 0.01566f * c.b,
                    0.02840f * c.r + 0.13383f * c.g + 0.83777f * c.b};
  auto fit = [](float v) {
    const float num = v * (v + 0.0245786f) - 0.000090537f;
    const float den = v * (0.983729f * v + 0.4329510f) + 0.238081f;
    return num / den;
  };
  const glm::vec3 b{fit(a.r), fit(a.g), fit(a.b)};
  const glm::vec3 o{1.60475f * b.r - 0.53108f * b.g - 0.07367f * b.b,
                    -0.10208f * b.r + 1.10813f * b.g - 0.00605f * b.b,
                    -0.00327f * b.r - 0.07276f * b.g + 1.07602f * b.b};
  return glm::clamp(o, glm::vec3(0.0f), glm::vec3(1.0f));
}

// Exposed linear colour (negative channels taken as 0) to display-linear [0, 1] by operator `t`.
inline glm::vec3 tone_map(glm::vec3 c, ToneMap t) {
  c = glm::max(c, glm::vec3(0.0f));
  switch (t) {
    case ToneMap::neutral: c = tone_map_neutral(c); break;
    case ToneMap::aces: c = tone_map_aces(c); break;
    case ToneMap::clamp: break;
  }
  return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

}  // namespace shading
