// From a scene light and the frame's overrides to what a frame is rendered with: the lighting model's Light,
// the light as the techniques see it (LightDesc) and its merged, checked shadow settings (ShadowConfig).
#pragma once
#include <cstddef>
#include <string>

#include "scenes/frame/frame.h"
#include "shading/lighting.h"

namespace frame {

// A file-name part for `prefix` + "-" + `name`: characters other than letters, digits, '-' and '_' become '-',
// and an empty (or all-punctuation) name adds nothing, so a stem never ends in '-' ("light0", "light1-sun").
std::string name_stem(const std::string& prefix, const std::string& name);

struct ResolvedLight {
  shading::Light light;
  tech::LightDesc desc;
  tech::ShadowConfig config;
};

// Throws FrameError naming the field: a technique the light's type does not take or that is not built, a map
// size, tap count or bias value out of range, a technique parameter of the wrong kind. `index` is the light's
// place in the scene, for messages naming lights[index].
ResolvedLight resolve_light(const scenes::Light& light, size_t index, const FrameConfig& config);

}  // namespace frame
