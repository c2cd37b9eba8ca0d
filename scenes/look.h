// How a scene is shown, as plain data: the camera's exposure (a fixed EV100 or automatic), the tone-mapping
// operator (shading/tone_map.h) and the background drawn where no surface is. A scene file may set them
// (`exposure`, `tonemap`, `background`); FrameConfig and the command line override them per frame.
#pragma once
#include <optional>
#include <string_view>

#include <glm/vec3.hpp>

#include "shading/tone_map.h"

namespace scenes {

// EV100 given, or none: automatic from the frame (develop.h says how).
struct Exposure {
  std::optional<float> ev100;
  bool operator==(const Exposure&) const = default;
};

// A vertical gradient from `bottom` (the frame's lowest row) to `top` (its highest), linear RGB in [0, 1], shown
// as given: it is not exposed or tone-mapped, only sRGB-encoded like every pixel.
struct Background {
  glm::vec3 top{0.0f};
  glm::vec3 bottom{0.0f};
  bool operator==(const Background&) const = default;
};

struct NamedBackground {
  std::string_view name;
  std::string_view description;
  Background background;
};
// The named backgrounds; the first is the default.
inline constexpr NamedBackground kBackgrounds[] = {
    {"sky", "a soft sky: pale blue-grey at the top to light grey at the bottom",
     {{0.305f, 0.402f, 0.546f}, {0.730f, 0.745f, 0.761f}}},
    {"grey", "flat middle grey (linear 0.18)", {glm::vec3(0.18f), glm::vec3(0.18f)}},
    {"black", "black", {glm::vec3(0.0f), glm::vec3(0.0f)}},
    {"tutorial", "the classic tutorial's glClearColor(0, 0, 0.4)", {{0.0f, 0.0f, 0.4f}, {0.0f, 0.0f, 0.4f}}},
};

inline std::optional<Background> named_background(std::string_view name) {
  for (const NamedBackground& b : kBackgrounds)
    if (b.name == name) return b.background;
  return std::nullopt;
}

struct Look {
  Exposure exposure;
  shading::ToneMap tone_map = shading::ToneMap::neutral;
  Background background = kBackgrounds[0].background;
  bool operator==(const Look&) const = default;
};

}  // namespace scenes
