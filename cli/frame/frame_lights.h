// From a scene light and the command-line overrides to what the frame renderer draws with: the lighting
// model's Light and, for shadowed lights, the technique layer's ClassicLight and ClassicSettings.
#pragma once
#include <string>

#include "cli/frame/frame.h"
#include "shading/lighting.h"
#include "shading/techniques/classic.h"

namespace frame {

struct ResolvedLight {
  shading::Light light;
  std::string technique;    // "shadowmap", "none", or a technique this renderer does not implement yet
  bool shadowed = false;    // a classic map is built and read
  bool fixed_box = false;   // directional: the tutorial's hand-made box instead of the automatic fit
  shading::tech::ClassicLight classic;
  shading::tech::ClassicSettings settings;
};

// Throws std::invalid_argument naming the option for an unknown technique, filter or bias, or a map size
// outside 16..16384.
ResolvedLight resolve_light(const scenes::Light& light, const FrameOptions& options);

}  // namespace frame
