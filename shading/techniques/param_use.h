// When a parameter a technique takes does nothing: the settings under which the technique does not read a key it
// declares (vocabulary.h). A light's own key that its settings leave unread is refused (scenes/frame/
// frame_lights.cpp), and so is a frame-wide override that no light reads (scenes/frame/frame.cpp), so that a
// setting never silently does nothing.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// Why `key` (declared for c.technique) is not read for a light of type `light` with the settings of `c`; nothing
// when it is read. The reasons:
//   pcss: the light's size is light_angle for a directional light and light_radius for a spot light;
//   cascades, cube: light_angle / light_radius with soft_shadows = pcss only; the moment keys with a `moments`
//     kind that reads them (blur_radius and moment_mips with any; esm_c with esm; light_bleed with the variance
//     kinds; min_variance with vsm; evsm_positive and evsm_min_variance with evsm2 and evsm4; evsm_negative with
//     evsm4);
//   shadowmap: fit, fit_cutoff and fit_smoothing size a directional light's box (a spot's frustum is its cone),
//     and fit_cutoff and fit_smoothing belong to fit = tutorial;
//   paraboloid: split_plane divides a point light's two paraboloids (a hemispherical light has one).
std::optional<std::string> unread_param(const ShadowConfig& c, LightType light, std::string_view key);

SHADOWLAB_ISA_END
}  // namespace shading::tech
