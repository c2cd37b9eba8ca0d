// Per-draw fixed-function state: what a GL application sets with glViewport, glScissor, glDepthFunc, glCullFace,
// glPolygonOffset and friends. A draw copies it once (the snapshot) before any stage runs; nothing global.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

namespace raster {

enum class DepthFunc : uint8_t { never, less, equal, lequal, greater, notequal, gequal, always };
enum class CullMode : uint8_t { none, back, front };
enum class FrontFace : uint8_t { ccw, cw };
// replace: dst = src. multiply: GL's glBlendFunc(GL_DST_COLOR, GL_ZERO), dst = src · dst.
enum class BlendMode : uint8_t { replace, multiply };

struct Rect {
  int x = 0, y = 0, width = 0, height = 0;  // lower-left origin, window pixels
  friend bool operator==(const Rect&, const Rect&) = default;
};

struct PolygonOffset {
  float factor = 0.0f;  // multiplies m = max(|dz/dx|, |dz/dy|) in window space
  float units = 0.0f;   // multiplies r, the format's minimum resolvable difference (see setup.cpp)
  friend bool operator==(const PolygonOffset&, const PolygonOffset&) = default;
};

struct DrawState {
  std::optional<Rect> viewport;  // default: the whole target
  std::optional<Rect> scissor;   // default: no scissor test
  DepthFunc depth_func = DepthFunc::less;
  bool depth_test = true;
  bool depth_write = true;
  bool color_write = true;
  CullMode cull = CullMode::none;
  FrontFace front_face = FrontFace::ccw;
  PolygonOffset polygon_offset{};
  bool depth_clamp = false;
  BlendMode blend = BlendMode::replace;
};

constexpr std::optional<DepthFunc> parse_depth_func(std::string_view s) {
  constexpr std::string_view names[] = {"never", "less", "equal", "lequal", "greater", "notequal", "gequal", "always"};
  for (int i = 0; i < 8; ++i)
    if (s == names[i]) return DepthFunc(i);
  return std::nullopt;
}

constexpr std::optional<CullMode> parse_cull_mode(std::string_view s) {
  if (s == "none") return CullMode::none;
  if (s == "back") return CullMode::back;
  if (s == "front") return CullMode::front;
  return std::nullopt;
}

}  // namespace raster
