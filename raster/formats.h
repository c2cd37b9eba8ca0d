// Storage formats of render targets: the three depth formats of CONVENTIONS and the colour formats (RGBA8, and
// 32-bit float with four, two or one channels).
// Shared by the targets (target.h), the depth test (depth_test.h) and everything that samples a target.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace raster {

enum class DepthFormat : uint8_t { d16, d24, d32f };
// The float formats store a write's first channels unchanged and drop the rest (GL's RG32F and R32F colour
// attachments); a read gives the missing ones as 0 and alpha as 1, as a texture lookup does.
enum class ColorFormat : uint8_t { rgba8, rgba32f, rg32f, r32f };

// Largest code of a unorm depth format (65535 for d16, 16777215 for d24); 0 for d32f.
constexpr uint32_t depth_max_code(DepthFormat f) {
  switch (f) {
    case DepthFormat::d16: return 0xFFFFu;
    case DepthFormat::d24: return 0xFFFFFFu;
    case DepthFormat::d32f: return 0u;
  }
  return 0u;
}

constexpr std::string_view to_string(DepthFormat f) {
  switch (f) {
    case DepthFormat::d16: return "d16";
    case DepthFormat::d24: return "d24";
    case DepthFormat::d32f: return "d32f";
  }
  return "?";
}

constexpr std::optional<DepthFormat> parse_depth_format(std::string_view s) {
  if (s == "d16") return DepthFormat::d16;
  if (s == "d24") return DepthFormat::d24;
  if (s == "d32f") return DepthFormat::d32f;
  return std::nullopt;
}

constexpr std::string_view to_string(ColorFormat f) {
  switch (f) {
    case ColorFormat::rgba8: return "rgba8";
    case ColorFormat::rgba32f: return "rgba32f";
    case ColorFormat::rg32f: return "rg32f";
    case ColorFormat::r32f: return "r32f";
  }
  return "?";
}

// Floats per texel of a float format (4, 2, 1); 0 for rgba8, whose texel is four bytes.
constexpr int float_channels(ColorFormat f) {
  switch (f) {
    case ColorFormat::rgba32f: return 4;
    case ColorFormat::rg32f: return 2;
    case ColorFormat::r32f: return 1;
    case ColorFormat::rgba8: return 0;
  }
  return 0;
}

constexpr size_t bytes_per_texel(ColorFormat f) { return f == ColorFormat::rgba8 ? 4 : size_t(float_channels(f)) * 4; }

}  // namespace raster
