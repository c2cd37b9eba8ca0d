// Storage formats of render targets: the three depth formats of CONVENTIONS and the two colour formats.
// Shared by the targets (target.h), the depth test (depth_test.h) and everything that samples a target.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

namespace raster {

enum class DepthFormat : uint8_t { d16, d24, d32f };
enum class ColorFormat : uint8_t { rgba8, rgba32f };

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

constexpr std::string_view to_string(ColorFormat f) { return f == ColorFormat::rgba8 ? "rgba8" : "rgba32f"; }

}  // namespace raster
